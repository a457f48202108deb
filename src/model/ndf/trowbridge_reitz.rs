//! Trowbridge–Reitz (GGX) NDF: D(θ) = α² / (π (sin²θ + α² cos²θ)²) with α = α_tr (docs/maths.md "Trowbridge–Reitz";
//! Trowbridge & Reitz 1975, Walter et al. 2007).
//!
//! - Domain: 1e-150 ≤ α_tr ≤ 1e4. Below, α_tr² leaves the normal double range and D(0) = 1/(π α_tr²) heads for
//!   overflow. Above, the super-rough lobe sits within ~1/α_tr rad of grazing, where θ's double spacing
//!   (2.2e-16) resolves it only to ~α_tr · 2e-16 (≤ 2e-12 at 1e4). Stated once, with these reasons, in
//!   [`TrowbridgeReitz::PARAMS`](super::Distribution::PARAMS).
//! - Normalization: the unnormalized α²/(sin²θ + α² cos²θ)² integrates to N = π over projected area.
//! - θ → 0: D → 1/(π α²). θ → π/2: D → α²/π (not 0: the lobe has heavy tails); α = 1 is uniform, 1/π.
//! - Stable form: sin²θ + α² cos²θ, a sum of non-negative terms, instead of the notebook's cos²θ (α² − 1) + 1,
//!   which cancels for small α near θ = 0; D = (α/q)²/π rather than α²/(π q²) so that α⁴ never underflows
//!   (q = α² at θ = 0).
//! - Smith Λ (Heitz 2014 eq. 72): Λ(θo) = (√(1 + x) − 1)/2 with x = α² tan²θo, evaluated as x/(2(√(1 + x) + 1)),
//!   whose textbook form loses ~7 digits at α = 1e-3, θo = 30°; x = (α tan θo)² so that α² tan²θo does not
//!   underflow as a product of an underflowing α². Λ(0) = 0; at θo = FRAC_PI_2, tan θo = 1.6e16 and Λ ≈ α tan θo/2
//!   is large but finite (≤ 8e19 at α = 1e4).

use super::Distribution;
use crate::model::domain::{Bound, DomainError, Param};
use crate::model::math::elementary::{self, Lanewise, at_one, map_lanes};
use std::f64::consts::FRAC_1_PI;
use std::f64::consts::PI;

/// α_tr's domain. At 1e-150, α_tr² = 1e-300 is still a normal double and D(0) = 1/(π α_tr²) ≈ 3e299
/// is finite; at 1e4 the grazing lobe, ~1/α_tr = 1e-4 rad wide, is resolved by θ to ~2e-12.
const ALPHA_TR: Param = Param {
    name: "alpha_tr",
    symbol: "α_{tr}",
    min: Bound::inclusive(1e-150, "D(0) = 1/(π alpha_tr²) overflows"),
    max: Bound::inclusive(1e4, "the lobe is unresolvably close to grazing"),
};

/// A validated Trowbridge–Reitz lobe.
#[derive(Debug, Clone, PartialEq)]
pub struct TrowbridgeReitz {
    alpha_tr: f64,
    /// α_tr², the only constant the evaluation needs.
    alpha2: f64,
}

impl TrowbridgeReitz {
    /// A Trowbridge–Reitz lobe of roughness `alpha_tr` ∈ [1e-150, 1e4]; rejects NaN, ±∞ and values outside.
    pub fn new(alpha_tr: f64) -> Result<Self, DomainError> {
        ALPHA_TR.check(alpha_tr)?;
        Ok(TrowbridgeReitz {
            alpha_tr,
            alpha2: alpha_tr * alpha_tr,
        })
    }


    /// N = π: the projected-area integral of α²/(sin²θ + α² cos²θ)², independent of α.
    pub fn normalization(&self) -> f64 {
        PI
    }

    /// The roughness α_tr.
    pub fn alpha_tr(&self) -> f64 {
        self.alpha_tr
    }
}

impl Lanewise for TrowbridgeReitz {
    /// D(θ) = α²/(π (sin²θ + α² cos²θ)²) for θ ∈ [0, π/2], normalized over projected area, as (α/q)²/π.
    #[inline(always)]
    fn at(&self, theta: f64) -> f64 {
        let (sin_theta, cos_theta) = elementary::sin_cos(theta);
        let q = sin_theta * sin_theta + self.alpha2 * cos_theta * cos_theta;
        let ratio = self.alpha_tr / q;
        ratio * ratio * FRAC_1_PI
    }
}

impl Distribution for TrowbridgeReitz {
    const NAME: &'static str = "trowbridge_reitz";
    const TITLE: &'static str = "Trowbridge–Reitz";
    const ALIASES: &'static [&'static str] = &["ggx"];
    const PARAMS: &'static [Param] = &[ALPHA_TR];
    const COLOUR: u32 = 0x648102;
    const LAMBDA_CLOSED_FORM: bool = true;
    const EXAMPLE: &'static [f64] = &[0.3];
    const PAGE_FORMULA: &'static str = include_str!("trowbridge_reitz.js");

    fn from_params(params: &[f64]) -> Result<Self, DomainError> {
        TrowbridgeReitz::new(params[0])
    }


    /// D(θ) by [`Lanewise::at`] ([`at_one`]), the one kernel of [`eval_many`](Distribution::eval_many).
    #[inline]
    fn eval(&self, theta: f64) -> f64 {
        at_one(self, theta)
    }

    /// D at every θ, a block at a time in vector lanes ([`map_lanes`]).
    fn eval_many(&self, thetas: &[f64], out: &mut [f64]) {
        map_lanes(self, thetas, out)
    }

    /// Λ(θo) = x/(2(√(1 + x) + 1)), x = (α_tr tan θo)² (module header).
    fn lambda(&self, theta_o: f64) -> f64 {
        let x = (self.alpha_tr * theta_o.tan()).powi(2);
        x / (2.0 * ((1.0 + x).sqrt() + 1.0))
    }

    /// The same from μ = cos θo: with a = α_tr² (1 − μ)(1 + μ) = α_tr² sin²θo,
    /// Λ = a/(2μ (√(μ² + a) + μ)), one root and one division, free of cancellation; +∞ at μ = 0.
    #[inline]
    fn lambda_at_cos(&self, mu: f64) -> f64 {
        let mu = mu.clamp(0.0, 1.0);
        let a = self.alpha2 * ((1.0 - mu) * (1.0 + mu));
        a / (2.0 * mu * ((mu * mu + a).sqrt() + mu))
    }

    /// None: D falls monotonically from its peak at θ = 0 (or rises to θ = π/2).
    fn interior_peak(&self) -> Option<f64> {
        None
    }

    /// False: D → α_tr²/π at grazing.
    fn unbounded_at_grazing(&self) -> bool {
        false
    }

    /// α_tr (the notebook's rough equivalence α_tr = α_b, docs/maths.md "Parameter equivalences and fits").
    fn beckmann_equivalent_alpha(&self) -> Option<f64> {
        Some(self.alpha_tr)
    }

    fn params(&self) -> Vec<f64> {
        vec![self.alpha_tr]
    }
}
