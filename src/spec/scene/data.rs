//! Data series entries of a panel (`{"data": …}`): validation into [`DataSpec`]s.
//!
//! `{"data": "spectrum", "quantity": "cumulative", "count": 20}` — the singular-value spectrum;
//! `{"data": "gulbrandsen", "x": "c0", "y": "c2", "z": "c3", "r": <sweep>, "g": <sweep>, "g_remap": false}`
//! — decomposition coefficients over Gulbrandsen's (r, g);
//! `{"data": "albedo", "ndf": "ggx", "map": "r2", "g2": "height-correlated", "value": "loss", "mu": 33, "r": 33}`
//! — the directional albedo E (or 1 − E) with F = 1 over (μ, r) on Cycles' grid, for heat-map and
//! surface panels;
//! `{"data": "audit", "table": "cycles-ggx-e"}` — |engine − exact| over (μ, r) of an engine's
//! table shipped with ndfplot, on the engine's own grid, for heat-map and surface panels (the
//! comparison is computed by [`crate::pipeline::resolve`]);
//! `{"data": "table", "x": [...], "y": [...]}` — literal points;
//! `{"data": "csv", "path": "renderer.csv", "x": "theta", "y": "value", "degrees": false}` — θ and
//! values of a CSV file next to the spec, to overlay on analytic curves; the file is named here
//! ([`CsvFile`]) and read by [`crate::pipeline::resolve`].
//! Every entry also takes `label`, `style`, `colour` (or `color`) and `mark`.
//!
//! A difference entry (`{"difference": …, "a": …, "b": …}`) with a CSV or table series on a side is a
//! data series too ([`read_difference`]): its values exist only where the samples are.

use super::reader::{Object, Reader};
use super::sweep;
use super::{Pending, SceneCurve, SceneData, Spec, read_curve_entry, read_style};
use crate::model::curve::DiffOp;
use crate::model::dataset::{AlbedoValue, Coefficient, Dataset, SpectrumQuantity};
use crate::model::engine_table::PublishedTable;
use crate::model::fresnel::{EDGE_TINT, REFLECTIVITY};
use crate::spec::curve::ParamKind;
use crate::spec::datafile::DataScope;
use crate::spec::json::{Node, Value};
use crate::spec::look::Rgb;
use crate::spec::numbers::pretty;
use std::f64::consts::FRAC_PI_2;

/// Most points one data series may have; a 1000 × 1000 coefficient grid is already far beyond
/// what a figure can show.
pub const MAX_DATA_POINTS: usize = 250_000;

/// Keys every data entry accepts besides its own.
pub const COMMON_KEYS: [&str; 6] = ["data", "label", "style", "colour", "color", "mark"];
/// The kinds of data entry (`"data": <kind>`).
pub const KINDS: &[&str] = &["spectrum", "gulbrandsen", "albedo", "audit", "table", "csv"];
/// NDF families an albedo series takes (`"ndf"`): those whose one parameter is the width α, whose
/// domain holds every α = map(r), r ∈ (0, 1]; the default first.
pub const ALBEDO_FAMILIES: &[&str] = &["ggx", "trowbridge_reitz", "beckmann"];
/// Fewest and most points on each axis of an albedo series (`"mu"`, `"r"`): a 65 × 65 table takes
/// a few seconds (1–3 ms a cell).
pub const ALBEDO_POINTS: (usize, usize) = (2, 65);
/// Points on each axis of an albedo series when `"mu"` or `"r"` is not given.
pub const DEFAULT_ALBEDO_POINTS: usize = 33;

/// Solarized blue, the default colour of data series.
const DATA_COLOUR: u32 = 0x268BD2;

/// A validated data series as the spec describes it.
#[derive(Debug, Clone)]
pub enum DataSpec {
    /// A dataset given in the spec itself (spectrum, Gulbrandsen, table).
    Ready(Dataset),
    /// θ and values of a CSV file, read by resolve into a [`Dataset::Csv`].
    Csv(CsvFile),
    /// A published engine table, compared with the exact one by resolve into a
    /// [`Dataset::Audit`].
    Audit(PublishedTable),
    /// A difference with a sampled side, made a [`Dataset::Difference`] by resolve, which also
    /// writes its label (`<a> <sign> <b>`, or `template` with `{a}` and `{b}` filled in).
    Difference {
        /// How the two values combine.
        op: DiffOp,
        /// The first operand.
        a: Box<SideSpec>,
        /// The second operand.
        b: Box<SideSpec>,
        /// The entry's `label`, if given.
        template: Option<String>,
        /// JSON path of the entry, where a problem of the pair is reported.
        at: String,
    },
}

