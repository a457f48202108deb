//! The microfacet normal distribution functions of docs/maths.md: the [`Distribution`] trait each family
//! file implements, and the one registry ([`families!`]) from which [`Family`], [`Ndf`], name lookup
//! and dispatch are generated.
//!
//! Every NDF is normalized over projected area: 2π ∫₀^{π/2} D(θ) sin θ cos θ dθ = 1.
//! Constructors validate their parameters against the domains their family states ([`Param`]) and
//! compute normalization constants once; `eval` (one θ) and `eval_many` (a block of θ, in vector lanes
//! where the family's D is branch-free, [`crate::model::math::elementary`]) are pure f64 code with no
//! allocation that give the same bits: the one evaluation path of every output. Adding a family: one file implementing [`Distribution`], one
//! registry line below, one reference-data file, one row in docs/reference.md's table of curves.

pub mod lambda_integral;

use crate::model::domain::{DomainError, Param};
#[cfg(doc)]
use crate::model::math::elementary::{Lanewise, map_lanes};
use std::fmt;

/// D(θm) as the integrals over it take it (normalized over projected area): any `Fn(f64) -> f64`
/// of θm, an [`Ndf`] (held or borrowed), or a family's [`Distribution`] ([`FamilyDensity`]), the last two also
/// evaluating a block of θm in vector lanes ([`Distribution::eval_many`]).
pub trait Density {
    /// D at θm.
    fn at(&self, theta: f64) -> f64;

    /// `out[k]` = D(`thetas[k]`), the values of [`Density::at`] (lengths equal); one at a time
    /// unless the implementation has a block path.
    fn at_many(&self, thetas: &[f64], out: &mut [f64]) {
        for (out, &theta) in out.iter_mut().zip(thetas) {
            *out = self.at(theta);
        }
    }
}

impl<F: Fn(f64) -> f64> Density for F {
    #[inline(always)]
    fn at(&self, theta: f64) -> f64 {
        self(theta)
    }
}

/// A family's D as a [`Density`]: [`Distribution::eval`] at a point, [`Distribution::eval_many`]
/// for a block (the same bits).
pub struct FamilyDensity<'a, T>(pub &'a T);

impl<T: Distribution> Density for FamilyDensity<'_, T> {
    #[inline]
    fn at(&self, theta: f64) -> f64 {
        self.0.eval(theta)
    }

    fn at_many(&self, thetas: &[f64], out: &mut [f64]) {
        self.0.eval_many(thetas, out);
    }
}

impl Density for Ndf {
    #[inline]
    fn at(&self, theta: f64) -> f64 {
        self.eval(theta)
    }

    fn at_many(&self, thetas: &[f64], out: &mut [f64]) {
        self.eval_many(thetas, out);
    }
}

/// A borrowed [`Ndf`] as the [`Density`] it is.
impl Density for &Ndf {
    #[inline]
    fn at(&self, theta: f64) -> f64 {
        (*self).at(theta)
    }

    fn at_many(&self, thetas: &[f64], out: &mut [f64]) {
        (*self).at_many(thetas, out);
    }
}

