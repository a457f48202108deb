//! Directional albedo of the single-scattering microfacet BRDF f = F D G2 / (4 cos θo cos θi), its
//! cosine-weighted average, the energy-compensation factors built on them and the tables renderers
//! precompute (docs/maths.md "Masking–shadowing and albedo").
//!
//! # The integral
//!
//! E(μo) = ∫ f cos θi dωi = (1/μo) ∫ D(h) G2(θo, θi) F(θd) ⟨ωo, h⟩ dωh over the half-vectors h whose
//! reflection ωi lies above the horizon, μo = cos θo, θd the angle between ωo and h, and
//! G2 = [`G2Model::g2`]`(Λ(θo), Λ(θi))`. The NDF enters only through two closures, D(θm) and Smith's
//! Λ(θ), held by a [`Microfacet`]; the Fresnel factor is an optional closure of θd ([`Fresnel`]).
//!
//! # Quadrature
//!
//! Polar coordinates of h about the normal (θh, φ), with the radial variable stretched by the
//! lobe's width w: tan θh = w tan β, β ∈ [0, π/2). For Trowbridge–Reitz with w = α the measure
//! D cos θh dωh becomes sin β cos β dβ dφ / π — the lobe and its whole 1/tan³ tail are one smooth
//! bump for every α — and any other lobe whose slopes scale like w is smooth in β too. Quadrature in
//! VNDF sample space would lump the heavy tail (where 1 − E lives) into a few cells instead.
//!
//! The fast path is a tensor product of fixed Gauss–Legendre rules ([`escalate`]): 16 × 16, then
//! 24 × 24, 32 × 32, 40 × 40 and 48 × 48 points per outer panel (outer × inner), from 8 × 8 at
//! tolerances of 1e-10 and looser (the average's E), each panel taking
//! the first level within 30 × the tolerance (3e-11) of the one before on its own, so a slow panel
//! does not raise the others' level; where a panel's levels never agree, or a value is not finite,
//! the nested adaptive Gauss–Kronrod ([`crate::model::math::quad::integrate`]) to the tolerance. The
//! rules see smooth integrands because every feature sits at a panel end with a known scale, to
//! which a sinh map x = a + δ sinh(t asinh((b − a)/δ)) grades the nodes ([`Graded`]):
//! - next to the horizon G2/μo turns over on the scale λ = min(w, μo)/2 in cos θi (height-correlated;
//!   w/2 separable): Λ(θi) ~ C/cos θi against Λ(θo) ≈ C/μo; the inner rule runs in u = φ_end − φ,
//!   the azimuth from the horizon end, graded over the u in which cos θi rises by 4λ, and the outer
//!   panels next to β_cut, β_end (and the end of E(1)) are graded on the corresponding scale in β;
//! - the outer integral is split at θh = ε/4 below the horizon's layer (for a lobe narrow beside
//!   the horizon, tan(ε/4) > 2w), at the two halves of the
//!   cut part, and, for a lobe with a light tail (D at slope 5w below 1e-3 of D at slope 2w:
//!   Beckmann, high Phong exponents), at slopes 2w and 5w, where a Gaussian dies off; and at
//!   2θh = θo, the slice whose reflection reaches the normal, next to which Λ(cos θi) is not
//!   analytic (Beckmann's e^{−cot²θ/α²} at θi = 0, Trowbridge–Reitz's root with its branch point at
//!   cos θi = α/√(α² − 1) just beyond the normal for α > 1, a table's √(1 − cos²θi)): the inner
//!   rule's far end, stretched by its grading towards the horizon, would otherwise lie beside it.
//!
//! Each level of a panel runs in stages: the geometry of every outer node's slice (θh, φ_end, the
//! inner grading), then of every inner node of a slice (cos θi, ⟨ωo, h⟩) and its Λ, each stage
//! over the whole rule in vector lanes ([`elementary::widest`], the crate's branch-free exp,
//! sin/cos, atan and asinh, Λ from the surface's table); D for every outer node at once
//! ([`Density::at_many`]); the Fresnel factor over the whole inner rule too where it is a smooth
//! curve's Chebyshev table or a tabulated weight's cells, else node by node ([`NodeFresnel`]).
//!
//! The inner integrand takes cos θi from sin(u/2) alone (cos θi = cos θi(φ_end) + (spread/2)
//! (sin φ_end sin u − cos φ_end (1 − cos u))), free of cancellation next to the horizon.
//!
//! The horizon is handled exactly rather than by a discontinuous integrand: writing ε = arcsin μo
//! (the view's elevation), cos θi = cos(2θh + θo) + 2 cos ε sin 2θh cos²(φ/2), so
//! - for 2θh ≤ ε every azimuth reflects above the horizon (inner φ over [0, π]);
//! - for ε < 2θh < π − ε the azimuths with cos²(φ/2) > q = sin(2θh − ε)/(2 cos ε sin 2θh) do, φ over
//!   [0, φmax], φmax = 2 arccos √q, with cos θi = 2 cos ε sin 2θh sin((φmax − φ)/2) sin((φmax + φ)/2)
//!   free of cancellation; the inner integral behaves like (θh − ε/2)^{3/2} at the first end and
//!   (π/2 − ε/2 − θh)^{3/2} at the other, so β runs through the smoothstep s²(3 − 2s) there, which
//!   makes both ends polynomial;
//! - for 2θh ≥ π − ε no azimuth does.
//!
//! G2 vanishes linearly in cos θi at the horizon for every Λ that grows like 1/cos θi, so the
//! integrand is continuous everywhere. At μo = 1 the azimuth drops out and E(1) =
//! 2π ∫₀^{π/4} D(θh) G2(0, 2θh) F(θh) cos θh sin θh dθh is one integral in β. Λ(θo) is
//! evaluated once per value, Λ(θi) once per inner node.
//!
//! # Tabulated Fresnel weights
//!
//! The Belcour–Bati–Barla basis functions and reconstructions are linear in cos θd between 1000
//! nodes; their kinks would stall any rule. They enter through a smooth surrogate with the same
//! integral over every grid cell ([`Smoothed`], module `tabulated`), exact at μo = 1 where the
//! integral is split at the nodes; for lobes narrower than [`SMOOTHED_CELLS`] cells the albedo of
//! the interpolant's residual against the surrogate is added, cell by cell in coordinates about the
//! view where cos θd is one of the variables (module `narrow`, [`Microfacet::albedo_tabulated`]).
//!
//! # The width
//!
//! An arbitrary NDF has no width parameter, so [`Microfacet::new`] takes the lobe's median slope:
//! the tan θ below which half of the projected area lies, 2π ∫₀^θ D sin θ cos θ dθ = ½
//! ([`median_slope`]; α for Trowbridge–Reitz, α √(ln 2) for Beckmann, 1 for the uniform lobe). It
//! exists for every normalized NDF — narrow, heavy-tailed, super-rough (mass near grazing) or flat —
//! and a factor of two off only costs a few more subdivisions. [`Microfacet::with_width`] takes an
//! explicit one.
//!
//! # Range and limits
//!
//! μo ∈ [0, 1]. μo = 0 is defined as the limit μo → 0⁺: with Λ(θo) → ∞ the factor G2/μo tends to
//! g(θi)/(μo Λ(θo)) with g = 1 (height-correlated) or G1(θi) (separable), and μo Λ(θo) → C =
//! ∫ D ⟨ωo, h⟩⁺ dωh for a horizontal ωo, so E(0) = ∫ D ⟨ωo, h⟩⁺ g F dωh / C (exactly 1 for
//! height-correlated G2 without Fresnel: at grazing incidence every visible facet reflects upwards).
//! Positive μo down to 1e-6 are tested; E(μo) approaches E(0) once μo is well below the lobe width.
//!
//! # Tables
//!
//! [`albedo_table`] follows Cycles' grid convention (μ = i/(n_μ − 1), r = j/(n_r − 1), α = map(r),
//! rows μ): its μ = 0 row is the limit above, and its r = 0 column the family's lobe at α = 0
//! ([`lobe`]): for a width parameter the mirror limit α → 0⁺, E = F(θo) (Cycles instead clamps μ
//! and r to 1e-4). [`average_albedo_table`] gives E_avg(r) (fixed rules in μ, [`average_albedo`]),
//! [`split_sum_tables`] the Belcour–Bati–Barla tables E_k (F = b_k, k = 0…3), [`dfg_tables`] the
//! split-sum pair of Schlick's Fresnel engines store (docs/maths.md "Split-sum tables of engines");
//! the `_at` variants take any axes (an engine's grid of texel centres).

mod narrow;
mod tabulated;

pub use tabulated::Smoothed;

use std::borrow::Borrow;
use std::cell::Cell;
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};
use std::fmt;
use std::sync::OnceLock;
use std::sync::atomic::{AtomicUsize, Ordering};

use rayon::prelude::*;

use crate::model::domain::DomainError;
use crate::model::fresnel::basis::basis;
use crate::model::masking::{G2Model, LambdaTable, g1};
use crate::model::math::chebyshev::Piecewise;
use crate::model::math::elementary::{self, Block};
use crate::model::math::gauss_legendre::Rule;
use crate::model::math::quad::{QuadError, integrate};
use crate::model::math::tolerance::ALBEDO_QUAD_REL_TOL;
use crate::model::names::named;
pub use crate::model::ndf::Density;
use crate::model::ndf::{Distribution, Family, Ndf, Phong, ZeroLimit};

/// The Fresnel factor inside an albedo; `None` is F ≡ 1.
pub type Fresnel<'a> = Option<FresnelFactor<'a>>;

/// A Fresnel factor F(θd) inside an albedo, θd ∈ [0, π/2] the angle between the view ωo and the
/// half-vector h: the curve, and its table in c = cos θd ([`FresnelTable`]), which the fixed rules
/// evaluate at their inner nodes instead of the curve. F must be ≥ 0 wherever the integrals are to
/// converge to a relative accuracy (signed weights, such as the basis functions b₂ and b₃, go
/// through [`split_sum_tables`], which shifts them).
#[derive(Clone, Copy)]
pub struct FresnelFactor<'a> {
    curve: &'a (dyn Fn(f64) -> f64 + Sync),
    table: Option<&'a FresnelTable>,
}

impl<'a> FresnelFactor<'a> {
    /// The factor `curve` with `table`, which must be the curve's own — [`FresnelTable::of`]`(curve)`,
    /// or [`FresnelTable::cells`] of its surrogate for a weight tabulated on the basis grid
    /// (`model::curve::quantity::fresnel_table` chooses) — built once and shared by every albedo
    /// with this factor (`None` where it does not converge: the curve is then evaluated node by
    /// node).
    pub fn new(
        curve: &'a (dyn Fn(f64) -> f64 + Sync),
        table: Option<&'a FresnelTable>,
    ) -> FresnelFactor<'a> {
        FresnelFactor { curve, table }
    }

    /// F(θd) by the curve itself.
    pub fn at(&self, theta_d: f64) -> f64 {
        (self.curve)(theta_d)
    }

    /// F_avg = 2 ∫₀¹ F μ dμ ([`average_fresnel`]); for a weight tabulated on the basis grid, its
    /// interpolant integrated exactly cell by cell ([`Smoothed::average`]).
    pub fn average(&self) -> Result<f64, QuadError> {
        match self.table {
            Some(FresnelTable(TableKind::Cells(cells))) => Ok(cells.average()),
            _ => average_fresnel(self.curve),
        }
    }
}

/// A Fresnel factor tabulated in c = cos θd on [0, 1], for [`FresnelFactor`]: a smooth curve's
/// [`Piecewise`] Chebyshev interpolant of F(arccos c) within [`FRESNEL_TABLE_TOL`] (a few tens of
/// values of F, against one per inner node of every albedo), or the smooth surrogate of a weight
/// tabulated on the basis grid ([`Smoothed`]), which the albedo then takes as
/// [`Microfacet::albedo_tabulated`] does.
#[derive(Debug, Clone)]
pub struct FresnelTable(TableKind);

/// What a [`FresnelTable`] holds.
#[derive(Debug, Clone)]
enum TableKind {
    Chebyshev(Piecewise),
    Cells(Smoothed),
}

impl FresnelTable {
    /// The table of the smooth `curve`, F(θd); `None` where F(arccos c) is not smooth enough for
    /// the interpolant to converge, or not finite.
    pub fn of(curve: &dyn Fn(f64) -> f64) -> Option<FresnelTable> {
        Piecewise::build(|c| curve(theta_d(c)), 0.0, 1.0, |_, _| FRESNEL_TABLE_TOL)
            .map(|table| FresnelTable(TableKind::Chebyshev(table)))
    }

    /// The table of a weight tabulated on the basis grid: its smooth surrogate ([`tabulated`]).
    pub fn cells(surrogate: Smoothed) -> FresnelTable {
        FresnelTable(TableKind::Cells(surrogate))
    }
}

/// The smooth surrogate ([`Smoothed`]) of a Fresnel curve tabulated on the basis grid and
/// interpolated linearly in cos θ (a Belcour–Bati–Barla reconstruction or basis function), for
/// [`Microfacet::albedo_tabulated`], as its combination of the basis functions
/// ([`Smoothed::of_basis`]: the reconstruction's coefficients, or the one basis function); `None`
/// for every other curve, which is smooth.
pub fn tabulated(fresnel: &crate::model::fresnel::Fresnel) -> Option<Smoothed> {
    use crate::model::fresnel::Fresnel::{Basis, Belcour};
    match fresnel {
        Belcour(_, c) => Some(Smoothed::of_basis([c.c0, c.c1, c.c2, c.c3])),
        Basis(k) => Some(Smoothed::of_basis(std::array::from_fn(|j| {
            f64::from(j == *k)
        }))),
        _ => None,
    }
}

