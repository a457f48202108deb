//! The front-facing projected area of the microfacets seen from θo, computed apart from Λ, to audit it.
//!
//! A(θo) = ∫_Ω ⟨ωo, m⟩⁺ D(m) dm. Exact Smith masking satisfies the weak white furnace G1(θo) A(θo) = cos θo
//! (Heitz 2014), so G1(θo) A(θo)/cos θo = A/(cos θo (1 + Λ)) = 1 checks a family's Λ (and D's normalization)
//! by a route that shares nothing with it but D: the azimuth is integrated over the front-facing part only,
//! by the direct arccos form (no cancellation: both terms are ≥ 0), and θm by the adaptive quadrature of
//! [`crate::model::math::quad`]. Meant for audits (`ndfplot check`, tests), not per sample.

use super::g1;
use crate::model::math::quad::{QuadError, integrate};
use crate::model::math::tolerance::QUAD_REL_TOL;
use crate::model::ndf::Ndf;
use std::f64::consts::{FRAC_PI_2, PI};

/// Ratio between successive quadrature breakpoints: pieces span a factor 4 in their distance to 0, to the
/// edge θm = π/2 − θo or to π/2, so that a lobe of any width meets a piece of comparable width.
const BREAK_RATIO: f64 = 4.0;

/// How many breakpoints each geometric sequence places (4⁻²⁴ ≈ 3.6e-15 of its span at the closest).
const BREAK_COUNT: i32 = 24;

/// A(θo) = ∫ ⟨ωo, m⟩⁺ D(m) dm for θo ∈ [0, π/2]:
/// 2π ∫₀^{θe} D a sin θm dθm + 2 ∫_{θe}^{π/2} D (a φ₀ + b sin φ₀) sin θm dθm, θe = π/2 − θo,
/// a = cos θo cos θm, b = sin θo sin θm, φ₀ = arccos(−a/b) (every azimuth faces ωo below θe, |φ| < φ₀ above).
/// Pieces split geometrically towards 0, θe and π/2 and from D's lobe width 1/√(π D(0)) both inwards and
/// outwards; a piece is accepted once its error estimate is within QUAD_REL_TOL of A's scale cos θo (its relative
/// error may be out of reach where it holds ~1e-30 of the whole).
pub fn front_projected_area(ndf: &Ndf, theta_o: f64) -> Result<f64, QuadError> {
    let (sin_o, cos_o) = theta_o.sin_cos();
    let edge = FRAC_PI_2 - theta_o;
    let integrand = |theta_m: f64| {
        let (sin_m, cos_m) = theta_m.sin_cos();
        let (a, b) = (cos_o * cos_m, sin_o * sin_m);
        let azimuthal = if theta_m <= edge || b <= a {
            2.0 * PI * a
        } else {
            let phi0 = (-a / b).acos();
            2.0 * (a * phi0 + b * phi0.sin())
        };
        ndf.eval(theta_m) * azimuthal * sin_m
    };
    let width = (1.0 / (PI * ndf.eval(0.0)).sqrt()).min(FRAC_PI_2);
    let mut breaks = vec![0.0, edge, FRAC_PI_2];
    let span_below = edge.min(FRAC_PI_2 - edge);
    for k in 0..BREAK_COUNT {
        let shrink = BREAK_RATIO.powi(-k);
        breaks.push(width * BREAK_RATIO.powi(3) * shrink);
        breaks.push(FRAC_PI_2 - 0.5 * shrink);
        breaks.push(edge - span_below * shrink);
        breaks.push(edge + 0.5 * theta_o * shrink);
    }
    // Outwards from the lobe too, up to π/2: a heavy tail (GGX's mass beyond θ falls only like (α/θ)²) then
    // meets pieces of its own scale, which the shift below cannot hide.
    let mut outward = width * BREAK_RATIO.powi(4);
    while outward < FRAC_PI_2 {
        breaks.push(outward);
        outward *= BREAK_RATIO;
    }
    breaks.retain(|b| (0.0..=FRAC_PI_2).contains(b));
    breaks.sort_by(f64::total_cmp);
    breaks.dedup();
    // Each piece integrates the integrand plus A's scale per radian, `shift`, and takes it off again: a
    // piece holding ~1e-30 of A then converges at once instead of chasing its own relative accuracy, while
    // the absolute error stays within QUAD_REL_TOL · (A + shift · π/2).
    let shift = cos_o.max(f64::MIN_POSITIVE);
    let budget = QUAD_REL_TOL * shift;
    let mut area = 0.0;
    for pair in breaks.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        let shifted = match integrate(|t| integrand(t) + shift, a, b, QUAD_REL_TOL) {
            Ok(v) => v,
            Err(QuadError::NotConverged { estimate, error }) if error <= budget => estimate,
            Err(e) => return Err(e),
        };
        area += shifted - shift * (b - a);
    }
    Ok(area)
}

/// G1(θo) A(θo)/cos θo with the family's own Λ: 1 for a consistent Λ (module header); 1 at θo = 0 by
/// definition (Λ(0) = 0 and A(0) = cos 0 · 1).
pub fn smith_furnace(ndf: &Ndf, theta_o: f64) -> Result<f64, QuadError> {
    Ok(g1(ndf.lambda(theta_o)) * front_projected_area(ndf, theta_o)? / theta_o.cos())
}
