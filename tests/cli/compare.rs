//! `compare` focused on a θ range (`--theta-range`, `--degrees`), the `max_log_ratio` metric for lobes
//! that fall to 0, `--metric NAME`, many pairs at once (`--pairs`), and the machine-readable
//! `--format json|csv` of `compare`, `check` and `coeffs`.

use crate::common::{ndfplot, ndfplot_stdin, scratch, streamed, text};
use std::process::Output;

/// GGX α = 0.3 and its peak-matched Beckmann (`fit --family beckmann --by peak` gives α_b = 0.3 too):
/// Beckmann underflows to 0 towards grazing, so `max_rel` is 1 over the whole hemisphere.
const GGX: &str = r#"{"ndf":"ggx","alpha_tr":0.3}"#;
const BECKMANN: &str = r#"{"ndf":"beckmann","alpha_b":0.3}"#;

fn ok(output: &Output) -> String {
    assert_eq!(output.status.code(), Some(0), "{}", text(&output.stderr));
    text(&output.stdout)
}

/// Asserts exit 2, nothing on stdout, and `needle` in the one `error:` line.
fn usage_error(output: &Output, needle: &str) {
    let err = text(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{err}");
    assert!(output.stdout.is_empty(), "{}", text(&output.stdout));
    assert!(
        err.starts_with("error: ") && err.contains(needle),
        "{needle:?} in {err}"
    );
}

fn compare(extra: &[&str]) -> Output {
    let mut args = vec!["compare", "--a", GGX, "--b", BECKMANN];
    args.extend(extra);
    ndfplot(&args)
}

fn number(text: &str) -> f64 {
    text.trim()
        .parse()
        .unwrap_or_else(|e| panic!("{text:?}: {e}"))
}

#[test]
fn compare_max_log_ratio_is_finite_where_max_rel_saturates() {
    let whole = ok(&compare(&["--metric", "max_rel"]));
    assert_eq!(number(&whole), 1.0, "Beckmann reaches 0 before grazing");
    let focused: serde_json::Value = serde_json::from_str(&ok(&compare(&[
        "--theta-range",
        "0:50",
        "--degrees",
        "--format",
        "json",
    ])))
    .unwrap();
    let log = focused["max_log_ratio"].as_f64().unwrap();
    // At 50°: ln(D_GGX/D_Beckmann), both evaluated by eval.
    let at_50 = |curve: &str| {
        let csv = ok(&ndfplot(&[
            "eval",
            "--curve",
            curve,
            "--theta",
            "50",
            "--degrees",
        ]));
        number(csv.lines().nth(1).unwrap().split(',').nth(1).unwrap())
    };
    let expected = (at_50(GGX) / at_50(BECKMANN)).ln();
    assert!((log / expected - 1.0).abs() < 1e-12, "{log} vs {expected}");
    assert_eq!(focused["max_log_ratio_theta_deg"], 50.0);
    assert_eq!(focused["theta_from_deg"], 0.0);
    assert_eq!(focused["theta_to_deg"], 50.0);
    assert!(focused["max_rel"].as_f64().unwrap() < 1.0, "{focused}");
    assert!(
        focused.get("max_rel_theta").is_none(),
        "angles are named _deg: {focused}"
    );
}

#[test]
fn a_theta_range_in_radians_accepts_multiples_of_pi_and_limits_every_metric() {
    let whole: serde_json::Value =
        serde_json::from_str(&ok(&compare(&["--format", "json"]))).unwrap();
    let focused: serde_json::Value = serde_json::from_str(&ok(&compare(&[
        "--theta-range",
        "pi/8:pi/4",
        "--format",
        "json",
    ])))
    .unwrap();
    let (lo, hi) = (std::f64::consts::PI / 8.0, std::f64::consts::FRAC_PI_4);
    assert_eq!(
        (focused["theta_from"].as_f64(), focused["theta_to"].as_f64()),
        (Some(lo), Some(hi))
    );
    for name in [
        "max_abs_theta",
        "max_rel_theta",
        "max_log_ratio_theta",
        "a_peak_theta",
        "b_peak_theta",
    ] {
        let theta = focused[name].as_f64().unwrap();
        assert!((lo..=hi).contains(&theta), "{name} = {theta}");
    }
    assert_eq!(
        focused["a_peak_theta"].as_f64(),
        Some(lo),
        "D falls off the normal"
    );
    for name in ["l2_projected", "l2_grid", "max_abs"] {
        assert!(
            focused[name].as_f64() < whole[name].as_f64(),
            "{name}: {focused} vs {whole}"
        );
    }
    let table = ok(&compare(&["--theta-range", "0:pi/4"]));
    assert!(
        table.contains("\ntheta  0.0:0.7853981633974483\n"),
        "{table}"
    );
    assert!(
        table.lines().any(|l| l.starts_with("max_log_ratio ")),
        "{table}"
    );
}

#[test]
fn an_undefined_log_ratio_is_reported_not_invented() {
    // Beckmann α_b = 0.001 is exp(−tan²θ / α_b²) = 0 from well before 60°.
    let narrow = r#"{"ndf":"beckmann","alpha_b":0.001}"#;
    let args = |extra: &[&'static str]| {
        let mut args = vec![
            "compare",
            "--a",
            narrow,
            "--b",
            GGX,
            "--theta-range",
            "60:90",
            "--degrees",
        ];
        args.extend_from_slice(extra);
        ndfplot(&args)
    };
    let table = ok(&args(&[]));
    let row = table
        .lines()
        .find(|l| l.starts_with("max_log_ratio"))
        .unwrap();
    assert!(
        row.contains("undefined")
            && row.contains("no theta in 60.0:90.0 where both sides exceed 1e-300"),
        "{table}"
    );
    let json: serde_json::Value = serde_json::from_str(&ok(&args(&["--format", "json"]))).unwrap();
    assert!(
        json["max_log_ratio"].is_null() && json["max_log_ratio_theta_deg"].is_null(),
        "{json}"
    );
    let csv = ok(&args(&["--format", "csv"]));
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let column = header.iter().position(|&h| h == "max_log_ratio").unwrap();
    let row = csv::ReaderBuilder::new()
        .from_reader(csv.as_bytes())
        .records()
        .next()
        .unwrap()
        .unwrap();
    assert_eq!(&row[column], "", "{csv}");
    usage_error(
        &args(&["--metric", "max_log_ratio"]),
        "compare: max_log_ratio is undefined",
    );
    let gated = args(&["--max-error", "max_log_ratio=1"]);
    assert_eq!(gated.status.code(), Some(1));
    assert!(
        text(&gated.stderr).contains("max_log_ratio is undefined"),
        "{}",
        text(&gated.stderr)
    );
}

#[test]
fn metric_prints_one_number_and_an_unknown_name_lists_the_names() {
    let json: serde_json::Value =
        serde_json::from_str(&ok(&compare(&["--format", "json"]))).unwrap();
    for name in [
        "max_abs",
        "max_abs_theta",
        "max_log_ratio",
        "l2_projected",
        "b_peak",
    ] {
        let out = ok(&compare(&["--metric", name]));
        assert_eq!(out.lines().count(), 1, "{out}");
        assert_eq!(number(&out), json[name].as_f64().unwrap(), "{name}");
    }
    usage_error(
        &compare(&["--metric", "max_relative"]),
        "--metric: unknown name (got \"max_relative\", expected one of: theta_from, theta_to, max_abs, max_abs_theta, max_rel, max_rel_theta, max_log_ratio, max_log_ratio_theta, l2_projected, l2_grid, a_peak, a_peak_theta, b_peak, b_peak_theta)",
    );
    usage_error(
        &compare(&["--metric", "max_abs_theta", "--degrees"]),
        "max_abs_theta_deg",
    );
    let both = compare(&["--metric", "max_abs", "--format", "json"]);
    assert_eq!(
        both.status.code(),
        Some(2),
        "--metric prints one number, not a format"
    );
}

#[test]
fn bad_theta_ranges_exit_2_naming_the_flag_and_value() {
    for (range, degrees, needle) in [
        (
            "0:100",
            true,
            "--theta-range: angle out of range (got 100.0 degrees, expected 0 to 90)",
        ),
        (
            "0.5:0.5",
            false,
            "--theta-range: the range is empty (got 0.5:0.5, expected A < B)",
        ),
        ("1:0", false, "the range is empty (got 1.0:0.0"),
        ("0:2", false, "angle out of range (got 2.0 radians"),
        ("0", false, "--theta-range: expected A:B (got \"0\""),
        ("0:x", false, "--theta-range: not a number (got \"x\")"),
        ("0:pi/4", true, "--theta-range: not a number (got \"pi/4\")"),
        ("0:nan", false, "not a finite number"),
    ] {
        let mut args = vec!["--theta-range", range];
        if degrees {
            args.push("--degrees");
        }
        usage_error(&compare(&args), needle);
    }
}

#[test]
fn compare_csv_is_one_row_with_the_json_names() {
    let json: serde_json::Value =
        serde_json::from_str(&ok(&compare(&["--format", "json"]))).unwrap();
    let csv = ok(&compare(&["--format", "csv"]));
    let mut reader = csv::Reader::from_reader(csv.as_bytes());
    let header: Vec<String> = reader.headers().unwrap().iter().map(String::from).collect();
    let names: Vec<&String> = json.as_object().unwrap().keys().collect();
    let mut sorted = header.clone();
    sorted.sort();
    assert_eq!(sorted.iter().collect::<Vec<_>>(), names, "same names");
    let rows: Vec<csv::StringRecord> = reader.records().map(Result::unwrap).collect();
    assert_eq!(rows.len(), 1);
    assert_eq!(&rows[0][0], r#"{"ndf":"trowbridge_reitz","alpha_tr":0.3}"#);
    for (name, cell) in header.iter().zip(rows[0].iter()).skip(2) {
        assert_eq!(number(cell), json[name].as_f64().unwrap(), "{name}");
    }
}

#[test]
fn check_and_coeffs_print_json_and_csv_with_the_table_columns() {
    let spec = crate::common::root().join("configs/fresnel-dielectrics.json");
    let spec = spec.to_str().unwrap();
    let table = ok(&ndfplot(&["check", spec]));
    let rows = table.lines().count() - 1;
    let json: serde_json::Value =
        serde_json::from_str(&ok(&ndfplot(&["check", spec, "--format", "json"]))).unwrap();
    let objects = json.as_array().unwrap();
    assert_eq!(objects.len(), rows);
    let first = &objects[0];
    assert_eq!(first["status"], "-");
    assert_eq!(first["quantity"], "hemispherical_average");
    assert!(
        first["deviation"].is_null() && first["curve"]["fresnel"].is_string(),
        "{first}"
    );
    let csv = ok(&ndfplot(&["check", spec, "--format", "csv"]));
    assert!(
        csv.starts_with("status,quantity,integral,error_estimate,deviation,scene,curve\n"),
        "{csv}"
    );
    assert_eq!(csv.lines().count(), rows + 1);
    let ndfs = crate::common::root().join("configs/abc-vs-tr.json");
    let json: serde_json::Value = serde_json::from_str(&ok(&ndfplot(&[
        "check",
        ndfs.to_str().unwrap(),
        "--format",
        "json",
    ])))
    .unwrap();
    assert!(
        json.as_array()
            .unwrap()
            .iter()
            .all(|row| row["status"] == "ok" && row["deviation"].as_f64().unwrap() < 1e-9)
    );

    let material = r#"{"fresnel":"belcour","eta":0.29,"kappa":2.86}"#;
    let csv = ok(&ndfplot(&[
        "coeffs", "--curve", material, "--curve", material,
    ]));
    let json: serde_json::Value = serde_json::from_str(&ok(&ndfplot(&[
        "coeffs", "--curve", material, "--curve", material, "--format", "json",
    ])))
    .unwrap();
    let rows = json.as_array().unwrap();
    assert_eq!(rows.len(), 2);
    let line: Vec<f64> = csv.lines().nth(1).unwrap().split(',').map(number).collect();
    let from_json: Vec<f64> = ["c0", "c1", "c2", "c3", "l2"]
        .iter()
        .map(|k| rows[0][k].as_f64().unwrap())
        .collect();
    assert_eq!(line, from_json);
    usage_error(
        &ndfplot(&["coeffs", "--curve", material, "--format", "table"]),
        "--format",
    );
}

/// Pairs of every form `--pairs` reads: `a`/`b`, a record of `fit --format jsonl` (whose `residual` and
/// `metric` are not read), Fresnel curves, and a CSV series; blank lines are skipped.
fn pairs() -> Vec<(String, String)> {
    let series = crate::common::root().join("examples/renderer-ggx.csv");
    let series = format!(r#"{{"data":"csv","path":{:?}}}"#, series.to_str().unwrap());
    [
        (GGX, BECKMANN),
        (
            r#"{"ndf":"phong","alpha_p":20}"#,
            r#"{"ndf":"ggx","alpha_tr":0.4}"#,
        ),
        (
            r#"{"fresnel":"exact","eta":1.5}"#,
            r#"{"fresnel":"schlick","eta":1.5}"#,
        ),
        (series.as_str(), GGX),
    ]
    .map(|(a, b)| (a.to_string(), b.to_string()))
    .to_vec()
}

/// The JSON Lines input of [`pairs`], the second one as a `fit` record and a blank line after the
/// first.
fn pairs_input() -> String {
    pairs()
        .iter()
        .enumerate()
        .map(|(i, (a, b))| match i {
            0 => format!("{{\"a\":{a},\"b\":{b}}}\n\n"),
            1 => format!(
                "{{\"target\":{a},\"fit\":{b},\"residual\":0.5,\"metric\":\"l2_projected\"}}\n"
            ),
            _ => format!("{{\"b\": {b}, \"a\": {a}}}\n"),
        })
        .collect()
}

/// `compare --a A --b B extra…` with the series' path allowed.
fn single(a: &str, b: &str, extra: &[&str]) -> String {
    let root = crate::common::root().to_str().unwrap().to_string();
    let mut args = vec!["compare", "--a", a, "--b", b, "--allow-read", &root];
    args.extend(extra);
    ok(&ndfplot(&args))
}

/// `compare --pairs - extra…` on `input`, with the series' path allowed.
fn batch(input: &str, extra: &[&str]) -> Output {
    let root = crate::common::root().to_str().unwrap().to_string();
    let mut args = vec!["compare", "--pairs", "-", "--allow-read", &root];
    args.extend(extra);
    ndfplot_stdin(&args, input)
}

/// The input lines of [`pairs_input`]'s pairs.
const PAIR_LINES: [usize; 4] = [1, 3, 4, 5];

#[test]
fn every_pair_gives_the_row_of_its_single_compare_in_input_order() {
    let input = pairs_input();
    for extra in [
        &["--format", "json"][..],
        &["--format", "json", "--theta-range", "10:60", "--degrees"],
        &["--metric", "l2_projected"],
        &["--metric", "max_rel_theta", "--theta-range", "0:pi/4"],
    ] {
        // A batch record is the single record between its line and its status.
        let expected: String = pairs()
            .iter()
            .zip(PAIR_LINES)
            .map(|((a, b), line)| {
                let one = single(a, b, extra);
                match one.strip_prefix('{') {
                    Some(fields) => format!(
                        "{{\"line\":{line},{},\"status\":\"ok\",\"error\":\"\"}}\n",
                        fields.trim_end().strip_suffix('}').unwrap()
                    ),
                    None => one,
                }
            })
            .collect();
        assert_eq!(ok(&batch(&input, extra)), expected, "{extra:?}");
    }
    let csv = ok(&batch(&input, &["--format", "csv"]));
    let mut expected = String::new();
    for (i, ((a, b), line)) in pairs().iter().zip(PAIR_LINES).enumerate() {
        let one = single(a, b, &["--format", "csv"]);
        let (header, row) = one.split_once('\n').unwrap();
        if i == 0 {
            expected = format!("line,{header},status,error\n");
        }
        expected.push_str(&format!("{line},{},ok,\n", row.trim_end()));
    }
    assert_eq!(csv, expected);
}

#[test]
fn the_pairs_table_has_one_row_per_pair_named_by_its_line() {
    let input = pairs_input();
    let table = ok(&batch(&input, &[]));
    let lines: Vec<&str> = table.lines().collect();
    let header: Vec<&str> = lines[0].split_whitespace().collect();
    assert_eq!(
        header,
        [
            "pair",
            "max_abs",
            "max_rel",
            "max_log_ratio",
            "l2_projected",
            "l2_grid",
            "a",
            "b"
        ]
    );
    assert_eq!(lines.len(), 1 + pairs().len(), "{table}");
    for ((line, source), (a, b)) in lines[1..]
        .iter()
        .zip(PAIR_LINES.map(|line| format!("stdin:{line}")))
        .zip(pairs())
    {
        let json: serde_json::Value =
            serde_json::from_str(&single(&a, &b, &["--format", "json"])).unwrap();
        let cells: Vec<&str> = line.split_whitespace().collect();
        assert_eq!(cells[0], &source, "{table}");
        for (cell, name) in cells[1..6].iter().zip(&header[1..6]) {
            assert_eq!(
                number(cell),
                json[*name].as_f64().unwrap(),
                "{name}: {table}"
            );
        }
        let one = single(&a, &b, &[]);
        let sides: Vec<&str> = one.lines().take(2).collect();
        assert_eq!(
            sides,
            [format!("a  {}", cells[6]), format!("b  {}", cells[7])]
        );
    }
    let focused = ok(&batch(&input, &["--theta-range", "0:50", "--degrees"]));
    assert!(
        focused.starts_with("theta_deg  0.0:50.0\n\npair "),
        "{focused}"
    );
}

#[test]
fn fit_records_pipe_into_pairs_and_l2_projected_equals_each_residual() {
    let targets: String = [0.1, 0.3, 0.7]
        .iter()
        .map(|a| format!("{{\"ndf\":\"ggx\",\"alpha_tr\":{a}}}\n"))
        .collect();
    let fits = ok(&ndfplot_stdin(
        &[
            "fit", "--target", "-", "--family", "abc", "--by", "l2", "--format", "jsonl",
        ],
        &targets,
    ));
    let residuals: Vec<f64> = fits
        .lines()
        .map(|l| {
            serde_json::from_str::<serde_json::Value>(l).unwrap()["residual"]
                .as_f64()
                .unwrap()
        })
        .collect();
    let compared = ok(&batch(&fits, &["--metric", "l2_projected"]));
    let values: Vec<f64> = compared.lines().map(number).collect();
    assert_eq!(values, residuals);
}

#[test]
fn a_bad_line_is_reported_by_its_line_and_the_others_are_still_compared() {
    let good = format!("{{\"a\":{GGX},\"b\":{BECKMANN}}}");
    let input = [
        good.as_str(),
        "not json",
        r#"{"a":{"ndf":"ggx","alpha_tr":0.3},"c":{"ndf":"ggx","alpha_tr":0.2}}"#,
        r#"{"a":{"ndf":"ggx","alpha_tr":0.3},"b":{"fresnel":"exact","eta":1.5}}"#,
        r#"{"a":{"ndf":"ggx","alpha_tr":0.3},"fit":{"ndf":"ggx","alpha_tr":0.2}}"#,
        r#"{"target":{"ndf":"ggx","alpha_tr":-1},"fit":{"ndf":"ggx","alpha_tr":0.2}}"#,
        "[1]",
        good.as_str(),
    ]
    .join("\n");
    let out = batch(&input, &["--metric", "max_abs", "-q"]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
    // One line per pair: a failed pair's is empty.
    let value = single(GGX, BECKMANN, &["--metric", "max_abs"]);
    assert_eq!(
        text(&out.stdout),
        format!("{value}{}{value}", "\n".repeat(6))
    );
    let err = text(&out.stderr);
    let lines: Vec<&str> = err.lines().collect();
    let expected = [
        "error: stdin:2: 1:1: invalid JSON",
        "error: stdin:3: c: unknown key for a pair (got {\"ndf\":\"ggx\",\"alpha_tr\":0.2}, expected one of: a, b, target, fit, line, family, residual, metric, status, error)",
        "error: stdin:3: b: missing side (got only a, expected {\"a\": <curve>, \"b\": <curve>} or a record of fit --format jsonl)",
        "error: stdin:4: b.fresnel: compare needs two curves of the same kind",
        "error: stdin:5: a pair needs its two sides under a and b, or target and fit",
        "error: stdin:6: target.alpha_tr: ",
        "error: stdin:7: a pair must be an object (got [1],",
    ];
    assert_eq!(lines.len(), expected.len(), "{err}");
    for (line, start) in lines.iter().zip(expected) {
        assert!(line.starts_with(start), "{start:?} in {err}");
    }
    // As CSV, each line is a row: the failed ones with status error and why.
    let rows = batch(&input, &["--format", "csv", "-q", "--keep-going"]);
    assert_eq!(rows.status.code(), Some(0), "{}", text(&rows.stderr));
    assert!(rows.stderr.is_empty(), "{}", text(&rows.stderr));
    let mut reader = csv::Reader::from_reader(&rows.stdout[..]);
    let records: Vec<csv::StringRecord> = reader.records().map(Result::unwrap).collect();
    let status: Vec<(&str, &str)> = records.iter().map(|r| (&r[0], &r[17])).collect();
    assert_eq!(
        status,
        [
            ("1", "ok"),
            ("2", "error"),
            ("3", "error"),
            ("4", "error"),
            ("5", "error"),
            ("6", "error"),
            ("7", "error"),
            ("8", "ok")
        ]
    );
    assert!(records[3][18].starts_with("b.fresnel: compare needs two curves of the same kind"));
    // The sides of a pair that was read but not compared are still written.
    assert_eq!(
        &records[3][2],
        r#"{"fresnel":"exact","eta":1.5,"kappa":0.0}"#
    );
    // A failed fit's record is refused with its error.
    let failed_fit = r#"{"line":4,"target":{"fresnel":"exact","eta":1.5},"family":"abc","fit":null,"alpha_abc1":null,"alpha_abc2":null,"residual":null,"metric":"l2_projected","status":"error","error":"fresnel: a fit needs an NDF target"}"#;
    let refused = batch(failed_fit, &["-q"]);
    assert_eq!(refused.status.code(), Some(2));
    assert!(
        text(&refused.stderr).starts_with("error: stdin:1: status: a record of a failed fit has no fit to compare (got error \"fresnel: a fit needs an NDF target\")"),
        "{}",
        text(&refused.stderr)
    );
}

#[test]
fn pairs_read_a_file_gate_on_bounds_and_refuse_a_and_b() {
    let dir = scratch("compare-pairs-file");
    std::fs::copy(
        crate::common::root().join("examples/renderer-ggx.csv"),
        dir.join("renderer.csv"),
    )
    .unwrap();
    let path = dir.join("pairs.jsonl");
    std::fs::write(
        &path,
        format!(
            "{{\"a\":{GGX},\"b\":{BECKMANN}}}\n{{\"a\":{{\"data\":\"csv\",\"path\":\"renderer.csv\"}},\"b\":{GGX}}}\n"
        ),
    )
    .unwrap();
    let path = path.to_str().unwrap();
    let rows = ok(&ndfplot(&[
        "compare", "--pairs", path, "--metric", "max_rel",
    ]));
    assert_eq!(
        rows.lines().count(),
        2,
        "the CSV path resolves against the file's folder"
    );
    let gated = ndfplot(&[
        "compare",
        "--pairs",
        path,
        "--max-error",
        "max_rel=0.5",
        "-q",
    ]);
    assert_eq!(gated.status.code(), Some(1));
    let err = text(&gated.stderr);
    assert!(
        err.starts_with(&format!(
            "compare: {path}:1: max_rel = 1.0 exceeds --max-error max_rel=0.5"
        )) && err.lines().count() == 1,
        "{err}"
    );
    assert_eq!(
        ndfplot(&["compare", "--pairs", path, "--a", GGX, "--b", GGX])
            .status
            .code(),
        Some(2)
    );
    usage_error(
        &ndfplot_stdin(&["compare", "--pairs", "-"], "\n"),
        "--pairs: no pair given",
    );
}

/// GGX and Beckmann of the same α as narrow as the families allow (down to α = 1e-150, where D(0) ≈ 3e299)
/// compare like any other pair: every metric finite, `l2_projected` on its slope-space limit. For α → 0 both
/// lobes are D = f(tan θ/α)/α² near the normal (f_tr(u) = 1/(π(1 + u²)²), f_b(u) = e^{−u²}/π), so
/// l2_projected · α → √(2π ∫₀^∞ (f_tr − f_b)² u du) = 0.0910219104013437498 (mpmath, 30 digits,
/// quad over [0, 1, 3, 10, ∞]); the corrections are O(α²).
#[test]
fn lobes_down_to_the_narrowest_alpha_compare_on_their_slope_space_limit() {
    const LIMIT: f64 = 0.091_021_910_401_343_75;
    for alpha in ["1e-5", "1e-10", "1e-40", "1e-100", "1e-150"] {
        let json: serde_json::Value = serde_json::from_str(&ok(&ndfplot(&[
            "compare",
            "--a",
            &format!(r#"{{"ndf":"ggx","alpha_tr":{alpha}}}"#),
            "--b",
            &format!(r#"{{"ndf":"beckmann","alpha_b":{alpha}}}"#),
            "--format",
            "json",
        ])))
        .unwrap();
        let a: f64 = alpha.parse().unwrap();
        let l2 = json["l2_projected"].as_f64().unwrap();
        assert!(
            (l2 * a / LIMIT - 1.0).abs() < 1e-9,
            "alpha {alpha}: l2_projected {l2}"
        );
        for metric in ["max_abs", "max_rel", "max_log_ratio", "l2_grid", "a_peak"] {
            assert!(
                json[metric].as_f64().is_some_and(f64::is_finite),
                "alpha {alpha}: {metric} in {json}"
            );
        }
    }
}

/// `--pairs -` streams: the first pair's row is written while the input is still open, and every
/// row equals that pair compared on its own.
#[test]
fn pairs_write_the_first_row_before_the_rest_of_their_input_arrives() {
    let input = pairs_input();
    let (head, tail) = input.split_once('\n').unwrap();
    let root = crate::common::root().to_str().unwrap().to_string();
    let (first, output) = streamed(
        &[
            "compare",
            "-q",
            "--pairs",
            "-",
            "--format",
            "json",
            "--allow-read",
            &root,
        ],
        &format!("{head}\n"),
        tail,
    );
    assert_eq!(output.status.code(), Some(0), "{}", text(&output.stderr));
    let rows: Vec<serde_json::Value> = text(&output.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(rows.len(), pairs().len());
    assert_eq!(
        rows[0],
        serde_json::from_str::<serde_json::Value>(&first).unwrap()
    );
    for (row, (a, b)) in rows.iter().zip(pairs()) {
        let alone: serde_json::Value =
            serde_json::from_str(&single(&a, &b, &["--format", "json"])).unwrap();
        assert_eq!(row["l2_projected"], alone["l2_projected"], "{a} {b}");
        assert_eq!(row["max_rel"], alone["max_rel"], "{a} {b}");
    }
}

/// A wide SGD lobe (Bagher et al.'s blue-fabric, red) against Phong 5: l2_projected equals Simpson's
/// rule over 400 001 uniform θ of the two curves' `eval` values (0.153246840215575, computed outside
/// ndfplot's quadrature), to 1e-9 — the quadrature's error budget is the whole integral's, so the
/// pieces by grazing, which hold next to nothing of it, neither spoil nor stall it.
#[test]
fn l2_projected_of_a_wide_lobe_matches_a_dense_simpson_sum() {
    let l2 = number(&ok(&ndfplot(&[
        "compare",
        "--a",
        r#"{"published":"bagher2012-sgd","material":"blue-fabric","channel":"red"}"#,
        "--b",
        r#"{"ndf":"phong","alpha_p":5}"#,
        "--metric",
        "l2_projected",
    ])));
    assert!((l2 / 0.153_246_840_215_575 - 1.0).abs() < 1e-9, "{l2}");
}

/// A problem inside a pair's side is named by the side's key and the path inside it, once
/// (`a.alpha_tr`), with the pair's line as its source.
#[test]
fn a_pairs_problem_names_its_side_and_key_once() {
    let out = ndfplot_stdin(
        &["compare", "--pairs", "-", "--format", "csv"],
        "{\"a\":{\"ndf\":\"ggx\",\"alpha_tr\":-1},\"b\":{\"ndf\":\"ggx\",\"alpha_tr\":0.3}}\n",
    );
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("error: stdin:1: a.alpha_tr: out of domain"),
        "{err}"
    );
    assert!(!err.contains("a.a."), "{err}");
}