/// The fewest grid cells the distribution of cos θd must span for the smooth surrogate of a
/// tabulated weight to integrate like the interpolant (measured: within 6e-12 of the interpolant's
/// direct integral for GGX α = 0.01 … 0.2 at μo = 0.5, from 9 cells on); a narrower lobe adds the
/// residual's albedo ([`Microfacet::albedo_tabulated`]).
pub const SMOOTHED_CELLS: f64 = 8.0;

/// Smith's Λ of a surface as the albedo integrals take it, at μ = cos θ ∈ [0, 1] (0 at μ = 1,
/// growing like 1/μ towards grazing): any `Fn(f64) -> f64` of μ, or an NDF's own with its
/// [`SurfaceParts`] ([`surface_with`], [`surface_of`]), whose table also runs a block in vector lanes.
pub trait Lambda {
    /// Λ at μ = cos θ.
    fn at_cos(&self, mu: f64) -> f64;

    /// `out[k]` = Λ(`mus[k]`), the values of [`Lambda::at_cos`] (lengths equal, at most 64),
    /// called inside [`elementary::widest`]; one at a time unless the implementation has a block
    /// path.
    #[inline(always)]
    fn at_cos_many(&self, mus: &[f64], out: &mut [f64]) {
        for (out, &mu) in out.iter_mut().zip(mus) {
            *out = self.at_cos(mu);
        }
    }
}

impl<F: Fn(f64) -> f64> Lambda for F {
    #[inline(always)]
    fn at_cos(&self, mu: f64) -> f64 {
        self(mu)
    }
}

/// An isotropic microfacet surface as the albedo integrals see it: D(θm), normalized over projected
/// area; Smith's Λ as a function of μ = cos θ (Λ = 0 at μ = 1, growing like 1/μ towards grazing:
/// the integrals have the cosine of the light's angle, not the angle); the G2 model; and the lobe
/// width w that scales the radial quadrature variable (module docs).
#[derive(Debug, Clone)]
pub struct Microfacet<D, L> {
    ndf: D,
    lambda: L,
    g2: G2Model,
    width: f64,
    /// Whether the lobe dies off fast beyond a few widths (a Gaussian's tail), where the outer
    /// integral is split at [`LOBE_SLOPES`].
    light_tail: bool,
    tolerance: f64,
}

impl<D, L> Microfacet<D, L>
where
    D: Density,
    L: Lambda,
{
    /// The surface with D(θ) = `ndf`(θ), Λ = `lambda`(cos θ) and the lobe width w =
    /// [`median_slope`]`(ndf)`.
    pub fn new(ndf: D, lambda: L, g2: G2Model) -> Self {
        let width = median_slope(|theta| ndf.at(theta));
        Self::with_width(ndf, lambda, g2, width)
    }

    /// The surface with an explicit lobe width w > 0 (a slope, tan θ; finite). Any positive value
    /// gives the same albedo; one within a factor of a few of the median slope gives it fastest.
    pub fn with_width(ndf: D, lambda: L, g2: G2Model, width: f64) -> Self {
        assert!(
            width > 0.0 && width.is_finite(),
            "the lobe width is a positive slope, got {width}"
        );
        let [core, tail] = LOBE_SLOPES.map(|k| ndf.at((k * width).atan()));
        Microfacet {
            light_tail: tail <= LIGHT_TAIL * core,
            ndf,
            lambda,
            g2,
            width,
            tolerance: ALBEDO_QUAD_REL_TOL,
        }
    }

    /// The same surface with each nested integral held to `tolerance` (absolute, in units of E)
    /// instead of [`ALBEDO_QUAD_REL_TOL`]: looser for a value only shown rounded.
    pub fn with_tolerance(self, tolerance: f64) -> Self {
        assert!(
            tolerance > 0.0 && tolerance < 1.0,
            "a tolerance in (0, 1), got {tolerance}"
        );
        Microfacet { tolerance, ..self }
    }

    /// The lobe width w in use.
    pub fn width(&self) -> f64 {
        self.width
    }

    /// The G2 model in use.
    pub fn g2(&self) -> G2Model {
        self.g2
    }

    /// E(μo) = (1/μo) ∫ D G2 F(θd) ⟨ωo, h⟩ dωh over the half-vectors reflecting above the horizon,
    /// for μo ∈ [0, 1]; μo = 0 is the limit μo → 0⁺ (module docs). The fixed rules' value is taken
    /// within 30 × the surface's tolerance ([`ALBEDO_QUAD_REL_TOL`] unless set) of the level
    /// before, else each nested adaptive integral is held to that tolerance in units of E; smooth,
    /// non-negative F lands within 1e-10 of the exact value (tests/numerics/albedo.rs).
    /// Errs if an integrand is not finite or a nested integral fails to converge.
    pub fn albedo(&self, mu_o: f64, fresnel: Fresnel) -> Result<f64, QuadError> {
        self.albedo_within(mu_o, fresnel, self.tolerance)
    }

    /// E(μo) with a Fresnel weight tabulated on the basis grid ([`Smoothed`]). At μo = 1, where
    /// θd = θh, the interpolant itself with the integral split at its nodes θh = arccos c_j
    /// ([`Microfacet::normal_tabulated`]). Below, the smooth surrogate inside [`Microfacet::albedo`];
    /// where the distribution of cos θd spans fewer than [`SMOOTHED_CELLS`] grid cells (its width
    /// about w (sin θo + w/2)), whose few cells the surrogate's cell means do not average, plus the
    /// albedo of the interpolant's residual against it (module `narrow`). Within 1e-10 either way.
    pub fn albedo_tabulated(&self, mu_o: f64, weight: &Smoothed) -> Result<f64, QuadError> {
        self.albedo_tabulated_within(mu_o, weight, self.tolerance)
    }

    /// The width of the distribution of cos θd about μo, w (sin θo + w/2): how far the lobe's
    /// half-vectors move ⟨ωo, h⟩ (by ~w sin θo across the view's plane, ~w²/2 along it).
    fn cos_spread(&self, mu_o: f64) -> f64 {
        let sin_o = ((1.0 - mu_o) * (1.0 + mu_o)).sqrt();
        self.width * (sin_o + 0.5 * self.width)
    }

    /// [`Microfacet::albedo_tabulated`] with each nested integral held to `tolerance`.
    fn albedo_tabulated_within(
        &self,
        mu_o: f64,
        weight: &Smoothed,
        tolerance: f64,
    ) -> Result<f64, QuadError> {
        if mu_o == 1.0 {
            return self.normal_tabulated(weight, tolerance);
        }
        let smooth = self.albedo_by(mu_o, Weight::Tabulated(weight), tolerance)?;
        if self.cos_spread(mu_o) >= SMOOTHED_CELLS * weight.cell() {
            Ok(smooth)
        } else {
            Ok(smooth + self.residual_albedo(mu_o, weight)?)
        }
    }

    /// E(1) with the tabulated weight's interpolant L(cos θh): adaptive Gauss–Kronrod in θh on
    /// each piece between successive nodes θh = arccos c_j over [0, π/4], where L is linear in
    /// cos θh, each piece held to the surface's tolerance in its share of E.
    fn normal_tabulated(&self, weight: &Smoothed, tolerance: f64) -> Result<f64, QuadError> {
        let lambda_o = self.lambda.at_cos(1.0);
        let corner = FRAC_PI_4.cos();
        let mut edges = vec![0.0];
        edges.extend(
            weight
                .nodes()
                .iter()
                .rev()
                .filter(|&&c| c > corner && c < 1.0)
                .map(|&c| c.acos()),
        );
        edges.push(FRAC_PI_4);
        let share = 1.0 / (2.0 * PI * (edges.len() - 1) as f64);
        let integrand = |theta_h: f64| {
            let (sin, cos) = theta_h.sin_cos();
            let g2 = self
                .g2
                .g2(lambda_o, self.lambda.at_cos(cos_double(sin, cos)));
            Ok(self.ndf.at(theta_h) * g2 * weight.linear_at_cos(cos) * cos * sin)
        };
        let mut sum = 0.0;
        for pair in edges.windows(2) {
            sum += integrate_to(integrand, pair[0], pair[1], share, tolerance)?;
        }
        Ok(2.0 * PI * sum)
    }

    /// [`Microfacet::albedo`] with each nested integral held to `tolerance` instead of the
    /// surface's own: the fixed rules of [`LEVELS`], each panel's value taken where its levels
    /// agree to within [`FIXED_AGREEMENT`] × `tolerance` ([`Oblique::fixed`]), else the nested
    /// adaptive quadrature.
    fn albedo_within(&self, mu_o: f64, fresnel: Fresnel, tolerance: f64) -> Result<f64, QuadError> {
        match fresnel.and_then(|f| f.table) {
            Some(FresnelTable(TableKind::Cells(cells))) => {
                self.albedo_tabulated_within(mu_o, cells, tolerance)
            }
            _ => self.albedo_by(mu_o, Weight::Curve(fresnel), tolerance),
        }
    }

    /// [`Microfacet::albedo_within`] with the Fresnel factor `weight`: a curve, or a weight
    /// tabulated on the basis grid taken by its smooth surrogate ([`Smoothed::at_cos`]). The fixed
    /// rules take it at their inner nodes as [`NodeFresnel::new`] says; the adaptive quadrature and
    /// E(1) as a function of θd.
    fn albedo_by(&self, mu_o: f64, weight: Weight, tolerance: f64) -> Result<f64, QuadError> {
        assert!(
            (0.0..=1.0).contains(&mu_o),
            "μo must lie in [0, 1], got {mu_o}"
        );
        let surrogate;
        let fresnel: Fresnel = match weight {
            Weight::Curve(fresnel) => fresnel,
            Weight::Tabulated(table) => {
                surrogate = move |theta_d: f64| table.at(theta_d);
                Some(FresnelFactor::new(&surrogate, None))
            }
        };
        let fixed = if mu_o == 1.0 {
            escalate(tolerance, |rules| self.normal_fixed(fresnel, &rules.outer))
        } else {
            let oblique = Oblique::new(self, mu_o);
            match oblique.fixed(&NodeFresnel::new(weight), tolerance) {
                Some(value) => return Ok(value),
                None => return oblique.adaptive(fresnel, tolerance),
            }
        };
        match fixed {
            Some(value) => Ok(value),
            None => self.normal_albedo(fresnel, tolerance),
        }
    }

    /// a, then for a light tail the points β = atan(k) of [`LOBE_SLOPES`] strictly inside (a, b),
    /// and b: the edges of the outer panels over [a, b].
    fn lobe_edges(&self, a: f64, b: f64) -> Vec<f64> {
        let mut edges = vec![a];
        if self.light_tail {
            edges.extend(
                LOBE_SLOPES
                    .iter()
                    .map(|k| k.atan())
                    .filter(|&beta| beta > a && beta < b),
            );
        }
        edges.push(b);
        edges
    }

    /// At β ∈ [0, π/2]: θh = atan(w tan β), dθh/dβ = w / (cos²β + w² sin²β), and sin θh, cos θh =
    /// (w sin β, cos β)/√(cos²β + w² sin²β), by branch-free code ([`elementary`]).
    #[inline(always)]
    fn radial(&self, beta: f64) -> Radial {
        let w = self.width;
        let (s, c) = elementary::sin_cos(beta);
        let (ws, square) = (w * s, c * c + w * w * s * s);
        let norm = square.sqrt();
        Radial {
            theta_h: elementary::atan(ws / c),
            jacobian: w / square,
            sin_h: ws / norm,
            cos_h: c / norm,
        }
    }

    /// β at the end of the integral at normal incidence, where 2θh = π/2.
    fn normal_end(&self) -> f64 {
        (1.0 / self.width).atan()
    }

    /// The integrand of E(1) in β: D(θh) G2(Λ(0), Λ(2θh)) F(θh) cos θh sin θh dθh/dβ.
    fn normal_integrand(&self, beta: f64, lambda_o: f64, fresnel: Fresnel) -> f64 {
        let Radial {
            theta_h,
            jacobian,
            sin_h: sin,
            cos_h: cos,
        } = self.radial(beta);
        let g2 = self
            .g2
            .g2(lambda_o, self.lambda.at_cos(cos_double(sin, cos)));
        let f = fresnel.map_or(1.0, |f| f.at(theta_h));
        self.ndf.at(theta_h) * g2 * f * cos * sin * jacobian
    }

    /// E(1) = 2π ∫₀^{π/4} D(θh) G2(Λ(0), Λ(2θh)) F(θh) cos θh sin θh dθh by `rule` in β.
    fn normal_fixed(&self, fresnel: Fresnel, rule: &Rule) -> f64 {
        let lambda_o = self.lambda.at_cos(1.0);
        let end = self.normal_end();
        let layer = 0.5 * self.width.min(1.0);
        let delta = layer / (2.0 * self.radial(end).jacobian);
        2.0 * PI
            * composite(
                rule,
                &self.lobe_edges(0.0, end),
                None,
                Some(delta),
                |beta| self.normal_integrand(beta, lambda_o, fresnel),
            )
    }

    /// E(1) by adaptive Gauss–Kronrod in β, held to `tolerance`.
    fn normal_albedo(&self, fresnel: Fresnel, tolerance: f64) -> Result<f64, QuadError> {
        let lambda_o = self.lambda.at_cos(1.0);
        let integrand = |beta: f64| Ok(self.normal_integrand(beta, lambda_o, fresnel));
        Ok(2.0
            * PI
            * integrate_to(
                integrand,
                0.0,
                self.normal_end(),
                1.0 / (2.0 * PI),
                tolerance,
            )?)
    }
}

