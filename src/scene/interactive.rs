//! Interactive scenes: sliders declared under the scene's `interactive` key drive curve
//! parameters written as slider references, and `render` precomputes every curve at every slider
//! position for the HTML page (`crate::output::html`).
//!
//! ```json
//! "interactive": {"params": [{"name": "a", "label": "α_b", "range": [0.1, 1.0, 0.01], "start": 0.3}]},
//! "panels": [{"curves": [{"ndf": "beckmann", "alpha_b": {"slider": "a"}},
//!                        {"ndf": "phong", "alpha_p": {"from_beckmann": {"slider": "a"}}}]}]
//! ```
//!
//! A slider takes `range` ([`crate::grid::range`], exact like a sweep's) or `geomspace`
//! (log-spaced, for parameters spanning decades) and may name a `start` position (default: the
//! first). A reference `{"slider": "a"}` may stand for any number inside a curve entry, also inside
//! a conversion or a fit target; it is resolved by substituting the slider's value into the
//! document and reading the entry as usual, so the static outputs show the start positions and
//! every position is validated (and reported with its JSON path) like a written number. This
//! module owns the declaration, the references and the caps; it evaluates nothing.

use super::reader::{Object, Reader};
use super::{SceneCurve, ScenePanel, Spec, Stage, data, read_curve_entry, sweep};
use crate::json::{Node, Number, Value};
use crate::look::PanelKind;
use crate::problem::{Problem, join_index, join_key, suggestion};
use std::borrow::Cow;

/// Most sliders one scene may declare (the notebooks use up to four).
pub const MAX_SLIDERS: usize = 6;
/// Most positions one slider may have: a range input wider than ~1000 steps moves more than one
/// step per screen pixel.
pub const MAX_POSITIONS_PER_SLIDER: usize = 1001;
/// Most curves one page may precompute, summed over its entries (curves per frame × the product of
/// the positions of the entry's sliders); keeps a page near or below 1 MB.
pub const MAX_PAGE_CURVES: usize = 2000;
/// Significant digits `geomspace` positions are rounded to, so that round values such as 10 are
/// positions exactly; 12 digits keep the spacing log-uniform to 1e-12.
const GEOMSPACE_DIGITS: usize = 12;
/// Relative tolerance for a `start` value to name a position (positions come from decimal
/// arithmetic and rounding; their spacing is far wider than this).
const START_TOLERANCE: f64 = 1e-9;
/// Keys of the scene's `interactive` object.
pub const INTERACTIVE_KEYS: &[&str] = &["params"];
/// Keys of one slider declaration.
pub const PARAM_KEYS: &[&str] = &["name", "label", "range", "geomspace", "start"];
/// The key of a slider reference, `{"slider": "<name>"}`.
pub const SLIDER_KEY: &str = "slider";

/// One slider: its positions and the position the page opens at.
#[derive(Debug, Clone, PartialEq)]
pub struct Slider {
    /// Name used by references, `^[a-z][a-z0-9_]{0,31}$`.
    pub name: String,
    /// Text shown next to the slider (default: the name).
    pub label: String,
    /// The positions' values, in slider order.
    pub values: Vec<f64>,
    /// Index of the start position.
    pub start: usize,
}

/// One curve entry of the interactive panel, resolved at every combination of its sliders.
#[derive(Debug, Clone)]
pub struct Entry<S: Stage = super::Resolved> {
    /// Indices (into [`Interactive::sliders`], ascending) of the sliders the entry references;
    /// empty for a static entry.
    pub sliders: Vec<usize>,
    /// The entry's curves per combination of its sliders' positions, row-major (the last slider
    /// varying fastest); one frame for a static entry.
    pub frames: Vec<Vec<SceneCurve<S>>>,
}

/// The interactive part of a scene: its sliders and its one panel's entries at every position.
#[derive(Debug, Clone)]
pub struct Interactive<S: Stage = super::Resolved> {
    /// Sliders in declaration order.
    pub sliders: Vec<Slider>,
    /// Curve entries in panel order.
    pub entries: Vec<Entry<S>>,
}

