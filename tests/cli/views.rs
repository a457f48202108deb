//! Panel views through the scene format: the projected view of every normalized NDF integrates to
//! 1/(2π) against sin θ dθ, the slope view to 1/(2π) against tan θ sec²θ dθ (∫∫ P₂₂ dp dq = 1), and a
//! CSV series compares against the curve it was sampled from.

use crate::common::{ndfplot, render_into, scratch, text};
use ndfplot::model::curve::Curve;
use ndfplot::model::math::quad::{QuadError, integrate};
use ndfplot::model::math::tolerance::QUAD_REL_TOL;
use ndfplot::model::metrics::lobe_width;
use ndfplot::spec::input::parse_json;
use ndfplot::spec::scene;
use std::f64::consts::{FRAC_PI_2, PI};

/// Accepted relative deviation of a view's total mass from 1/(2π).
const MASS_TOL: f64 = 1e-9;

/// Every family at the ends and the middle of its domain (docs/maths.md), including ABC's exact a₂ = 1 and
/// 2 and SGD's a₂ = 0.
const CURVES: &[&str] = &[
    r#"{"ndf": "phong", "alpha_p": [0, 1, 100, 10000, 1000000]}"#,
    r#"{"ndf": "beckmann", "alpha_b": [0.001, 0.1, 0.5, 1, 7, 100]}"#,
    r#"{"ndf": "torrance_sparrow", "alpha_ts": [0.001, 0.2, 1, 100]}"#,
    r#"{"ndf": "trowbridge_reitz", "alpha_tr": [0.001, 0.1, 1, 7, 100]}"#,
    r#"{"ndf": "abc", "alpha_abc1": [0.0212, 1, 23.5, 1000], "alpha_abc2": [0.5, 1, 1.75, 2, 1000]}"#,
    r#"{"ndf": "sgd", "alpha_sgd1": [0.1, 0.5, 1], "alpha_sgd2": [0, 0.5, 1.5]}"#,
];

/// The curves of a one-panel scene showing `CURVES` through `transform`.
fn panel_curves(transform: &str) -> Vec<Curve> {
    let text = format!(
        r#"{{"id": "views", "panels": [{{"transform": "{transform}", "x": {{"unit": "radians"}}, "curves": [{}]}}]}}"#,
        CURVES.join(", ")
    );
    let node = parse_json(&text, "scene").unwrap();
    let spec = scene::parse(&node, None).unwrap_or_else(|p| panic!("{p:?}"));
    let scene = ndfplot::pipeline::resolve::scene(spec).unwrap_or_else(|p| panic!("{p:?}"));
    scene.panels[0]
        .curves
        .iter()
        .map(|c| c.curve.clone())
        .collect()
}

/// ∫₀^{π/2} f over pieces growing geometrically (×4) away from 0 from `width`/64, and towards π/2
/// down to 1e-12 rad, so lobes of any width are resolved. A piece whose relative accuracy is out of
/// reach (a grazing tail of ~1e-27) counts when its absolute error is below 1e-15.
fn piecewise(f: impl Fn(f64) -> f64, width: f64) -> f64 {
    let mut breaks = vec![0.0, FRAC_PI_2];
    let mut t = width / 64.0;
    while t < FRAC_PI_2 {
        breaks.push(t);
        t *= 4.0;
    }
    let mut d = 0.25;
    while d > 1e-12 {
        breaks.push(FRAC_PI_2 - d);
        d /= 4.0;
    }
    breaks.sort_by(f64::total_cmp);
    breaks.dedup();
    breaks
        .windows(2)
        .map(|w| match integrate(&f, w[0], w[1], QUAD_REL_TOL) {
            Ok(value) => value,
            Err(QuadError::NotConverged { estimate, error }) if error < 1e-15 => estimate,
            Err(e) => panic!("[{}, {}]: {e:?}", w[0], w[1]),
        })
        .sum()
}