/// An NDF family, as one file implements it: its names, its parameters with their domains, its
/// colour, a validating constructor and D(θ).
pub trait Distribution: Sized + Clone + fmt::Debug + PartialEq {
    /// The canonical name in curve JSON (`"ndf": "<name>"`).
    const NAME: &'static str;
    /// The family's name in prose and on figures (`Torrance–Sparrow`).
    const TITLE: &'static str;
    /// Other accepted names (`ggx` for Trowbridge–Reitz).
    const ALIASES: &'static [&'static str] = &[];
    /// The parameters in docs/maths.md's order, each with its domain and the reason for each bound: the only
    /// statement of the bounds, which the constructor checks and everything else reads.
    const PARAMS: &'static [Param];
    /// Written before the parameter symbols of an automatic legend label when they alone do not name
    /// the family (ABC and SGD share a₁, a₂; GTR's α and γ are generic): `"ABC"` gives `ABC a₁ = 10`.
    const LEGEND_PREFIX: Option<&'static str> = None;
    /// The family's colour, as 0xRRGGBB: the notebook's hue, apart from every other family's in
    /// normal vision and under deuteranopia (`spec::look` tests it).
    const COLOUR: u32;
    /// Whether [`lambda`](Self::lambda) is a closed form; otherwise it is the generic quadrature
    /// ([`crate::model::ndf::lambda_integral::lambda_integral`]).
    const LAMBDA_CLOSED_FORM: bool = false;
    /// A representative parameter set in [`PARAMS`](Self::PARAMS) order, the one the numpy peer times:
    /// `ndfplot bench` and `cargo bench --bench eval` measure it.
    const EXAMPLE: &'static [f64];

    /// The validated NDF of `params` (in [`PARAMS`](Self::PARAMS) order, as many), or the error naming
    /// the first value outside its domain.
    fn from_params(params: &[f64]) -> Result<Self, DomainError>;

    /// D(θ) for θ ∈ [0, π/2], normalized over projected area.
    fn eval(&self, theta: f64) -> f64;

    /// `out[i]` = D(`thetas[i]`) for every i (equal lengths): the bits of [`eval`](Self::eval) at each θ. A
    /// family whose D is branch-free ([`Lanewise`]) computes a block at a time in vector lanes
    /// ([`map_lanes`]); the others point by point.
    fn eval_many(&self, thetas: &[f64], out: &mut [f64]) {
        assert_eq!(thetas.len(), out.len(), "one output per angle");
        for (o, &theta) in out.iter_mut().zip(thetas) {
            *o = self.eval(theta);
        }
    }

    /// Smith's Λ(θo) for θo ∈ [0, π/2] (docs/maths.md "Masking–shadowing and albedo"), with G1 = 1/(1 + Λ): Λ(0) = 0,
    /// non-decreasing in θo, finite and ≥ 0 (or +∞ where θo reaches π/2 if the family's Λ diverges there),
    /// never NaN. Each family states its route (closed form or [`crate::model::ndf::lambda_integral::lambda_integral`]).
    fn lambda(&self, theta_o: f64) -> f64;

    /// Λ at μ = cos θo ∈ [0, 1], for integrals that have the cosine and not the angle (the albedo's
    /// inner nodes): by default [`lambda`](Self::lambda) at arccos μ; a family whose closed form
    /// takes tan²θo = (1 − μ)(1 + μ)/μ² directly overrides it. +∞ or the value at θo = π/2 at μ = 0.
    fn lambda_at_cos(&self, mu: f64) -> f64 {
        self.lambda(mu.clamp(0.0, 1.0).acos())
    }

    /// The parameter values in [`PARAMS`](Self::PARAMS) order.
    fn params(&self) -> Vec<f64>;

    /// θ ∈ (0, π/2) of an off-normal maximum of D, where the lobe has one (a super-rough
    /// Beckmann's, say); `None` when D peaks at θ = 0 or π/2 (grid points of every sampling).
    /// The sampler starts its adaptive grid there, so that no peak falls between samples.
    fn interior_peak(&self) -> Option<f64>;

    /// Whether D → +∞ as θ → π/2 (an integrable singularity: a Student-t lobe with γ < 2). Such a lobe
    /// keeps mass closer to grazing than any double θ resolves, so quadratures over θ that weigh
    /// grazing (the weak white furnace audit) cannot check it.
    fn unbounded_at_grazing(&self) -> bool;

    /// The Beckmann roughness α_b renderers substitute for this lobe in a Beckmann-based G1
    /// (Walter's rational, the Beckmann-equivalent Smith), or `None` if the family has none.
    fn beckmann_equivalent_alpha(&self) -> Option<f64>;

    /// What the lobe tends to as the first parameter tends to 0 from inside its domain, given the
    /// other parameters `others` (in [`PARAMS`](Self::PARAMS) order, the first left out): the r = 0
    /// column of an albedo table, where α = r or r² is 0. A fact of the family, not of the table:
    /// a width parameter's 0 is the mirror (the default), but ABC's a₁ → 0 is the uniform lobe.
    fn zero_limit(_others: &[f64]) -> ZeroLimit {
        ZeroLimit::Mirror
    }

    /// D for the interactive page, in JavaScript: an expression that takes the parameter array (in
    /// [`PARAMS`](Self::PARAMS) order) and returns `θ => D(θ)`, in the same stable form and
    /// operation order as [`eval`](Self::eval) (the page's test holds them to 1e-12). It may use
    /// the helpers `maths.js` defines (`PI`, `powi`, `exprel`, `phi`, `upperGammaScaled`,
    /// `integrate`); the page assembles its table of families from the registry.
    const PAGE_FORMULA: &'static str;
}

/// What a family's lobe tends to as its first parameter tends to 0 ([`Distribution::zero_limit`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ZeroLimit {
    /// The mirror: every microfacet faces the normal (E = F(θo)).
    Mirror,
    /// The uniform lobe D = 1/π, Phong's α_p = 0.
    Uniform,
    /// A lobe ndfplot does not evaluate, described for messages.
    Other(&'static str),
}

