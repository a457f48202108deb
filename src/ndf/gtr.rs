//! Generalized Trowbridge–Reitz NDF (Burley 2012, the Disney BRDF; MATH.md "Generalized Trowbridge–Reitz"):
//! D(θ) = c / (α² cos²θ + sin²θ)^γ with α = `alpha_gtr` and γ = `gamma_gtr`. γ = 1 is Burley's GTR1 ("Berry"),
//! γ = 2 is Trowbridge–Reitz with α_tr = α, γ → 0 and α = 1 are uniform.
//!
//! - Domain: 1e-150 ≤ α ≤ 1e3, 0 < γ ≤ 100 (reasons at each bound's constant). Any γ > 0 works: as γ → 0
//!   the lobe tends to the uniform 1/π, which the evaluation reaches to within a few ulps.
//! - Owns the family's formula, domain and evaluation; no registry, parsing or batch path lives here.
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

use crate::domain::{DomainError, check};
use crate::math::special::exprel;
use std::f64::consts::{FRAC_1_PI, PI};

/// Smallest accepted α: α² = 1e-300 is still a normal double, and the peak D(0) ≈ (γ − 1)/(π α²) (γ > 1) or
/// (1 − γ) α^{−2γ}/π (γ < 1) stays below 3.2e301 for every accepted γ.
pub const ALPHA_GTR_MIN: f64 = 1e-150;
/// Largest accepted α: for α > 1 the lobe lies within ~1/(α √γ) rad of grazing, 1e-4 rad at α = 1e3 and
/// γ = [`GAMMA_GTR_MAX`] — the narrowest grazing lobe accepted for Trowbridge–Reitz, which θ's double
/// spacing near π/2 (2.2e-16) resolves to ~2e-12.
pub const ALPHA_GTR_MAX: f64 = 1e3;
/// Largest accepted γ: the grazing lobe width 1/(α √γ) reaches 1e-4 rad at [`ALPHA_GTR_MAX`] (see there).
/// Accuracy alone would allow more: D's relative error is ~γ times the few-ulp error of q/q_peak, measured
/// against mpmath at ≤ 8e-14 for γ ≤ 100, 3e-13 for γ = 1e3 and 3e-12 (past the 1e-12 the NDFs are held
/// to) for γ = 1e4.
pub const GAMMA_GTR_MAX: f64 = 100.0;
/// What [`Gtr::new`] accepts, as shown in `--help`.
pub const DOMAIN: &str = "1e-150 ≤ alpha_gtr ≤ 1e3, 0 < gamma_gtr ≤ 100";

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
        check(
            "alpha_gtr",
            alpha_gtr,
            |v| (ALPHA_GTR_MIN..=ALPHA_GTR_MAX).contains(&v),
            "in [1e-150, 1e3] (smaller: the peak D(0) heads for overflow; larger: the lobe is unresolvably close to grazing)",
        )?;
        check(
            "gamma_gtr",
            gamma_gtr,
            |v| v > 0.0 && v <= GAMMA_GTR_MAX,
            "in (0, 100] (larger: D(θ) loses accuracy as γ ulps and the grazing lobe becomes unresolvably narrow)",
        )?;
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

    /// D(θ) = c / (α² cos²θ + sin²θ)^γ for θ ∈ [0, π/2], normalized over projected area.
    #[inline]
    pub fn eval(&self, theta: f64) -> f64 {
        let (sin_theta, cos_theta) = theta.sin_cos();
        let q_over_q_peak =
            1.0 + self.k_sin * sin_theta * sin_theta + self.k_cos * cos_theta * cos_theta;
        if self.gamma_gtr <= 1.0 {
            self.peak_scale * q_over_q_peak.powf(-self.gamma_gtr)
        } else {
            (self.peak_scale / q_over_q_peak).powf(self.gamma_gtr)
        }
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
    use crate::math::quad::{QuadError, integrate};
    use crate::math::tolerance::{
        ABS_FLOOR, NORMALIZATION_TOL, QUAD_REL_TOL, REL_TOL_NDF, REL_TOL_TROWBRIDGE_REITZ,
    };
    use crate::ndf::Distribution;
    use crate::ndf::TrowbridgeReitz;
    use std::f64::consts::FRAC_PI_2;

    /// 50-digit mpmath values from the exact doubles written in the file (`tests/data/gtr_reference_gen.py`).
    const REFERENCE: &str = include_str!("../../tests/data/reference/gtr.csv");

    /// Geometric ratio between quadrature breakpoints: pieces span a factor 4, so that a lobe of any width
    /// meets a piece of comparable width.
    const BREAK_RATIO: f64 = 4.0;

    /// The decades 10^e for e = lo, lo + step, … ≤ hi, each the double nearest 10^e (as written `1e{e}`).
    fn decades(lo: i32, hi: i32, step: usize) -> impl Iterator<Item = f64> {
        (lo..=hi)
            .step_by(step)
            .map(|e| format!("1e{e}").parse().expect("a decade parses"))
    }

    /// α over the whole domain, bounds included, plus the uniform lobe and its neighbours.
    fn alpha_grid() -> Vec<f64> {
        let mut alphas = decades(-150, 3, 3).collect::<Vec<_>>();
        alphas.extend([
            1.0,
            1.0 - 1e-9,
            1.0 + 1e-9,
            1.0 - 1e-6,
            1.0 + 1e-6,
            0.5,
            2.0,
            10.0,
            100.0,
        ]);
        alphas
    }

    /// γ from the smallest positive double to the bound, plus Berry, Trowbridge–Reitz and their neighbours.
    fn gamma_grid() -> Vec<f64> {
        let mut gammas = decades(-6, 2, 1).collect::<Vec<_>>();
        gammas.extend([
            f64::from_bits(1),
            1e-300,
            0.5,
            1.0 - 1e-9,
            1.0,
            1.0 + 1e-9,
            1.5,
            2.0,
            3.0,
            30.0,
        ]);
        gammas
    }

    /// The number after `"key":` in a `curve_json` cell, parsed by `str::parse` (correctly rounded).
    fn field(curve_json: &str, key: &str) -> f64 {
        let tag = format!("\"{key}\":");
        let start = curve_json.find(&tag).expect("key present") + tag.len();
        let rest = &curve_json[start..];
        let end = rest.find([',', '}']).expect("value terminated");
        rest[..end].parse().expect("numeric value")
    }

    #[test]
    fn matches_50_digit_references() {
        let mut reader = csv::Reader::from_reader(REFERENCE.as_bytes());
        let (mut worst, mut worst_case) = (0.0, String::new());
        let mut failures = Vec::new();
        for record in reader.records() {
            let record = record.expect("well-formed CSV row");
            let gtr = Gtr::new(
                field(&record[1], "alpha_gtr"),
                field(&record[1], "gamma_gtr"),
            )
            .expect("reference parameters are in the domain");
            let theta: f64 = record[2].parse().expect("theta");
            let want: f64 = record[3].parse().expect("value");
            let got = gtr.eval(theta);
            let err = if want.abs() > ABS_FLOOR {
                ((got - want) / want).abs()
            } else {
                (got - want).abs()
            };
            if err > worst || err.is_nan() {
                (worst, worst_case) = (err, format!("{} θ = {theta:e}", &record[1]));
            }
            if !(got.is_finite() && got >= 0.0 && err <= REL_TOL_NDF) {
                failures.push(format!(
                    "{}: got {got:e}, want {want:e}, err {err:.2e}",
                    &record[0]
                ));
            }
        }
        println!("gtr: max error {worst:.2e} at {worst_case}");
        assert!(failures.is_empty(), "{}", failures.join("\n"));
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

    /// 2π ∫₀^{π/2} D sin θ cos θ dθ = π ∫₀¹ D dt with t = sin²θ (α < 1) or cos²θ (α ≥ 1), the variable in which
    /// D ∝ (1 + k t)^{−γ}; the pieces break geometrically up from the lobe's scale t ~ 1/(k max(γ, 1)).
    fn projected_integral(gtr: &Gtr) -> f64 {
        let k = gtr.k_sin + gtr.k_cos;
        let theta_of_t = |t: f64| {
            if gtr.alpha_gtr < 1.0 {
                t.sqrt().asin()
            } else {
                t.sqrt().acos()
            }
        };
        let mut breaks = vec![0.0];
        let mut t = 1.0 / (k * gtr.gamma_gtr.max(1.0) * BREAK_RATIO.powi(3));
        while t < 1.0 {
            breaks.push(t);
            t *= BREAK_RATIO;
        }
        breaks.push(1.0);
        // The last pieces of a heavy lobe can hold ~1e-30 of the mass, sampled by θ a few ulps apart (near
        // π/2 for α > 1): a piece is also accepted once its absolute error estimate fits the whole budget.
        let piece =
            |a: f64, b: f64| match integrate(|t| gtr.eval(theta_of_t(t)), a, b, QUAD_REL_TOL) {
                Ok(v) => v,
                Err(QuadError::NotConverged { estimate, error }) if error <= QUAD_REL_TOL / PI => {
                    estimate
                }
                Err(e) => panic!("{gtr:?} on [{a:e}, {b:e}]: {e}"),
            };
        PI * breaks.windows(2).map(|w| piece(w[0], w[1])).sum::<f64>()
    }

    #[test]
    fn normalized_over_the_domain() {
        let mut worst: (f64, f64, f64) = (0.0, 0.0, 0.0);
        for alpha in alpha_grid() {
            for gamma in gamma_grid() {
                let mass = projected_integral(&Gtr::new(alpha, gamma).unwrap());
                let err = (mass - 1.0).abs();
                assert!(
                    err <= NORMALIZATION_TOL,
                    "α = {alpha:e}, γ = {gamma:e}: mass {mass}"
                );
                if err > worst.0 {
                    worst = (err, alpha, gamma);
                }
            }
        }
        println!(
            "gtr: max |2π∫D sinθ cosθ dθ − 1| = {:.2e} at α = {:e}, γ = {:e}",
            worst.0, worst.1, worst.2
        );
    }

    #[test]
    fn finite_and_non_negative_over_the_domain() {
        let mut thetas = vec![0.0, FRAC_PI_2];
        thetas.extend(decades(-300, 0, 2));
        thetas.extend((1..100).map(|i| FRAC_PI_2 * i as f64 / 100.0));
        thetas.extend(decades(-15, 0, 1).map(|d| FRAC_PI_2 - d));
        for alpha in alpha_grid() {
            for gamma in gamma_grid() {
                let gtr = Gtr::new(alpha, gamma).unwrap();
                for &theta in &thetas {
                    let d = gtr.eval(theta);
                    assert!(
                        d.is_finite() && d >= 0.0,
                        "α = {alpha:e}, γ = {gamma:e}, θ = {theta:e}: {d}"
                    );
                }
            }
        }
    }

    #[test]
    fn accepts_exactly_its_domain() {
        let below = |v: f64| f64::from_bits(v.to_bits() - 1);
        let above = |v: f64| f64::from_bits(v.to_bits() + 1);
        for (alpha, gamma) in [
            (ALPHA_GTR_MIN, 1.0),
            (ALPHA_GTR_MAX, 1.0),
            (1.0, f64::from_bits(1)),
            (1.0, GAMMA_GTR_MAX),
            (ALPHA_GTR_MIN, GAMMA_GTR_MAX),
            (ALPHA_GTR_MAX, GAMMA_GTR_MAX),
        ] {
            assert!(
                Gtr::new(alpha, gamma).is_ok(),
                "α = {alpha:e}, γ = {gamma:e}"
            );
        }
        for (alpha, gamma) in [
            (below(ALPHA_GTR_MIN), 1.0),
            (above(ALPHA_GTR_MAX), 1.0),
            (0.0, 1.0),
            (-1.0, 1.0),
            (1.0, 0.0),
            (1.0, -1.0),
            (1.0, above(GAMMA_GTR_MAX)),
            (f64::NAN, 1.0),
            (1.0, f64::NAN),
            (f64::INFINITY, 1.0),
            (f64::NEG_INFINITY, 1.0),
            (1.0, f64::INFINITY),
            (1.0, f64::NEG_INFINITY),
        ] {
            assert!(
                Gtr::new(alpha, gamma).is_err(),
                "α = {alpha:e}, γ = {gamma:e}"
            );
        }
    }
}
