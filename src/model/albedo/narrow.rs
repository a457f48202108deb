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
//! scale in c, its spread s = w (sin θo + w/2), so each cell's share of R is a smooth weight against
//! a residual of mean zero:
//! - near the lobe, |c − μo| ≤ [`NEAR_SPREADS`] s (at least [`NEAR_CELLS`] cells), each cell, split
//!   into panels no wider than s/2, takes the 8-point Gauss–Legendre rule with ρ at every node;
//! - farther out, to [`FAR_SPREADS`] s (at least [`FAR_CELLS`] cells), ρ is a parabola across a
//!   cell to far below the tolerance, through its values at the cell's ends and middle, and a
//!   cell's share is ρ' ∫ r (c − c_mid) dc + (ρ''/2) ∫ r (c − c_mid)² dc, r's moments by the same
//!   rule (exact for a cubic). Both terms count: r is mostly even about the middle of its cell
//!   (L − S is the interpolation error of a parabola's arc), so its second moment outweighs the
//!   first, and a linear ρ left 1e-10 of E over the cells next to the near window at μo = 0;
//! - beyond, where ρ'' has fallen with the lobe's tail, R is left out.
//!
//! ρ(c) integrates ψ over [0, ψmax] (the half circle, doubled by symmetry), ψmax where the
//! reflection meets the horizon (cos θh = μo/(2c)), on panels doubling from a quarter of the lobe's
//! width in ψ, w/(√(1 − c²) sin θo), each with the 8-point rule: the lobe peaks at ψ = 0, where the
//! circle passes nearest the normal. θh is formed as atan2 of h's horizontal and vertical parts,
//! exact next to the normal.
//!
//! R is of order h² L'' ~ 1e-7 of E, so its windows and rules need only ~1e-4 of relative accuracy.
//! Measured (GGX, b₁ … b₃ shifted by 1, α = 0.0015 … 0.0166, μo = 0.15 … 0.97): within 3e-11 of the
//! residual integrated by nested adaptive Gauss–Kronrod at 1e-11 and of the interpolant itself at
//! 1e-11, and at μo = 0 (α = 0.002) within 2e-12 of the residual's; doubling either window moves
//! E by less than 1e-12.

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
        let spread = self.width * (sin_o + 0.5 * self.width);
        let rho = |c: f64| density_in_cos(&oblique, sin_o, c);
        let residual = |c: f64| weight.linear_at_cos(c) - weight.at_cos(c);
        let near = (NEAR_SPREADS * spread).max(NEAR_CELLS * cell);
        let far = (FAR_SPREADS * spread).max(FAR_CELLS * cell);
        let nodes = weight.nodes();
        let cells = nodes.len() - 1;
        let index = |c: f64| ((c / cell).floor().max(0.0) as usize).min(cells);
        let panels_per_cell = (2.0 * cell / spread).ceil().clamp(1.0, 64.0) as usize;
        let mut sum = 0.0;
        let mut rho_at_start = None;
        for j in index(mu_o - far)..index(mu_o + far).min(cells) {
            let (a, b) = (nodes[j], nodes[j + 1]);
            let mid = 0.5 * (a + b);
            if (mid - mu_o).abs() <= near + cell {
                let width = (b - a) / panels_per_cell as f64;
                for p in 0..panels_per_cell {
                    let lo = a + p as f64 * width;
                    sum += rule().integrate(|c| residual(c) * rho(c), lo, lo + width);
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
    let psi_max = if b == 0.0 {
        PI
    } else {
        let q = (0.5 * mu_o / c - a) / b;
        if q >= 1.0 {
            return 0.0;
        }
        q.max(-1.0).acos()
    };
    let start = if b == 0.0 {
        psi_max
    } else {
        (0.25 * surface.width / b).min(psi_max)
    };
    let mut integral = rule().integrate(at, 0.0, start);
    let mut lo = start;
    while lo < psi_max {
        let hi = (2.0 * lo).min(psi_max);
        integral += rule().integrate(at, lo, hi);
        lo = hi;
    }
    2.0 * c * integral
}
