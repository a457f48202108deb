//! Special functions the NDFs need and no available crate computes accurately over the whole domain.
//!
//! - [`exprel`]`(x) = (eˣ − 1)/x`: the removable singularity at 0 of the ABC normalization.
//! - [`phi`]`(k, z) = Σ_{j≥0} zʲ/(j + k)!`: the φ-functions of exponential integrators, which turn the ABC
//!   normalization into a sum of positive terms for small a₁.
//! - [`upper_gamma_scaled`]`(s, x) = eˣ Γ(s, x)`: the SGD normalization for every real s, including s ≤ 0
//!   where Γ(s, x) is defined (x > 0) but statrs, puruspe and the like refuse it.
//!
//! - [`gamma_half_ratio`]`(p) = Γ(p + ½)/Γ(p)`: the normalization of the Student-t slope distribution behind
//!   Phong's Smith Λ, for p up to f64::MAX, where ln Γ would lose p ln p ulps.
//!
//! Dawson's, the Faddeeva and the scaled complementary error function erfcx come from `errorfunctions` (a
//! port of S. G. Johnson's Faddeeva package, accurate to ~1e-15). Nothing here allocates.

/// Machine epsilon: series and continued fractions stop when the next correction is below it, relative.
const EPS: f64 = f64::EPSILON;

/// Hard cap on the terms of any series or continued fraction here: every loop converges in fewer than
/// ~100 terms on its documented domain, so reaching the cap means a caller went outside it.
const MAX_TERMS: usize = 1000;

/// exprel(x) = (eˣ − 1)/x, with exprel(0) = 1.
///
/// `expm1` is relatively accurate for every x, so the quotient is too; only x = 0 needs the limit.
/// Overflows to +∞ for x ≳ 709.78 (like eˣ).
pub fn exprel(x: f64) -> f64 {
    if x == 0.0 {
        return 1.0;
    }
    x.exp_m1() / x
}

/// φ_k(z) = Σ_{j≥0} zʲ/(j + k)! = ∫₀¹ e^{(1−τ) z} τ^{k−1}/(k − 1)! dτ for k ≥ 1 (φ₁ = exprel).
///
/// Positive for every real z. Accurate to a few ulps for z ≤ 700 and k ≤ 100:
/// - z ≥ 0: the defining series, all terms positive.
/// - z < 0 with x = −z > k: the recurrence φ_{i+1} = (φ_i − 1/i!)/z upward from φ₁ = exprel(z), which damps
///   errors by i/x < 1 per step (and never cancels by more than a factor 2).
/// - z < 0 with x ≤ k: Kummer's transformation φ_k(−x) = e^{−x}/(k−1)! · Σ_j xʲ/((k + j) j!), all terms
///   positive (φ_k(z) = ₁F₁(1; k+1; z)/k!, DLMF 13.2.39 and 13.6.5).
pub fn phi(k: u32, z: f64) -> f64 {
    debug_assert!(k >= 1, "phi is defined for k ≥ 1");
    let kf = f64::from(k);
    if z >= 0.0 {
        let mut term = inv_factorial(k);
        let mut sum = term;
        for j in 1..MAX_TERMS {
            term *= z / (kf + j as f64);
            sum += term;
            if term <= EPS * sum {
                break;
            }
        }
        return sum;
    }
    let x = -z;
    if kf < x {
        let mut phi_i = exprel(z);
        let mut inv_fact_i = 1.0;
        for i in 1..k {
            phi_i = (phi_i - inv_fact_i) / z;
            inv_fact_i /= f64::from(i + 1);
        }
        return phi_i;
    }
    let mut power_over_fact = 1.0;
    let mut sum = 1.0 / kf;
    for j in 1..MAX_TERMS {
        let jf = j as f64;
        power_over_fact *= x / jf;
        let term = power_over_fact / (kf + jf);
        sum += term;
        if jf > x && term <= EPS * sum {
            break;
        }
    }
    (-x).exp() * inv_factorial(k - 1) * sum
}

/// Below this p, [`gamma_half_ratio`] steps up to it by the recurrence; from it on the asymptotic series'
/// last term kept, 0.0591/p¹⁵, is below 6e-17.
const GAMMA_HALF_RATIO_ASYMPTOTIC_MIN: f64 = 10.0;

