//! Phong NDF: D(θ) = (α_p + 2)/(2π) · cos^{α_p} θ (docs/maths.md "Phong", after Blinn 1977 with the projected-area
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
//! - Smith Λ, exactly: Phong's slope distribution is Student's t (Ribardière et al. 2017) with γ = (α_p + 4)/2,
//!   so its marginal slope density is P₂(q) = Γ(β)/(√π Γ(β − ½)) (1 + q²)^{−β} with β = (α_p + 3)/2, and
//!   Λ = (1/μ̃) ∫_{μ̃}^∞ (q − μ̃) P₂(q) dq, μ̃ = cot θo (docs/maths.md's incomplete-beta form). That form subtracts two
//!   nearly equal terms wherever Λ is a far tail (they cancel by ~(α_p + 3) cos²θo), and the incomplete beta's
//!   continued fraction needs ~√α_p terms near its switch point, so ndfplot integrates the excess itself:
//!   substituting 1 + q² = (1 + μ̃²)(1 + y) and y = e^σ − 1,
//!   Λ = Γ(p + ½)/(2√π Γ(p)) · tan θo · sin^{2k}θo · ∫₀^∞ e^{−kσ} b(expm1(σ)/cos²θo) dσ,
//!   p = (α_p + 2)/2, k = β − 1 = (α_p + 1)/2, b(v) = 1 − (1 + v)^{−½} = v/(√(1 + v)(√(1 + v) + 1)) ∈ [0, 1):
//!   an integral of a positive, bounded, smooth integrand (verified against the incomplete-beta form with
//!   mpmath). It lives on the scales 1/k (the decay), ln(1 + cos²θo) (where b turns from linear to 1) and
//!   |ln sin²θo| (the distance to its singularity at σ = ln sin²θo < 0), so it is split geometrically from a
//!   sixteenth of the smallest of them to σ_max = (40 + ln(1 + 2k cos²θo))/k (beyond which the rest is below
//!   e^{−40} of the whole) and each panel takes the 16-point Gauss–Legendre rule: ~1e-15, ~100 evaluations
//!   at ordinary θo. Γ(p + ½)/Γ(p) is [`gamma_half_ratio`], sin^{2k}θo = exp(k ln sin²θo) with
//!   ln sin²θo = log1p(−cos²θo) above 45°. α_p = 0 (k = ½) is the uniform lobe's Λ; every finite α_p works
//!   (the integral's scale shrinks as 1/k). Λ(0) = 0; at θo = FRAC_PI_2 Λ is large but finite.

use super::Distribution;
use crate::model::domain::{Bound, DomainError, Param};
use crate::model::math::elementary::{self, Lanewise, at_one, map_lanes};
use crate::model::math::gauss_legendre;
use crate::model::math::special::gamma_half_ratio;
use std::f64::consts::{FRAC_PI_4, PI};

/// Ratio of successive panel ends in Λ's integral (module header).
const LAMBDA_PANEL_RATIO: f64 = 4.0;

/// Λ's integral starts its geometric split this many ratios below its smallest scale.
const LAMBDA_PANEL_DEPTH: i32 = 2;

/// e^{−this} bounds the relative size of the integral's tail cut off at σ_max.
const LAMBDA_TAIL_EXPONENT: f64 = 40.0;

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

impl Lanewise for Phong {
    /// D(θ) = (α_p + 2)/(2π) · cos^{α_p} θ for θ ∈ [0, π/2], normalized over projected area, in the stable
    /// form of the module header with tan θ = sin θ/cos θ.
    #[inline(always)]
    fn at(&self, theta: f64) -> f64 {
        let tan_theta = elementary::tan(theta);
        let tan2_theta = tan_theta * tan_theta;
        elementary::exp(
            self.ln_inv_normalization - 0.5 * self.alpha_p * elementary::ln_1p(tan2_theta),
        )
    }
}

impl Distribution for Phong {
    const NAME: &'static str = "phong";
    const TITLE: &'static str = "Phong";
    const PARAMS: &'static [Param] = &[ALPHA_P];
    const COLOUR: u32 = 0xDE3255;
    const LAMBDA_CLOSED_FORM: bool = true;
    /// α_p = 2/α_b² − 2 of the notebook's α_b = 0.3 (docs/maths.md, Walter et al. 2007).
    const EXAMPLE: &'static [f64] = &[2.0 / (0.3 * 0.3) - 2.0];
    const PAGE_FORMULA: &'static str = include_str!("phong.js");

    fn from_params(params: &[f64]) -> Result<Self, DomainError> {
        Phong::new(params[0])
    }

    /// The uniform lobe, which α_p = 0 is (inside the domain, so a table computes it as it is).
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

    /// Λ(θo) by the Student-t identity (module header).
    fn lambda(&self, theta_o: f64) -> f64 {
        if theta_o <= 0.0 {
            return 0.0;
        }
        let k = 0.5 * (self.alpha_p + 1.0);
        let cos2 = theta_o.cos().powi(2);
        let ln_sin2 = if theta_o < FRAC_PI_4 {
            2.0 * theta_o.sin().ln()
        } else {
            (-cos2).ln_1p()
        };
        let excess = student_t_excess(k, cos2, -ln_sin2);
        let prefactor = gamma_half_ratio(k + 0.5) * theta_o.tan() * excess / (2.0 * PI.sqrt());
        let exponent = k * ln_sin2;
        if exponent > f64::MIN_POSITIVE.ln() {
            prefactor * exponent.exp()
        } else {
            (exponent + prefactor.ln()).exp()
        }
    }

    /// None: D falls monotonically from its peak at θ = 0 (or rises to θ = π/2).
    fn interior_peak(&self) -> Option<f64> {
        None
    }

    /// False: cos^{α_p}θ/N is bounded by its value at θ = 0 (α_p ≥ 0).
    fn unbounded_at_grazing(&self) -> bool {
        false
    }

    /// √(2/(α_p + 2)) (Walter et al. 2007; bbm's a = √(α_p/2 + 1) cot θo).
    fn beckmann_equivalent_alpha(&self) -> Option<f64> {
        Some((2.0 / (self.alpha_p + 2.0)).sqrt())
    }

    fn params(&self) -> Vec<f64> {
        vec![self.alpha_p]
    }
}

/// ∫₀^∞ e^{−kσ} b(expm1(σ)/z) dσ, b(v) = 1 − (1 + v)^{−½}, for k > 0, z = cos²θo ∈ (0, 1] and
/// `neg_ln_x` = −ln sin²θo (module header): geometric panels of the 16-point Gauss–Legendre rule.
fn student_t_excess(k: f64, z: f64, neg_ln_x: f64) -> f64 {
    let b = |sigma: f64| {
        let v = sigma.exp_m1() / z;
        let root = (1.0 + v).sqrt();
        if v > 1.0 { 1.0 - 1.0 / root } else { v / (root * (root + 1.0)) }
    };
    let integrand = |sigma: f64| (-k * sigma).exp() * b(sigma);
    let scale = (1.0 / k).min(z.ln_1p()).min(neg_ln_x);
    let end = (LAMBDA_TAIL_EXPONENT + (2.0 * k * z).ln_1p()) / k;
    let mut lo = scale.min(end) * LAMBDA_PANEL_RATIO.powi(-LAMBDA_PANEL_DEPTH);
    let mut sum = gauss_legendre::integrate(integrand, 0.0, lo);
    while lo < end {
        let hi = (lo * LAMBDA_PANEL_RATIO).min(end);
        sum += gauss_legendre::integrate(integrand, lo, hi);
        lo = hi;
    }
    sum
}
