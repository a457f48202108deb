//! Polynomial approximations of Fresnel reflectance: Schlick and Lazanyi–Schlick, and the
//! Lazanyi correction term normalized to a maximum of 1.
//!
//! Formulas (docs/maths.md "Fresnel"), with c = cos θ and x = 1 − c:
//! - Schlick (1994): F = F₀ + (1 − F₀) x⁵, F₀ = F(θ = 0) ∈ [0, 1].
//! - Lazanyi–Schlick (Lazányi and Szirmay-Kalos 2005): F = F₀ + (1 − F₀) x⁵ − a c x⁶; a = 0 is Schlick.
//! - The normalized Lazanyi term c x⁶ / ((1/7)(6/7)⁶), which the notebook compares with b₂.
//!
//! Domain of a: F stays in [0, 1] for every θ exactly when a_min(F₀) ≤ a ≤ a_max(F₀), with
//! - a_min = −5 (1 − F₀): F ≤ 1 ⇔ −a ≤ (1 − F₀)(1 − x⁵)/(c x⁶) = (1 − F₀)(1 + x + x² + x³ + x⁴)/x⁶,
//!   which decreases in x and tends to 5 (1 − F₀) at grazing incidence (x → 1);
//! - a_max = min over x ∈ (0, 1) of h(x) = (F₀ + (1 − F₀) x⁵)/((1 − x) x⁶): F ≥ 0 ⇔ a ≤ h(x) for all x.
//!   ln h is strictly convex (its second derivative is at least 1/(1 − x)² + 1/x² > 0), so the minimum
//!   is the unique root of (ln h)′, found by bisection. a_max(0) = 4 (at x = 1/2) and
//!   a_max(1) = 1/((1/7)(6/7)⁶) ≈ 17.65 (at x = 6/7).
//!
//! Stable forms: for θ < π/3, x = 1 − cos θ is computed as 2 sin²(θ/2), since 1 − cos θ rounds to
//! 0 for θ < 1e-8 and loses relative accuracy for small θ; beyond, 1 − cos θ is the more accurate
//! form. The Lazanyi results are clamped into [0, 1] against rounding at the ends of the domain.

/// Peak of the Lazanyi term c (1 − c)⁶, at c = 1/7 (where its derivative (1 − c)⁵ (1 − 7c) vanishes):
/// (1/7)(6/7)⁶.
pub const LAZANYI_TERM_PEAK: f64 =
    (1.0 / 7.0) * (6.0 / 7.0) * (6.0 / 7.0) * (6.0 / 7.0) * (6.0 / 7.0) * (6.0 / 7.0) * (6.0 / 7.0);

/// 1 − cos θ for θ ∈ [0, π/2], in [0, 1]: 2 sin²(θ/2) for θ < π/3, 1 − cos θ beyond.
///
/// 2 sin²(θ/2) is accurate to ~3 ulps everywhere; 1 − cos θ is accurate to ε c/(2(1 − c)), at most
/// ε/2 for c ≤ 1/2 (θ ≥ π/3), and near π/2 it is the better one (it keeps the 1 − 6e-17 of
/// θ = fl(π/2), which 2 sin²(π/4) rounds 2 ulps below 1).
fn one_minus_cos(theta: f64) -> f64 {
    if theta < std::f64::consts::FRAC_PI_3 {
        let sin_half = (0.5 * theta).sin();
        2.0 * sin_half * sin_half
    } else {
        1.0 - theta.cos()
    }
}

/// Schlick's approximation F = F₀ + (1 − F₀)(1 − cos θ)⁵, for `f0` ∈ [0, 1] and θ ∈ [0, π/2].
pub fn schlick(f0: f64, theta: f64) -> f64 {
    f0 + (1.0 - f0) * one_minus_cos(theta).powi(5)
}

/// Lazanyi–Schlick F = F₀ + (1 − F₀)(1 − c)⁵ − a c (1 − c)⁶, c = cos θ, clamped into [0, 1].
///
/// Within [0, 1] without the clamp (up to rounding) for `a` in [`lazanyi_a_range`]`(f0)`.
pub fn lazanyi(f0: f64, a: f64, theta: f64) -> f64 {
    let x = one_minus_cos(theta);
    (f0 + (1.0 - f0) * x.powi(5) - a * theta.cos() * x.powi(6)).clamp(0.0, 1.0)
}

/// The Lazanyi term normalized to a maximum of 1: c (1 − c)⁶ / ((1/7)(6/7)⁶), c = cos θ; in [0, 1].
pub fn lazanyi_term(theta: f64) -> f64 {
    (theta.cos() * one_minus_cos(theta).powi(6) / LAZANYI_TERM_PEAK).min(1.0)
}

/// The range [a_min, a_max] of Lazanyi's `a` for which F stays within [0, 1] at every θ, given
/// `f0` ∈ [0, 1]: a_min = −5 (1 − F₀), a_max = min over x of (F₀ + (1 − F₀) x⁵)/((1 − x) x⁶).
pub fn lazanyi_a_range(f0: f64) -> (f64, f64) {
    let h = |x: f64| (f0 + (1.0 - f0) * x.powi(5)) / ((1.0 - x) * x.powi(6));
    // (ln h)′(x) = 5 (1 − F₀) x⁴/(F₀ + (1 − F₀) x⁵) + 1/(1 − x) − 6/x rises from −∞ to +∞ on (0, 1).
    let d_ln_h = |x: f64| {
        5.0 * (1.0 - f0) * x.powi(4) / (f0 + (1.0 - f0) * x.powi(5)) + 1.0 / (1.0 - x) - 6.0 / x
    };
    let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
    loop {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if d_ln_h(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (-5.0 * (1.0 - f0), h(lo).min(h(hi)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_range_has_the_closed_forms_at_the_ends() {
        let (a_min, a_max) = lazanyi_a_range(0.0);
        assert_eq!(a_min, -5.0);
        assert!((a_max - 4.0).abs() < 1e-14, "{a_max}");
        let (a_min, a_max) = lazanyi_a_range(1.0);
        assert_eq!(a_min, 0.0);
        assert!((a_max - 1.0 / LAZANYI_TERM_PEAK).abs() < 1e-13, "{a_max}");
    }

    #[test]
    fn lazanyi_term_peaks_at_one_seventh() {
        let theta_peak = (1.0_f64 / 7.0).acos();
        assert!((lazanyi_term(theta_peak) - 1.0).abs() < 1e-14);
        assert_eq!(lazanyi_term(0.0), 0.0);
    }
}