/// The oblique integral of one E(μo), μo ∈ [0, 1): the view, the outer variable's split and
/// Λ(θo), shared by the fixed rules ([`Oblique::fixed`]) and the adaptive fallback
/// ([`Oblique::adaptive`]).
struct Oblique<'s, D, L> {
    surface: &'s Microfacet<D, L>,
    view: View,
    /// β where 2θh = ε: every azimuth reflects upwards below it.
    beta_cut: f64,
    /// β_end − β_cut, β_end where 2θh = π − ε (no azimuth beyond); [β_cut, β_end] runs through
    /// the smoothstep s²(3 − 2s).
    span: f64,
    /// Λ(θo), or `None` at μo = 0, where G2/μo is replaced by its limit g(θi)/C.
    lambda_o: Option<f64>,
}

impl<'s, D, L> Oblique<'s, D, L>
where
    D: Density,
    L: Lambda,
{
    fn new(surface: &'s Microfacet<D, L>, mu_o: f64) -> Self {
        let view = View::new(mu_o);
        let w = surface.width;
        let beta_cut = ((0.5 * view.elevation).tan() / w).atan();
        let beta_end = if mu_o > 0.0 {
            ((0.5 * view.elevation).tan().recip() / w).atan()
        } else {
            FRAC_PI_2
        };
        let lambda_o = (mu_o > 0.0).then(|| surface.lambda.at_cos(mu_o));
        Oblique {
            surface,
            view,
            beta_cut,
            span: beta_end - beta_cut,
            lambda_o,
        }
    }

    /// (β, dβ/ds) at s ∈ [0, 1] of the cut part: β = β_cut + span · s²(3 − 2s).
    fn smoothstep(&self, s: f64) -> (f64, f64) {
        (
            self.beta_cut + self.span * s * s * (3.0 - 2.0 * s),
            self.span * 6.0 * s * (1.0 - s),
        )
    }

    /// The integrand in s of C = ∫ D ⟨ωo, h⟩⁺ dωh = 2 ∫₀^{π/2} D(θh) sin²θh dθh, the unit of E at
    /// μo = 0 (∫ cos φ over [0, π/2] is 1).
    fn visible(&self, s: f64) -> f64 {
        let (beta, beta_jacobian) = self.smoothstep(s);
        let radial = self.surface.radial(beta);
        let sin = radial.sin_h;
        2.0 * self.surface.ndf.at(radial.theta_h) * sin * sin * radial.jacobian * beta_jacobian
    }

    /// G2/μo at Λ(θi), or its limit g(θi) at μo = 0 (g = 1 height-correlated, G1 separable).
    #[inline(always)]
    fn weight(&self, lambda_i: f64) -> f64 {
        match self.lambda_o {
            Some(lambda_o) => self.surface.g2.g2(lambda_o, lambda_i) * self.view.inverse_mu,
            None => match self.surface.g2 {
                G2Model::HeightCorrelated => 1.0,
                G2Model::Separable => g1(lambda_i),
            },
        }
    }

    /// At β, with dβ/dx of the outer variable x: the outer factor 2 D(θh) sin θh dθh/dβ dβ/dx
    /// (the factor 2 counts φ ∈ [π, 2π) by symmetry) and the slice of azimuths.
    fn slice(&self, beta: f64, beta_jacobian: f64) -> (f64, Slice<'_>) {
        let (theta_h, factor, slice) = self.geometry(beta, beta_jacobian);
        (self.surface.ndf.at(theta_h) * factor, slice)
    }

    /// [`Oblique::slice`] without D: θh, the outer factor's geometry 2 sin θh dθh/dβ dβ/dx and the
    /// slice, by branch-free code.
    #[inline(always)]
    fn geometry(&self, beta: f64, beta_jacobian: f64) -> (f64, f64, Slice<'_>) {
        let radial = self.surface.radial(beta);
        let factor = 2.0 * radial.sin_h * radial.jacobian * beta_jacobian;
        (radial.theta_h, factor, self.view.slice(&radial))
    }

    /// The inner integrand at u = φ_end − φ of `slice`: weight(Λ(θi)) F(θd) ⟨ωo, h⟩.
    fn inner(&self, slice: &Slice, u: f64, fresnel: Fresnel) -> f64 {
        let point = slice.at(u);
        let f = fresnel.map_or(1.0, |f| f.at(theta_d(point.dot)));
        self.weight(self.surface.lambda.at_cos(point.cos_i.clamp(0.0, 1.0))) * f * point.dot
    }

    /// The layer λ in cos θi in which the weight G2/μo turns over next to the horizon: Λ(θi) grows
    /// like C/cos θi below cos θi ~ w, and next to Λ(θo) ≈ C/μo (height-correlated) it matters
    /// below cos θi ~ μo; λ = min(w, μo)/2 (w at most 1), or w/2.
    fn layer(&self) -> f64 {
        let w = self.surface.width.min(1.0);
        match (self.lambda_o, self.surface.g2) {
            (Some(_), G2Model::HeightCorrelated) => 0.5 * w.min(self.view.mu),
            _ => 0.5 * w,
        }
    }

    /// E(μo) by the tensor product of the fixed rules on each outer panel ([`Oblique::panels`]):
    /// every panel escalates through [`LEVELS`] on its own ([`escalate`], to `tolerance` in units
    /// of E), so one slow panel does not take the others to its level. At μo = 0 the unit C is
    /// escalated first. `None` if a panel's levels never agree or a value is not finite.
    fn fixed(&self, fresnel: &NodeFresnel, tolerance: f64) -> Option<f64> {
        let unit = match self.lambda_o {
            Some(_) => 1.0,
            None => {
                let edges: Vec<f64> = self
                    .surface
                    .lobe_edges(0.0, FRAC_PI_2)
                    .into_iter()
                    .map(|beta| inverse_smoothstep(beta / FRAC_PI_2))
                    .collect();
                escalate(tolerance, |rules| {
                    composite(&rules.outer, &edges, None, None, |s| self.visible(s))
                })?
            }
        };
        let layer = self.layer() * fresnel.layers();
        let mut sum = 0.0;
        for panel in &self.panels(layer) {
            sum += escalate_agreeing(panel.agreements, tolerance * unit, |rules| {
                self.panel(panel, layer, fresnel, rules)
            })?;
        }
        Some(sum / unit)
    }

    /// The outer panels of the fixed rules: on [0, β_cut] in β, split at the lobe's edges
    /// ([`Microfacet::lobe_edges`]), at θh = ε/4 for a lobe narrow beside the horizon and at the
    /// slice reflecting to the normal, the last panel graded towards β_cut on the scale `layer`
    /// in cos θi (a multiple of [`Oblique::layer`]); and on [0, 1] in s (the cut part), split at the same points, at
    /// its half and graded towards both ends, where the azimuth range closes like s².
    fn panels(&self, layer: f64) -> Vec<Panel> {
        let mut panels = Vec::new();
        let normal = self.normal_reflection();
        if self.beta_cut > 0.0 {
            // A lobe narrow beside the horizon's distance lies below θh = ε/4, the horizon's layer
            // next to θh = ε/2 above it: a panel end at ε/4 keeps the layer's grading off the
            // lobe. A wider lobe reaches the layer anyway, and one panel serves.
            let quarter_slope = (0.25 * self.view.elevation).tan();
            let lobe_end = if quarter_slope > NARROW_BESIDE_HORIZON * self.surface.width {
                (quarter_slope / self.surface.width).atan()
            } else {
                self.beta_cut
            };
            let slope = self.surface.radial(self.beta_cut).jacobian;
            let mut edges = self.surface.lobe_edges(0.0, lobe_end);
            let normal_edge = normal.filter(|&beta| beta < self.beta_cut);
            edges.extend(normal_edge);
            edges.push(self.beta_cut);
            edges.sort_by(f64::total_cmp);
            edges.dedup();
            panels.extend(
                graded_panels(&edges, None, Some(layer / (2.0 * slope))).map(|graded| Panel {
                    agreements: self.agreements(&graded, normal_edge),
                    graded,
                    cut: false,
                }),
            );
        }
        let start_slope = self.surface.radial(self.beta_cut).jacobian;
        let start = (layer / (6.0 * self.span * start_slope)).sqrt();
        let end_slope = self.surface.radial(self.beta_cut + self.span).jacobian;
        let end = (layer / (6.0 * self.span * end_slope)).sqrt();
        let mut edges: Vec<f64> = self
            .surface
            .lobe_edges(self.beta_cut, self.beta_cut + self.span)
            .into_iter()
            .map(|beta| inverse_smoothstep((beta - self.beta_cut) / self.span))
            .collect();
        let normal_edge = normal
            .filter(|&beta| beta > self.beta_cut && beta < self.beta_cut + self.span)
            .map(|beta| inverse_smoothstep((beta - self.beta_cut) / self.span));
        edges.extend(normal_edge);
        edges.push(0.5);
        edges.push(1.0);
        edges.sort_by(f64::total_cmp);
        edges.dedup();
        panels.extend(
            graded_panels(&edges, Some(start), Some(end)).map(|graded| Panel {
                agreements: self.agreements(&graded, normal_edge),
                graded,
                cut: true,
            }),
        );
        panels
    }

    /// The agreements a panel's levels need: 2 where the lobe is rough (w > [`ROUGH_WIDTH`]) and
    /// the panel ends at `normal_edge`, the edge (in the panel's variable) at the slice reflecting
    /// to the normal, where Λ's singularity beside the normal lies at the inner rule's far end for
    /// the slices next to that end and two levels can agree while both miss it (Beckmann α = 9 at
    /// μo = 0.2 by 7.5e-10); else 1.
    fn agreements(&self, graded: &Graded, normal_edge: Option<f64>) -> usize {
        let at_normal = normal_edge.is_some_and(|edge| graded.a == edge || graded.b == edge);
        if at_normal && self.surface.width > ROUGH_WIDTH {
            2
        } else {
            1
        }
    }

    /// One outer panel by the tensor product of `rules`: the outer rule over the panel, the inner
    /// rule on [0, φ_end] of each slice, graded towards the horizon end over the weight's `layer`.
    /// The slices' geometry for the whole outer rule runs in vector lanes ([`OuterNodes`]), then D
    /// for all of them ([`Density::at_many`]), then each slice's inner integral
    /// ([`Oblique::inner_fixed`]).
    fn panel(&self, panel: &Panel, layer: f64, fresnel: &NodeFresnel, rules: &Rules) -> f64 {
        let mut nodes = OuterNodes::new(self, panel, layer, &rules.outer_nodes);
        elementary::widest(&mut nodes);
        let n = rules.outer.points.len();
        let mut d = [0.0; MAX_NODES];
        self.surface.ndf.at_many(&nodes.theta_h[..n], &mut d[..n]);
        let mut sum = 0.0;
        for (k, &(_, w)) in rules.outer.points.iter().enumerate() {
            let slice = nodes.slice(k);
            let outer = d[k] * nodes.factor[k];
            let value = if outer == 0.0 || slice.phi_end <= 0.0 {
                0.0
            } else {
                outer * self.inner_fixed(&slice, &nodes.graded(k), rules, fresnel)
            };
            sum += w * value;
        }
        sum
    }

    /// ∫ of [`Oblique::inner`] over `slice` by the inner rule of `rules` in the variable of
    /// `graded` (u from the horizon end), in stages: the nodes' geometry (the grading's exp, sin/cos
    /// of u/2), Λ(θi), the weight and a smooth curve's table of F for the whole rule in vector
    /// lanes ([`InnerNodes`]), then a tabulated weight's cells in lanes too ([`CellsFactor`]) or
    /// else a curve node by node, then the weighted sum in the rule's order: the value
    /// [`Rule::integrate`] gives for the same integrand.
    fn inner_fixed(
        &self,
        slice: &Slice,
        graded: &Graded,
        rules: &Rules,
        fresnel: &NodeFresnel,
    ) -> f64 {
        let mut nodes = InnerNodes {
            oblique: self,
            slice,
            graded,
            fresnel,
            nodes: &rules.inner_nodes,
            dot: [0.0; MAX_NODES],
            value: [0.0; MAX_NODES],
        };
        elementary::widest(&mut nodes);
        if let NodeFresnel::Cells(cells) = fresnel {
            let n = rules.inner.points.len();
            CellsFactor::apply(cells, &nodes.dot[..n], &mut nodes.value[..n]);
        }
        let mut sum = 0.0;
        for (k, &(_, w)) in rules.inner.points.iter().enumerate() {
            let value = match fresnel {
                NodeFresnel::Curve(f) => nodes.value[k] * f(theta_d(nodes.dot[k])),
                _ => nodes.value[k],
            };
            sum += w * value;
        }
        sum
    }

    /// β where 2θh = θo: the slice whose reflection reaches the normal (θi = 0 at φ = 0). Next to
    /// it Λ(cos θi) is not analytic at the inner rule's far end (module docs), which its grading
    /// towards the horizon stretches: two levels of the fixed rules can agree there while both are
    /// off by 1e-9 (Trowbridge–Reitz α = 3 at μo = 0.01). An outer panel end there keeps them
    /// converging. `None` at μo ∈ {0, 1}.
    fn normal_reflection(&self) -> Option<f64> {
        let mu = self.view.mu;
        (mu > 0.0 && mu < 1.0).then(|| {
            let half_theta_o = 0.5 * (FRAC_PI_2 - self.view.elevation);
            (half_theta_o.tan() / self.surface.width).atan()
        })
    }

    /// E(μo) by nested adaptive Gauss–Kronrod, each level held to an absolute error of
    /// `tolerance` in units of E (of E·C at μo = 0).
    fn adaptive(&self, fresnel: Fresnel, tolerance: f64) -> Result<f64, QuadError> {
        let unit = match self.lambda_o {
            Some(_) => 1.0,
            None => integrate(|s| self.visible(s), 0.0, 1.0, tolerance)?,
        };
        let radial = |beta: f64, beta_jacobian: f64| {
            let (outer, slice) = self.slice(beta, beta_jacobian);
            let scale = unit / outer;
            // A slice whose weight `outer` times azimuth range is below 1e-200 of the unit (D
            // underflowing in a far tail, the last sliver before the horizon) carries nothing —
            // its contribution is below outer · φmax / μo — and its error scale per radian would
            // overflow the shifted sums of [`integrate_to`].
            if slice.phi_end <= 0.0 || scale / slice.phi_end > NEGLIGIBLE_SLICE {
                return Ok(0.0);
            }
            let integrand = |u: f64| Ok(self.inner(&slice, u, fresnel));
            Ok(outer * integrate_to(integrand, 0.0, slice.phi_end, scale, tolerance)?)
        };
        let uncut = if self.beta_cut > 0.0 {
            integrate_to(
                |beta| radial(beta, 1.0),
                0.0,
                self.beta_cut,
                unit,
                tolerance,
            )?
        } else {
            0.0
        };
        let cut = integrate_to(
            |s| {
                let (beta, beta_jacobian) = self.smoothstep(s);
                radial(beta, beta_jacobian)
            },
            0.0,
            1.0,
            unit,
            tolerance,
        )?;
        Ok((uncut + cut) / unit)
    }
}