/// The registry: `Variant => module::Type` per family, in docs/maths.md's order. Declares the modules and
/// generates [`Family`] (the family without values), [`Ndf`] (a validated NDF of any family) and
/// their dispatch, each arm a static call of the family's [`Distribution`] implementation.
macro_rules! families {
    ($($variant:ident => $module:ident::$ty:ident,)+) => {
        $(pub mod $module;)+
        $(pub use $module::$ty;)+

        /// An NDF family; its data lives in the family's [`Distribution`] implementation.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum Family {
            $(#[doc = concat!("See [`", stringify!($ty), "`].")] $variant,)+
        }

        /// A validated NDF of any family.
        #[derive(Debug, Clone, PartialEq)]
        pub enum Ndf {
            $(#[doc = concat!("See [`", stringify!($ty), "`].")] $variant($ty),)+
        }

        /// The number of families.
        const FAMILY_COUNT: usize = [$(stringify!($variant)),+].len();
        /// The number of accepted names, canonical names and aliases.
        const NAME_COUNT: usize = FAMILY_COUNT $(+ <$ty as Distribution>::ALIASES.len())+;

        impl Family {
            /// Every family, in docs/maths.md's order.
            pub const ALL: [Family; FAMILY_COUNT] = [$(Family::$variant),+];

            /// Accepted names, canonical names first then aliases (for "did you mean" suggestions).
            pub const NAMES: [&'static str; NAME_COUNT] = {
                let mut names = [""; NAME_COUNT];
                let mut i = 0;
                $(
                    names[i] = <$ty as Distribution>::NAME;
                    i += 1;
                )+
                $(
                    let aliases = <$ty as Distribution>::ALIASES;
                    let mut k = 0;
                    while k < aliases.len() {
                        names[i] = aliases[k];
                        i += 1;
                        k += 1;
                    }
                )+
                names
            };

            /// The canonical name used in curve JSON (`"ndf": "<name>"`).
            pub fn name(self) -> &'static str {
                match self {
                    $(Family::$variant => <$ty as Distribution>::NAME,)+
                }
            }

            /// The family's name in prose and on figures (see [`Distribution::TITLE`]).
            pub fn title(self) -> &'static str {
                match self {
                    $(Family::$variant => <$ty as Distribution>::TITLE,)+
                }
            }

            /// Other accepted names.
            pub fn aliases(self) -> &'static [&'static str] {
                match self {
                    $(Family::$variant => <$ty as Distribution>::ALIASES,)+
                }
            }

            /// The parameters in docs/maths.md's order, with their domains.
            pub fn params(self) -> &'static [Param] {
                match self {
                    $(Family::$variant => <$ty as Distribution>::PARAMS,)+
                }
            }

            /// See [`Distribution::LEGEND_PREFIX`].
            pub fn legend_prefix(self) -> Option<&'static str> {
                match self {
                    $(Family::$variant => <$ty as Distribution>::LEGEND_PREFIX,)+
                }
            }

            /// See [`Distribution::LAMBDA_CLOSED_FORM`].
            pub fn lambda_closed_form(self) -> bool {
                match self {
                    $(Family::$variant => <$ty as Distribution>::LAMBDA_CLOSED_FORM,)+
                }
            }

            /// The family's colour, as 0xRRGGBB (see [`Distribution::COLOUR`]).
            pub fn colour(self) -> u32 {
                match self {
                    $(Family::$variant => <$ty as Distribution>::COLOUR,)+
                }
            }

            /// D in JavaScript for the interactive page (see [`Distribution::PAGE_FORMULA`]).
            pub fn page_formula(self) -> &'static str {
                match self {
                    $(Family::$variant => <$ty as Distribution>::PAGE_FORMULA,)+
                }
            }

            /// A representative parameter set (see [`Distribution::EXAMPLE`]).
            pub fn example(self) -> &'static [f64] {
                match self {
                    $(Family::$variant => <$ty as Distribution>::EXAMPLE,)+
                }
            }

            /// See [`Distribution::zero_limit`].
            pub fn zero_limit(self, others: &[f64]) -> ZeroLimit {
                match self {
                    $(Family::$variant => <$ty as Distribution>::zero_limit(others),)+
                }
            }

            /// Builds a validated NDF of this family from its parameters, given in `params()` order.
            ///
            /// `params.len()` must equal `params().len()`.
            pub fn build(self, params: &[f64]) -> Result<Ndf, DomainError> {
                Ok(match self {
                    $(Family::$variant => Ndf::$variant(<$ty as Distribution>::from_params(params)?),)+
                })
            }
        }

        impl Ndf {
            /// D(θ) for θ ∈ [0, π/2], normalized over projected area.
            #[inline]
            pub fn eval(&self, theta: f64) -> f64 {
                match self {
                    $(Ndf::$variant(d) => d.eval(theta),)+
                }
            }

            /// D at every θ of `thetas` into `out` (see [`Distribution::eval_many`]): the bits of
            /// [`Ndf::eval`], a block at a time.
            pub fn eval_many(&self, thetas: &[f64], out: &mut [f64]) {
                match self {
                    $(Ndf::$variant(d) => d.eval_many(thetas, out),)+
                }
            }

            /// Smith's Λ(θo) for θo ∈ [0, π/2] (see [`Distribution::lambda`]).
            #[inline]
            pub fn lambda(&self, theta_o: f64) -> f64 {
                match self {
                    $(Ndf::$variant(d) => d.lambda(theta_o),)+
                }
            }

            /// Λ at μ = cos θo ∈ [0, 1] (see [`Distribution::lambda_at_cos`]).
            #[inline]
            pub fn lambda_at_cos(&self, mu: f64) -> f64 {
                match self {
                    $(Ndf::$variant(d) => d.lambda_at_cos(mu),)+
                }
            }

            /// See [`Distribution::interior_peak`].
            pub fn interior_peak(&self) -> Option<f64> {
                match self {
                    $(Ndf::$variant(d) => d.interior_peak(),)+
                }
            }

            /// See [`Distribution::unbounded_at_grazing`].
            pub fn unbounded_at_grazing(&self) -> bool {
                match self {
                    $(Ndf::$variant(d) => d.unbounded_at_grazing(),)+
                }
            }

            /// See [`Distribution::beckmann_equivalent_alpha`].
            pub fn beckmann_equivalent_alpha(&self) -> Option<f64> {
                match self {
                    $(Ndf::$variant(d) => d.beckmann_equivalent_alpha(),)+
                }
            }

            /// The family of this NDF.
            pub fn family(&self) -> Family {
                match self {
                    $(Ndf::$variant(_) => Family::$variant,)+
                }
            }

            /// The parameter values in `family().params()` order.
            pub fn params(&self) -> Vec<f64> {
                match self {
                    $(Ndf::$variant(d) => d.params(),)+
                }
            }
        }
    };
}

