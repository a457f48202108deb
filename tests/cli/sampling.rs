//! Sampling: adaptive sampling of drawn curves (within tolerance, few samples, also as drawn in projected, slope
//! and polar panels), the spec's `sampling` key, and the plan skipping what a run does not need
//! (formats not requested, jobs shared between panels).

use crate::common::scratch;
use ndfplot::model::ndf::Family;
use ndfplot::output::Format;
use ndfplot::pipeline::adaptive::{self, Frame, distance_to_segment, max_deviation_px};
use ndfplot::pipeline::figure::Figure;
use ndfplot::pipeline::plan::{Job, Outputs, plan};
use ndfplot::pipeline::provenance::Provenance;
use ndfplot::pipeline::sample::evaluate_all;
use ndfplot::render::{self, RenderOptions};
use ndfplot::spec::look::{Dash, PanelKind, Rgb, Scale, XUnit};
use ndfplot::spec::source::{self, CanvasOverride};
use std::collections::BTreeMap;
use std::f64::consts::FRAC_PI_2;
use std::path::Path;

fn frame() -> Frame {
    Frame {
        theta_range: (0.0, FRAC_PI_2),
        width_px: 600.0,
        height_px: 370.0,
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        y_range: None,
        tolerance_px: 0.25,
        geometry: adaptive::Geometry::Angle,
    }
}

/// The narrow lobes of the issue: drawn within 0.25 px with a few hundred samples at most.
#[test]
fn narrow_lobes_are_drawn_within_a_quarter_pixel() {
    for (family, alpha) in [
        (Family::Phong, 2048.0),
        (Family::TrowbridgeReitz, 0.01),
        (Family::Beckmann, 0.001),
    ] {
        let ndf = family.build(&[alpha]).unwrap();
        let f = |t: f64| ndf.eval(t);
        let start = adaptive::initial(&f, frame().theta_range, &[]);
        let extent = adaptive::extent([start.points.as_slice()]);
        let refined = adaptive::sample(&f, &frame(), start, extent);
        let error = max_deviation_px(&f, &frame().map(extent), &refined.points, 64);
        assert!(error <= 0.25, "{ndf:?}: {error} px");
        assert!(
            refined.points.len() <= 400,
            "{ndf:?}: {} points",
            refined.points.len()
        );
    }
}

#[test]
fn flat_curves_keep_the_initial_grid() {
    let ndf = Family::TrowbridgeReitz.build(&[1.0]).unwrap();
    let f = |t: f64| ndf.eval(t);
    let start = adaptive::initial(&f, frame().theta_range, &[]);
    let extent = adaptive::extent([start.points.as_slice()]);
    let refined = adaptive::sample(&f, &frame(), start, extent);
    assert_eq!(refined.points.len(), adaptive::INITIAL_POINTS);
}

fn scene(sampling: &str) -> String {
    format!(
        r#"{{"id":"s","title":"t",{sampling}"panels":[
            {{"curves":[{{"ndf":"phong","alpha_p":2048}},{{"ndf":"beckmann","alpha_b":0.4}}]}},
            {{"curves":[{{"ndf":"phong","alpha_p":2048}},{{"ndf":"beckmann","alpha_b":0.4}}]}}]}}"#
    )
}

fn load(dir: &Path, text: &str) -> Vec<ndfplot::spec::scene::Scene> {
    let path = dir.join("s.json");
    std::fs::write(&path, text).unwrap();
    ndfplot::pipeline::resolve::scenes(source::load_scenes(
        &source::sources(&[path], &[]).unwrap(),
        CanvasOverride::default(),
    ))
    .unwrap()
}

