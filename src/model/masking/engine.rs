//! The G1 a renderer uses for an NDF, and what it does to energy (docs/maths.md "Masking–shadowing and albedo";
//! research: Walter et al. 2007, Heitz 2014).
//!
//! Engines rarely evaluate the exact Smith G1 of the NDF they shade with: Mitsuba 3, Cycles and bbm use Walter
//! 2007's rational fit of the Beckmann G1, and bbm shades Phong through its Beckmann-equivalent roughness.
//! [`G1Model`] names the three choices; its weak white furnace value W(θo) = G1_used(θo) (1 + Λ_exact(θo))
//! is 1 for exact Smith and measures the energy an approximation gains or loses at θo.

use crate::model::names::named;
use crate::model::ndf::{Family, Ndf, beckmann};
use std::fmt;

named! {
    /// Which G1(θo) an engine uses for an NDF.
    pub enum G1Model {
        /// G1 = 1/(1 + Λ(θo)) with the family's exact Λ ([`Ndf::lambda`]).
        Smith = "smith",
        /// Walter 2007's rational Beckmann G1 ([`walter_rational_g1`]) at a = cot θo/α, α the family's
        /// Beckmann-equivalent roughness ([`Ndf::beckmann_equivalent_alpha`]): Mitsuba 3, Cycles, bbm.
        WalterRational = "walter-rational",
        /// The exact Smith G1 of the Beckmann lobe of the family's Beckmann-equivalent roughness.
        BeckmannEquivalent = "beckmann-equivalent",
    }
}

impl G1Model {
    /// G1(θo) ∈ [0, 1] (Walter's rational reaches 1.0000613) for θo ∈ [0, π/2] as this model computes it
    /// for `ndf`; an error for the two Beckmann-based models when the family has no Beckmann equivalent.
    pub fn g1(self, ndf: &Ndf, theta_o: f64) -> Result<f64, NoBeckmannEquivalent> {
        Ok(match self {
            G1Model::Smith => super::g1(ndf.lambda(theta_o)),
            G1Model::WalterRational => {
                let alpha = self.equivalent_alpha(ndf)?;
                walter_rational_g1(1.0 / (alpha * theta_o.tan()))
            }
            G1Model::BeckmannEquivalent => {
                let alpha = self.equivalent_alpha(ndf)?;
                super::g1(beckmann::smith_lambda(alpha, theta_o))
            }
        })
    }

    /// The weak white furnace W(θo) = G1_used(θo) (1 + Λ_exact(θo)) (Heitz 2014): ∫ G1 ⟨ωo, m⟩⁺ D dm / cos θo
    /// for this model's G1 and `ndf`'s exact Λ. 1 exactly for [`G1Model::Smith`]; above 1 where the model's G1
    /// overestimates (creates energy). Where Λ_exact = +∞, W is taken as 1 if G1_used is 0 too.
    pub fn weak_furnace(self, ndf: &Ndf, theta_o: f64) -> Result<f64, NoBeckmannEquivalent> {
        if self == G1Model::Smith {
            return Ok(1.0);
        }
        let used = self.g1(ndf, theta_o)?;
        let lambda = ndf.lambda(theta_o);
        Ok(if used == 0.0 {
            1.0
        } else {
            used * (1.0 + lambda)
        })
    }

    fn equivalent_alpha(self, ndf: &Ndf) -> Result<f64, NoBeckmannEquivalent> {
        ndf.beckmann_equivalent_alpha().ok_or(NoBeckmannEquivalent {
            family: ndf.family(),
            model: self,
        })
    }
}

impl fmt::Display for G1Model {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A Beckmann-based [`G1Model`] asked of a family with no Beckmann-equivalent roughness (ABC, SGD, GTR).
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error(
    "{} has no Beckmann-equivalent roughness, so the \"{model}\" G1 does not apply to it; use \"smith\"",
    family.title()
)]
pub struct NoBeckmannEquivalent {
    /// The family asked for.
    pub family: Family,
    /// The model asked for.
    pub model: G1Model,
}

/// Above this a, Walter's rational G1 is 1 (its own cut-off).
const WALTER_RATIONAL_MAX_A: f64 = 1.6;

/// Walter 2007's rational fit of the Beckmann Smith G1 at a = cot θo/α_b (Mitsuba 3, Cycles, bbm):
/// (3.535a + 2.181a²)/(1 + 2.276a + 2.577a²) for a < 1.6, else 1. Slightly above 1 just below the cut-off
/// (up to 1.0000613 at a ≈ 1.589); 0 at a = 0 (grazing).
pub fn walter_rational_g1(a: f64) -> f64 {
    if a < WALTER_RATIONAL_MAX_A {
        (3.535 * a + 2.181 * a * a) / (1.0 + 2.276 * a + 2.577 * a * a)
    } else {
        1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ndf::{Phong, TrowbridgeReitz};

    #[test]
    fn names_round_trip() {
        for (name, model) in G1Model::NAMES {
            assert_eq!(model.name(), name);
            assert_eq!(G1Model::from_name(name), Some(model));
        }
        assert_eq!(G1Model::from_name("separable"), None);
    }

    /// next-raise §1.4: Phong n = 20 through the rational at a = √(n/2 + 1) cot θo.
    #[test]
    fn phong_through_walters_rational_gains_energy_at_grazing() {
        let ndf = Ndf::Phong(Phong::new(20.0).unwrap());
        for (degrees, want) in [(75.0, 1.0076), (85.0, 1.0221), (89.0, 1.0340)] {
            let w = G1Model::WalterRational
                .weak_furnace(&ndf, f64::to_radians(degrees))
                .unwrap();
            assert!((w - want).abs() <= 5e-5, "{degrees}°: W = {w}, want {want}");
        }
        assert_eq!(G1Model::Smith.weak_furnace(&ndf, 1.0), Ok(1.0));
    }

    /// next-raise §1.3: the rational exceeds 1, by at most 6.13e-5 near a ≈ 1.589.
    #[test]
    fn walters_rational_exceeds_one_below_its_cut_off() {
        let max = (0..=16000)
            .map(|i| walter_rational_g1(f64::from(i) * 1e-4))
            .fold(0.0, f64::max);
        assert!((max - 1.0000613).abs() <= 1e-7, "max {max}");
        assert_eq!(walter_rational_g1(0.0), 0.0);
        assert_eq!(walter_rational_g1(1.6), 1.0);
    }

    #[test]
    fn families_without_an_equivalent_are_refused_clearly() {
        let abc = Family::Abc.build(Family::Abc.example()).unwrap();
        let err = G1Model::WalterRational.g1(&abc, 1.0).unwrap_err();
        assert_eq!(
            err.to_string(),
            "ABC has no Beckmann-equivalent roughness, so the \"walter-rational\" G1 does not apply to it; use \"smith\""
        );
        assert!(G1Model::Smith.g1(&abc, 1.0).is_ok());
        let ggx = Ndf::TrowbridgeReitz(TrowbridgeReitz::new(0.3).unwrap());
        assert_eq!(ggx.beckmann_equivalent_alpha(), Some(0.3));
    }
}