/// The half-vector's polar angle at a value of the radial variable β ([`Microfacet::radial`]).
#[derive(Debug, Clone, Copy)]
struct Radial {
    theta_h: f64,
    /// dθh/dβ.
    jacobian: f64,
    sin_h: f64,
    cos_h: f64,
}

/// A sinh map t ∈ [0, 1] → x ∈ [a, b] that grades the nodes of a rule towards one end, for an
/// integrand analytic except near that end, at distance ~δ beyond it: x = a + δ sinh(A t)
/// (towards a) or b − δ sinh(A (1 − t)) (towards b), A = asinh((b − a)/δ). Where δ ≥ b − a it
/// is nearly linear; as δ → 0 the nodes crowd the end geometrically.
struct Graded {
    a: f64,
    b: f64,
    delta: f64,
    stretch: f64,
    towards_b: bool,
}

impl Graded {
    #[inline(always)]
    fn towards_start(a: f64, b: f64, delta: f64) -> Graded {
        Graded::new(a, b, delta, false)
    }

    fn towards_end(a: f64, b: f64, delta: f64) -> Graded {
        Graded::new(a, b, delta, true)
    }

    /// By branch-free code ([`elementary`]); δ = ∞ gives the linear map (stretch 0).
    #[inline(always)]
    fn new(a: f64, b: f64, delta: f64, towards_b: bool) -> Graded {
        let delta = delta.max(MIN_GRADING * (b - a));
        let stretch = elementary::asinh((b - a) / delta);
        Graded {
            a,
            b,
            delta,
            stretch: if delta.is_infinite() { 0.0 } else { stretch },
            towards_b,
        }
    }

    /// (x, dx/dt) at t ∈ [0, 1], by branch-free code (both maps computed, one selected) so that a
    /// loop over it vectorizes.
    #[inline(always)]
    fn point(&self, t: f64) -> (f64, f64) {
        let linear = (self.a + (self.b - self.a) * t, self.b - self.a);
        let tau = if self.towards_b { 1.0 - t } else { t };
        let e = elementary::exp(self.stretch * tau);
        let (sinh, cosh) = (0.5 * (e - 1.0 / e), 0.5 * (e + 1.0 / e));
        let offset = self.delta * sinh;
        let x = if self.towards_b {
            self.b - offset
        } else {
            self.a + offset
        };
        let stretched = (x, self.delta * self.stretch * cosh);
        if self.stretch == 0.0 {
            linear
        } else {
            stretched
        }
    }

    /// ∫ₐᵇ f(x) dx by `rule` in t.
    fn integrate(&self, rule: &Rule, mut f: impl FnMut(f64) -> f64) -> f64 {
        rule.integrate(
            |t| {
                let (x, jacobian) = self.point(t);
                f(x) * jacobian
            },
            0.0,
            1.0,
        )
    }
}

/// The slopes tan β (in units of the lobe width) at which the outer integral is split: the
/// lobe's core, its shoulder, and its tail, where a Gaussian lobe dies off.
const LOBE_SLOPES: [f64; 2] = [2.0, 5.0];

/// tan(ε/4) over the lobe width w above which the oblique albedo's outer integral is split at
/// θh = ε/4 (the lobe below, the horizon's layer above; ε the view's elevation).
const NARROW_BESIDE_HORIZON: f64 = 2.0;

/// D at slope 5w over D at slope 2w ([`LOBE_SLOPES`]) below which a lobe's tail is light: 4.8e-7
/// for Beckmann, 0.037 for Trowbridge–Reitz.
const LIGHT_TAIL: f64 = 1e-3;

/// cos 2θ = (cos θ − sin θ)(cos θ + sin θ) from sin θ and cos θ: the light's cosine at normal
/// incidence (θi = 2θh), free of the cancellation of 1 − 2 sin²θ next to θ = π/4.
#[inline]
fn cos_double(sin: f64, cos: f64) -> f64 {
    (cos - sin) * (cos + sin)
}

/// s ∈ [0, 1] with s²(3 − 2s) = y ∈ [0, 1].
fn inverse_smoothstep(y: f64) -> f64 {
    0.5 - ((1.0 - 2.0 * y).clamp(-1.0, 1.0).asin() / 3.0).sin()
}

/// ∫ f over the panels between successive `edges` by `rule`, graded as [`graded_panels`].
fn composite(
    rule: &Rule,
    edges: &[f64],
    start: Option<f64>,
    end: Option<f64>,
    mut f: impl FnMut(f64) -> f64,
) -> f64 {
    graded_panels(edges, start, end)
        .map(|graded| graded.integrate(rule, &mut f))
        .sum()
}

/// The panels between successive `edges` (empty ones skipped), the first graded towards its start
/// by `start` and the last towards its end by `end` ([`Graded`]), where given.
fn graded_panels(
    edges: &[f64],
    start: Option<f64>,
    end: Option<f64>,
) -> impl Iterator<Item = Graded> + '_ {
    let last = edges.len() - 2;
    edges.windows(2).enumerate().filter_map(move |(k, pair)| {
        let (a, b) = (pair[0], pair[1]);
        (b > a).then(|| match (k, start, end) {
            (k, _, Some(delta)) if k == last => Graded::towards_end(a, b, delta),
            (0, Some(delta), _) => Graded::towards_start(a, b, delta),
            _ => Graded::towards_end(a, b, f64::INFINITY),
        })
    })
}

/// One outer panel of the oblique albedo's fixed rules: its graded interval, in β or, for the
/// cut part, in s ([`Oblique::smoothstep`]).
struct Panel {
    graded: Graded,
    cut: bool,
    /// The successive agreements its levels need ([`escalate_agreeing`]): 2 for a panel ending at
    /// the slice reflecting to the normal of a rough lobe, else 1.
    agreements: usize,
}

/// The slices at every node of an outer rule on one panel ([`Oblique::panel`]'s first stage), in
/// columns: for each t of `nodes` (at most [`MAX_NODES`], a multiple of [`LANES`]), x = the
/// panel's grading of t, β = x (or the cut part's smoothstep of x), θh, the outer factor without D
/// (2 sin θh dθh/dβ dβ/dx dx/dt), the slice ([`View::slice`]) and its inner grading
/// (`Graded::towards_start(0, φ_end, layer_width)`).
struct OuterNodes<'a, 's, D, L> {
    oblique: &'a Oblique<'s, D, L>,
    panel: &'a Panel,
    layer: f64,
    nodes: &'a [f64],
    theta_h: [f64; MAX_NODES],
    factor: [f64; MAX_NODES],
    sin_h: [f64; MAX_NODES],
    cos_h: [f64; MAX_NODES],
    spread: [f64; MAX_NODES],
    floor: [f64; MAX_NODES],
    phi_end: [f64; MAX_NODES],
    sin_end: [f64; MAX_NODES],
    cos_end: [f64; MAX_NODES],
    cos_i_end: [f64; MAX_NODES],
    delta: [f64; MAX_NODES],
    stretch: [f64; MAX_NODES],
}

impl<'a, 's, D, L> OuterNodes<'a, 's, D, L> {
    fn new(oblique: &'a Oblique<'s, D, L>, panel: &'a Panel, layer: f64, nodes: &'a [f64]) -> Self {
        let zero = [0.0; MAX_NODES];
        OuterNodes {
            oblique,
            panel,
            layer,
            nodes,
            theta_h: zero,
            factor: zero,
            sin_h: zero,
            cos_h: zero,
            spread: zero,
            floor: zero,
            phi_end: zero,
            sin_end: zero,
            cos_end: zero,
            cos_i_end: zero,
            delta: zero,
            stretch: zero,
        }
    }

    /// The slice at node k.
    fn slice(&self, k: usize) -> Slice<'a> {
        Slice {
            view: &self.oblique.view,
            sin_h: self.sin_h[k],
            cos_h: self.cos_h[k],
            spread: self.spread[k],
            floor: self.floor[k],
            phi_end: self.phi_end[k],
            sin_end: self.sin_end[k],
            cos_end: self.cos_end[k],
            cos_i_end: self.cos_i_end[k],
        }
    }

    /// The inner grading at node k.
    fn graded(&self, k: usize) -> Graded {
        Graded {
            a: 0.0,
            b: self.phi_end[k],
            delta: self.delta[k],
            stretch: self.stretch[k],
            towards_b: false,
        }
    }
}

impl<D, L> Block for OuterNodes<'_, '_, D, L>
where
    D: Density,
    L: Lambda,
{
    #[inline(always)]
    fn run(&mut self) {
        let n = self.nodes.len().min(MAX_NODES);
        for k in 0..n {
            let (x, dx) = self.panel.graded.point(self.nodes[k]);
            let (beta, beta_jacobian) = if self.panel.cut {
                self.oblique.smoothstep(x)
            } else {
                (x, 1.0)
            };
            let (theta_h, factor, slice) = self.oblique.geometry(beta, beta_jacobian * dx);
            let graded = Graded::towards_start(0.0, slice.phi_end, slice.layer_width(self.layer));
            self.theta_h[k] = theta_h;
            self.factor[k] = factor;
            self.sin_h[k] = slice.sin_h;
            self.cos_h[k] = slice.cos_h;
            self.spread[k] = slice.spread;
            self.floor[k] = slice.floor;
            self.phi_end[k] = slice.phi_end;
            self.sin_end[k] = slice.sin_end;
            self.cos_end[k] = slice.cos_end;
            self.cos_i_end[k] = slice.cos_i_end;
            self.delta[k] = graded.delta;
            self.stretch[k] = graded.stretch;
        }
    }
}

/// The inner nodes of one slice ([`Oblique::inner_fixed`]'s first stage): for each t of `nodes`
/// (at most [`MAX_NODES`], a multiple of [`LANES`]), at u = `graded`(t), ⟨ωo, h⟩ and the
/// integrand without F, weight(Λ(θi)) ⟨ωo, h⟩ du/dt, cos θi clamped to [0, 1]; with F where it
/// is a smooth curve's table.
struct InnerNodes<'a, 's, 'v, D, L> {
    oblique: &'a Oblique<'s, D, L>,
    slice: &'a Slice<'v>,
    graded: &'a Graded,
    /// The Fresnel factor: where it is tabulated ([`NodeFresnel::Table`]), `value` includes it.
    fresnel: &'a NodeFresnel<'a>,
    nodes: &'a [f64],
    dot: [f64; MAX_NODES],
    value: [f64; MAX_NODES],
}

impl<D: Density, L: Lambda> Block for InnerNodes<'_, '_, '_, D, L> {
    #[inline(always)]
    fn run(&mut self) {
        let n = self.nodes.len().min(MAX_NODES);
        let (mut cos_i, mut jacobian, mut lambda_i) =
            ([0.0; MAX_NODES], [0.0; MAX_NODES], [0.0; MAX_NODES]);
        for k in 0..n {
            let (u, du) = self.graded.point(self.nodes[k]);
            let point = self.slice.at(u);
            cos_i[k] = point.cos_i.clamp(0.0, 1.0);
            self.dot[k] = point.dot;
            jacobian[k] = du;
        }
        self.oblique
            .surface
            .lambda
            .at_cos_many(&cos_i[..n], &mut lambda_i[..n]);
        for k in 0..n {
            self.value[k] = self.oblique.weight(lambda_i[k]) * self.dot[k] * jacobian[k];
        }
        if let NodeFresnel::Table(table) = self.fresnel {
            let mut f = [0.0; MAX_NODES];
            table.eval_many(&self.dot[..n], &mut f[..n]);
            for k in 0..n {
                self.value[k] *= f[k];
            }
        }
    }
}

/// A tabulated weight's cells applied to an inner rule's values ([`Oblique::inner_fixed`]'s second
/// stage for [`NodeFresnel::Cells`]): `value[k]` ×= F̃(`dot[k]`) for the first `n` nodes, in
/// vector lanes ([`Smoothed::at_cos_many`]). A block of its own: inside [`InnerNodes`] the gathers
/// slowed every other albedo by a tenth (the 8 × 8 E table 1.15 → 1.30 ms).
struct CellsFactor<'a> {
    cells: &'a Smoothed,
    dot: &'a [f64],
    value: &'a mut [f64],
}

impl CellsFactor<'_> {
    /// Runs the block on `value` and `dot` in the widest lanes, out of line: inlined into
    /// [`Oblique::inner_fixed`], its three compiled paths slowed every other albedo too.
    #[inline(never)]
    fn apply(cells: &Smoothed, dot: &[f64], value: &mut [f64]) {
        elementary::widest(&mut CellsFactor { cells, dot, value });
    }
}

