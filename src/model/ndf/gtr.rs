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
//!   (see [`peak`]). Then
//!   D = D_peak (q/q_peak)^{−γ} for γ ≤ 1, and D = (D_peak^{1/γ}/(q/q_peak))^γ for γ > 1: the one power never
//!   overflows or underflows on the way to a representable D (D_peak ≤ 3.2e301, D_peak^{1/γ} ≥ π^{−1/γ}, and
//!   q/q_peak ≤ 1 + k ≤ 1e300). Its relative error is ~γ times that of q/q_peak (a few ulps), plus for γ > 1
//!   the rounding of 1/γ times ln D_peak (≤ 690 · 2⁻⁵³ ≈ 8e-14), where exp(ln D_peak − γ ln(q/q_peak)) would
//!   add |ln D| ulps (up to ~1450).
//! - Smith Λ: no closed form is known; docs/maths.md's 1D integral by [`crate::model::ndf::lambda_integral::lambda_integral`], within
//!   2.4e-13 of the 40-digit references (`tests/data/reference/lambda.csv`). Λ(0) = 0; Λ grows like 1/cos θo towards grazing and is large but finite
//!   at θo = FRAC_PI_2 (cos = 6.1e-17).

use super::Distribution;
use crate::model::domain::{Bound, DomainError, Param};
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
/// more: D's relative error is ~γ times the few-ulp error of q/q_peak, measured against mpmath at ≤ 8e-14
/// for γ ≤ 100, 3e-13 for γ = 1e3 and 3e-12 (past the 1e-12 the NDFs are held to) for γ = 1e4.
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
    /// D_peak for γ ≤ 1, D_peak^{1/γ} for γ > 1 (module header).
    peak_scale: f64,
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
        let peak = peak(k_sin + k_cos, gamma_gtr);
        let peak_scale = if gamma_gtr <= 1.0 {
            peak
        } else {
            peak.powf(1.0 / gamma_gtr)
        };
        Ok(Gtr {
            alpha_gtr,
            gamma_gtr,
            k_sin,
            k_cos,
            peak_scale,
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

    /// D(θ) = c / (α² cos²θ + sin²θ)^γ for θ ∈ [0, π/2], normalized over projected area.
    #[inline]
    fn eval(&self, theta: f64) -> f64 {
        let (sin_theta, cos_theta) = theta.sin_cos();
        let q_over_q_peak =
            1.0 + self.k_sin * sin_theta * sin_theta + self.k_cos * cos_theta * cos_theta;
        if self.gamma_gtr <= 1.0 {
            self.peak_scale * q_over_q_peak.powf(-self.gamma_gtr)
        } else {
            (self.peak_scale / q_over_q_peak).powf(self.gamma_gtr)
        }
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
    use crate::model::math::tolerance::REL_TOL_TROWBRIDGE_REITZ;
    use crate::model::ndf::TrowbridgeReitz;
    use std::f64::consts::FRAC_PI_2;

    /// The decades 10^e for e = lo, lo + step, … ≤ hi, each the double nearest 10^e (as written `1e{e}`).
    fn decades(lo: i32, hi: i32, step: usize) -> impl Iterator<Item = f64> {
        (lo..=hi)
            .step_by(step)
            .map(|e| format!("1e{e}").parse().expect("a decade parses"))
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
