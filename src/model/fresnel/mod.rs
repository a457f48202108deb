//! Fresnel reflectance curves F(θ), θ the angle of incidence in [0, π/2]: validated material indices
//! and the curve enum the rest of the crate evaluates.
//!
//! - `exact`: the exact complex-index Fresnel of docs/maths.md (the normative form).
//! - `approx`: Schlick, Lazanyi–Schlick and the normalized Lazanyi term.
//! - `gulbrandsen`: the (r, g) ↔ (η, κ) parameterization.
//! - `basis`: the Belcour–Bati–Barla basis, its projection and the spectrum check.
//!
//! Constructors validate (docs/contracts.md "Parameter domains"); `eval` then never fails. Physical
//! curves (exact, Schlick, Lazanyi with `a` in range, the Lazanyi term) stay within [0, 1]; the
//! `belcour` reconstruction and the `basis` functions are tabulated approximations that may not.
//! Pure f64 code: no I/O.

pub mod approx;
pub mod basis;
pub mod exact;
pub mod gulbrandsen;

pub use basis::Coefficients;
pub use exact::{Incidence, Index};

use crate::model::domain::{Bound, DomainError, Param, check};

/// Largest accepted η and κ: |η̃|² ≤ 2e300 stays below f64::MAX ≈ 1.8e308, so η̃² and every
/// product the exact form takes (`exact`) are finite.
pub const INDEX_MAX: f64 = 1e150;

/// Smallest accepted η: η² ≥ 1e-300 stays a normal double (≥ 2.2e-308), so η̃² never underflows to 0
/// and the r_p denominator η̃² c + w never vanishes.
pub const ETA_MIN: f64 = 1e-150;

/// η's domain, [`ETA_MIN`] to [`INDEX_MAX`].
pub const ETA: Param = Param {
    name: "eta",
    symbol: "η",
    min: Bound::inclusive(
        ETA_MIN,
        "η² leaves the normal doubles and r_p's denominator may vanish",
    ),
    max: Bound::inclusive(INDEX_MAX, "|η̃|² overflows"),
};

/// κ's domain, 0 to [`INDEX_MAX`].
pub const KAPPA: Param = Param {
    name: "kappa",
    symbol: "κ",
    min: Bound::inclusive(0.0, "κ < 0 is a gain medium, not a reflector"),
    max: Bound::inclusive(INDEX_MAX, "|η̃|² overflows"),
};

/// Gulbrandsen's reflectivity r, a normal-incidence reflectance short of 1.
pub const REFLECTIVITY: Param = Param {
    name: "r",
    symbol: "r",
    min: Bound::inclusive(0.0, "a reflectance is not negative"),
    max: Bound::exclusive(1.0, "the map to (η, κ) is singular at r = 1"),
};

/// Gulbrandsen's edge tint g.
pub const EDGE_TINT: Param = Param {
    name: "g",
    symbol: "g",
    min: Bound::inclusive(0.0, "η = g n_min + (1 − g) n_max would pass n_max"),
    max: Bound::inclusive(1.0, "η = g n_min + (1 − g) n_max would pass n_min"),
};

/// Schlick's and Lazanyi's F₀, a reflectance.
pub const F0: Param = Param {
    name: "f0",
    symbol: "F₀",
    min: Bound::inclusive(0.0, "a reflectance is not negative"),
    max: Bound::inclusive(1.0, "a reflectance is at most 1"),
};

/// The index k of a basis function b_k, a whole number.
pub const BASIS_INDEX: Param = Param {
    name: "index",
    symbol: "index",
    min: Bound::inclusive(0.0, "b₀ is the first basis function"),
    max: Bound::inclusive(3.0, "the basis has four functions, b₀ … b₃"),
};

/// Every Fresnel parameter whose domain is fixed: what the constructors below check and whatever
/// shows a domain reads. Lazanyi's `a` has none of its own: its range depends on F₀
/// ([`approx::lazanyi_a_range`]).
pub const PARAMS: &[Param] = &[ETA, KAPPA, REFLECTIVITY, EDGE_TINT, F0, BASIS_INDEX];