/// Coefficients c_k of ln(Γ(p + ½)/Γ(p)) − ½ ln p ~ Σ c_k p^{−k} (k = 1, 3, …, 15; the even ones vanish):
/// (−1)^{k+1} (B_{k+1}(½) − B_{k+1}(0))/(k (k + 1)), Bernoulli polynomials (DLMF 5.11.8), from mpmath.
#[allow(clippy::excessive_precision)] // mpmath values, kept at the printed 20 digits
const GAMMA_HALF_RATIO_SERIES: [f64; 8] = [
    -0.125,
    0.005208333333333333333,
    -0.0015625,
    0.0011858258928571428571,
    -0.0016818576388888888889,
    0.0038341175426136363636,
    -0.012819730318509615385,
    0.059100405375162760417,
];

/// Γ(p + ½)/Γ(p) for p > 0 (→ √p as p → ∞; Γ(3/2)/Γ(1) = √π/2).
///
/// For p ≥ 10, √p · exp(Σ c_k p^{−k}), the asymptotic series of the log ratio (whose sum is below 0.0126 in
/// magnitude, so exp adds no error beyond an ulp); below, R(p) = R(p + m) Π_{j<m} (p + j)/(p + j + ½) with m
/// the steps up to 10, each exact but for a rounding. A few ulps in all; finite for every finite p > 0.
pub fn gamma_half_ratio(p: f64) -> f64 {
    debug_assert!(p > 0.0, "Γ(p + ½)/Γ(p) needs p > 0");
    let mut shifted = p;
    let mut factor = 1.0;
    while shifted < GAMMA_HALF_RATIO_ASYMPTOTIC_MIN {
        factor *= shifted / (shifted + 0.5);
        shifted += 1.0;
    }
    let inv = 1.0 / shifted;
    let inv2 = inv * inv;
    let series = inv
        * GAMMA_HALF_RATIO_SERIES
            .iter()
            .rev()
            .fold(0.0, |acc, &c| acc * inv2 + c);
    factor * shifted.sqrt() * series.exp()
}

/// 1/n! by direct product (exact enough: n ≤ 100 here, each step one rounding).
fn inv_factorial(n: u32) -> f64 {
    (1..=n).fold(1.0, |acc, i| acc / f64::from(i))
}

/// Taylor coefficients d_k of 1/Γ(1 + s) = Σ_k d_k s^k, k = 0 … 26 (Abramowitz & Stegun 6.1.34, whose c_{k+1}
/// they are, recomputed to 20 digits with mpmath `taylor(lambda z: 1/gamma(1+z), 0, 30)`). Truncating after
/// d₂₆ costs Σ_{k>26} |d_k| < 2e-18 for |s| ≤ 1.
#[allow(clippy::excessive_precision)] // the published digits, kept verbatim for checking
const INV_GAMMA_1P_TAYLOR: [f64; 27] = [
    1.0,
    0.577_215_664_901_532_860_61,
    -0.655_878_071_520_253_881_08,
    -0.042_002_635_034_095_235_529,
    0.166_538_611_382_291_489_5,
    -0.042_197_734_555_544_336_748,
    -0.009_621_971_527_876_973_562_1,
    0.007_218_943_246_663_099_542_4,
    -0.001_165_167_591_859_065_112_1,
    -0.000_215_241_674_114_950_972_82,
    0.000_128_050_282_388_116_186_15,
    -0.000_020_134_854_780_788_238_656,
    -1.250_493_482_142_670_657_3e-6,
    1.133_027_231_981_695_882_4e-6,
    -2.056_338_416_977_607_103_5e-7,
    6.116_095_104_481_415_817_9e-9,
    5.002_007_644_469_222_930_1e-9,
    -1.181_274_570_487_020_144_6e-9,
    1.043_426_711_691_100_510_5e-10,
    7.782_263_439_905_071_254e-12,
    -3.696_805_618_642_205_708_2e-12,
    5.100_370_287_454_475_979e-13,
    -2.058_326_053_566_506_783_2e-14,
    -5.348_122_539_423_017_982_4e-15,
    1.226_778_628_238_260_790_2e-15,
    -1.181_259_301_697_458_769_5e-16,
    1.186_692_254_751_600_332_6e-18,
];

