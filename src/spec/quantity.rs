//! What a curve of an NDF shows: D(θ) itself, or a quantity of the microfacet model built on it
//! (docs/contracts.md "Quantities of an NDF"; docs/maths.md "Masking–shadowing and albedo").
//!
//! A curve object names it with `"quantity"`: `"d"` (the default, D(θm)), `"lambda"` (Smith Λ),
//! `"g1"` (masking), `"g2"` (masking–shadowing, with `"g2"` naming the [`G2Model`] and
//! `"theta_i"` the light's angle or `"same"`), `"albedo"` (the directional albedo E(μo), μo = cos θo,
//! with `"g2"` and an optional nested `"fresnel"` curve) and `"furnace"` (the weak white furnace of
//! the G1 named by `"g1"`). For every quantity but D, θ is the view angle θo.
//!
//! This module owns those keys: which quantity takes which, their defaults, their canonical JSON
//! and their labels. Evaluation defers to [`crate::model::masking`] and [`crate::model::albedo`].

use crate::model::curve::quantity::{NAMES, Quantity, ThetaI};
use crate::model::masking::{G1Model, G2Model};
use crate::model::ndf::Family;
use crate::problem::{Problem, join_key, suggestion};
use crate::spec::json::{Node, Value};
use serde::ser::{SerializeMap, Serializer};
use std::f64::consts::FRAC_PI_2;

/// The keys a curve of an NDF takes besides its model key and parameters.
pub const KEYS: &[&str] = &[QUANTITY_KEY, G2_KEY, THETA_I_KEY, G1_KEY, FRESNEL_KEY];
/// The key naming the quantity.
pub const QUANTITY_KEY: &str = "quantity";
/// The key naming a G2 model (`g2` and `albedo` curves).
pub const G2_KEY: &str = "g2";
/// The key giving the light's angle θi of a `g2` curve.
pub const THETA_I_KEY: &str = "theta_i";
/// The key naming the G1 a `furnace` curve audits.
pub const G1_KEY: &str = "g1";
/// The key nesting the Fresnel curve of an `albedo` curve.
pub const FRESNEL_KEY: &str = "fresnel";
/// The word of `theta_i` for a light in the view direction, θi = θo.
pub const SAME: &str = "same";

/// Each option key with the quantities that take it.
pub const OPTION_TAKERS: [(&str, &[&str]); 4] = [
    (G2_KEY, &["g2", "albedo"]),
    (THETA_I_KEY, &["g2"]),
    (G1_KEY, &["furnace"]),
    (FRESNEL_KEY, &["albedo"]),
];

/// The largest light angle `theta_i` takes, radians (grazing); the smallest is 0.
pub const THETA_I_MAX: f64 = FRAC_PI_2;

/// The placeholder of a label template that an albedo curve fills with its average E_avg.
pub const E_AVG_PLACEHOLDER: &str = "{e_avg}";

impl<F> Quantity<F> {
    /// Checks what only the family tells: a Beckmann-based G1 needs a family with a Beckmann
    /// equivalent ([`Ndf::beckmann_equivalent_alpha`](crate::model::ndf::Ndf::beckmann_equivalent_alpha), asked of the family's example lobe).
    pub fn check_family(&self, family: Family, path: &str) -> Result<(), Problem> {
        let Quantity::Furnace { g1 } = self else {
            return Ok(());
        };
        let example = family
            .build(family.example())
            .expect("a family's example lies in its domain");
        match g1.g1(&example, 1.0) {
            Ok(_) => Ok(()),
            Err(e) => Err(Problem::new(
                join_key(path, G1_KEY),
                format!("{e} (got ndf \"{}\")", family.name()),
            )),
        }
    }
}

