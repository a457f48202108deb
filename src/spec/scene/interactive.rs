//! Interactive scenes: sliders declared under the scene's `interactive` key drive curve
//! parameters written as slider references; the page (`crate::output::html`) evaluates the curves
//! live in the browser as the sliders move.
//!
//! ```json
//! "interactive": {"params": [{"name": "a", "label": "α_b", "range": [0.1, 1.0], "start": 0.3}]},
//! "panels": [{"curves": [{"ndf": "beckmann", "alpha_b": {"slider": "a"}},
//!                        {"ndf": "phong", "alpha_p": {"from_beckmann": {"slider": "a"}}}]}]
//! ```
//!
//! A slider is continuous over `range: [min, max]`, opens at `start` (default: min), and moves
//! on a log scale where `scale` says so (default: log when 0 < min and max ≥ 10 min, i.e. the range
//! spans a decade or more). A reference `{"slider": "a"}` stands for a curve parameter's value, or
//! for α_b inside `from_beckmann`. The static outputs show the start values: references are
//! resolved by substituting them into the document and reading it as usual. Every entry is also
//! read at each corner of its sliders' ranges (every domain here is an interval, and α_p =
//! 2/α_b² − 2 is monotone), so that the whole slider range is valid; what the page can evaluate
//! (NDFs and the Fresnel models of `maths.js`) is checked here too. This module owns the
//! declaration, the references and the bindings; it evaluates nothing.

use super::reader::{Object, Reader};
use super::{SceneCurve, ScenePanel, Spec, data, read_curve_entry};
use crate::model::fresnel::Fresnel;
use crate::problem::{Problem, join_index, join_key, suggestion};
use crate::spec::curve::{CurveSpec, Label, Model, symbol};
use crate::spec::json::{Node, Number, Value};
use crate::spec::look::{PanelKind, Scale};
use crate::spec::scene::sweep::FROM_BECKMANN_KEY;
use std::borrow::Cow;

/// Most sliders one scene may declare (the notebooks use up to four).
pub const MAX_SLIDERS: usize = 6;
/// A range spanning at least this ratio (a decade) moves on a log scale unless `scale` says otherwise.
const LOG_SCALE_MIN_RATIO: f64 = 10.0;
/// Keys of the scene's `interactive` object.
pub const INTERACTIVE_KEYS: &[&str] = &["params"];
/// Keys of one slider declaration.
pub const PARAM_KEYS: &[&str] = &["name", "label", "range", "start", "scale"];
/// Accepted values of a slider's `scale`.
pub const SCALES: &[&str] = &["linear", "log"];
/// The key of a slider reference, `{"slider": "<name>"}`.
pub const SLIDER_KEY: &str = "slider";

/// One continuous slider.
#[derive(Debug, Clone, PartialEq)]
pub struct Slider {
    /// Name used by references, `^[a-z][a-z0-9_]{0,31}$`.
    pub name: String,
    /// Text shown next to the slider (default: the name).
    pub label: String,
    /// The low end of the range.
    pub min: f64,
    /// The high end of the range (> min).
    pub max: f64,
    /// The value the page opens at, in [min, max].
    pub start: f64,
    /// How the slider's position maps to its value: linear, or log (then 0 < min).
    pub scale: Scale,
}

/// A curve parameter driven by a slider.
#[derive(Debug, Clone, PartialEq)]
pub struct Binding {
    /// The parameter's canonical name (a member of the curve's canonical JSON).
    pub param: String,
    /// Index into [`Interactive::sliders`].
    pub slider: usize,
    /// Whether the slider gives α_b and the parameter is α_p = 2/α_b² − 2 (`from_beckmann`).
    pub from_beckmann: bool,
}

/// One curve entry of the interactive panel: the curve it gives at the start values is the
/// panel's curve of the same index.
#[derive(Debug, Clone, PartialEq)]
pub struct Entry {
    /// The parameters sliders drive; empty for a static curve.
    pub bindings: Vec<Binding>,
    /// The legend label as a template: `{param}` stands for a parameter's value, `{=slider}` for
    /// a slider's value, `{l2}` for a Belcour reconstruction's `l2_grid` (two decimals).
    pub label: String,
}