impl Block for CellsFactor<'_> {
    #[inline(always)]
    fn run(&mut self) {
        let n = self.dot.len().min(MAX_NODES);
        let mut f = [0.0; MAX_NODES];
        self.cells.at_cos_many(&self.dot[..n], &mut f[..n]);
        for (value, f) in self.value.iter_mut().zip(&f[..n]) {
            *value *= f;
        }
    }
}

/// The lobe width (a slope) above which a lobe is rough enough for Λ's singularity beside the normal
/// to reach its albedo's panels ([`Oblique::agreements`]): Trowbridge–Reitz's branch point
/// α/√(α² − 1) exists from α = 1 on.
const ROUGH_WIDTH: f64 = 1.0;

/// The Fresnel factor at the fixed rules' inner nodes: none (F ≡ 1); a smooth F(arccos c)
/// by its table in c = ⟨ωo, h⟩ = cos θd ([`FresnelTable`]); the curve itself where the table does
/// not converge (F not smooth enough in cos θd); or the
/// smooth surrogate of a weight tabulated on the basis grid, cubic cell by cell in c
/// ([`Smoothed`]), which no interpolant of a few pieces follows. A table and the cells are
/// evaluated over a whole inner rule in vector lanes ([`InnerNodes`]), the curve node by node.
enum NodeFresnel<'a> {
    One,
    Table(&'a Piecewise),
    Curve(&'a (dyn Fn(f64) -> f64 + Sync)),
    Cells(&'a Smoothed),
}

impl<'a> NodeFresnel<'a> {
    /// The nodes' factor for `weight`: none for F ≡ 1, a curve's table where it converged or else
    /// the curve, and the cells of a tabulated weight.
    fn new(weight: Weight<'a>) -> NodeFresnel<'a> {
        match weight {
            Weight::Curve(None) => NodeFresnel::One,
            Weight::Curve(Some(FresnelFactor {
                table: Some(FresnelTable(TableKind::Chebyshev(table))),
                ..
            })) => NodeFresnel::Table(table),
            Weight::Curve(Some(FresnelFactor { curve, .. })) => NodeFresnel::Curve(curve),
            Weight::Tabulated(cells) => NodeFresnel::Cells(cells),
        }
    }

    /// The layers λ over which the fixed rules are graded next to the horizon: [`GRADED_LAYERS`],
    /// or 1 for cells, which vary most at grazing θd, next to the horizon.
    fn layers(&self) -> f64 {
        match self {
            NodeFresnel::Cells(_) => 1.0,
            _ => GRADED_LAYERS,
        }
    }
}

/// The absolute error of a Fresnel factor's table inside the fixed rules ([`NodeFresnel`]): E
/// moves by at most this much (E ≤ 1), far below its tolerance of 1e-10.
const FRESNEL_TABLE_TOL: f64 = 1e-13;

/// The most points of an outer or inner rule ([`LEVELS`]): the size of the fixed rules' stages
/// ([`OuterNodes`], [`InnerNodes`]).
const MAX_NODES: usize = 48;

/// The layers λ of the weight's turnover ([`Oblique::layer`]) over which the fixed rules are graded
/// next to the horizon for a smooth Fresnel factor. Graded within λ itself, an inner rule crowds
/// its nodes at the horizon and leaves too few at its far end, where on the slices beside the one
/// reflecting to the normal Λ(θi) of a light-tailed lobe rises from 0 (Beckmann's
/// exp(−cot²θi/α²), not analytic at θi = 0) and converges slowest: Beckmann α = 0.3 at μo = 0.5
/// took 26, 36, 26 and 36 points a side on its four panels, and takes 24, 32, 24 and 32 over 4λ;
/// SGD's panels, 20 to 26 before, all agree at 24. Accuracy across the domain is unchanged or
/// better (tests/numerics/albedo.rs). A factor of cells ([`NodeFresnel::Cells`]) keeps λ: it
/// varies most at grazing θd, next to the horizon, and over 4λ the split-sum tables cost 1.2×.
const GRADED_LAYERS: f64 = 4.0;

/// The finest grading of [`Graded`], relative to its interval: far below any layer that matters.
const MIN_GRADING: f64 = 1e-14;

/// The points of the outer and the inner Gauss–Legendre rule of each level of the fast path
/// ([`escalate`]): whole vectors of [`LANES`] each, since a rule is padded to them anyway (20 points
/// cost what 24 do), growing by one vector a level.
const LEVELS: [Order; 6] = [
    Order { outer: 8, inner: 8 },
    Order {
        outer: 16,
        inner: 16,
    },
    Order {
        outer: 24,
        inner: 24,
    },
    Order {
        outer: 32,
        inner: 32,
    },
    Order {
        outer: 40,
        inner: 40,
    },
    Order {
        outer: 48,
        inner: 48,
    },
];

/// The points of one level's outer rule (per outer panel, and of E(1)'s integral) and inner rule.
#[derive(Debug, Clone, Copy)]
struct Order {
    /// Points of the outer rule.
    outer: usize,
    /// Points of the inner rule in u.
    inner: usize,
}

/// An outer and an inner Gauss–Legendre rule.
struct Rules {
    outer: Rule,
    inner: Rule,
    /// The outer rule's points t, then ½ up to a multiple of [`LANES`]: [`OuterNodes`] runs over
    /// whole vectors, its padding's values unused.
    outer_nodes: Vec<f64>,
    /// The same for the inner rule ([`InnerNodes`]).
    inner_nodes: Vec<f64>,
}

/// The points t of `rule`, then ½ up to a multiple of [`LANES`].
fn padded_nodes(rule: &Rule) -> Vec<f64> {
    let mut nodes: Vec<f64> = rule.points.iter().map(|&(t, _)| t).collect();
    nodes.resize(nodes.len().next_multiple_of(LANES), 0.5);
    nodes
}

/// The lanes of the widest vectors [`elementary::widest`] runs in (AVX-512: 8 doubles).
const LANES: usize = 8;

/// The rules of [`LEVELS`], built once.
fn level_rules() -> &'static [Rules; 6] {
    static RULES: OnceLock<[Rules; 6]> = OnceLock::new();
    RULES.get_or_init(|| {
        LEVELS.map(|order| {
            let (outer, inner) = (Rule::new(order.outer), Rule::new(order.inner));
            Rules {
                outer_nodes: padded_nodes(&outer),
                inner_nodes: padded_nodes(&inner),
                outer,
                inner,
            }
        })
    })
}

/// The value of `by` at the first level of [`LEVELS`] (from the second) that differs from the
/// level before by at most [`FIXED_AGREEMENT`] × `tolerance`: that difference is about the error
/// e of the level before, and where a Gauss rule's error decays geometrically the next level's is
/// about e^{n'/n} (e^{1.5} from 16 to 24 points: 2e-16 at e = 3e-11), so the accepted value is
/// within ~`tolerance` (measured against the adaptive quadrature at 1e-14 across the domain:
/// tests/numerics/albedo.rs). `None` if no two successive levels agree or a value is not finite.
fn escalate(tolerance: f64, by: impl Fn(&Rules) -> f64) -> Option<f64> {
    escalate_agreeing(1, tolerance, by)
}

/// [`escalate`] taking the value where `agreements` successive differences in a row are within
/// the bound: with 2, a coincidental agreement of two levels that both miss a feature is caught by
/// the third.
fn escalate_agreeing(agreements: usize, tolerance: f64, by: impl Fn(&Rules) -> f64) -> Option<f64> {
    let rules = &level_rules()[usize::from(tolerance < COARSE_LEVEL_TOL)..];
    let mut last = by(&rules[0]);
    let mut agreed = 0;
    for level in &rules[1..] {
        let value = by(level);
        if !value.is_finite() {
            return None;
        }
        if (value - last).abs() <= FIXED_AGREEMENT * tolerance {
            agreed += 1;
            if agreed == agreements {
                return Some(value);
            }
        } else {
            agreed = 0;
        }
        last = value;
    }
    None
}

/// The least tolerance at which [`escalate`] starts from the 8 × 8 level of [`LEVELS`]; tighter
/// ones start from 16 × 16, since 8 points rarely agree with 16 to them and would only add their
/// cost. At 3e-10 ([`AVERAGE_E_TOL`]) two agreeing levels of 8 and 16 points leave the 16-point value
/// within ~(9e-9)² of its limit where the rule's error decays geometrically.
const COARSE_LEVEL_TOL: f64 = 1e-10;

/// A level's value is taken where it differs from the level before by at most this many times
/// the surface's tolerance (3e-11 at the default 1e-12).
const FIXED_AGREEMENT: f64 = 30.0;

/// unit / (outer · φmax) above which a slice of the oblique albedo is left out (module docs'
/// quadrature): far below any tolerance, far above overflow.
const NEGLIGIBLE_SLICE: f64 = 1e200;

/// The view direction ωo = (cos ε, 0, sin ε) at elevation ε = arcsin μo above the horizon.
struct View {
    elevation: f64,
    cos_elevation: f64,
    mu: f64,
    /// 1/μo, which every inner node's weight G2/μo multiplies by.
    inverse_mu: f64,
}

/// The half-vectors at polar angle θh that reflect ωo above the horizon: φ ∈ [0, φ_end] (and its
/// mirror image), parameterized by u = φ_end − φ, the azimuth from the horizon end (φ_end = φmax
/// where azimuths are cut off, π where none are), with what the inner integrand needs.
struct Slice<'v> {
    view: &'v View,
    sin_h: f64,
    cos_h: f64,
    /// 2 cos ε sin 2θh.
    spread: f64,
    /// cos(2θh + θo) = sin(ε − 2θh): cos θi at φ = π.
    floor: f64,
    /// The length of the azimuth range, φ_end.
    phi_end: f64,
    /// sin φ_end and cos φ_end.
    sin_end: f64,
    cos_end: f64,
    /// cos θi at φ_end: 0 where azimuths are cut off, else `floor`.
    cos_i_end: f64,
}

/// What the inner integrand needs at one azimuth.
struct Azimuth {
    /// ⟨ωo, h⟩ = cos θd.
    dot: f64,
    /// cos θi.
    cos_i: f64,
}

/// θd, the angle between ωo and h, from ⟨ωo, h⟩: its arccos. Next to θd = 0 that angle is off by up
/// to ~1e-8, which moves F(θd) — smooth and even in θd there — by ~1e-16.
fn theta_d(dot: f64) -> f64 {
    dot.clamp(-1.0, 1.0).acos()
}

impl View {
    fn new(mu: f64) -> View {
        View {
            elevation: mu.asin(),
            cos_elevation: ((1.0 - mu) * (1.0 + mu)).sqrt(),
            mu,
            inverse_mu: 1.0 / mu,
        }
    }

    /// The slice of half-vectors at `radial`'s θh, by branch-free code ([`elementary`]).
    #[inline(always)]
    fn slice(&self, radial: &Radial) -> Slice<'_> {
        let Radial {
            theta_h,
            sin_h,
            cos_h,
            ..
        } = *radial;
        let spread = 2.0 * self.cos_elevation * (2.0 * sin_h * cos_h);
        let floor = elementary::sin_cos(self.elevation - 2.0 * theta_h).0;
        // Cut off: cos²(φmax/2) = q = −floor / spread, so φmax = 2 arccos √q, cos φmax = 2q − 1 and
        // sin φmax = 2 √(q (1 − q)); q ≥ 1 leaves no azimuth.
        let q = -floor / spread;
        let cut = (
            2.0 * arccos_sqrt(q),
            2.0 * (q * (1.0 - q)).sqrt(),
            2.0 * q - 1.0,
            0.0,
        );
        let (phi_end, sin_end, cos_end, cos_i_end) = if floor >= 0.0 {
            (PI, 0.0, -1.0, floor)
        } else if q < 1.0 {
            cut
        } else {
            (0.0, 0.0, 1.0, 0.0)
        };
        Slice {
            view: self,
            sin_h,
            cos_h,
            spread,
            floor,
            phi_end,
            sin_end,
            cos_end,
            cos_i_end,
        }
    }
}

/// arccos √y for y ∈ [0, 1] as arctan √((1 − y)/y) ([`elementary::atan`]; π/2 at y = 0).
#[inline(always)]
fn arccos_sqrt(y: f64) -> f64 {
    elementary::atan(((1.0 - y) / y).sqrt())
}

impl Slice<'_> {
    /// The distance in u from the slice's horizon end over which cos θi rises by its value
    /// there plus `layer`.
    #[inline(always)]
    fn layer_width(&self, layer: f64) -> f64 {
        let y = (layer + self.floor.abs()) / self.spread;
        let inside = self.phi_end - 2.0 * arccos_sqrt(y);
        if y >= 1.0 { self.phi_end } else { inside }
    }

    /// The azimuth u = φ_end − φ from the horizon end: with σ = sin(u/2), cos u = 1 − 2σ², and
    /// cos θi = cos θi(φ_end) + (spread/2)(sin φ_end sin u − cos φ_end (1 − cos u)), free of
    /// cancellation next to the horizon.
    #[inline(always)]
    fn at(&self, u: f64) -> Azimuth {
        let (half_sin, half_cos) = elementary::sin_cos(0.5 * u);
        let sin_u = 2.0 * half_sin * half_cos;
        let versine = 2.0 * half_sin * half_sin;
        let cos_u = 1.0 - versine;
        let cos_phi = self.cos_end * cos_u + self.sin_end * sin_u;
        let (sin_o, cos_o) = (self.view.cos_elevation, self.view.mu);
        Azimuth {
            dot: sin_o * self.sin_h * cos_phi + cos_o * self.cos_h,
            cos_i: self.cos_i_end
                + 0.5 * self.spread * (self.sin_end * sin_u - self.cos_end * versine),
        }
    }
}

