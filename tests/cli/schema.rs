//! The JSON Schema of `ndfplot schema` against the validator: for every key table the schema's
//! property set equals the validator's, every key is described, the committed
//! `schema/ndfplot.schema.json` is current, every config validates against it, misspelt keys and
//! names fail it as they fail the validator, parameter domains and text fields refuse what the
//! validator refuses, and every malformed spec it accepts is named with the reason.

use crate::common::{ndfplot, root};
use ndfplot::spec::curve::{DIFFERENCE_KEYS, ENGINE_KEY, Model, TRANSFORM_KEYS};
use ndfplot::spec::input::parse_json;
use ndfplot::spec::quantity;
use ndfplot::spec::scene::interactive::{INTERACTIVE_KEYS, PARAM_KEYS, SLIDER_KEY};
use ndfplot::spec::scene::sweep::{FIT_KEY, FIT_KEYS, FROM_BECKMANN_KEY, SWEEP_KEYS};
use ndfplot::spec::scene::{self as scene, data};
use ndfplot::spec::schema::{self, data_def, model_names, models, signature_def};
use serde_json::{Value, json};
use std::collections::BTreeSet;

fn def<'a>(schema: &'a Value, name: &str) -> &'a Value {
    schema["$defs"]
        .get(name)
        .unwrap_or_else(|| panic!("no $defs/{name}"))
}

fn keys(object_schema: &Value) -> BTreeSet<String> {
    object_schema["properties"]
        .as_object()
        .expect("an object schema")
        .keys()
        .cloned()
        .collect()
}

fn set<'a>(words: impl IntoIterator<Item = &'a str>) -> BTreeSet<String> {
    words.into_iter().map(str::to_string).collect()
}

fn enum_of(schema: &Value) -> BTreeSet<String> {
    schema["enum"]
        .as_array()
        .expect("an enum")
        .iter()
        .map(|v| v.as_str().unwrap().to_string())
        .collect()
}

fn validator(schema: &Value, def: Option<&str>) -> jsonschema::Validator {
    let schema = match def {
        Some(name) => {
            json!({ "$schema": schema["$schema"], "$ref": format!("#/$defs/{name}"), "$defs": schema["$defs"] })
        }
        None => schema.clone(),
    };
    jsonschema::validator_for(&schema).expect("the schema compiles")
}

fn errors(validator: &jsonschema::Validator, instance: &Value) -> Vec<String> {
    validator
        .iter_errors(instance)
        .map(|e| format!("{}: {e}", e.instance_path()))
        .collect()
}

