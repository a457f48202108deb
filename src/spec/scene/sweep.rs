//! Parameter sweeps in scene curves: a number, a list, `{"range": [a, b, s]}` (Mathematica's
//! `Range`, exact per docs/contracts.md) or, for Phong's exponent, `{"from_beckmann": …}` through
//! Walter et al.'s equivalence α_p = 2/α_b² − 2. A parameter may also be fitted, one value per
//! target curve (`{"fit": {"target": <curve or sweep>, "by": "peak"}}`), and a curve entry may be a
//! difference series of two curves or matched sweeps (`{"difference": "minus", "a": …, "b": …}`).
//! The fitting itself is [`crate::model::fit`]'s, run by [`crate::pipeline::resolve`]; this module only expands
//! entries into values and curve descriptions.

use super::reader::{self, Reader};
use super::{Pending, SceneCurve, Spec, default_colour, read_curve_entry, read_style};
use crate::model::fit::By;
use crate::model::grid;
use crate::problem::{join_index, join_key};
use crate::spec::curve::{self, Fitted, Label, Model, ParamKind, ParamSpec, ParamValue, symbol};
use crate::spec::json::{Node, Value};

/// Most curves one scene may expand to (docs/contracts.md).
pub const MAX_CURVES_PER_SCENE: usize = 10_000;

/// Keys of a sweep object: `{"range": [start, stop, step]}` or `{"linspace": [start, stop, count]}`.
pub const SWEEP_KEYS: &[&str] = &["range", "linspace"];
/// The key of a Beckmann-to-Phong conversion (`"alpha_p": {"from_beckmann": …}`).
pub const FROM_BECKMANN_KEY: &str = "from_beckmann";
/// The one parameter that takes a Beckmann-to-Phong conversion: Phong's exponent.
pub const FROM_BECKMANN_PARAM: &str = "alpha_p";
/// The key of a fitted parameter (`{"fit": {…}}`).
pub const FIT_KEY: &str = "fit";
/// Keys of a fit object.
pub const FIT_KEYS: &[&str] = &["target", "by"];

/// One value a swept parameter takes, with its legend text.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepValue {
    /// The parameter value.
    pub value: ParamValue,
    /// Legend text for this value, e.g. `α_b = 0.4` or `α_p = 10.5 (α_b = 0.4)`.
    pub label: String,
}

/// The values of one parameter of a scene curve.
#[derive(Debug, Clone, PartialEq)]
pub struct Sweep {
    /// Values in the order written.
    pub values: Vec<SweepValue>,
    /// True when written as a list, range or conversion, so its value belongs in legend labels.
    pub varies: bool,
}

/// Expands the node of parameter `name` (of `kind`) at `path`; problems go to `reader`.
pub fn expand(
    reader: &mut Reader,
    name: &'static str,
    kind: ParamKind,
    node: &Node,
    path: &str,
) -> Option<Sweep> {
    let label = |v: f64| format!("{} = {}", symbol(name), crate::spec::numbers::pretty(v));
    match (&node.value, kind) {
        (Value::Bool(b), ParamKind::Flag) => Some(Sweep {
            values: vec![SweepValue {
                value: ParamValue::Flag(*b),
                label: format!("{name} = {b}"),
            }],
            varies: false,
        }),
        (Value::Object(_), ParamKind::Number)
            if name == FROM_BECKMANN_PARAM && has_key(node, FROM_BECKMANN_KEY) =>
        {
            from_beckmann(reader, node, path)
        }
        (_, ParamKind::Number) => {
            let (numbers, varies) = numbers(reader, node, path)?;
            let values = numbers
                .into_iter()
                .map(|v| SweepValue {
                    value: ParamValue::Number(v),
                    label: label(v),
                })
                .collect();
            Some(Sweep { values, varies })
        }
        (Value::Array(items), ParamKind::Flag) if !items.is_empty() => {
            let mut values = Vec::new();
            for (i, item) in items.iter().enumerate() {
                match item.value {
                    Value::Bool(b) => values.push(SweepValue {
                        value: ParamValue::Flag(b),
                        label: format!("{name} = {b}"),
                    }),
                    _ => reader.report(
                        join_index(path, i),
                        format!("expected true or false (got {item})"),
                    ),
                }
            }
            (values.len() == items.len()).then_some(Sweep {
                values,
                varies: true,
            })
        }
        _ => {
            reader.report(
                path,
                format!("expected true, false or a list of them (got {node})"),
            );
            None
        }
    }
}