families! {
    Phong => phong::Phong,
    Beckmann => beckmann::Beckmann,
    TorranceSparrow => torrance_sparrow::TorranceSparrow,
    TrowbridgeReitz => trowbridge_reitz::TrowbridgeReitz,
    Abc => abc::Abc,
    Sgd => sgd::Sgd,
    Gtr => gtr::Gtr,
    StudentT => student_t::StudentT,
}

impl Family {
    /// Looks a family up by canonical name or alias (`ggx` → Trowbridge–Reitz), in any case
    /// (`GGX`).
    pub fn from_name(name: &str) -> Option<Family> {
        Family::ALL.into_iter().find(|f| {
            f.name().eq_ignore_ascii_case(name)
                || f.aliases().iter().any(|a| a.eq_ignore_ascii_case(name))
        })
    }

    /// Parameter names in docs/maths.md's order.
    pub fn param_names(self) -> Vec<&'static str> {
        self.params().iter().map(|p| p.name).collect()
    }

    /// The parameter domains in one line (for `--help`): `alpha_b in [1e-150, 1e4]`, parameters with
    /// the same domain sharing it (`alpha_abc1, alpha_abc2 in (0, 1e100]`).
    pub fn domain(self) -> String {
        let mut groups: Vec<(Vec<&str>, String)> = Vec::new();
        for param in self.params() {
            let interval = param.interval();
            match groups.last_mut() {
                Some((names, last)) if *last == interval => names.push(param.name),
                _ => groups.push((vec![param.name], interval)),
            }
        }
        groups
            .iter()
            .map(|(names, interval)| format!("{} {interval}", names.join(", ")))
            .collect::<Vec<_>>()
            .join(", ")
    }
}

/// Grids and checks the families' tests share.
#[cfg(test)]
pub(crate) mod test_support {
    use super::Distribution;
    use crate::model::math::tolerance::floored_relative_difference;

