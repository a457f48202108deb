//! Shifted Gamma Distribution NDF (Bagher, Soler, Holzschuch 2012), with a₁ = `alpha_sgd1`, a₂ = `alpha_sgd2`
//! and x = tan²θ:
//! p₂₂(x) = a₁^{a₂−1} e^{−(a₁² + x)/a₁} / (Γ(1 − a₂, a₁) (a₁² + x)^{a₂}),   D(θ) = p₂₂(tan²θ)/(π cos⁴θ).
//!
//! - Domain: 1e-6 ≤ a₁ ≤ 1e6, −10 ≤ a₂ ≤ 10 (a₂ = 0 and the notebook's 0 … 1.5 included). Γ(s, a₁) with
//!   s = 1 − a₂ ∈ [−9, 11] is computed to ~1e-15 there (checked against mpmath), D(0) ≲ a₁^{−a₂−1} ≤ 1e66
//!   stays finite, and the grazing lobe of large a₁ (tan θ ~ √a₁ ≤ 1e3) is resolved by θ in double precision.
//!   Stated once, with these reasons, in [`Sgd::PARAMS`](super::Distribution::PARAMS).
//! - Normalization: ∫₀^∞ p₂₂(x) dx = 1 exactly (substitute t = (a₁² + x)/a₁: the integral is
//!   a₁^{a₂−1} a₁^{1−a₂} Γ(1 − a₂, a₁)/Γ(1 − a₂, a₁)), and the projected-area integral of p₂₂(tan²θ)/(π cos⁴θ)
//!   is that same integral (dx = 2 tan θ/cos²θ dθ), so N = 1 and D = p₂₂/(π cos⁴θ) as written.
//! - θ → 0: D → a₁^{−a₂−1} e^{−a₁}/(π Γ(1 − a₂, a₁)). θ → π/2: e^{−x/a₁} beats the growth of 1/cos⁴θ and
//!   D → 0; at the double nearest π/2 it is exactly 0.
//! - Stable form: all in log space. e^{−a₁}/Γ(1 − a₂, a₁) is formed as 1/(e^{a₁} Γ(1 − a₂, a₁)), whose factors
//!   alone under- and overflow for large a₁; (a₁² + x)^{−a₂} = a₁^{−2a₂} (1 + x/a₁²)^{−a₂} via log1p;
//!   1/cos⁴θ = (1 + x)² via log1p. Then ln D = ln D(0) − x/a₁ − a₂ log1p(x/a₁²) + 2 log1p(x).
//! - Smith Λ: no closed form is known; docs/maths.md's 1D integral by [`crate::model::ndf::lambda_integral::lambda_integral`], within
//!   2.4e-13 of the 40-digit references (`tests/data/reference/lambda.csv`). Λ(0) = 0; Λ grows like 1/cos θo towards grazing and is large but finite
//!   at θo = FRAC_PI_2 (cos = 6.1e-17).

use super::Distribution;
use crate::model::domain::{Bound, DomainError, Param};
use crate::model::math::elementary::{self, Lanewise, at_one, map_lanes};
use crate::model::math::special::upper_gamma_scaled;
use std::f64::consts::PI;

/// a₁'s domain (module header).
const ALPHA_SGD1: Param = Param {
    name: "alpha_sgd1",
    symbol: "a₁",
    min: Bound::inclusive(1e-6, "D(0) ≲ a₁^(−a₂−1) passes 1e66"),
    max: Bound::inclusive(
        1e6,
        "the grazing lobe (tan θ ~ √a₁) is unresolved by θ in double precision",
    ),
};

/// The reason for both bounds of a₂.
const ALPHA_SGD2_REASON: &str = "Γ(1 − a₂, a₁) is verified to ~1e-15 for 1 − a₂ in [−9, 11] only";

/// a₂'s domain (module header).
const ALPHA_SGD2: Param = Param {
    name: "alpha_sgd2",
    symbol: "a₂",
    min: Bound::inclusive(-10.0, ALPHA_SGD2_REASON),
    max: Bound::inclusive(10.0, ALPHA_SGD2_REASON),
};

/// A validated SGD lobe with its log-normalization precomputed.
#[derive(Debug, Clone, PartialEq)]
pub struct Sgd {
    alpha_sgd1: f64,
    alpha_sgd2: f64,
    /// ln D(0) = −(a₂ + 1) ln a₁ − ln(e^{a₁} Γ(1 − a₂, a₁)) − ln π.
    ln_peak: f64,
}