/// ∫ₐᵇ f(x) dx held to an absolute error of about `tolerance` · (|∫ f| + `scale`):
/// [`integrate`]'s relative criterion applied to f + scale/(b − a), whose Gauss–Kronrod error
/// estimate is that of f (constants are integrated exactly), then scale subtracted. An integrand
/// may itself fail (an inner integral): the first failure is returned instead.
fn integrate_to(
    f: impl Fn(f64) -> Result<f64, QuadError>,
    a: f64,
    b: f64,
    scale: f64,
    tolerance: f64,
) -> Result<f64, QuadError> {
    let shift = scale / (b - a);
    let failure: Cell<Option<QuadError>> = Cell::new(None);
    let shifted = integrate(
        |x| match f(x) {
            Ok(value) => value + shift,
            Err(error) => {
                let first = failure.take().unwrap_or(error);
                failure.set(Some(first));
                f64::NAN
            }
        },
        a,
        b,
        tolerance,
    );
    match failure.into_inner() {
        Some(error) => Err(error),
        None => Ok(shifted? - scale),
    }
}

/// Why [`lobe`] gives no lobe.
#[derive(Debug, Clone, PartialEq)]
pub enum NoLobe {
    /// A parameter outside its domain (the first one nonzero).
    Domain(DomainError),
    /// The first parameter is 0, outside the domain, and the family's lobe tends there to one
    /// ndfplot does not evaluate (what [`ZeroLimit::Other`] says).
    Limit(&'static str),
}

/// The lobe of `family` with `params` (in the family's order, the first the roughness parameter α
/// a table maps r to): the NDF where every parameter is in its domain, and at α = 0 outside it the
/// family's own limit there ([`crate::model::ndf::Distribution::zero_limit`]) — `None` for the
/// mirror, the uniform lobe (Phong's α_p = 0) for [`ZeroLimit::Uniform`]. The one statement of
/// what an albedo table's r = 0 column is.
pub fn lobe(family: Family, params: &[f64]) -> Result<Option<Ndf>, NoLobe> {
    match family.build(params) {
        Ok(ndf) => Ok(Some(ndf)),
        Err(e) if params[0] == 0.0 && e.param == family.params()[0].name => {
            for (param, &value) in family.params()[1..].iter().zip(&params[1..]) {
                param.check(value).map_err(NoLobe::Domain)?;
            }
            match family.zero_limit(&params[1..]) {
                ZeroLimit::Mirror => Ok(None),
                ZeroLimit::Uniform => Ok(Some(Ndf::Phong(
                    Phong::new(0.0).expect("α_p = 0 is in Phong's domain"),
                ))),
                ZeroLimit::Other(what) => Err(NoLobe::Limit(what)),
            }
        }
        Err(e) => Err(NoLobe::Domain(e)),
    }
}

/// What turning an NDF into a surface costs integrals for, found once: its [`median_slope`] (the
/// lobe width) and Λ as a [`LambdaTable`] built from [`Ndf::lambda`] (G1 within 1e-12; a few ns a
/// value in a block of the albedo's inner nodes, instead of a quadrature's 10–25 µs for four
/// families, Phong's 1.5 µs, Student-t's 80 ns and Beckmann's ~35 ns), or `None` — Λ is then
/// [`Ndf::lambda`] itself — for Trowbridge–Reitz, whose root and division cost no more than the
/// table, and where the table does not converge or D is unbounded at grazing (module
/// masking::table).
/// A curve keeps them for all its values ([`surface_with`]); the same NDF gives the same parts.
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceParts {
    width: f64,
    table: Option<LambdaTable>,
}

impl SurfaceParts {
    /// The parts of `ndf`.
    pub fn of(ndf: &Ndf) -> SurfaceParts {
        let width = median_slope(|theta| ndf.eval(theta));
        let elementary = matches!(ndf, Ndf::TrowbridgeReitz(_));
        let table = if elementary || ndf.unbounded_at_grazing() {
            None
        } else {
            LambdaTable::build(|theta| ndf.lambda(theta), width)
        };
        SurfaceParts { width, table }
    }

    /// Λ at μ = cos θ of `ndf`, the NDF these parts are of: by the table where there is one.
    #[inline]
    fn lambda_at_cos(&self, ndf: &Ndf, mu: f64) -> f64 {
        match &self.table {
            Some(table) => table.lambda_at_cos(mu),
            None => ndf.lambda_at_cos(mu),
        }
    }
}

/// Λ of an NDF by its [`SurfaceParts`] (each held or borrowed): the [`Lambda`] of [`surface_with`]
/// and [`surface_of`], a table's block in vector lanes ([`LambdaTable::lambda_at_cos_many`]).
struct SurfaceLambda<N, P> {
    ndf: N,
    parts: P,
}

impl<N: Borrow<Ndf>, P: Borrow<SurfaceParts>> Lambda for SurfaceLambda<N, P> {
    #[inline(always)]
    fn at_cos(&self, mu: f64) -> f64 {
        self.parts.borrow().lambda_at_cos(self.ndf.borrow(), mu)
    }

    #[inline(always)]
    fn at_cos_many(&self, mus: &[f64], out: &mut [f64]) {
        match &self.parts.borrow().table {
            Some(table) => table.lambda_at_cos_many(mus, out),
            None => match self.ndf.borrow() {
                // Its closed form, branch-free: one loop in vector lanes.
                Ndf::TrowbridgeReitz(ndf) => {
                    for (out, &mu) in out.iter_mut().zip(mus) {
                        *out = ndf.lambda_at_cos(mu);
                    }
                }
                ndf => {
                    for (out, &mu) in out.iter_mut().zip(mus) {
                        *out = ndf.lambda_at_cos(mu);
                    }
                }
            },
        }
    }
}

/// The microfacet surface of `ndf` under `g2` with its [`SurfaceParts`] `parts` (found for this
/// `ndf`): D by [`Ndf::eval`], Λ ([`Ndf::lambda_at_cos`] or the table's) and the width from the
/// parts.
pub fn surface_with<'a>(
    ndf: &'a Ndf,
    parts: &'a SurfaceParts,
    g2: G2Model,
) -> Microfacet<impl Density + Sync + Send + 'a, impl Lambda + Sync + Send + 'a> {
    Microfacet::with_width(ndf, SurfaceLambda { ndf, parts }, g2, parts.width)
}

/// The microfacet surface of `ndf` under `g2`, owning it and its [`SurfaceParts`]: what
/// [`surface_with`] gives for parts found now. The one way the crate turns an NDF into a surface.
pub fn surface_of(
    ndf: Ndf,
    g2: G2Model,
) -> Microfacet<impl Density + Sync + Send, impl Lambda + Sync + Send> {
    let parts = SurfaceParts::of(&ndf);
    let width = parts.width;
    let for_lambda = ndf.clone();
    Microfacet::with_width(
        ndf,
        SurfaceLambda {
            ndf: for_lambda,
            parts,
        },
        g2,
        width,
    )
}

/// The median slope of a lobe: tan θ at which 2π ∫₀^θ D sin θ cos θ dθ reaches ½, to within a
/// factor of 2^{1/2} (enough for a quadrature scale). The projected area is accumulated over slope
/// octaves tan θ ∈ [2^k, 2^{k+1}] up to k = 64, each integrated on its own, so lobes of any width,
/// down to D(0) near f64::MAX, are resolved. Below slope s, where D is still D(0) to within a factor
/// near 1 (s ≤ 2^{−40}), the mass is about π D(0) s², so the octaves start where that is below
/// 2^{−100} (at k = −1000 if D(0) is 0 or not finite): the skipped mass is nothing, and a lobe of
/// ordinary width costs ~60 octaves instead of ~1000 (the albedo builds this once per value).
/// Returns 2^{k+½} for the octave where the half is crossed (1 if rounding keeps the total below ½,
/// which a normalized D does not).
pub fn median_slope(ndf: impl Fn(f64) -> f64) -> f64 {
    const LOWEST_OCTAVE: i32 = -1000;
    const HIGHEST_OCTAVE: i32 = 64;
    /// The highest first octave: far below any lobe's own scale, where every D is flat.
    const FLAT_OCTAVE: i32 = -40;
    /// log₂ of the mass allowed below the first octave.
    const SKIPPED_MASS_LOG2: f64 = -100.0;
    /// The mass of an octave to a few digits is all the bracket needs.
    const OCTAVE_REL_TOL: f64 = 1e-6;
    let peak_mass_log2 = (PI * ndf(0.0)).log2();
    let first = if peak_mass_log2.is_finite() {
        (((SKIPPED_MASS_LOG2 - peak_mass_log2) / 2.0).floor() as i32)
            .clamp(LOWEST_OCTAVE, FLAT_OCTAVE)
    } else {
        LOWEST_OCTAVE
    };
    let mut mass = 0.0;
    for k in first..HIGHEST_OCTAVE {
        let (lo, hi) = (2f64.powi(k).atan(), 2f64.powi(k + 1).atan());
        let octave = integrate(
            |theta: f64| 2.0 * PI * ndf(theta) * theta.sin() * theta.cos(),
            lo,
            hi,
            OCTAVE_REL_TOL,
        )
        .unwrap_or(0.0);
        mass += octave;
        if mass >= 0.5 {
            return 2f64.powf(f64::from(k) + 0.5);
        }
    }
    1.0
}

/// E_avg = 2 ∫₀¹ E(μ) μ dμ, the cosine-weighted average of [`Microfacet::albedo`] over the
/// hemisphere (for F ≡ 1, the fraction of uniform incident light the single-scattering lobe
/// reflects), by fixed Gauss–Legendre rules on the panels of the two places where E(μ) is not a
/// polynomial to working precision: it turns over to its grazing limit where μ falls below the lobe
/// width w, so the panels are graded geometrically (ratio [`AVERAGE_GRADING`], 8 points each) from
/// μ = min(w, 1)/16 up to [`AVERAGE_TOP`] = 1/2 (below μ = [`AVERAGE_FLOOR`], E = E(0)); and near
/// μ = 1 the horizon cut's contribution vanishes like (1 − μ)^{5/4} (the cut spans
/// θh ∈ [ε/2, π/2 − ε/2], ε = arcsin μ), so the last panel [1/2, 1] runs in s with μ = 1 − s⁴
/// (14 points). Each E is computed to the tolerance [`AVERAGE_E_TOL`] (or the surface's own if
/// looser), its fixed rules escalating from 8 × 8 points ([`COARSE_LEVEL_TOL`]), which holds it
/// within a few times that (measured within 1.03e-9 of the same E at 1e-12 across the families:
/// tests/numerics/albedo.rs); the weights sum to 1, so E_avg keeps about that accuracy. 38–70 albedos per value (40.7 on
/// average over the cases below; 44–76 and 49.4 with the graded panels ending at 1/4 and two
/// 14-point halves above); within 3.0e-9 of 16-point rules on finer panels (ratio 1.6 from
/// min(w, 1)/64, eight pieces in s above 1/4) with every E to 1e-12, themselves within 1.4e-13
/// of 24-point rules on finer panels still: GGX, Beckmann, GTR γ = 1.5 and Student-t γ = 3, both
/// G2 models, maps r², r and √r at r = 1/31 … 1, 744 values; the largest differences are
/// Beckmann's, whose light tail reaches the horizon over a narrow range of μ. [`AVERAGE_TOL`] is
/// the bound stated.
pub fn average_albedo<D, L>(surface: &Microfacet<D, L>, fresnel: Fresnel) -> Result<f64, QuadError>
where
    D: Density,
    L: Lambda,
{
    let tolerance = surface.tolerance.max(AVERAGE_E_TOL);
    let albedo = |mu: f64| surface.albedo_within(mu, fresnel, tolerance);
    let edges = average_edges(surface.width);
    // Below μ = [`AVERAGE_FLOOR`] E is taken as its limit E(0): the panel carries at most
    // AVERAGE_FLOOR²/2 = 5e-11 of E_avg/2, and E's quadrature needs μ well above a tiny lobe width.
    let mut half = if edges[1] == AVERAGE_FLOOR {
        albedo(0.0)? * AVERAGE_FLOOR * AVERAGE_FLOOR / 2.0
    } else {
        0.0
    };
    let last = edges.len() - 2;
    let [graded, top] = average_rules();
    for (k, pair) in edges.windows(2).enumerate() {
        let (a, b) = (pair[0], pair[1]);
        if a == 0.0 && b == AVERAGE_FLOOR {
            continue;
        }
        // The last panel in s with μ = 1 − s⁴, (1 − μ)^{5/4} becoming s⁵.
        let rule = if k == last { top } else { graded };
        for &(x, weight) in &rule.points {
            let (mu, jacobian) = if k == last {
                let top = (1.0 - a).powf(0.25);
                let s = top * x;
                (1.0 - s.powi(4), top * 4.0 * s.powi(3))
            } else {
                (a + (b - a) * x, b - a)
            };
            half += jacobian * weight * albedo(mu)? * mu;
        }
    }
    Ok(2.0 * half)
}

/// The accuracy [`average_albedo`] holds E_avg to (at the default tolerance): its rule and the
/// looser [`AVERAGE_E_TOL`] of each E together (measured: within 3.0e-9), below float32's
/// half-ulp at 1 (6e-8), the precision engines store it in.
pub const AVERAGE_TOL: f64 = 1e-8;

/// The tolerance of each nested integral of the E values [`average_albedo`] weighs.
pub const AVERAGE_E_TOL: f64 = 3e-10;

