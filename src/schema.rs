//! The JSON Schema (draft 2020-12) of the scene spec and curve formats, generated from the very key
//! tables and enums the validator reads with (`scene::*_KEYS`, `Model::signatures()`,
//! `Family::NAMES`, `FresnelModel::all()`, …), so that schema and validator cannot drift: a key added
//! to a table without a schema here makes generation panic, which the tests catch.
//!
//! The schema describes shapes, types and names (with `additionalProperties: false` wherever the
//! validator rejects unknown keys), and the numeric bounds of a plain curve's NDF parameters, read
//! from the domain each family states ([`crate::domain::Param`]); value domains that depend on other
//! values (Fresnel parameters, sweep sizes, canvas pixels) are the validator's alone. The root validates a scene file; a curve
//! file of `eval`, `compare` and `fit` validates against `#/$defs/curve`.

use crate::curve::By;
use crate::curve::{
    DIFFERENCE_KEY, DIFFERENCE_KEYS, DiffOp, Model, PUBLISHED_KEY, PUBLISHED_KEYS, ParamKind,
    ParamSpec, TRANSFORM_KEY, TRANSFORM_KEYS,
};
use crate::dataset::{Coefficient, SpectrumQuantity};
use crate::fresnel::FresnelModel;
use crate::ndf::Family;
use crate::published::{Channel, Source};
use crate::scene::interactive::{
    INTERACTIVE_KEYS, MAX_SLIDERS, PARAM_KEYS, SCALES, SLIDER_KEY,
};
use crate::scene::sweep::{
    FIT_KEY, FIT_KEYS, FROM_BECKMANN_KEY, FROM_BECKMANN_PARAM, MAX_CURVES_PER_SCENE, SWEEP_KEYS,
};
use crate::scene::{self, data};
use crate::transform::Transform;
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

/// A published fit of `source`: its name, one of its materials (or, where `lists`, a non-empty list
/// of them), and `channel` exactly when the source fits per channel; `extras` are the keys the
/// context adds.
fn published(source: Source, extras: &[&str], lists: bool) -> Value {
    let name_or_list = |names: Vec<&str>| {
        if lists {
            json!({ "anyOf": [strings(&names), { "type": "array", "items": strings(&names), "minItems": 1 }] })
        } else {
            strings(&names)
        }
    };
    let keys: Vec<&str> = PUBLISHED_KEYS
        .iter()
        .filter(|&&k| k != "channel" || source.per_channel())
        .chain(extras)
        .copied()
        .collect();
    let required: Vec<&str> = keys
        .iter()
        .copied()
        .filter(|k| PUBLISHED_KEYS.contains(k))
        .collect();
    object(&keys, &required, |key| match key {
        PUBLISHED_KEY => json!({ "const": source.name(), "description": source.title() }),
        "material" => name_or_list(source.materials().collect()),
        "channel" => name_or_list(Channel::ALL.iter().map(|c| c.name()).collect()),
        extra => extra_key(extra),
    })
}

/// The `$defs` name of a data entry of `kind` (`data_spectrum`).
pub fn data_def(kind: &str) -> String {
    format!("data_{kind}")
}

fn reference(def: &str) -> Value {
    json!({ "$ref": format!("#/$defs/{def}") })
}

fn strings(words: &[&str]) -> Value {
    json!({ "type": "string", "enum": words })
}

