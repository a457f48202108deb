//! Student-t slope distribution, STD (Ribardière, Bringier, Meneveaux, Simonot 2017;
//! docs/maths.md "Student-t slope distribution (STD)"): with α = `alpha_std`, γ = `gamma_std`, t = tan²θ/α²,
//! D(θ) = (γ − 1)^γ / (π α² cos⁴θ (γ − 1 + t)^γ) = (1 + t/(γ − 1))^{−γ} / (π α² cos⁴θ).
//! The slopes follow a 2D Student t; γ = 2 is Trowbridge–Reitz with α_tr = α, γ → ∞ is Beckmann with α_b = α, and
//! Phong with exponent n is γ = (n + 4)/2, α = √(2/(n + 2)).
//!
//! - Domain: 1e-150 ≤ α ≤ 1e4 and every finite γ > 1.5, stated once with the reasons in
//!   [`StudentT::PARAMS`](super::Distribution::PARAMS). D is a distribution for every γ > 1, but the 1D slope
//!   marginal's tail is q^{1−2γ}: Smith's Λ (its first moment) is finite only for γ > 1.5 (Λ ~ 1/(2γ − 3) as γ → 1.5).
//!   α's bounds are Beckmann's and Trowbridge–Reitz's, for the same reasons. No upper bound on γ: the forms below
//!   tend to Beckmann without overflow or cancellation, up to γ = f64::MAX.
//! - Normalization (projected area): ∫ P₂₂(x̃) dx̃ = 1 for γ > 1 (substitute ρ = |x̃|²/(α²(γ − 1))), so D needs no
//!   computed constant; D(0) = 1/(π α²) for every γ.
//! - Shape: with u = tan²θ, ln D = const + 2 ln(1 + u) − γ ln(1 + u/s²), s² = α²(γ − 1), whose slope at u = 0 is
//!   2 − γ/s². D is non-increasing exactly when γ ≥ 2 and s² ≤ γ/2. For γ > 2 and s² > γ/2 the maximum leaves
//!   θ = 0 for tan²θ* = (2s² − γ)/(γ − 2) (Beckmann's 2α² − 1 as γ → ∞; see
//!   [`interior_peak`](Distribution::interior_peak)). For γ ≤ 2 and s² > γ/2, D rises all the way to grazing; for
//!   γ < 2 and s² < γ/2 it has a maximum at 0, a minimum at tan²θ = (γ − 2s²)/(2 − γ), and rises again.
//! - θ → 0: D → 1/(π α²). θ → π/2: D ≈ (γ − 1)^γ α^{2γ−2} cos^{2γ−4}θ / π, so D(π/2) is 0 for γ > 2, α²/π for
//!   γ = 2 (Trowbridge–Reitz) and +∞ for γ < 2 (still integrable: D sin θ cos θ ~ cos^{2γ−3}θ, γ > 1). At the
//!   double nearest π/2 (cos θ = 6.12e-17, not 0) D is finite: ≤ ~2e19 for γ → 1.5 and α = 1e4, and what is
//!   returned there, as for the other families; the exact limits never reach `eval`.
//! - Stable form: D = (1 + u/s²)^{2−γ} / (π Q²), Q = α cos²θ + sin²θ/(α (γ − 1)) (from (1 + tan²θ)/(1 + u/s²) =
//!   s²/(s² cos²θ + sin²θ)). Q is a sum of non-negative terms, and at γ = 2 D = 1/(π Q²) is Trowbridge–Reitz's
//!   rational form, with no exponential at all (exact to a few ulps, where ln D would carry |ln D| ulps: up to 690 at
//!   α = 1e-150). The power (1 + v²)^{2−γ}, v = tan θ/(α √(γ − 1)), is exp(e) with
//!   e = −((γ − 2)/(γ − 1)) r² ln_1p(v²)/v² for v < 1 (r = tan θ/α; ln_1p(v²)/v² → 1 without v² ever being
//!   formed as a subnormal, so γ = 1e8 … f64::MAX reach Beckmann's exp(−r²) exactly), and
//!   e = −(γ − 2) ln_1p(v²) beyond (2 ln v when v² would overflow). |e| is D's drop from (1 + v²)^0: ≤ ~1450
//!   where D is a normal double. e is carried as an unevaluated sum hi + lo and D formed as
//!   e^{hi} (1 + lo)/(π Q²): r = sin θ/(α cos θ), v = r/√(γ − 1) and v² keep the errors of their products
//!   and quotients (fused multiply-adds, √(γ − 1) as hi + lo), ln_1p(v²) is
//!   [`elementary::ln_1p_parts`] (within 2⁻⁵⁶), and each product of e keeps its rounding error. What is left
//!   of e's relative error is that of sin θ and cos θ (< 1 ulp each, doubled in r²) and of the stored
//!   (γ − 2)/(γ − 1), so D is within a few |e| ulps at worst and a few ulps near the peak (measured against
//!   mpmath over 160 000 random (α, γ, θ): 1.8e-13 at worst and 1.3e-15 on average, where the rounded
//!   doubles of libm's tan, ln_1p and exp reach 4.0e-13 and 2.9e-15). Where 1/(π Q²) would overflow or
//!   exp(e) underflow (α ≤ 1e-150-ish at grazing, γ → ∞ at grazing), D is exp(e − 2 ln Q − ln π), with
//!   ln Q by [`elementary::ln_parts`] and the sums by TwoSum; D is then 0 or tiny, never NaN. Both routes of
//!   e and both forms of D are computed and the right ones selected, so D is one branch-free kernel in
//!   vector lanes ([`Lanewise`]).
//! - Smith Λ, closed form, derived for ndfplot from docs/maths.md's slope-space integral and checked against mpmath's
//!   quadrature of the definition and its incomplete-beta form (`student_t_reference_gen.py`). With A = cot θo/α
//!   (Beckmann's a), m = A/√(γ − 1), x = 1/m = α √(γ − 1) tan θo and w = 1/(1 + m²):
//!   Λ = x Γ(γ − ½)/(4 √π Γ(γ)) · w^{γ−3/2} · E,   E = 1/(γ − 3/2) + w G(w)/γ,   G(w) = ₂F₁(1, γ − ½; γ + 1; w).
//!   (Substituting 1 + r² = (1 + m²)/σ in (1/m) ∫_m^∞ (r − m)(1 + r²)^{½−γ} dr leaves ∫₀¹ σ^{γ−5/2} dσ minus a
//!   ₂F₁ in w; Euler's transformation and the contiguous difference of (1 − w) ₂F₁(1, γ; γ + ½; w) turn that
//!   difference into the positive sum E. docs/maths.md's incomplete-beta form, Γ(γ − ½)/(√π Γ(γ − 1)) ·
//!   w^{γ−3/2}/(2 (γ − 3/2) m) − I_w(γ − 1, ½)/2, is the same value but cancels by up to 2γ.) G is summed by one
//!   of three routes, each to a few ulps; c = 1 − w = m² w:
//!   - (a) m ≥ 1 (w ≤ ½): its series Σ_k (γ − ½)_k/(γ + 1)_k w^k, positive terms falling at least 2-fold (≤ ~55).
//!   - (b) m < 1 and (γ − ½) c ≤ 2 (near grazing, or γ near 1.5): the connection formula at 1 − w,
//!     w G/γ = 2 w F(c) − 2 √π [Γ(γ)/Γ(γ − ½)] √c w^{1−γ}, F(c) = ₂F₁(1, γ − ½; ½; c) = Σ_k (γ − ½)_k/(½)_k c^k,
//!     terms falling from k = 3 on (≤ ~70). (γ − ½) c ≤ 2 bounds the difference's cancellation (measured ≤ 7e-14);
//!     (γ − ½) c is formed as ((γ − ½)/(γ − 1)) A² w and √c as m √w, since c itself underflows near grazing when
//!     γ is huge (m ~ 1e-160 at γ = 1e300); w^{1−γ} = exp(A² ln_1p(m²)/m²) < e⁴.
//!   - (c) otherwise (the Beckmann-like body): with z = x², w G/γ = z H/γ, H = ₂F₁(1, 3/2; γ + 1; −z), by Gauss's
//!     continued fraction H = 1/(1 + k₁z/(1 + k₂z/(1 + …))) with
//!     k_{2n+1} = (n + 3/2)(γ + n)/((γ + 2n)(γ + 2n + 1)), k_{2n+2} = (n + 1)(γ − ½ + n)/((γ + 2n + 1)(γ + 2n + 2)):
//!     all k > 0, a Stieltjes fraction convergent for every z ≥ 0; modified Lentz. On this route k z stays bounded
//!     (z < (γ − ½)/2 and more), and the steps peak at ~115 where (γ − ½) c = 2 (A ≈ 1.4), for every γ up to
//!     f64::MAX; the lower the switch, the more steps (~200 at 1) and the less cancellation in (b) (1.2e-12 at 4).
//!
//!   w^{γ−3/2} is exp(−((γ − 3/2)/(γ − 1)) A² ln_1p(m²)/m²) for m < 1 (Beckmann's e^{−A²} as γ → ∞, never through
//!   a subnormal m²) and exp(−(γ − 3/2)(2 ln m + ln_1p(1/m²))) beyond; where it underflows, the product is formed in
//!   log space. Γ(γ − ½)/Γ(γ) = [`gamma_half_ratio`](γ − 1)/(γ − 1) and Γ(γ)/Γ(γ − ½) = [`gamma_half_ratio`](γ − ½),
//!   a few ulps up to γ = f64::MAX. The error is a few ulps plus Λ's own condition in θo, ~2A² ε through the
//!   rounding of tan θo (≤ 2.5e-13 where Λ is a normal double). Λ(0) = 0; Λ → +∞ as θo → π/2
//!   (Λ ≈ x Γ(γ − ½)/(2 √π Γ(γ − 1)(2γ − 3))), large but finite at θo = FRAC_PI_2 (≤ 1e35 over the domain). As
//!   γ → 1.5, Λ ~ 1/(2γ − 3) at every θo > 0: the heavy slope tail masks everything, and most of that Λ comes from
//!   microfacets closer to grazing than the double nearest π/2, which no quadrature over θ can see (the weak white
//!   furnace audit holds only from γ ≈ 2 on). γ = 2 gives Trowbridge–Reitz's Λ, γ = (n + 4)/2 with α = √(2/(n + 2))
//!   Phong's.