/// Ratio of successive panel ends of [`average_albedo`]'s μ axis below [`AVERAGE_TOP`]: 8 points
/// span a factor of 6 in μ where E turns over on the scale μ itself (ratio 8 left 3.3e-8 for
/// Beckmann, with two 8-point halves above 1/2).
const AVERAGE_GRADING: f64 = 6.0;
/// Where [`average_albedo`]'s last panel, in s with μ = 1 − s⁴, begins: above 1/2 a single
/// 14-point rule in s holds E(μ) μ within the bound (one from 1/4 left 3.7e-8 for Beckmann, and
/// 12 points from 0.6 1.6e-8).
const AVERAGE_TOP: f64 = 0.5;
/// The smallest μ at which [`average_albedo`] evaluates E.
const AVERAGE_FLOOR: f64 = 1e-5;

/// Points of [`average_albedo`]'s rules: per graded panel below μ = [`AVERAGE_TOP`], and on the
/// last panel [`AVERAGE_TOP`, 1] (in s).
const AVERAGE_POINTS: [usize; 2] = [8, 14];

/// The rules of [`average_albedo`], built once.
fn average_rules() -> &'static [Rule; 2] {
    static RULES: OnceLock<[Rule; 2]> = OnceLock::new();
    RULES.get_or_init(|| AVERAGE_POINTS.map(Rule::new))
}

/// The panel ends of [`average_albedo`]'s μ axis for a lobe of width w: 0, then s, 6s, 36s, … below
/// [`AVERAGE_TOP`] from s = max(min(w, 1)/16, [`AVERAGE_FLOOR`]), then [`AVERAGE_TOP`] and 1.
fn average_edges(width: f64) -> Vec<f64> {
    let mut edges = vec![0.0];
    let mut end = (width.min(1.0) / 16.0).max(AVERAGE_FLOOR);
    while end < AVERAGE_TOP {
        edges.push(end);
        end *= AVERAGE_GRADING;
    }
    edges.extend([AVERAGE_TOP, 1.0]);
    edges
}

/// F_avg = 2 ∫₀¹ F(μ) μ dμ = 2 ∫₀^{π/2} F(θ) cos θ sin θ dθ, the cosine-weighted average of a Fresnel
/// curve given as a function of θ (Schlick: F₀ + (1 − F₀)/21).
pub fn average_fresnel(fresnel: impl Fn(f64) -> f64) -> Result<f64, QuadError> {
    let half = integrate(
        |theta: f64| fresnel(theta) * theta.cos() * theta.sin(),
        0.0,
        FRAC_PI_2,
        ALBEDO_QUAD_REL_TOL,
    )?;
    Ok(2.0 * half)
}

/// Kulla–Conty's multiple-scattering lobe f_ms(μo, μi) = (1 − E(μo))(1 − E(μi)) / (π(1 − E_avg)),
/// whose albedo is exactly 1 − E(μo) (the energy the single-scattering lobe loses). `e_o`, `e_i`
/// are E(μo) and E(μi) and `e_avg` is E_avg, all computed with F ≡ 1; E_avg < 1.
pub fn kulla_conty_lobe(e_o: f64, e_i: f64, e_avg: f64) -> f64 {
    (1.0 - e_o) * (1.0 - e_i) / (PI * (1.0 - e_avg))
}

/// Kulla–Conty's Fresnel colouring of f_ms: F_ms = F_avg² E_avg / (1 − F_avg (1 − E_avg)), the
/// average Fresnel over the infinite series of bounces (F_avg from [`average_fresnel`], E_avg with
/// F ≡ 1). Equals 1 for F_avg = 1.
pub fn kulla_conty_fresnel(f_avg: f64, e_avg: f64) -> f64 {
    f_avg * f_avg * e_avg / (1.0 - f_avg * (1.0 - e_avg))
}

/// Turquin's energy-compensation factor 1 + F₀ (1 − E(μo)) / E(μo), by which f_ss is scaled; `e_o` is
/// E(μo) with F ≡ 1 (> 0). For F₀ = 1 it is 1/E(μo).
pub fn turquin_factor(f0: f64, e_o: f64) -> f64 {
    1.0 + f0 * (1.0 - e_o) / e_o
}

/// How a table's roughness coordinate r ∈ [0, 1] maps to the NDF width α.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum RoughnessMap {
    /// α = r² (Burley's perceptual roughness: Cycles, Filament, Unreal).
    Squared,
    /// α = r.
    Linear,
    /// α = √r (pbrt-v4's `RoughnessToAlpha`).
    Root,
}

impl RoughnessMap {
    /// Each map with its key in a scene's `"map"` and `ndfplot albedo --map`, the default first.
    pub const KEYS: [(&'static str, RoughnessMap); 3] = [
        ("r2", RoughnessMap::Squared),
        ("r", RoughnessMap::Linear),
        ("sqrt", RoughnessMap::Root),
    ];

    /// The map whose key is `key` (`r2`, `r`, `sqrt`), if any.
    pub fn from_key(key: &str) -> Option<RoughnessMap> {
        Self::KEYS
            .iter()
            .find(|(k, _)| *k == key)
            .map(|&(_, map)| map)
    }

    /// The map's key (`r2`, `r`, `sqrt`).
    pub fn key(self) -> &'static str {
        Self::KEYS
            .iter()
            .find(|&&(_, m)| m == self)
            .map(|&(key, _)| key)
            .expect("every map has a key")
    }

    /// The expression of α in r: `r^2`, `r` or `sqrt(r)`.
    pub fn expression(self) -> &'static str {
        match self {
            RoughnessMap::Squared => "r^2",
            RoughnessMap::Linear => "r",
            RoughnessMap::Root => "sqrt(r)",
        }
    }

    /// The map's name in outputs: `alpha = r^2`, `alpha = r` or `alpha = sqrt(r)`.
    pub fn name(self) -> &'static str {
        match self {
            RoughnessMap::Squared => "alpha = r^2",
            RoughnessMap::Linear => "alpha = r",
            RoughnessMap::Root => "alpha = sqrt(r)",
        }
    }

    /// α = map(r).
    pub fn alpha(self, r: f64) -> f64 {
        match self {
            RoughnessMap::Squared => r * r,
            RoughnessMap::Linear => r,
            RoughnessMap::Root => r.sqrt(),
        }
    }
}

/// A table of values over μ (rows) and roughness r (columns) on Cycles' grid: μ_i = i/(n_μ − 1),
/// r_j = j/(n_r − 1), α_j = map(r_j); `values[i * n_r + j]` belongs to (μ_i, r_j).
#[derive(Debug, Clone, PartialEq)]
pub struct AlbedoTable {
    /// How r maps to α.
    pub map: RoughnessMap,
    /// The row coordinates μ_i.
    pub mu: Vec<f64>,
    /// The column coordinates r_j.
    pub roughness: Vec<f64>,
    /// Row-major values, rows μ.
    pub values: Vec<f64>,
}

impl AlbedoTable {
    /// The value at row i (μ_i), column j (r_j).
    pub fn get(&self, i: usize, j: usize) -> f64 {
        self.values[i * self.roughness.len() + j]
    }
}

/// Reports progress as (cells done, cells in all); called from the worker threads.
pub type ProgressFn<'a> = &'a (dyn Fn(usize, usize) + Sync);

/// The n ≥ 2 coordinates i/(n − 1), i = 0 … n − 1, of a table axis ([`AlbedoTable`]'s μ and r,
/// [`average_albedo_table`]'s r), the last exactly 1. Panics for n < 2.
pub fn unit_grid(n: usize) -> Vec<f64> {
    assert!(n >= 2, "a table axis needs at least two points, got {n}");
    (0..n).map(|i| i as f64 / (n - 1) as f64).collect()
}

/// E(μ, r) on the n_μ × n_r grid of [`AlbedoTable`]: `surface(α)` builds the surface for each
/// column's α, or `None` where the lobe is the mirror (the caller's family decides what its lobe is
/// at α = 0, [`crate::model::ndf::Distribution::zero_limit`]), whose column is E = F(θo) (1 without
/// Fresnel); the μ = 0 row is the grazing limit of [`Microfacet::albedo`]. Cells are computed in parallel (rayon),
/// each value's quadrature sequentially; `progress` is told after each cell.
pub fn albedo_table<D, L>(
    n_mu: usize,
    n_r: usize,
    map: RoughnessMap,
    surface: impl Fn(f64) -> Option<Microfacet<D, L>> + Sync,
    fresnel: Fresnel,
    progress: Option<ProgressFn>,
) -> Result<AlbedoTable, QuadError>
where
    D: Density + Sync + Send,
    L: Lambda + Sync + Send,
{
    albedo_table_at(
        unit_grid(n_mu),
        unit_grid(n_r),
        map,
        surface,
        fresnel,
        progress,
    )
}

/// E(μ_i, r_j) as [`albedo_table`] computes it, on any axes: `mu` in [0, 1] (0 the grazing limit)
/// and `roughness` with map(r) in the family's domain or at its α = 0 limit — an engine's grid of
/// cell centres, say.
pub fn albedo_table_at<D, L>(
    mu: Vec<f64>,
    roughness: Vec<f64>,
    map: RoughnessMap,
    surface: impl Fn(f64) -> Option<Microfacet<D, L>> + Sync,
    fresnel: Fresnel,
    progress: Option<ProgressFn>,
) -> Result<AlbedoTable, QuadError>
where
    D: Density + Sync + Send,
    L: Lambda + Sync + Send,
{
    let [values] = grid_values(
        &mu,
        &roughness,
        map,
        &surface,
        [Weight::Curve(fresnel)],
        progress,
    )?;
    Ok(AlbedoTable {
        map,
        mu,
        roughness,
        values,
    })
}

/// A Fresnel weight inside an albedo ([`grid_values`], [`Microfacet::albedo_by`]): a curve
/// ([`Fresnel`]) or a weight tabulated on the basis grid ([`Smoothed`]).
#[derive(Clone, Copy)]
enum Weight<'a> {
    Curve(Fresnel<'a>),
    Tabulated(&'a Smoothed),
}

impl Weight<'_> {
    /// E(μo) of `surface` with this weight, or of the mirror (`None`): F(θo).
    fn value<D, L>(self, surface: Option<&Microfacet<D, L>>, mu_o: f64) -> Result<f64, QuadError>
    where
        D: Density,
        L: Lambda,
    {
        match (self, surface) {
            (Weight::Curve(fresnel), Some(surface)) => surface.albedo(mu_o, fresnel),
            (Weight::Curve(fresnel), None) => Ok(fresnel.map_or(1.0, |f| f.at(mu_o.acos()))),
            (Weight::Tabulated(table), Some(surface)) => surface.albedo_tabulated(mu_o, table),
            (Weight::Tabulated(table), None) => Ok(table.linear_at_cos(mu_o)),
        }
    }
}

/// The values of each of the `N` weights on the grid, computed cell by cell in parallel.
fn grid_values<D, L, const N: usize>(
    mu: &[f64],
    roughness: &[f64],
    map: RoughnessMap,
    surface: &(impl Fn(f64) -> Option<Microfacet<D, L>> + Sync),
    weights: [Weight; N],
    progress: Option<ProgressFn>,
) -> Result<[Vec<f64>; N], QuadError>
where
    D: Density + Sync + Send,
    L: Lambda + Sync + Send,
{
    let (n_mu, n_r) = (mu.len(), roughness.len());
    let surfaces: Vec<Option<Microfacet<D, L>>> = roughness
        .par_iter()
        .map(|&r| surface(map.alpha(r)))
        .collect();
    let total = n_mu * n_r;
    let done = AtomicUsize::new(0);
    let cells: Vec<[f64; N]> = (0..total)
        .into_par_iter()
        .map(|cell| {
            let (mu_o, column) = (mu[cell / n_r], &surfaces[cell % n_r]);
            let mut values = [0.0; N];
            for (value, weight) in values.iter_mut().zip(weights) {
                *value = weight.value(column.as_ref(), mu_o)?;
            }
            let finished = done.fetch_add(1, Ordering::Relaxed) + 1;
            if let Some(progress) = progress {
                progress(finished, total);
            }
            Ok(values)
        })
        .collect::<Result<_, QuadError>>()?;
    Ok(std::array::from_fn(|k| {
        cells.iter().map(|c| c[k]).collect()
    }))
}

/// E_avg(r_j) = 2 ∫₀¹ E(μ, α_j) μ dμ ([`average_albedo`]) at r_j = j/(n_r − 1), α_j = map(r_j), in
/// parallel over r; where `surface` gives `None`, the mirror (as for [`albedo_table`]),
/// 2 ∫₀¹ F(arccos μ) μ dμ ([`average_fresnel`]; 1 without Fresnel). `progress` is told after each r.
pub fn average_albedo_table<D, L>(
    n_r: usize,
    map: RoughnessMap,
    surface: impl Fn(f64) -> Option<Microfacet<D, L>> + Sync,
    fresnel: Fresnel,
    progress: Option<ProgressFn>,
) -> Result<Vec<f64>, QuadError>
where
    D: Density,
    L: Lambda,
{
    average_albedo_table_at(&unit_grid(n_r), map, surface, fresnel, progress)
}

/// E_avg(r) as [`average_albedo_table`] computes it, at any r of `roughness` (an engine's grid).
pub fn average_albedo_table_at<D, L>(
    roughness: &[f64],
    map: RoughnessMap,
    surface: impl Fn(f64) -> Option<Microfacet<D, L>> + Sync,
    fresnel: Fresnel,
    progress: Option<ProgressFn>,
) -> Result<Vec<f64>, QuadError>
where
    D: Density,
    L: Lambda,
{
    let done = AtomicUsize::new(0);
    let n_r = roughness.len();
    roughness
        .par_iter()
        .map(|&r| {
            let value = match surface(map.alpha(r)) {
                Some(surface) => average_albedo(&surface, fresnel)?,
                None => match fresnel {
                    Some(f) => f.average()?,
                    None => 1.0,
                },
            };
            let finished = done.fetch_add(1, Ordering::Relaxed) + 1;
            if let Some(progress) = progress {
                progress(finished, n_r);
            }
            Ok(value)
        })
        .collect()
}