#[test]
fn default_sampling_draws_adaptively_and_tabulates_uniformly() {
    let dir = scratch("sampling-default");
    let scenes = load(&dir, &scene(""));
    let plan = plan(
        &scenes,
        Outputs {
            drawn: true,
            table: true,
        },
    );
    let drawn = plan.drawn.as_ref().unwrap();
    let table = plan.table.as_ref().unwrap();
    // Identical panels share their jobs: 2 adaptive + 2 uniform in all.
    assert_eq!(plan.jobs.len(), 4);
    assert_eq!(drawn[0][0], drawn[0][1]);
    assert!(
        drawn[0][0]
            .iter()
            .all(|&j| matches!(plan.jobs[j], Job::Adaptive { .. }))
    );
    assert!(
        table[0][0]
            .iter()
            .all(|&j| matches!(plan.jobs[j], Job::Uniform { samples: 1000, .. }))
    );
    let evaluated = evaluate_all(&plan).unwrap();
    for &j in &drawn[0][0] {
        assert!(
            evaluated[j].points.len() < 1000,
            "{} points",
            evaluated[j].points.len()
        );
    }
}

#[test]
fn polar_panels_are_drawn_adaptively_in_the_disc() {
    let dir = scratch("sampling-polar");
    let scenes = load(
        &dir,
        r#"{"id":"s","panels":[{"view":"polar","curves":[{"ndf":"phong","alpha_p":48}]}]}"#,
    );
    let outputs = Outputs {
        drawn: true,
        table: false,
    };
    let p = plan(&scenes, outputs);
    let job = p.drawn.as_ref().unwrap()[0][0][0];
    assert!(matches!(p.jobs[job], Job::Adaptive { frame: 0, .. }));
    assert_eq!(p.frames[0].geometry, adaptive::Geometry::Polar);
}

