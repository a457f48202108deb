//! Beckmann NDF: D(θ) = exp(−tan²θ/α_b²) / (π α_b² cos⁴θ) (MATH.md "Beckmann"; Beckmann & Spizzichino 1963,
//! Walter et al. 2007), α_b the RMS microfacet slope.
//!
//! - Domain: 1e-150 ≤ α_b ≤ 1e4. Below, α_b² leaves the normal double range and D(0) = 1/(π α_b²) heads for
//!   overflow (at α_b ≈ 4e-155). Above, the super-rough lobe sits within ~1/α_b rad of grazing, where the
//!   double spacing of θ near π/2 (2.2e-16) resolves it only to ~α_b · 2e-16: 1e4 keeps that ≤ 2e-12, so D
//!   stays verifiably normalized. Stated once, with these reasons, in
//!   [`Beckmann::PARAMS`](super::Distribution::PARAMS).
//! - Normalization: the unnormalized lobe exp(−tan²θ/α_b²)/(α_b² cos⁴θ) integrates to N = π over projected
//!   area, for every α_b.
//! - θ → 0: D → 1/(π α_b²), with curvature 2 − 1/α_b² in tan²θ (a dip at 0 for α_b > 1/√2). θ → π/2: the
//!   exponential wins over 1/cos⁴θ and D → 0; at the double nearest π/2, tan²θ = 2.7e32 and D is exactly 0.
//! - Stable form: tan θ directly (the notebook's (1 − cos²θ)/cos²θ cancels for small θ), and D in log space,
//!   ln D = −ln(π α_b²) − tan²θ/α_b² + 2 log1p(tan²θ), using 1/cos⁴θ = (1 + tan²θ)²: no factor overflows or
//!   underflows on its own, and the result is 0, never NaN, at grazing.

use super::Distribution;
use crate::domain::{Bound, DomainError, Param};
use std::f64::consts::PI;

/// α_b's domain. At 1e-150, α_b² = 1e-300 is still a normal double and D(0) = 1/(π α_b²) ≈ 3e299 is
/// finite; at 1e4 the grazing lobe, ~1/α_b = 1e-4 rad wide, is resolved by θ to ~2e-12.
const ALPHA_B: Param = Param {
    name: "alpha_b",
    symbol: "α_b",
    min: Bound::inclusive(1e-150, "D(0) = 1/(π alpha_b²) overflows"),
    max: Bound::inclusive(1e4, "the lobe is unresolvably close to grazing"),
};

/// A validated Beckmann lobe with its log-normalization precomputed.
#[derive(Debug, Clone, PartialEq)]
pub struct Beckmann {
    alpha_b: f64,
    /// ln(1/(π α_b²)) = ln D(0).
    ln_peak: f64,
}

impl Beckmann {
    /// A Beckmann lobe of RMS slope `alpha_b` ∈ [1e-150, 1e4]; rejects NaN, ±∞ and values outside.
    pub fn new(alpha_b: f64) -> Result<Self, DomainError> {
        ALPHA_B.check(alpha_b)?;
        Ok(Beckmann {
            alpha_b,
            ln_peak: -PI.ln() - 2.0 * alpha_b.ln(),
        })
    }


    /// N = π: the projected-area integral of exp(−tan²θ/α_b²)/(α_b² cos⁴θ), independent of α_b.
    pub fn normalization(&self) -> f64 {
        PI
    }

    /// The RMS microfacet slope α_b.
    pub fn alpha_b(&self) -> f64 {
        self.alpha_b
    }
}

impl Distribution for Beckmann {
    const NAME: &'static str = "beckmann";
    const TITLE: &'static str = "Beckmann";
    const PARAMS: &'static [Param] = &[ALPHA_B];
    const COLOUR: u32 = 0x2689D1;
    const EXAMPLE: &'static [f64] = &[0.3];

    fn from_params(params: &[f64]) -> Result<Self, DomainError> {
        Beckmann::new(params[0])
    }

    /// D(θ) = exp(−tan²θ/α_b²)/(π α_b² cos⁴θ) for θ ∈ [0, π/2], normalized over projected area.
    #[inline]
    fn eval(&self, theta: f64) -> f64 {
        let tan_theta = theta.tan();
        let tan2_theta = tan_theta * tan_theta;
        (self.ln_peak - (tan_theta / self.alpha_b).powi(2) + 2.0 * tan2_theta.ln_1p()).exp()
    }

    fn params(&self) -> Vec<f64> {
        vec![self.alpha_b]
    }
}