#[test]
fn every_key_table_equals_the_schema_properties() {
    let schema = schema::schema();
    let tables: [(&str, &[&str]); 12] = [
        ("scene", scene::SCENE_KEYS),
        ("layout", scene::LAYOUT_KEYS),
        ("sampling", scene::SAMPLING_KEYS),
        ("panel", scene::PANEL_KEYS),
        ("x_axis", scene::X_KEYS),
        ("y_axis", scene::Y_KEYS),
        ("z_axis", scene::Z_KEYS),
        ("camera", scene::CAMERA_KEYS),
        ("interactive", INTERACTIVE_KEYS),
        ("slider", PARAM_KEYS),
        ("slider_reference", &[SLIDER_KEY]),
        ("curve_transformed", TRANSFORM_KEYS),
    ];
    for (name, table) in tables {
        assert_eq!(
            keys(def(&schema, name)),
            set(table.iter().copied()),
            "$defs/{name}"
        );
    }
    let adaptive = &def(&schema, "sampling")["properties"]["adaptive"];
    assert_eq!(keys(adaptive), set(scene::ADAPTIVE_KEYS.iter().copied()));
    let sweep_object = &def(&schema, "sweep")["anyOf"][2];
    assert_eq!(keys(sweep_object), set(SWEEP_KEYS.iter().copied()));
    let fit = def(&schema, "fit");
    assert_eq!(keys(fit), set([FIT_KEY]));
    assert_eq!(
        keys(&fit["properties"][FIT_KEY]),
        set(FIT_KEYS.iter().copied())
    );
    assert_eq!(
        keys(def(&schema, "curve_difference")),
        set(DIFFERENCE_KEYS.iter().copied())
    );
    let scene_difference: BTreeSet<String> = set(DIFFERENCE_KEYS
        .iter()
        .chain(scene::CURVE_EXTRA_KEYS)
        .copied());
    assert_eq!(
        keys(def(&schema, "scene_curve_difference")),
        scene_difference
    );

    // Every model and signature, in both the plain and the scene curve format.
    for model in models() {
        for (i, params) in model.signatures().iter().enumerate() {
            // An NDF's parameters, then the keys of the quantity it shows, then an engine's.
            let engine = model.takes_engine(params);
            let params: Vec<&str> = params
                .iter()
                .map(|p| p.name)
                .chain(match model {
                    Model::Ndf(_) => quantity::KEYS.to_vec(),
                    Model::Fresnel(_) => vec![],
                })
                .chain(engine.then_some(ENGINE_KEY))
                .collect();
            let plain = def(&schema, &signature_def("curve", model, i));
            assert_eq!(
                keys(plain),
                set([model.key()].into_iter().chain(params.iter().copied())),
                "{model:?} {i}"
            );
            let in_scene = def(&schema, &signature_def("scene_curve", model, i));
            let expected = set([model.key()]
                .into_iter()
                .chain(params.iter().copied())
                .chain(scene::CURVE_EXTRA_KEYS.iter().copied()));
            assert_eq!(keys(in_scene), expected, "{model:?} {i}");
            assert_eq!(
                enum_of(&plain["properties"][model.key()]),
                set(model_names(model))
            );
        }
    }
    // Every accepted model name (aliases included) appears in some branch.
    let mut all_names = BTreeSet::new();
    for model in models() {
        all_names.extend(
            set(model_names(model))
                .into_iter()
                .map(|n| format!("{}:{n}", model.key())),
        );
    }
    let mut accepted: BTreeSet<String> = ndfplot::model::ndf::Family::NAMES
        .iter()
        .map(|n| format!("ndf:{n}"))
        .collect();
    accepted.extend(
        ndfplot::model::fresnel::FresnelModel::all().map(|m| format!("fresnel:{}", m.name())),
    );
    assert_eq!(all_names, accepted);

    for &kind in data::KINDS {
        let expected = set(data::COMMON_KEYS
            .iter()
            .chain(data::own_keys(kind))
            .copied());
        assert_eq!(keys(def(&schema, &data_def(kind))), expected, "data {kind}");
    }

    // Enumerated words.
    let panel = def(&schema, "panel");
    assert_eq!(
        enum_of(&panel["properties"]["kind"]),
        set(scene::PANEL_KINDS.iter().copied())
    );
    assert_eq!(
        enum_of(&def(&schema, "x_axis")["properties"]["unit"]),
        set(scene::X_UNITS.iter().copied())
    );
    assert_eq!(
        enum_of(&def(&schema, "y_axis")["properties"]["scale"]),
        set(scene::SCALES.iter().copied())
    );
    let curve = def(&schema, &signature_def("scene_curve", models()[0], 0));
    assert_eq!(
        enum_of(&curve["properties"]["style"]["anyOf"][0]),
        set(scene::STYLE_WORDS.iter().copied())
    );
    assert_eq!(
        enum_of(&curve["properties"]["mark"]),
        set(scene::MARKS.iter().copied())
    );
    let phong = &curve["properties"]["alpha_p"]["anyOf"];
    assert!(
        phong
            .as_array()
            .unwrap()
            .iter()
            .any(|o| o["properties"].get(FROM_BECKMANN_KEY).is_some())
    );
}