impl<S: Stage> Interactive<S> {
    /// Every curve of every slider position: entries in order, each entry's positions in
    /// order, each position's curves in order (the order the page lists them in).
    pub fn curves(&self) -> impl Iterator<Item = &SceneCurve<S>> {
        self.entries.iter().flat_map(|e| e.frames.iter().flatten())
    }
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
    let values = match (object.get("range"), object.get("geomspace")) {
        (Some(_), Some(_)) => {
            reader.report(
                path,
                "a slider has either \"range\" or \"geomspace\", not both",
            );
            None
        }
        (Some(range), None) => sweep::range(
            reader,
            range,
            &object.path_of("range"),
            MAX_POSITIONS_PER_SLIDER,
        ),
        (None, Some(geom)) => geomspace(reader, geom, &object.path_of("geomspace")),
        (None, None) => {
            reader.report(
                path,
                "missing \"range\": [start, stop, step] (or \"geomspace\": [start, stop, count])",
            );
            None
        }
    };
    let values = values.filter(|values| {
        let enough = values.len() >= 2;
        if !enough {
            reader.report(
                path,
                format!("a slider needs at least 2 positions (got {})", values.len()),
            );
        }
        enough
    })?;
    let start = match object.get("start").map(|n| &n.value) {
        None => 0,
        Some(Value::Number(n)) => start_position(reader, &values, n, &object.path_of("start"))?,
        Some(_) => {
            reader.report(
                object.path_of("start"),
                "expected a number: the value the page opens at",
            );
            return None;
        }
    };
    let name = name?;
    Some(Slider {
        label: label.unwrap_or_else(|| name.clone()),
        name,
        values,
        start,
    })
}

/// numpy's `geomspace(start, stop, count)` for 0 < start, stop: log-uniform positions with both
/// ends exact, rounded to [`GEOMSPACE_DIGITS`] significant digits.
fn geomspace(reader: &mut Reader, node: &Node, path: &str) -> Option<Vec<f64>> {
    let numbers = super::sweep::number_items(node);
    let cap = MAX_POSITIONS_PER_SLIDER as f64;
    match numbers[..] {
        [start, stop, count]
            if start > 0.0
                && stop > 0.0
                && start != stop
                && count.fract() == 0.0
                && (2.0..=cap).contains(&count) =>
        {
            let n = count as usize;
            let (log_start, log_stop) = (start.log10(), stop.log10());
            let round = |v: f64| {
                format!("{v:.*e}", GEOMSPACE_DIGITS - 1)
                    .parse()
                    .unwrap_or(v)
            };
            let inner = (1..n - 1).map(|i| {
                round(10f64.powf(log_start + (log_stop - log_start) * i as f64 / (n - 1) as f64))
            });
            Some(
                std::iter::once(start)
                    .chain(inner)
                    .chain(std::iter::once(stop))
                    .collect(),
            )
        }
        [_, _, count] if count.fract() == 0.0 && count > cap => {
            reader.report(path, format!("more slider positions than the cap (got {count}, expected at most {MAX_POSITIONS_PER_SLIDER})"));
            None
        }
        _ => {
            reader.report(path, format!("expected [start, stop, count] with 0 < start ≠ stop and a whole count from 2 to {MAX_POSITIONS_PER_SLIDER} (got {node})"));
            None
        }
    }
}

/// The position whose value is `start` (to [`START_TOLERANCE`]); anything else is reported with
/// the nearest positions.
fn start_position(
    reader: &mut Reader,
    values: &[f64],
    start: &Number,
    path: &str,
) -> Option<usize> {
    let v = start.value;
    let matches =
        |p: f64| (p - v).abs() <= START_TOLERANCE * p.abs().max(v.abs()).max(f64::MIN_POSITIVE);
    if let Some(i) = values.iter().position(|&p| matches(p)) {
        return Some(i);
    }
    let (low, high) = (
        values[0].min(values[values.len() - 1]),
        values[0].max(values[values.len() - 1]),
    );
    let mut sorted: Vec<f64> = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    let above = sorted.partition_point(|&p| p < v);
    let near: Vec<String> = sorted[above.saturating_sub(1)..(above + 1).min(sorted.len())]
        .iter()
        .map(|p| format!("{p:?}"))
        .collect();
    let expected = if (low..=high).contains(&v) {
        format!("a slider position; nearest: {}", near.join(" and "))
    } else {
        format!("a slider position within [{low:?}, {high:?}]")
    };
    reader.report(
        path,
        format!(
            "not a slider position (got {}, expected {expected})",
            start.literal
        ),
    );
    None
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
        sliders.map(|s| s[slider].values[s[slider].start])
    });
    if found {
        Cow::Owned(start)
    } else {
        Cow::Borrowed(node)
    }
}