/// (Γ(1 + s) − 1)/s for |s| ≤ 1, without the cancellation of the direct form near s = 0.
///
/// With h(s) = (1/Γ(1 + s) − 1)/s = Σ_{k≥1} d_k s^{k−1} (a plain polynomial), Γ(1 + s) = 1/(1 + s h) and
/// (Γ(1 + s) − 1)/s = −h Γ(1 + s). At s = 0 it is −γ (Euler's constant).
fn gamma1p_minus_one_over_s(s: f64) -> f64 {
    let h = INV_GAMMA_1P_TAYLOR[1..]
        .iter()
        .rev()
        .fold(0.0, |acc, &d| acc * s + d);
    -h / (1.0 + s * h)
}

/// Γ(s, x) for −0.5 ≤ s < 1 and 0 < x < 1 (Temme's form of the series, N. M. Temme, "Special Functions", 1996, §11.2):
///
/// Γ(s, x) = Γ(s) − γ(s, x) with γ(s, x) = x^s Σ_{n≥0} (−x)ⁿ/(n! (s + n)). The n = 0 term x^s/s and Γ(s) both
/// blow up as s → 0; grouping them, Γ(s) − x^s/s = (Γ(1+s) − 1)/s − (x^s − 1)/s, and
/// (x^s − 1)/s = ln x · exprel(s ln x). Hence
/// Γ(s, x) = (Γ(1+s) − 1)/s − ln x · exprel(s ln x) − x^s Σ_{n≥1} (−x)ⁿ/(n! (s + n)),
/// which at s = 0 is E₁(x) = −γ − ln x − Σ_{n≥1} (−x)ⁿ/(n · n!). Every part is O(1) (s + n ≥ 0.5, |s| ≤ 1 for
/// the Γ series); near x = 1 the parts cancel by up to a factor ~10, the price of the Γ(s) − γ(s, x) split.
fn upper_gamma_small_x(s: f64, x: f64) -> f64 {
    let ln_x = x.ln();
    let mut power_over_fact = 1.0;
    let mut tail = 0.0;
    for n in 1..MAX_TERMS {
        let nf = n as f64;
        power_over_fact *= -x / nf;
        let term = power_over_fact / (s + nf);
        tail += term;
        if term.abs() <= EPS * tail.abs() {
            break;
        }
    }
    gamma1p_minus_one_over_s(s) - ln_x * exprel(s * ln_x) - x.powf(s) * tail
}

/// eˣ Γ(s, x) = x^s / (x + 1 − s − 1(1 − s)/(x + 3 − s − 2(2 − s)/(x + 5 − s − …))) for x ≥ 1 and s < 1
/// (Legendre's continued fraction, DLMF 8.9.2), evaluated by the modified Lentz method
/// (Numerical Recipes, 3rd ed., §6.2 `gcf`). With x + 1 − s ≥ 1 every partial denominator is positive and the
/// fraction converges in at most ~60 terms at x = 1, fewer as x grows.
fn upper_gamma_scaled_cf(s: f64, x: f64) -> f64 {
    // Lentz's guard against a zero denominator: far below any value the fraction takes.
    let tiny = f64::MIN_POSITIVE / EPS;
    let mut b = x + 1.0 - s;
    let mut c = 1.0 / tiny;
    let mut d = 1.0 / b;
    let mut h = d;
    for i in 1..MAX_TERMS {
        let i = i as f64;
        let an = -i * (i - s);
        b += 2.0;
        d = an * d + b;
        if d.abs() < tiny {
            d = tiny;
        }
        c = b + an / c;
        if c.abs() < tiny {
            c = tiny;
        }
        d = 1.0 / d;
        let delta = d * c;
        h *= delta;
        if (delta - 1.0).abs() <= EPS {
            break;
        }
    }
    x.powf(s) * h
}

