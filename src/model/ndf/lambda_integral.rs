//! Smith's Λ(θo) of any isotropic NDF by docs/maths.md's 1D integral, fast enough to run per plotted sample.
//!
//! Λ(θo) = (2/cos θo) ∫_{π/2−θo}^{π/2} D(θm) [b sin φ₀ − a (π − φ₀)] sin θm dθm,
//! a = cos θo cos θm, b = sin θo sin θm, φ₀ = arccos(−a/b): the back-facing projected area of the microfacets
//! seen from θo, over cos θo, with the azimuth integrated analytically.
//!
//! - Variables: t = θm − (π/2 − θo) ∈ [0, θo] from the edge and d = π/2 − θm = θo − t from grazing, whichever
//!   is small is the one formed first, so that neither loses digits. Then cos θm = sin d, sin θm = sin θm (θm
//!   is accurate relative to itself where it is small) and
//!   b² − a² = sin t · sin(θo + d) without cancellation (sin(θo + d) taken as sin(2θe + t) past π/2), and with s = √(b² − a²) and ψ = π − φ₀ = atan(s/a) the
//!   bracket is g = s − a atan(s/a) = a (r − atan r), r = s/a, summed as a series for r < ½ (it is ~a r³/3,
//!   the cancellation the textbook form suffers at the edge).
//! - Panels: the integrand has a square-root edge at t = 0 (g ~ t^{3/2}), is analytic in t up to a
//!   singularity at t = −θe (θm = 0, with θe = π/2 − θo the edge) and lives on the scales D itself varies on:
//!   the lobe's decay away from the edge (a far tail: Λ ≈ 1e-135 for Beckmann α = 0.1 at 30°) and grazing
//!   lobes at θm → π/2 (super-rough α > 1). The width over which D stays within a factor e of its value at each
//!   end is found by a galloping bisection on the exponent of 2 ([`flat_width`], ≤ ~22 evaluations); each half
//!   of [0, θo] is then split geometrically, ratio [`PANEL_RATIO`] = 2, from a sixteenth of that width (or of θe,
//!   or of the half) outwards, and each panel takes the 16-point Gauss–Legendre rule, the one at the edge after
//!   t = u² (which makes the integrand smooth there). A lobe of any width so meets panels of its own scale.
//! - Far tails: D is evaluated in log space by every family, so it is representable wherever Λ is; the
//!   products D g sin θm w at the nodes that carry the integral are ~Λ cos θo/16 ≥ 1e-297 whenever Λ > 1e-280,
//!   so Λ does not underflow to a wrong 0 (below ABS_FLOOR it may lose relative precision, like every value).
//! - Cost: ~2 + log₂(half/edge width) + log₂(half/grazing width) panels of 16 nodes plus the width searches:
//!   ~200–500 evaluations of D at ordinary parameters.
//! - D is assumed smooth wherever it is flat by the width test: a D with a weak power singularity at grazing
//!   (Phong's cos^{α_p} θ for non-integer α_p < 1, ~(π/2 − θ)^{α_p}) is integrated to only ~1e-7; no family
//!   that takes this route has one.

use crate::model::math::gauss_legendre;
use std::f64::consts::FRAC_PI_2;

/// π/2 − FRAC_PI_2: the low part of π/2, so that the edge π/2 − θo is formed to an ulp also near θo = π/2.
const FRAC_PI_2_LO: f64 = 6.123233995736766e-17;

/// Ratio of successive panel ends: a feature of any width w meets a panel of width between w and 2w, which the
/// 16-point rule integrates to ~1e-15. Lobes off both ends are as narrow as ~0.2 of their distance from θm = 0
/// (SGD with a₂ = −10 peaks like θ²⁰ e^{−θ²/a₁}); a ratio of 4 left 2e-9 there.
const PANEL_RATIO: f64 = 2.0;

/// The geometric split starts this many times [`PANEL_RATIO`] below the width where D stays flat.
const PANEL_DEPTH: i32 = 4;

/// Below this r = s/a, r − atan r is summed as its series (which then needs ≤ 27 terms); above, the direct
/// difference loses at most a factor r/(r − atan r) ≤ 14 of atan's ulp.
const SERIES_MAX_R: f64 = 0.5;

/// Largest exponent j of the trial widths max · 2^{−j} of [`flat_width`]: 2^{−1100} · π/2 is 0 in doubles.
const FLAT_WIDTH_MAX_EXPONENT: i32 = 1100;

