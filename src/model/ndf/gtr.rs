//! Generalized Trowbridge–Reitz NDF (Burley 2012, the Disney BRDF; docs/maths.md "Generalized Trowbridge–Reitz"):
//! D(θ) = c / (α² cos²θ + sin²θ)^γ with α = `alpha_gtr` and γ = `gamma_gtr`. γ = 1 is Burley's GTR1 ("Berry"),
//! γ = 2 is Trowbridge–Reitz with α_tr = α, γ → 0 and α = 1 are uniform.
//!
//! - Domain: 1e-150 ≤ α ≤ 1e3, 0 < γ ≤ 100, stated once with the reasons in
//!   [`Gtr::PARAMS`](super::Distribution::PARAMS).
//! - Normalization (projected area): with q = α² cos²θ + sin²θ and u = cos²θ, 2π ∫₀^{π/2} q^{−γ} sin θ cos θ dθ
//!   = π ∫₀¹ (1 + (α² − 1) u)^{−γ} du = π exprel((1 − γ) L)/exprel(L), L = ln α², exprel(x) = (eˣ − 1)/x, so
//!   c = exprel(L)/(π exprel((1 − γ) L)): exact through α = 1 (c = 1/π) and γ = 1 (c = (α² − 1)/(π L)), where
//!   the textbook (γ − 1)(α² − 1)/(π (1 − (α²)^{1−γ})) is 0/0.
//! - θ → 0: D → c α^{−2γ}, the peak when α < 1. θ → π/2: D → c, the peak when α > 1 (a grazing lobe).
//! - Stable form: D is written relative to its peak. With q_peak = min(α², 1) (q at the peak) and
//!   k = max(α², α⁻²) − 1 (so that ln(1 + k) = |L| =: M),
//!   q/q_peak = 1 + k_sin sin²θ + k_cos cos²θ with (k_sin, k_cos) = (k, 0) for α < 1 and (0, k) for α > 1: a sum
//!   of non-negative terms (never the cancelling 1 + (α² − 1) cos²θ of small α), whose deviation from 1 is
//!   formed directly, so it stays accurate near α = 1. The peak value is, for either side,
//!   D_peak = exprel(M)/(π exprel((1 − γ) M)) (for α < 1, c α^{−2γ} = c e^{−γL} folds into exprel(−L) and
//!   exprel((γ − 1) L)), formed from k and powers of 1 + k so that no logarithm's rounding is exponentiated
//!   (see [`peak`]). Then D = exp(ln D_peak − γ ln(1 + k_sin sin²θ + k_cos cos²θ)), one branch-free form for
//!   every γ (vector lanes, [`Lanewise`]): ln_1p takes the non-negative deviation of q/q_peak from 1
//!   directly (never rounded as 1 + …), both logarithms are unevaluated sums hi + lo within 2⁻⁵⁶ absolute
//!   ([`elementary::ln_parts`], [`elementary::ln_1p_parts`]), γ times the second keeps its rounding error (a
//!   fused multiply-add) and the difference is taken by TwoSum, so the exponent, up to ln D_peak ≤ 693.5 and
//!   down to −69 100, is exact to ~(γ + 1) 2⁻⁵⁶ plus the error of its inputs, and D = e^{hi} (1 + lo) adds
//!   one rounding to exp's ulp. D's relative error is thus ~γ times that of q/q_peak − 1 (a few ulps), plus
//!   that of D_peak: the accuracy of a correctly rounded power, where exp(ln D_peak − γ ln(q/q_peak)) in
//!   rounded doubles would add |ln D| ulps (up to ~1450). Nothing overflows on the way (e^{hi} ≤ D_peak), and
//!   D underflows only where it is below the smallest double itself.
//! - Smith Λ: no closed form is known; docs/maths.md's 1D integral by [`crate::model::ndf::lambda_integral::lambda_integral`], within
//!   2.4e-13 of the 40-digit references (`tests/data/reference/lambda.csv`). Λ(0) = 0; Λ grows like 1/cos θo towards grazing and is large but finite
//!   at θo = FRAC_PI_2 (cos = 6.1e-17).

use super::Distribution;
use crate::model::domain::{Bound, DomainError, Param};
use crate::model::math::elementary::{self, Lanewise, at_one, map_lanes};
use crate::model::math::special::exprel;
use std::f64::consts::{FRAC_1_PI, PI};