/// Resolves every curve entry of the (single) panel at every combination of its sliders'
/// positions. `node` is the original scene document (with references), `panels` the panels as
/// read at the start positions. `None` when the scene is not interactive or a problem was reported.
pub fn read(
    reader: &mut Reader,
    node: &Node,
    sliders: Option<Vec<Slider>>,
    panels: Option<&[ScenePanel<Spec>]>,
) -> Option<Interactive<Spec>> {
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
    let mut plans = Vec::with_capacity(items.len());
    let mut total = 0usize;
    for (i, item) in items.iter().enumerate() {
        let path = join_index("panels[0].curves", i);
        if data::is_data(item) {
            reader.report(
                &path,
                "an interactive page draws curves only (got a data series)",
            );
            continue;
        }
        let mut used = Vec::new();
        substitute(item, &path, &mut |r, _| {
            if let Some(Value::String(name)) = reference(r).map(|n| &n.value) {
                used.extend(sliders.iter().position(|s| &s.name == name));
            }
            None
        });
        used.sort_unstable();
        used.dedup();
        let frames: usize = used.iter().map(|&s| sliders[s].values.len()).product();
        total = total.saturating_add(frames);
        plans.push((item, path, used, frames));
    }
    for (i, slider) in sliders.iter().enumerate() {
        if !plans.iter().any(|(_, _, used, _)| used.contains(&i)) {
            reader.report(
                join_index("interactive.params", i),
                format!("slider \"{}\" drives no curve", slider.name),
            );
        }
    }
    if total > MAX_PAGE_CURVES {
        let sizes: Vec<String> = plans
            .iter()
            .map(|(_, _, _, frames)| frames.to_string())
            .collect();
        reader.report(
            "interactive.params",
            format!(
                "the page would precompute up to {total} curves (positions per entry: {}; expected at most {MAX_PAGE_CURVES}: use fewer positions)",
                sizes.join(", ")
            ),
        );
    }
    if reader.problems.len() > before {
        return None;
    }
    let mut entries = Vec::with_capacity(plans.len());
    let mut precomputed = 0;
    for (item, path, used, frames) in plans {
        let entry = read_entry(reader, item, &path, &sliders, used, frames)?;
        precomputed += entry.frames.iter().map(Vec::len).sum::<usize>();
        entries.push(entry);
    }
    if precomputed > MAX_PAGE_CURVES {
        reader.report("interactive.params", format!("the page would precompute {precomputed} curves (expected at most {MAX_PAGE_CURVES})"));
        return None;
    }
    Some(Interactive { sliders, entries })
}

/// Reads one entry at each of its `frames` slider combinations; stops at the first combination
/// with a problem and reports it with the slider values.
fn read_entry(
    reader: &mut Reader,
    item: &Node,
    path: &str,
    sliders: &[Slider],
    used: Vec<usize>,
    frames: usize,
) -> Option<Entry<Spec>> {
    let mut curves_per_frame = Vec::with_capacity(frames);
    for frame in 0..frames {
        let positions = positions(sliders, &used, frame);
        let resolved = substitute(
            item,
            path,
            &mut |r, _| match reference(r).map(|n| &n.value) {
                Some(Value::String(name)) => sliders
                    .iter()
                    .position(|s| &s.name == name)
                    .map(|s| sliders[s].values[positions[s]]),
                _ => None,
            },
        );
        let mut scratch = Reader {
            data: reader.data.clone(),
            ..Reader::default()
        };
        let mut curves = Vec::new();
        read_curve_entry(&mut scratch, &resolved, path, &mut curves);
        reader.pending.append(&mut scratch.pending);
        if !scratch.problems.is_empty() {
            reader.problems.extend(
                scratch
                    .problems
                    .into_iter()
                    .map(|p| at_frame(p, sliders, &used, frame)),
            );
            return None;
        }
        curves_per_frame.push(curves);
    }
    Some(Entry {
        sliders: used,
        frames: curves_per_frame,
    })
}