/// Λ(θo) for θo ∈ [0, π/2] of the isotropic NDF `d` (D(θm) for θm ∈ [0, π/2], normalized over projected
/// area), by docs/maths.md's 1D integral (module header). Λ(0) = 0; finite and ≥ 0 for every θo ≤ FRAC_PI_2 (where
/// Λ ~ 1/cos θo is large but finite, cos FRAC_PI_2 = 6.1e-17); never NaN for finite non-negative D.
pub fn lambda_integral(d: impl Fn(f64) -> f64, theta_o: f64) -> f64 {
    debug_assert!(
        (0.0..=FRAC_PI_2).contains(&theta_o),
        "θo = {theta_o} outside [0, π/2]"
    );
    if theta_o <= 0.0 {
        return 0.0;
    }
    let cos_o = theta_o.cos();
    let edge = (FRAC_PI_2 - theta_o) + FRAC_PI_2_LO;
    let half = 0.5 * theta_o;
    // g sin θm D(θm) at the microfacet angle with offsets t from the edge and d from grazing (t + d = θo).
    // sin(θo + d) is sin(2θe + t) past π/2, where θo + d nears π and its rounding would dominate.
    let integrand = |t: f64, dist: f64, theta_m: f64| {
        let a = cos_o * dist.sin();
        let sin_sum = if theta_o + dist <= FRAC_PI_2 {
            (theta_o + dist).sin()
        } else {
            (2.0 * edge + t).sin()
        };
        let s = (t.sin() * sin_sum).sqrt();
        d(theta_m) * back_facing_excess(s, a) * theta_m.sin()
    };
    let from_edge = |t: f64| integrand(t, theta_o - t, edge + t);
    let from_grazing =
        |dist: f64| integrand(theta_o - dist, dist, (FRAC_PI_2 - dist) + FRAC_PI_2_LO);

    let edge_width = flat_width(&d, edge, 1.0, half).min(edge);
    let grazing_width = flat_width(&d, FRAC_PI_2, -1.0, half);
    let mut sum = 0.0;
    let mut lo = panel_start(edge_width, half);
    // The first panel after t = u², dt = 2u du: g ~ t^{3/2} becomes ~u³, smooth.
    sum += gauss_legendre::integrate(|u| 2.0 * u * from_edge(u * u), 0.0, lo.sqrt());
    for_each_panel(&mut lo, half, |a, b| {
        sum += gauss_legendre::integrate(from_edge, a, b)
    });
    let mut lo = panel_start(grazing_width, half);
    sum += gauss_legendre::integrate(from_grazing, 0.0, lo);
    for_each_panel(&mut lo, half, |a, b| {
        sum += gauss_legendre::integrate(from_grazing, a, b)
    });
    2.0 * sum / cos_o
}

/// The first panel end of a half of length `half` whose integrand is flat over `width`.
fn panel_start(width: f64, half: f64) -> f64 {
    width.min(half) * PANEL_RATIO.powi(-PANEL_DEPTH)
}

/// Calls `panel(a, b)` for the geometric panels from `*lo` to `end`, each [`PANEL_RATIO`] times the last (the
/// final one ends at `end`, at most that ratio long).
fn for_each_panel(lo: &mut f64, end: f64, mut panel: impl FnMut(f64, f64)) {
    while *lo < end {
        let hi = if *lo * PANEL_RATIO < end {
            *lo * PANEL_RATIO
        } else {
            end
        };
        panel(*lo, hi);
        *lo = hi;
    }
}

/// g = s − a atan(s/a) = a (r − atan r) with r = s/a, for s, a ≥ 0: the azimuthal integral of the
/// back-facing projection, over 2 (module header). The series r³/3 − r⁵/5 + … for r < ½ avoids the
/// cancellation of r − atan r; a = 0 (θm = π/2) gives s.
#[inline]
fn back_facing_excess(s: f64, a: f64) -> f64 {
    if s < SERIES_MAX_R * a {
        let r = s / a;
        let r2 = r * r;
        let mut term = r * r2;
        let mut sum = 0.0;
        for k in 0..40 {
            let next = term / f64::from(2 * k + 3);
            sum += if k % 2 == 0 { next } else { -next };
            if next <= f64::EPSILON * sum {
                break;
            }
            term *= r2;
        }
        a * sum
    } else {
        s - a * s.atan2(a)
    }
}

/// The largest h = max · 2^{−j} (0 ≤ j ≤ [`FLAT_WIDTH_MAX_EXPONENT`]) with D(anchor + direction · h) within a
/// factor e of D(anchor) (both 0 counts as within): the scale D varies on next to `anchor`. Galloping on j
/// (1, 2, 4, …) then bisecting: ≤ ~22 evaluations of D; assumes "within" holds for small h and fails beyond some
/// width, which a factor-2 answer suffices for.
fn flat_width(d: impl Fn(f64) -> f64, anchor: f64, direction: f64, max: f64) -> f64 {
    let at_anchor = d(anchor);
    let flat = |j: i32| {
        let h = max * 2f64.powi(-j);
        let value = d((anchor + direction * h).clamp(0.0, FRAC_PI_2));
        if value == at_anchor {
            return true;
        }
        if value == 0.0 || at_anchor == 0.0 {
            return false;
        }
        (value / at_anchor).ln().abs() <= 1.0
    };
    if flat(0) {
        return max;
    }
    // Invariant: flat(lo) is false, flat(hi) true (or hi is the largest exponent tried).
    let (mut lo, mut hi) = (0, 1);
    while hi < FLAT_WIDTH_MAX_EXPONENT && !flat(hi) {
        lo = hi;
        hi = (2 * hi).min(FLAT_WIDTH_MAX_EXPONENT);
    }
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if flat(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    max * 2f64.powi(-hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_back_facing_excess_is_continuous_at_the_series_switch() {
        let a = 0.7;
        let below = back_facing_excess(SERIES_MAX_R * a * (1.0 - 1e-15), a);
        let above = back_facing_excess(SERIES_MAX_R * a, a);
        assert!(
            ((below - above) / above).abs() <= 1e-14,
            "{below} vs {above}"
        );
        // r − atan r = r³/3 − r⁵/5 + … for tiny r, where the direct difference loses everything.
        let tiny = back_facing_excess(3e-6, 1.0);
        let want = 9e-18 * (1.0 - 0.6 * 9e-12);
        assert!((tiny / want - 1.0).abs() <= 1e-15, "{tiny:e}");
        assert_eq!(back_facing_excess(0.3, 0.0), 0.3);
    }

    #[test]
    fn flat_width_finds_a_gaussian_scale() {
        // D = exp(−(θ/w)²) from θ = 0: within a factor e up to h = w, so the answer is in (w/2, w].
        for w in [1e-200, 1e-8, 0.01, 0.3] {
            let h = flat_width(|t: f64| (-(t / w).powi(2)).exp(), 0.0, 1.0, 1.0);
            assert!(h > 0.5 * w && h <= w, "w = {w:e}: {h:e}");
        }
    }
}