/// One operand of a difference entry with a sampled side, as the spec describes it.
#[derive(Debug, Clone)]
pub enum SideSpec {
    /// A curve (one member of a sweep), with its label's description.
    Curve(SceneCurve<Spec>),
    /// A CSV or table series of θ, with its label.
    Sampled {
        /// The series.
        data: DataSpec,
        /// Its label.
        label: String,
    },
}

impl DataSpec {
    /// Whether the series' x is θ in radians (see [`Dataset::is_theta`]).
    pub fn is_theta(&self) -> bool {
        match self {
            DataSpec::Ready(dataset) => dataset.is_theta(),
            DataSpec::Csv(_) | DataSpec::Difference { .. } => true,
            DataSpec::Audit(_) => false,
        }
    }

    /// Whether the series is z over a rectilinear grid (see [`Dataset::is_map`]).
    pub fn is_map(&self) -> bool {
        match self {
            DataSpec::Ready(dataset) => dataset.is_map(),
            DataSpec::Audit(_) => true,
            DataSpec::Csv(_) | DataSpec::Difference { .. } => false,
        }
    }

    /// Whether the series has a z coordinate (see [`Dataset::has_z`]).
    pub fn has_z(&self) -> bool {
        match self {
            DataSpec::Ready(dataset) => dataset.has_z(),
            DataSpec::Audit(_) => true,
            DataSpec::Csv(_) | DataSpec::Difference { .. } => false,
        }
    }
}

/// A `{"data": "csv", …}` series: which file and columns to read. Nothing is read at validation.
#[derive(Debug, Clone, PartialEq)]
pub struct CsvFile {
    /// The file as the spec names it (relative to the spec's folder).
    pub path: String,
    /// Where it may be read from: the spec's folder and the folders allowed beside it.
    pub scope: DataScope,
    /// Column holding θ.
    pub x_column: String,
    /// Column holding the values.
    pub y_column: String,
    /// Whether the file's θ are in degrees.
    pub degrees: bool,
    /// JSON path of the entry's `path` key, where a problem reading the file is reported.
    pub at: String,
}

/// Whether a panel entry is a data series (has a `data` key) rather than a curve.
pub fn is_data(node: &Node) -> bool {
    matches!(&node.value, Value::Object(members) if members.iter().any(|(k, _)| k == "data"))
}

/// The keys of a data entry of `kind` (one of [`KINDS`]) besides [`COMMON_KEYS`].
pub fn own_keys(kind: &str) -> &'static [&'static str] {
    match kind {
        "spectrum" => &["quantity", "count"],
        "gulbrandsen" => &["x", "y", "z", "r", "g", "g_remap"],
        "albedo" => &["ndf", "map", "g2", "value", "mu", "r"],
        "audit" => &["table"],
        "csv" => &["path", "x", "y", "degrees"],
        _ => &["x", "y"],
    }
}