fn has_key(node: &Node, key: &str) -> bool {
    matches!(&node.value, Value::Object(members) if members.iter().any(|(k, _)| k == key))
}

/// Reads a number, a non-empty list of numbers or `{"range": [a, b, s]}`; the flag says whether
/// the value was written as a list or range.
fn numbers(reader: &mut Reader, node: &Node, path: &str) -> Option<(Vec<f64>, bool)> {
    match &node.value {
        Value::Number(n) => Some((vec![n.value], false)),
        Value::Array(items) if items.is_empty() => {
            reader.report(path, "empty list: a sweep needs at least one value (got [], expected a number or a non-empty list)");
            None
        }
        Value::Array(items) if items.len() > MAX_CURVES_PER_SCENE => {
            reader.report(
                path,
                format!(
                    "list too long (got {} values, expected at most {MAX_CURVES_PER_SCENE})",
                    items.len()
                ),
            );
            None
        }
        Value::Array(items) => {
            let mut values = Vec::with_capacity(items.len());
            for (i, item) in items.iter().enumerate() {
                match &item.value {
                    Value::Number(n) => values.push(n.value),
                    other => reader.report(
                        join_index(path, i),
                        format!("expected a number (got {} {item})", other.kind()),
                    ),
                }
            }
            (values.len() == items.len()).then_some((values, true))
        }
        Value::Object(_) => {
            let object = reader.object(node, path, SWEEP_KEYS)?;
            if object.get("range").is_some() && object.get("linspace").is_some() {
                reader.report(
                    path,
                    "keys range, linspace cannot be combined (expected one of them)",
                );
                return None;
            }
            if let Some(linspace_node) = object.get("linspace") {
                return linspace(reader, linspace_node, &join_key(path, "linspace"))
                    .map(|v| (v, true));
            }
            let Some(range_node) = object.get("range") else {
                reader.report(path, format!("expected a number, a list, {{\"range\": [start, stop, step]}} or {{\"linspace\": [start, stop, count]}} (got {node})"));
                return None;
            };
            range(
                reader,
                range_node,
                &join_key(path, "range"),
                MAX_CURVES_PER_SCENE,
            )
            .map(|v| (v, true))
        }
        other => {
            reader.report(path, format!("expected a number, a list or {{\"range\": [start, stop, step]}} (got {} {node})", other.kind()));
            None
        }
    }
}

/// Reads `[start, stop, step]` at `path` as Mathematica's exact `Range` (docs/contracts.md), at most
/// `cap` values.
pub(super) fn range(reader: &mut Reader, node: &Node, path: &str, cap: usize) -> Option<Vec<f64>> {
    let Value::Array(items) = &node.value else {
        reader.report(path, format!("expected [start, stop, step] (got {node})"));
        return None;
    };
    let literals: Vec<_> = items
        .iter()
        .filter_map(|item| match &item.value {
            Value::Number(n) => Some(n),
            _ => None,
        })
        .collect();
    let [start, stop, step] = literals[..] else {
        reader.report(
            path,
            format!("expected [start, stop, step] of three numbers (got {node})"),
        );
        return None;
    };
    if items.len() != 3 {
        reader.report(
            path,
            format!("expected [start, stop, step] of three numbers (got {node})"),
        );
        return None;
    }
    let decimals = start.decimals().zip(step.decimals()).map(|(a, s)| a.max(s));
    match grid::range(start.value, stop.value, step.value, decimals, cap) {
        Ok(values) => Some(values),
        Err(error) => {
            reader.report(path, format!("{error} (got {node})"));
            None
        }
    }
}