/// The Belcour–Bati–Barla split-sum tables E_k(μ, r), k = 0…3: the albedo with F = b_k(θd), where
/// b_k is the basis of [`crate::model::fresnel::basis`] evaluated at c = cos θd by its linear
/// interpolation in c ([`crate::model::fresnel::basis::Basis::interpolate`]). E_0 = E (b₀ = 1). Since
/// F̂ = Σ c_k b_k is linear in c, E_F̂ = Σ c_k E_k. The basis functions b₂, b₃ change sign, so each
/// E_k (k ≥ 1) is computed as E[1 + b_k] − E (1 + b_k ≥ 0, as |b_k| ≤ 1), keeping every integral
/// positive; each tabulated weight enters through its smooth surrogate ([`Smoothed`]), which has
/// the interpolant's integral over every grid cell, at the surface's own tolerance. Grid, limits
/// and `progress` (cells of all four tables together) as for [`albedo_table`].
pub fn split_sum_tables<D, L>(
    n_mu: usize,
    n_r: usize,
    map: RoughnessMap,
    surface: impl Fn(f64) -> Option<Microfacet<D, L>> + Sync,
    progress: Option<ProgressFn>,
) -> Result<[AlbedoTable; 4], QuadError>
where
    D: Density + Sync + Send,
    L: Lambda + Sync + Send,
{
    let basis = basis();
    let shifted = |k: usize| Smoothed::new(basis.function(k).iter().map(|b| 1.0 + b).collect());
    let [b1, b2, b3] = [1, 2, 3].map(shifted);
    let [e, e1, e2, e3] = grid_values(
        &unit_grid(n_mu),
        &unit_grid(n_r),
        map,
        &surface,
        [
            Weight::Curve(None),
            Weight::Tabulated(&b1),
            Weight::Tabulated(&b2),
            Weight::Tabulated(&b3),
        ],
        progress,
    )?;
    let table = |values: Vec<f64>| AlbedoTable {
        map,
        mu: unit_grid(n_mu),
        roughness: unit_grid(n_r),
        values,
    };
    let unshift =
        |shifted: Vec<f64>| -> Vec<f64> { shifted.iter().zip(&e).map(|(s, e)| s - e).collect() };
    let (t1, t2, t3) = (unshift(e1), unshift(e2), unshift(e3));
    Ok([table(e), table(t1), table(t2), table(t3)])
}

/// Schlick's weight Fc = (1 − cos θd)⁵ of the split sum.
fn schlick_weight(theta_d: f64) -> f64 {
    (1.0 - theta_d.cos()).powi(5)
}

/// The split-sum pair renderers store per (μ, r) (Karis 2013; Filament's `DFV`): DFG1 = E_F with
/// F = 1 − Fc and DFG2 = E_F with F = Fc, Fc = (1 − cos θd)⁵, so that a Schlick Fresnel
/// F₀ + (F₉₀ − F₀) Fc integrates to F₀ DFG1 + F₉₀ DFG2 and DFG1 + DFG2 = E. Both weights are smooth
/// and non-negative, so each value is held to [`ALBEDO_QUAD_REL_TOL`] as E is. Grid, limits and
/// `progress` as for [`albedo_table_at`]; at a mirror column DFG1 = 1 − Fc(θo), DFG2 = Fc(θo).
pub fn dfg_tables<D, L>(
    mu: Vec<f64>,
    roughness: Vec<f64>,
    map: RoughnessMap,
    surface: impl Fn(f64) -> Option<Microfacet<D, L>> + Sync,
    progress: Option<ProgressFn>,
) -> Result<[AlbedoTable; 2], QuadError>
where
    D: Density + Sync + Send,
    L: Lambda + Sync + Send,
{
    let scale = |theta_d: f64| 1.0 - schlick_weight(theta_d);
    let (scale_table, weight_table) = (FresnelTable::of(&scale), FresnelTable::of(&schlick_weight));
    let [dfg1, dfg2] = grid_values(
        &mu,
        &roughness,
        map,
        &surface,
        [
            Weight::Curve(Some(FresnelFactor::new(&scale, scale_table.as_ref()))),
            Weight::Curve(Some(FresnelFactor::new(
                &schlick_weight,
                weight_table.as_ref(),
            ))),
        ],
        progress,
    )?;
    let table = |values| AlbedoTable {
        map,
        mu: mu.clone(),
        roughness: roughness.clone(),
        values,
    };
    Ok([table(dfg1), table(dfg2)])
}

impl fmt::Display for RoughnessMap {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

named! {
    /// The tables of a surface's albedo a renderer may store, by their names in `ndfplot albedo --table`.
    pub enum Table {
        /// E(μ, r) (or E_F with a Fresnel factor) and Turquin's factor 1/E.
        E = "e",
        /// E_avg(r), Kulla–Conty's 1/(π(1 − E_avg)) and, with a Fresnel factor, F_avg and F_ms.
        Average = "average",
        /// The split-sum tables E_0 … E_3.
        SplitSum = "split-sum",
        /// The split-sum pair DFG1, DFG2 of Schlick's Fresnel ([`dfg_tables`]).
        Dfg = "dfg",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::math::tolerance::ALBEDO_TOL;

    /// Trowbridge–Reitz D(θ) = α²/(π (sin²θ + α² cos²θ)²).
    fn ggx_d(alpha: f64) -> impl Fn(f64) -> f64 {
        move |theta: f64| {
            let (s, c) = theta.sin_cos();
            let k = s * s + alpha * alpha * c * c;
            alpha * alpha / (PI * k * k)
        }
    }

    /// Trowbridge–Reitz Λ = x/(2(√(1 + x) + 1)) at μ = cos θ, x = α² tan²θ = α² (1 − μ²)/μ².
    fn ggx_lambda(alpha: f64) -> impl Fn(f64) -> f64 {
        move |mu: f64| {
            let x = alpha * alpha * (1.0 - mu * mu) / (mu * mu);
            x / (2.0 * ((1.0 + x).sqrt() + 1.0))
        }
    }

    fn ggx(alpha: f64, g2: G2Model) -> Microfacet<impl Fn(f64) -> f64, impl Fn(f64) -> f64> {
        Microfacet::new(ggx_d(alpha), ggx_lambda(alpha), g2)
    }

    /// A lobe spanning fewer than SMOOTHED_CELLS cells in cos θd, weight k of the basis shifted by 1
    /// (as the split-sum tables take it) at α and μo: the surrogate plus the residual's albedo
    /// within ALBEDO_TOL of the interpolant L itself through nested adaptive Gauss–Kronrod at 1e-11
    /// (slow over L's kinks, but independent of the surrogate).
    fn assert_narrow_albedo_is_the_interpolants(k: usize, alpha: f64, mu: f64) {
        let weight = Smoothed::new(basis().function(k).iter().map(|b| 1.0 + b).collect());
        let surface = ggx(alpha, G2Model::HeightCorrelated);
        assert!(surface.cos_spread(mu) < SMOOTHED_CELLS * weight.cell());
        let value = surface.albedo_tabulated(mu, &weight).unwrap();
        let linear = |theta_d: f64| weight.linear_at_cos(theta_d.cos());
        let direct = Oblique::new(&surface, mu)
            .adaptive(Some(FresnelFactor::new(&linear, None)), 1e-11)
            .unwrap();
        assert!(
            (value - direct).abs() <= ALBEDO_TOL,
            "b{k} α = {alpha} μo = {mu}: {value} vs {direct}"
        );
    }

    #[test]
    fn a_narrow_lobe_gives_the_albedo_of_the_interpolant_itself() {
        // Grazing, oblique and near-normal views; at the first the former direct route (the
        // interpolant at 1e-8 per level) was off by 6.6e-7, at the second a lobe width in ψ taken
        // as w/b instead of w/√b by 1.2e-9.
        use rayon::prelude::*;
        let cases: [(usize, f64, f64); 5] = [
            (1, 0.016_649_323_621_227_886, 0.967_741_935_483_871),
            (3, 0.005, 0.9999),
            (1, 0.0015, 0.85),
            (2, 0.0015, 0.5),
            (3, 0.004, 0.15),
        ];
        cases
            .par_iter()
            .for_each(|&(k, alpha, mu)| assert_narrow_albedo_is_the_interpolants(k, alpha, mu));
    }

    #[test]
    #[ignore = "the direct reference takes ~12 s at μo = 0; run with --ignored"]
    fn a_narrow_lobe_gives_the_albedo_of_the_interpolant_itself_at_grazing_limit() {
        assert_narrow_albedo_is_the_interpolants(2, 0.002, 0.0);
    }

    #[test]
    fn uniform_lobe_at_normal_incidence_is_one_minus_ln_2() {
        let e = ggx(1.0, G2Model::HeightCorrelated)
            .albedo(1.0, None)
            .unwrap();
        assert!((e - (1.0 - 2f64.ln())).abs() <= 1e-12, "{e}");
    }

    #[test]
    fn a_tabulated_fresnel_factor_gives_the_albedo_of_the_curve() {
        // A conductor (gold-like), a dielectric and Schlick's: the fixed rules take F from its
        // table in cos θd; the same integral with F taken node by node from the curve.
        use crate::model::fresnel::{Fresnel as Curve, Ior};
        let curves = [
            Curve::Exact(Ior::eta_kappa(0.18, 3.4).unwrap()),
            Curve::Exact(Ior::eta_kappa(1.5, 0.0).unwrap()),
            Curve::schlick(0.04).unwrap(),
        ];
        for alpha in [0.05, 0.5, 2.0] {
            let surface = ggx(alpha, G2Model::HeightCorrelated);
            for curve in &curves {
                let f = |theta_d: f64| curve.eval(theta_d);
                let table = FresnelTable::of(&f);
                assert!(table.is_some(), "{curve:?}: no table");
                for mu in [0.05, 0.5, 0.9] {
                    let factor = FresnelFactor::new(&f, table.as_ref());
                    let tabulated = surface.albedo(mu, Some(factor)).unwrap();
                    let tolerance = surface.tolerance;
                    let direct = Oblique::new(&surface, mu)
                        .fixed(&NodeFresnel::Curve(&f), tolerance)
                        .unwrap();
                    assert!(
                        (tabulated - direct).abs() <= 1e-12,
                        "{curve:?} α = {alpha} μo = {mu}: {tabulated} vs {direct}"
                    );
                }
            }
        }
    }

    #[test]
    fn a_weight_of_cells_in_lanes_gives_the_albedo_of_its_surrogate_node_by_node() {
        // Glass's Belcour–Bati–Barla reconstruction and the basis function b₃, whose surrogate is
        // steepest: the fixed rules with the cells evaluated over each inner rule against the same
        // surrogate called at every node as a curve of θd (graded over four layers instead of one).
        use crate::model::fresnel::{Fresnel as Curve, Ior};
        let weights = [
            Curve::belcour(Ior::eta_kappa(1.5, 0.0).unwrap()),
            Curve::basis(3).unwrap(),
        ]
        .map(|curve| tabulated(&curve).unwrap());
        for alpha in [0.1, 0.5, 2.0] {
            let surface = ggx(alpha, G2Model::HeightCorrelated);
            for weight in &weights {
                let f = |theta_d: f64| weight.at(theta_d);
                for mu in [0.05, 0.5, 0.9] {
                    let oblique = Oblique::new(&surface, mu);
                    let tolerance = surface.tolerance;
                    let cells = oblique
                        .fixed(&NodeFresnel::Cells(weight), tolerance)
                        .unwrap();
                    let curve = oblique.fixed(&NodeFresnel::Curve(&f), tolerance).unwrap();
                    assert!(
                        (cells - curve).abs() <= 1e-11,
                        "α = {alpha} μo = {mu}: {cells} vs {curve}"
                    );
                }
            }
        }
    }

    #[test]
    fn median_slope_of_ggx_is_alpha() {
        for alpha in [1e-6, 0.01, 0.3, 1.0, 2.5] {
            let w = median_slope(ggx_d(alpha));
            assert!(w / alpha > 0.5 && w / alpha < 2.0, "α = {alpha}: {w}");
        }
    }

    #[test]
    fn oblique_view_joins_normal_incidence() {
        for alpha in [1e-3, 0.1, 1.0] {
            let surface = ggx(alpha, G2Model::HeightCorrelated);
            let normal = surface.albedo(1.0, None).unwrap();
            let near = surface.albedo(1.0 - 1e-13, None).unwrap();
            assert!(
                (normal - near).abs() <= ALBEDO_TOL,
                "α = {alpha}: {normal} vs {near}"
            );
        }
    }

    #[test]
    fn compensation_factors_follow_their_formulas() {
        assert_eq!(turquin_factor(1.0, 0.5), 2.0);
        assert_eq!(turquin_factor(0.0, 0.5), 1.0);
        assert_eq!(kulla_conty_fresnel(1.0, 0.7), 1.0);
        assert!((kulla_conty_lobe(0.5, 0.5, 0.5) - 0.5 / PI).abs() <= 1e-16);
        let schlick = |f0: f64| move |theta: f64| f0 + (1.0 - f0) * (1.0 - theta.cos()).powi(5);
        let f_avg = average_fresnel(schlick(0.04)).unwrap();
        assert!((f_avg - (0.04 + 0.96 / 21.0)).abs() <= 1e-14, "{f_avg}");
    }
}