fn keys(own: &[&'static str]) -> Vec<&'static str> {
    COMMON_KEYS.iter().chain(own).copied().collect()
}

/// Validates a data entry at `path`; problems go to `reader`, a CSV file to its pending work.
pub fn read_entry(reader: &mut Reader, node: &Node, path: &str) -> Option<SceneData<Spec>> {
    let Value::Object(members) = &node.value else {
        return None;
    };
    let probe = Object::from_members(members, path);
    let kind = reader.choice(&probe, "data", KINDS)?;
    let entry = reader.object(node, path, &keys(own_keys(kind)))?;
    let before = reader.problems.len();
    let dataset = match kind {
        "spectrum" => read_spectrum(reader, &entry).map(DataSpec::Ready),
        "gulbrandsen" => read_gulbrandsen(reader, &entry).map(DataSpec::Ready),
        "albedo" => read_albedo(reader, &entry).map(DataSpec::Ready),
        "audit" => read_audit(reader, &entry),
        "csv" => read_csv(reader, &entry).map(DataSpec::Csv),
        _ => read_table(reader, &entry).map(DataSpec::Ready),
    };
    let style = read_style(reader, &entry, Rgb::from_hex(DATA_COLOUR));
    let label = reader.text(&entry, "label");
    if reader.problems.len() != before {
        return None;
    }
    let dataset = dataset?;
    let label = label.unwrap_or_else(|| default_label(&dataset));
    Some(SceneData {
        dataset,
        label,
        style: style?,
    })
}

/// Validates a `{"data": "csv", …}` series given on its own (a `compare` side) at JSON path `path`
/// (`""` for a whole argument), its file to be read from `scope` but not read. Other data kinds are
/// not functions of θ and are reported.
pub fn parse_csv_series(
    node: &Node,
    path: &str,
    scope: DataScope,
) -> Result<CsvFile, Vec<crate::problem::Problem>> {
    let mut reader = Reader {
        data: Some(scope),
        ..Reader::default()
    };
    let entry = read_entry(&mut reader, node, path);
    match entry.map(|e| e.dataset) {
        Some(DataSpec::Csv(csv)) if reader.problems.is_empty() => Ok(csv),
        Some(DataSpec::Ready(other)) => Err(vec![crate::problem::Problem::new(
            crate::problem::join_key(path, "data"),
            format!(
                "not a series of θ (got {}, expected {{\"data\": \"csv\", \"path\": …}})",
                other.canonical_json()
            ),
        )]),
        _ => Err(reader.problems),
    }
}

/// Whether `node` is a difference entry with a data series on a side (read by [`read_difference`]).
pub fn is_sampled_difference(node: &Node) -> bool {
    crate::spec::curve::is_difference(node)
        && matches!(&node.value, Value::Object(members)
            if members.iter().any(|(k, v)| (k == "a" || k == "b") && is_data(v)))
}

/// Validates a difference entry with a CSV or table series on one side or both at `path`: one data
/// series per member of the other side's sweep (a single curve against a CSV, or a sweep against it,
/// pairs as [`super::sweep::difference_entry`] pairs curves).
pub fn read_difference(reader: &mut Reader, node: &Node, path: &str) -> Vec<SceneData<Spec>> {
    let parts = crate::spec::curve::difference_parts(node, path, super::CURVE_EXTRA_KEYS);
    let Some((op, a_node, b_node)) = reader.accept(parts) else {
        return Vec::new();
    };
    let before = reader.problems.len();
    let a = read_side(reader, a_node, &crate::problem::join_key(path, "a"));
    let b = read_side(reader, b_node, &crate::problem::join_key(path, "b"));
    if reader.problems.len() > before
        || a.is_empty()
        || b.is_empty()
        || !sweep::pairs(reader, path, a.len(), b.len())
    {
        return Vec::new();
    }
    let Value::Object(members) = &node.value else {
        return Vec::new();
    };
    let entry = Object::from_members(members, path);
    let template = reader.text(&entry, "label");
    let colour = [&a[0], &b[0]]
        .iter()
        .find_map(|side| match side {
            SideSpec::Curve(c) => Some(super::default_colour(c.curve.model())),
            SideSpec::Sampled { .. } => None,
        })
        .unwrap_or(Rgb::from_hex(DATA_COLOUR));
    let Some(style) = read_style(reader, &entry, colour) else {
        return Vec::new();
    };
    let count = a.len().max(b.len());
    (0..count)
        .map(|k| SceneData {
            dataset: DataSpec::Difference {
                op,
                a: Box::new(a[k.min(a.len() - 1)].clone()),
                b: Box::new(b[k.min(b.len() - 1)].clone()),
                template: template.clone(),
                at: path.to_string(),
            },
            label: String::new(),
            style: super::sweep_style(style, k, count),
        })
        .collect()
}

/// One side of a difference with a sampled side: a CSV or table series of θ, or a (swept) curve.
fn read_side(reader: &mut Reader, node: &Node, path: &str) -> Vec<SideSpec> {
    if !is_data(node) {
        let mut curves = Vec::new();
        read_curve_entry(reader, node, path, &mut curves);
        return curves.into_iter().map(SideSpec::Curve).collect();
    }
    let Some(entry) = read_entry(reader, node, path) else {
        return Vec::new();
    };
    match &entry.dataset {
        DataSpec::Csv(_) => {}
        DataSpec::Ready(Dataset::Table { x, .. }) => {
            if let Some(bad) = x.iter().find(|t| !(0.0..=FRAC_PI_2).contains(*t)) {
                reader.report(
                    crate::problem::join_key(path, "x"),
                    format!("θ out of range (got {bad:?}, expected radians within [0, π/2])"),
                );
                return Vec::new();
            }
        }
        DataSpec::Ready(other) => {
            reader.report(
                crate::problem::join_key(path, "data"),
                format!(
                    "not a series of θ (got {}, expected {{\"data\": \"csv\", …}} or {{\"data\": \"table\", …}})",
                    other.canonical_json()
                ),
            );
            return Vec::new();
        }
        DataSpec::Difference { .. } => unreachable!("read_entry reads no difference"),
        DataSpec::Audit(table) => {
            reader.report(
                crate::problem::join_key(path, "data"),
                format!(
                    "not a series of θ (got {{\"data\": \"audit\", \"table\": \"{}\"}}, expected {{\"data\": \"csv\", …}} or {{\"data\": \"table\", …}})",
                    table.name()
                ),
            );
            return Vec::new();
        }
    }
    vec![SideSpec::Sampled {
        data: entry.dataset,
        label: entry.label,
    }]
}

fn read_spectrum(reader: &mut Reader, entry: &Object) -> Option<Dataset> {
    let names: Vec<&'static str> = SpectrumQuantity::NAMES.iter().map(|(n, _)| *n).collect();
    let quantity = match entry.get("quantity") {
        None => SpectrumQuantity::Cumulative,
        Some(_) => {
            let name = reader.choice(entry, "quantity", &names)?;
            SpectrumQuantity::NAMES
                .iter()
                .find(|(n, _)| *n == name)
                .map(|(_, q)| *q)?
        }
    };
    let whole = |v: f64| v.fract() == 0.0 && (1.0..=100.0).contains(&v);
    let count = match entry.get("count") {
        None => 20.0,
        Some(_) => reader.number(entry, "count", whole, "a whole number from 1 to 100")?,
    };
    Some(Dataset::Spectrum {
        quantity,
        count: count as usize,
    })
}

fn coefficient(reader: &mut Reader, entry: &Object, key: &str) -> Option<Coefficient> {
    let names: Vec<&'static str> = Coefficient::NAMES.iter().map(|(n, _)| *n).collect();
    let name = reader.choice(entry, key, &names)?;
    Coefficient::NAMES
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, c)| *c)
}