/// The numbers of an array node, in order (non-numbers skipped; callers check the count).
pub(super) fn number_items(node: &Node) -> Vec<f64> {
    match &node.value {
        Value::Array(items) => items
            .iter()
            .filter_map(|item| match &item.value {
                Value::Number(n) => Some(n.value),
                _ => None,
            })
            .collect(),
        _ => Vec::new(),
    }
}

/// numpy's `linspace(start, stop, count)`, both ends included, 1 ≤ count ≤ the scene cap.
fn linspace(reader: &mut Reader, node: &Node, path: &str) -> Option<Vec<f64>> {
    let numbers = number_items(node);
    match numbers[..] {
        [start, stop, count]
            if count.fract() == 0.0 && (1.0..=MAX_CURVES_PER_SCENE as f64).contains(&count) =>
        {
            Some(grid::linspace(start, stop, count as usize))
        }
        _ => {
            reader.report(path, format!("expected [start, stop, count] with a whole count from 1 to {MAX_CURVES_PER_SCENE} (got {node})"));
            None
        }
    }
}

/// α_p = 2/α_b² − 2 for α_b ∈ (0, 1] (Walter et al. 2007); beyond 1 the exponent would be negative.
pub fn phong_from_beckmann(alpha_b: f64) -> Option<f64> {
    (alpha_b > 0.0 && alpha_b <= 1.0).then(|| 2.0 / (alpha_b * alpha_b) - 2.0)
}

fn from_beckmann(reader: &mut Reader, node: &Node, path: &str) -> Option<Sweep> {
    let object = reader.object(node, path, &[FROM_BECKMANN_KEY])?;
    let inner_path = join_key(path, FROM_BECKMANN_KEY);
    let (alphas, _) = numbers(reader, object.get(FROM_BECKMANN_KEY)?, &inner_path)?;
    let mut values = Vec::with_capacity(alphas.len());
    for alpha_b in alphas {
        match phong_from_beckmann(alpha_b) {
            Some(alpha_p) => values.push(SweepValue {
                value: ParamValue::Number(alpha_p),
                label: format!(
                    "α_p = {} (α_b = {})",
                    crate::spec::numbers::significant(alpha_p, crate::spec::numbers::LEGEND_DIGITS),
                    crate::spec::numbers::pretty(alpha_b)
                ),
            }),
            None => reader.report(
                inner_path.clone(),
                format!("Beckmann-to-Phong conversion needs 0 < α_b ≤ 1 (got {alpha_b:?}, α_p = 2/α_b² − 2 would be negative or infinite)"),
            ),
        }
    }
    Some(Sweep {
        values,
        varies: true,
    })
}

/// Whether a parameter node asks for a fit (`{"fit": {…}}`).
pub fn is_fit(node: &Node) -> bool {
    has_key(node, FIT_KEY)
}