/// The interactive part of a scene: its sliders and its one panel's entries.
#[derive(Debug, Clone, PartialEq)]
pub struct Interactive {
    /// Sliders in declaration order.
    pub sliders: Vec<Slider>,
    /// Curve entries in panel order, one per curve of the panel.
    pub entries: Vec<Entry>,
}

/// Reads the scene's `interactive` key: `None` when absent or invalid (reported).
pub fn read_sliders(reader: &mut Reader, scene: &Object) -> Option<Vec<Slider>> {
    let node = scene.get("interactive")?;
    let path = scene.path_of("interactive");
    let object = reader.object(node, &path, INTERACTIVE_KEYS)?;
    let params_path = object.path_of("params");
    let items = match object.get("params").map(|n| &n.value) {
        Some(Value::Array(items)) if !items.is_empty() && items.len() <= MAX_SLIDERS => items,
        Some(Value::Array(items)) => {
            reader.report(
                params_path,
                format!("expected 1 to {MAX_SLIDERS} sliders (got {})", items.len()),
            );
            return None;
        }
        Some(_) => {
            reader.report(params_path, "expected a list of sliders");
            return None;
        }
        None => {
            reader.report(path, "missing \"params\": the list of sliders");
            return None;
        }
    };
    let before = reader.problems.len();
    let mut sliders: Vec<Slider> = Vec::with_capacity(items.len());
    for (i, item) in items.iter().enumerate() {
        let item_path = join_index(&params_path, i);
        if let Some(slider) = read_slider(reader, item, &item_path) {
            if sliders.iter().any(|s| s.name == slider.name) {
                reader.report(
                    join_key(&item_path, "name"),
                    format!("duplicate slider name (got \"{}\")", slider.name),
                );
            }
            sliders.push(slider);
        }
    }
    (reader.problems.len() == before).then_some(sliders)
}

fn valid_name(name: &str) -> bool {
    let bytes = name.as_bytes();
    (1..=32).contains(&bytes.len())
        && bytes[0].is_ascii_lowercase()
        && bytes
            .iter()
            .all(|&b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'_')
}

fn read_slider(reader: &mut Reader, node: &Node, path: &str) -> Option<Slider> {
    let object = reader.object(node, path, PARAM_KEYS)?;
    let name = match reader.string(&object, "name") {
        Some(name) if valid_name(&name) => Some(name),
        Some(name) => {
            reader.report(
                object.path_of("name"),
                format!(
                    "invalid slider name (got \"{}\", expected ^[a-z][a-z0-9_]{{0,31}}$)",
                    crate::problem::excerpt(&name)
                ),
            );
            None
        }
        None => {
            if object.get("name").is_none() {
                reader.report(path, "missing \"name\": the name curve parameters refer to");
            }
            None
        }
    };
    let label = reader.text(&object, "label");
    if object.get("range").is_none() {
        reader.report(
            path,
            "missing \"range\": [min, max], the values the slider spans",
        );
    }
    let (min, max) = reader.interval(&object, "range", f64::is_finite, "both finite")?;
    let scale = match reader.choice(&object, "scale", SCALES) {
        Some("log") if min <= 0.0 => {
            reader.report(
                object.path_of("scale"),
                format!("a log slider needs 0 < min (got min {min:?})"),
            );
            return None;
        }
        Some("log") => Scale::Log,
        Some(_) => Scale::Linear,
        None if min > 0.0 && max >= LOG_SCALE_MIN_RATIO * min => Scale::Log,
        None => Scale::Linear,
    };
    let expected = format!("a value within the range [{min:?}, {max:?}]");
    let start = match object.get("start") {
        None => min,
        Some(_) => reader.number(&object, "start", |v| (min..=max).contains(&v), &expected)?,
    };
    let name = name?;
    Some(Slider {
        label: label.unwrap_or_else(|| name.clone()),
        name,
        min,
        max,
        start,
        scale,
    })
}