/// α's domain. At 1e-150, α² = 1e-300 is still a normal double, and the peak D(0) ≈ (γ − 1)/(π α²) (γ > 1)
/// or (1 − γ) α^{−2γ}/π (γ < 1) stays below 3.2e301 for every accepted γ. Above 1 the lobe lies within
/// ~1/(α √γ) rad of grazing: 1e-4 rad at α = 1e3 and γ = 100, the narrowest grazing lobe accepted for
/// Trowbridge–Reitz, which θ's double spacing near π/2 (2.2e-16) resolves to ~2e-12.
const ALPHA_GTR: Param = Param {
    name: "alpha_gtr",
    symbol: "α",
    min: Bound::inclusive(1e-150, "the peak D(0) heads for overflow"),
    max: Bound::inclusive(1e3, "the lobe is unresolvably close to grazing"),
};

/// γ's domain. Any γ > 0 is a distribution (γ → 0 tends to the uniform 1/π, reached to a few ulps). Above
/// 100 the grazing lobe of α = 1e3 narrows past 1e-4 rad (see [`ALPHA_GTR`]); accuracy alone would allow
/// more: D's relative error is ~γ times the few-ulp error of q/q_peak − 1, measured against mpmath at
/// ≤ 4.1e-14 for γ ≤ 100 and 1.2e-13 for γ = 1e3 and 1e4 (the reference generator's grid, 65 more angles).
const GAMMA_GTR: Param = Param {
    name: "gamma_gtr",
    symbol: "γ",
    min: Bound::exclusive(0.0, "D is no longer a distribution"),
    max: Bound::inclusive(
        100.0,
        "D(θ) loses accuracy as γ ulps and the grazing lobe becomes unresolvably narrow",
    ),
};

/// A validated Generalized Trowbridge–Reitz lobe with its peak precomputed.
#[derive(Debug, Clone, PartialEq)]
pub struct Gtr {
    alpha_gtr: f64,
    gamma_gtr: f64,
    /// α⁻² − 1 for α < 1, else 0: the weight of sin²θ in q/q_peak − 1.
    k_sin: f64,
    /// α² − 1 for α > 1, else 0: the weight of cos²θ in q/q_peak − 1.
    k_cos: f64,
    /// ln D_peak (module header), the head of the unevaluated sum with [`ln_peak_lo`](Self::ln_peak_lo).
    ln_peak: f64,
    /// ln D_peak − [`ln_peak`](Self::ln_peak), below half an ulp of it.
    ln_peak_lo: f64,
}

impl Gtr {
    /// A GTR lobe with `alpha_gtr` = α ∈ [1e-150, 1e3] and `gamma_gtr` = γ ∈ (0, 100]; rejects NaN, ±∞ and
    /// values outside.
    pub fn new(alpha_gtr: f64, gamma_gtr: f64) -> Result<Self, DomainError> {
        ALPHA_GTR.check(alpha_gtr)?;
        GAMMA_GTR.check(gamma_gtr)?;
        // α² − 1 = (α − 1)(α + 1) and α⁻² − 1 = (1 − α)(1 + α)/α²: α − 1 is exact near 1, so neither cancels.
        let (k_sin, k_cos) = if alpha_gtr < 1.0 {
            (
                (1.0 - alpha_gtr) * (1.0 + alpha_gtr) / (alpha_gtr * alpha_gtr),
                0.0,
            )
        } else {
            (0.0, (alpha_gtr - 1.0) * (alpha_gtr + 1.0))
        };
        let (ln_peak, ln_peak_lo) = elementary::ln_parts(peak(k_sin + k_cos, gamma_gtr));
        Ok(Gtr {
            alpha_gtr,
            gamma_gtr,
            k_sin,
            k_cos,
            ln_peak,
            ln_peak_lo,
        })
    }

    /// The roughness α.
    pub fn alpha_gtr(&self) -> f64 {
        self.alpha_gtr
    }

    /// The tail exponent γ.
    pub fn gamma_gtr(&self) -> f64 {
        self.gamma_gtr
    }
}

impl Lanewise for Gtr {
    /// D(θ) = c/(α² cos²θ + sin²θ)^γ for θ ∈ [0, π/2], normalized over projected area, as
    /// exp(ln D_peak − γ ln(1 + k_sin sin²θ + k_cos cos²θ)) with the exponent carried as hi + lo (module
    /// header).
    #[inline(always)]
    fn at(&self, theta: f64) -> f64 {
        let (sin_theta, cos_theta) = elementary::sin_cos(theta);
        let excess = self.k_sin * sin_theta * sin_theta + self.k_cos * cos_theta * cos_theta;
        let (ln_ratio, ln_ratio_lo) = elementary::ln_1p_parts(excess);
        let gamma = self.gamma_gtr;
        let fall = gamma * ln_ratio;
        let fall_lo = gamma.mul_add(ln_ratio, -fall) + gamma * ln_ratio_lo;
        let (exponent, exponent_error) = elementary::two_sum(self.ln_peak, -fall);
        let exponent_lo = exponent_error + (self.ln_peak_lo - fall_lo);
        let value = elementary::exp(exponent);
        value.mul_add(exponent_lo, value)
    }
}

