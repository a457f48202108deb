//! Torrance–Sparrow NDF (Gaussian in angle): D(θ) = exp(−(θ/α_ts)²) / N(α_ts) (docs/maths.md "Torrance–Sparrow";
//! Torrance & Sparrow 1967).
//!
//! - Domain: 1e-150 ≤ α_ts ≤ 1e150. Below, N ≈ π α_ts² leaves the normal double range and D(0) = 1/N heads for
//!   overflow; above, Dawson's F(α_ts) ≈ 1/(2 α_ts) would approach the subnormal range. (Past α_ts ≈ 1e8 the
//!   lobe is uniform, D = 1/π, to double precision.) Stated once, with these reasons, in
//!   [`TorranceSparrow::PARAMS`](super::Distribution::PARAMS).
//! - Normalization: N(α) = 2π ∫₀^{π/2} exp(−θ²/α²) sin θ cos θ dθ
//!   = π α [F(α) + (√π/2) e^{−π²/(4α²)} Im w(α + iπ/(2α))], with F Dawson's integral and w the Faddeeva
//!   function: the first term is the integral over [0, ∞), the second removes (π/2, ∞). Both terms are
//!   positive, so the sum does not cancel; for α ≲ 0.25 the second is below 1e-17 of the first, for α → ∞ each tends to
//!   1/(2α) and N → π. Mathematica's form with e^{−α²} erfi(α) breaks down above α ≈ 26.6 (0 · ∞).
//! - θ → 0: D → 1/N ≈ 1/(π α²) for small α. θ → π/2: D → exp(−(π/(2α))²)/N, exactly 0 for small α.
//! - Stable form: D = exp(ln(1/N) − (θ/α)²) in one exponential, so that exp(−(θ/α)²) cannot underflow while
//!   D itself is still representable (1/N reaches 3e299).
//! - Smith Λ: no closed form is known; docs/maths.md's 1D integral by [`crate::model::ndf::lambda_integral::lambda_integral`], within
//!   2.4e-13 of the 40-digit references (`tests/data/reference/lambda.csv`). Λ(0) = 0; Λ grows like 1/cos θo towards grazing and is large but finite
//!   at θo = FRAC_PI_2 (cos = 6.1e-17).

use super::Distribution;
use crate::model::domain::{Bound, DomainError, Param};
use crate::model::math::elementary::{self, Lanewise, at_one, map_lanes};
use errorfunctions::{ComplexErrorFunctions, RealErrorFunctions};
use num_complex::Complex;
use std::f64::consts::{FRAC_PI_2, PI};

/// α_ts's domain. At 1e-150, N ≈ π α_ts² ≈ 3e-300 stays a normal double and D(0) = 1/N is finite;
/// at 1e150, F(α_ts) ≈ 1/(2 α_ts) ≥ 5e-151 stays a normal double.
const ALPHA_TS: Param = Param {
    name: "alpha_ts",
    symbol: "α_{ts}",
    min: Bound::inclusive(1e-150, "D(0) ≈ 1/(π alpha_ts²) overflows"),
    max: Bound::inclusive(
        1e150,
        "Dawson's F(alpha_ts) ≈ 1/(2 alpha_ts) in N nears the subnormal range",
    ),
};

/// A validated Torrance–Sparrow lobe with its log-normalization precomputed.
#[derive(Debug, Clone, PartialEq)]
pub struct TorranceSparrow {
    alpha_ts: f64,
    normalization: f64,
    /// ln(1/N) = ln D(0).
    ln_peak: f64,
}

impl TorranceSparrow {
    /// A Gaussian-in-angle lobe of width `alpha_ts` ∈ [1e-150, 1e150]; rejects NaN, ±∞ and values outside.
    pub fn new(alpha_ts: f64) -> Result<Self, DomainError> {
        ALPHA_TS.check(alpha_ts)?;
        let normalization = normalization(alpha_ts);
        Ok(TorranceSparrow {
            alpha_ts,
            normalization,
            ln_peak: -normalization.ln(),
        })
    }


    /// N(α_ts) = 2π ∫₀^{π/2} exp(−θ²/α_ts²) sin θ cos θ dθ.
    pub fn normalization(&self) -> f64 {
        self.normalization
    }

    /// The angular width α_ts (radians).
    pub fn alpha_ts(&self) -> f64 {
        self.alpha_ts
    }
}

impl Lanewise for TorranceSparrow {
    /// D(θ) = exp(−(θ/α_ts)²)/N(α_ts) for θ ∈ [0, π/2], normalized over projected area, in one exponential.
    #[inline(always)]
    fn at(&self, theta: f64) -> f64 {
        let ratio = theta / self.alpha_ts;
        elementary::exp(self.ln_peak - ratio * ratio)
    }
}

impl Distribution for TorranceSparrow {
    const NAME: &'static str = "torrance_sparrow";
    const TITLE: &'static str = "Torrance–Sparrow";
    const PARAMS: &'static [Param] = &[ALPHA_TS];
    const COLOUR: u32 = 0x834D02;
    /// The notebook's peak match of Phong at α_b = 0.3 (docs/maths.md).
    const EXAMPLE: &'static [f64] = &[0.3097];
    const PAGE_FORMULA: &'static str = include_str!("torrance_sparrow.js");

    fn from_params(params: &[f64]) -> Result<Self, DomainError> {
        TorranceSparrow::new(params[0])
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

    /// Λ(θo) by docs/maths.md's 1D integral ([`crate::model::ndf::lambda_integral::lambda_integral`]): no closed form is known.
    fn lambda(&self, theta_o: f64) -> f64 {
        crate::model::ndf::lambda_integral::lambda_integral(&super::FamilyDensity(self), theta_o)
    }

    /// None: D falls monotonically from its peak at θ = 0 (or rises to θ = π/2).
    fn interior_peak(&self) -> Option<f64> {
        None
    }

    /// False: e^{−θ²/α_ts²}/N is bounded by its value at θ = 0.
    fn unbounded_at_grazing(&self) -> bool {
        false
    }

    /// α_ts (the notebook's rough equivalence α_ts = α_b, docs/maths.md "Parameter equivalences and fits").
    fn beckmann_equivalent_alpha(&self) -> Option<f64> {
        Some(self.alpha_ts)
    }

    fn params(&self) -> Vec<f64> {
        vec![self.alpha_ts]
    }
}

/// N(α) = π α [F(α) + (√π/2) e^{−y²} Im w(α + i y)] with y = π/(2α) (docs/maths.md).
///
/// Derivation: 2 sin θ cos θ = sin 2θ and ∫₀^∞ e^{−θ²/α²} sin 2θ dθ = α F(α) (DLMF 7.7.6 family); the tail
/// over (π/2, ∞) is −α (√π/2) e^{−y²} Im w(α + i y) (docs/maths.md; both checked against 50-digit quadrature).
fn normalization(alpha: f64) -> f64 {
    let y = FRAC_PI_2 / alpha;
    let tail = if y * y > TAIL_EXPONENT_NEGLIGIBLE {
        0.0
    } else {
        0.5 * PI.sqrt() * (-y * y).exp() * Complex::new(alpha, y).w().im
    };
    PI * alpha * (alpha.dawson() + tail)
}

/// Above this y², e^{−y²} < 1e-326 underflows to 0 and the tail term vanishes; skipping it also avoids
/// evaluating w at |z| = y ≈ 1e150 for the smallest α.
const TAIL_EXPONENT_NEGLIGIBLE: f64 = 750.0;
