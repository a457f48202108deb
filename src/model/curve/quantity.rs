//! What a curve of an NDF shows besides D(θ): a quantity of the microfacet model built on it
//! (docs/contracts.md "Quantities of an NDF"; docs/maths.md "Masking–shadowing and albedo"), and
//! its evaluation, which defers to [`crate::model::masking`] and [`crate::model::albedo`]. For every
//! quantity but D, θ is the view angle θo. The keys that name them in curve JSON are the spec's
//! (`crate::spec::quantity`).

use super::Curve;
use crate::model::albedo;
use crate::model::masking::{self, G1Model, G2Model};
use crate::model::ndf::Ndf;
use std::sync::OnceLock;

/// The quantity names in curve JSON, the default first.
pub const NAMES: [&str; 6] = ["d", "lambda", "g1", "g2", "albedo", "furnace"];

/// The light's angle of a G2 curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ThetaI {
    /// θi = θo: the light in the view direction (a backscattering configuration).
    Same,
    /// A fixed θi in [0, π/2], radians.
    Fixed(f64),
}

/// A quantity of an NDF other than D itself, whose nested Fresnel curve (an albedo's) is `F`: a
/// [`CurveSpec`] as a spec describes it, a [`Curve`] once resolved.
#[derive(Debug, Clone, PartialEq)]
pub enum Quantity<F> {
    /// Smith Λ(θo).
    Lambda,
    /// Smith masking G1(θo) = 1/(1 + Λ(θo)).
    G1,
    /// Masking–shadowing G2(θo, θi) of the model.
    G2 {
        /// How masking and shadowing combine.
        model: G2Model,
        /// The light's angle.
        theta_i: ThetaI,
    },
    /// The directional albedo E(μo) of the single-scattering microfacet BRDF
    /// f = F D G2 / (4 cos θo cos θi), at μo = cos θo.
    Albedo {
        /// The G2 of the BRDF.
        model: G2Model,
        /// F(θd) at the angle θd between the view and the half vector; F = 1 without it.
        fresnel: Option<Box<F>>,
    },
    /// The weak white furnace W(θo) = G1_used(θo) (1 + Λ(θo)): 1 for exact Smith masking.
    Furnace {
        /// The G1 audited.
        g1: G1Model,
    },
}

impl<F> Quantity<F> {
    /// The quantity's name in curve JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Quantity::Lambda => "lambda",
            Quantity::G1 => "g1",
            Quantity::G2 { .. } => "g2",
            Quantity::Albedo { .. } => "albedo",
            Quantity::Furnace { .. } => "furnace",
        }
    }

    /// The axis label of the quantity, math text.
    pub fn axis_label(&self) -> &'static str {
        match self {
            Quantity::Lambda => "Λ(θ_o)",
            Quantity::G1 => "G_1(θ_o)",
            Quantity::G2 { .. } => "G_2(θ_o, θ_i)",
            Quantity::Albedo { .. } => "E(cos θ_o)",
            Quantity::Furnace { .. } => "W(θ_o) = G_1(θ_o) (1 + Λ(θ_o))",
        }
    }

    /// The same quantity with its Fresnel curve mapped by `map` (a spec's curve resolved into a
    /// [`Curve`], say); the first error `map` returns.
    pub fn map_fresnel<G, E>(&self, map: impl Fn(&F) -> Result<G, E>) -> Result<Quantity<G>, E> {
        Ok(match self {
            Quantity::Lambda => Quantity::Lambda,
            Quantity::G1 => Quantity::G1,
            Quantity::G2 { model, theta_i } => Quantity::G2 {
                model: *model,
                theta_i: *theta_i,
            },
            Quantity::Albedo { model, fresnel } => Quantity::Albedo {
                model: *model,
                fresnel: match fresnel {
                    Some(f) => Some(Box::new(map(f)?)),
                    None => None,
                },
            },
            Quantity::Furnace { g1 } => Quantity::Furnace { g1: *g1 },
        })
    }
}

/// What a quantity's values share, found on first use and kept (a curve's): an albedo's
/// [`albedo::SurfaceParts`] and its Fresnel factor's table ([`fresnel_table`]). Equality ignores
/// it (it follows from the curve).
#[derive(Debug, Clone, Default)]
pub struct Prepared(OnceLock<Shared>);

