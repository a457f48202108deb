//! The albedo of a Fresnel weight tabulated on the basis grid for a lobe that spans only a few of
//! the grid's cells in cos θd (docs/maths.md "Directional albedo", its tabulated Fresnel curves).
//!
//! The interpolant L is linear between the nodes c_j; its smooth surrogate S̃ ([`Smoothed`]) has
//! L's integral over every cell, so the residual r = L − S̃, a cubic on each cell, has mean zero on
//! each. E(L) = E(S̃) + R: the first by the fixed rules, the second
//!
//! R = ∫ r(c) ρ(c) dc, ρ(c) = c ∫₀^{2π} D(θh) (G2/μo)(θo, θi) dψ,
//!
//! in coordinates about the view, h = c ωo + √(1 − c²)(cos ψ t₁ + sin ψ t₂), t₁ in the plane of
//! ωo and the normal, where dωh = dc dψ exactly, cos θh = c μo + √(1 − c²) sin θo cos ψ and
//! cos θi = 2c cos θh − μo (at μo = 0, G2/μo is its limit g/C as in [`Microfacet::albedo`], C the
//! visible projected area). ρ, the albedo's density in c = cos θd, is smooth on the lobe's own
//! scale in c, its spread s = w (sin θo + w/2) (`Microfacet::cos_spread`), so each cell's share of R is a smooth weight against
//! a residual of mean zero:
//! - near the lobe, |c − μo| ≤ [`NEAR_SPREADS`] s (at least [`NEAR_CELLS`] cells), each cell is
//!   split into panels no wider than half the larger of s and their distance from μo ([`graded`]),
//!   each with the 8-point Gauss–Legendre rule and ρ at every node. ρ vanishes below the least c
//!   whose circle reflects above the horizon anywhere ([`visible_edge`]) and rises like a power of
//!   (c − edge) above it: a panel the edge cuts starts there, graded on G2's layer, in u with
//!   c = edge + (hi − edge) u²;
//! - farther out, to [`FAR_SPREADS`] s (at least [`FAR_CELLS`] cells), ρ is a parabola across a
//!   cell to far below the tolerance, through its values at the cell's ends and middle, and a
//!   cell's share is ρ' ∫ r (c − c_mid) dc + (ρ''/2) ∫ r (c − c_mid)² dc, r's moments by the same
//!   rule (exact for a cubic). Both terms count: r is mostly even about the middle of its cell
//!   (L − S is the interpolation error of a parabola's arc), so its second moment outweighs the
//!   first, and a linear ρ left 1e-10 of E over the cells next to the near window at μo = 0;
//! - beyond, where ρ'' has fallen with the lobe's tail, R is left out.
//!
//! ρ(c) integrates ψ over [0, ψmax] (the half circle, doubled by symmetry), ψmax where the
//! reflection meets the horizon (cos θh = μo/(2c)), on panels doubling ([`doubling`]) from a
//! quarter of the lobe's width in ψ, w/√b with b = √(1 − c²) sin θo (θh² ≈ θh(0)² + b ψ²), each
//! with the 8-point rule (grading towards ψmax as well, on G2's layer at the horizon, moved no
//! value by 1e-12 and doubled the cost). θh is formed as atan2 of h's horizontal and vertical parts, exact next to the
//! normal.
//!
//! R is of order h² L'' ~ 1e-7 of E. Measured (GGX, b₁ … b₃ shifted by 1, α = 1e-4 … 0.0166,
//! μo = 0 … 0.9999, both G2 models): within 8e-12 of the interpolant integrated directly by nested
//! adaptive Gauss–Kronrod at 1e-12, except at grazing views with the steep b₃ (μo ≤ 0.01, α ≤ 0.001),
//! where that direct route, integrating L's kinks in coordinates that do not follow them, lands
//! 3e-10 … 1e-9 above; there ∫ L ρ dc split at every node converges towards this value as its rule
//! grows (24, 40 points: 3.7e-10, 0.8e-10 below it), and ρ against a smooth steep F, e^{−c/0.003},
//! matches the fixed rules to 3e-13. Doubling either window, the points of either rule, or dividing
//! every panel in c into 64 moves a value by less than 1e-11.

use super::{Density, Lambda, Microfacet, Oblique, Smoothed};
use crate::model::math::gauss_legendre::Rule;
use crate::model::math::quad::{QuadError, integrate};
use std::f64::consts::PI;
use std::sync::OnceLock;

