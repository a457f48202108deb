//! The JSON Schema (draft 2020-12) of the scene spec and curve formats, generated from the very key
//! tables and enums the validator reads with (`scene::*_KEYS`, `Model::signatures()`,
//! `Family::NAMES`, `FresnelModel::all()`, …), so that schema and validator cannot drift: a key added
//! to a table without a schema here makes generation panic, which the tests catch.
//!
//! The schema describes shapes, types and names (with `additionalProperties: false` wherever the
//! validator rejects unknown keys) and gives every key a description. It bounds every parameter
//! whose domain is fixed — each NDF family's and the Fresnel parameters' ([`crate::model::domain::Param`],
//! read from the family registry and [`fresnel::PARAMS`]) — in plain curves and in sweeps alike (a
//! value, a list's items, a range's start, a linspace's ends), refuses a range step of 0 and a sweep
//! object with both `range` and `linspace`, and refuses in every text field the characters the
//! validator refuses ([`REFUSED_IN_TEXT`]). What depends on other values (a range's direction, sweep
//! and point counts, canvas pixels, which keys a panel's kind allows), computed bounds and the
//! file system are the validator's alone. The root validates a scene file; a curve file of `eval`,
//! `compare` and `fit` validates against `#/$defs/curve`.

use crate::model::curve::DiffOp;
use crate::model::dataset::{AlbedoValue, Coefficient, SpectrumQuantity};
use crate::model::domain::Param;
use crate::model::fit::By;
use crate::model::fresnel::{self, FresnelModel};
use crate::model::masking::{G1Model, G2Model};
use crate::model::metal::Metal;
use crate::model::ndf::Family;
use crate::model::published::{Channel, Source};
use crate::model::renderer::Engine;
use crate::model::transform::Transform;
use crate::spec::curve::{
    DIFFERENCE_KEY, DIFFERENCE_KEYS, ENGINE_KEY, METAL_KEY, METAL_KEYS, Model, PUBLISHED_KEY,
    PUBLISHED_KEYS, ParamKind, ParamSpec, TRANSFORM_KEY, TRANSFORM_KEYS, WAVELENGTH_KEY,
};
use crate::spec::quantity;
use crate::spec::scene::interactive::{
    INTERACTIVE_KEYS, MAX_SLIDERS, PARAM_KEYS, SCALES, SLIDER_KEY,
};
use crate::spec::scene::reader::{MAX_TEXT_CHARS, REFUSED_IN_TEXT};
use crate::spec::scene::sweep::{
    FIT_KEY, FIT_KEYS, FROM_BECKMANN_KEY, FROM_BECKMANN_PARAM, MAX_CURVES_PER_SCENE, SWEEP_KEYS,
};
use crate::spec::scene::{self, data};
use serde_json::{Map, Value, json};

/// The draft the schema follows.
pub const DIALECT: &str = "https://json-schema.org/draft/2020-12/schema";

/// Where the schema is committed in the repository, relative to its root; configs refer to it as
/// `"$schema": "../schema/ndfplot.schema.json"`.
pub const COMMITTED_PATH: &str = "schema/ndfplot.schema.json";

/// Every model of the curve format, NDF families first.
pub fn models() -> Vec<Model> {
    Family::ALL
        .into_iter()
        .map(Model::Ndf)
        .chain(FresnelModel::all().map(Model::Fresnel))
        .collect()
}

/// The names a model accepts under its key, canonical name first (`trowbridge_reitz`, `ggx`).
pub fn model_names(model: Model) -> Vec<&'static str> {
    let mut names = vec![model.name()];
    names.extend(
        Model::names(model.key()).into_iter().filter(|&n| {
            n != model.name() && Model::from_key_and_name(model.key(), n) == Some(model)
        }),
    );
    names
}

/// The `$defs` name of one signature of a model: `curve_ndf_beckmann_0` for the plain curve
/// format, `scene_curve_fresnel_exact_1` for scene curve entries.
pub fn signature_def(prefix: &str, model: Model, signature: usize) -> String {
    format!("{prefix}_{}_{}_{signature}", model.key(), model.name())
}

/// The `$defs` name of a published source's curve: `curve_published_low2012-abc`.
pub fn published_def(prefix: &str, source: Source) -> String {
    format!("{prefix}_{PUBLISHED_KEY}_{}", source.name())
}

/// The `$defs` name of a fixed parameter domain with `prefix` (`plain_number`, `number`, `sweep`):
/// `sweep_ndf_beckmann_alpha_b` for an NDF family's parameter, `sweep_fresnel_eta` for a Fresnel
/// parameter, whose domain is the same in every model.
fn domain_def(prefix: &str, model: Model, param: &Param) -> String {
    match model {
        Model::Ndf(family) => format!("{prefix}_ndf_{}_{}", family.name(), param.name),
        Model::Fresnel(_) => format!("{prefix}_fresnel_{}", param.name),
    }
}

/// The parameters of `model` whose domain is fixed, as validation checks them: the family's, or
/// [`fresnel::PARAMS`] (Lazanyi's `a`, bounded by a function of `f0`, is not among them).
fn domains(model: Model) -> &'static [Param] {
    match model {
        Model::Ndf(family) => family.params(),
        Model::Fresnel(_) => fresnel::PARAMS,
    }
}