/// Writes the quantity's members of canonical curve JSON: `"quantity"`, then its keys with their
/// values, defaults included.
pub fn serialize_members<M: SerializeMap, F: serde::Serialize>(
    map: &mut M,
    quantity: &Quantity<F>,
) -> Result<(), M::Error> {
    map.serialize_entry(QUANTITY_KEY, quantity.name())?;
    match quantity {
        Quantity::Lambda | Quantity::G1 => {}
        Quantity::G2 { model, theta_i } => {
            map.serialize_entry(G2_KEY, model.name())?;
            match theta_i {
                ThetaI::Same => map.serialize_entry(THETA_I_KEY, SAME)?,
                ThetaI::Fixed(theta) => map.serialize_entry(THETA_I_KEY, theta)?,
            }
        }
        Quantity::Albedo { model, fresnel } => {
            map.serialize_entry(G2_KEY, model.name())?;
            if let Some(fresnel) = fresnel {
                map.serialize_entry(FRESNEL_KEY, fresnel)?;
            }
        }
        Quantity::Furnace { g1 } => map.serialize_entry(G1_KEY, g1.name())?,
    }
    Ok(())
}

/// The legend text of a quantity's options that are not its defaults (`separable`, `θ_i = 0.5`,
/// `Walter rational`), to follow the NDF's parameters in an automatic label.
pub fn label_parts<F>(quantity: &Quantity<F>) -> Vec<String> {
    let mut parts = Vec::new();
    match quantity {
        Quantity::G2 { model, theta_i } => {
            if *model != G2Model::HeightCorrelated {
                parts.push(model.name().to_string());
            }
            if let ThetaI::Fixed(theta) = theta_i {
                parts.push(format!("θ_i = {}", crate::spec::numbers::pretty(*theta)));
            }
        }
        Quantity::Albedo { model, .. } if *model != G2Model::HeightCorrelated => {
            parts.push(model.name().to_string());
        }
        Quantity::Furnace { g1 } => parts.push(g1_title(*g1).to_string()),
        _ => {}
    }
    parts
}

/// A G1 model in legend text.
fn g1_title(g1: G1Model) -> &'static str {
    match g1 {
        G1Model::Smith => "exact Smith G_1",
        G1Model::WalterRational => "Walter's rational G_1",
        G1Model::BeckmannEquivalent => "Beckmann-equivalent G_1",
    }
}

/// Reads the quantity keys of the NDF curve object `members` at `path`; `None` for D (no
/// `"quantity"`, or `"d"`). Every problem is reported: an unknown name, a key the quantity does
/// not take, a value of the wrong kind.
pub fn parse<F>(
    members: &[(String, Node)],
    path: &str,
    fresnel: impl Fn(&Node, &str) -> Result<F, Vec<Problem>>,
) -> Result<Option<Quantity<F>>, Vec<Problem>> {
    let get = |key: &str| members.iter().find(|(k, _)| k == key).map(|(_, n)| n);
    let mut problems = Vec::new();
    let name = match get(QUANTITY_KEY) {
        None => "d",
        Some(node) => match &node.value {
            Value::String(name) if NAMES.iter().any(|n| n.eq_ignore_ascii_case(name)) => NAMES
                .into_iter()
                .find(|n| n.eq_ignore_ascii_case(name))
                .expect("checked"),
            Value::String(name) => {
                return Err(vec![Problem::new(
                    join_key(path, QUANTITY_KEY),
                    format!(
                        "unknown quantity (got \"{}\", expected one of: {}){}",
                        crate::problem::excerpt(name),
                        NAMES.join(", "),
                        suggestion(name, NAMES)
                    ),
                )]);
            }
            _ => {
                return Err(vec![Problem::new(
                    join_key(path, QUANTITY_KEY),
                    format!(
                        "expected a quantity name (got {node}, expected one of: {})",
                        NAMES.join(", ")
                    ),
                )]);
            }
        },
    };
    for (key, quantities) in OPTION_TAKERS {
        if let Some(node) = get(key)
            && !quantities.contains(&name)
        {
            let takers = quantities
                .iter()
                .map(|q| format!("\"{q}\""))
                .collect::<Vec<_>>()
                .join(" or ");
            problems.push(Problem::new(
                join_key(path, key),
                format!(
                    "only a quantity {takers} curve takes this key (got {node} on quantity \"{name}\")"
                ),
            ));
        }
    }
    let g2 = get(G2_KEY)
        .map(|node| named(node, &join_key(path, G2_KEY), &G2Model::NAMES, "G2 model"))
        .transpose();
    let g1 = get(G1_KEY)
        .map(|node| named(node, &join_key(path, G1_KEY), &G1Model::NAMES, "G1"))
        .transpose();
    let theta_i = get(THETA_I_KEY)
        .map(|node| theta_i(node, &join_key(path, THETA_I_KEY)))
        .transpose();
    let fresnel = get(FRESNEL_KEY)
        .map(|node| fresnel(node, &join_key(path, FRESNEL_KEY)))
        .transpose();
    let (g2, g1, theta_i, fresnel) = match (g2, g1, theta_i, fresnel) {
        (Ok(g2), Ok(g1), Ok(theta_i), Ok(fresnel)) if problems.is_empty() => {
            (g2, g1, theta_i, fresnel)
        }
        (g2, g1, theta_i, fresnel) => {
            problems.extend(g2.err().into_iter().flatten());
            problems.extend(g1.err().into_iter().flatten());
            problems.extend(theta_i.err().into_iter().flatten());
            problems.extend(fresnel.err().into_iter().flatten());
            return Err(problems);
        }
    };
    let model = g2.unwrap_or(G2Model::HeightCorrelated);
    Ok(match name {
        "lambda" => Some(Quantity::Lambda),
        "g1" => Some(Quantity::G1),
        "g2" => Some(Quantity::G2 {
            model,
            theta_i: theta_i.unwrap_or(ThetaI::Same),
        }),
        "albedo" => Some(Quantity::Albedo {
            model,
            fresnel: fresnel.map(Box::new),
        }),
        "furnace" => Some(Quantity::Furnace {
            g1: g1.unwrap_or(G1Model::Smith),
        }),
        "d" => None,
        other => unreachable!("quantity \"{other}\" is named but has no parse arm"),
    })
}