use super::Distribution;
use crate::model::domain::{Bound, DomainError, Param};
use crate::model::math::elementary::{self, Lanewise, at_one, map_lanes};
use crate::model::math::special::gamma_half_ratio;
use std::f64::consts::{FRAC_1_PI, PI};

/// Route (b) of Λ's ₂F₁ applies for (γ − ½) c up to this (module header): its difference cancels by a bounded
/// factor there, and beyond it the continued fraction converges in few steps.
const LAMBDA_CONNECTION_MAX: f64 = 2.0;

/// Cap on the terms of Λ's series and continued fraction: each converges in fewer than ~120 on its route.
const LAMBDA_MAX_TERMS: usize = 1000;

/// Above this v (= tan θ/(α √(γ − 1))), ln_1p(v²) is 2 ln v (v² would overflow; 1/v² < 1e-300 is negligible).
const LN_1P_SQUARE_LOG_MIN: f64 = 1e150;

/// ln of the smallest normal double, 2⁻¹⁰²²: below this exponent exp(e) is subnormal and D is formed in log space.
const LN_MIN_POSITIVE: f64 = -708.396_418_532_264_1;

/// ln π, the double nearest it.
const LN_PI: f64 = 1.144_729_885_849_400_2;

/// ln π − [`LN_PI`] (mpmath).
const LN_PI_LO: f64 = 1.026_595_116_270_782_6e-17;