/// The domain of the parameter `name` of `model`, if fixed.
fn domain(model: Model, name: &str) -> Option<&'static Param> {
    domains(model).iter().find(|p| p.name == name)
}

/// A published fit of `source`: its name, one of its materials (or, where `lists`, a non-empty list
/// of them), `channel` exactly when the source fits per channel, and the keys of a quantity;
/// `extras` are the keys the context adds.
fn published(source: Source, extras: &[&str], lists: bool) -> Value {
    let name_or_list = |names: Vec<&str>, description: &str| {
        if lists {
            let list = json!({ "type": "array", "items": strings(&names), "minItems": 1 });
            described(
                json!({ "anyOf": [strings(&names), list] }),
                format!("{description}, or a list of them"),
            )
        } else {
            described(strings(&names), description)
        }
    };
    let keys: Vec<&str> = PUBLISHED_KEYS
        .iter()
        .filter(|&&k| k != "channel" || source.per_channel())
        .chain(quantity::KEYS)
        .chain(extras)
        .copied()
        .collect();
    let required: Vec<&str> = keys
        .iter()
        .copied()
        .filter(|k| PUBLISHED_KEYS.contains(k))
        .collect();
    let mut schema = object(&keys, &required, |key| match key {
        PUBLISHED_KEY => json!({ "const": source.name(), "description": source.title() }),
        "material" => name_or_list(
            source.materials().collect(),
            "a MERL material the source fits",
        ),
        "channel" => name_or_list(
            Channel::ALL.iter().map(|c| c.name()).collect(),
            "the colour channel: the source fits each separately",
        ),
        key if quantity::KEYS.contains(&key) => quantity_key(key),
        extra => extra_key(extra),
    });
    schema["dependentSchemas"] = quantity_dependencies();
    schema
}

/// The `$defs` name of a data entry of `kind` (`data_spectrum`).
pub fn data_def(kind: &str) -> String {
    format!("data_{kind}")
}

fn reference(def: &str) -> Value {
    json!({ "$ref": format!("#/$defs/{def}") })
}

/// `schema` with its `description`.
fn described(mut schema: Value, description: impl Into<String>) -> Value {
    schema["description"] = Value::String(description.into());
    schema
}

fn strings(words: &[&str]) -> Value {
    json!({ "type": "string", "enum": words })
}