/// Reads `{"fit": {"target": <curve or sweep>, "by": "peak"|"max"|"l2"}}` (default `peak`), the
/// node of parameter `free` of the curve entry at `entry_path`, a curve of `model`: one
/// [`Fitted`] per target curve, each also listed in the reader's pending work. The curve's other
/// parameters, `sweeps` (the entry at `free` is ignored), are the fit's fixed keys and must each
/// have a single value. The target is expanded like any scene curve entry. Nothing is fitted here.
pub fn fit(
    reader: &mut Reader,
    model: Model,
    params: &[ParamSpec],
    sweeps: &[&Sweep],
    free: usize,
    node: &Node,
    entry_path: &str,
) -> Option<Vec<Fitted>> {
    let at = join_key(entry_path, params[free].name);
    let path = at.as_str();
    let Model::Ndf(family) = model else {
        reader.report(
            path,
            format!(
                "only NDF parameters can be fitted (got {} \"{}\", expected an ndf curve)",
                model.key(),
                model.name()
            ),
        );
        return None;
    };
    let object = reader.object(node, path, &[FIT_KEY])?;
    let fit_path = object.path_of(FIT_KEY);
    let spec = reader.object(object.get(FIT_KEY)?, &fit_path, FIT_KEYS)?;
    let names: Vec<&'static str> = By::ALL.iter().map(|b| b.name()).collect();
    let by = match (spec.get("by"), reader.choice(&spec, "by", &names)) {
        (None, _) => By::Peak,
        (Some(_), Some(name)) => By::from_name(name).expect("choice() returns one of the names"),
        (Some(_), None) => return None,
    };
    let Some(target_node) = spec.get("target") else {
        reader.report(&fit_path, "missing \"target\": the curve or sweep to fit");
        return None;
    };
    let mut fixed = Vec::new();
    for (j, (param, sweep)) in params.iter().zip(sweeps).enumerate() {
        if j == free {
            continue;
        }
        match sweep.values[..] {
            [SweepValue { value, .. }] => fixed.push((param.name.to_string(), value.number())),
            _ => {
                reader.report(
                    path,
                    format!(
                        "a fitted parameter needs the curve's other parameters fixed (got {} values of {}, expected one)",
                        sweep.values.len(),
                        param.name
                    ),
                );
                return None;
            }
        }
    }
    let mut targets = Vec::new();
    let before = reader.problems.len();
    read_curve_entry(
        reader,
        target_node,
        &join_key(&fit_path, "target"),
        &mut targets,
    );
    if reader.problems.len() > before {
        return None;
    }
    let fits: Vec<Fitted> = targets
        .into_iter()
        .map(|target| Fitted {
            family,
            free,
            fixed: fixed.clone(),
            by,
            target: target.curve,
            target_label: target.label,
            path: entry_path.to_string(),
        })
        .collect();
    reader
        .pending
        .extend(fits.iter().map(|fit| Pending::Fit(Box::new(fit.clone()))));
    Some(fits)
}

/// Expands a metal's Fresnel entry (`{"fresnel": "exact", "metal": …, "wavelength_nm": …}`, the
/// metal a name or a list, the wavelength a number, list or range, see [`curve::metal_keys`]) into
/// `out`, one curve per metal and wavelength, the later key varying fastest. Labels name the model,
/// metal and wavelength (`exact, Au 550 nm`); a `label` may use `{metal}` and `{wavelength_nm}`.
pub fn metal_entry(reader: &mut Reader, node: &Node, path: &str, out: &mut Vec<SceneCurve<Spec>>) {
    let Some(keys) = reader.accept(curve::metal_keys(node, path, super::CURVE_EXTRA_KEYS, true))
    else {
        return;
    };
    let Some((entry, template)) = super::entry_with_label(reader, node, path) else {
        return;
    };
    let wavelength_path = join_key(path, curve::WAVELENGTH_KEY);
    let Some(wavelengths) = expand(
        reader,
        curve::WAVELENGTH_KEY,
        ParamKind::Number,
        keys.wavelength,
        &wavelength_path,
    ) else {
        return;
    };
    let Some(style) = read_style(reader, &entry, default_colour(keys.model)) else {
        return;
    };
    let metal_node = match &node.value {
        Value::Object(members) => members
            .iter()
            .find(|(k, _)| k == curve::METAL_KEY)
            .map(|(_, n)| n),
        _ => None,
    };
    let wavelength_first =
        metal_node.is_some_and(|m| (keys.wavelength.line, keys.wavelength.col) < (m.line, m.col));
    let mut pairs = Vec::new();
    if wavelength_first {
        for w in &wavelengths.values {
            pairs.extend(keys.metals.iter().map(|&m| (m, w.value.number())));
        }
    } else {
        for &m in &keys.metals {
            pairs.extend(wavelengths.values.iter().map(|w| (m, w.value.number())));
        }
    }
    let count = pairs.len();
    for (k, (metal, wavelength)) in pairs.into_iter().enumerate() {
        let Some((curve, label)) = reader
            .accept(curve::metal_curve(keys.model, metal, wavelength, path).map_err(|p| vec![p]))
        else {
            return;
        };
        let text = match &template {
            Some(template) => template
                .replace("{metal}", metal.symbol())
                .replace("{wavelength_nm}", &crate::spec::numbers::pretty(wavelength)),
            None => label,
        };
        out.push(labelled_member(curve, text, style, k, count));
    }
}

