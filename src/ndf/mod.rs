//! The six microfacet normal distribution functions of MATH.md, each a validated type.
//!
//! Every NDF is normalized over projected area: 2π ∫₀^{π/2} D(θ) sin θ cos θ dθ = 1.
//! Constructors validate their parameters and compute normalization constants once;
//! `eval` is pure f64 code with no allocation, the one evaluation path of every output.

pub mod abc;
pub mod beckmann;
pub mod phong;
pub mod sgd;
pub mod torrance_sparrow;
pub mod trowbridge_reitz;

pub use abc::Abc;
pub use beckmann::Beckmann;
pub use phong::Phong;
pub use sgd::Sgd;
pub use torrance_sparrow::TorranceSparrow;
pub use trowbridge_reitz::TrowbridgeReitz;

/// An NDF family: its canonical name, parameter names (in MATH.md's order) and notebook colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Family {
    /// Phong, `alpha_p`.
    Phong,
    /// Beckmann, `alpha_b`.
    Beckmann,
    /// Torrance–Sparrow (Gaussian in angle), `alpha_ts`.
    TorranceSparrow,
    /// Trowbridge–Reitz / GGX, `alpha_tr`.
    TrowbridgeReitz,
    /// ABC (Low et al. 2012), `alpha_abc1`, `alpha_abc2`.
    Abc,
    /// Shifted Gamma Distribution (Bagher et al. 2012), `alpha_sgd1`, `alpha_sgd2`.
    Sgd,
}

impl Family {
    /// Every family, in MATH.md's order.
    pub const ALL: [Family; 6] = [
        Family::Phong,
        Family::Beckmann,
        Family::TorranceSparrow,
        Family::TrowbridgeReitz,
        Family::Abc,
        Family::Sgd,
    ];

    /// The canonical name used in curve JSON (`"ndf": "<name>"`).
    pub fn name(self) -> &'static str {
        match self {
            Family::Phong => "phong",
            Family::Beckmann => "beckmann",
            Family::TorranceSparrow => "torrance_sparrow",
            Family::TrowbridgeReitz => "trowbridge_reitz",
            Family::Abc => "abc",
            Family::Sgd => "sgd",
        }
    }

    /// Looks a family up by canonical name or alias (`ggx` → Trowbridge–Reitz).
    pub fn from_name(name: &str) -> Option<Family> {
        match name {
            "ggx" => Some(Family::TrowbridgeReitz),
            _ => Family::ALL.into_iter().find(|f| f.name() == name),
        }
    }

    /// Accepted names, canonical names first then aliases (for "did you mean" suggestions).
    pub const NAMES: [&'static str; 7] = [
        "phong",
        "beckmann",
        "torrance_sparrow",
        "trowbridge_reitz",
        "abc",
        "sgd",
        "ggx",
    ];

    /// Parameter names in MATH.md's order.
    pub fn param_names(self) -> &'static [&'static str] {
        match self {
            Family::Phong => &["alpha_p"],
            Family::Beckmann => &["alpha_b"],
            Family::TorranceSparrow => &["alpha_ts"],
            Family::TrowbridgeReitz => &["alpha_tr"],
            Family::Abc => &["alpha_abc1", "alpha_abc2"],
            Family::Sgd => &["alpha_sgd1", "alpha_sgd2"],
        }
    }

    /// The notebook's Solarized-based colour for the family, as 0xRRGGBB.
    pub fn colour(self) -> u32 {
        match self {
            Family::Phong => 0xDB2E2E,
            Family::Beckmann => 0x2689D1,
            Family::TorranceSparrow => 0xFF9900,
            Family::TrowbridgeReitz => 0x849900,
            Family::Abc => 0x6C70C4,
            Family::Sgd => 0xB58800,
        }
    }

    /// A one-line statement of the parameter domain the family's constructor accepts (for `--help`).
    pub fn domain(self) -> &'static str {
        match self {
            Family::Phong => phong::DOMAIN,
            Family::Beckmann => beckmann::DOMAIN,
            Family::TorranceSparrow => torrance_sparrow::DOMAIN,
            Family::TrowbridgeReitz => trowbridge_reitz::DOMAIN,
            Family::Abc => abc::DOMAIN,
            Family::Sgd => sgd::DOMAIN,
        }
    }

    /// Builds a validated NDF of this family from its parameters, given in `param_names()` order.
    ///
    /// `params.len()` must equal `param_names().len()`.
    pub fn build(self, params: &[f64]) -> Result<Ndf, crate::domain::DomainError> {
        Ok(match self {
            Family::Phong => Ndf::Phong(Phong::new(params[0])?),
            Family::Beckmann => Ndf::Beckmann(Beckmann::new(params[0])?),
            Family::TorranceSparrow => Ndf::TorranceSparrow(TorranceSparrow::new(params[0])?),
            Family::TrowbridgeReitz => Ndf::TrowbridgeReitz(TrowbridgeReitz::new(params[0])?),
            Family::Abc => Ndf::Abc(Abc::new(params[0], params[1])?),
            Family::Sgd => Ndf::Sgd(Sgd::new(params[0], params[1])?),
        })
    }
}

/// A validated NDF of any family.
#[derive(Debug, Clone, PartialEq)]
pub enum Ndf {
    /// See [`Phong`].
    Phong(Phong),
    /// See [`Beckmann`].
    Beckmann(Beckmann),
    /// See [`TorranceSparrow`].
    TorranceSparrow(TorranceSparrow),
    /// See [`TrowbridgeReitz`].
    TrowbridgeReitz(TrowbridgeReitz),
    /// See [`Abc`].
    Abc(Abc),
    /// See [`Sgd`].
    Sgd(Sgd),
}

impl Ndf {
    /// D(θ) for θ ∈ [0, π/2], normalized over projected area.
    #[inline]
    pub fn eval(&self, theta: f64) -> f64 {
        match self {
            Ndf::Phong(d) => d.eval(theta),
            Ndf::Beckmann(d) => d.eval(theta),
            Ndf::TorranceSparrow(d) => d.eval(theta),
            Ndf::TrowbridgeReitz(d) => d.eval(theta),
            Ndf::Abc(d) => d.eval(theta),
            Ndf::Sgd(d) => d.eval(theta),
        }
    }

    /// The family of this NDF.
    pub fn family(&self) -> Family {
        match self {
            Ndf::Phong(_) => Family::Phong,
            Ndf::Beckmann(_) => Family::Beckmann,
            Ndf::TorranceSparrow(_) => Family::TorranceSparrow,
            Ndf::TrowbridgeReitz(_) => Family::TrowbridgeReitz,
            Ndf::Abc(_) => Family::Abc,
            Ndf::Sgd(_) => Family::Sgd,
        }
    }

    /// The parameter values in `family().param_names()` order.
    pub fn params(&self) -> Vec<f64> {
        match self {
            Ndf::Phong(d) => vec![d.alpha_p()],
            Ndf::Beckmann(d) => vec![d.alpha_b()],
            Ndf::TorranceSparrow(d) => vec![d.alpha_ts()],
            Ndf::TrowbridgeReitz(d) => vec![d.alpha_tr()],
            Ndf::Abc(d) => vec![d.alpha_abc1(), d.alpha_abc2()],
            Ndf::Sgd(d) => vec![d.alpha_sgd1(), d.alpha_sgd2()],
        }
    }
}