/// A name from `table` given as a JSON string.
fn named<T: Copy>(
    node: &Node,
    path: &str,
    table: &[(&'static str, T)],
    what: &str,
) -> Result<T, Vec<Problem>> {
    let names: Vec<&str> = table.iter().map(|(n, _)| *n).collect();
    match &node.value {
        Value::String(name) => match table.iter().find(|(n, _)| n == name) {
            Some((_, value)) => Ok(*value),
            None => Err(vec![Problem::new(
                path,
                format!(
                    "unknown {what} (got \"{}\", expected one of: {}){}",
                    crate::problem::excerpt(name),
                    names.join(", "),
                    suggestion(name, names.iter().copied())
                ),
            )]),
        },
        _ => Err(vec![Problem::new(
            path,
            format!(
                "expected a {what} name (got {node}, expected one of: {})",
                names.join(", ")
            ),
        )]),
    }
}

/// `theta_i`: radians in [0, π/2], or `"same"`.
fn theta_i(node: &Node, path: &str) -> Result<ThetaI, Vec<Problem>> {
    match &node.value {
        Value::Number(n) if (0.0..=THETA_I_MAX).contains(&n.value) => Ok(ThetaI::Fixed(n.value)),
        Value::String(word) if word == SAME => Ok(ThetaI::Same),
        _ => Err(vec![Problem::new(
            path,
            format!(
                "expected the light's angle (got {node}, expected radians in [0, {THETA_I_MAX}] or \"{SAME}\")"
            ),
        )]),
    }
}

/// Serializes `quantity` of an NDF curve whose model key and parameters `write_model` writes.
pub fn serialize_curve<S: Serializer, F: serde::Serialize>(
    serializer: S,
    write_model: impl FnOnce(&mut S::SerializeMap) -> Result<(), S::Error>,
    quantity: &Quantity<F>,
) -> Result<S::Ok, S::Error> {
    let mut map = serializer.serialize_map(None)?;
    write_model(&mut map)?;
    serialize_members(&mut map, quantity)?;
    map.end()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every quantity name parses to the quantity of that name (D to none): a name added to the
    /// table without its parse arm fails here.
    #[test]
    fn every_named_quantity_parses_to_itself() {
        for name in NAMES {
            let node = crate::spec::json::parse(&format!(r#"{{"quantity":"{name}"}}"#)).unwrap();
            let crate::spec::json::Value::Object(members) = &node.value else {
                unreachable!()
            };
            let parsed = parse(members, "", |_, _| Ok(())).unwrap();
            assert_eq!(parsed.map_or("d", |q| q.name()), name);
        }
    }
}