#[test]
fn explicit_sampling_applies_to_tables_too() {
    let dir = scratch("sampling-explicit");
    let uniform = load(&dir, &scene(r#""sampling":{"uniform":50},"#));
    let p = plan(
        &uniform,
        Outputs {
            drawn: true,
            table: true,
        },
    );
    assert_eq!(p.drawn, p.table);
    assert!(
        p.jobs
            .iter()
            .all(|j| matches!(j, Job::Uniform { samples: 50, .. }))
    );
    let adaptive = load(
        &dir,
        &scene(r#""sampling":{"adaptive":{"tolerance_px":0.5}},"#),
    );
    let p = plan(
        &adaptive,
        Outputs {
            drawn: true,
            table: true,
        },
    );
    assert_eq!(p.drawn, p.table);
    assert!(p.jobs.iter().all(|j| matches!(j, Job::Adaptive { .. })));
    assert_eq!(p.frames[0].tolerance_px, 0.5);
}

#[test]
fn sampling_key_errors_name_the_problem() {
    let dir = scratch("sampling-errors");
    for (sampling, needle) in [
        (
            r#""sampling":{"uniform":50,"adaptive":{}},"#,
            "exactly one of",
        ),
        (
            r#""sampling":{"adaptive":{"tolerance_px":0}},"#,
            "tolerance_px",
        ),
        (r#""sampling":{"adaptive":{"tol":1}},"#, "tol"),
    ] {
        let path = dir.join("s.json");
        std::fs::write(&path, scene(sampling)).unwrap();
        let error = ndfplot::pipeline::resolve::scenes(source::load_scenes(
            &source::sources(&[path], &[]).unwrap(),
            CanvasOverride::default(),
        ))
        .unwrap_err();
        assert!(error.to_string().contains(needle), "{sampling}: {error}");
    }
}

#[test]
fn a_run_produces_only_the_requested_formats_and_needed_jobs() {
    let dir = scratch("sampling-formats");
    let spec = dir.join("s.json");
    std::fs::write(&spec, scene("")).unwrap();
    let options = |formats: Vec<Format>| RenderOptions {
        paths: vec![spec.clone()],
        out: dir.join("out"),
        formats,
        canvas: CanvasOverride::default(),
        allow_read: Vec::new(),
    };
    let (_, svg_only) = render::run_with_stats(&options(vec![Format::Svg])).unwrap();
    assert_eq!(
        svg_only.produced,
        BTreeMap::from([(Format::Svg, 1)]),
        "an svg-only run never rasterizes nor tabulates"
    );
    let (_, pdf_only) = render::run_with_stats(&options(vec![Format::Pdf])).unwrap();
    assert_eq!(
        pdf_only.produced,
        BTreeMap::from([(Format::Pdf, 1)]),
        "a pdf-only run converts the drawing, never rasterizes nor tabulates"
    );
    assert_eq!(
        pdf_only.evaluations, svg_only.evaluations,
        "a PDF is sampled as the SVG it is drawn from"
    );
    let (_, csv_only) = render::run_with_stats(&options(vec![Format::Csv])).unwrap();
    assert_eq!(csv_only.produced, BTreeMap::from([(Format::Csv, 1)]));
    // A CSV-only run evaluates the two uniform curves once each, however many panels show them.
    assert_eq!(csv_only.evaluations, 2 * 1000);
    let scenes = load(&dir, &scene(""));
    assert!(
        plan(
            &scenes,
            Outputs {
                drawn: false,
                table: true,
            },
        )
        .drawn
        .is_none()
    );
}

#[test]
fn the_requested_formats_never_change_a_value_written() {
    let dir = scratch("sampling-same-values");
    let spec = dir.join("s.json");
    // Adaptive tables: their points depend on the pixel frame, which must not depend on whether
    // PNG is drawn.
    std::fs::write(&spec, scene(r#""sampling":{"adaptive":{}},"#)).unwrap();
    let run = |name: &str, formats: Vec<Format>| {
        let out = dir.join(name);
        render::run(&RenderOptions {
            paths: vec![spec.clone()],
            out: out.clone(),
            formats,
            canvas: CanvasOverride::default(),
            allow_read: Vec::new(),
        })
        .unwrap();
        out
    };
    let all = run("all", vec![Format::Svg, Format::Png, Format::Csv]);
    let csv = run("csv", vec![Format::Csv]);
    let svg = run("svg", vec![Format::Svg]);
    let read = |dir: &Path, name: &str| std::fs::read(dir.join(name)).unwrap();
    assert_eq!(read(&all, "s.csv"), read(&csv, "s.csv"));
    assert_eq!(read(&all, "s.svg"), read(&svg, "s.svg"));
}

/// The vertices of each `<polyline>` of `svg` stroked in `hex`, in SVG units.
fn polylines(svg: &str, hex: &str) -> Vec<Vec<(f64, f64)>> {
    let document = roxmltree::Document::parse(svg).unwrap();
    document
        .descendants()
        .filter(|n| n.has_tag_name("polyline") && n.attribute("stroke") == Some(hex))
        .map(|n| {
            let vertex = |p: &str| {
                let (x, y) = p.split_once(',').unwrap();
                (x.parse().unwrap(), y.parse().unwrap())
            };
            n.attribute("points")
                .unwrap()
                .split_whitespace()
                .map(vertex)
                .collect()
        })
        .collect()
}

/// The least-squares solution of `rows` (coefficients, right-hand side), by the normal equations
/// and Gauss–Jordan elimination with partial pivoting.
fn least_squares(rows: &[(Vec<f64>, f64)]) -> Vec<f64> {
    let n = rows[0].0.len();
    let mut a = vec![vec![0.0; n + 1]; n];
    for (r, y) in rows {
        for i in 0..n {
            for j in 0..n {
                a[i][j] += r[i] * r[j];
            }
            a[i][n] += r[i] * y;
        }
    }
    for i in 0..n {
        let pivot = (i..n)
            .max_by(|&p, &q| a[p][i].abs().total_cmp(&a[q][i].abs()))
            .unwrap();
        a.swap(i, pivot);
        for r in (0..n).filter(|&r| r != i) {
            let f = a[r][i] / a[i][i];
            let pivot_row = a[i].clone();
            for (x, p) in a[r][i..=n].iter_mut().zip(&pivot_row[i..=n]) {
                *x -= f * p;
            }
        }
    }
    (0..n).map(|i| a[i][n] / a[i][i]).collect()
}

/// What [`drawn_deviation`] measures for one series, in output (PNG) pixels.
struct Drawn {
    /// Largest distance of the true curve from the polyline through the samples, placed by the
    /// panel's own data-to-pixel map (fitted to the drawing).
    sampled: f64,
    /// Largest distance of the true curve from the polyline as drawn (vertices on whole device units).
    drawn: f64,
    /// Largest distance of a drawn vertex from its sample placed by the fitted map.
    snapped: f64,
}

/// Probes per polyline segment when the true curve is compared with it.
const PROBES: usize = 16;
/// Error, in output pixels, of a data-to-pixel map fitted by least squares to a few dozen
/// vertices snapped to whole device units (half an output pixel): a few hundredths of a pixel.
const FIT_SLACK_PX: f64 = 0.05;

/// Draws series `s` of panel `p` of catalogue figure `id` in a colour of its own (a solid
/// line, legend off: nothing else of the layout changes) and measures it against its curve in
/// the panel's pixels, as rendered with PNG output; `None` when its drawn polyline is not one
/// vertex per sample (clipped).
fn drawn_deviation(id: &str, p: usize, s: usize) -> Option<Drawn> {
    const UNIQUE: &str = "#010203";
    let scenes = ndfplot::pipeline::resolve::scenes(source::load_scenes(
        &source::sources(&[], &[]).unwrap(),
        CanvasOverride::default(),
    ))
    .unwrap()
    .into_iter()
    .filter(|scene| scene.id == id)
    .collect::<Vec<_>>();
    let scene = &scenes[0];
    let outputs = Outputs {
        drawn: true,
        table: false,
    };
    let planned = plan(&scenes, outputs);
    let evaluated = evaluate_all(&planned).unwrap();
    let mut figure = Figure::assemble(
        scene,
        &Provenance::without_spec(),
        &planned.drawn.as_ref().unwrap()[0],
        &evaluated,
    );
    let panel = &mut figure.panels[p];
    panel.axes.legend = ndfplot::spec::look::LegendPlace::None;
    panel.series[s].style.colour = Rgb::from_hex(0x010203);
    panel.series[s].style.dash = Dash::Solid;
    let panel = &figure.panels[p];
    let svg = String::from_utf8(ndfplot::output::plot::svg(&figure).unwrap()).unwrap();
    // SVG units per output pixel: the viewBox width over the CSS width, over the PNG scale.
    let root = roxmltree::Document::parse(&svg).unwrap();
    let root = root.root_element();
    let css_width: f64 = root.attribute("width").unwrap().parse().unwrap();
    let view_width: f64 = root
        .attribute("viewBox")
        .unwrap()
        .split(' ')
        .nth(2)
        .unwrap()
        .parse()
        .unwrap();
    let units_per_px = view_width / css_width / scene.canvas.png_scale;
    let curve = &scene.panels[p].curves[s].curve;
    let points = &panel.series[s].points;
    let lines = polylines(&svg, UNIQUE);
    let polar = panel.axes.kind == PanelKind::Polar;
    let drawn: Vec<(f64, f64)> = match (polar, lines.as_slice()) {
        // One path through the normal: the mirror image, then the lobe itself from θ = 0.
        (true, [line]) if line.len() == 2 * points.len() - 1 => line[points.len() - 1..].to_vec(),
        (false, [line]) if line.len() == points.len() => line.clone(),
        _ => return None,
    };
    // The panel's map from (θ, value) to SVG units, fitted to the drawn vertices.
    let y_display = |v: f64| match panel.axes.y_scale {
        Scale::Linear => v,
        Scale::Log => v.log10(),
    };
    let place: Box<dyn Fn(f64, f64) -> (f64, f64)> = if polar {
        let floor = panel
            .axes
            .y_range
            .map_or(f64::NEG_INFINITY, |(lo, hi)| y_display(lo.min(hi)));
        let rho = move |v: f64| y_display(v).max(floor);
        let rows: Vec<(Vec<f64>, f64)> = points
            .iter()
            .zip(&drawn)
            .flat_map(|(&(t, v), &(x, y))| {
                let (sin, cos) = t.sin_cos();
                [
                    (vec![1.0, 0.0, rho(v) * sin, sin], x),
                    (vec![0.0, 1.0, -rho(v) * cos, -cos], y),
                ]
            })
            .collect();
        let c = least_squares(&rows);
        Box::new(move |t: f64, v: f64| {
            let (sin, cos) = t.sin_cos();
            let r = c[2] * rho(v) + c[3];
            (c[0] + r * sin, c[1] - r * cos)
        })
    } else {
        let x_display = move |t: f64| match panel.axes.x_unit {
            XUnit::Degrees => t.to_degrees(),
            XUnit::Slope => t.tan(),
            XUnit::Radians | XUnit::Plain => t,
        };
        let fit = |pick: &dyn Fn(usize) -> (f64, f64)| {
            let rows: Vec<(Vec<f64>, f64)> = (0..points.len())
                .map(pick)
                .map(|(u, w)| (vec![1.0, u], w))
                .collect();
            least_squares(&rows)
        };
        let cx = fit(&|i| (x_display(points[i].0), drawn[i].0));
        let cy = fit(&|i| (y_display(points[i].1), drawn[i].1));
        Box::new(move |t: f64, v: f64| (cx[0] + cx[1] * x_display(t), cy[0] + cy[1] * y_display(v)))
    };
    let mut measured = Drawn {
        sampled: 0.0,
        drawn: 0.0,
        snapped: 0.0,
    };
    for (i, w) in points.windows(2).enumerate() {
        let chord = (place(w[0].0, w[0].1), place(w[1].0, w[1].1));
        for k in 1..PROBES {
            let t = w[0].0 + (w[1].0 - w[0].0) * k as f64 / PROBES as f64;
            let truth = place(t, curve.eval(t));
            measured.sampled = measured
                .sampled
                .max(distance_to_segment(truth, chord.0, chord.1));
            measured.drawn = measured
                .drawn
                .max(distance_to_segment(truth, drawn[i], drawn[i + 1]));
        }
        let (x, y) = chord.0;
        let snap = (x - drawn[i].0).hypot(y - drawn[i].1);
        measured.snapped = measured.snapped.max(snap);
    }
    for value in [
        &mut measured.sampled,
        &mut measured.drawn,
        &mut measured.snapped,
    ] {
        *value /= units_per_px;
    }
    Some(measured)
}

/// The drawn polylines of transformed (projected, slope) and polar panels stay within the
/// sampling tolerance of their true curves in the panel's own pixels, as rendered: the map is
/// fitted to the drawing itself, so a wrong frame, y range or scale in the sampler shows here.
#[test]
fn drawn_curves_of_every_view_follow_their_true_curves_in_the_panels_pixels() {
    let tolerance = ndfplot::spec::scene::DEFAULT_TOLERANCE_PX;
    // Device units are a quarter CSS pixel, half an output pixel at PNG scale 2: a vertex moves
    // at most half a diagonal of that when it is snapped, plus the error of a map fitted to
    // vertices snapped so.
    let snap = std::f64::consts::SQRT_2 / 4.0 + FIT_SLACK_PX;
    for (id, panel, series) in [
        // Projected: Phong α_p = 10.5 and Trowbridge–Reitz α = 0.4, 0.1.
        ("tr-vs-phong-projected", 0, 7),
        ("tr-vs-phong-projected", 0, 0),
        ("tr-vs-phong-projected", 1, 0),
        // Slope, log y: ABC fitted to SGD.
        ("sgd-vs-abc-slope", 0, 4),
        ("sgd-vs-abc-slope", 1, 5),
        // Polar, linear and log radius: Phong α_p = 48, Beckmann α_b = 0.5.
        ("beckmann-vs-phong-polar", 0, 4),
        ("beckmann-vs-phong-polar", 1, 3),
    ] {
        let Drawn {
            sampled,
            drawn,
            snapped,
        } = drawn_deviation(id, panel, series).unwrap_or_else(|| panic!("{id} {panel} {series}"));
        let at = format!("{id}, panel {panel}, series {series}");
        assert!(sampled <= tolerance, "{at}: samples {sampled} px off");
        assert!(snapped <= snap, "{at}: vertices snapped {snapped} px");
        assert!(drawn <= tolerance + snap, "{at}: drawn {drawn} px off");
    }
}
