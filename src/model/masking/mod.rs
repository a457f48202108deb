//! Smith masking–shadowing (docs/maths.md "Masking–shadowing and albedo"; Heitz 2014, JCGT 3(2)).
//!
//! For an isotropic NDF D normalized over projected area, the Smith masking of a view direction at
//! angle θo from the normal is G1(θo) = 1/(1 + Λ(θo)), where Λ is the family's auxiliary function
//! (each family computes its own; see [`Ndf::lambda`]). Masking and shadowing together, for a view at
//! θo and a light at θi, follow one of two [`G2Model`]s. Everything here is pure f64 code.
//!
//! - [`lambda_by_integral`]: Λ of any NDF by docs/maths.md's 1D integral ([`lambda_integral`], which lives with the
//!   families that take it as their route).
//! - [`engine`]: the G1 renderers use ([`G1Model`]: exact Smith, Walter's rational, the Beckmann-equivalent
//!   Smith) and the weak white furnace value of each.
//! - [`table`]: Λ of one surface tabulated once (a Chebyshev table of G1), for the albedo's integrals.
//! - [`projected_area`]: the front-facing projected area, computed apart from Λ, to audit Λ against.

pub mod engine;
pub mod projected_area;
pub mod table;

pub use engine::{G1Model, NoBeckmannEquivalent, walter_rational_g1};
pub use projected_area::{front_projected_area, smith_furnace};
pub use table::LambdaTable;

use crate::model::names::named;
use crate::model::ndf::Ndf;
use crate::model::ndf::lambda_integral::lambda_integral;
use std::fmt;

/// Λ(θo) of `ndf` by the generic 1D integral ([`lambda_integral`]), whatever route its family takes in
/// [`Ndf::lambda`]: the independent check of the closed forms, and the route a benchmark compares them with.
pub fn lambda_by_integral(ndf: &Ndf, theta_o: f64) -> f64 {
    lambda_integral(ndf, theta_o)
}

named! {
    /// How masking (view) and shadowing (light) combine into G2.
    pub enum G2Model {
        /// G2 = 1/(1 + Λ(θo) + Λ(θi)) (Heitz 2014 eq. 99): a microfacet high on the surface is likelier to
        /// be both visible and lit. pbrt-v4, Cycles, Filament and MaterialX use it.
        HeightCorrelated = "height-correlated",
        /// G2 = G1(θo) G1(θi): masking and shadowing independent (Mitsuba 3's `G`).
        Separable = "separable",
    }
}

impl G2Model {
    /// G2 from Λ(θo) and Λ(θi), both ≥ 0 (possibly +∞ at grazing, where G2 is 0).
    #[inline]
    pub fn g2(self, lambda_o: f64, lambda_i: f64) -> f64 {
        match self {
            G2Model::HeightCorrelated => 1.0 / (1.0 + lambda_o + lambda_i),
            G2Model::Separable => g1(lambda_o) * g1(lambda_i),
        }
    }
}

impl fmt::Display for G2Model {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Smith G1 = 1/(1 + Λ) from Λ ≥ 0: in [0, 1], 0 for Λ = +∞.
#[inline]
pub fn g1(lambda: f64) -> f64 {
    1.0 / (1.0 + lambda)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn g2_models_combine_lambda_as_heitz_states() {
        // Λo = 1, Λi = 3: height-correlated 1/5, separable (1/2)(1/4).
        assert_eq!(G2Model::HeightCorrelated.g2(1.0, 3.0), 0.2);
        assert_eq!(G2Model::Separable.g2(1.0, 3.0), 0.125);
        // No masking at all: both models give 1; grazing (Λ = ∞) gives 0.
        for model in [G2Model::HeightCorrelated, G2Model::Separable] {
            assert_eq!(model.g2(0.0, 0.0), 1.0);
            assert_eq!(model.g2(f64::INFINITY, 0.5), 0.0);
            assert_eq!(G2Model::from_name(model.name()), Some(model));
        }
        assert_eq!(G2Model::from_name("smith"), None);
    }
}