/// The contents of [`Prepared`].
#[derive(Debug, Clone)]
struct Shared {
    parts: albedo::SurfaceParts,
    table: Option<albedo::FresnelTable>,
}

impl Prepared {
    /// The surface parts of `ndf` and the table of `fresnel`, found on the first call (for the
    /// albedo of `ndf` with `fresnel`, the same on every call).
    fn of(&self, ndf: &Ndf, fresnel: Option<&Curve>) -> &Shared {
        self.0.get_or_init(|| Shared {
            parts: albedo::SurfaceParts::of(ndf),
            table: fresnel.and_then(fresnel_table),
        })
    }
}

/// The table of `curve` as a Fresnel factor inside an albedo ([`albedo::FresnelFactor`]): the
/// smooth surrogate of a curve tabulated on the basis grid (a Belcour–Bati–Barla reconstruction or
/// basis function, [`albedo::tabulated`]), else the Chebyshev table of the curve where it converges.
pub fn fresnel_table(curve: &Curve) -> Option<albedo::FresnelTable> {
    let surrogate = match curve {
        Curve::Fresnel(model) => albedo::tabulated(model),
        _ => None,
    };
    match surrogate {
        Some(surrogate) => Some(albedo::FresnelTable::cells(surrogate)),
        None => albedo::FresnelTable::of(&|t| curve.eval(t)),
    }
}

impl PartialEq for Prepared {
    fn eq(&self, _: &Prepared) -> bool {
        true
    }
}

impl Quantity<Curve> {
    /// The quantity of `ndf` at the view angle θo ∈ [0, π/2], with what its values share in
    /// `prepared` (filled on first use: the same bits as a fresh one).
    pub fn eval(&self, ndf: &Ndf, prepared: &Prepared, theta_o: f64) -> f64 {
        match self {
            Quantity::Lambda => ndf.lambda(theta_o),
            Quantity::G1 => masking::g1(ndf.lambda(theta_o)),
            Quantity::G2 { model, theta_i } => {
                let theta_i = match theta_i {
                    ThetaI::Same => theta_o,
                    ThetaI::Fixed(theta_i) => *theta_i,
                };
                model.g2(ndf.lambda(theta_o), ndf.lambda(theta_i))
            }
            // A quadrature that fails, or a G1 the family lacks (refused when the spec is read),
            // gives NaN, which evaluation reports as a non-finite value of the curve.
            Quantity::Albedo { model, fresnel } => {
                let shared = prepared.of(ndf, fresnel.as_deref());
                let surface = albedo::surface_with(ndf, &shared.parts, *model);
                let mu_o = theta_o.cos().clamp(0.0, 1.0);
                let result = match fresnel.as_deref() {
                    Some(f) => {
                        let curve = |t| f.eval(t);
                        let factor = albedo::FresnelFactor::new(&curve, shared.table.as_ref());
                        surface.albedo(mu_o, Some(factor))
                    }
                    None => surface.albedo(mu_o, None),
                };
                result.unwrap_or(f64::NAN)
            }
            Quantity::Furnace { g1 } => g1.weak_furnace(ndf, theta_o).unwrap_or(f64::NAN),
        }
    }
}

/// Absolute accuracy of the E_avg a label shows (to four decimals): far looser than the curve's own
/// values, as the label rounds it, and ~100× faster to integrate.
const LABEL_E_AVG_TOL: f64 = 1e-7;

impl Quantity<Curve> {
    /// For an albedo, E_avg = 2 ∫₀¹ E(μ) μ dμ of `ndf` with this albedo's G2 and Fresnel, to
    /// [`LABEL_E_AVG_TOL`], on the surface parts in `prepared` (the curve's, found here if not yet);
    /// `None` for other quantities or when the quadrature fails.
    pub fn label_average(&self, ndf: &Ndf, prepared: &Prepared) -> Option<f64> {
        let Quantity::Albedo { model, fresnel } = self else {
            return None;
        };
        let shared = prepared.of(ndf, fresnel.as_deref());
        let surface =
            albedo::surface_with(ndf, &shared.parts, *model).with_tolerance(LABEL_E_AVG_TOL);
        let result = match fresnel {
            Some(f) => {
                let curve = |t| f.eval(t);
                let factor = albedo::FresnelFactor::new(&curve, shared.table.as_ref());
                albedo::average_albedo(&surface, Some(factor))
            }
            None => albedo::average_albedo(&surface, None),
        };
        result.ok()
    }
}