fn names<T>(table: &[(&'static str, T)]) -> Vec<&'static str> {
    table.iter().map(|(n, _)| *n).collect()
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
    match key {
        "$schema" => {
            json!({ "type": "string", "description": "the schema this file follows, e.g. ../schema/ndfplot.schema.json" })
        }
        "id" => {
            json!({ "type": "string", "pattern": "^[a-z0-9][a-z0-9_-]{0,63}$", "description": "names the output files <id>.svg, .png, .csv" })
        }
        "title" => json!({ "type": "string" }),
        "layout" => reference("layout"),
        "aspect_ratio" | "width" | "height" | "font_px" | "png_scale" => {
            json!({ "type": "number" })
        }
        "font_pt" => {
            json!({ "type": "number", "description": "base font size in points (1 pt = 1/72 in); instead of font_px" })
        }
        "dpi" => {
            json!({ "type": "number", "description": "PNG pixels per inch (96 CSS px = 1 in); instead of png_scale" })
        }
        "unit" => strings(scene::SIZE_UNITS),
        "sampling" => reference("sampling"),
        "theme" => strings(scene::THEMES),
        "panels" => json!({ "type": "array", "items": reference("panel"), "minItems": 1 }),
        "interactive" => reference("interactive"),
        other => panic!("no schema for the scene key {other:?}"),
    }
}

fn panel_key(key: &str) -> Value {
    match key {
        "title" => json!({ "type": "string" }),
        "kind" => strings(scene::PANEL_KINDS),
        "x" => reference("x_axis"),
        "y" => reference("y_axis"),
        "z" => reference("z_axis"),
        "view" => strings(scene::VIEWS),
        "transform" => strings(scene::PANEL_TRANSFORMS),
        "camera" => reference("camera"),
        "legend" => json!({ "anyOf": [{ "type": "boolean" }, strings(scene::LEGEND_PLACES)] }),
        "grid" => json!({ "type": "boolean" }),
        "curves" => json!({
            "type": "array",
            "minItems": 1,
            "items": { "anyOf": [reference("scene_curve"), reference("data")] },
        }),
        other => panic!("no schema for the panel key {other:?}"),
    }
}

fn axis_key(key: &str) -> Value {
    match key {
        "unit" => strings(scene::X_UNITS),
        "scale" => strings(scene::SCALES),
        "range" => interval(),
        "label" => json!({ "type": "string" }),
        "ticks" => json!({ "anyOf": [
            { "type": "integer", "minimum": 2, "maximum": scene::MAX_TICK_COUNT },
            { "type": "array", "items": { "type": "number" }, "minItems": 1 },
        ] }),
        "elevation" | "azimuth" => json!({ "type": "number" }),
        other => panic!("no schema for the axis key {other:?}"),
    }
}

/// The keys a scene curve entry has besides its parameters.
fn extra_key(key: &str) -> Value {
    match key {
        "style" => {
            json!({ "anyOf": [strings(scene::STYLE_WORDS), { "type": "array", "items": strings(scene::STYLE_WORDS) }] })
        }
        "colour" | "color" => json!({ "type": "string", "pattern": "^#[0-9A-Fa-f]{6}$" }),
        "label" => json!({ "type": "string" }),
        "mark" => strings(scene::MARKS),
        "width" => {
            json!({ "type": "number", "minimum": scene::LINE_WIDTHS.0, "maximum": scene::LINE_WIDTHS.1 })
        }
        other => panic!("no schema for the series key {other:?}"),
    }
}

/// A parameter of a plain curve: a single number or flag; an NDF parameter's number within its
/// family's domain (`minimum`/`exclusiveMinimum`, `maximum`/`exclusiveMaximum`; none on a side open
/// to every finite value), described with the reasons for its bounds.
fn plain_param(model: Model, spec: &ParamSpec) -> Value {
    let domain = match model {
        Model::Ndf(family) => family.params().iter().find(|p| p.name == spec.name),
        Model::Fresnel(_) => None,
    };
    match (spec.kind, domain) {
        (ParamKind::Number, Some(param)) => {
            let mut schema = json!({ "type": "number", "description": param.expected() });
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
        (ParamKind::Number, None) => json!({ "type": "number" }),
        (ParamKind::Flag, _) => json!({ "type": "boolean" }),
    }
}

/// A parameter of a scene curve: a value or a sweep, and for NDF parameters a fit, for Phong's
/// exponent a Beckmann conversion.
fn scene_param(model: Model, spec: &ParamSpec) -> Value {
    match spec.kind {
        ParamKind::Flag => {
            json!({ "anyOf": [{ "type": "boolean" }, { "type": "array", "items": { "type": "boolean" }, "minItems": 1 }] })
        }
        ParamKind::Number => {
            let mut options = vec![reference("sweep")];
            if matches!(model, Model::Ndf(_)) {
                options.push(reference("fit"));
            }
            if spec.name == FROM_BECKMANN_PARAM {
                options.push(object(&[FROM_BECKMANN_KEY], &[FROM_BECKMANN_KEY], |_| {
                    reference("sweep")
                }));
            }
            json!({ "anyOf": options })
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
    let keys: Vec<&str> = [model.key()]
        .into_iter()
        .chain(params.iter().map(|p| p.name))
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
        .collect();
    object(&keys, &required, |key| {
        if key == model.key() {
            strings(&model_names(model))
        } else if let Some(spec) = params.iter().find(|p| p.name == key) {
            param(spec)
        } else {
            extra_key(key)
        }
    })
}

fn data_key(kind: &str, key: &str) -> Value {
    match (kind, key) {
        (_, "data") => json!({ "const": kind }),
        (_, "style" | "colour" | "color" | "label" | "mark") => extra_key(key),
        ("spectrum", "quantity") => strings(&names(&SpectrumQuantity::NAMES)),
        ("spectrum", "count") => json!({ "type": "integer", "minimum": 1, "maximum": 100 }),
        ("gulbrandsen", "x" | "y" | "z") => strings(&names(&Coefficient::NAMES)),
        ("gulbrandsen", "r" | "g") | ("table", "x" | "y") => reference("plain_sweep"),
        ("gulbrandsen", "g_remap") | ("csv", "degrees") => json!({ "type": "boolean" }),
        ("csv", "path" | "x" | "y") => json!({ "type": "string" }),
        (kind, key) => panic!("no schema for the key {key:?} of {kind:?} data"),
    }
}

fn data_required(kind: &str) -> &'static [&'static str] {
    match kind {
        "gulbrandsen" => &["data", "x", "y", "r", "g"],
        "table" => &["data", "x", "y"],
        "csv" => &["data", "path"],
        _ => &["data"],
    }
}

/// A sweep of numbers: a number, a list, `{"range": …}` or `{"linspace": …}`; `number` is the
/// `$defs` name of one number (slider references are allowed only in curve entries).
fn sweep(number: &str) -> Value {
    let mut ranges = object(SWEEP_KEYS, &[], |key| match key {
        "range" => triple(reference(number), reference(number), reference(number)),
        "linspace" => triple(
            reference(number),
            reference(number),
            json!({ "type": "integer", "minimum": 1, "maximum": MAX_CURVES_PER_SCENE }),
        ),
        other => panic!("no schema for the sweep key {other:?}"),
    });
    ranges["minProperties"] = json!(1);
    json!({ "anyOf": [
        reference(number),
        { "type": "array", "items": reference(number), "minItems": 1, "maxItems": MAX_CURVES_PER_SCENE },
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
        object(
            scene::LAYOUT_KEYS,
            &[],
            |_| json!({ "type": "integer", "minimum": 1, "maximum": 100 }),
        ),
    );
    let mut sampling = object(scene::SAMPLING_KEYS, &[], |key| match key {
        "uniform" => {
            json!({ "type": "integer", "minimum": 2, "maximum": scene::MAX_SAMPLES_PER_CURVE })
        }
        "adaptive" => object(scene::ADAPTIVE_KEYS, &[], |_| json!({ "type": "number" })),
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
        "interactive",
        object(
            INTERACTIVE_KEYS,
            &["params"],
            |_| json!({ "type": "array", "items": reference("slider"), "minItems": 1, "maxItems": MAX_SLIDERS }),
        ),
    );
    def(
        "slider",
        object(PARAM_KEYS, &["name"], |key| match key {
            "name" => json!({ "type": "string", "pattern": "^[a-z][a-z0-9_]{0,31}$" }),
            "label" => json!({ "type": "string" }),
            "range" => json!({ "type": "array", "items": { "type": "number" }, "minItems": 2, "maxItems": 2 }),
            "scale" => json!({ "enum": SCALES }),
            "start" => json!({ "type": "number" }),
            other => panic!("no schema for the slider key {other:?}"),
        }),
    );
    def(
        "slider_reference",
        object(
            &[SLIDER_KEY],
            &[SLIDER_KEY],
            |_| json!({ "type": "string" }),
        ),
    );
    def(
        "number",
        json!({ "anyOf": [{ "type": "number" }, reference("slider_reference")] }),
    );
    def("plain_number", json!({ "type": "number" }));
    def("sweep", sweep("number"));
    def("plain_sweep", sweep("plain_number"));
    def(
        "fit",
        object(&[FIT_KEY], &[FIT_KEY], |_| {
            object(FIT_KEYS, &["target"], |key| match key {
                "target" => reference("scene_curve"),
                "by" => strings(&By::ALL.iter().map(|b| b.name()).collect::<Vec<_>>()),
                other => panic!("no schema for the fit key {other:?}"),
            })
        }),
    );

    let ops: Vec<&str> = DiffOp::ALL.iter().map(|op| op.name()).collect();
    let mut curves = Vec::new();
    let mut scene_curves = Vec::new();
    for model in models() {
        for (i, params) in model.signatures().iter().enumerate() {
            let name = signature_def("curve", model, i);
            def(
                &name,
                signature(model, params, &[], |spec| plain_param(model, spec)),
            );
            curves.push(reference(&name));
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
    let difference = |operand: &str, extras: &[&str]| {
        let keys: Vec<&str> = DIFFERENCE_KEYS.iter().chain(extras).copied().collect();
        object(&keys, DIFFERENCE_KEYS, |key| match key {
            DIFFERENCE_KEY => strings(&ops),
            "a" | "b" => reference(operand),
            extra => extra_key(extra),
        })
    };
    def("curve_difference", difference("curve", &[]));
    def(
        "scene_curve_difference",
        difference("scene_curve", scene::CURVE_EXTRA_KEYS),
    );
    def(
        "curve_transformed",
        object(TRANSFORM_KEYS, TRANSFORM_KEYS, |key| match key {
            TRANSFORM_KEY => strings(&names(&Transform::NAMES)),
            _ => reference("curve"),
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
    // The branches exclude one another (each requires its model key and names, and admits no other
    // keys), so exactly one matches a valid curve.
    def(
        "curve",
        json!({ "description": "the curve format of eval, compare and fit", "oneOf": curves }),
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
