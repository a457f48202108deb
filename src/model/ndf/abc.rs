//! ABC NDF (Low, Kronander, Ynnerman & Unger 2012): u(θ) = (1 + a₁ (1 − cos θ))^{−a₂}, D = u/N, with
//! a₁ = `alpha_abc1` (roughness) and a₂ = `alpha_abc2` (shape: ≈ 1.75 mimics Trowbridge–Reitz, a₂ → ∞ Phong).
//!
//! - Domain: 0 < a₁ ≤ 1e100, 0 < a₂ ≤ 1e100. Every positive a₁ works (a₁ → 0 is uniform); the caps keep
//!   e^{(2 − a₂) ln(1 + a₁)} ≤ 1e200 and D(0) = 1/N ≲ a₁ a₂/(2π) finite. Stated once, with these reasons,
//!   in [`Abc::PARAMS`](super::Distribution::PARAMS).
//! - Normalization (docs/maths.md), with U = 1 + a₁, L = ln U = log1p(a₁) and c = (2 − a₂) L:
//!   N = 2π ∫₀¹ (1 + a₁ (1 − μ))^{−a₂} μ dμ = (2π L/a₁²) [U exprel((1 − a₂) L) − exprel((2 − a₂) L)],
//!   exact through the removable singularities a₂ = 1 and 2 (exprel(0) = 1, no ε dodge). The bracket cancels
//!   by a factor ~1/(1 − e^{−L}) as a₁ → 0, so for L ≤ 1 it is rewritten as a sum of positive terms:
//!   U exprel((1 − a₂) L) − exprel((2 − a₂) L) = Σ_{m≥1} L^m φ_{m+1}(c) (expand e^{L(1−s)} − 1 under
//!   ∫₀¹ e^{cs} ds), so N = 2π (L/a₁)² Σ_{m≥0} L^m φ_{m+2}(c), which tends to 2π φ₂(0) = π as a₁ → 0.
//! - θ → 0: D → 1/N; 1 − cos θ is taken as 2 sin²(θ/2), exact for tiny θ where 1 − cos θ rounds to 0.
//!   θ → π/2: D → (1 + a₁)^{−a₂}/N, small but positive.
//! - Stable form: D = exp(−a₂ log1p(2 a₁ sin²(θ/2)) − ln N), so that U^{−a₂} (e.g. (1e6)^{−1e4}) never
//!   under- or overflows by itself.
//! - Smith Λ: no closed form is known; docs/maths.md's 1D integral by [`crate::model::ndf::lambda_integral::lambda_integral`], within
//!   2.4e-13 of the 40-digit references (`tests/data/reference/lambda.csv`). Λ(0) = 0; Λ grows like 1/cos θo towards grazing and is large but finite
//!   at θo = FRAC_PI_2 (cos = 6.1e-17).

use super::Distribution;
use crate::model::domain::{Bound, DomainError, Param};
use crate::model::math::elementary::{self, Lanewise, at_one, map_lanes};
use crate::model::math::special::{exprel, phi};
use std::f64::consts::PI;

/// The cap of a₁ and a₂: with L = ln(1 + a₁) ≤ 230.3, exprel((2 − a₂) L) ≤ e^{460.6} and every
/// intermediate of the normalization stays finite.
const ALPHA_ABC_MAX: f64 = 1e100;

/// a₁'s domain (module header).
const ALPHA_ABC1: Param = Param {
    name: "alpha_abc1",
    symbol: "a₁",
    min: Bound::exclusive(
        0.0,
        "a₁ = 0 makes N's ln(1 + a₁)/a₁ 0/0, and a₁ < 0 a lobe rising towards grazing",
    ),
    max: Bound::inclusive(
        ALPHA_ABC_MAX,
        "N's exprel((2 − a₂) ln(1 + a₁)) nears overflow",
    ),
};

/// a₂'s domain (module header).
const ALPHA_ABC2: Param = Param {
    name: "alpha_abc2",
    symbol: "a₂",
    min: Bound::exclusive(0.0, "a₂ ≤ 0 is no lobe: u is constant or rises towards grazing"),
    max: Bound::inclusive(ALPHA_ABC_MAX, "D(0) = 1/N ≲ a₁ a₂/(2π) nears overflow"),
};

/// Largest L = ln(1 + a₁) summed as a series: there the closed form's bracket cancels by at most
/// 1/(1 − e^{−1}) ≈ 1.6, and the series needs ≲ 20 terms (L^m φ_{m+2} ≤ e²/(m + 2)!).
const SERIES_MAX_LN_U: f64 = 1.0;

/// Series terms allowed: the terms fall below ε relative within 20 for L ≤ 1 (see [`SERIES_MAX_LN_U`]).
const SERIES_MAX_TERMS: u32 = 40;

/// A validated ABC lobe with its log-normalization precomputed.
#[derive(Debug, Clone, PartialEq)]
pub struct Abc {
    alpha_abc1: f64,
    alpha_abc2: f64,
    normalization: f64,
    /// ln(1/N) = ln D(0).
    ln_peak: f64,
}

impl Abc {
    /// An ABC lobe with `alpha_abc1` = a₁ ∈ (0, 1e100] and `alpha_abc2` = a₂ ∈ (0, 1e100]; rejects NaN, ±∞ and
    /// values outside.
    pub fn new(alpha_abc1: f64, alpha_abc2: f64) -> Result<Self, DomainError> {
        ALPHA_ABC1.check(alpha_abc1)?;
        ALPHA_ABC2.check(alpha_abc2)?;
        let normalization = normalization(alpha_abc1, alpha_abc2);
        Ok(Abc {
            alpha_abc1,
            alpha_abc2,
            normalization,
            ln_peak: -normalization.ln(),
        })
    }


