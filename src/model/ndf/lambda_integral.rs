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
//!   ~200–500 evaluations of D at ordinary parameters. All panels' nodes are laid out first, then D runs over
//!   them as one block and the rest of the integrand in vector lanes (branch-free sin and atan,
//!   [`crate::model::math::elementary`]): 4–6 µs a value for families whose D is branch-free.
//! - D is assumed smooth wherever it is flat by the width test: a D with a weak power singularity at grazing
//!   (Phong's cos^{α_p} θ for non-integer α_p < 1, ~(π/2 − θ)^{α_p}) is integrated to only ~1e-7; no family
//!   that takes this route has one.

use crate::model::math::elementary::{self, Block};
use crate::model::math::gauss_legendre;
use crate::model::ndf::Density;
use std::f64::consts::FRAC_PI_2;

/// π/2 − FRAC_PI_2: the low part of π/2, so that the edge π/2 − θo is formed to an ulp also near θo = π/2.
const FRAC_PI_2_LO: f64 = 6.123233995736766e-17;

/// Ratio of successive panel ends: a feature of any width w meets a panel of width between w and 2w, which the
/// 16-point rule integrates to ~1e-15. Lobes off both ends are as narrow as ~0.2 of their distance from θm = 0
/// (SGD with a₂ = −10 peaks like θ²⁰ e^{−θ²/a₁}); a ratio of 4 left 2e-9 there.
const PANEL_RATIO: f64 = 2.0;

/// The geometric split starts this many times [`PANEL_RATIO`] below the width where D stays flat.
const PANEL_DEPTH: i32 = 4;

/// Below this r = s/a, r − atan r is summed as its series (which then needs ≤ 27 terms, [`SERIES`]); above,
/// the direct difference loses at most a factor r/(r − atan r) ≤ 14 of atan's ulp.
const SERIES_MAX_R: f64 = 0.5;

/// The coefficients 1/(2k + 3) of the series (r − atan r)/r³ = Σₖ (−r²)ᵏ/(2k + 3), as many terms as
/// r < [`SERIES_MAX_R`] needs: the 27th is below 2⁻⁵³ of the first (r²ᵏ · 3/(2k + 3) ≤ 4⁻²⁶ · 3/55).
const SERIES: [f64; 27] = {
    let mut c = [0.0; 27];
    let mut k = 0;
    while k < c.len() {
        c[k] = 1.0 / (2 * k + 3) as f64;
        k += 1;
    }
    c
};

/// Largest exponent j of the trial widths max · 2^{−j} of [`flat_width`]: 2^{−1100} · π/2 is 0 in doubles.
const FLAT_WIDTH_MAX_EXPONENT: i32 = 1100;

/// Λ(θo) for θo ∈ [0, π/2] of the isotropic NDF `d` (D(θm) for θm ∈ [0, π/2], normalized over projected
/// area), by docs/maths.md's 1D integral (module header). Λ(0) = 0; finite and ≥ 0 for every θo ≤ FRAC_PI_2 (where
/// Λ ~ 1/cos θo is large but finite, cos FRAC_PI_2 = 6.1e-17); never NaN for finite non-negative D.
/// The panels' nodes are laid out first ([`Nodes`]), then D runs over all of them as one block
/// ([`Density::at_many`]) and the rest of the integrand in vector lanes; the sum is taken panel by panel.
pub fn lambda_integral(d: &(impl Density + ?Sized), theta_o: f64) -> f64 {
    debug_assert!(
        (0.0..=FRAC_PI_2).contains(&theta_o),
        "θo = {theta_o} outside [0, π/2]"
    );
    if theta_o <= 0.0 {
        return 0.0;
    }
    let edge = (FRAC_PI_2 - theta_o) + FRAC_PI_2_LO;
    let half = 0.5 * theta_o;
    let edge_width = flat_width(|t| d.at(t), edge, 1.0, half).min(edge);
    let grazing_width = flat_width(|t| d.at(t), FRAC_PI_2, -1.0, half);
    let mut nodes = Nodes::new(theta_o, edge);
    let mut lo = panel_start(edge_width, half);
    // The first panel after t = u², dt = 2u du: g ~ t^{3/2} becomes ~u³, smooth.
    nodes.panel(0.0, lo.sqrt(), Offset::SquaredFromEdge);
    for_each_panel(&mut lo, half, |a, b| nodes.panel(a, b, Offset::FromEdge));
    let mut lo = panel_start(grazing_width, half);
    nodes.panel(0.0, lo, Offset::FromGrazing);
    for_each_panel(&mut lo, half, |a, b| nodes.panel(a, b, Offset::FromGrazing));
    2.0 * nodes.integral(d) / theta_o.cos()
}

/// What a panel's variable x is: the offset from the edge t = x, its square t = x² (dt = 2x dx, the
/// first panel at the edge), or the offset from grazing d = x (t = θo − d).
#[derive(Clone, Copy)]
enum Offset {
    FromEdge,
    SquaredFromEdge,
    FromGrazing,
}