/// Half-width of the near window, in spreads of the lobe in c.
const NEAR_SPREADS: f64 = 4.0;
/// Least half-width of the near window, in cells.
const NEAR_CELLS: f64 = 2.0;
/// Half-width of the far window, in spreads.
const FAR_SPREADS: f64 = 64.0;
/// Least half-width of the far window, in cells.
const FAR_CELLS: f64 = 8.0;
/// Points of the rule on each panel, in c and in ψ.
const POINTS: usize = 8;

/// The [`POINTS`]-point rule on [0, 1], built once.
fn rule() -> &'static Rule {
    static RULE: OnceLock<Rule> = OnceLock::new();
    RULE.get_or_init(|| Rule::new(POINTS))
}

impl<D, L> Microfacet<D, L>
where
    D: Density,
    L: Lambda,
{
    /// R = E(L) − E(S̃) of `weight` at μo ∈ [0, 1) (module docs); errs only where C, the unit at
    /// μo = 0, fails to converge.
    pub(super) fn residual_albedo(&self, mu_o: f64, weight: &Smoothed) -> Result<f64, QuadError> {
        let oblique = Oblique::new(self, mu_o);
        let unit = if mu_o > 0.0 {
            1.0
        } else {
            integrate(|s| oblique.visible(s), 0.0, 1.0, self.tolerance)?
        };
        let sin_o = ((1.0 - mu_o) * (1.0 + mu_o)).sqrt();
        let cell = weight.cell();
        let spread = self.cos_spread(mu_o);
        let rho = |c: f64| density_in_cos(&oblique, sin_o, c);
        let residual = |c: f64| weight.linear_at_cos(c) - weight.at_cos(c);
        let near = (NEAR_SPREADS * spread).max(NEAR_CELLS * cell);
        let far = (FAR_SPREADS * spread).max(FAR_CELLS * cell);
        let nodes = weight.nodes();
        let cells = nodes.len() - 1;
        let index = |c: f64| ((c / cell).floor().max(0.0) as usize).min(cells);
        let edge = visible_edge(mu_o, sin_o);
        // G2's layer at the horizon in c: cos θi ≈ 2 (c − edge) there.
        let layer = 0.5 * oblique.layer();
        // ∫ r ρ over [lo, hi], by the rule in u where c = edge + (hi − edge) u² on a panel that
        // the edge cuts (ρ = 0 below it, ~(c − edge)^{3/2} above).
        let panel = |lo: f64, hi: f64| {
            if hi <= edge {
                0.0
            } else if lo < edge {
                // Graded from the edge on that layer.
                let mut sum = 0.0;
                doubling(edge, hi, 0.25 * layer, &mut |x0, x1| {
                    let length = x1 - x0;
                    sum += rule().integrate(
                        |u| {
                            let c = x0 + length * u * u;
                            residual(c) * rho(c) * 2.0 * length * u
                        },
                        0.0,
                        1.0,
                    );
                });
                sum
            } else {
                rule().integrate(|c| residual(c) * rho(c), lo, hi)
            }
        };
        let mut sum = 0.0;
        let mut rho_at_start = None;
        for j in index(mu_o - far)..index(mu_o + far).min(cells) {
            let (a, b) = (nodes[j], nodes[j + 1]);
            let mid = 0.5 * (a + b);
            if (mid - mu_o).abs() <= near + cell || (a..b).contains(&edge) {
                let mut add = |lo: f64, hi: f64| sum += panel(lo, hi);
                if a < mu_o && mu_o < b {
                    graded(mu_o, a, mu_o, spread, &mut add);
                    graded(mu_o, b, mu_o, spread, &mut add);
                } else if mu_o <= a {
                    graded(a, b, mu_o, spread, &mut add);
                } else {
                    graded(b, a, mu_o, spread, &mut add);
                }
                rho_at_start = None;
            } else {
                let rho_a = rho_at_start.unwrap_or_else(|| rho(a));
                let (rho_mid, rho_b) = (rho(mid), rho(b));
                let h = b - a;
                let slope = (rho_b - rho_a) / h;
                let curvature = 4.0 * (rho_a - 2.0 * rho_mid + rho_b) / (h * h);
                let first = rule().integrate(|c| residual(c) * (c - mid), a, b);
                let second = rule().integrate(|c| residual(c) * (c - mid) * (c - mid), a, b);
                sum += slope * first + 0.5 * curvature * second;
                rho_at_start = Some(rho_b);
            }
        }
        Ok(sum / unit)
    }
}