/// `value` if `param` contains it, else the error stating its interval (`in [0, 1)`) after `lead`.
fn within(param: &Param, value: f64, lead: &str) -> Result<f64, DomainError> {
    if param.contains(value) {
        Ok(value)
    } else {
        Err(DomainError::new(
            param.name,
            value,
            format!("{lead}{}", param.interval()),
        ))
    }
}

/// How a material's complex index is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Ior {
    /// η̃ = η + iκ directly.
    EtaKappa {
        /// Real part η ∈ [1e-150, 1e150].
        eta: f64,
        /// Extinction coefficient κ ∈ [0, 1e150].
        kappa: f64,
    },
    /// Gulbrandsen's reflectivity r ∈ [0, 1) and edge tint g ∈ [0, 1]; with `g_remap` the tint used
    /// is ḡ = 1 − (1 − g)³.
    Gulbrandsen {
        /// Reflectivity r ∈ [0, 1), the normal-incidence reflectance.
        r: f64,
        /// Edge tint g ∈ [0, 1].
        g: f64,
        /// Use the notebook's remapped tint ḡ = 1 − (1 − g)³ instead of g.
        g_remap: bool,
    },
}

impl Ior {
    /// η̃ = η + iκ with η in [`ETA`] = [1e-150, 1e150] and κ in [`KAPPA`] = [0, 1e150].
    pub fn eta_kappa(eta: f64, kappa: f64) -> Result<Ior, DomainError> {
        let eta = within(&ETA, eta, "> 0, ")?;
        let kappa = within(&KAPPA, kappa, "≥ 0, ")?;
        Ok(Ior::EtaKappa { eta, kappa })
    }

    /// Gulbrandsen's (r, g) with r in [`REFLECTIVITY`] = [0, 1) (r = 1 is singular) and g in
    /// [`EDGE_TINT`] = [0, 1].
    pub fn gulbrandsen(r: f64, g: f64, g_remap: bool) -> Result<Ior, DomainError> {
        let r = within(&REFLECTIVITY, r, "")?;
        let g = within(&EDGE_TINT, g, "")?;
        Ok(Ior::Gulbrandsen { r, g, g_remap })
    }

    /// The complex index with η − 1 (`exact::Index`): η̃ itself, or Gulbrandsen's map
    /// (`gulbrandsen::index`) of (r, g) or of (r, ḡ).
    pub fn index(&self) -> Index {
        match *self {
            Ior::EtaKappa { eta, kappa } => Index::new(eta, kappa),
            Ior::Gulbrandsen { r, g, g_remap } => {
                let g = if g_remap {
                    gulbrandsen::remap_edge_tint(g)
                } else {
                    g
                };
                gulbrandsen::index(r, g)
            }
        }
    }

    /// The complex index (η, κ) of [`Ior::index`].
    pub fn complex(&self) -> (f64, f64) {
        let index = self.index();
        (index.eta, index.kappa)
    }
}

/// Where Schlick's F₀ comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SchlickF0 {
    /// F₀ given directly, in [0, 1] (validated by [`Fresnel::schlick`]).
    F0(f64),
    /// F₀ = F(θ = 0) of the exact Fresnel for this index, ((η − 1)² + κ²)/((η + 1)² + κ²).
    Ior(Ior),
}