/// α's domain: Beckmann's and Trowbridge–Reitz's, for their reasons. At 1e-150, α² = 1e-300 is still a normal
/// double and D(0) = 1/(π α²) ≈ 3e299 is finite. Above 1, the lobe's core (slopes ~α) sits within ~1/α rad of
/// grazing, which θ's double spacing near π/2 (2.2e-16) resolves only to ~α · 2e-16: 1e4 keeps that ≤ 2e-12.
const ALPHA_STD: Param = Param {
    name: "alpha_std",
    symbol: "α",
    min: Bound::inclusive(1e-150, "D(0) = 1/(π alpha_std²) overflows"),
    max: Bound::inclusive(1e4, "the lobe is unresolvably close to grazing"),
};

/// γ's domain. At and below 1.5 the 1D slope marginal's tail q^{1−2γ} has no finite first moment: Smith's Λ is
/// infinite at every θo > 0 (D itself stays a distribution down to γ > 1). No upper bound: D and Λ are formed
/// through (γ − 2)/(γ − 1), (γ − 3/2)/(γ − 1) and ln_1p(y)/y, which tend to Beckmann's exp(−tan²θ/α²) and
/// e^{−a²} without overflow or cancellation, so every finite γ works (STD differs from Beckmann by ~1.7e5/γ
/// relative where D is a normal double: 1.7e-3 at γ = 1e8, below 1e-12 from ~2e17 on).
const GAMMA_STD: Param = Param {
    name: "gamma_std",
    symbol: "γ",
    min: Bound::exclusive(
        1.5,
        "Smith's Lambda is infinite: the slopes' tail q^(1 - 2 gamma_std) has no mean",
    ),
    max: Bound::inclusive(
        f64::MAX,
        "every finite gamma_std works: large values tend to Beckmann without overflow",
    ),
};

/// A validated Student-t slope distribution with the constants of D and Λ precomputed.
#[derive(Debug, Clone, PartialEq)]
pub struct StudentT {
    alpha_std: f64,
    gamma_std: f64,
    /// √(γ − 1): v = tan θ/(α √(γ − 1)) and m = cot θo/(α √(γ − 1)).
    sqrt_gamma_m1: f64,
    /// √(γ − 1) − [`sqrt_gamma_m1`](Self::sqrt_gamma_m1), below half an ulp of it: D's v carries it.
    sqrt_gamma_m1_lo: f64,
    /// 1/√(γ − 1), to an ulp: D's v = r/√(γ − 1) is this product, its residual recovered.
    inv_sqrt_gamma_m1: f64,
    /// 1/(α (γ − 1)), the weight of sin²θ in Q (0 where α (γ − 1) overflows: the term is then below 1e-300 of
    /// α cos²θ).
    sin2_weight: f64,
    /// (γ − 2)/(γ − 1): D's exponent per r² ln_1p(v²)/v².
    d_exponent_ratio: f64,
    /// (γ − 3/2)/(γ − 1): Λ's exponent per A² ln_1p(m²)/m².
    lambda_exponent_ratio: f64,
    /// Γ(γ − ½)/Γ(γ), Λ's normalization.
    lambda_normalization: f64,
    /// Γ(γ)/Γ(γ − ½), route (b) of Λ.
    gamma_ratio_b: f64,
    /// (γ − ½)/(γ − 1): (γ − ½) c = this · A² w in route (b) of Λ.
    beta_ratio: f64,
}