/// Calls `each` on panels from `from` to `to` (either way), each at most half as wide as the
/// larger of `scale` and its start's distance from `centre`: graded geometrically away from a
/// feature of width `scale` at `centre`.
fn graded(from: f64, to: f64, centre: f64, scale: f64, each: &mut impl FnMut(f64, f64)) {
    let direction = (to - from).signum();
    let mut x = from;
    while (to - x) * direction > 0.0 {
        let step = 0.5 * scale.max((x - centre).abs());
        let next = if (to - x).abs() <= 1.5 * step {
            to
        } else {
            x + direction * step
        };
        each(x.min(next), x.max(next));
        x = next;
    }
}

/// Calls `each` on the panels from `from` towards `to` whose ends lie at `from` ± `first` · 2^k (the
/// last one ending at `to`): geometric panels away from a feature of width ~4 `first` at `from`.
fn doubling(from: f64, to: f64, first: f64, each: &mut impl FnMut(f64, f64)) {
    let direction = (to - from).signum();
    let span = (to - from).abs();
    let first = if first > 0.0 && first.is_finite() {
        first
    } else {
        span
    };
    let mut offset = 0.0;
    let mut step = first;
    while offset < span {
        let next = (offset + step).min(span);
        let (x0, x1) = (from + direction * offset, from + direction * next);
        each(x0.min(x1), x0.max(x1));
        offset = next;
        step = if offset == first { first } else { offset };
    }
}

/// The least c = cos θd whose circle about the view reflects above the horizon anywhere: where the
/// half-vector nearest the normal (ψ = 0, cos θh = c μo + √(1 − c²) sin θo) reflects to it,
/// 2c cos θh = μo; by bisection on [0, μo], where 2c cos θh − μo rises from −μo to μo (0 at μo = 0).
fn visible_edge(mu_o: f64, sin_o: f64) -> f64 {
    let rises = |c: f64| 2.0 * c * (c * mu_o + ((1.0 - c) * (1.0 + c)).sqrt() * sin_o) - mu_o;
    let (mut lo, mut hi) = (0.0, mu_o);
    for _ in 0..64 {
        let mid = 0.5 * (lo + hi);
        if rises(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

/// ρ(c) = c · 2 ∫₀^{ψmax} D(θh) (G2/μo)(θo, θi) dψ, the albedo's density in c = cos θd at the view
/// of `oblique` (sin θo = `sin_o`) without the Fresnel factor, in units of the unit C at μo = 0.
fn density_in_cos<D: Density, L: Lambda>(oblique: &Oblique<'_, D, L>, sin_o: f64, c: f64) -> f64 {
    if c <= 0.0 {
        return 0.0;
    }
    let surface = oblique.surface;
    let mu_o = oblique.view.mu;
    let s = ((1.0 - c) * (1.0 + c)).sqrt();
    let (a, b) = (c * mu_o, s * sin_o);
    let at = |psi: f64| {
        let (sin_psi, cos_psi) = psi.sin_cos();
        let cos_h = a + b * cos_psi;
        let cos_i = 2.0 * c * cos_h - mu_o;
        if cos_h <= 0.0 || cos_i <= 0.0 {
            return 0.0;
        }
        let horizontal = (c * sin_o - s * mu_o * cos_psi).hypot(s * sin_psi);
        let theta_h = horizontal.atan2(cos_h);
        let lambda_i = surface.lambda.at_cos(cos_i.min(1.0));
        surface.ndf.at(theta_h) * oblique.weight(lambda_i)
    };
    if b == 0.0 {
        // c = 1 (h is the view itself) or a view along the normal: θh is the same all round.
        return 2.0 * c * rule().integrate(at, 0.0, PI);
    }
    let q = (0.5 * mu_o / c - a) / b;
    if q >= 1.0 {
        return 0.0;
    }
    let psi_max = q.max(-1.0).acos();
    // Graded from ψ = 0 on the lobe's width in ψ.
    let lobe = 0.25 * surface.width / b.sqrt();
    let mut integral = 0.0;
    doubling(0.0, psi_max, lobe, &mut |lo, hi| {
        integral += rule().integrate(at, lo, hi)
    });
    2.0 * c * integral
}