impl Distribution for Gtr {
    const NAME: &'static str = "gtr";
    const TITLE: &'static str = "GTR";
    const PARAMS: &'static [Param] = &[ALPHA_GTR, GAMMA_GTR];
    const LEGEND_PREFIX: Option<&'static str> = Some("GTR");
    const COLOUR: u32 = 0x199C93;
    /// Between Berry (γ = 1) and Trowbridge–Reitz (γ = 2) at the catalogue's α = 0.3.
    const EXAMPLE: &'static [f64] = &[0.3, 1.5];
    const PAGE_FORMULA: &'static str = include_str!("gtr.js");

    fn from_params(params: &[f64]) -> Result<Self, DomainError> {
        Gtr::new(params[0], params[1])
    }

    /// The mirror for γ ≥ 1 (for γ = 1 slowly: c ≈ 1/(π ln α⁻²) → 0). For γ < 1, c → (1 − γ)/π and
    /// D → (1 − γ)/(π sin^{2γ} θ), a lobe with an integrable peak, not the mirror.
    fn zero_limit(others: &[f64]) -> super::ZeroLimit {
        match others.first() {
            Some(&gamma) if gamma < 1.0 => super::ZeroLimit::Other(
                "the lobe tends to (1 - gamma_gtr)/(pi sin^(2 gamma_gtr) theta), not the mirror",
            ),
            _ => super::ZeroLimit::Mirror,
        }
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

    /// False: D → c at grazing (sin²θ + α² cos²θ → 1).
    fn unbounded_at_grazing(&self) -> bool {
        false
    }

    /// None: renderers have no Beckmann equivalent for this family.
    fn beckmann_equivalent_alpha(&self) -> Option<f64> {
        None
    }

    fn params(&self) -> Vec<f64> {
        vec![self.alpha_gtr, self.gamma_gtr]
    }
}

/// D_peak = exprel(M)/(π exprel((1 − γ) M)) with M = ln(1 + k), k = max(α², α⁻²) − 1: D(0) for α ≤ 1 and
/// D(π/2) for α ≥ 1.
///
/// exprel(M) is taken as k/M, exact but for two roundings, where expm1 of the rounded M would carry M's
/// rounding times M (up to 690 ulps at α = 1e-150). The same holds for exprel(Y), Y = (1 − γ) M, once Y is
/// large: for Y > 1 the ratio is (1 − γ) k/(e^Y − 1) with e^Y = (1 + k)(1 + k)^{−γ}, a power of an accurate
/// base to the unrounded γ (and e^Y − 1 > e − 1 does not cancel); for Y ≤ 1 the rounding of Y costs at most
/// 2 ulps in expm1. Either way nothing overflows: Y ≤ M ≤ 690.8 < 709.78.
fn peak(k: f64, gamma: f64) -> f64 {
    // α = 1: exprel(0)/(π exprel(0)), the uniform lobe.
    if k == 0.0 {
        return FRAC_1_PI;
    }
    let m = k.ln_1p();
    let y = (1.0 - gamma) * m;
    if y > 1.0 {
        (1.0 - gamma) * k / (PI * ((1.0 + k) * (1.0 + k).powf(-gamma) - 1.0))
    } else {
        k / m / (PI * exprel(y))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ndf::test_support::{block_error, decades};
    use crate::model::math::tolerance::REL_TOL_TROWBRIDGE_REITZ;
    use crate::model::ndf::TrowbridgeReitz;
    use std::f64::consts::FRAC_PI_2;

    /// How far the lane kernel may lie from [`libm_form`]: each is within ~γ times the few-ulp error of
    /// q/q_peak − 1 of the truth (≤ 4.1e-14 for the kernel against mpmath), and the libm form adds up to
    /// 8e-14 for γ > 1 (the rounding of 1/γ times ln D_peak ≤ 690); measured 8.0e-14 over
    /// [`lane_kernel_matches_the_libm_form`]'s grid.
    const REL_TOL_LIBM_FORM: f64 = 2e-13;

    /// The point-by-point form the lane kernel replaced, kept as a cross-check: libm's sin_cos and powf,
    /// D = D_peak (q/q_peak)^{−γ} for γ ≤ 1 and (D_peak^{1/γ}/(q/q_peak))^γ for γ > 1.
    fn libm_form(gtr: &Gtr, theta: f64) -> f64 {
        let (gamma, peak) = (gtr.gamma_gtr, peak(gtr.k_sin + gtr.k_cos, gtr.gamma_gtr));
        let (sin_theta, cos_theta) = theta.sin_cos();
        let q_over_q_peak =
            1.0 + gtr.k_sin * sin_theta * sin_theta + gtr.k_cos * cos_theta * cos_theta;
        if gamma <= 1.0 {
            peak * q_over_q_peak.powf(-gamma)
        } else {
            (peak.powf(1.0 / gamma) / q_over_q_peak).powf(gamma)
        }
    }

    /// `eval_many` against [`libm_form`] over the whole domain, α from 1e-150 to 1e3 and through 1 (to
    /// within 1e-9), γ from the smallest positive double to 100 and through 1, θ from 0 through 1e-300 and
    /// the lobe's width to the double nearest π/2; and `eval_many` gives `eval`'s bits there.
    #[test]
    fn lane_kernel_matches_the_libm_form() {
        let mut alphas: Vec<f64> = decades(-150, 3, 1).collect();
        alphas.extend([
            1e-150 * (1.0 + f64::EPSILON),
            0.3,
            0.5,
            1.0 - 1e-6,
            1.0 - 1e-9,
            1.0,
            1.0 + 1e-9,
            1.0 + 1e-6,
            2.0,
        ]);
        let gammas = [
            5e-324,
            1e-300,
            1e-6,
            1e-3,
            0.1,
            0.5,
            1.0 - 1e-9,
            1.0,
            1.0 + 1e-9,
            1.5,
            2.0,
            3.0,
            10.0,
            31.6,
            99.9,
            100.0,
        ];
        let fixed: Vec<f64> = [0.0, 5e-324, 1e-300, 1e-151, 1e-8, FRAC_PI_2]
            .into_iter()
            .chain((1..512).map(|i| FRAC_PI_2 * f64::from(i) / 512.0))
            .chain(decades(-16, -1, 1).map(|d| FRAC_PI_2 - d))
            .chain((1..8).map(|i| f64::from_bits(FRAC_PI_2.to_bits() - i)))
            .collect();
        let mut worst = (0.0, 0.0, 0.0, 0.0);
        for &alpha in &alphas {
            // 64 steps of a sixteenth of the lobe's width 1/√(max(α², α⁻²) − 1), from θ = 0 (α < 1) or
            // from grazing (α > 1).
            let width = 1.0 / (alpha.max(1.0 / alpha).powi(2) - 1.0).sqrt();
            let lobe = (1..=64).map(|i| width * f64::from(i) / 16.0);
            let thetas: Vec<f64> = if alpha < 1.0 {
                lobe.filter(|&t| t < FRAC_PI_2).chain(fixed.clone()).collect()
            } else {
                lobe.map(|t| FRAC_PI_2 - t)
                    .filter(|&t| t > 0.0)
                    .chain(fixed.clone())
                    .collect()
            };
            for &gamma in &gammas {
                let gtr = Gtr::new(alpha, gamma).unwrap();
                let at = format!("α = {alpha:e}, γ = {gamma:e}");
                let (error, theta) =
                    block_error(&gtr, &thetas, |theta| libm_form(&gtr, theta), &at);
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


    #[test]
    fn gamma_2_is_trowbridge_reitz() {
        let thetas: Vec<f64> = [0.0, 1e-300, 1e-8, FRAC_PI_2]
            .into_iter()
            .chain((1..64).map(|i| FRAC_PI_2 * i as f64 / 64.0))
            .chain(decades(-15, -1, 1).map(|d| FRAC_PI_2 - d))
            .collect();
        let mut alphas = decades(-150, 3, 1).collect::<Vec<_>>();
        alphas.extend([1.0, 1.0 - 1e-9, 1.0 + 1e-9]);
        for alpha in alphas {
            let (gtr, tr) = (
                Gtr::new(alpha, 2.0).unwrap(),
                TrowbridgeReitz::new(alpha).unwrap(),
            );
            for &theta in &thetas {
                let (got, want) = (gtr.eval(theta), tr.eval(theta));
                assert!(
                    ((got - want) / want).abs() <= REL_TOL_TROWBRIDGE_REITZ,
                    "α = {alpha:e}, θ = {theta:e}: {got:e} vs {want:e}"
                );
            }
        }
    }
}