impl StudentT {
    /// An STD lobe with `alpha_std` = α ∈ [1e-150, 1e4] and `gamma_std` = γ > 1.5 finite; rejects NaN, ±∞ and
    /// values outside.
    pub fn new(alpha_std: f64, gamma_std: f64) -> Result<Self, DomainError> {
        ALPHA_STD.check(alpha_std)?;
        GAMMA_STD.check(gamma_std)?;
        let gamma_m1 = gamma_std - 1.0;
        let sqrt_gamma_m1 = gamma_m1.sqrt();
        Ok(StudentT {
            alpha_std,
            gamma_std,
            sqrt_gamma_m1,
            inv_sqrt_gamma_m1: 1.0 / sqrt_gamma_m1,
            sqrt_gamma_m1_lo: (-sqrt_gamma_m1).mul_add(sqrt_gamma_m1, gamma_m1) / (2.0 * sqrt_gamma_m1),
            sin2_weight: 1.0 / (alpha_std * gamma_m1),
            d_exponent_ratio: (gamma_std - 2.0) / gamma_m1,
            lambda_exponent_ratio: (gamma_std - 1.5) / gamma_m1,
            lambda_normalization: gamma_half_ratio(gamma_m1) / gamma_m1,
            gamma_ratio_b: gamma_half_ratio(gamma_std - 0.5),
            beta_ratio: (gamma_std - 0.5) / gamma_m1,
        })
    }

    /// The roughness α (the Beckmann-equivalent roughness too: Beckmann's α_b as γ → ∞, Trowbridge–Reitz's α_tr at
    /// γ = 2, and Phong's √(2/(α_p + 2)) for the Phong lobe it contains).
    pub fn alpha_std(&self) -> f64 {
        self.alpha_std
    }

    /// The tail exponent γ.
    pub fn gamma_std(&self) -> f64 {
        self.gamma_std
    }
}

impl Lanewise for StudentT {
    /// D(θ) = (1 + t/(γ − 1))^{−γ}/(π α² cos⁴θ), t = tan²θ/α², for θ ∈ [0, π/2], normalized over projected
    /// area, as exp(e)/(π Q²), or exp(e − 2 ln Q − ln π) where 1/(π Q²) leaves the normal range or exp(e)
    /// underflows, with e = ln (1 + v²)^{2−γ} carried as hi + lo (module header): both routes of e and both
    /// forms of D are computed and the right ones selected.
    #[inline(always)]
    fn at(&self, theta: f64) -> f64 {
        let alpha = self.alpha_std;
        let (sin_theta, cos_theta) = elementary::sin_cos(theta);
        let q = alpha * cos_theta * cos_theta + sin_theta * sin_theta * self.sin2_weight;
        // r = tan θ/α = sin θ/(α cos θ) as r + r_lo: the product's and the quotient's residuals by fused
        // multiply-adds (so that r itself may be the product with the reciprocal, to an ulp).
        let denominator = alpha * cos_theta;
        let denominator_lo = alpha.mul_add(cos_theta, -denominator);
        let inv_denominator = 1.0 / denominator;
        let r = sin_theta * inv_denominator;
        let r_lo = ((-r).mul_add(denominator, sin_theta) - r * denominator_lo) * inv_denominator;
        // v = r/√(γ − 1) and v² as hi + lo likewise, √(γ − 1) itself as hi + lo.
        let sqrt_gamma_m1 = self.sqrt_gamma_m1;
        let v = r * self.inv_sqrt_gamma_m1;
        let v_lo = ((-v).mul_add(sqrt_gamma_m1, r) - v * self.sqrt_gamma_m1_lo + r_lo)
            * self.inv_sqrt_gamma_m1;
        let v2 = v * v;
        let v2_lo = v.mul_add(v, -v2) + 2.0 * v * v_lo;
        // ln_1p(v²) as l + l_lo, or 2 ln_1p(v) where v² would overflow (it exceeds ln_1p(v²) by
        // 2/v − 1/v² < 2e-150); for the v ≥ 1 route, plus the argument's low part to first order.
        let beyond_square = v >= LN_1P_SQUARE_LOG_MIN;
        let (l, l_lo) = elementary::ln_1p_parts(if beyond_square { v } else { v2 });
        let (argument_lo, argument) = if beyond_square {
            (v_lo, v)
        } else {
            (v2_lo, 1.0 + v2)
        };
        let l_tail_lo = l_lo + argument_lo / argument;
        let (l_tail, l_tail_lo) = if beyond_square {
            (2.0 * l, 2.0 * l_tail_lo)
        } else {
            (l, l_tail_lo)
        };
        // v < 1: e = −((γ − 2)/(γ − 1)) r² ρ with ρ = ln_1p(v²)/v² (1 at v = 0), which moves by less than
        // v²/2 times v²'s low part; divided by v², whose reciprocal overflows where v² is subnormal.
        let rho_quotient = l / v2;
        let rho_quotient_lo = ((-rho_quotient).mul_add(v2, l) + l_lo) / v2;
        let (rho, rho_lo) = if v2 == 0.0 {
            (1.0, 0.0)
        } else {
            (rho_quotient, rho_quotient_lo)
        };
        let ratio = self.d_exponent_ratio;
        let weight = ratio * rho;
        let weight_lo = ratio.mul_add(rho, -weight) + ratio * rho_lo;
        let r2 = r * r;
        let r2_lo = r.mul_add(r, -r2) + 2.0 * r * r_lo;
        let body = weight * r2;
        let body_lo = weight.mul_add(r2, -body) + (weight * r2_lo + weight_lo * r2);
        // v ≥ 1: e = −(γ − 2) ln_1p(v²).
        let gamma_m2 = self.gamma_std - 2.0;
        let tail = gamma_m2 * l_tail;
        let tail_lo = gamma_m2.mul_add(l_tail, -tail) + gamma_m2 * l_tail_lo;
        let (exponent, exponent_lo) = if v < 1.0 {
            (-body, -body_lo)
        } else {
            (-tail, -tail_lo)
        };
        let inv_q = 1.0 / q;
        let base = inv_q * inv_q * FRAC_1_PI;
        let direct =
            (f64::MIN_POSITIVE..f64::INFINITY).contains(&base) && exponent > LN_MIN_POSITIVE;
        // Log space: ln D = e − (2 ln Q + ln π), each logarithm as hi + lo, the sums by TwoSum.
        let (ln_q, ln_q_lo) = elementary::ln_parts(q);
        let (shift, shift_error) = elementary::two_sum(2.0 * ln_q, LN_PI);
        let shift_lo = shift_error + (2.0 * ln_q_lo + LN_PI_LO);
        let (ln_d, ln_d_error) = elementary::two_sum(exponent, -shift);
        let ln_d_lo = ln_d_error + (exponent_lo - shift_lo);
        let (x, x_lo) = if direct {
            (exponent, exponent_lo)
        } else {
            (ln_d, ln_d_lo)
        };
        // The low part is ≲ 1e-13 wherever exp(x) is above 0; where x is ±∞ (and the low part ∞ or NaN
        // from a product with it), it is dropped.
        let x_lo = if x_lo.abs() < 1.0 { x_lo } else { 0.0 };
        let power = elementary::exp(x);
        let power = power.mul_add(x_lo, power);
        if direct { base * power } else { power }
    }
}