fn names<T>(table: &[(&'static str, T)]) -> Vec<&'static str> {
    table.iter().map(|(n, _)| *n).collect()
}

/// The ranges of [`REFUSED_IN_TEXT`], each end written by `code` (of its code point), the two ends
/// joined by `to` and the ranges by `and`.
fn refused_in_text(code: impl Fn(u32) -> String, to: &str, and: &str) -> String {
    REFUSED_IN_TEXT
        .iter()
        .map(|&(first, last)| format!("{}{to}{}", code(first.into()), code(last.into())))
        .collect::<Vec<_>>()
        .join(and)
}

/// The pattern of printable text: no character of [`REFUSED_IN_TEXT`], written as `\uXXXX`
/// escapes, which ECMA-262 and Rust regular expressions read alike.
fn text_pattern() -> String {
    let ranges = refused_in_text(|c| format!("\\u{c:04X}"), "-", "");
    format!("^[^{ranges}]*$")
}

/// A text field (`$defs/text`: printable text) with its description.
fn text_field(description: &str) -> Value {
    described(reference("text"), description)
}

/// An object with exactly `keys` (each given its schema by `schema_of`), `required` among them,
/// and no other key.
fn object(keys: &[&str], required: &[&str], mut schema_of: impl FnMut(&str) -> Value) -> Value {
    let properties: Map<String, Value> = keys
        .iter()
        .map(|&k| (k.to_string(), schema_of(k)))
        .collect();
    json!({ "type": "object", "properties": properties, "required": required, "additionalProperties": false })
}

fn interval() -> Value {
    json!({ "type": "array", "items": { "type": "number" }, "minItems": 2, "maxItems": 2 })
}

/// `[a, b, c]`: three items with the given schemas.
fn triple(a: Value, b: Value, c: Value) -> Value {
    json!({ "type": "array", "prefixItems": [a, b, c], "minItems": 3, "maxItems": 3 })
}

fn scene_key(key: &str) -> Value {
    let number = |description: &str| described(json!({ "type": "number" }), description);
    match key {
        "$schema" => {
            json!({ "type": "string", "description": "the schema this file follows, e.g. ../schema/ndfplot.schema.json" })
        }
        "id" => {
            json!({ "type": "string", "pattern": "^[a-z0-9][a-z0-9_-]{0,63}$", "description": "names the output files <id>.svg, .png, .csv" })
        }
        "title" => text_field("the figure's title, math text (optional)"),
        "layout" => described(
            reference("layout"),
            "the panel grid; default one row of all panels",
        ),
        "aspect_ratio" => number("panel height / width (default 1/φ)"),
        "width" => number("figure width in units of `unit` (default from the number of columns)"),
        "height" => number("figure height in units of `unit` (default from the aspect ratio)"),
        "font_px" => number("base font size in CSS px; instead of font_pt"),
        "png_scale" => number("PNG pixels per CSS pixel; instead of dpi"),
        "font_pt" => number("base font size in points (1 pt = 1/72 in); instead of font_px"),
        "dpi" => number("PNG pixels per inch (96 CSS px = 1 in); instead of png_scale"),
        "unit" => described(
            strings(scene::SIZE_UNITS),
            "the unit of width and height: CSS pixels (default), inches or centimetres",
        ),
        "preset" => described(
            strings(scene::PRESETS),
            "a paper's figure: paper-column (3.3 in wide) or paper-page (7 in wide), 8 pt text, 300 dpi, the height from the panel rows and titles; paper-column stacks the panels in one column (two past 9 in), paper-page sets at most four a row; width, height, font and dpi keys given win; render --preset overrides it",
        ),
        "sampling" => described(
            reference("sampling"),
            "how curves are sampled over θ (default: adaptive for figures, uniform for CSV tables)",
        ),
        "theme" => described(
            strings(scene::THEMES),
            "the colours (default notebook); render --theme overrides it",
        ),
        "font" => described(
            strings(scene::FONTS),
            "the typeface, embedded: sans (default, DejaVu Sans) or serif (DejaVu Serif), with its slanted face for variables",
        ),
        "background" => described(
            strings(scene::BACKGROUNDS),
            "opaque (default): the theme's page colour; transparent: none (the PNG gets an alpha channel)",
        ),
        "panel_letters" => {
            json!({ "type": "boolean", "description": "letter the panels (a), (b), … in front of their titles, in order (default false)" })
        }
        "panels" => json!({
            "type": "array",
            "items": reference("panel"),
            "minItems": 1,
            "description": "the panels, in reading order",
        }),
        "interactive" => described(
            reference("interactive"),
            "the sliders of the scene's interactive page",
        ),
        other => panic!("no schema for the scene key {other:?}"),
    }
}

fn panel_key(key: &str) -> Value {
    match key {
        "title" => text_field("the panel's title, math text (optional)"),
        "kind" => described(
            strings(scene::PANEL_KINDS),
            "cartesian (default), surface (3D, with z and camera) or heatmap (a grid's z as coloured cells with a colour bar, with z)",
        ),
        "x" => described(
            reference("x_axis"),
            "the x axis: θ in a unit, or a data series' x",
        ),
        "y" => described(reference("y_axis"), "the y axis: the curves' values"),
        "z" => described(
            reference("z_axis"),
            "a surface panel's z axis, or a heat-map panel's colour bar",
        ),
        "view" => described(
            strings(scene::VIEWS),
            "cartesian (default) or polar: the lobe in the plane of incidence",
        ),
        "transform" => described(
            strings(scene::PANEL_TRANSFORMS),
            "applied to every NDF curve of the panel: projected (D cos θ) or slope (P₂₂ = D cos⁴θ against tan θ)",
        ),
        "camera" => described(reference("camera"), "a surface panel's viewpoint"),
        "legend" => json!({
            "anyOf": [{ "type": "boolean" }, strings(scene::LEGEND_PLACES)],
            "description": "true or best (default: where it hides no curve), false or none, or a place",
        }),
        "grid" => {
            json!({ "type": "boolean", "description": "grid lines at the ticks (default true)" })
        }
        "annotations" => json!({
            "type": "array",
            "maxItems": scene::MAX_ANNOTATIONS,
            "description": "reference lines ({\"x\": v} or {\"y\": v}), bands ({\"x\": [a, b]}) with an optional label, and notes ({\"text\": \"…\", \"at\": [x, y]}), in the units the axes show",
            "items": {
                "type": "object",
                "additionalProperties": false,
                "properties": {
                    "x": { "description": "a vertical line at this x, or a band over [a, b]", "anyOf": [{ "type": "number" }, { "type": "array", "items": { "type": "number" }, "minItems": 2, "maxItems": 2 }] },
                    "y": { "description": "a horizontal line at this y, or a band over [a, b]", "anyOf": [{ "type": "number" }, { "type": "array", "items": { "type": "number" }, "minItems": 2, "maxItems": 2 }] },
                    "label": text_field("text beside a line's end or inside a band"),
                    "text": text_field("a note's text, up and right of its point"),
                    "at": { "type": "array", "items": { "type": "number" }, "minItems": 2, "maxItems": 2, "description": "a note's data point [x, y]" },
                },
            },
        }),
        "curves" => json!({
            "type": "array",
            "minItems": 1,
            "items": { "anyOf": [reference("scene_curve"), reference("data")] },
            "description": "the curves and data series, drawn in order",
        }),
        other => panic!("no schema for the panel key {other:?}"),
    }
}

fn axis_key(key: &str) -> Value {
    match key {
        "unit" => described(
            strings(scene::X_UNITS),
            "what the x axis shows: θ in radians (default) or degrees, the slope tan θ, or a plain value",
        ),
        "scale" => described(strings(scene::SCALES), "linear (default) or log"),
        "range" => described(interval(), "[low, high], in the unit shown"),
        "label" => text_field("the axis label, math text"),
        "ticks" => json!({
            "anyOf": [
                { "type": "integer", "minimum": 2, "maximum": scene::MAX_TICK_COUNT },
                { "type": "array", "items": { "type": "number" }, "minItems": 1 },
            ],
            "description": "at most this many nice ticks, or the values to tick, in the unit shown",
        }),
        "elevation" => {
            json!({ "type": "number", "description": "the camera's height above the base plane, in degrees" })
        }
        "azimuth" => {
            json!({ "type": "number", "description": "the camera's direction around the vertical axis, in degrees" })
        }
        other => panic!("no schema for the axis key {other:?}"),
    }
}

/// The keys a scene curve entry has besides its parameters.
fn extra_key(key: &str) -> Value {
    match key {
        "style" => json!({
            "anyOf": [strings(scene::STYLE_WORDS), { "type": "array", "items": strings(scene::STYLE_WORDS) }],
            "description": "a line style word or a list of them",
        }),
        "colour" => json!({
            "type": "string",
            "pattern": "^#[0-9A-Fa-f]{6}$",
            "description": "#RRGGBB: the hue a sweep is shaded in",
        }),
        "color" => described(extra_key("colour"), "the other spelling of colour"),
        "label" => text_field(
            "the legend label, math text; {param} placeholders take a swept value, {l2} a Belcour reconstruction's error",
        ),
        "mark" => described(
            strings(scene::MARKS),
            "how the series is drawn (default line)",
        ),
        "width" => json!({
            "type": "number",
            "minimum": scene::LINE_WIDTHS.0,
            "maximum": scene::LINE_WIDTHS.1,
            "description": "the line width in multiples of the default",
        }),
        other => panic!("no schema for the series key {other:?}"),
    }
}

/// A number within `param`'s domain (`minimum`/`exclusiveMinimum`, `maximum`/`exclusiveMaximum`;
/// none on a side open to every finite value; a whole number for the basis index), described with
/// the reasons for its bounds.
fn bounded(param: &Param) -> Value {
    let kind = if *param == fresnel::BASIS_INDEX {
        "integer"
    } else {
        "number"
    };
    let mut schema = json!({ "type": kind, "description": param_description(param) });
    for (bound, inclusive_key, exclusive_key) in [
        (param.min, "minimum", "exclusiveMinimum"),
        (param.max, "maximum", "exclusiveMaximum"),
    ] {
        if !bound.is_open() {
            let key = if bound.inclusive {
                inclusive_key
            } else {
                exclusive_key
            };
            schema[key] = json!(bound.value);
        }
    }
    schema
}

/// A parameter with a fixed domain in words: its symbol and [`Param::expected`].
fn param_description(param: &Param) -> String {
    format!("{} {}", param.symbol, param.expected())
}

/// What a parameter without a fixed domain means.
fn free_param(name: &str) -> &'static str {
    match name {
        "a" => {
            "Lazanyi's weight of the c (1 − c)⁶ term, in [−5 (1 − f0), a_max(f0)] so that 0 ≤ F ≤ 1 (bounds that depend on f0: checked by ndfplot)"
        }
        "g_remap" => "use the remapped edge tint ḡ = 1 − (1 − g)³ instead of g (default false)",
        "roughness" => {
            "an artist's roughness in [0, 1] (with \"engine\"), mapped to α by that engine's convention"
        }
        other => panic!("no description for the parameter {other:?}"),
    }
}

/// A parameter of a plain curve: a single number or flag; a number within its domain where that
/// is fixed.
fn plain_param(model: Model, spec: &ParamSpec) -> Value {
    match (spec.kind, domain(model, spec.name)) {
        (ParamKind::Number, Some(param)) => described(
            reference(&domain_def("plain_number", model, param)),
            param_description(param),
        ),
        (ParamKind::Number, None) => described(json!({ "type": "number" }), free_param(spec.name)),
        (ParamKind::Flag, _) => described(json!({ "type": "boolean" }), free_param(spec.name)),
    }
}

/// A parameter of a scene curve: a value or a sweep (bounded by the parameter's domain where that
/// is fixed), and for NDF parameters a fit, for Phong's exponent a Beckmann conversion.
fn scene_param(model: Model, spec: &ParamSpec) -> Value {
    match spec.kind {
        ParamKind::Flag => json!({
            "anyOf": [{ "type": "boolean" }, { "type": "array", "items": { "type": "boolean" }, "minItems": 1 }],
            "description": format!("{}; or a list of flags", free_param(spec.name)),
        }),
        ParamKind::Number => {
            let (sweep, meaning) = match domain(model, spec.name) {
                Some(param) => (
                    reference(&domain_def("sweep", model, param)),
                    param_description(param),
                ),
                None => (reference("sweep"), free_param(spec.name).to_string()),
            };
            let mut options = vec![sweep];
            let mut forms = String::from("a value, a list, a range or a linspace");
            if matches!(model, Model::Ndf(_)) {
                options.push(reference("fit"));
                forms += ", or fitted to a target";
            }
            if spec.name == FROM_BECKMANN_PARAM {
                options.push(object(&[FROM_BECKMANN_KEY], &[FROM_BECKMANN_KEY], |_| {
                    described(
                        reference("sweep"),
                        "α_b in (0, 1] (a value, list or sweep), converted to α_p = 2/α_b² − 2",
                    )
                }));
                forms += ", or converted from Beckmann's α_b";
            }
            json!({ "anyOf": options, "description": format!("{meaning}: {forms}") })
        }
    }
}

/// One signature of a model as an object schema; `param` gives each parameter's schema and
/// `extras` are the keys the context adds (a scene's `style`, …).
fn signature(
    model: Model,
    params: &[ParamSpec],
    extras: &[&str],
    param: impl Fn(&ParamSpec) -> Value,
) -> Value {
    let quantity_keys: &[&str] = match model {
        Model::Ndf(_) => quantity::KEYS,
        Model::Fresnel(_) => &[],
    };
    let engine_keys: &[&str] = if model.takes_engine(params) {
        &[ENGINE_KEY]
    } else {
        &[]
    };
    let keys: Vec<&str> = [model.key()]
        .into_iter()
        .chain(params.iter().map(|p| p.name))
        .chain(quantity_keys.iter().copied())
        .chain(engine_keys.iter().copied())
        .chain(extras.iter().copied())
        .collect();
    let required: Vec<&str> = [model.key()]
        .into_iter()
        .chain(
            params
                .iter()
                .filter(|p| p.default.is_none())
                .map(|p| p.name),
        )
        .chain(Model::needs_engine(params).then_some(ENGINE_KEY))
        .collect();
    let title = match model {
        Model::Ndf(family) => format!("the {} NDF", family.title()),
        Model::Fresnel(model) => format!("the Fresnel model {}", model.name()),
    };
    let mut schema = object(&keys, &required, |key| {
        if key == model.key() {
            described(strings(&model_names(model)), title.as_str())
        } else if let Some(spec) = params.iter().find(|p| p.name == key) {
            param(spec)
        } else if quantity_keys.contains(&key) {
            quantity_key(key)
        } else if key == ENGINE_KEY {
            described(
                strings(&names(&Engine::NAMES)),
                "the renderer whose own computation the curve shows (its expression, precision and clamps)",
            )
        } else {
            extra_key(key)
        }
    });
    if !quantity_keys.is_empty() {
        schema["dependentSchemas"] = quantity_dependencies();
    }
    schema
}

/// The keys an NDF curve takes to show a quantity other than D ([`quantity`]).
fn quantity_key(key: &str) -> Value {
    match key {
        quantity::QUANTITY_KEY => described(
            strings(&crate::model::curve::quantity::NAMES),
            "what the curve shows: d (default) D(θ); lambda Smith Λ(θo); g1 G1(θo); g2 G2(θo, θi); albedo E(cos θo); furnace the weak white furnace of a G1",
        ),
        quantity::G2_KEY => described(
            strings(&names(&G2Model::NAMES)),
            "how masking and shadowing combine (default height-correlated); g2 and albedo curves",
        ),
        quantity::THETA_I_KEY => json!({
            "anyOf": [
                { "type": "number", "minimum": 0, "maximum": quantity::THETA_I_MAX },
                { "const": quantity::SAME },
            ],
            "description": "the light's angle θi in radians, or \"same\" for θi = θo (default); g2 curves",
        }),
        quantity::G1_KEY => described(
            strings(&names(&G1Model::NAMES)),
            "the G1 a furnace curve audits (default smith; the others need a family with a Beckmann-equivalent roughness)",
        ),
        quantity::FRESNEL_KEY => described(
            reference("fresnel_curve"),
            "the Fresnel factor F(θd) of an albedo curve (default F = 1)",
        ),
        other => panic!("no schema for the quantity key {other:?}"),
    }
}

/// Each quantity option key requires a quantity that takes it.
fn quantity_dependencies() -> Value {
    let requires = |quantities: &[&str]| {
        let names: Vec<String> = quantities.iter().map(|q| format!("\"{q}\"")).collect();
        json!({
            "properties": { quantity::QUANTITY_KEY: {
                "enum": quantities,
                "description": format!("this key needs quantity {}", names.join(" or ")),
            } },
            "required": [quantity::QUANTITY_KEY],
        })
    };
    Value::Object(
        quantity::OPTION_TAKERS
            .iter()
            .map(|(key, quantities)| (key.to_string(), requires(quantities)))
            .collect(),
    )
}

fn data_key(kind: &str, key: &str) -> Value {
    match (kind, key) {
        (_, "data") => json!({ "const": kind, "description": match kind {
            "spectrum" => "the singular values of the Fresnel basis' training curves",
            "gulbrandsen" => "decomposition coefficients over Gulbrandsen's (r, g)",
            "albedo" => "the directional albedo E (F = 1) of an NDF family over μ = cos θo × roughness r, on Cycles' grid",
            "audit" => "|engine − exact| over μ = cos θo × roughness r of an engine's albedo table shipped with ndfplot, on the engine's grid, against the exact table",
            "table" => "literal points",
            "csv" => "θ and values read from a CSV file",
            other => panic!("no description for the data kind {other:?}"),
        } }),
        (_, "style" | "colour" | "color" | "label" | "mark") => extra_key(key),
        ("spectrum", "quantity") => described(
            strings(&names(&SpectrumQuantity::NAMES)),
            "the singular values s_k, s_k / Σ s, or their running sums (default)",
        ),
        ("spectrum", "count") => {
            json!({ "type": "integer", "minimum": 1, "maximum": 100, "description": "how many singular values" })
        }
        ("gulbrandsen", "x" | "y" | "z") => described(
            strings(&names(&Coefficient::NAMES)),
            format!("the coefficient on the {key} axis"),
        ),
        ("gulbrandsen", "r" | "g") => {
            let param = fresnel::PARAMS
                .iter()
                .find(|p| p.name == key)
                .expect("Gulbrandsen's r and g are Fresnel parameters");
            described(
                sweep(reference("plain_number"), bounded(param)),
                format!(
                    "{}: a value, a list, a range or a linspace",
                    param_description(param)
                ),
            )
        }
        ("gulbrandsen", "g_remap") => described(json!({ "type": "boolean" }), free_param(key)),
        ("albedo", "ndf") => described(
            strings(data::ALBEDO_FAMILIES),
            "the NDF family, its one parameter the width α (default ggx)",
        ),
        ("albedo", "map") => described(
            strings(&names(&crate::model::albedo::RoughnessMap::KEYS)),
            "how r maps to α: r2 (α = r², Cycles and Filament; default) or r (α = r)",
        ),
        ("albedo", "g2") => described(
            strings(&names(&G2Model::NAMES)),
            "how masking and shadowing combine (default height-correlated)",
        ),
        ("albedo", "value") => described(
            strings(&names(&AlbedoValue::NAMES)),
            "E (default) or loss: 1 − E, the energy single scattering loses",
        ),
        ("albedo", "mu" | "r") => json!({
            "type": "integer",
            "minimum": data::ALBEDO_POINTS.0,
            "maximum": data::ALBEDO_POINTS.1,
            "description": format!(
                "points on the {} axis, i/(n − 1) for i = 0 … n − 1 (default {})",
                if key == "mu" { "μ" } else { "r" },
                data::DEFAULT_ALBEDO_POINTS
            ),
        }),
        ("audit", "table") => described(
            strings(&names(&crate::model::engine_table::PublishedTable::NAMES)),
            "the published engine table: cycles-ggx-e, Cycles' table_ggx_E (32 × 32 E of GGX, height-correlated G2, F = 1, α = r²); openpbr-metal-1-e, Adobe openpbr-bsdf's ideal-metal table (32 × 32 1 − E of GGX, separable G2, F = 1, α = r²)",
        ),
        ("table", "x") => described(reference("plain_sweep"), "the points' x: a list or a sweep"),
        ("table", "y") => described(reference("plain_sweep"), "the points' y, as many as x"),
        ("csv", "path") => text_field(
            "the CSV file, relative to the spec's folder, which it may not leave unless --allow-read allows",
        ),
        ("csv", "x") => text_field("the column of θ (default theta)"),
        ("csv", "y") => text_field("the column of values (default value)"),
        ("csv", "degrees") => {
            json!({ "type": "boolean", "description": "θ in degrees (default false: radians)" })
        }
        (kind, key) => panic!("no schema for the key {key:?} of {kind:?} data"),
    }
}

fn data_required(kind: &str) -> &'static [&'static str] {
    match kind {
        "gulbrandsen" => &["data", "x", "y", "r", "g"],
        "table" => &["data", "x", "y"],
        "csv" => &["data", "path"],
        "audit" => &["data", "table"],
        _ => &["data"],
    }
}

/// A sweep of numbers: a number, a list, `{"range": [start, stop, step]}` or
/// `{"linspace": [start, stop, count]}` (one of the two keys). `any` is the schema of one number of
/// the context (slider references are allowed only in curve entries), `within` that of a value the
/// parameter may take: it bounds a single value, a list's items, a range's start and a linspace's
/// ends — its stop only when the count is not 1, since `linspace(a, b, 1)` is `[a]`. A range's stop
/// is left unbounded: `Range` need not reach it.
fn sweep(any: Value, within: Value) -> Value {
    let step = json!({ "allOf": [any, { "not": { "const": 0 } }] });
    let count = json!({ "type": "integer", "minimum": 1, "maximum": MAX_CURVES_PER_SCENE });
    let mut ranges = object(SWEEP_KEYS, &[], |key| match key {
        "range" => described(
            triple(within.clone(), any.clone(), step.clone()),
            "[start, stop, step]: Mathematica's Range made exact, from start towards stop in steps of step ≠ 0",
        ),
        "linspace" => {
            let mut linspace = triple(within.clone(), any.clone(), count.clone());
            if within != any {
                linspace["anyOf"] = json!([
                    { "prefixItems": [true, within] },
                    { "prefixItems": [true, true, { "const": 1 }] },
                ]);
            }
            described(
                linspace,
                "[start, stop, count]: numpy's linspace, count values from start to stop",
            )
        }
        other => panic!("no schema for the sweep key {other:?}"),
    });
    ranges["oneOf"] = SWEEP_KEYS
        .iter()
        .map(|key| json!({ "required": [key] }))
        .collect();
    json!({ "anyOf": [
        within,
        { "type": "array", "items": within, "minItems": 1, "maxItems": MAX_CURVES_PER_SCENE },
        ranges,
    ] })
}

/// The whole schema as a JSON value.
pub fn schema() -> Value {
    let mut defs = Map::new();
    let mut def = |name: &str, value: Value| {
        defs.insert(name.to_string(), value);
    };
    def(
        "scene",
        object(scene::SCENE_KEYS, &["id", "panels"], scene_key),
    );
    def(
        "layout",
        object(scene::LAYOUT_KEYS, &[], |key| {
            let count = json!({ "type": "integer", "minimum": 1, "maximum": 100 });
            match key {
                "rows" => described(count, "rows of panels (default 1)"),
                "cols" => described(
                    count,
                    "columns of panels (default: as many as the panels need)",
                ),
                other => panic!("no schema for the layout key {other:?}"),
            }
        }),
    );
    let mut sampling = object(scene::SAMPLING_KEYS, &[], |key| match key {
        "uniform" => json!({
            "type": "integer",
            "minimum": 2,
            "maximum": scene::MAX_SAMPLES_PER_CURVE,
            "description": "this many evenly spaced θ per curve over the visible range, both ends included",
        }),
        "adaptive" => described(
            object(scene::ADAPTIVE_KEYS, &[], |key| match key {
                "tolerance_px" => json!({
                    "type": "number",
                    "minimum": scene::MIN_TOLERANCE_PX,
                    "maximum": scene::MAX_SIDE_PX,
                    "description": format!("the largest distance in output pixels between the polyline and the curve (default {})", scene::DEFAULT_TOLERANCE_PX),
                }),
                other => panic!("no schema for the adaptive key {other:?}"),
            }),
            "bisection until the drawn polyline is within tolerance_px of the curve",
        ),
        other => panic!("no schema for the sampling key {other:?}"),
    });
    sampling["minProperties"] = json!(1);
    sampling["maxProperties"] = json!(1);
    def("sampling", sampling);
    def("panel", object(scene::PANEL_KEYS, &["curves"], panel_key));
    def("x_axis", object(scene::X_KEYS, &[], axis_key));
    def("y_axis", object(scene::Y_KEYS, &[], axis_key));
    def("z_axis", object(scene::Z_KEYS, &[], axis_key));
    def("camera", object(scene::CAMERA_KEYS, &[], axis_key));
    def(
        "text",
        json!({
            "type": "string",
            "pattern": text_pattern(),
            "maxLength": MAX_TEXT_CHARS,
            "description": format!("printable text of at most {MAX_TEXT_CHARS} characters: none of {}", refused_in_text(|c| format!("U+{c:04X}"), "–", ", ")),
        }),
    );
    def(
        "interactive",
        object(INTERACTIVE_KEYS, &["params"], |key| match key {
            "params" => json!({
                "type": "array",
                "items": reference("slider"),
                "minItems": 1,
                "maxItems": MAX_SLIDERS,
                "description": "the sliders, each a parameter curves refer to as {\"slider\": name}",
            }),
            other => panic!("no schema for the interactive key {other:?}"),
        }),
    );
    def(
        "slider",
        object(PARAM_KEYS, &["name"], |key| match key {
            "name" => json!({
                "type": "string",
                "pattern": "^[a-z][a-z0-9_]{0,31}$",
                "description": "what curves refer to: {\"slider\": name}",
            }),
            "label" => text_field("the slider's label, math text"),
            "range" => described(interval(), "[min, max] of the slider"),
            "scale" => {
                json!({ "enum": SCALES, "description": "linear or log (default: log over a decade or more)" })
            }
            "start" => {
                json!({ "type": "number", "description": "the opening value, inside range (default min)" })
            }
            other => panic!("no schema for the slider key {other:?}"),
        }),
    );
    def(
        "slider_reference",
        object(
            &[SLIDER_KEY],
            &[SLIDER_KEY],
            |_| json!({ "type": "string", "description": "the name of a slider of interactive.params" }),
        ),
    );
    def(
        "number",
        json!({ "anyOf": [{ "type": "number" }, reference("slider_reference")] }),
    );
    def("plain_number", json!({ "type": "number" }));
    def("sweep", sweep(reference("number"), reference("number")));
    def(
        "plain_sweep",
        sweep(reference("plain_number"), reference("plain_number")),
    );
    // Each fixed domain once (a Fresnel parameter's is shared by the models that take it): a
    // number within it, that or a slider reference, and a sweep of those.
    for model in models() {
        for param in domains(model) {
            def(&domain_def("plain_number", model, param), bounded(param));
            let within = reference(&domain_def("plain_number", model, param));
            def(
                &domain_def("number", model, param),
                json!({ "anyOf": [within, reference("slider_reference")] }),
            );
            def(
                &domain_def("sweep", model, param),
                sweep(
                    reference("number"),
                    reference(&domain_def("number", model, param)),
                ),
            );
        }
    }
    def(
        "fit",
        object(&[FIT_KEY], &[FIT_KEY], |_| {
            let by = By::ALL.iter().map(|b| b.name()).collect::<Vec<_>>();
            described(
                object(FIT_KEYS, &["target"], |key| match key {
                    "target" => described(
                        reference("scene_curve"),
                        "the curve to match, or a sweep of curves (one fit each)",
                    ),
                    "by" => described(
                        strings(&by),
                        "peak (default): equal D(0); max: equal maxima; l2: the least L2 difference",
                    ),
                    other => panic!("no schema for the fit key {other:?}"),
                }),
                "this parameter fitted to a target curve, the curve's other parameters fixed",
            )
        }),
    );

    let ops: Vec<&str> = DiffOp::ALL.iter().map(|op| op.name()).collect();
    let mut curves = Vec::new();
    let mut fresnel_curves = Vec::new();
    let mut scene_curves = Vec::new();
    for model in models() {
        for (i, params) in model.signatures().iter().enumerate() {
            let name = signature_def("curve", model, i);
            def(
                &name,
                signature(model, params, &[], |spec| plain_param(model, spec)),
            );
            curves.push(reference(&name));
            if let Model::Fresnel(_) = model {
                fresnel_curves.push(reference(&name));
            }
            let name = signature_def("scene_curve", model, i);
            def(
                &name,
                signature(model, params, scene::CURVE_EXTRA_KEYS, |spec| {
                    scene_param(model, spec)
                }),
            );
            scene_curves.push(reference(&name));
        }
    }
    let difference = |operand: Value, extras: &[&str]| {
        let keys: Vec<&str> = DIFFERENCE_KEYS.iter().chain(extras).copied().collect();
        object(&keys, DIFFERENCE_KEYS, |key| match key {
            DIFFERENCE_KEY => described(
                strings(&ops),
                "minus: a − b; ratio: a / b (0/0 = 1); relative: (a − b)/|b|; log-ratio: ln(a/b) (both 0 where a = b)",
            ),
            "a" => described(operand.clone(), "the first curve"),
            "b" => described(operand.clone(), "the second curve, of the same kind as a"),
            extra => extra_key(extra),
        })
    };
    def("curve_difference", difference(reference("curve"), &[]));
    // In a scene, either side may be a series of θ: the difference is taken at its samples.
    let scene_operand = json!({ "anyOf": [
        reference("scene_curve"),
        reference(&data_def("csv")),
        reference(&data_def("table")),
    ] });
    def(
        "scene_curve_difference",
        difference(scene_operand, scene::CURVE_EXTRA_KEYS),
    );
    def(
        "curve_transformed",
        object(TRANSFORM_KEYS, TRANSFORM_KEYS, |key| match key {
            TRANSFORM_KEY => described(
                strings(&names(&Transform::NAMES)),
                "projected: D cos θ; slope: P₂₂ = D cos⁴θ against tan θ",
            ),
            _ => described(reference("curve"), "the NDF curve transformed"),
        }),
    );
    curves.extend([
        reference("curve_difference"),
        reference("curve_transformed"),
    ]);
    scene_curves.push(reference("scene_curve_difference"));
    for source in Source::ALL {
        let name = published_def("curve", source);
        def(&name, published(source, &[], false));
        curves.push(reference(&name));
        let name = published_def("scene_curve", source);
        def(&name, published(source, scene::CURVE_EXTRA_KEYS, true));
        scene_curves.push(reference(&name));
    }
    // A metal's Fresnel curve: a model that takes an index, a metal, a wavelength.
    let metal = |extras: &[&str], lists: bool| {
        let takers: Vec<&str> = FresnelModel::all()
            .map(Model::Fresnel)
            .filter(|m| m.eta_signature().is_some())
            .map(Model::name)
            .collect();
        let metals: Vec<&str> = Metal::all_names().collect();
        let keys: Vec<&str> = METAL_KEYS.iter().chain(extras).copied().collect();
        object(&keys, METAL_KEYS, |key| match key {
            "fresnel" => described(
                strings(&takers),
                "a Fresnel model that takes an index (η, κ)",
            ),
            METAL_KEY if lists => described(
                json!({ "anyOf": [strings(&metals), { "type": "array", "items": strings(&metals), "minItems": 1 }] }),
                "a measured metal by symbol or English name (ndfplot list --metals), or a list of them",
            ),
            METAL_KEY => described(
                strings(&metals),
                "a measured metal by symbol or English name (ndfplot list --metals)",
            ),
            WAVELENGTH_KEY if lists => described(
                reference("plain_sweep"),
                "the wavelengths in nm at which the measured (η, κ) is interpolated, within the metal's data",
            ),
            WAVELENGTH_KEY => described(
                reference("plain_number"),
                "the wavelength in nm at which the measured (η, κ) is interpolated, within the metal's data",
            ),
            extra => extra_key(extra),
        })
    };
    def("curve_metal", metal(&[], false));
    def("scene_curve_metal", metal(scene::CURVE_EXTRA_KEYS, true));
    curves.push(reference("curve_metal"));
    fresnel_curves.push(reference("curve_metal"));
    scene_curves.push(reference("scene_curve_metal"));
    // The branches exclude one another (each requires its model key and names, and admits no other
    // keys), so exactly one matches a valid curve.
    def(
        "curve",
        json!({ "description": "the curve format of eval, compare and fit", "oneOf": curves }),
    );
    def(
        "fresnel_curve",
        json!({ "description": "a Fresnel curve given by its parameters", "oneOf": fresnel_curves }),
    );
    def(
        "scene_curve",
        json!({ "description": "a curve entry of a panel: a curve whose parameters may be swept or fitted", "oneOf": scene_curves }),
    );

    let mut kinds = Vec::new();
    for &kind in data::KINDS {
        let keys: Vec<&str> = data::COMMON_KEYS
            .iter()
            .chain(data::own_keys(kind))
            .copied()
            .collect();
        def(
            &data_def(kind),
            object(&keys, data_required(kind), |key| data_key(kind, key)),
        );
        kinds.push(reference(&data_def(kind)));
    }
    def(
        "data",
        json!({ "description": "a data series of a panel (not a function of θ)", "anyOf": kinds }),
    );

    json!({
        "$schema": DIALECT,
        "title": "ndfplot scene spec",
        "description": "A scene file of `ndfplot render`; a curve file of eval, compare and fit is #/$defs/curve. Generated by `ndfplot schema`.",
        "$ref": "#/$defs/scene",
        "$defs": defs,
    })
}

/// The schema as printed by `ndfplot schema`: pretty JSON with a final newline.
pub fn text() -> String {
    serde_json::to_string_pretty(&schema()).expect("a JSON value always serializes") + "\n"
}