/// The name under `slider` when `node` is a slider reference (an object with a `slider` key).
fn reference(node: &Node) -> Option<&Node> {
    match &node.value {
        Value::Object(members) => members
            .iter()
            .find(|(k, _)| k == SLIDER_KEY)
            .map(|(_, n)| n),
        _ => None,
    }
}

/// A copy of `node` with every slider reference replaced by the number `value_of(name, path)`
/// gives (keeping the reference's position); `None` from it leaves the reference in place.
fn substitute(
    node: &Node,
    path: &str,
    value_of: &mut dyn FnMut(&Node, &str) -> Option<f64>,
) -> Node {
    if reference(node).is_some() {
        if let Some(v) = value_of(node, path) {
            return Node {
                value: Value::Number(Number {
                    value: v,
                    literal: format!("{v:?}"),
                }),
                ..*node
            };
        }
        return node.clone();
    }
    let value = match &node.value {
        Value::Array(items) => Value::Array(
            items
                .iter()
                .enumerate()
                .map(|(i, n)| substitute(n, &join_index(path, i), value_of))
                .collect(),
        ),
        Value::Object(members) => Value::Object(
            members
                .iter()
                .map(|(k, n)| (k.clone(), substitute(n, &join_key(path, k), value_of)))
                .collect(),
        ),
        other => other.clone(),
    };
    Node { value, ..*node }
}

/// Whether `path` lies strictly inside a curve entry, `panels[p].curves[c].<more>`.
fn inside_curve_entry(path: &str) -> bool {
    let index = |rest: &str| {
        rest.find(']')
            .filter(|&end| end > 0 && rest[..end].bytes().all(|b| b.is_ascii_digit()))
            .map(|end| end + 1)
    };
    let Some(rest) = path.strip_prefix("panels[") else {
        return false;
    };
    let Some(end) = index(rest) else { return false };
    let Some(rest) = rest[end..].strip_prefix(".curves[") else {
        return false;
    };
    index(rest).is_some_and(|end| !rest[end..].is_empty())
}

/// Checks one reference: its keys, its name among `sliders` (with a suggestion) and its place in
/// a curve entry; `Some(slider index)` when valid.
fn check_reference(
    reader: &mut Reader,
    node: &Node,
    path: &str,
    sliders: Option<&[Slider]>,
) -> Option<usize> {
    let object = reader.object(node, path, &[SLIDER_KEY])?;
    let name_path = object.path_of(SLIDER_KEY);
    let Some(Value::String(name)) = object.get(SLIDER_KEY).map(|n| &n.value) else {
        reader.report(name_path, "expected the name of a slider");
        return None;
    };
    if !inside_curve_entry(path) {
        reader.report(
            path,
            "a slider can only drive a curve parameter (inside panels[…].curves[…])",
        );
        return None;
    }
    let Some(sliders) = sliders else {
        reader.report(
            name_path,
            format!(
                "unknown slider (got \"{}\"; the scene declares no \"interactive\" params)",
                crate::problem::excerpt(name)
            ),
        );
        return None;
    };
    let found = sliders.iter().position(|s| &s.name == name);
    if found.is_none() {
        let names: Vec<&str> = sliders.iter().map(|s| s.name.as_str()).collect();
        reader.report(
            name_path,
            format!(
                "unknown slider (got \"{}\", expected one of: {}){}",
                crate::problem::excerpt(name),
                names.join(", "),
                suggestion(name, names.iter().copied())
            ),
        );
    }
    found
}

/// The scene document with every slider reference replaced by its slider's start value, so the
/// rest of the scene reads as a static figure; bad references are reported. Borrows `node` when
/// it holds no reference.
pub fn at_start<'a>(
    reader: &mut Reader,
    node: &'a Node,
    sliders: Option<&[Slider]>,
) -> Cow<'a, Node> {
    let mut found = false;
    let start = substitute(node, "", &mut |reference_node, path| {
        found = true;
        let slider = check_reference(reader, reference_node, path, sliders)?;
        sliders.map(|s| s[slider].start)
    });
    if found {
        Cow::Owned(start)
    } else {
        Cow::Borrowed(node)
    }
}

