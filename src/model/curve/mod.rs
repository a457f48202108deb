//! The resolved curve: what every stage after `resolve` evaluates — an NDF, a Fresnel reflectance,
//! a difference or a view of them, or a quantity of an NDF's microfacet model ([`quantity`]).
//!
//! Pure f64 evaluation: reading curves from JSON, their canonical JSON and their labels are the
//! spec's (`crate::spec::curve`).

pub mod quantity;

use crate::model::fresnel::Fresnel;
use crate::model::names::named;
use crate::model::ndf::Ndf;
use crate::model::renderer::{Emulation, Target};
use crate::model::transform::Transform;
use quantity::{Prepared, Quantity};

/// A validated curve: an NDF D(θ) or a Fresnel reflectance F(θ).
#[derive(Debug, Clone, PartialEq)]
pub enum Curve {
    /// A normal distribution function.
    Ndf(Ndf),
    /// A Fresnel reflectance curve (θ is the angle of incidence).
    Fresnel(Fresnel),
    /// A difference series of two curves of the same kind: a − b or a / b at every θ.
    Difference {
        /// How the two values are combined.
        op: DiffOp,
        /// The first operand.
        a: Box<Curve>,
        /// The second operand.
        b: Box<Curve>,
    },
    /// An NDF seen through a view transform (`projected`: D cos θ; `slope`: D cos⁴θ).
    Transformed {
        /// The transform.
        transform: Transform,
        /// The transformed NDF.
        curve: Box<Curve>,
    },
    /// A quantity of an NDF's microfacet model other than D (Λ, G1, G2, albedo, furnace), a
    /// function of the view angle θo.
    Quantity {
        /// The quantity.
        quantity: Quantity<Curve>,
        /// The NDF.
        ndf: Ndf,
        /// What the quantity's values share, found on first use.
        prepared: Prepared,
    },
    /// D, G1, G2 or Schlick's F as a renderer computes it ([`crate::model::renderer`]).
    Emulated(Emulation),
}

/// What a curve's values are, for the rules that pair curves (differences, `compare`) and for
/// axis labels: an NDF quantity (`"d"` for D itself) or a Fresnel reflectance.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A quantity of an NDF, by its name in curve JSON ([`quantity::NAMES`]).
    Ndf(&'static str),
    /// A Fresnel reflectance.
    Fresnel,
}

impl Kind {
    /// The kind in messages: `ndf`, `ndf quantity "g1"`, `fresnel`.
    pub fn describe(self) -> String {
        match self {
            Kind::Ndf("d") => "ndf".to_string(),
            Kind::Ndf(quantity) => format!("ndf quantity \"{quantity}\""),
            Kind::Fresnel => "fresnel".to_string(),
        }
    }
}

impl Kind {
    /// The symbol of the values, math text: `D`, `Λ`, `G_1`, `G_2`, `E`, `W` (the furnace test's
    /// G_1 (1 + Λ)), `F`.
    pub fn symbol(self) -> &'static str {
        match self {
            Kind::Ndf("lambda") => "Λ",
            Kind::Ndf("g1") => "G_1",
            Kind::Ndf("g2") => "G_2",
            Kind::Ndf("albedo") => "E",
            Kind::Ndf("furnace") => "W",
            Kind::Ndf(_) => "D",
            Kind::Fresnel => "F",
        }
    }
}

impl Curve {
    /// The curve's value at θ ∈ [0, π/2] (radians).
    #[inline]
    pub fn eval(&self, theta: f64) -> f64 {
        match self {
            Curve::Ndf(d) => d.eval(theta),
            Curve::Fresnel(f) => f.eval(theta),
            Curve::Difference { op, a, b } => op.apply(a.eval(theta), b.eval(theta)),
            Curve::Transformed { transform, curve } => transform.apply(theta, curve.eval(theta)),
            Curve::Quantity {
                quantity,
                ndf,
                prepared,
            } => quantity.eval(ndf, prepared, theta),
            Curve::Emulated(emulation) => emulation.eval(theta),
        }
    }

    /// `out[i]` = the curve at `thetas[i]` for every i (equal lengths): the bits of [`Curve::eval`], an
    /// NDF's a block at a time in vector lanes ([`Ndf::eval_many`]).
    pub fn eval_many(&self, thetas: &[f64], out: &mut [f64]) {
        match self {
            Curve::Ndf(d) => d.eval_many(thetas, out),
            _ => {
                assert_eq!(thetas.len(), out.len(), "one output per angle");
                for (o, &theta) in out.iter_mut().zip(thetas) {
                    *o = self.eval(theta);
                }
            }
        }
    }

    /// Whether a renderer's emulation ([`Curve::Emulated`]) computes any part of the curve: its values
    /// then carry that engine's float32 or half-float rounding.
    pub fn emulated(&self) -> bool {
        match self {
            Curve::Emulated(_) => true,
            Curve::Difference { a, b, .. } => a.emulated() || b.emulated(),
            Curve::Transformed { curve, .. } => curve.emulated(),
            Curve::Ndf(_) | Curve::Fresnel(_) | Curve::Quantity { .. } => false,
        }
    }

    /// How many integrals one value of the curve computes: 1 for a directional albedo E(μo)
    /// (a double integral over the light's hemisphere), the sum of its operands' for a
    /// difference, 0 for the closed forms. Scenes and commands budget their work by it.
    pub fn integrals_per_value(&self) -> usize {
        match self {
            Curve::Quantity {
                quantity: Quantity::Albedo { .. },
                ..
            } => 1,
            Curve::Difference { a, b, .. } => a.integrals_per_value() + b.integrals_per_value(),
            Curve::Transformed { curve, .. } => curve.integrals_per_value(),
            Curve::Ndf(_) | Curve::Fresnel(_) | Curve::Quantity { .. } | Curve::Emulated(_) => 0,
        }
    }