impl Distribution for StudentT {
    const NAME: &'static str = "student_t";
    const TITLE: &'static str = "Student-t";
    const ALIASES: &'static [&'static str] = &["std"];
    const PARAMS: &'static [Param] = &[ALPHA_STD, GAMMA_STD];
    /// α and γ are generic symbols (GTR's too): the legend says which family they belong to.
    const LEGEND_PREFIX: Option<&'static str> = Some("STD");
    /// Solarized magenta, the one Solarized accent the other seven families leave free.
    const COLOUR: u32 = 0xD33682;
    const LAMBDA_CLOSED_FORM: bool = true;
    /// Between Trowbridge–Reitz (γ = 2) and Beckmann (γ → ∞) at the catalogue's α = 0.3.
    const EXAMPLE: &'static [f64] = &[0.3, 3.0];
    const PAGE_FORMULA: &'static str = include_str!("student_t.js");

    fn from_params(params: &[f64]) -> Result<Self, DomainError> {
        StudentT::new(params[0], params[1])
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

    /// Λ(θo) in closed form: x Γ(γ − ½)/(4√π Γ(γ)) w^{γ−3/2} (1/(γ − 3/2) + w ₂F₁(1, γ − ½; γ + 1; w)/γ) (module
    /// header).
    fn lambda(&self, theta_o: f64) -> f64 {
        if theta_o <= 0.0 {
            return 0.0;
        }
        let gamma = self.gamma_std;
        let beta = gamma - 0.5;
        let a = 1.0 / (self.alpha_std * theta_o.tan());
        let m = a / self.sqrt_gamma_m1;
        let x = 1.0 / m;
        // ln w^{γ−3/2} and w G(w)/γ, w = 1/(1 + m²), by one of the three routes. m² and c = m² w may underflow
        // (γ ~ 1e300 near grazing: m ~ 1e-160) where A = cot θo/α does not: (γ − ½) c is formed from A², √c as m √w.
        let (exponent, w_g) = if m < 1.0 {
            let m2 = m * m;
            let w = 1.0 / (1.0 + m2);
            let exponent = -self.lambda_exponent_ratio * (a * a) * ln_1p_ratio(m2);
            let beta_c = self.beta_ratio * (a * a) * w;
            let w_g = if beta_c <= LAMBDA_CONNECTION_MAX {
                // w^{1−γ} = exp((γ − 1) ln_1p(m²)) = exp(A² ln_1p(m²)/m²) < e⁴.
                let w_power = ((a * a) * ln_1p_ratio(m2)).exp();
                2.0 * w * series_in_c(beta, beta_c, m2 * w)
                    - 2.0 * PI.sqrt() * self.gamma_ratio_b * (m * w.sqrt()) * w_power
            } else {
                let z = x * x;
                z * continued_fraction(gamma, z) / gamma
            };
            (exponent, w_g)
        } else {
            let im2 = x * x;
            let w = im2 / (1.0 + im2);
            let ln_w = -(2.0 * m.ln() + im2.ln_1p());
            ((gamma - 1.5) * ln_w, w * series_in_w(beta, w) / gamma)
        };
        let sum = 1.0 / (gamma - 1.5) + w_g;
        let prefactor = x * self.lambda_normalization * sum / (4.0 * PI.sqrt());
        if exponent > f64::MIN_POSITIVE.ln() {
            prefactor * exponent.exp()
        } else {
            (exponent + prefactor.ln()).exp()
        }
    }

    /// θ* with tan²θ* = (2 α² (γ − 1) − γ)/(γ − 2) when γ > 2 and α² (γ − 1) > γ/2 (module header). None when
    /// the maximum is at θ = 0, or at grazing (γ ≤ 2 with α² (γ − 1) > γ/2: D rises to α²/π at γ = 2 and without
    /// bound for γ < 2). Written as 2α² (γ − 1)/(γ − 2) − γ/(γ − 2), which tends to Beckmann's 2α² − 1 without
    /// overflowing up to γ = f64::MAX.
    fn interior_peak(&self) -> Option<f64> {
        let (alpha, gamma) = (self.alpha_std, self.gamma_std);
        if gamma > 2.0 && 2.0 * alpha * alpha * (gamma - 1.0) > gamma {
            let tan2 =
                2.0 * alpha * alpha * ((gamma - 1.0) / (gamma - 2.0)) - gamma / (gamma - 2.0);
            Some(tan2.max(0.0).sqrt().atan())
        } else {
            None
        }
    }

    /// γ < 2: D ≈ (γ − 1)^γ α^{2γ−2} cos^{2γ−4}θ / π grows without bound towards grazing.
    fn unbounded_at_grazing(&self) -> bool {
        self.gamma_std < 2.0
    }

    /// α_std itself: Beckmann's α_b as γ → ∞, Trowbridge–Reitz's α_tr at γ = 2 (the same rough equivalence
    /// α_tr = α_b), and for the Phong lobe STD contains, exactly Phong's √(2/(α_p + 2)).
    fn beckmann_equivalent_alpha(&self) -> Option<f64> {
        Some(self.alpha_std)
    }

    fn params(&self) -> Vec<f64> {
        vec![self.alpha_std, self.gamma_std]
    }
}

