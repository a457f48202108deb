//! The Fresnel basis (two 1000 × 1000 SVDs) is computed only when a figure needs it, and only by
//! the resolve stage: reading a spec computes nothing and reads no data file. Each check runs in a
//! process of its own (this binary started again for that one test), so that no other test
//! computes the basis first.

use crate::common::scratch;
use ndfplot::model::fresnel::basis::basis_is_loaded;
use ndfplot::output::Format;
use ndfplot::pipeline::resolve;
use ndfplot::render::{self, RenderOptions};
use ndfplot::spec::curve::CurveSpec;
use ndfplot::spec::scene::data::DataSpec;
use ndfplot::spec::source::{self, CanvasOverride};
use std::process::Command;

/// Set in the process that runs a check alone.
const ALONE: &str = "NDFPLOT_TEST_ALONE";

/// Whether this process runs the test `name` alone; if not, runs it alone in a new process of
/// this binary and asserts that it passed there.
fn alone(name: &str) -> bool {
    if std::env::var_os(ALONE).is_some() {
        return true;
    }
    let (_, module) = module_path!().split_once("::").unwrap();
    let out = Command::new(std::env::current_exe().unwrap())
        .args([&format!("{module}::{name}"), "--exact", "--test-threads=1"])
        .env(ALONE, "1")
        .output()
        .unwrap();
    let report = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        out.status.success() && report.contains("1 passed"),
        "{report}"
    );
    false
}

fn render(dir: &std::path::Path, spec: &str) {
    let path = dir.join("s.json");
    std::fs::write(&path, spec).unwrap();
    render::run(&RenderOptions {
        paths: vec![path],
        out: dir.join("out"),
        formats: vec![Format::Svg, Format::Png, Format::Csv],
        canvas: CanvasOverride::default(),
        allow_read: Vec::new(),
    })
    .unwrap();
}

#[test]
fn the_basis_is_loaded_only_for_a_figure_that_uses_it() {
    if !alone("the_basis_is_loaded_only_for_a_figure_that_uses_it") {
        return;
    }
    let dir = scratch("lazy-basis");
    render(
        &dir,
        r#"{"id": "ndf-and-exact-fresnel", "panels": [
            {"curves": [{"ndf": "ggx", "alpha_tr": 0.3}, {"ndf": "beckmann", "alpha_b": 0.3}]},
            {"curves": [{"fresnel": "exact", "eta": 1.5, "kappa": 0.0}]}]}"#,
    );
    assert!(!basis_is_loaded(), "NDFs and exact Fresnel need no basis");
    render(
        &dir,
        r#"{"id": "belcour", "panels": [{"curves": [{"fresnel": "belcour", "eta": 1.5, "kappa": 0.0}]}]}"#,
    );
    assert!(basis_is_loaded(), "the decomposition needs the basis");
}

#[test]
fn reading_a_spec_fits_nothing_computes_no_basis_and_reads_no_data_file() {
    if !alone("reading_a_spec_fits_nothing_computes_no_basis_and_reads_no_data_file") {
        return;
    }
    let dir = scratch("spec-then-resolve");
    let spec = dir.join("s.json");
    // A fit that cannot reach its target, a Belcour reconstruction and a data file not yet written.
    std::fs::write(
        &spec,
        r#"{"id": "pending", "panels": [
            {"curves": [{"ndf": "torrance_sparrow", "alpha_ts": {"fit": {"target": {"ndf": "phong", "alpha_p": [1, 0]}}}},
                        {"data": "csv", "path": "renderer.csv"}]},
            {"curves": [{"fresnel": "belcour", "eta": 1.5, "label": "Belcour, L2 = {l2}"}]}]}"#,
    )
    .unwrap();
    let loaded = source::load_scenes(
        &source::sources(std::slice::from_ref(&spec), &[]).unwrap(),
        CanvasOverride::default(),
    );
    let scene = loaded[0].scene.as_ref().expect("the spec is valid");
    let [fit_to_one, fit_to_zero] = &scene.panels[0].curves[..] else {
        panic!("one fitted curve per target: {:?}", scene.panels[0].curves)
    };
    assert!(matches!(fit_to_one.curve, CurveSpec::Fitted(_)));
    assert!(matches!(fit_to_zero.curve, CurveSpec::Fitted(_)));
    assert!(matches!(scene.panels[0].data[0].dataset, DataSpec::Csv(_)));
    assert!(matches!(
        scene.panels[1].curves[0].curve,
        CurveSpec::Belcour(_)
    ));
    assert!(!basis_is_loaded(), "validation computes no coefficients");

    // Resolve runs the fits and reads the file; their problems name the file and the JSON path.
    let error = resolve::scenes(loaded.clone()).unwrap_err().to_string();
    assert!(basis_is_loaded(), "resolve computes the coefficients");
    let source = spec.display();
    for needle in [
        format!(
            "error: {source}: panels[0].curves[0].alpha_ts: fit to α_p = 0: alpha_ts: torrance_sparrow cannot reach"
        ),
        format!("error: {source}: panels[0].curves[1].path: cannot read \"renderer.csv\""),
    ] {
        assert!(error.contains(&needle), "expected {needle:?} in: {error}");
    }

    std::fs::write(
        &spec,
        std::fs::read_to_string(&spec)
            .unwrap()
            .replace("[1, 0]", "1"),
    )
    .unwrap();
    std::fs::write(dir.join("renderer.csv"), "theta,value\n0,1\n0.5,2\n").unwrap();
    let loaded = source::load_scenes(
        &source::sources(std::slice::from_ref(&spec), &[]).unwrap(),
        CanvasOverride::default(),
    );
    let scenes = resolve::scenes(loaded).unwrap();
    let panels = &scenes[0].panels;
    assert!(
        panels[0].curves[0].label.ends_with("(peak fit to α_p = 1)"),
        "{}",
        panels[0].curves[0].label
    );
    assert_eq!(
        panels[0].data[0].dataset.evaluate().points,
        [(0.0, 1.0), (0.5, 2.0)]
    );
    let belcour = &panels[1].curves[0].label;
    assert!(
        belcour.starts_with("Belcour, L2 = ") && !belcour.contains("{l2}"),
        "{belcour}"
    );
}