/// eˣ Γ(s, x) = eˣ ∫ₓ^∞ t^{s−1} e^{−t} dt for x > 0 and every real s (Γ(0, x) = E₁(x)).
///
/// The scaling removes the e^{−x} that makes Γ(s, x) underflow for large x; eˣ Γ(s, x) ≈ x^{s−1} there.
/// Accurate to ~1e-15 relative while the result and x^s are finite (checked against mpmath for
/// s ∈ [−9, 11], x ∈ [1e-6, 1e6]). Method:
/// - s < 1, x ≥ 1: Legendre's continued fraction.
/// - s < 0, x < 1: Temme's series at s₀ = s − round(s) ∈ [−0.5, 0.5] (exact through the removable
///   singularity at s₀ = 0), then downward Γ(s − 1, x) = (Γ(s, x) − x^{s−1} e^{−x})/(s − 1). For s ≤ 0.5 and
///   x < 1, Γ(s, x) stays below ~0.7 x^{s−1} e^{−x}, so the subtraction loses at most a factor ~3 once and the
///   ratio shrinks further with each step (for s → −∞ it tends to x/(x + |s|)). Starting instead from
///   s₀ ∈ [0, 1) fails near s₀ = 1, where Γ(s₀, x) → x^{s₀−1} e^{−x} cancels completely (s just below −1).
/// - s ≥ 0: s₀ = s − ⌊s⌋ ∈ [0, 1) from the continued fraction (x ≥ 1) or Temme's series (x < 1), then upward
///   Γ(s + 1, x) = s Γ(s, x) + x^s e^{−x}, all terms positive.
pub fn upper_gamma_scaled(s: f64, x: f64) -> f64 {
    debug_assert!(x > 0.0, "upper_gamma_scaled needs x > 0");
    if s < 1.0 && x >= 1.0 {
        return upper_gamma_scaled_cf(s, x);
    }
    if s < 0.0 && x < 1.0 {
        // Base s₀ = s − round(s) ∈ [−0.5, 0.5]: starting lower from s₀ near 1 would cancel, since
        // Γ(s₀, x) → x^{s₀−1} e^{−x} as s₀ → 1.
        let steps = -s.round();
        let s0 = s + steps;
        let mut g = upper_gamma_small_x(s0, x) * x.exp();
        for j in 0..steps as u32 {
            let sj = s0 - f64::from(j);
            g = (g - x.powf(sj - 1.0)) / (sj - 1.0);
        }
        return g;
    }
    let steps = s.floor();
    let s0 = s - steps;
    let mut g = if x >= 1.0 {
        upper_gamma_scaled_cf(s0, x)
    } else {
        upper_gamma_small_x(s0, x) * x.exp()
    };
    for j in 0..steps as u32 {
        let sj = s0 + f64::from(j);
        g = sj * g + x.powf(sj);
    }
    g
}

#[cfg(test)]
#[allow(clippy::excessive_precision)] // mpmath reference values, kept at the printed 20 digits
mod tests {
    use super::*;
    use crate::model::math::tolerance::{REL_TOL_SPECIAL, relative_difference as rel_err};

    /// (p, Γ(p + ½)/Γ(p)) from mpmath 1.3 at 30 digits, p the exact doubles; both sides of the switch to the
    /// asymptotic series at 10, and p far beyond where ln Γ could give the ratio.
    const GAMMA_HALF_RATIO: [(f64, f64); 10] = [
        (1.0, 0.88622692545275801365),
        (1.5, std::f64::consts::FRAC_2_SQRT_PI),
        (2.75, 1.5850045281367708352),
        (9.999, 3.1228513798142109311),
        (10.0, 3.1230114333906127848),
        (10.5, 3.2020375888099552726),
        (123.456, 11.099831243667407841),
        (1e6, 999.9998750000078125),
        (1e20, 9999999999.9999999999875),
        (1e300, 1.0000000000000000263e150),
    ];

    #[test]
    fn gamma_half_ratio_matches_mpmath() {
        for (p, want) in GAMMA_HALF_RATIO {
            let got = gamma_half_ratio(p);
            assert!(
                rel_err(got, want) <= REL_TOL_SPECIAL,
                "Γ({p} + ½)/Γ({p}) = {got}, want {want}"
            );
        }
    }