    /// N = 2π ∫₀^{π/2} (1 + a₁ (1 − cos θ))^{−a₂} sin θ cos θ dθ.
    pub fn normalization(&self) -> f64 {
        self.normalization
    }

    /// The roughness parameter a₁.
    pub fn alpha_abc1(&self) -> f64 {
        self.alpha_abc1
    }

    /// The shape parameter a₂.
    pub fn alpha_abc2(&self) -> f64 {
        self.alpha_abc2
    }
}

impl Lanewise for Abc {
    /// D(θ) = (1 + a₁ (1 − cos θ))^{−a₂}/N for θ ∈ [0, π/2], normalized over projected area, in the stable
    /// form of the module header.
    #[inline(always)]
    fn at(&self, theta: f64) -> f64 {
        let sin_half_theta = elementary::sin_cos(0.5 * theta).0;
        let one_minus_cos_theta = 2.0 * (sin_half_theta * sin_half_theta);
        elementary::exp(
            self.ln_peak
                - self.alpha_abc2 * elementary::ln_1p(self.alpha_abc1 * one_minus_cos_theta),
        )
    }
}

impl Distribution for Abc {
    const NAME: &'static str = "abc";
    const TITLE: &'static str = "ABC";
    const PARAMS: &'static [Param] = &[ALPHA_ABC1, ALPHA_ABC2];
    const LEGEND_PREFIX: Option<&'static str> = Some("ABC");
    const COLOUR: u32 = 0x406AFD;
    /// The notebook's match of Trowbridge–Reitz α_tr = 0.3 (docs/maths.md).
    const EXAMPLE: &'static [f64] = &[23.5, 1.75];
    const PAGE_FORMULA: &'static str = include_str!("abc.js");

    fn from_params(params: &[f64]) -> Result<Self, DomainError> {
        Abc::new(params[0], params[1])
    }

    /// The uniform lobe: (1 + a₁ (1 − cos θ))^{−a₂} → 1 as a₁ → 0, whatever a₂ (N → π).
    fn zero_limit(_others: &[f64]) -> super::ZeroLimit {
        super::ZeroLimit::Uniform
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

    /// False: D is bounded by its value at θ = 0.
    fn unbounded_at_grazing(&self) -> bool {
        false
    }

    /// None: renderers have no Beckmann equivalent for this family.
    fn beckmann_equivalent_alpha(&self) -> Option<f64> {
        None
    }

    fn params(&self) -> Vec<f64> {
        vec![self.alpha_abc1, self.alpha_abc2]
    }
}

/// N(a₁, a₂), by the positive series for L = log1p(a₁) ≤ 1 and the exprel closed form above (module header).
fn normalization(a1: f64, a2: f64) -> f64 {
    let ln_u = a1.ln_1p();
    if ln_u <= SERIES_MAX_LN_U {
        let c = (2.0 - a2) * ln_u;
        let mut sum = 0.0;
        let mut ln_u_power = 1.0;
        for m in 0..SERIES_MAX_TERMS {
            let term = ln_u_power * phi(m + 2, c);
            sum += term;
            if term <= f64::EPSILON * sum {
                break;
            }
            ln_u_power *= ln_u;
        }
        2.0 * PI * (ln_u / a1).powi(2) * sum
    } else {
        // (2π L/a₁²)[U exprel((1 − a₂)L) − exprel((2 − a₂)L)], with U/a₁ = 1 + 1/a₁ so that a₁² never forms.
        let bracket_over_a1 =
            (1.0 + 1.0 / a1) * exprel((1.0 - a2) * ln_u) - exprel((2.0 - a2) * ln_u) / a1;
        2.0 * PI * (ln_u / a1) * bracket_over_a1
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// docs/maths.md's 15-digit check values of N(a₁, a₂).
    #[test]
    fn normalization_matches_math_md_checks() {
        for (a1, a2, want) in [
            (10.0, 1.75, 0.562584587671993),
            (23.5, 1.75, 0.282172212012306),
            (0.0212, 1000.0, 0.282651269230233),
            (3.0, 0.5, 2.32710566932577),
        ] {
            let got = Abc::new(a1, a2).unwrap().normalization();
            // 15 significant digits are given: 1e-14 relative is their rounding.
            assert!(
                ((got - want) / want).abs() <= 1e-14,
                "N({a1}, {a2}) = {got}, want {want}"
            );
        }
    }

    #[test]
    fn series_and_closed_form_agree_at_the_switch() {
        let a1_switch = SERIES_MAX_LN_U.exp_m1();
        for a2 in [1e-3, 0.5, 1.0, 1.75, 2.0, 10.0, 1e4] {
            let series = normalization(a1_switch, a2);
            let closed = normalization(a1_switch * (1.0 + 4.0 * f64::EPSILON), a2);
            assert!(
                ((series - closed) / closed).abs() <= 1e-14,
                "a2 = {a2}: {series} vs {closed}"
            );
        }
    }

    #[test]
    fn tends_to_uniform_as_a1_vanishes() {
        for a2 in [1e-3, 1.0, 2.0, 1e4] {
            assert!((normalization(1e-300, a2) / PI - 1.0).abs() <= 4.0 * f64::EPSILON);
        }
    }

    #[test]
    fn rejects_out_of_domain_parameters() {
        assert!(Abc::new(0.0, 1.0).is_err());
        assert!(Abc::new(1.0, 0.0).is_err());
        assert!(Abc::new(1.0, f64::NAN).is_err());
        assert!(Abc::new(f64::INFINITY, 1.0).is_err());
        assert!(Abc::new(1e101, 1.0).is_err());
        assert!(Abc::new(1e100, 1e100).is_ok());
    }
}