#[test]
fn the_projected_view_of_every_normalized_ndf_integrates_to_one_over_two_pi() {
    let curves = panel_curves("projected");
    assert_eq!(curves.len(), 5 + 6 + 4 + 5 + 20 + 9);
    for curve in &curves {
        let width = lobe_width(curve.eval(0.0));
        let mass = piecewise(|t| curve.eval(t) * t.sin(), width);
        assert!(
            (mass * 2.0 * PI - 1.0).abs() < MASS_TOL,
            "{}: ∫ D cos θ sin θ dθ = {mass:e}, expected 1/(2π)",
            curve.canonical_json()
        );
    }
}

#[test]
fn the_slope_view_of_every_normalized_ndf_is_a_density_over_the_slope_plane() {
    // ∫∫ P₂₂(p, q) dp dq = 2π ∫₀^∞ P₂₂ r dr with r = tan θ, dr = sec²θ dθ.
    for curve in panel_curves("slope") {
        let width = lobe_width(curve.eval(0.0));
        let mass = piecewise(
            |t| {
                let c = t.cos();
                if c == 0.0 {
                    0.0
                } else {
                    curve.eval(t) * t.sin() / (c * c * c)
                }
            },
            width,
        );
        assert!(
            (mass * 2.0 * PI - 1.0).abs() < MASS_TOL,
            "{}: 2π ∫ P₂₂ tan θ sec²θ dθ = {:e}",
            curve.canonical_json(),
            mass * 2.0 * PI
        );
    }
}