/// The interactive part of a scene: every entry of the (single) panel with its bindings and label
/// template, each read at every corner of its sliders' ranges. `node` is the original scene
/// document (with references), `panels` the panels as read at the start values. `None` when the
/// scene is not interactive or a problem was reported.
pub fn read(
    reader: &mut Reader,
    node: &Node,
    sliders: Option<Vec<Slider>>,
    panels: Option<&[ScenePanel<Spec>]>,
) -> Option<Interactive> {
    let sliders = sliders?;
    let panels = panels?;
    if panels.len() != 1 || panels[0].axes.kind != PanelKind::Cartesian {
        reader.report(
            "panels",
            format!(
                "an interactive scene has one 2D panel (got {} panels)",
                panels.len()
            ),
        );
        return None;
    }
    let Value::Object(members) = &node.value else {
        return None;
    };
    let scene = Object::from_members(members, "");
    let Value::Array(panel_nodes) = &scene.get("panels")?.value else {
        return None;
    };
    let Value::Object(panel_members) = &panel_nodes[0].value else {
        return None;
    };
    let Value::Array(items) = &Object::from_members(panel_members, "panels[0]")
        .get("curves")?
        .value
    else {
        return None;
    };

    let before = reader.problems.len();
    let mut entries = Vec::with_capacity(items.len());
    for (i, item) in items.iter().enumerate() {
        let path = join_index("panels[0].curves", i);
        if data::is_data(item) {
            reader.report(
                &path,
                "an interactive page draws curves only (got a data series)",
            );
            continue;
        }
        entries.extend(read_entry(reader, item, &path, &sliders));
    }
    for (i, slider) in sliders.iter().enumerate() {
        let drives = entries
            .iter()
            .any(|e| e.bindings.iter().any(|b| b.slider == i));
        if !drives && reader.problems.len() == before {
            reader.report(
                join_index("interactive.params", i),
                format!("slider \"{}\" drives no curve", slider.name),
            );
        }
    }
    (reader.problems.len() == before).then_some(Interactive { sliders, entries })
}

/// The slider a node refers to: `{"slider": name}` with a declared name.
fn slider_of(node: &Node, sliders: &[Slider]) -> Option<usize> {
    match &reference(node)?.value {
        Value::String(name) => sliders.iter().position(|s| &s.name == name),
        _ => None,
    }
}

/// One entry: its bindings (a reference as a parameter's value, or as from_beckmann's α_b), its
/// curve at the start values (exactly one, of a kind the page evaluates), its label template,
/// and its reading at every corner of its sliders' ranges.
fn read_entry(reader: &mut Reader, item: &Node, path: &str, sliders: &[Slider]) -> Option<Entry> {
    let Value::Object(members) = &item.value else {
        return None;
    };
    let mut bindings = Vec::new();
    for (key, value) in members {
        let from_beckmann = match &value.value {
            Value::Object(inner) if inner.len() == 1 && inner[0].0 == FROM_BECKMANN_KEY => {
                Some(&inner[0].1)
            }
            _ => None,
        };
        if let Some(slider) = slider_of(value, sliders) {
            bindings.push(Binding {
                param: key.clone(),
                slider,
                from_beckmann: false,
            });
        } else if let Some(slider) = from_beckmann.and_then(|n| slider_of(n, sliders)) {
            bindings.push(Binding {
                param: key.clone(),
                slider,
                from_beckmann: true,
            });
        } else if mentions_slider(value) {
            reader.report(
                join_key(path, key),
                "a live page drives a parameter's value or from_beckmann's α_b with a slider, nothing nested deeper",
            );
            return None;
        }
    }
    let curves = read_at(reader, item, path, sliders, &|s| sliders[s].start)?;
    let [start] = &curves[..] else {
        reader.report(
            path,
            format!(
                "an interactive entry gives one curve (got {})",
                curves.len()
            ),
        );
        return None;
    };
    if !bindings.is_empty() {
        check_live(reader, start, &bindings, path)?;
    }
    let used: Vec<usize> = bindings.iter().map(|b| b.slider).collect();
    for corner in 0..1usize << used.len() {
        let value_of = |s: usize| match used.iter().position(|&u| u == s) {
            Some(k) if corner >> k & 1 == 1 => sliders[s].max,
            Some(_) => sliders[s].min,
            None => sliders[s].start,
        };
        read_at(reader, item, path, sliders, &value_of)?;
    }
    Some(Entry {
        label: label_template(start, members, sliders),
        bindings,
    })
}