/// ln_1p(y)/y for y ≥ 0 (1 at y = 0): the exponent of (1 + y)^p as p y · ln_1p_ratio(y), which never forms p y
/// from a subnormal y.
#[inline]
fn ln_1p_ratio(y: f64) -> f64 {
    if y == 0.0 { 1.0 } else { y.ln_1p() / y }
}

/// Route (a): ₂F₁(1, β; β + 3/2; w) = Σ_k (β)_k/(β + 3/2)_k w^k for w ≤ ½, positive terms with ratio
/// w (β + k)/(β + k + 3/2) < w.
fn series_in_w(beta: f64, w: f64) -> f64 {
    let (mut term, mut sum) = (1.0, 1.0);
    for k in 0..LAMBDA_MAX_TERMS {
        let k = k as f64;
        term *= w * ((beta + k) / (beta + k + 1.5));
        sum += term;
        if term <= 0.5 * f64::EPSILON * sum {
            break;
        }
    }
    sum
}

/// Route (b): ₂F₁(1, β; ½; c) = Σ_k (β)_k/(½)_k c^k for c < ½ and β c ≤ 2, positive terms with ratio
/// (β c + k c)/(½ + k), below 1 from k = 3 on; β c is passed formed (c alone may underflow when β is huge).
fn series_in_c(beta: f64, beta_c: f64, c: f64) -> f64 {
    debug_assert!(beta_c <= LAMBDA_CONNECTION_MAX && beta > 1.0);
    let (mut term, mut sum) = (1.0, 1.0);
    for k in 0..LAMBDA_MAX_TERMS {
        let k = k as f64;
        term *= (beta_c + k * c) / (0.5 + k);
        sum += term;
        if term <= 0.5 * f64::EPSILON * sum {
            break;
        }
    }
    sum
}