fn values(
    reader: &mut Reader,
    entry: &Object,
    key: &'static str,
    ok: impl Fn(f64) -> bool,
    expected: &str,
) -> Option<Vec<f64>> {
    let Some(node) = entry.get(key) else {
        reader.report(
            entry.path_of(key),
            "missing parameter (expected a number, a list or a sweep)",
        );
        return None;
    };
    let sweep = sweep::expand(reader, key, ParamKind::Number, node, &entry.path_of(key))?;
    let values: Vec<f64> = sweep.values.iter().map(|v| v.value.number()).collect();
    if let Some(bad) = values.iter().find(|&&v| !ok(v)) {
        reader.report(
            entry.path_of(key),
            format!("out of domain (got {bad:?}, expected {expected})"),
        );
        return None;
    }
    Some(values)
}

fn read_gulbrandsen(reader: &mut Reader, entry: &Object) -> Option<Dataset> {
    let x = coefficient(reader, entry, "x");
    let y = coefficient(reader, entry, "y");
    let z = entry.get("z").and_then(|_| coefficient(reader, entry, "z"));
    let [r, g] = [REFLECTIVITY, EDGE_TINT].map(|param| {
        values(
            reader,
            entry,
            param.name,
            |v| param.contains(v),
            &param.interval(),
        )
    });
    let g_remap = reader.boolean(entry, "g_remap").unwrap_or(false);
    if x.is_none() && entry.get("x").is_none() {
        reader.report(
            entry.path_of("x"),
            "missing coefficient (expected c0, c1, c2 or c3)",
        );
    }
    if y.is_none() && entry.get("y").is_none() {
        reader.report(
            entry.path_of("y"),
            "missing coefficient (expected c0, c1, c2 or c3)",
        );
    }
    let (r, g) = (r?, g?);
    if r.len() * g.len() > MAX_DATA_POINTS {
        reader.report(
            entry.path(),
            format!(
                "too many points (got {} × {}, expected at most {MAX_DATA_POINTS})",
                r.len(),
                g.len()
            ),
        );
        return None;
    }
    Some(Dataset::Gulbrandsen {
        x: x?,
        y: y?,
        z,
        r,
        g,
        g_remap,
    })
}