    /// What the curve's values are; a difference's are its first operand's (both share them).
    pub fn kind(&self) -> Kind {
        match self {
            Curve::Ndf(_) | Curve::Transformed { .. } => Kind::Ndf("d"),
            Curve::Quantity { quantity, .. } => Kind::Ndf(quantity.name()),
            Curve::Fresnel(_) => Kind::Fresnel,
            Curve::Difference { a, .. } => a.kind(),
            Curve::Emulated(emulation) => match emulation.target() {
                Target::D(..) => Kind::Ndf("d"),
                Target::G1(..) => Kind::Ndf("g1"),
                Target::G2 { .. } => Kind::Ndf("g2"),
                Target::Schlick(_) | Target::Dielectric(_) => Kind::Fresnel,
            },
        }
    }
}

named! {
    /// How a difference series combines its operands.
    pub enum DiffOp {
        /// a − b.
        Minus = "minus",
        /// a / b, with 0/0 = 1 (both curves vanish: they agree) and x/0 = +∞ for x ≠ 0, which every
        /// consumer reports as an error at that θ instead of printing it.
        Ratio = "ratio",
        /// (a − b)/|b|, with 0 where a = b (both 0 included) and ±∞ where only b is 0.
        Relative = "relative",
        /// ln(a/b), with 0 where a = b (both 0 included); −∞ or NaN where a/b ≤ 0.
        LogRatio = "log-ratio",
    }
}

impl DiffOp {
    /// a − b, a / b with 0/0 = 1, (a − b)/|b| or ln(a/b), each 0 (1 for the ratio) where a = b.
    #[inline]
    pub fn apply(self, a: f64, b: f64) -> f64 {
        match self {
            DiffOp::Minus => a - b,
            DiffOp::Ratio if a == 0.0 && b == 0.0 => 1.0,
            DiffOp::Ratio => a / b,
            DiffOp::Relative | DiffOp::LogRatio if a == b => 0.0,
            DiffOp::Relative => (a - b) / b.abs(),
            DiffOp::LogRatio => (a / b).ln(),
        }
    }

    /// How a label joins the operands' labels: `a − b`, `a / b`, `a relative to b`, `ln(a / b)` as
    /// `a log-ratio to b`.
    pub fn sign(self) -> &'static str {
        match self {
            DiffOp::Minus => "−",
            DiffOp::Ratio => "/",
            DiffOp::Relative => "relative to",
            DiffOp::LogRatio => "log-ratio to",
        }
    }
}

impl DiffOp {
    /// The value axis label of a panel of such differences, math text, for operands whose values
    /// are `symbol` ([`Kind::symbol`]; `None` when unknown, both sides being data):
    /// `D_{a} − D_{b}`, `D_{a} / D_{b}`, `relative difference in D`, `ln(D_{a} / D_{b})`.
    pub fn axis_label(self, symbol: Option<&str>) -> String {
        let operand = |side: &str| match symbol {
            // A subscripted symbol takes the side after its subscript: G_{1,a}.
            Some(s) => match s.split_once('_') {
                Some((base, sub)) => format!("{base}_{{{sub},{side}}}"),
                None => format!("{s}_{{{side}}}"),
            },
            None => side.to_string(),
        };
        let (a, b) = (operand("a"), operand("b"));
        match (self, symbol) {
            (DiffOp::Minus, _) => format!("{a} − {b}"),
            (DiffOp::Ratio, _) => format!("{a} / {b}"),
            (DiffOp::Relative, Some(s)) => format!("relative difference in {s}"),
            (DiffOp::Relative, None) => "relative difference".to_string(),
            (DiffOp::LogRatio, _) => format!("ln({a} / {b})"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{DiffOp, Kind};

    #[test]
    fn difference_axes_name_the_operation_and_the_symbol() {
        let d = Some(Kind::Ndf("d").symbol());
        assert_eq!(DiffOp::Minus.axis_label(d), "D_{a} − D_{b}");
        assert_eq!(DiffOp::Ratio.axis_label(d), "D_{a} / D_{b}");
        assert_eq!(DiffOp::Relative.axis_label(d), "relative difference in D");
        let g1 = Some(Kind::Ndf("g1").symbol());
        assert_eq!(DiffOp::LogRatio.axis_label(g1), "ln(G_{1,a} / G_{1,b})");
        assert_eq!(DiffOp::Relative.axis_label(None), "relative difference");
        assert_eq!(DiffOp::Minus.axis_label(None), "a − b");
    }

    #[test]
    fn relative_and_log_ratio_are_zero_where_the_operands_agree() {
        assert_eq!(DiffOp::Relative.apply(3.0, 2.0), 0.5);
        assert_eq!(DiffOp::Relative.apply(1.0, -2.0), 1.5);
        assert_eq!(DiffOp::Relative.apply(0.0, 0.0), 0.0);
        assert_eq!(DiffOp::Relative.apply(1.0, 0.0), f64::INFINITY);
        assert_eq!(DiffOp::LogRatio.apply(std::f64::consts::E, 1.0), 1.0);
        assert_eq!(DiffOp::LogRatio.apply(0.0, 0.0), 0.0);
        assert_eq!(DiffOp::LogRatio.apply(0.0, 1.0), f64::NEG_INFINITY);
        for op in DiffOp::ALL {
            assert_eq!(DiffOp::from_name(op.name()), Some(op));
        }
    }
}