/// The JSON paths of the properties without a non-empty description, under `at`.
fn undescribed(schema: &Value, at: &str, missing: &mut Vec<String>) {
    match schema {
        Value::Object(members) => {
            if let Some(Value::Object(properties)) = members.get("properties") {
                for (key, property) in properties {
                    if property["description"].as_str().is_none_or(str::is_empty) {
                        missing.push(format!("{at}/properties/{key}"));
                    }
                }
            }
            for (key, member) in members {
                undescribed(member, &format!("{at}/{key}"), missing);
            }
        }
        Value::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                undescribed(item, &format!("{at}/{i}"), missing);
            }
        }
        _ => {}
    }
}

#[test]
fn every_property_has_a_description() {
    let mut missing = Vec::new();
    undescribed(&schema::schema(), "#", &mut missing);
    assert!(missing.is_empty(), "undescribed: {missing:#?}");
}

/// Whether the validator accepts the scene `text`.
fn validator_accepts(text: &str) -> bool {
    let node = parse_json(text, "scene").unwrap();
    scene::parse(&node, None).is_ok()
}

#[test]
fn parameter_domains_bound_values_and_sweeps_as_the_validator_does() {
    let validator = validator(&schema::schema(), None);
    let scene_of = |entry: &str| format!(r#"{{"id": "x", "panels": [{{"curves": [{entry}]}}]}}"#);
    // (curve entry, valid): every bound at its edge, each form of sweep, and the values a sweep
    // need not take (a range's stop, a linspace's stop at count 1).
    let cases = [
        (r#"{"ndf": "beckmann", "alpha_b": [1e-150, 1e4]}"#, true),
        (r#"{"ndf": "beckmann", "alpha_b": [0.5, 1.1e4]}"#, false),
        (r#"{"ndf": "abc", "alpha_abc1": 0, "alpha_abc2": 1}"#, false),
        (
            r#"{"ndf": "trowbridge_reitz", "alpha_tr": {"range": [0.1, 10000.05, 1000]}}"#,
            true,
        ),
        (
            r#"{"ndf": "trowbridge_reitz", "alpha_tr": {"range": [0, 1, 0.5]}}"#,
            false,
        ),
        (
            r#"{"ndf": "beckmann", "alpha_b": {"range": [0.1, 1, -0.0]}}"#,
            false,
        ),
        (
            r#"{"ndf": "beckmann", "alpha_b": {"linspace": [1e-150, 1e4, 3]}}"#,
            true,
        ),
        (
            r#"{"ndf": "beckmann", "alpha_b": {"linspace": [0.5, 1e5, 1]}}"#,
            true,
        ),
        (
            r#"{"ndf": "beckmann", "alpha_b": {"linspace": [0.5, 1e5, 2]}}"#,
            false,
        ),
        (
            r#"{"ndf": "beckmann", "alpha_b": {"linspace": [0, 0.5, 2]}}"#,
            false,
        ),
        (
            r#"{"fresnel": "exact", "eta": 1e-150, "kappa": [0, 1e150]}"#,
            true,
        ),
        (r#"{"fresnel": "exact", "eta": 1.5, "kappa": -0.1}"#, false),
        (r#"{"fresnel": "exact", "eta": 1.1e150}"#, false),
        (r#"{"fresnel": "belcour", "r": 0.999, "g": [0, 1]}"#, true),
        (r#"{"fresnel": "normalized", "r": 0.5, "g": 1.5}"#, false),
        (
            r#"{"fresnel": "schlick", "f0": {"range": [0, 1, 0.25]}}"#,
            true,
        ),
        (r#"{"fresnel": "lazanyi", "f0": 1.5, "a": 0}"#, false),
        (r#"{"fresnel": "basis", "index": [0, 1.0, 3]}"#, true),
        (r#"{"fresnel": "basis", "index": 4}"#, false),
        (r#"{"fresnel": "basis", "index": -1}"#, false),
        (
            r#"{"data": "gulbrandsen", "x": "c0", "y": "c1", "r": {"linspace": [0, 0.9, 4]}, "g": 1}"#,
            true,
        ),
        (
            r#"{"data": "gulbrandsen", "x": "c0", "y": "c1", "r": [0.5, 1], "g": 1}"#,
            false,
        ),
        (
            r#"{"ndf": "ggx", "alpha_tr": 0.3, "label": "α = {alpha_tr} ✓ \u00a0😀"}"#,
            true,
        ),
        (
            r#"{"ndf": "ggx", "alpha_tr": 0.3, "label": "a\u009fb"}"#,
            false,
        ),
        (
            r#"{"ndf": "ggx", "alpha_tr": 0.3, "label": "a\ufffeb"}"#,
            false,
        ),
        (
            r#"{"data": "table", "x": [0, 1], "y": [0, 1], "label": "a\u007f"}"#,
            false,
        ),
    ];
    for (entry, valid) in cases {
        let text = scene_of(entry);
        assert_eq!(validator_accepts(&text), valid, "validator: {entry}");
        let instance: Value = serde_json::from_str(&text).unwrap();
        assert_eq!(
            validator.is_valid(&instance),
            valid,
            "schema: {entry}: {:?}",
            errors(&validator, &instance)
        );
    }
    let slider = |label: &str| {
        format!(
            r#"{{"id": "x", "interactive": {{"params": [{{"name": "a", "label": "{label}", "range": [0.1, 1]}}]}}, "panels": [{{"curves": [{{"ndf": "beckmann", "alpha_b": {{"slider": "a"}}}}]}}]}}"#
        )
    };
    for (label, valid) in [("α_b", true), (r"α\u0000", false)] {
        let text = slider(label);
        assert_eq!(validator_accepts(&text), valid, "validator: {label}");
        let instance: Value = serde_json::from_str(&text).unwrap();
        assert_eq!(validator.is_valid(&instance), valid, "schema: {label}");
    }
}

#[test]
fn text_fields_refuse_exactly_the_control_characters_and_u_fffe_u_ffff() {
    let validator = validator(&schema::schema(), Some("text"));
    let refused: Vec<char> = (0..=u32::from(char::MAX))
        .filter_map(char::from_u32)
        .filter(|&c| !validator.is_valid(&json!(format!("a{c}b"))))
        .collect();
    let control: Vec<char> = (0..=u32::from(char::MAX))
        .filter_map(char::from_u32)
        .filter(|&c| c.is_control() || matches!(c, '\u{fffe}' | '\u{ffff}'))
        .collect();
    assert_eq!(refused, control);
}

#[test]
fn the_committed_schema_is_the_generated_one() {
    let out = ndfplot(&["schema"]);
    assert_eq!(out.status.code(), Some(0));
    let committed = std::fs::read_to_string(root().join(schema::COMMITTED_PATH)).unwrap();
    assert!(
        committed == String::from_utf8(out.stdout).unwrap(),
        "{} is stale: regenerate it with `ndfplot schema > {}`",
        schema::COMMITTED_PATH,
        schema::COMMITTED_PATH
    );
}

#[test]
fn every_config_validates_and_references_the_schema() {
    let schema = schema::schema();
    let validator = validator(&schema, None);
    let mut count = 0;
    for entry in std::fs::read_dir(root().join("configs")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "json") {
            continue;
        }
        let config: Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
        assert_eq!(
            config["$schema"],
            "../schema/ndfplot.schema.json",
            "{}",
            path.display()
        );
        let problems = errors(&validator, &config);
        assert!(problems.is_empty(), "{}: {problems:#?}", path.display());
        count += 1;
    }
    assert!(count >= 20, "only {count} configs");
}

#[test]
fn curves_validate_against_the_curve_definition() {
    let validator = validator(&schema::schema(), Some("curve"));
    for good in [
        json!({"ndf": "ggx", "alpha_tr": 0.5}),
        json!({"fresnel": "exact", "r": 0.5, "g": 0.2, "g_remap": true}),
        json!({"fresnel": "lazanyi_term"}),
        json!({"difference": "ratio", "a": {"ndf": "phong", "alpha_p": 10}, "b": {"ndf": "beckmann", "alpha_b": 0.4}}),
        json!({"transform": "slope", "curve": {"ndf": "beckmann", "alpha_b": 0.4}}),
    ] {
        assert!(
            errors(&validator, &good).is_empty(),
            "{good}: {:?}",
            errors(&validator, &good)
        );
    }
    for bad in [
        json!({"ndf": "beckman", "alpha_b": 0.5}),
        json!({"ndf": "beckmann", "alpha": 0.5}),
        json!({"ndf": "abc", "alpha_abc1": 1}),
        json!({"fresnel": "exact", "eta": 1.5, "r": 0.5}),
        json!({"ndf": "beckmann", "alpha_b": [0.1, 0.2]}),
        json!({"ndf": "beckmann", "alpha_b": 0.5, "style": "thick"}),
    ] {
        assert!(!validator.is_valid(&bad), "{bad} passed");
    }
}

#[test]
fn misspelt_keys_and_names_fail_the_schema_as_they_fail_the_validator() {
    let validator = validator(&schema::schema(), None);
    let dir = root().join("tests/data/malformed");
    for case in [
        "unknown-scene-key",
        "style-key-misspelt",
        "style-misspelt",
        "misspelt-param",
        "unknown-family",
        "unknown-fresnel",
        "sweep-misspelt",
        "data-kind-misspelt",
        "mark-bad",
        "x-unit-misspelt",
        "exclusive-keys",
        "both-models",
        "no-model",
        "missing-id",
        "missing-param",
        "difference-op-misspelt",
        "fit-by-misspelt",
        "empty-panels",
        "sweep-empty-list",
        "view-misspelt",
        "theme-misspelt",
        "transform-misspelt",
    ] {
        let text = std::fs::read_to_string(dir.join(format!("{case}.json"))).unwrap();
        let instance: Value = serde_json::from_str(&text).unwrap();
        assert!(!validator.is_valid(&instance), "{case} passed the schema");
    }
}

/// Malformed specs the schema accepts, each with the reason: cross-field and computed rules and the
/// file system, which a JSON Schema cannot state; it rejects every other file of
/// `tests/data/malformed/`.
const SCHEMA_CANNOT_TELL: &[(&str, &str)] = &[
    (
        "albedo-without-heatmap",
        "cross-field: a data series with z needs a surface or heat-map panel",
    ),
    (
        "camera-without-surface",
        "cross-field: camera is allowed only when the panel's kind is surface",
    ),
    (
        "colour-both-spellings",
        "cross-field: `colour` and `color` are one key in two spellings",
    ),
    (
        "data-csv-absolute-path",
        "the file system decides: where the path leads",
    ),
    ("data-csv-long-header", "the file's contents decide"),
    ("data-csv-missing-file", "the file system decides"),
    ("data-csv-non-numeric", "the file's contents decide"),
    ("data-csv-not-a-file", "the file system decides"),
    (
        "data-csv-parent-path",
        "the file system decides: where the path leads",
    ),
    ("data-csv-repeated-column", "the file's contents decide"),
    ("data-csv-unknown-column", "the file's contents decide"),
    (
        "data-gulbrandsen-grid-cap",
        "cross-field: the product of the grid sizes",
    ),
    (
        "data-table-lengths",
        "cross-field: the columns' lengths must agree",
    ),
    (
        "difference-mixed-kinds",
        "cross-field: both operands of one kind",
    ),
    (
        "duplicate-key",
        "a JSON parser keeps one value per key: the schema never sees the duplicate",
    ),
    (
        "from-beckmann-out-of-range",
        "the converted value's domain (2/α_b² − 2 ≥ 0) is a computed bound",
    ),
    (
        "heatmap-axes",
        "cross-field: a heat-map panel's x axis has no unit",
    ),
    (
        "heatmap-camera",
        "cross-field: camera is allowed only when the panel's kind is surface",
    ),
    (
        "heatmap-log-y",
        "cross-field: a heat-map panel's y axis is linear",
    ),
    (
        "heatmap-not-a-map",
        "cross-field: a heat-map panel shows one albedo series",
    ),
    (
        "heatmap-with-curves",
        "cross-field: a heat-map panel shows no curves of θ",
    ),
    (
        "label-unknown-placeholder",
        "cross-field: a label's placeholders are the curve's parameters",
    ),
    (
        "layout-too-small",
        "cross-field: rows × cols against the number of panels",
    ),
    (
        "metal-out-of-range",
        "data: each metal's measured wavelength range is in its table",
    ),
    (
        "png-over-raster-cap",
        "computed: the product width × height × scale² against the cap",
    ),
    (
        "png-too-many-pixels",
        "cross-field: width × height × png_scale²",
    ),
    ("points-over-cap", "cross-field: curves × samples"),
    (
        "quantity-g1-family",
        "cross-field: a Beckmann-based G1 needs a family with a Beckmann-equivalent roughness",
    ),
    (
        "range-over-cap",
        "computed: the number of values a range gives",
    ),
    (
        "range-wrong-direction",
        "cross-field: the sign of (b − a)/s",
    ),
    (
        "slope-range-negative",
        "cross-field: the x unit decides the range's domain",
    ),
    (
        "sweep-at-curve-cap-over-points-cap",
        "computed: curves × samples against the scene's point cap",
    ),
    (
        "sweep-product-over-cap",
        "computed: the product of the sweeps' sizes",
    ),
    (
        "transform-fresnel",
        "cross-field: a view transform applies to NDF curves only",
    ),
    (
        "transform-on-data",
        "cross-field: the panel's transform against its data series",
    ),
    (
        "transform-on-surface",
        "cross-field: the panel's kind against its transform",
    ),
    (
        "view-on-surface",
        "cross-field: the panel's kind against its view",
    ),
    (
        "view-polar-on-slope-axis",
        "cross-field: the view against the x unit",
    ),
    (
        "view-polar-with-slope-transform",
        "cross-field: the view against the transform",
    ),
    (
        "width-too-big",
        "cross-field: the size cap depends on the unit (px, in, cm)",
    ),
    (
        "x-log-polar",
        "cross-field: the x scale against the panel's view",
    ),
    (
        "x-log-range-from-zero",
        "cross-field: the x scale decides whether the range may start at 0",
    ),
    (
        "x-log-without-range",
        "cross-field: a log θ axis needs the range key",
    ),
    (
        "x-range-degrees",
        "cross-field: the x unit decides the range's bounds",
    ),
    (
        "y-log-range",
        "cross-field: a log scale needs a positive range",
    ),
    (
        "y-range-overflowing-span",
        "computed: the span b − a overflows",
    ),
];

#[test]
fn the_schema_rejects_every_malformed_spec_it_can_express() {
    let schema: Value = serde_json::from_str(&schema::text()).unwrap();
    let validator = validator(&schema, None);
    let dir = root().join("tests/data/malformed");
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|n| n.ends_with(".json"))
        .collect();
    names.sort();
    let mut accepted = Vec::new();
    for name in &names {
        // A file that is not JSON at all (a syntax mistake) is rejected before any schema.
        let Ok(instance) = serde_json::from_slice::<Value>(&std::fs::read(dir.join(name)).unwrap())
        else {
            continue;
        };
        if validator.is_valid(&instance) {
            accepted.push(name.trim_end_matches(".json").to_string());
        }
    }
    let expected: Vec<String> = SCHEMA_CANNOT_TELL
        .iter()
        .map(|(n, _)| n.to_string())
        .collect();
    assert_eq!(accepted, expected, "malformed specs the schema accepts");
}