/// Reads `{"data": "albedo", …}`: every key has a default (GGX, α = r², height-correlated G2, E,
/// [`DEFAULT_ALBEDO_POINTS`] on each axis).
fn read_albedo(reader: &mut Reader, entry: &Object) -> Option<Dataset> {
    let family = match entry.get("ndf") {
        None => Some(crate::model::ndf::Family::TrowbridgeReitz),
        Some(_) => reader
            .choice(entry, "ndf", ALBEDO_FAMILIES)
            .and_then(crate::model::ndf::Family::from_name),
    };
    let map = named(
        reader,
        entry,
        "map",
        &crate::model::albedo::RoughnessMap::KEYS,
    );
    let g2 = named(reader, entry, "g2", &crate::model::masking::G2Model::NAMES);
    let value = named(reader, entry, "value", &AlbedoValue::NAMES);
    let (lo, hi) = ALBEDO_POINTS;
    let expected = format!("a whole number from {lo} to {hi}");
    let mut count = |key: &str| match entry.get(key) {
        None => Some(DEFAULT_ALBEDO_POINTS),
        Some(_) => reader
            .number(
                entry,
                key,
                |v| v.fract() == 0.0 && (lo as f64..=hi as f64).contains(&v),
                &expected,
            )
            .map(|v| v as usize),
    };
    let (mu, r) = (count("mu"), count("r"));
    Some(Dataset::Albedo {
        family: family?,
        map: map?,
        g2: g2?,
        value: value?,
        mu: mu?,
        r: r?,
    })
}

/// Reads `{"data": "audit", "table": <name>}`: which published engine table (required).
fn read_audit(reader: &mut Reader, entry: &Object) -> Option<DataSpec> {
    if entry.get("table").is_none() {
        reader.report(
            entry.path_of("table"),
            format!(
                "missing the table to audit (expected one of: {})",
                PublishedTable::NAMES.map(|(n, _)| n).join(", ")
            ),
        );
        return None;
    }
    named(reader, entry, "table", &PublishedTable::NAMES).map(DataSpec::Audit)
}

