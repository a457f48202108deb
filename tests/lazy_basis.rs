//! The Fresnel basis (two 1000 × 1000 SVDs) is computed only when a figure needs it. A test binary
//! of its own, so that no other test in the process computes the basis first.

use ndfplot::fresnel::basis::basis_is_computed;
use ndfplot::output::Format;
use ndfplot::render::{self, RenderOptions};
use ndfplot::source::CanvasOverride;

fn render(dir: &std::path::Path, spec: &str) {
    let path = dir.join("s.json");
    std::fs::write(&path, spec).unwrap();
    render::run(&RenderOptions {
        paths: vec![path],
        out: dir.join("out"),
        formats: vec![Format::Svg, Format::Png, Format::Csv],
        canvas: CanvasOverride::default(),
    })
    .unwrap();
}

#[test]
fn the_basis_is_computed_only_for_a_figure_that_uses_it() {
    let dir = std::env::temp_dir().join(format!("ndfplot-lazy-basis-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    render(
        &dir,
        r#"{"id": "ndf-and-exact-fresnel", "panels": [
            {"curves": [{"ndf": "ggx", "alpha_tr": 0.3}, {"ndf": "beckmann", "alpha_b": 0.3}]},
            {"curves": [{"fresnel": "exact", "eta": 1.5, "kappa": 0.0}]}]}"#,
    );
    assert!(!basis_is_computed(), "NDFs and exact Fresnel need no basis");
    render(
        &dir,
        r#"{"id": "belcour", "panels": [{"curves": [{"fresnel": "belcour", "eta": 1.5, "kappa": 0.0}]}]}"#,
    );
    assert!(basis_is_computed(), "the decomposition needs the basis");
    std::fs::remove_dir_all(&dir).unwrap();
}