/// Member `k` of `count` curves an entry expands into, labelled with the finished `text` (no
/// placeholder left to fill) and styled as the sweep's member `k`.
fn labelled_member(
    curve: curve::CurveSpec,
    text: String,
    style: crate::spec::look::Style,
    k: usize,
    count: usize,
) -> SceneCurve<Spec> {
    SceneCurve {
        curve,
        label: Label::Template {
            template: text,
            values: vec![],
        },
        style: super::sweep_style(style, k, count),
    }
}

/// Expands a published-fit entry (`{"published": …, "material": …, "channel": …}`, material and
/// channel each a name or a list, see [`curve::published`]) into `out`, one curve per fit. Labels
/// name the source, the material when several are listed and the channel; a `label` may use
/// `{source}`, `{material}` and `{channel}`.
pub fn published_entry(
    reader: &mut Reader,
    node: &Node,
    path: &str,
    out: &mut Vec<SceneCurve<Spec>>,
) {
    let extra: Vec<&str> = super::CURVE_EXTRA_KEYS
        .iter()
        .chain(crate::spec::quantity::KEYS)
        .copied()
        .collect();
    let Some(choices) = reader.accept(curve::published(node, path, &extra)) else {
        return;
    };
    let Some((entry, template)) = super::entry_with_label(reader, node, path) else {
        return;
    };
    let Some(first) = choices.first() else { return };
    let Some(style) = read_style(
        reader,
        &entry,
        default_colour(Model::Ndf(first.preset.source().family())),
    ) else {
        return;
    };
    let count = choices.len();
    for (k, choice) in choices.into_iter().enumerate() {
        let preset = choice.preset;
        let text = match &template {
            Some(template) => template
                .replace("{source}", preset.source().name())
                .replace("{material}", preset.material())
                .replace("{channel}", preset.channel().map_or("", |c| c.name())),
            None => choice.label,
        };
        let Some(curve) = reader.accept(curve::published_showing(node, path, preset)) else {
            return;
        };
        out.push(labelled_member(curve, text, style, k, count));
    }
}

/// Expands a difference entry `{"difference": "minus"|"ratio", "a": …, "b": …}` at `path` into
/// `out`: a and b are curve entries (possibly swept) of the same kind, paired element-wise (equal
/// numbers of curves, or one curve against a sweep). Labels are `<a> − <b>` or `<a> / <b>` unless
/// the entry's `label` template says otherwise (`{a}` and `{b}` stand for the operands' labels).
pub fn difference_entry(
    reader: &mut Reader,
    node: &Node,
    path: &str,
    out: &mut Vec<SceneCurve<Spec>>,
) {
    let (op, a_node, b_node) = match curve::difference_parts(node, path, super::CURVE_EXTRA_KEYS) {
        Ok(parts) => parts,
        Err(problems) => {
            reader.problems.extend(problems);
            return;
        }
    };
    let (mut a, mut b) = (Vec::new(), Vec::new());
    let before = reader.problems.len();
    read_curve_entry(reader, a_node, &join_key(path, "a"), &mut a);
    read_curve_entry(reader, b_node, &join_key(path, "b"), &mut b);
    if reader.problems.len() > before || a.is_empty() || b.is_empty() {
        return;
    }
    if !pairs(reader, path, a.len(), b.len()) {
        return;
    }
    let Value::Object(members) = &node.value else {
        return;
    };
    let entry = reader::Object::from_members(members, path);
    let template = reader.text(&entry, "label");
    let Some(style) = read_style(reader, &entry, default_colour(a[0].curve.model())) else {
        return;
    };
    let count = a.len().max(b.len());
    let sign = op.sign();
    for k in 0..count {
        let (x, y) = (&a[k.min(a.len() - 1)], &b[k.min(b.len() - 1)]);
        let curve = match curve::difference(op, x.curve.clone(), y.curve.clone(), path) {
            Ok(curve) => curve,
            Err(problem) => {
                reader.problems.push(problem);
                return;
            }
        };
        out.push(SceneCurve {
            curve,
            label: Label::Difference {
                template: template.clone(),
                sign,
                a: Box::new(x.label.clone()),
                b: Box::new(y.label.clone()),
            },
            style: super::sweep_style(style, k, count),
        });
    }
}