/// The value of `key` among `names` (JSON name, value), the first when the key is absent.
fn named<T: Copy>(
    reader: &mut Reader,
    entry: &Object,
    key: &str,
    names: &[(&'static str, T)],
) -> Option<T> {
    if entry.get(key).is_none() {
        return Some(names[0].1);
    }
    let choices: Vec<&'static str> = names.iter().map(|(n, _)| *n).collect();
    let name = reader.choice(entry, key, &choices)?;
    names.iter().find(|(n, _)| *n == name).map(|(_, v)| *v)
}

fn read_table(reader: &mut Reader, entry: &Object) -> Option<Dataset> {
    let any = |v: f64| v.is_finite();
    let x = values(reader, entry, "x", any, "finite");
    let y = values(reader, entry, "y", any, "finite");
    let (x, y) = (x?, y?);
    if x.len() != y.len() {
        reader.report(
            entry.path(),
            format!(
                "x and y differ in length (got {} and {} values, expected as many y as x)",
                x.len(),
                y.len()
            ),
        );
        return None;
    }
    Some(Dataset::Table { x, y })
}

/// Reads `{"data": "csv", "path": "file.csv", "x": "theta", "y": "value", "degrees": false}`:
/// which two named columns of which CSV file (with a header row) to read; the file is listed in
/// the reader's pending work and read by resolve.
fn read_csv(reader: &mut Reader, entry: &Object) -> Option<CsvFile> {
    let path = reader.text(entry, "path");
    let x_column = reader.text(entry, "x").unwrap_or_else(|| "theta".into());
    let y_column = reader.text(entry, "y").unwrap_or_else(|| "value".into());
    let degrees = reader.boolean(entry, "degrees").unwrap_or(false);
    let at = entry.path_of("path");
    let Some(path) = path else {
        if entry.get("path").is_none() {
            reader.report(at, "missing the CSV file to read");
        }
        return None;
    };
    let Some(scope) = reader.data.clone() else {
        reader.report(
            at,
            format!(
                "data files need a spec read from disk (got \"{}\" in a built-in or inline spec)",
                crate::problem::excerpt(&path)
            ),
        );
        return None;
    };
    let csv = CsvFile {
        path,
        scope,
        x_column,
        y_column,
        degrees,
        at,
    };
    reader.pending.push(Pending::Csv(csv.clone()));
    Some(csv)
}

fn symbol(c: Coefficient) -> &'static str {
    match c {
        Coefficient::C0 => "c₀",
        Coefficient::C1 => "c₁",
        Coefficient::C2 => "c₂",
        Coefficient::C3 => "c₃",
    }
}

fn default_label(dataset: &DataSpec) -> String {
    let dataset = match dataset {
        DataSpec::Ready(dataset) => dataset,
        DataSpec::Csv(csv) => return csv.path.clone(),
        DataSpec::Audit(table) => return format!("{} − exact", table.title()),
        // Written by resolve, from its operands' labels.
        DataSpec::Difference { .. } => return String::new(),
    };
    match dataset {
        Dataset::Spectrum { quantity, .. } => match quantity {
            SpectrumQuantity::SingularValue => "singular values".into(),
            SpectrumQuantity::Normalized => "s_k / Σ s".into(),
            SpectrumQuantity::Cumulative => "cumulative Σ s_k / Σ s".into(),
        },
        Dataset::Gulbrandsen { g, g_remap, .. } => {
            let tint = if *g_remap { "ḡ" } else { "g" };
            match g.as_slice() {
                [g] => format!("{tint} = {}", pretty(*g)),
                _ => format!("r × {tint} grid"),
            }
        }
        Dataset::Albedo { value, .. } => albedo_symbol(*value).into(),
        Dataset::Table { .. }
        | Dataset::Csv { .. }
        | Dataset::Difference { .. }
        | Dataset::Audit { .. } => "data".into(),
    }
}

/// E or 1 − E, as an albedo series names its value.
fn albedo_symbol(value: AlbedoValue) -> &'static str {
    match value {
        AlbedoValue::Albedo => "E",
        AlbedoValue::Loss => "1 − E",
    }
}

/// Default (x, y) axis labels of a panel whose first series is `dataset`.
pub fn default_labels(dataset: &DataSpec) -> (String, String) {
    let dataset = match dataset {
        DataSpec::Ready(dataset) => dataset,
        DataSpec::Csv(csv) => return (csv.x_column.clone(), csv.y_column.clone()),
        DataSpec::Audit(_) => return ("μ = cos θ_o".into(), "r".into()),
        DataSpec::Difference { op, a, b, .. } => {
            let symbol = [a, b].iter().find_map(|side| match side.as_ref() {
                SideSpec::Curve(c) => Some(c.curve.kind().symbol()),
                SideSpec::Sampled { .. } => None,
            });
            return ("θ (radians)".into(), op.axis_label(symbol));
        }
    };
    match dataset {
        Dataset::Spectrum { .. } => ("index k".into(), "singular values".into()),
        Dataset::Gulbrandsen { x, y, .. } => (symbol(*x).into(), symbol(*y).into()),
        Dataset::Albedo { .. } | Dataset::Audit { .. } => ("μ = cos θ_o".into(), "r".into()),
        Dataset::Table { .. } | Dataset::Csv { .. } | Dataset::Difference { .. } => {
            ("x".into(), "y".into())
        }
    }
}

/// Default z axis label of a surface or heat-map panel whose first series is `dataset`.
pub fn z_label(dataset: &DataSpec) -> String {
    match dataset {
        DataSpec::Ready(Dataset::Gulbrandsen { z: Some(z), .. }) => symbol(*z).into(),
        DataSpec::Ready(Dataset::Albedo { value, .. }) => albedo_symbol(*value).into(),
        DataSpec::Audit(_) => "|engine − exact|".into(),
        _ => "z".into(),
    }
}
impl Dataset {
    /// A canonical one-line JSON name, used as the CSV `curve` column: `{"data":<kind>,…}` with
    /// the dataset's keys in the spec format's order, numbers in shortest round-trip form.
    pub fn canonical_json(&self) -> String {
        crate::spec::json::to_string(self)
    }
}
