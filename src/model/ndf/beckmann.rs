//! Beckmann NDF: D(θ) = exp(−tan²θ/α_b²) / (π α_b² cos⁴θ) (docs/maths.md "Beckmann"; Beckmann & Spizzichino 1963,
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
//! - Smith Λ (Walter et al. 2007, Heitz 2014): with a = cot θo/α_b, Λ = e^{−a²}/(2a√π) − erfc(a)/2
//!   = e^{−a²} [1/(2a√π) − erfcx(a)/2] (erfcx(a) = e^{a²} erfc(a), scaled, never erf(a) − 1, which loses
//!   everything by a ≈ 8). The bracket still cancels by ~2a² (≤ 128, ~3e-14, below a = 8); from a = 8 on it is
//!   its asymptotic series (1/(2a√π)) Σ_{k≥1} (−1)^{k+1} (2k − 1)!!/(2a²)^k, alternating with terms falling
//!   at least 128/17-fold at first, truncated at ε. e^{−a²} carries the rounding of a² (a fused multiply-add
//!   recovers it), so Λ is a far tail that stays representable down to a ≈ 27 (α_b = 0.1, θo = 30°:
//!   1.39e-135), and 0 from a = 40 on. Λ(0) = 0; at θo = FRAC_PI_2, a = 6.1e-17/α_b and Λ ≈ 1/(2a√π) is
//!   large but finite.

use super::Distribution;
use crate::model::domain::{Bound, DomainError, Param};
use crate::model::math::elementary::{self, Lanewise, at_one, map_lanes};
use errorfunctions::RealErrorFunctions;
use std::f64::consts::PI;

/// From this a = cot θo/α_b on, Λ's bracket is summed as its asymptotic series (module header).
const LAMBDA_SERIES_MIN_A: f64 = 8.0;

/// From this a on, Λ < e^{−a²}/(4a³√π) < 1e-700 is 0 in doubles.
const LAMBDA_ZERO_MIN_A: f64 = 40.0;

/// The asymptotic series' terms: at a ≥ 8 they reach ε relative within ~25.
const LAMBDA_SERIES_MAX_TERMS: u32 = 60;

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

impl Lanewise for Beckmann {
    /// D(θ) = exp(−tan²θ/α_b²)/(π α_b² cos⁴θ) for θ ∈ [0, π/2], normalized over projected area, in the log
    /// form of the module header.
    #[inline(always)]
    fn at(&self, theta: f64) -> f64 {
        let tan_theta = elementary::tan(theta);
        let tan2_theta = tan_theta * tan_theta;
        let slope = tan_theta / self.alpha_b;
        elementary::exp(self.ln_peak - slope * slope + 2.0 * elementary::ln_1p(tan2_theta))
    }
}

impl Distribution for Beckmann {
    const NAME: &'static str = "beckmann";
    const TITLE: &'static str = "Beckmann";
    const PARAMS: &'static [Param] = &[ALPHA_B];
    const COLOUR: u32 = 0x3C96DF;
    const LAMBDA_CLOSED_FORM: bool = true;
    const EXAMPLE: &'static [f64] = &[0.3];
    const PAGE_FORMULA: &'static str = include_str!("beckmann.js");

    fn from_params(params: &[f64]) -> Result<Self, DomainError> {
        Beckmann::new(params[0])
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

    /// Λ(θo) = e^{−a²} [1/(2a√π) − erfcx(a)/2], a = cot θo/α_b (see [`smith_lambda`]).
    fn lambda(&self, theta_o: f64) -> f64 {
        smith_lambda(self.alpha_b, theta_o)
    }

    /// Λ at a = μ/(α_b √((1 − μ)(1 + μ))), μ = cos θo.
    fn lambda_at_cos(&self, mu: f64) -> f64 {
        let mu = mu.clamp(0.0, 1.0);
        lambda_of_a(mu / (self.alpha_b * ((1.0 - mu) * (1.0 + mu)).sqrt()))
    }

    /// A super-rough lobe (α_b > 1/√2) peaks off the normal where d ln D/d tan²θ = 2/(1 + tan²θ) − 1/α_b²
    /// vanishes: tan²θ = 2α_b² − 1.
    fn interior_peak(&self) -> Option<f64> {
        (self.alpha_b > std::f64::consts::FRAC_1_SQRT_2)
            .then(|| (2.0 * self.alpha_b.powi(2) - 1.0).sqrt().atan())
    }

    /// False: D → 0 at grazing: e^{−tan²θ/α_b²} beats 1/cos⁴θ.
    fn unbounded_at_grazing(&self) -> bool {
        false
    }

    /// α_b itself.
    fn beckmann_equivalent_alpha(&self) -> Option<f64> {
        Some(self.alpha_b)
    }

    fn params(&self) -> Vec<f64> {
        vec![self.alpha_b]
    }
}

/// Smith's Λ(θo) of a Beckmann lobe of RMS slope `alpha_b` > 0, for θo ∈ [0, π/2] (module header): also the
/// Λ of the Beckmann-equivalent lobes engines substitute for other families, whose α may lie outside
/// [`Beckmann::PARAMS`](Distribution::PARAMS) (Phong's √(2/(α_p + 2)) reaches 1e-154).
pub fn smith_lambda(alpha_b: f64, theta_o: f64) -> f64 {
    lambda_of_a(1.0 / (alpha_b * theta_o.tan()))
}

/// Λ = e^{−a²} [1/(2a√π) − erfcx(a)/2] at a = cot θo/α_b ≥ 0 (+∞ at a = 0, grazing).
fn lambda_of_a(a: f64) -> f64 {
    if a >= LAMBDA_ZERO_MIN_A {
        return 0.0;
    }
    let a2 = a * a;
    let gauss = (-a2).exp() * (1.0 - a.mul_add(a, -a2));
    let inv_2a_sqrt_pi = 0.5 / (a * PI.sqrt());
    let bracket = if a < LAMBDA_SERIES_MIN_A {
        inv_2a_sqrt_pi - 0.5 * a.erfcx()
    } else {
        let mut term = 1.0;
        let mut sum = 0.0;
        for k in 1..=LAMBDA_SERIES_MAX_TERMS {
            term *= f64::from(2 * k - 1) / (2.0 * a2);
            sum += if k % 2 == 1 { term } else { -term };
            if term <= f64::EPSILON * sum {
                break;
            }
        }
        inv_2a_sqrt_pi * sum
    };
    gauss * bracket
}