/// The 16-point Gauss–Legendre nodes of every panel of one Λ(θo), in columns: for node k, t (from the
/// edge), d = θo − t (from grazing), θm and the factor jacobian × weight × half-width; each panel's 16
/// nodes in [`gauss_legendre::integrate`]'s order.
struct Nodes {
    theta_o: f64,
    cos_o: f64,
    edge: f64,
    t: Vec<f64>,
    dist: Vec<f64>,
    theta_m: Vec<f64>,
    factor: Vec<f64>,
}

/// Panels room is made for at once in [`Nodes`]: each half of a Λ(θo) starts [`PANEL_DEPTH`] ratios
/// below its flat width and mostly ends within a few ratios above it; a lobe far narrower than θo
/// takes more, and the columns grow.
const RESERVED_PANELS: usize = 2 * (PANEL_DEPTH as usize + 4);

impl Nodes {
    fn new(theta_o: f64, edge: f64) -> Nodes {
        let column = || Vec::with_capacity(RESERVED_PANELS * gauss_legendre::POINTS);
        Nodes {
            theta_o,
            cos_o: theta_o.cos(),
            edge,
            t: column(),
            dist: column(),
            theta_m: column(),
            factor: column(),
        }
    }

    /// The nodes of the panel [a, b] in the variable `offset` names. t and d are each formed
    /// directly where small (module header): from the edge θm = edge + t, from grazing θm =
    /// (π/2 − d) + its low part.
    fn panel(&mut self, a: f64, b: f64, offset: Offset) {
        for (x, weight) in gauss_legendre::nodes(a, b) {
            let (t, dist, theta_m, jacobian) = match offset {
                Offset::FromEdge => (x, self.theta_o - x, self.edge + x, 1.0),
                Offset::SquaredFromEdge => {
                    let t = x * x;
                    (t, self.theta_o - t, self.edge + t, 2.0 * x)
                }
                Offset::FromGrazing => (self.theta_o - x, x, (FRAC_PI_2 - x) + FRAC_PI_2_LO, 1.0),
            };
            self.t.push(t);
            self.dist.push(dist);
            self.theta_m.push(theta_m);
            self.factor.push(jacobian * weight);
        }
    }

    /// Σ over the panels of Σ factor · D(θm) g sin θm: D for all nodes as one block, the rest in
    /// vector lanes ([`Integrand`]), then each panel's 16 values summed in pairs as
    /// [`gauss_legendre::integrate`] does.
    fn integral(&self, d: &(impl Density + ?Sized)) -> f64 {
        let mut values = vec![0.0; self.t.len()];
        d.at_many(&self.theta_m, &mut values);
        elementary::widest(&mut Integrand {
            nodes: self,
            values: &mut values,
        });
        values
            .chunks_exact(gauss_legendre::POINTS)
            .map(|panel| {
                panel
                    .chunks_exact(2)
                    .map(|pair| pair[0] + pair[1])
                    .sum::<f64>()
            })
            .sum()
    }
}

/// [`Nodes::integral`]'s stage in vector lanes: each value D(θm) becomes factor · D g sin θm, with
/// a = cos θo cos θm = cos θo sin d, s = √(b² − a²) = √(sin t · sin(θo + d)) (sin(θo + d) taken as
/// sin(2θe + t) past π/2, where θo + d nears π and its rounding would dominate) and g =
/// [`back_facing_excess`]`(s, a)`.
struct Integrand<'a> {
    nodes: &'a Nodes,
    values: &'a mut [f64],
}

impl Block for Integrand<'_> {
    #[inline(always)]
    fn run(&mut self) {
        let n = self.nodes;
        let (theta_o, edge, cos_o) = (n.theta_o, n.edge, n.cos_o);
        let columns = n.t.iter().zip(&n.dist).zip(&n.theta_m).zip(&n.factor);
        for (value, (((&t, &dist), &theta_m), &factor)) in self.values.iter_mut().zip(columns) {
            let a = cos_o * elementary::sin_cos(dist).0;
            let sum_angle = if theta_o + dist <= FRAC_PI_2 {
                theta_o + dist
            } else {
                2.0 * edge + t
            };
            let s = (elementary::sin_cos(t).0 * elementary::sin_cos(sum_angle).0).sqrt();
            let sin_m = elementary::sin_cos(theta_m).0;
            *value *= back_facing_excess(s, a) * sin_m * factor;
        }
    }
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
/// back-facing projection, over 2 (module header). The series r³ Σₖ (−r²)ᵏ/(2k + 3) for r < ½
/// ([`SERIES`] by Horner's rule, from the smallest) avoids the cancellation of r − atan r;
/// a = 0 (θm = π/2) gives s. Branch-free: both forms are computed and one selected.
#[inline(always)]
fn back_facing_excess(s: f64, a: f64) -> f64 {
    let r = s / a;
    let r2 = r * r;
    let mut sum = 0.0;
    for &c in SERIES.iter().rev() {
        sum = c - r2 * sum;
    }
    let series = a * (r * r2 * sum);
    let direct = s - a * elementary::atan(r);
    if s < SERIES_MAX_R * a {
        series
    } else if a > 0.0 {
        direct
    } else {
        s
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