/// Whether a slider reference appears anywhere inside `node`.
fn mentions_slider(node: &Node) -> bool {
    let mut found = false;
    substitute(node, "", &mut |_, _| {
        found = true;
        None
    });
    found
}

/// The entry's curves with every slider `s` at `value_of(s)`; problems are reported with the
/// sliders' values.
fn read_at(
    reader: &mut Reader,
    item: &Node,
    path: &str,
    sliders: &[Slider],
    value_of: &dyn Fn(usize) -> f64,
) -> Option<Vec<SceneCurve<Spec>>> {
    let resolved = substitute(item, path, &mut |r, _| slider_of(r, sliders).map(value_of));
    let mut scratch = Reader {
        data: reader.data.clone(),
        ..Reader::default()
    };
    let mut curves = Vec::new();
    read_curve_entry(&mut scratch, &resolved, path, &mut curves);
    reader.pending.append(&mut scratch.pending);
    if scratch.problems.is_empty() {
        return Some(curves);
    }
    let at: Vec<String> = sliders
        .iter()
        .enumerate()
        .map(|(s, slider)| format!("{} = {:?}", slider.name, value_of(s)))
        .collect();
    reader.problems.extend(
        scratch
            .problems
            .into_iter()
            .map(|p| Problem::new(p.at, format!("{} (at slider {})", p.message, at.join(", ")))),
    );
    None
}

/// Checks that the page can evaluate a slider-driven curve (an NDF, or a Fresnel model of
/// `maths.js`, given by its parameters) and that every bound parameter is one of its members.
fn check_live(
    reader: &mut Reader,
    curve: &SceneCurve<Spec>,
    bindings: &[Binding],
    path: &str,
) -> Option<()> {
    let live = match &curve.curve {
        CurveSpec::Ready(crate::model::curve::Curve::Ndf(_)) | CurveSpec::Belcour(_) => true,
        CurveSpec::Ready(crate::model::curve::Curve::Fresnel(f)) => {
            !matches!(f, Fresnel::Normalized(_))
        }
        _ => false,
    };
    if !live {
        reader.report(
            path,
            format!(
                "a live page evaluates NDF and Fresnel curves given by their parameters (got {})",
                curve.curve.canonical_json()
            ),
        );
        return None;
    }
    let canonical = curve.curve.canonical_json();
    for binding in bindings {
        if !canonical.contains(&format!("\"{}\":", binding.param)) {
            reader.report(
                join_key(path, &binding.param),
                format!("a slider drives a parameter of the curve (got \"{}\", the curve is {canonical})", binding.param),
            );
            return None;
        }
    }
    Some(())
}

