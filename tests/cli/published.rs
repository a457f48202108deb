//! Published MERL fits as curves (`{"published": …}`) through the real binary: `eval`, `compare`,
//! `fit` and scenes (sweeps over materials and channels) see the family curve of the fit; bad names
//! exit 2 with a suggestion.

use crate::common::{csv_records, ndfplot, render_into, scratch, text};

const GOLD_SGD_RED: &str =
    r#"{"published":"bagher2012-sgd","material":"gold-metallic-paint","channel":"red"}"#;

#[test]
fn eval_names_the_column_by_the_resolved_family_curve() {
    let out = ndfplot(&[
        "eval",
        "--curve",
        GOLD_SGD_RED,
        "--curve",
        r#"{"published":"ngan2005-blinn-phong","material":"gold-metallic-paint"}"#,
        "--theta",
        "0,0.5",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let header = text(&out.stdout).lines().next().unwrap().to_string();
    assert_eq!(
        header,
        r#"theta,"{""ndf"":""sgd"",""alpha_sgd1"":0.127954,""alpha_sgd2"":0.781093}","{""ndf"":""phong"",""alpha_p"":41.9}""#
    );
    // The same numbers as the family curve written out.
    let family = ndfplot(&[
        "eval",
        "--curve",
        r#"{"ndf":"sgd","alpha_sgd1":0.127954,"alpha_sgd2":0.781093}"#,
        "--theta",
        "0,0.5",
    ]);
    let preset = ndfplot(&["eval", "--curve", GOLD_SGD_RED, "--theta", "0,0.5"]);
    assert_eq!(text(&family.stdout), text(&preset.stdout));
}

#[test]
fn fit_and_compare_take_published_curves() {
    let fit = ndfplot(&[
        "fit",
        "--target",
        r#"{"published":"low2012-abc","material":"gray-plastic"}"#,
        "--family",
        "beckmann",
        "--by",
        "peak",
    ]);
    assert_eq!(fit.status.code(), Some(0), "{}", text(&fit.stderr));
    assert!(text(&fit.stdout).starts_with(r#"{"ndf":"beckmann","alpha_b":"#));
    let compare = ndfplot(&[
        "compare",
        "--a",
        r#"{"published":"low2012-cook-torrance","material":"gray-plastic"}"#,
        "--b",
        r#"{"published":"ngan2005-cook-torrance","material":"gray-plastic"}"#,
    ]);
    assert_eq!(compare.status.code(), Some(0), "{}", text(&compare.stderr));
    assert!(text(&compare.stdout).contains(r#"{"ndf":"beckmann","alpha_b":0.031441}"#));
}

#[test]
fn unknown_names_and_channel_mistakes_exit_2_naming_the_key() {
    let cases = [
        (
            r#"{"published":"bagher2012-sgd","material":"gold-metalic-paint","channel":"red"}"#,
            r#"material: unknown material (got "gold-metalic-paint", expected one of the 100 names the source fits); did you mean "gold-metallic-paint"?"#,
        ),
        (
            r#"{"published":"low2012-abd","material":"gray-plastic"}"#,
            r#"published: unknown source (got "low2012-abd", expected one of: bagher2012-sgd, low2012-abc, low2012-cook-torrance, ngan2005-cook-torrance, ngan2005-blinn-phong); did you mean "low2012-abc"?"#,
        ),
        (
            r#"{"published":"bagher2012-sgd","material":"gray-plastic","channel":"gren"}"#,
            r#"channel: unknown channel (got "gren", expected one of: red, green, blue); did you mean "green"?"#,
        ),
        (
            r#"{"published":"bagher2012-sgd","material":"gray-plastic"}"#,
            r#"channel: missing channel: "bagher2012-sgd" fits each RGB channel separately (expected one of: red, green, blue)"#,
        ),
        (
            r#"{"published":"low2012-abc","material":"gray-plastic","channel":"red"}"#,
            r#"channel: "low2012-abc" fits one lobe per material, not per channel (got "red", expected no "channel")"#,
        ),
        (
            r#"{"published":"low2012-abc"}"#,
            r#"material: missing the MERL material of the published fit"#,
        ),
        (
            r#"{"published":"low2012-abc","material":["gray-plastic","gold-metallic-paint"]}"#,
            "a list of materials or channels sweeps in scenes only",
        ),
    ];
    for (curve, message) in cases {
        let out = ndfplot(&["eval", "--curve", curve, "--theta", "0"]);
        assert_eq!(out.status.code(), Some(2), "{curve}");
        let stderr = text(&out.stderr);
        assert!(
            stderr.contains(&format!("error: --curve: {message}")),
            "{curve}: {stderr}"
        );
    }
}

#[test]
fn scenes_sweep_materials_and_channels_and_fit_to_published_targets() {
    let dir = scratch("published-scene");
    let spec = dir.join("published.json");
    std::fs::write(
        &spec,
        r#"{"id": "published", "panels": [{"curves": [
            {"published": "bagher2012-sgd", "material": ["gold-metallic-paint", "gray-plastic"], "channel": ["red", "blue"]},
            {"ndf": "trowbridge_reitz", "alpha_tr": {"fit": {"target": {"published": "low2012-abc", "material": "gray-plastic"}, "by": "peak"}}},
            {"difference": "minus", "a": {"published": "low2012-cook-torrance", "material": "gray-plastic"},
             "b": {"published": "ngan2005-cook-torrance", "material": "gray-plastic"}}
        ]}]}"#,
    )
    .unwrap();
    let out = dir.join("out");
    render_into(&[&spec], &out, "csv,svg");
    let mut curves: Vec<String> = csv_records(out.join("published.csv").to_str().unwrap())
        .iter()
        .map(|r| r[2].to_string())
        .collect();
    curves.dedup();
    assert_eq!(curves.len(), 6, "{curves:?}");
    assert_eq!(
        curves[0],
        r#"{"ndf":"sgd","alpha_sgd1":0.127954,"alpha_sgd2":0.781093}"#
    );
    assert_eq!(
        curves[1],
        r#"{"ndf":"sgd","alpha_sgd1":0.109623,"alpha_sgd2":0.661313}"#
    );
    assert!(
        curves[2].contains(r#""alpha_sgd1":0.00758705"#),
        "{curves:?}"
    );
    assert!(curves[4].starts_with(r#"{"ndf":"trowbridge_reitz","alpha_tr":"#));
    assert_eq!(
        curves[5],
        r#"{"difference":"minus","a":{"ndf":"beckmann","alpha_b":0.031441},"b":{"ndf":"beckmann","alpha_b":0.026}}"#
    );
    let svg = std::fs::read_to_string(out.join("published.svg")).unwrap();
    assert!(svg.contains("Bagher 2012 SGD, gray-plastic, blue"));
    assert!(svg.contains("Low 2012 Cook–Torrance − Ngan 2005 Cook–Torrance"));
}

#[test]
fn a_bad_material_in_a_scene_names_the_file_and_path() {
    let dir = scratch("published-bad");
    let spec = dir.join("bad.json");
    std::fs::write(
        &spec,
        r#"{"id": "bad", "panels": [{"curves": [{"published": "ngan2005-cook-torrance", "material": ["gray-plastic", "grey-plastic"]}]}]}"#,
    )
    .unwrap();
    let out = ndfplot(&[
        "render",
        spec.to_str().unwrap(),
        "-o",
        dir.join("out").to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains(
            "bad.json: panels[0].curves[0].material[1]: unknown material (got \"grey-plastic\""
        ) && stderr.contains("did you mean \"gray-plastic\"?"),
        "{stderr}"
    );
}

/// A published fit shows a quantity as its resolved family curve does: `"quantity": "g1"` on Low
/// 2012's ABC fit of gold-metallic-paint is G1 of that ABC lobe (the published parameters typed out),
/// in `eval` and in a scene; a quantity the family cannot show is refused at the fit's path.
#[test]
fn a_published_fit_shows_quantities_as_its_family_curve_does() {
    let published =
        r#"{"published":"low2012-abc","material":"gold-metallic-paint","quantity":"g1"}"#;
    let typed = r#"{"ndf":"abc","alpha_abc1":53.738525,"alpha_abc2":1.51173,"quantity":"g1"}"#;
    let theta = "0,0.5,1,1.4,1.5707963267948966";
    let a = ndfplot(&["eval", "--curve", published, "--theta", theta]);
    let b = ndfplot(&["eval", "--curve", typed, "--theta", theta]);
    assert_eq!(a.status.code(), Some(0), "{}", text(&a.stderr));
    assert_eq!(text(&a.stdout), text(&b.stdout));

    let dir = scratch("published-quantity");
    let spec = dir.join("published-g1.json");
    std::fs::write(
        &spec,
        format!(r#"{{"id":"published-g1","sampling":{{"uniform":5}},"panels":[{{"curves":[{published}]}}]}}"#),
    )
    .unwrap();
    render_into(&[&spec], &dir, "csv");
    let rows = csv_records(dir.join("published-g1.csv").to_str().unwrap());
    assert_eq!(rows.len(), 5);

    let furnace = r#"{"published":"low2012-abc","material":"gold-metallic-paint","quantity":"furnace","g1":"no-such"}"#;
    let out = ndfplot(&["eval", "--curve", furnace, "--theta", "0"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).contains("--curve: g1:"),
        "{}",
        text(&out.stderr)
    );
}