    /// (s, x, eˣ Γ(s, x)) from mpmath 1.3 at 40 digits: `exp(x) * gammainc(s, x)` with s, x the exact doubles.
    const UPPER_GAMMA_SCALED: [(f64, f64, f64); 72] = [
        (-2.5, 1e-06, 399999733333865.76768),
        (-2.5, 0.1, 119.06090905719629402),
        (-2.5, 0.5, 1.7681972190186854791),
        (-2.5, 0.999, 0.26320709860966155388),
        (-2.5, 1.0, 0.26246818339130021011),
        (-2.5, 50.0, 1.0586073130084180501e-6),
        (-1.999999999, 1e-06, 499999493348.86957208),
        (-1.999999999, 0.1, 46.007321186651824466),
        (-1.999999999, 0.999, 0.29887665826650793266),
        (-1.999999999, 1.0, 0.29817368124184025809),
        (-1.999999999, 2.5, 0.031762918277812035546),
        (-1.999999999, 1000000.0, 9.9999701382747129012e-19),
        (-1.0000001, 1e-06, 999988.04323463071725),
        (-1.0000001, 0.1, 7.9853587399326549427),
        (-1.0000001, 0.5, 1.0770893935350729084),
        (-1.0000001, 0.999, 0.40424967387740222322),
        (-1.0000001, 2.5, 0.096474152641069600954),
        (-1.0000001, 50.0, 0.00038488991858782802491),
        (-0.999999999999, 1e-06, 999986.7616780535344),
        (-0.999999999999, 0.1, 7.9853574552787016844),
        (-0.999999999999, 0.5, 1.0770893675160093489),
        (-0.999999999999, 0.999, 0.40424968763245272317),
        (-0.999999999999, 1.0, 0.40365263767694360987),
        (-0.999999999999, 1000000.0, 9.999980000198151543e-13),
        (-0.5, 1e-06, 1996.4590887559462067),
        (-0.5, 0.1, 3.7595365409130593083),
        (-0.5, 0.5, 0.97388532182769035144),
        (-0.5, 0.999, 0.48477192461889169855),
        (-0.5, 2.5, 0.17026640662253594537),
        (-0.5, 1000000.0, 9.9999850000374998688e-10),
        (0.0, 1e-06, 13.238309131365003501),
        (0.0, 0.1, 2.0146425447084516348),
        (0.0, 0.5, 0.92291063248373046883),
        (0.0, 0.999, 0.59675131336868582481),
        (0.0, 1.0, 0.59634736232319407434),
        (0.0, 50.0, 0.019615109930114870365),
        (1e-10, 1e-06, 13.23830912192048158),
        (1e-10, 0.1, 2.014642544489043276),
        (1e-10, 0.999, 0.59675131339525573004),
        (1e-10, 1.0, 0.59634736234979061285),
        (1e-10, 2.5, 0.30352583652141019789),
        (1e-10, 1000000.0, 9.999990013835497692e-7),
        (0.5, 1e-06, 1.7704556220269192934),
        (0.5, 0.1, 1.2825093897118495901),
        (0.5, 0.5, 0.92727090145924987308),
        (0.5, 0.999, 0.75811441300332783499),
        (0.5, 1.0, 0.75787215614131210604),
        (0.5, 50.0, 0.1400475841930957119),
        (3.0, 1e-06, 2.000002000001),
        (3.0, 0.1, 2.2100000000000000122),
        (3.0, 0.999, 4.9960009999999999964),
        (3.0, 2.5, 13.25),
        (3.0, 1000000.0, 1000002000002.0),
        (-9.0, 1e-06, 1.111110972222242516e+53),
        (-9.0, 0.1, 109741739.2579033439),
        (-9.0, 0.999, 0.09983476984034591651),
        (-9.0, 1.0, 0.098929132640646155219),
        (-9.0, 1000000.0, 9.9999000010999868002e-61),
        (11.0, 1e-06, 3628803.6288018144006),
        (11.0, 0.5, 5982879.7470703125),
        (11.0, 0.999, 9854241.8304014108791),
        (11.0, 50.0, 121354850321068800.0),
        (11.0, 1000000.0, 1.00001000009000072e+60),
        (0.999999999, 1e-06, 1.0000000005772014113),
        (0.999999999, 0.999, 0.99999999940424920408),
        (0.999999999, 1.0, 0.99999999940365265481),
        (-1.0, 1e-06, 999986.76169086868025),
        (-1.0, 0.999, 0.40424968763231517708),
        (-1.0, 1.0, 0.40365263767680592566),
        (-2.0, 1e-06, 499999500006.61919982),
        (-2.0, 0.5, 1.4614553162418652344),
        (-2.0, 1.0, 0.29817368116159703717),
    ];