/// Whether `a` and `b` operands of a difference at `path` pair element-wise: equal numbers, or one
/// against a sweep. Otherwise reports it and returns `false`.
pub fn pairs(reader: &mut Reader, path: &str, a: usize, b: usize) -> bool {
    let paired = a == b || a == 1 || b == 1;
    if !paired {
        reader.report(
            path,
            format!(
                "a and b pair element-wise (got {a} and {b} curves, expected equal numbers, or one curve against a sweep)"
            ),
        );
    }
    paired
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spec::json;

    fn run(text: &str, name: &'static str) -> (Option<Sweep>, Vec<String>) {
        let node = json::parse(text).unwrap();
        let mut reader = Reader::default();
        let sweep = expand(&mut reader, name, ParamKind::Number, &node, "p");
        (
            sweep,
            reader
                .problems
                .iter()
                .map(|p| format!("{}: {}", p.at, p.message))
                .collect(),
        )
    }

    fn numbers_of(sweep: &Sweep) -> Vec<f64> {
        sweep.values.iter().map(|v| v.value.number()).collect()
    }

    #[test]
    fn ranges_lists_and_conversions() {
        let (sweep, _) = run(r#"{"range": [0.4, 1.0, 0.1]}"#, "alpha_b");
        assert_eq!(
            numbers_of(&sweep.unwrap()),
            [0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0]
        );
        let (sweep, _) = run("[1, 10, 100]", "alpha_abc1");
        let sweep = sweep.unwrap();
        assert_eq!(
            (numbers_of(&sweep), sweep.varies),
            (vec![1.0, 10.0, 100.0], true)
        );
        assert_eq!(sweep.values[1].label, "a₁ = 10");
        let (sweep, _) = run(
            r#"{"from_beckmann": {"range": [0.2, 0.5, 0.1]}}"#,
            "alpha_p",
        );
        let sweep = sweep.unwrap();
        assert_eq!(numbers_of(&sweep)[0], 2.0 / (0.2 * 0.2) - 2.0);
        assert_eq!(sweep.values[2].label, "α_p = 10.5 (α_b = 0.4)");
    }

    #[test]
    fn bad_sweeps_are_reported_at_their_path() {
        for (text, needle) in [
            ("[]", "empty list"),
            (r#"{"range": [0, 1, 0]}"#, "step must not be 0"),
            (r#"{"range": [0, 1, -0.1]}"#, "away from stop"),
            (r#"{"range": [0, 1e9, 1e-9]}"#, "exceed the cap"),
            (r#"{"range": [0, 1]}"#, "three numbers"),
            (r#"{"rang": [0, 1, 0.1]}"#, "did you mean \"range\""),
            (r#"{"from_beckmann": 1.2}"#, "0 < α_b ≤ 1"),
            (r#"["a"]"#, "p[0]: expected a number"),
        ] {
            let (_, problems) = run(text, "alpha_p");
            assert!(
                problems.iter().any(|p| p.contains(needle)),
                "{text}: {problems:?}"
            );
        }
    }
}