#[test]
fn figures_take_physical_sizes_tick_choices_line_widths_and_no_grid() {
    let dir = scratch("views-paper");
    let spec = dir.join("paper.json");
    std::fs::write(
        &spec,
        r#"{"id": "paper", "unit": "in", "width": 3.5, "height": 2.5, "dpi": 288, "font_pt": 8,
            "panels": [{"grid": false,
                        "x": {"unit": "degrees", "ticks": [0, 45, 90]},
                        "y": {"scale": "log", "ticks": [0.1, 1, 10]},
                        "curves": [{"ndf": "ggx", "alpha_tr": 0.3, "width": 0.5}]}]}"#,
    )
    .unwrap();
    let out = dir.join("out");
    render_into(&[&spec], &out, "svg,png");
    let svg = std::fs::read_to_string(out.join("paper.svg")).unwrap();
    // 3.5 × 2.5 in, stated in inches; the PNG at 288 dpi is 3.5 × 288 by 2.5 × 288 pixels.
    assert!(
        svg.starts_with(r#"<svg width="3.5in" height="2.5in""#),
        "{}",
        &svg[..80]
    );
    let png = std::fs::read(out.join("paper.png")).unwrap();
    let size = |at: usize| u32::from_be_bytes(png[at..at + 4].try_into().unwrap());
    assert_eq!((size(16), size(20)), (1008, 720));
    // pHYs: 288 dpi is 11 339 pixels per metre each way, unit 1 (metre).
    let phys = png
        .windows(4)
        .position(|w| w == b"pHYs")
        .expect("a pHYs chunk");
    assert_eq!(
        (size(phys + 4), size(phys + 8), png[phys + 12]),
        (11339, 11339, 1)
    );
    for label in ["0°", "45°", "90°", "0.1", "10"] {
        assert!(svg.contains(&format!(">{label}</text>")), "{label}");
    }
    assert!(!svg.contains(">30°</text>"), "only the chosen ticks");

    let bad = dir.join("bad.json");
    std::fs::write(
        &bad,
        r#"{"id": "bad", "font_px": 12, "font_pt": 9, "png_scale": 2, "dpi": 300, "unit": "mm",
            "panels": [{"y": {"scale": "log", "ticks": [0, 1]}, "x": {"ticks": 1},
                        "curves": [{"ndf": "ggx", "alpha_tr": 0.3, "width": 50}]}]}"#,
    )
    .unwrap();
    let output = ndfplot(&["render", bad.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    assert_eq!(output.status.code(), Some(2));
    let stderr = text(&output.stderr);
    for expected in [
        "font_pt: give font_px or font_pt, not both",
        "dpi: give png_scale or dpi, not both",
        "unit: unknown value (got \"mm\", expected one of: px, in, cm)",
        "panels[0].y.ticks[0]: invalid tick (got 0, expected a number > 0 on a log axis)",
        "panels[0].x.ticks: expected a whole count from 2 to 20, a list of values or \"pi\" (got 1)",
        "panels[0].curves[0].width",
    ] {
        assert!(stderr.contains(expected), "{expected} not in {stderr}");
    }
}

#[test]
fn a_legend_goes_where_the_spec_places_it() {
    let dir = scratch("views-legend");
    // The legend box is the one translucent rectangle: its top-left corner, or none.
    let legend_at = |place: &str| -> Option<(f64, f64)> {
        let spec = dir.join(format!("{}.json", place.replace(' ', "-")));
        std::fs::write(
            &spec,
            format!(
                r#"{{"id": "{}", "width": 640, "height": 400,
                    "panels": [{{"legend": {place}, "curves": [{{"ndf": "ggx", "alpha_tr": [0.2, 0.4]}}]}}]}}"#,
                place.trim_matches('"').replace(' ', "-")
            ),
        )
        .unwrap();
        let out = dir.join("out");
        render_into(&[&spec], &out, "svg");
        let name = format!("{}.svg", place.trim_matches('"').replace(' ', "-"));
        let svg = std::fs::read_to_string(out.join(name)).unwrap();
        let rect = svg
            .lines()
            .find(|l| l.starts_with("<rect") && l.contains(r#"fill-opacity="0.85""#))?;
        let number = |key: &str| -> f64 {
            let start = rect.find(&format!(r#" {key}=""#)).unwrap() + key.len() + 3;
            rect[start..].split('"').next().unwrap().parse().unwrap()
        };
        Some((number("x"), number("y")))
    };
    let upper_left = legend_at(r#""upper left""#).unwrap();
    let lower_right = legend_at(r#""lower right""#).unwrap();
    assert!(
        upper_left.0 < lower_right.0 && upper_left.1 < lower_right.1,
        "{upper_left:?} {lower_right:?}"
    );
    let right = legend_at(r#""right""#).unwrap();
    let below = legend_at(r#""below""#).unwrap();
    assert!(
        right.0 > lower_right.0 && below.1 > lower_right.1,
        "{right:?} {below:?} {lower_right:?}"
    );
    assert_eq!(legend_at(r#""none""#), None);
    assert_eq!(legend_at("false"), None);
}

/// A legend that several panels share and that is too wide for a plot area at full size goes
/// inside one of them at a smaller size, rather than taking a band that shortens the whole row:
/// the catalogue's SGD grid, whose rows share "a₁ = 1, 0.5, 0.2, 0.1" and "a₂ = 0 … 1.5".
#[test]
fn a_shared_legend_goes_inside_a_plot_at_a_smaller_size_before_taking_a_band() {
    let out = scratch("views-shared-legend");
    let spec = crate::common::root().join("configs/sgd-grid.json");
    render_into(&[&spec], &out, "svg");
    let svg = std::fs::read_to_string(out.join("sgd-grid.svg")).unwrap();
    let attribute = |line: &str, key: &str| -> f64 {
        let start = line.find(&format!(r#" {key}=""#)).unwrap() + key.len() + 3;
        line[start..].split('"').next().unwrap().parse().unwrap()
    };
    // The plot frames' spans: the long vertical (x, top, bottom) and horizontal (y, left, right)
    // axis lines.
    let mut vertical = Vec::new();
    let mut horizontal = Vec::new();
    for line in svg.lines().filter(|l| l.contains(r##"stroke="#555555""##)) {
        let Some(start) = line.find(r#"points=""#) else {
            continue;
        };
        let points: Vec<(f64, f64)> = line[start + 8..]
            .split('"')
            .next()
            .unwrap()
            .split_whitespace()
            .map(|p| {
                let (x, y) = p.split_once(',').unwrap();
                (x.parse().unwrap(), y.parse().unwrap())
            })
            .collect();
        if let [(x0, y0), (x1, y1)] = points[..] {
            if x0 == x1 && (y1 - y0).abs() > 1000.0 {
                vertical.push((y0.min(y1), y0.max(y1)));
            } else if y0 == y1 && (x1 - x0).abs() > 1000.0 {
                horizontal.push((x0.min(x1), x0.max(x1)));
            }
        }
    }
    let boxes: Vec<[f64; 4]> = svg
        .lines()
        .filter(|l| l.starts_with("<rect") && l.contains(r#"fill-opacity="0.85""#))
        .map(|l| ["x", "y", "width", "height"].map(|k| attribute(l, k)))
        .collect();
    assert_eq!(boxes.len(), 2, "one legend per row");
    for [x, y, w, h] in boxes {
        let across = horizontal.iter().any(|&(l, r)| l <= x && x + w <= r);
        let down = vertical.iter().any(|&(t, b)| t <= y && y + h <= b);
        assert!(
            across && down,
            "legend box {x},{y} {w}×{h} is outside every plot area"
        );
    }
}

/// The committed `plots/examples/paper-figure.svg` is what rendering `examples/paper-figure.json`
/// (the style-keys example of docs/reference.md, which `readme.rs` holds to the file) draws now.
#[test]
fn the_committed_drawing_of_the_readme_style_example_is_current() {
    let root = crate::common::root();
    let out = scratch("paper-figure");
    render_into(&[&root.join("examples/paper-figure.json")], &out, "svg");
    let drawn = std::fs::read(out.join("paper-figure.svg")).unwrap();
    let committed = std::fs::read(root.join("plots/examples/paper-figure.svg")).unwrap();
    assert!(
        drawn == committed,
        "re-render plots/examples (docs/reference.md shows the command)"
    );
}

#[test]
fn panel_letters_open_the_panel_titles_in_order_and_stay_upright() {
    let dir = scratch("views-letters");
    let spec = dir.join("letters.json");
    std::fs::write(
        &spec,
        r#"{"id": "letters", "panel_letters": true,
            "panels": [{"title": "rough", "curves": [{"ndf": "ggx", "alpha_tr": 0.5}]},
                       {"curves": [{"ndf": "ggx", "alpha_tr": 0.1}]}]}"#,
    )
    .unwrap();
    let out = dir.join("out");
    render_into(&[&spec], &out, "svg");
    let svg = std::fs::read_to_string(out.join("letters.svg")).unwrap();
    assert!(
        svg.contains(">(a) rough</text>"),
        "the first panel's title, upright"
    );
    assert!(
        svg.contains(">(b)</text>"),
        "the untitled second panel's letter"
    );
    assert_eq!(scene::lettered(27, "x"), "(ab) x");
}

#[test]
fn a_transparent_background_leaves_the_page_unpainted() {
    let dir = scratch("views-transparent");
    let spec = dir.join("clear.json");
    std::fs::write(
        &spec,
        r#"{"id": "clear", "background": "transparent", "width": 320, "height": 200,
            "panels": [{"curves": [{"ndf": "ggx", "alpha_tr": 0.5}]}]}"#,
    )
    .unwrap();
    let out = dir.join("out");
    render_into(&[&spec], &out, "svg,png");
    let svg = std::fs::read_to_string(out.join("clear.svg")).unwrap();
    assert!(!svg.contains(r##"width="5120" height="3200" fill="#FFFFFF""##));
    let decoder = png::Decoder::new(std::io::BufReader::new(
        std::fs::File::open(out.join("clear.png")).unwrap(),
    ));
    let mut reader = decoder.read_info().unwrap();
    let mut pixels = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut pixels).unwrap();
    assert_eq!(info.color_type, png::ColorType::Rgba);
    assert_eq!(pixels[3], 0, "the top-left corner is see-through");
    assert!(
        pixels.chunks_exact(4).any(|p| p[3] == 255),
        "the curves and text are opaque"
    );
}

#[test]
fn annotations_mark_lines_bands_and_points_and_bad_ones_are_named() {
    let dir = scratch("views-annotations");
    let spec = dir.join("marked.json");
    std::fs::write(
        &spec,
        r#"{"id": "marked", "width": 640, "height": 400,
            "panels": [{"curves": [{"ndf": "beckmann", "alpha_b": 0.3}],
              "annotations": [{"x": 0.785, "label": "quarter"}, {"y": 1.0},
                              {"x": [1.2, 1.4], "label": "grazing"},
                              {"text": "peak", "at": [0, 3.54]}]}]}"#,
    )
    .unwrap();
    let out = dir.join("out");
    render_into(&[&spec], &out, "svg");
    let svg = std::fs::read_to_string(out.join("marked.svg")).unwrap();
    for label in ["quarter", "grazing", "peak"] {
        assert!(svg.contains(&format!(">{label}</text>")), "{label}");
    }
    let lint = ndfplot(&[
        "render",
        spec.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--strict",
        "-q",
    ]);
    assert_eq!(lint.status.code(), Some(0), "{}", text(&lint.stderr));

    let bad = dir.join("bad.json");
    std::fs::write(
        &bad,
        r#"{"id": "bad", "panels": [{"y": {"scale": "log"},
            "curves": [{"ndf": "beckmann", "alpha_b": 0.3}],
            "annotations": [{"x": 1, "text": "two kinds"}, {"y": 0}, {"text": "where?"},
                            {"x": [2, 1]}]}]}"#,
    )
    .unwrap();
    let output = ndfplot(&["render", bad.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    assert_eq!(output.status.code(), Some(2));
    let stderr = text(&output.stderr);
    for expected in [
        "panels[0].annotations[0]: expected exactly one of",
        "panels[0].annotations[1].y: out of range (got 0, expected a finite number > 0 on a log axis)",
        "panels[0].annotations[2].at: expected the data point [x, y]",
        "panels[0].annotations[3].x: invalid interval",
    ] {
        assert!(stderr.contains(expected), "{expected} not in {stderr}");
    }
}

#[test]
fn a_serif_figure_sets_every_text_in_the_embedded_serif_faces() {
    let dir = scratch("views-serif");
    let spec = dir.join("serif.json");
    std::fs::write(
        &spec,
        r#"{"id": "serif", "font": "serif", "title": "Beckmann α_b",
            "panels": [{"curves": [{"ndf": "beckmann", "alpha_b": 0.3}]}]}"#,
    )
    .unwrap();
    let out = dir.join("out");
    render_into(&[&spec], &out, "svg,pdf");
    let svg = std::fs::read_to_string(out.join("serif.svg")).unwrap();
    assert!(svg.contains(r#"font-family="DejaVu Serif, serif""#));
    assert!(!svg.contains("DejaVu Sans"));
    let pdf = std::fs::read(out.join("serif.pdf")).unwrap();
    let has = |name: &str| pdf.windows(name.len()).any(|w| w == name.as_bytes());
    assert!(
        has("DejaVuSerif-Italic"),
        "the variables' italic face is embedded"
    );
    assert!(has("DejaVuSerif") && !has("DejaVuSans"));
}

#[test]
fn bad_figure_options_exit_2_naming_their_keys() {
    let dir = scratch("views-bad-options");
    let bad = dir.join("bad.json");
    std::fs::write(
        &bad,
        r#"{"id": "bad", "font": "comic", "background": "glass", "panel_letters": "yes",
            "panels": [{"x": {"unit": "degrees", "ticks": "pi"}, "y": {"ticks": "pi"},
                        "curves": [{"ndf": "ggx", "alpha_tr": 0.3}]},
                       {"view": "polar", "annotations": [{"x": 0.5}],
                        "curves": [{"ndf": "ggx", "alpha_tr": 0.3}]}]}"#,
    )
    .unwrap();
    let out = dir.join("out");
    let output = ndfplot(&["render", bad.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    assert_eq!(output.status.code(), Some(2));
    let stderr = text(&output.stderr);
    for expected in [
        "font: unknown value (got \"comic\"",
        "background: unknown value (got \"glass\"",
        "panel_letters: expected true or false",
        "panels[0].x.ticks: \"pi\" ticks are for a linear θ axis in radians",
        "panels[0].y.ticks: \"pi\" ticks are for a θ axis in radians",
        "panels[1].annotations: annotations are drawn on cartesian panels",
    ] {
        assert!(stderr.contains(expected), "{expected} not in {stderr}");
    }
    assert!(!out.exists(), "nothing written");
}