/// Route (c): H = ₂F₁(1, 3/2; γ + 1; −z) for z ≥ 0 by Gauss's continued fraction 1/(1 + k₁z/(1 + k₂z/(1 + …)))
/// (module header), modified Lentz. Each k is a product of two ratios so that nothing overflows at γ = f64::MAX.
fn continued_fraction(gamma: f64, z: f64) -> f64 {
    const TINY: f64 = 1e-300;
    let (mut f, mut c, mut d) = (1.0_f64, 1.0_f64, 0.0_f64);
    for j in 1..LAMBDA_MAX_TERMS {
        let k = if j % 2 == 1 {
            let n = ((j - 1) / 2) as f64;
            ((n + 1.5) / (gamma + 2.0 * n)) * ((gamma + n) / (gamma + 2.0 * n + 1.0))
        } else {
            let n = ((j - 2) / 2) as f64;
            ((n + 1.0) / (gamma + 2.0 * n + 1.0)) * ((gamma - 0.5 + n) / (gamma + 2.0 * n + 2.0))
        };
        let a = k * z;
        d = 1.0 + a * d;
        if d == 0.0 {
            d = TINY;
        }
        c = 1.0 + a / c;
        if c == 0.0 {
            c = TINY;
        }
        d = 1.0 / d;
        let delta = c * d;
        f *= delta;
        if (delta - 1.0).abs() <= f64::EPSILON {
            break;
        }
    }
    1.0 / f
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ndf::test_support::{block_error, decades};
    use crate::model::math::tolerance::{
        REL_TOL_LAMBDA_CLOSED_FORM, REL_TOL_NDF, REL_TOL_TROWBRIDGE_REITZ,
        floored_relative_difference,
    };
    use crate::model::ndf::{Phong, TrowbridgeReitz, beckmann};
    use std::f64::consts::FRAC_PI_2;

    /// How far the lane kernel may lie from [`libm_form`]: both exponentiate the same exponent e, each within
    /// a few ulps of |e| ≤ ~1450 where D is a normal double, so they may differ by a few 1e-13. Measured
    /// 3.0e-13 over [`lane_kernel_matches_the_libm_form`]'s grid, at α = 1e-122, γ = 1e4, θ = 3e-121
    /// (e ≈ −862), where the libm form is off by 2.8e-13 against mpmath and the kernel by 2.5e-14.
    const REL_TOL_LIBM_FORM: f64 = REL_TOL_NDF;

    /// The point-by-point form the lane kernel replaced, kept as a cross-check: libm's sin_cos, tan, ln_1p,
    /// ln and exp, with branches.
    fn libm_form(std: &StudentT, theta: f64) -> f64 {
        let (sin_theta, cos_theta) = theta.sin_cos();
        let q = std.alpha_std * cos_theta * cos_theta + sin_theta * sin_theta * std.sin2_weight;
        let r = theta.tan() / std.alpha_std;
        let v = r / std.sqrt_gamma_m1;
        let exponent = if v < 1.0 {
            -std.d_exponent_ratio * (r * r) * ln_1p_ratio(v * v)
        } else if v < LN_1P_SQUARE_LOG_MIN {
            -(std.gamma_std - 2.0) * (v * v).ln_1p()
        } else {
            -(std.gamma_std - 2.0) * 2.0 * v.ln()
        };
        let inv_q = 1.0 / q;
        let base = inv_q * inv_q * FRAC_1_PI;
        if base.is_finite() && base >= f64::MIN_POSITIVE && exponent > f64::MIN_POSITIVE.ln() {
            base * exponent.exp()
        } else {
            (exponent - 2.0 * q.ln() - PI.ln()).exp()
        }
    }

    #[test]
    fn log_constants_are_libm_s() {
        assert_eq!(LN_MIN_POSITIVE, f64::MIN_POSITIVE.ln());
        assert_eq!(LN_PI, PI.ln());
    }

    /// `eval_many` against [`libm_form`] over the whole domain, α from 1e-150 to 1e4, γ from just above 1.5
    /// through 2 to f64::MAX, θ from 0 through 1e-300 to the double nearest π/2, with the lobe's core
    /// (tan θ ~ α) and the switches v = 1 and v = 1e150 sampled; and `eval_many` gives `eval`'s bits there.
    #[test]
    fn lane_kernel_matches_the_libm_form() {
        let mut alphas: Vec<f64> = decades(-150, 4, 1).collect();
        alphas.extend([0.3, 0.707, 1.0 - 1e-9, 1.0 + 1e-9, 2.0]);
        let gammas = [
            1.5 * (1.0 + f64::EPSILON),
            1.5000001,
            1.6,
            2.0 - 1e-9,
            2.0,
            2.0 + 1e-9,
            2.5,
            3.0,
            10.0,
            100.0,
            1e4,
            1e8,
            1e20,
            1e100,
            1e300,
            f64::MAX,
        ];
        let fixed: Vec<f64> = thetas()
            .into_iter()
            .chain([5e-324, 1e-150, 1e-100, 1e-20])
            .chain((1..512).map(|i| FRAC_PI_2 * f64::from(i) / 512.0))
            .chain(decades(-16, -1, 1).map(|d| FRAC_PI_2 - d))
            .chain((1..8).map(|i| f64::from_bits(FRAC_PI_2.to_bits() - i)))
            .collect();
        let mut worst = (0.0, 0.0, 0.0, 0.0);
        for &alpha in &alphas {
            for &gamma in &gammas {
                let std = StudentT::new(alpha, gamma).unwrap();
                // tan θ at multiples of α (the core) and of α √(γ − 1) (v = 1, 1e150, and around them).
                let scales = [alpha, alpha * std.sqrt_gamma_m1];
                let mut thetas = fixed.clone();
                for scale in scales {
                    for m in [1e-3, 0.1, 0.5, 0.99, 1.0, 1.01, 2.0, 10.0, 30.0, 1e3, 1e150] {
                        let theta = (m * scale).atan();
                        if theta <= FRAC_PI_2 {
                            thetas.push(theta);
                        }
                    }
                }
                let at = format!("α = {alpha:e}, γ = {gamma:e}");
                let (error, theta) =
                    block_error(&std, &thetas, |theta| libm_form(&std, theta), &at);
                if error > worst.0 {
                    worst = (error, alpha, gamma, theta);
                }
            }
        }
        let (error, alpha, gamma, theta) = worst;
        println!("worst {error:.2e} at α = {alpha:e}, γ = {gamma:e}, θ = {theta:e}");
        assert!(
            error <= REL_TOL_LIBM_FORM,
            "{error:e} at α = {alpha:e}, γ = {gamma:e}, θ = {theta:e}"
        );
    }


    /// θ from 0 through tiny angles and a uniform grid to the double nearest π/2.
    fn thetas() -> Vec<f64> {
        [0.0, 1e-300, 1e-8, FRAC_PI_2]
            .into_iter()
            .chain((1..64).map(|i| FRAC_PI_2 * i as f64 / 64.0))
            .chain(decades(-15, -1, 1).map(|d| FRAC_PI_2 - d))
            .collect()
    }

    #[test]
    fn gamma_2_is_trowbridge_reitz() {
        for alpha in decades(-150, 4, 1).chain([1.0, 1.0 - 1e-9, 1.0 + 1e-9]) {
            let (std, tr) = (
                StudentT::new(alpha, 2.0).unwrap(),
                TrowbridgeReitz::new(alpha).unwrap(),
            );
            for theta in thetas() {
                let (got, want) = (std.eval(theta), tr.eval(theta));
                assert!(
                    ((got - want) / want).abs() <= REL_TOL_TROWBRIDGE_REITZ,
                    "α = {alpha:e}, θ = {theta:e}: {got:e} vs {want:e}"
                );
                let (got, want) = (std.lambda(theta), tr.lambda(theta));
                assert!(
                    floored_relative_difference(got, want) <= REL_TOL_LAMBDA_CLOSED_FORM,
                    "α = {alpha:e}, θo = {theta:e}: Λ {got:e} vs {want:e}"
                );
            }
        }
    }

    /// Phong n is STD with γ = (n + 4)/2, α = √(2/(n + 2)); α is rounded, which moves D by ~n sin²θ ε relative (the
    /// exponent's own condition), so the comparison stops where the lobe has fallen below 1e-200 of its peak.
    #[test]
    fn phong_is_a_student_t() {
        for n in [0.0, 0.5, 1.0, 2.0, 20.0, 200.0, 2e3, 1e5, 1e8, 1e12] {
            let phong = Phong::new(n).unwrap();
            let std = StudentT::new((2.0 / (n + 2.0)).sqrt(), (n + 4.0) / 2.0).unwrap();
            let peak = phong.eval(0.0);
            for theta in thetas() {
                let want = phong.eval(theta);
                if want < 1e-200 * peak {
                    continue;
                }
                let got = std.eval(theta);
                assert!(
                    floored_relative_difference(got, want) <= REL_TOL_NDF,
                    "n = {n:e}, θ = {theta:e}: {got:e} vs {want:e}"
                );
                let (got, want) = (std.lambda(theta), phong.lambda(theta));
                assert!(
                    floored_relative_difference(got, want) <= REL_TOL_LAMBDA_CLOSED_FORM,
                    "n = {n:e}, θo = {theta:e}: Λ {got:e} vs {want:e}"
                );
            }
        }
    }

    /// γ → ∞ is Beckmann: D differs by ~(t − t²/2)/γ in its exponent (t = tan²θ/α² ≲ 1450 where D is a normal
    /// double), Λ likewise, so from γ = 1e20 on they agree to the NDF tolerance.
    #[test]
    fn large_gamma_is_beckmann() {
        for alpha in [1e-150, 1e-3, 0.1, 0.3, 1.0, 10.0, 1e4] {
            let beckmann_d = |theta: f64| {
                let t = theta.tan() / alpha;
                let tan2 = theta.tan().powi(2);
                (-t * t + 2.0 * tan2.ln_1p()).exp() / (PI * alpha * alpha)
            };
            for gamma in [1e20, 1e100, 1e300, f64::MAX] {
                let std = StudentT::new(alpha, gamma).unwrap();
                for theta in thetas() {
                    let (got, want) = (std.eval(theta), beckmann_d(theta));
                    assert!(
                        floored_relative_difference(got, want) <= REL_TOL_NDF,
                        "α = {alpha:e}, γ = {gamma:e}, θ = {theta:e}: {got:e} vs {want:e}"
                    );
                    let (got, want) = (std.lambda(theta), beckmann::smith_lambda(alpha, theta));
                    assert!(
                        floored_relative_difference(got, want) <= REL_TOL_LAMBDA_CLOSED_FORM,
                        "α = {alpha:e}, γ = {gamma:e}, θo = {theta:e}: Λ {got:e} vs {want:e}"
                    );
                }
            }
        }
    }

    #[test]
    fn the_peak_is_where_the_slope_vanishes() {
        for (alpha, gamma) in [
            (0.9, 3.0),
            (2.0, 2.5),
            (10.0, 1e8),
            (1.0, f64::MAX),
            (0.75, 10.0),
        ] {
            let d = StudentT::new(alpha, gamma).unwrap();
            let t = d.interior_peak().expect("an off-normal peak");
            assert!(d.eval(t) >= d.eval(t * (1.0 - 1e-6)) && d.eval(t) >= d.eval(t * (1.0 + 1e-6)));
        }
        for (alpha, gamma) in [(0.5, 3.0), (5.0, 2.0), (5.0, 1.6), (0.1, 1e8)] {
            assert_eq!(StudentT::new(alpha, gamma).unwrap().interior_peak(), None);
        }
    }
}