impl Sgd {
    /// An SGD lobe with `alpha_sgd1` = a₁ ∈ [1e-6, 1e6] and `alpha_sgd2` = a₂ ∈ [−10, 10]; rejects NaN, ±∞
    /// and values outside.
    pub fn new(alpha_sgd1: f64, alpha_sgd2: f64) -> Result<Self, DomainError> {
        ALPHA_SGD1.check(alpha_sgd1)?;
        ALPHA_SGD2.check(alpha_sgd2)?;
        let scaled_gamma = upper_gamma_scaled(1.0 - alpha_sgd2, alpha_sgd1);
        let ln_peak = -(alpha_sgd2 + 1.0) * alpha_sgd1.ln() - scaled_gamma.ln() - PI.ln();
        Ok(Sgd {
            alpha_sgd1,
            alpha_sgd2,
            ln_peak,
        })
    }


    /// N = 1: p₂₂ is a probability density in x = tan²θ, which makes D normalized as it stands.
    pub fn normalization(&self) -> f64 {
        1.0
    }

    /// The parameter a₁.
    pub fn alpha_sgd1(&self) -> f64 {
        self.alpha_sgd1
    }

    /// The parameter a₂.
    pub fn alpha_sgd2(&self) -> f64 {
        self.alpha_sgd2
    }
}

impl Lanewise for Sgd {
    /// D(θ) = p₂₂(tan²θ)/(π cos⁴θ) for θ ∈ [0, π/2], normalized over projected area, in the log form of the
    /// module header.
    #[inline(always)]
    fn at(&self, theta: f64) -> f64 {
        let tan_theta = elementary::tan(theta);
        let tan2_theta = tan_theta * tan_theta;
        let slope = tan_theta / self.alpha_sgd1;
        elementary::exp(
            self.ln_peak
                - tan2_theta / self.alpha_sgd1
                - self.alpha_sgd2 * elementary::ln_1p(slope * slope)
                + 2.0 * elementary::ln_1p(tan2_theta),
        )
    }
}

impl Distribution for Sgd {
    const NAME: &'static str = "sgd";
    const TITLE: &'static str = "SGD";
    const PARAMS: &'static [Param] = &[ALPHA_SGD1, ALPHA_SGD2];
    const LEGEND_PREFIX: Option<&'static str> = Some("SGD");
    const COLOUR: u32 = 0xB78A02;
    /// One of the notebook's sgd-grid curves, as the numpy peer times it.
    const EXAMPLE: &'static [f64] = &[0.2, 0.5];
    const PAGE_FORMULA: &'static str = include_str!("sgd.js");

    fn from_params(params: &[f64]) -> Result<Self, DomainError> {
        Sgd::new(params[0], params[1])
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

    /// With x = tan²θ, d ln D/dx = −1/a₁ − a₂/(a₁² + x) + 2/(1 + x) has the sign of −(x² + Bx + C),
    /// B = (1 − a₁)² + a₁a₂, C = a₁(a₁ + a₂ − 2a₁²): D has an off-normal maximum at the larger root
    /// x₊ of x² + Bx + C when it is real and positive (always when C < 0, i.e. D rises from θ = 0).
    /// x₊ is formed without cancellation: (−B + √Δ)/2 for B < 0, else −2C/(B + √Δ).
    fn interior_peak(&self) -> Option<f64> {
        let (a1, a2) = (self.alpha_sgd1, self.alpha_sgd2);
        let b = (1.0 - a1).powi(2) + a1 * a2;
        let c = a1 * (a1 + a2 - 2.0 * a1 * a1);
        let discriminant = b * b - 4.0 * c;
        if !(discriminant > 0.0) {
            return None;
        }
        let root = discriminant.sqrt();
        let x = if b < 0.0 { (root - b) / 2.0 } else { -2.0 * c / (b + root) };
        (x > 0.0 && x.is_finite()).then(|| x.sqrt().atan())
    }

    /// False: D → 0 at grazing: e^{−tan²θ/a₁} beats 1/cos⁴θ.
    fn unbounded_at_grazing(&self) -> bool {
        false
    }

    /// None: renderers have no Beckmann equivalent for this family.
    fn beckmann_equivalent_alpha(&self) -> Option<f64> {
        None
    }

    fn params(&self) -> Vec<f64> {
        vec![self.alpha_sgd1, self.alpha_sgd2]
    }
}
