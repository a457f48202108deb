//! Panel views through the scene format: the projected view of every normalized NDF integrates to
//! 1/(2π) against sin θ dθ, the slope view to 1/(2π) against tan θ sec²θ dθ (∫∫ P₂₂ dp dq = 1), and a
//! CSV series compares against the curve it was sampled from.

use ndfplot::curve::Curve;
use ndfplot::input::parse_json;
use ndfplot::math::quad::{QuadError, integrate};
use ndfplot::math::tolerance::QUAD_REL_TOL;
use ndfplot::metrics::lobe_width;
use ndfplot::scene;
use std::f64::consts::{FRAC_PI_2, PI};

/// Accepted relative deviation of a view's total mass from 1/(2π).
const MASS_TOL: f64 = 1e-9;

/// Every family at the ends and the middle of its domain (MATH.md), including ABC's exact a₂ = 1 and
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
    let scene = ndfplot::resolve::scene(spec).unwrap_or_else(|p| panic!("{p:?}"));
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