    #[test]
    fn upper_gamma_scaled_matches_mpmath() {
        for (s, x, want) in UPPER_GAMMA_SCALED {
            let got = upper_gamma_scaled(s, x);
            assert!(
                rel_err(got, want) <= REL_TOL_SPECIAL,
                "s={s} x={x}: got {got}, want {want}"
            );
        }
    }

    #[test]
    fn upper_gamma_scaled_is_continuous_across_the_method_switch_at_x_1() {
        for s in [-3.5, -1.0, 0.0, 0.3, 2.7] {
            let below = upper_gamma_scaled(s, 1.0 - 1e-15);
            let at = upper_gamma_scaled(s, 1.0);
            assert!(
                rel_err(below, at) <= REL_TOL_SPECIAL,
                "s={s}: {below} vs {at}"
            );
        }
    }

    #[test]
    fn exprel_is_exact_at_and_near_zero() {
        // Reference values within two ulps: (e^x − 1)/x by mpmath, rounded to double.
        assert_eq!(exprel(0.0), 1.0);
        assert_eq!(exprel(1e-300), 1.0);
        // mpmath: (exp(x) − 1)/x at x = ±1e-9 and 1.
        assert!(rel_err(exprel(1e-9), 1.000_000_000_5) <= 2.0 * EPS);
        assert!(rel_err(exprel(-1e-9), 0.999_999_999_5) <= 2.0 * EPS);
        assert!(rel_err(exprel(1.0), 1.718_281_828_459_045_2) <= 2.0 * EPS);
        assert!(rel_err(exprel(-1e5), 1e-5) <= 2.0 * EPS);
    }

    /// (k, z, φ_k(z)) from mpmath: `(exp(z) − Σ_{j<k} zʲ/j!)/z^k` at 400 digits (cross-checked by quadrature).
    const PHI: [(u32, f64, f64); 12] = [
        (1, -0.5, 0.78693868057473315279),
        (2, 2.0, 1.0972640247326625568),
        (2, -1e-9, 0.49999999983333333337),
        (2, -5.0, 0.16026951787996341868),
        (3, -5.0, 0.067946096424007316263),
        (5, -4.999, 0.0043849462521499117955),
        (5, -5.001, 0.0043840748767148733363),
        (7, -30.0, 0.000038393735711019661633),
        (12, -11.5, 1.0886735697625275933e-9),
        (20, -1e6, 8.220479057366053315e-24),
        (20, 0.5, 4.2104559064818103062e-19),
        (4, -1e100, 1.6666666666666666402e-101),
    ];

    #[test]
    fn phi_matches_mpmath_on_both_sides_of_the_method_switch() {
        for (k, z, want) in PHI {
            let got = phi(k, z);
            assert!(
                rel_err(got, want) <= REL_TOL_SPECIAL,
                "k={k} z={z}: got {got}, want {want}"
            );
        }
    }

    #[test]
    fn gamma1p_series_reproduces_known_values() {
        // (Γ(1+s) − 1)/s: −γ at 0, 0 at s = 1, (√π/2 − 1)/0.5 at s = 0.5.
        assert!(rel_err(gamma1p_minus_one_over_s(0.0), -0.577_215_664_901_532_9) <= 2.0 * EPS);
        assert!(gamma1p_minus_one_over_s(1.0).abs() <= 2.0 * EPS);
        let half = (std::f64::consts::PI.sqrt() / 2.0 - 1.0) / 0.5;
        assert!(rel_err(gamma1p_minus_one_over_s(0.5), half) <= 1e-14);
    }
}