/// The position of every slider at frame `frame` of an entry driven by the sliders `used`:
/// row-major over them, the last varying fastest; the other sliders at their start.
fn positions(sliders: &[Slider], used: &[usize], frame: usize) -> Vec<usize> {
    let mut positions: Vec<usize> = sliders.iter().map(|s| s.start).collect();
    let mut rest = frame;
    for &s in used.iter().rev() {
        positions[s] = rest % sliders[s].values.len();
        rest /= sliders[s].values.len();
    }
    positions
}

/// `problem`, met at frame `frame` of an entry driven by the sliders `used` (see [`Entry`]), its
/// message ending with the sliders' values there: `… (at slider a = 0.3, b = 2.0)`.
pub fn at_frame(problem: Problem, sliders: &[Slider], used: &[usize], frame: usize) -> Problem {
    let positions = positions(sliders, used, frame);
    let at: Vec<String> = used
        .iter()
        .map(|&s| {
            format!(
                "{} = {:?}",
                sliders[s].name, sliders[s].values[positions[s]]
            )
        })
        .collect();
    Problem::new(
        problem.at,
        format!("{} (at slider {})", problem.message, at.join(", ")),
    )
}

#[cfg(test)]
mod tests {
    use crate::json;

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
    fn sliders_resolve_at_every_position_and_the_static_scene_at_the_start() {
        let text = scene(
            r#"{"params": [{"name": "a", "label": "α_b", "range": [0.2, 1.0, 0.1], "start": 0.3}]}"#,
            r#"[{"ndf": "beckmann", "alpha_b": {"slider": "a"}}, {"ndf": "phong", "alpha_p": {"from_beckmann": {"slider": "a"}}}, {"ndf": "ggx", "alpha_tr": 0.5}]"#,
        );
        let parsed = super::super::parse(&json::parse(&text).unwrap(), None).unwrap();
        assert_eq!(
            parsed.panels[0].curves[0].curve.canonical_json(),
            r#"{"ndf":"beckmann","alpha_b":0.3}"#
        );
        let interactive = parsed.interactive.unwrap();
        assert_eq!(interactive.sliders[0].values.len(), 9);
        assert_eq!(interactive.sliders[0].start, 1);
        let [beckmann, phong, ggx] = &interactive.entries[..] else {
            panic!()
        };
        assert_eq!(
            (beckmann.frames.len(), phong.frames.len(), ggx.frames.len()),
            (9, 9, 1)
        );
        assert_eq!(ggx.sliders, Vec::<usize>::new());
        assert_eq!(
            phong.frames[8][0].curve.canonical_json(),
            r#"{"ndf":"phong","alpha_p":0.0}"#
        );
    }

    #[test]
    fn frames_are_row_major_over_the_sliders_an_entry_uses() {
        let text = scene(
            r#"{"params": [{"name": "a", "geomspace": [1, 1000, 4], "start": 10}, {"name": "b", "range": [0.5, 2.5, 1]}]}"#,
            r#"[{"ndf": "abc", "alpha_abc1": {"slider": "a"}, "alpha_abc2": {"slider": "b"}}]"#,
        );
        let parsed = super::super::parse(&json::parse(&text).unwrap(), None).unwrap();
        let interactive = parsed.interactive.unwrap();
        assert_eq!(interactive.sliders[0].values, [1.0, 10.0, 100.0, 1000.0]);
        let entry = &interactive.entries[0];
        // a at position 2 (100), b at position 1 (1.5): frame 2 · 3 + 1.
        assert_eq!(entry.frames.len(), 12);
        assert_eq!(
            entry.frames[7][0].curve.canonical_json(),
            r#"{"ndf":"abc","alpha_abc1":100.0,"alpha_abc2":1.5}"#
        );
    }