/// A Fresnel reflectance curve F(θ). Its variants, without their values, are the [`FresnelModel`]s of
/// the curve format, named in snake case (`LazanyiTerm` is `"lazanyi_term"`).
#[derive(Debug, Clone, PartialEq)]
pub enum Fresnel {
    /// The exact complex-index Fresnel (`exact::reflectance`).
    Exact(Ior),
    /// Schlick: F₀ + (1 − F₀)(1 − cos θ)⁵.
    Schlick(SchlickF0),
    /// Lazanyi–Schlick: F₀ + (1 − F₀)(1 − c)⁵ − a c (1 − c)⁶; build with [`Fresnel::lazanyi`].
    Lazanyi {
        /// F₀ ∈ [0, 1].
        f0: f64,
        /// Weight of the c (1 − c)⁶ term, within `approx::lazanyi_a_range(f0)`.
        a: f64,
    },
    /// The normalized Lazanyi term c (1 − c)⁶ / ((1/7)(6/7)⁶).
    LazanyiTerm,
    /// The four-term Belcour–Bati–Barla reconstruction of this material, with its coefficients
    /// (computed at construction); build with [`Fresnel::belcour`].
    Belcour(Ior, Coefficients),
    /// Basis function b_k, k ∈ 0..=3; build with [`Fresnel::basis`].
    Basis(usize),
    /// The exact Fresnel normalized as the basis training curves are: (F − F₀)/(1 − F₀), formed
    /// with its factor sin⁴θ explicit, or as 1 − (1 − F)/(1 − F₀) near grazing incidence where that
    /// rounds less (`exact::normalized_reflectance`): no cancellation at θ → 0.
    Normalized(Ior),
}

/// A Fresnel model of the curve format: a [`Fresnel`] variant without its values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FresnelModel {
    /// See [`Fresnel::Exact`].
    Exact,
    /// See [`Fresnel::Schlick`].
    Schlick,
    /// See [`Fresnel::Lazanyi`].
    Lazanyi,
    /// See [`Fresnel::LazanyiTerm`].
    LazanyiTerm,
    /// See [`Fresnel::Belcour`].
    Belcour,
    /// See [`Fresnel::Basis`].
    Basis,
    /// See [`Fresnel::Normalized`].
    Normalized,
}

impl FresnelModel {
    /// Every Fresnel model with its canonical name, in the order of [`Fresnel`]'s variants.
    const NAMED: [(FresnelModel, &'static str); 7] = [
        (FresnelModel::Exact, "exact"),
        (FresnelModel::Schlick, "schlick"),
        (FresnelModel::Lazanyi, "lazanyi"),
        (FresnelModel::LazanyiTerm, "lazanyi_term"),
        (FresnelModel::Belcour, "belcour"),
        (FresnelModel::Basis, "basis"),
        (FresnelModel::Normalized, "normalized"),
    ];

    /// Every Fresnel model, in the order of [`Fresnel`]'s variants.
    pub fn all() -> impl Iterator<Item = FresnelModel> {
        Self::NAMED.into_iter().map(|(model, _)| model)
    }

    /// Canonical name in curve JSON (`"exact"`, `"lazanyi_term"`).
    pub fn name(self) -> &'static str {
        Self::NAMED[self as usize].1
    }
}

impl From<&Fresnel> for FresnelModel {
    fn from(fresnel: &Fresnel) -> FresnelModel {
        match fresnel {
            Fresnel::Exact(_) => FresnelModel::Exact,
            Fresnel::Schlick(_) => FresnelModel::Schlick,
            Fresnel::Lazanyi { .. } => FresnelModel::Lazanyi,
            Fresnel::LazanyiTerm => FresnelModel::LazanyiTerm,
            Fresnel::Belcour(..) => FresnelModel::Belcour,
            Fresnel::Basis(_) => FresnelModel::Basis,
            Fresnel::Normalized(_) => FresnelModel::Normalized,
        }
    }
}

impl Fresnel {
    /// Schlick with a given F₀ ∈ [0, 1].
    pub fn schlick(f0: f64) -> Result<Fresnel, DomainError> {
        let f0 = within(&F0, f0, "")?;
        Ok(Fresnel::Schlick(SchlickF0::F0(f0)))
    }

