//! Phong NDF: D(θ) = (α_p + 2)/(2π) · cos^{α_p} θ (MATH.md "Phong", after Blinn 1977 with the projected-area
//! normalization).
//!
//! - Domain: α_p ≥ 0, any finite value. α_p = 0 is the uniform distribution 1/π; below it D → ∞ at grazing.
//!   Stated once, with these reasons, in [`Phong::PARAMS`](super::Distribution::PARAMS).
//! - Normalization: N = 2π ∫₀^{π/2} cos^{α_p} θ sin θ cos θ dθ = 2π/(α_p + 2), so D = cos^{α_p} θ / N.
//! - θ → 0: D → (α_p + 2)/(2π), flat to second order. θ → π/2: D → 0 like cos^{α_p} θ; at the double
//!   nearest π/2, cos θ = 6.12e-17, not 0, so D is tiny but positive for α_p ≲ 20 (6.12e-17^20 ≈ 5e-323) and exactly 1/π for α_p = 0.
//! - Stable form: the whole of D in log space, ln D = ln((α_p + 2)/(2π)) − (α_p/2) · log1p(tan²θ), using
//!   ln cos θ = −½ ln(1 + tan²θ). Raising a rounded cos θ to the power α_p would multiply its rounding error
//!   by α_p (1e-8 relative at α_p = 1e8); log1p(tan²θ) keeps full relative accuracy from θ = 0 to π/2, and the
//!   sum of logs avoids cos^{α_p} underflowing where (α_p + 2)/(2π) · cos^{α_p} is still representable.
//!   Every finite α_p ≥ 0 is accepted: the exponent is never NaN (α_p · 0 = 0 at θ = 0) and (α_p + 2)/(2π)
//!   ≤ 2.9e307 is finite.

use super::Distribution;
use crate::domain::{Bound, DomainError, Param};
use std::f64::consts::PI;

/// α_p's domain: every finite value ≥ 0 (module header).
const ALPHA_P: Param = Param {
    name: "alpha_p",
    symbol: "α_p",
    min: Bound::inclusive(0.0, "D(π/2) = cos^alpha_p(π/2)/N is infinite"),
    max: Bound::inclusive(
        f64::MAX,
        "every finite alpha_p works: (alpha_p + 2)/(2π) ≤ 2.9e307 is finite",
    ),
};

/// A validated Phong lobe with its log-normalization precomputed.
#[derive(Debug, Clone, PartialEq)]
pub struct Phong {
    alpha_p: f64,
    /// ln(1/N) = ln((α_p + 2)/(2π)).
    ln_inv_normalization: f64,
}

impl Phong {
    /// A Phong lobe with exponent `alpha_p`; rejects NaN, ±∞ and negative values.
    pub fn new(alpha_p: f64) -> Result<Self, DomainError> {
        ALPHA_P.check(alpha_p)?;
        Ok(Phong {
            alpha_p,
            ln_inv_normalization: ((alpha_p + 2.0) / (2.0 * PI)).ln(),
        })
    }


    /// N = 2π/(α_p + 2), the projected-area integral of the unnormalized lobe cos^{α_p} θ.
    pub fn normalization(&self) -> f64 {
        2.0 * PI / (self.alpha_p + 2.0)
    }

    /// The cosine exponent α_p.
    pub fn alpha_p(&self) -> f64 {
        self.alpha_p
    }
}

impl Distribution for Phong {
    const NAME: &'static str = "phong";
    const TITLE: &'static str = "Phong";
    const PARAMS: &'static [Param] = &[ALPHA_P];
    const COLOUR: u32 = 0xDB2E2E;
    /// α_p = 2/α_b² − 2 of the notebook's α_b = 0.3 (MATH.md, Walter et al. 2007).
    const EXAMPLE: &'static [f64] = &[2.0 / (0.3 * 0.3) - 2.0];

    fn from_params(params: &[f64]) -> Result<Self, DomainError> {
        Phong::new(params[0])
    }

    /// D(θ) = (α_p + 2)/(2π) · cos^{α_p} θ for θ ∈ [0, π/2], normalized over projected area.
    #[inline]
    fn eval(&self, theta: f64) -> f64 {
        let tan2_theta = theta.tan().powi(2);
        (self.ln_inv_normalization - 0.5 * self.alpha_p * tan2_theta.ln_1p()).exp()
    }

    fn params(&self) -> Vec<f64> {
        vec![self.alpha_p]
    }
}