    #[test]
    fn bad_declarations_and_references_are_reported_at_their_path() {
        let one = r#"{"params": [{"name": "a", "range": [0.2, 1.0, 0.1]}]}"#;
        let beckmann = r#"[{"ndf": "beckmann", "alpha_b": {"slider": "a"}}]"#;
        for (interactive, curves, needle) in [
            (
                one,
                r#"[{"ndf": "beckmann", "alpha_b": {"slider": "b"}}]"#,
                "panels[0].curves[0].alpha_b.slider: unknown slider (got \"b\"",
            ),
            (
                r#"{"params": [{"name": "a", "range": [1.0, 0.2, 0.1]}]}"#,
                beckmann,
                "interactive.params[0].range: step points away",
            ),
            (
                r#"{"params": [{"name": "a", "range": [0, 1, 1e-5]}]}"#,
                beckmann,
                "interactive.params[0].range: 100001 values exceed the cap of 1001",
            ),
            (
                r#"{"params": [{"name": "a", "geomspace": [1, 10, 5000]}]}"#,
                beckmann,
                "interactive.params[0].geomspace: more slider positions than the cap",
            ),
            (
                r#"{"params": [{"name": "a", "range": [0.2, 0.2, 0.1]}]}"#,
                beckmann,
                "at least 2 positions",
            ),
            (
                r#"{"params": [{"name": "a", "range": [0.2, 1.0, 0.1], "start": 0.25}]}"#,
                beckmann,
                "start: not a slider position (got 0.25, expected a slider position; nearest: 0.2 and 0.3)",
            ),
            (
                r#"{"params": [{"name": "a", "rnge": [0.2, 1.0, 0.1]}]}"#,
                beckmann,
                "did you mean \"range\"",
            ),
            (
                r#"{"params": [{"name": "A", "range": [0.2, 1.0, 0.1]}]}"#,
                beckmann,
                "invalid slider name",
            ),
            (r#"{"params": []}"#, beckmann, "expected 1 to 6 sliders"),
            (
                r#"{"params": [{"name": "a", "range": [0.2, 1.0, 0.1]}, {"name": "b", "range": [1, 2, 1]}]}"#,
                beckmann,
                "interactive.params[1]: slider \"b\" drives no curve",
            ),
            (
                r#"{"params": [{"name": "a", "range": [0.5, 1.2, 0.1]}]}"#,
                r#"[{"ndf": "phong", "alpha_p": {"from_beckmann": {"slider": "a"}}}]"#,
                "0 < α_b ≤ 1 (got 1.1, α_p = 2/α_b² − 2 would be negative or infinite) (at slider a = 1.1)",
            ),
            (
                r#"{"params": [{"name": "a", "range": [1, 1000, 1]}, {"name": "b", "range": [1, 3, 1]}]}"#,
                r#"[{"ndf": "abc", "alpha_abc1": {"slider": "a"}, "alpha_abc2": {"slider": "b"}}]"#,
                "up to 3000 curves",
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
        let outside = r#"{"id": "s", "interactive": {"params": [{"name": "a", "range": [0.2, 1.0, 0.1]}]}, "width": {"slider": "a"}, "panels": [{"curves": [{"ndf": "beckmann", "alpha_b": {"slider": "a"}}]}]}"#;
        assert!(
            problems(outside)
                .iter()
                .any(|p| p.starts_with("width: a slider can only drive a curve parameter"))
        );
        let two_panels = r#"{"id": "s", "interactive": {"params": [{"name": "a", "range": [0.2, 1.0, 0.1]}]}, "panels": [{"curves": [{"ndf": "beckmann", "alpha_b": {"slider": "a"}}]}, {"curves": [{"ndf": "ggx", "alpha_tr": 0.1}]}]}"#;
        assert!(
            problems(two_panels)
                .iter()
                .any(|p| p.contains("one 2D panel (got 2 panels)"))
        );
    }
}