    /// Lazanyi–Schlick with F₀ ∈ [0, 1] and a ∈ [−5 (1 − F₀), a_max(F₀)] (`approx::lazanyi_a_range`):
    /// exactly the `a` for which F stays within [0, 1] at every θ (a_max(0) = 4, a_max(1) ≈ 17.65).
    pub fn lazanyi(f0: f64, a: f64) -> Result<Fresnel, DomainError> {
        let f0 = within(&F0, f0, "")?;
        let (a_min, a_max) = approx::lazanyi_a_range(f0);
        let expected = format!("in [{a_min:?}, {a_max:?}] for f0 = {f0:?}, so that 0 ≤ F ≤ 1");
        let a = check("a", a, |v| (a_min..=a_max).contains(&v), &expected)?;
        Ok(Fresnel::Lazanyi { f0, a })
    }

    /// The Belcour–Bati–Barla reconstruction of `ior`, its coefficients computed now (`basis::coeffs`;
    /// the basis itself is computed on first use).
    pub fn belcour(ior: Ior) -> Fresnel {
        Fresnel::Belcour(ior, basis::coeffs(ior.index()))
    }

    /// Basis function b_k, `index` in [`BASIS_INDEX`] = 0..=3.
    pub fn basis(index: usize) -> Result<Fresnel, DomainError> {
        if BASIS_INDEX.contains(index as f64) {
            Ok(Fresnel::Basis(index))
        } else {
            Err(DomainError::new("index", index as f64, "0, 1, 2 or 3"))
        }
    }

    /// F(θ) at the angle of incidence θ ∈ [0, π/2]. Tabulated curves (`belcour`, `basis`) are
    /// interpolated linearly in cos θ between the 1000 grid nodes and reproduce a node to ~1e-14.
    pub fn eval(&self, theta: f64) -> f64 {
        match self {
            Fresnel::Exact(ior) => exact::reflectance(Incidence::from_theta(theta), ior.index()),
            Fresnel::Schlick(SchlickF0::F0(f0)) => approx::schlick(*f0, theta),
            Fresnel::Schlick(SchlickF0::Ior(ior)) => {
                approx::schlick(exact::reflectance(Incidence::NORMAL, ior.index()), theta)
            }
            Fresnel::Lazanyi { f0, a } => approx::lazanyi(*f0, *a, theta),
            Fresnel::LazanyiTerm => approx::lazanyi_term(theta),
            Fresnel::Belcour(_, coefficients) => coefficients.interpolate(theta.cos()),
            Fresnel::Basis(k) => basis::basis().interpolate(*k, theta.cos()),
            Fresnel::Normalized(ior) => {
                exact::normalized_reflectance(Incidence::from_theta(theta), ior.index())
            }
        }
    }

    /// The curve's canonical model name: "exact", "schlick", "lazanyi", "lazanyi_term", "belcour", "basis" or "normalized".
    pub fn name(&self) -> &'static str {
        match self {
            Fresnel::Exact(_) => "exact",
            Fresnel::Schlick(_) => "schlick",
            Fresnel::Lazanyi { .. } => "lazanyi",
            Fresnel::LazanyiTerm => "lazanyi_term",
            Fresnel::Belcour(..) => "belcour",
            Fresnel::Basis(_) => "basis",
            Fresnel::Normalized(_) => "normalized",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each model's name is looked up by its position: the table lists them in declaration order,
    /// under distinct snake-case names.
    #[test]
    fn models_are_named_in_declaration_order() {
        let named = FresnelModel::NAMED;
        for (position, (model, name)) in named.iter().enumerate() {
            assert_eq!(*model as usize, position, "{name}");
            assert_eq!(model.name(), *name);
            assert!(
                name.chars().all(|c| c.is_ascii_lowercase() || c == '_'),
                "{name}"
            );
        }
        let distinct: std::collections::HashSet<_> = named.iter().map(|(_, name)| name).collect();
        assert_eq!(distinct.len(), named.len());
        assert_eq!(
            FresnelModel::from(&Fresnel::LazanyiTerm).name(),
            "lazanyi_term"
        );
    }
}