/// The legend label of an entry as a template (see [`Entry::label`]): a `label` template as
/// written, or the automatic label of the static figure with every written parameter's value
/// replaced by its placeholder: the family prefix (an NDF's) or model name (a Fresnel curve's),
/// then `symbol = {param}` per parameter in document order, then a Belcour reconstruction's L2.
fn label_template(
    curve: &SceneCurve<Spec>,
    members: &[(String, Node)],
    sliders: &[Slider],
) -> String {
    if let Label::Template { template, .. } = &curve.label {
        return template.clone();
    }
    let canonical = curve.curve.canonical_json();
    let parts: Vec<String> = members
        .iter()
        .filter(|(key, _)| {
            canonical.contains(&format!("\"{key}\":"))
                && !canonical.starts_with(&format!("{{\"{key}\":"))
        })
        .map(|(key, node)| {
            let value = format!("{} = {{{key}}}", symbol(key));
            match &node.value {
                Value::Object(inner) if inner.len() == 1 && inner[0].0 == FROM_BECKMANN_KEY => {
                    let alpha_b = match (&inner[0].1.value, slider_of(&inner[0].1, sliders)) {
                        (_, Some(s)) => format!("{{={}}}", sliders[s].name),
                        (Value::Number(n), None) => crate::spec::numbers::pretty(n.value),
                        _ => String::new(),
                    };
                    format!("{value} (α_b = {alpha_b})")
                }
                _ => value,
            }
        })
        .collect();
    let text = parts.join(", ");
    match curve.curve.model() {
        Model::Ndf(family) => match family.legend_prefix() {
            Some(prefix) => format!("{prefix} {text}"),
            None => text,
        },
        Model::Fresnel(model) => {
            let l2 = if matches!(curve.curve, CurveSpec::Belcour(_)) {
                ", L2 = {l2}"
            } else {
                ""
            };
            format!("{} {text}{l2}", crate::spec::look::literal(model.name()))
                .trim_end()
                .to_string()
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::spec::json;
    use crate::spec::look::Scale;

    fn problems(text: &str) -> Vec<String> {
        let node = json::parse(text).unwrap();
        match super::super::parse(&node, None) {
            Ok(_) => Vec::new(),
            Err(invalid) => invalid
                .problems
                .iter()
                .map(|p| format!("{}: {}", p.at, p.message))
                .collect(),
        }
    }

    fn scene(interactive: &str, curves: &str) -> String {
        format!(
            r#"{{"id": "s", "interactive": {interactive}, "panels": [{{"curves": {curves}}}]}}"#
        )
    }

    #[test]
    fn sliders_bind_parameters_and_the_static_scene_shows_the_start() {
        let text = scene(
            r#"{"params": [{"name": "a", "label": "α_b", "range": [0.05, 1.0], "start": 0.3}, {"name": "p", "range": [0, 200]}]}"#,
            r#"[{"ndf": "beckmann", "alpha_b": {"slider": "a"}}, {"ndf": "phong", "alpha_p": {"from_beckmann": {"slider": "a"}}}, {"ndf": "ggx", "alpha_tr": 0.5}, {"ndf": "phong", "alpha_p": {"slider": "p"}, "label": "P {alpha_p}"}]"#,
        );
        let parsed = super::super::parse(&json::parse(&text).unwrap(), None).unwrap();
        assert_eq!(
            parsed.panels[0].curves[0].curve.canonical_json(),
            r#"{"ndf":"beckmann","alpha_b":0.3}"#
        );
        let interactive = parsed.interactive.unwrap();
        let [a, p] = &interactive.sliders[..] else {
            panic!()
        };
        assert_eq!(
            (a.min, a.max, a.start, a.scale),
            (0.05, 1.0, 0.3, Scale::Log)
        );
        assert_eq!((p.start, p.scale), (0.0, Scale::Linear));
        let labels: Vec<&str> = interactive
            .entries
            .iter()
            .map(|e| e.label.as_str())
            .collect();
        assert_eq!(
            labels,
            [
                "α_b = {alpha_b}",
                "α_p = {alpha_p} (α_b = {=a})",
                "α_{tr} = {alpha_tr}",
                "P {alpha_p}"
            ]
        );
        let phong = &interactive.entries[1].bindings[0];
        assert_eq!(
            (phong.param.as_str(), phong.slider, phong.from_beckmann),
            ("alpha_p", 0, true)
        );
        assert!(interactive.entries[2].bindings.is_empty());
    }

    #[test]
    fn bad_declarations_and_references_are_reported_at_their_path() {
        let one = r#"{"params": [{"name": "a", "range": [0.2, 1.0]}]}"#;
        let beckmann = r#"[{"ndf": "beckmann", "alpha_b": {"slider": "a"}}]"#;
        for (interactive, curves, needle) in [
            (
                one,
                r#"[{"ndf": "beckmann", "alpha_b": {"slider": "b"}}]"#,
                "panels[0].curves[0].alpha_b.slider: unknown slider (got \"b\"",
            ),
            (
                r#"{"params": [{"name": "a", "range": [1.0, 0.2]}]}"#,
                beckmann,
                "interactive.params[0].range: invalid interval",
            ),
            (
                r#"{"params": [{"name": "a", "range": [0.2, 1.0], "start": 1.5}]}"#,
                beckmann,
                "start: out of range (got 1.5, expected a value within the range [0.2, 1.0])",
            ),
            (
                r#"{"params": [{"name": "a", "range": [0, 1.0], "scale": "log"}]}"#,
                beckmann,
                "scale: a log slider needs 0 < min",
            ),
            (
                r#"{"params": [{"name": "a", "rnge": [0.2, 1.0]}]}"#,
                beckmann,
                "did you mean \"range\"",
            ),
            (
                r#"{"params": [{"name": "A", "range": [0.2, 1.0]}]}"#,
                beckmann,
                "invalid slider name",
            ),
            (r#"{"params": []}"#, beckmann, "expected 1 to 6 sliders"),
            (
                r#"{"params": [{"name": "a", "range": [0.2, 1.0]}, {"name": "b", "range": [1, 2]}]}"#,
                beckmann,
                "interactive.params[1]: slider \"b\" drives no curve",
            ),
            (
                r#"{"params": [{"name": "a", "range": [0.5, 1.2]}]}"#,
                r#"[{"ndf": "phong", "alpha_p": {"from_beckmann": {"slider": "a"}}}]"#,
                "0 < α_b ≤ 1 (got 1.2, α_p = 2/α_b² − 2 would be negative or infinite) (at slider a = 1.2)",
            ),
            (
                r#"{"params": [{"name": "a", "range": [0.5, 1.2]}]}"#,
                r#"[{"ndf": "abc", "alpha_abc1": {"fit": {"target": {"ndf": "ggx", "alpha_tr": {"slider": "a"}}}}, "alpha_abc2": 1.75}]"#,
                "alpha_abc1: a live page drives a parameter's value or from_beckmann's α_b",
            ),
            (
                one,
                r#"[{"ndf": "beckmann", "alpha_b": {"slider": "a", "scale": 2}}]"#,
                "alpha_b.scale: unknown key",
            ),
        ] {
            let found = problems(&scene(interactive, curves));
            assert!(
                found.iter().any(|p| p.contains(needle)),
                "{needle}: {found:?}"
            );
        }
        let no_params = r#"{"id": "s", "panels": [{"curves": [{"ndf": "beckmann", "alpha_b": {"slider": "a"}}]}]}"#;
        assert!(
            problems(no_params)
                .iter()
                .any(|p| p.contains("declares no \"interactive\" params"))
        );
        let outside = r#"{"id": "s", "interactive": {"params": [{"name": "a", "range": [0.2, 1.0]}]}, "width": {"slider": "a"}, "panels": [{"curves": [{"ndf": "beckmann", "alpha_b": {"slider": "a"}}]}]}"#;
        assert!(
            problems(outside)
                .iter()
                .any(|p| p.starts_with("width: a slider can only drive a curve parameter"))
        );
        let two_panels = r#"{"id": "s", "interactive": {"params": [{"name": "a", "range": [0.2, 1.0]}]}, "panels": [{"curves": [{"ndf": "beckmann", "alpha_b": {"slider": "a"}}]}, {"curves": [{"ndf": "ggx", "alpha_tr": 0.1}]}]}"#;
        assert!(
            problems(two_panels)
                .iter()
                .any(|p| p.contains("one 2D panel (got 2 panels)"))
        );
    }
}