    /// The decades 10^e for e = lo, lo + step, … ≤ hi, each the double nearest 10^e (as written `1e{e}`).
    pub fn decades(lo: i32, hi: i32, step: usize) -> impl Iterator<Item = f64> {
        (lo..=hi)
            .step_by(step)
            .map(|e| format!("1e{e}").parse().expect("a decade parses"))
    }

    /// The largest floored relative difference of `ndf`'s `eval_many` over `thetas` from `reference`, with
    /// the θ where it is, after asserting that every value is `eval`'s bits, finite and non-negative (`at`
    /// names the parameters in the messages).
    pub fn block_error<D: Distribution>(
        ndf: &D,
        thetas: &[f64],
        reference: impl Fn(f64) -> f64,
        at: &str,
    ) -> (f64, f64) {
        let mut block = vec![0.0; thetas.len()];
        ndf.eval_many(thetas, &mut block);
        let mut worst = (0.0, 0.0);
        for (&theta, &got) in thetas.iter().zip(&block) {
            assert_eq!(
                got.to_bits(),
                ndf.eval(theta).to_bits(),
                "{at}, θ = {theta:e}"
            );
            assert!(
                got.is_finite() && got >= 0.0,
                "{at}, θ = {theta:e}: {got:e}"
            );
            let error = floored_relative_difference(got, reference(theta));
            if error > worst.0 {
                worst = (error, theta);
            }
        }
        worst
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_list_canonical_names_then_aliases() {
        assert_eq!(
            Family::NAMES,
            [
                "phong",
                "beckmann",
                "torrance_sparrow",
                "trowbridge_reitz",
                "abc",
                "sgd",
                "gtr",
                "student_t",
                "ggx",
                "std"
            ]
        );
        assert_eq!(Family::from_name("ggx"), Some(Family::TrowbridgeReitz));
        for family in Family::ALL {
            assert_eq!(Family::from_name(family.name()), Some(family));
            assert_eq!(
                family.build(family.example()).unwrap().params(),
                family.example()
            );
        }
    }

    /// `eval_many` gives `eval`'s bits for every family, at its example and at each end of each
    /// parameter's domain, from θ = 0 through tiny angles to the double nearest π/2.
    #[test]
    fn blocks_equal_point_by_point_evaluation() {
        let half_pi = std::f64::consts::FRAC_PI_2;
        let thetas: Vec<f64> = (0..=1000)
            .map(|i| half_pi * f64::from(i) / 1000.0)
            .chain((1..=300).map(|e| 10f64.powi(-e)))
            .chain((1..=16).map(|e| half_pi - 10f64.powi(-e)))
            .chain([half_pi, f64::from_bits(half_pi.to_bits() - 1)])
            .collect();
        for family in Family::ALL {
            let example = family.example();
            let mut sets = vec![example.to_vec()];
            for (i, param) in family.params().iter().enumerate() {
                for end in [param.min.value, param.max.value] {
                    let mut set = example.to_vec();
                    set[i] = end;
                    sets.push(set);
                }
            }
            for set in sets {
                let Ok(ndf) = family.build(&set) else {
                    continue;
                };
                let mut block = vec![0.0; thetas.len()];
                ndf.eval_many(&thetas, &mut block);
                for (&theta, &value) in thetas.iter().zip(&block) {
                    assert_eq!(
                        value.to_bits(),
                        ndf.eval(theta).to_bits(),
                        "{} {set:?} at θ = {theta:e}",
                        family.name()
                    );
                }
            }
        }
    }

    /// The table of curves in docs/reference.md states each family's domain as the registry does.
    #[test]
    fn reference_rows_state_the_registry_domains() {
        let reference = include_str!("../../../docs/reference.md");
        for family in Family::ALL {
            let mut domain = family.domain();
            for param in family.params() {
                domain = domain.replace(param.name, &format!("`{}`", param.name));
            }
            let prefix = format!("| `ndf: {}`", family.name());
            let row = reference
                .lines()
                .find(|l| l.starts_with(&prefix))
                .unwrap_or_else(|| panic!("docs/reference.md has no row {prefix}"));
            let cells: Vec<&str> = row.split(" | ").collect();
            assert!(
                cells[1].starts_with(&domain),
                "docs/reference.md row {row:?} should state {domain:?}"
            );
            for alias in family.aliases() {
                assert!(
                    cells[0].contains(&format!("`{alias}`")),
                    "{row:?} lacks alias {alias}"
                );
            }
        }
    }
}
