//! `ndfplot fit` on several targets and with several free parameters: batch order, the jsonl and csv
//! records with a column per parameter, failing targets as rows with status error (exit 2, or 0 with
//! `--keep-going`), repeated `--target`, the single-target output, the multi-parameter L2 acceptance
//! case against `compare`, and identical bytes on 1 and 2 threads.

use crate::common::{ndfplot, ndfplot_stdin, ndfplot_stdin_env, streamed, text};

const GGX_03: &str = r#"{"ndf":"trowbridge_reitz","alpha_tr":0.3}"#;

/// The ABC L2 optimum for GGX α = 0.3 with a₂ = 1.75 fixed (docs/reference.md, docs/maths.md's table).
const ONE_PARAMETER_L2_OPTIMUM: f64 = 0.014279685;

fn ggx(alpha: f64) -> String {
    format!(r#"{{"ndf":"trowbridge_reitz","alpha_tr":{alpha:?}}}"#)
}

fn json(line: &str) -> serde_json::Value {
    serde_json::from_str(line).unwrap_or_else(|e| panic!("{e}: {line}"))
}

/// The fitted curve of a jsonl record as written: the object after `"fit":` (a curve object holds
/// no nested object).
fn fit_text(record: &str) -> &str {
    let start = record.find(r#","fit":"#).unwrap() + r#","fit":"#.len();
    let end = start + record[start..].find('}').unwrap() + 1;
    &record[start..end]
}

/// Asserts that `stderr` is the closing line of a batch: `<what> in <seconds> s`.
fn assert_summary(stderr: &[u8], what: &str) {
    let stderr = text(stderr);
    let seconds = stderr
        .strip_prefix(&format!("{what} in "))
        .and_then(|rest| rest.strip_suffix(" s\n"))
        .unwrap_or_else(|| panic!("expected \"{what} in <x> s\", got {stderr:?}"));
    assert!(seconds.parse::<f64>().is_ok_and(|s| s >= 0.0), "{stderr}");
}

/// `fit --target TARGET --family abc --fix alpha_abc2=1.75` followed by `more`.
fn abc_fixed<'a>(target: &'a str, more: &[&'a str]) -> Vec<&'a str> {
    let mut args = vec![
        "fit",
        "--target",
        target,
        "--family",
        "abc",
        "--fix",
        "alpha_abc2=1.75",
    ];
    args.extend(more);
    args
}

#[test]
fn fit_batch_keeps_input_order_in_jsonl_and_csv_records() {
    let alphas = [0.9, 0.2, 0.5, 0.05, 0.7];
    let stdin: String = alphas.iter().map(|&a| ggx(a) + "\n").collect();
    let jsonl = ndfplot_stdin(&abc_fixed("-", &["--format", "jsonl"]), &stdin);
    assert_eq!(jsonl.status.code(), Some(0), "{}", text(&jsonl.stderr));
    assert_summary(&jsonl.stderr, "fit: 5 targets fitted, written to stdout");
    let stdout = text(&jsonl.stdout);
    let lines: Vec<&str> = stdout.lines().collect();
    assert!(
        lines
            .iter()
            .enumerate()
            .all(|(i, l)| l.starts_with(&format!(
                r#"{{"line":{},"family":"abc","alpha_abc1":"#,
                i + 1
            )) && l.contains(
                r#","metric":"d0_rel","status":"ok","target":{"ndf":"trowbridge_reitz","#
            ) && l.contains(r#"},"fit":{"ndf":"abc","#)
                && l.ends_with(r#"},"error":""}"#)),
        "{stdout}"
    );
    let records: Vec<serde_json::Value> = lines.iter().copied().map(json).collect();
    assert_eq!(records.len(), alphas.len());
    for (record, &alpha) in records.iter().zip(&alphas) {
        assert_eq!(record.as_object().unwrap().len(), 10, "{record}");
        assert_eq!(record["target"], json(&ggx(alpha)));
        assert_eq!(record["fit"]["ndf"], "abc");
        assert_eq!(record["alpha_abc2"], 1.75);
        // The parameter columns are the fitted curve's values, to the last digit.
        assert_eq!(record["alpha_abc1"], record["fit"]["alpha_abc1"]);
        assert!(record["residual"].as_f64().unwrap() < 1e-12, "{record}");
        assert_eq!(record["metric"], "d0_rel");
    }
    // Rougher targets need smaller a₁: the order of the fits follows the targets'.
    let a1 = |i: usize| records[i]["fit"]["alpha_abc1"].as_f64().unwrap();
    assert!(a1(3) > a1(1) && a1(1) > a1(2) && a1(2) > a1(4) && a1(4) > a1(0));

    let csv = ndfplot_stdin(&abc_fixed("-", &["--format", "csv", "-q"]), &stdin);
    assert_eq!(csv.status.code(), Some(0), "{}", text(&csv.stderr));
    assert!(csv.stderr.is_empty(), "-q: {}", text(&csv.stderr));
    let mut reader = csv::Reader::from_reader(&csv.stdout[..]);
    assert_eq!(
        reader.headers().unwrap(),
        vec![
            "line",
            "family",
            "alpha_abc1",
            "alpha_abc2",
            "residual",
            "metric",
            "status",
            "target",
            "fit",
            "error"
        ]
    );
    let rows: Vec<csv::StringRecord> = reader.records().map(Result::unwrap).collect();
    assert_eq!(rows.len(), alphas.len());
    for ((row, record), line) in rows.iter().zip(&records).zip(&lines) {
        // The same curves as canonical JSON text, the same numbers to the last digit.
        assert_eq!(row[0].parse::<u64>().ok(), record["line"].as_u64());
        assert_eq!(&row[1], "abc");
        for (column, key) in [(2, "alpha_abc1"), (3, "alpha_abc2"), (4, "residual")] {
            assert_eq!(
                row[column].parse::<f64>().ok(),
                record[key].as_f64(),
                "{key}"
            );
        }
        assert_eq!((&row[5], &row[6]), ("d0_rel", "ok"));
        assert_eq!(json(&row[7]), record["target"]);
        assert_eq!(&row[8], fit_text(line));
        assert_eq!(&row[9], "");
    }
}

#[test]
fn fit_batch_reports_a_failing_line_by_number_and_still_fits_the_others() {
    let stdin = [
        &ggx(0.3),
        "{not json",
        r#"{"ndf":"phong","alpha_p":0}"#,
        "",
        r#"{"fresnel":"exact","eta":1.5}"#,
        &ggx(0.6),
    ]
    .join("\n");
    let args = [
        "fit",
        "--target",
        "-",
        "--family",
        "torrance_sparrow",
        "--format",
        "jsonl",
    ];
    let out = ndfplot_stdin(&args, &stdin);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
    let records: Vec<serde_json::Value> = text(&out.stdout).lines().map(json).collect();
    let lines_and_status: Vec<(u64, &str)> = records
        .iter()
        .map(|r| (r["line"].as_u64().unwrap(), r["status"].as_str().unwrap()))
        .collect();
    assert_eq!(
        lines_and_status,
        [
            (1, "ok"),
            (2, "error"),
            (3, "error"),
            (5, "error"),
            (6, "ok")
        ]
    );
    let ok: Vec<&serde_json::Value> = records
        .iter()
        .filter(|r| r["status"] == "ok")
        .map(|r| &r["target"])
        .collect();
    assert_eq!(ok, [&json(&ggx(0.3)), &json(&ggx(0.6))]);
    // A failed row has its error and no numbers; an unreadable target has no target either.
    assert!(records[1]["target"].is_null() && records[1]["alpha_ts"].is_null());
    assert!(
        records[2]["error"]
            .as_str()
            .unwrap()
            .starts_with("alpha_ts: torrance_sparrow cannot reach")
    );
    assert!(records[2]["residual"].is_null() && records[2]["fit"].is_null());
    let stderr = text(&out.stderr);
    let lines: Vec<&str> = stderr.lines().collect();
    assert_eq!(lines.len(), 4, "{stderr}");
    assert!(
        lines[0].starts_with("fit: 2 of 5 targets fitted (3 failed), written to stdout in "),
        "{stderr}"
    );
    let lines = &lines[1..];
    assert!(
        lines[0].starts_with("error: stdin:2: 1:") && lines[0].contains("invalid JSON"),
        "{stderr}"
    );
    assert!(
        lines[1].starts_with(
            "error: stdin:3: alpha_ts: torrance_sparrow cannot reach the target's D(0)"
        ),
        "{stderr}"
    );
    assert!(
        lines[2].starts_with("error: stdin:5: fresnel: a fit needs an NDF target"),
        "{stderr}"
    );
    // --keep-going: the same records, exit 0, the errors left to the rows.
    let kept = ndfplot_stdin(&[&args[..], &["--keep-going"]].concat(), &stdin);
    assert_eq!(kept.status.code(), Some(0), "{}", text(&kept.stderr));
    assert_eq!(kept.stdout, out.stdout);
    assert_summary(
        &kept.stderr,
        "fit: 2 of 5 targets fitted (3 failed), written to stdout",
    );
}

#[test]
fn fit_takes_repeated_targets_in_order_and_names_a_failing_one_by_index() {
    let second = ggx(0.6);
    let out = ndfplot(&[
        "fit",
        "--target",
        GGX_03,
        "--target",
        &second,
        "--target",
        r#"{"ndf":"phong","alpha_p":0}"#,
        "--family",
        "torrance_sparrow",
        "--format",
        "csv",
    ]);
    assert_eq!(out.status.code(), Some(2));
    let stdout = text(&out.stdout);
    let lines: Vec<&str> = stdout.lines().collect();
    assert_eq!(lines.len(), 4, "{stdout}");
    assert!(
        lines[1].starts_with("1,torrance_sparrow,0.30968")
            && lines[1]
                .contains(r#",d0_rel,ok,"{""ndf"":""trowbridge_reitz"",""alpha_tr"":0.3}","#),
        "{stdout}"
    );
    assert!(
        lines[2].starts_with("2,torrance_sparrow,0.70337")
            && lines[2]
                .contains(r#",d0_rel,ok,"{""ndf"":""trowbridge_reitz"",""alpha_tr"":0.6}","#),
        "{stdout}"
    );
    assert!(
        lines[3].starts_with(r#"3,torrance_sparrow,,,d0_rel,error,"{""ndf"":""phong"",""alpha_p"":0.0}",,"alpha_ts: torrance_sparrow cannot reach"#),
        "{stdout}"
    );
    assert!(
        text(&out.stderr).lines().nth(1).is_some_and(
            |l| l.starts_with("error: --target[2]: alpha_ts: torrance_sparrow cannot reach")
        ),
        "{}",
        text(&out.stderr)
    );
}

#[test]
fn fit_single_target_without_format_prints_the_curve_and_the_residual_line_as_before() {
    let single = ndfplot(&abc_fixed(GGX_03, &["--by", "l2"]));
    assert_eq!(single.status.code(), Some(0), "{}", text(&single.stderr));
    let line = text(&ndfplot(&abc_fixed(GGX_03, &["--by", "l2", "--format", "jsonl"])).stdout);
    let record = json(line.trim_end());
    assert_eq!(text(&single.stdout), format!("{}\n", fit_text(&line)));
    let residual = record["residual"].as_f64().unwrap();
    assert_eq!(
        text(&single.stderr),
        format!("residual={residual:?} (l2_projected)\n")
    );
    // One line on stdin is a single target too; several give one curve line and one residual line each.
    let from_stdin = ndfplot_stdin(&abc_fixed("-", &["--by", "l2"]), GGX_03);
    assert_eq!(
        (from_stdin.stdout, from_stdin.stderr),
        (single.stdout.clone(), single.stderr.clone())
    );
    let twice = ndfplot_stdin(
        &abc_fixed("-", &["--by", "l2"]),
        &format!("{GGX_03}\n{GGX_03}\n"),
    );
    assert_eq!(twice.status.code(), Some(0));
    assert_eq!(text(&twice.stdout), text(&single.stdout).repeat(2));
    assert_eq!(text(&twice.stderr), text(&single.stderr).repeat(2));
}

#[test]
fn fit_by_l2_frees_every_unfixed_parameter_and_compare_reports_its_residual() {
    let out = ndfplot(&[
        "fit", "--target", GGX_03, "--family", "abc", "--by", "l2", "--format", "jsonl",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let record = json(text(&out.stdout).trim_end());
    let residual = record["residual"].as_f64().unwrap();
    assert!(residual < ONE_PARAMETER_L2_OPTIMUM, "{record}");
    assert_ne!(record["fit"]["alpha_abc2"], 1.75);
    let line = text(&out.stdout);
    let compare = ndfplot(&[
        "compare",
        "--a",
        fit_text(&line),
        "--b",
        GGX_03,
        "--format",
        "json",
    ]);
    assert_eq!(compare.status.code(), Some(0), "{}", text(&compare.stderr));
    assert_eq!(
        json(&text(&compare.stdout))["l2_projected"].as_f64(),
        Some(residual)
    );

    // GTR holds GGX at γ = 2: both parameters are recovered.
    let gtr = ndfplot(&["fit", "--target", GGX_03, "--family", "gtr", "--by", "l2"]);
    assert_eq!(gtr.status.code(), Some(0), "{}", text(&gtr.stderr));
    let curve = json(text(&gtr.stdout).trim_end());
    assert!(
        (curve["alpha_gtr"].as_f64().unwrap() / 0.3 - 1.0).abs() < 1e-6,
        "{curve}"
    );
    assert!(
        (curve["gamma_gtr"].as_f64().unwrap() / 2.0 - 1.0).abs() < 1e-6,
        "{curve}"
    );
}

#[test]
fn fit_by_peak_or_max_with_two_free_parameters_is_an_error_naming_them() {
    for by in ["peak", "max"] {
        let out = ndfplot(&["fit", "--target", GGX_03, "--family", "sgd", "--by", by]);
        assert_eq!(out.status.code(), Some(2));
        assert!(out.stdout.is_empty());
        let stderr = text(&out.stderr);
        assert!(
            stderr.starts_with("error: --fix: alpha_sgd1, alpha_sgd2: sgd has 2 free parameters")
                && stderr.contains(&format!("--by {by} matches one number")),
            "{stderr}"
        );
    }
}

#[test]
fn fit_batch_gives_the_same_bytes_on_one_and_two_threads() {
    let stdin: String = (1..=20).map(|i| ggx(0.05 * i as f64) + "\n").collect();
    let gtr = [
        "fit", "--target", "-", "--family", "gtr", "--by", "l2", "--format", "csv", "-q",
    ];
    for args in [
        abc_fixed("-", &["--by", "l2", "--format", "jsonl", "-q"]),
        gtr.to_vec(),
    ] {
        let one = ndfplot_stdin_env(&args, &stdin, &[("RAYON_NUM_THREADS", "1")]);
        let two = ndfplot_stdin_env(&args, &stdin, &[("RAYON_NUM_THREADS", "2")]);
        // GTR cannot determine γ for the uniform GGX α = 1: one error line, both times.
        assert!(
            text(&one.stdout).lines().count() >= 19,
            "{}",
            text(&one.stderr)
        );
        assert_eq!(
            (one.status.code(), &one.stdout, &one.stderr),
            (two.status.code(), &two.stdout, &two.stderr)
        );
    }
}

/// A batch on standard input streams: the first target's record is written while the input is still
/// open (the command has not read the rest), and the records of the whole batch are those of each
/// target fitted on its own, in input order.
#[test]
fn fit_writes_the_first_record_before_the_rest_of_its_input_arrives() {
    let targets: Vec<String> = [0.1, 0.2, 0.3, 0.4, 0.5].map(ggx).to_vec();
    let args = [
        "fit", "-q", "--target", "-", "--family", "beckmann", "--by", "peak", "--format", "jsonl",
    ];
    let (first, output) = streamed(
        &args,
        &format!("{}\n", targets[0]),
        &(targets[1..].join("\n") + "\n"),
    );
    assert_eq!(output.status.code(), Some(0), "{}", text(&output.stderr));
    let lines: Vec<String> = text(&output.stdout).lines().map(str::to_string).collect();
    assert_eq!(lines.len(), targets.len());
    assert_eq!(lines[0], first.trim_end());
    for (i, (line, target)) in lines.iter().zip(&targets).enumerate() {
        let alone = ndfplot(&[
            "fit", "-q", "--target", target, "--family", "beckmann", "--by", "peak", "--format",
            "jsonl",
        ]);
        let mut expected = json(text(&alone.stdout).trim());
        expected["line"] = serde_json::json!(i + 1);
        assert_eq!(json(line), expected);
    }
}

/// A family whose shape parameter is bounded away from 0 (STD's γ > 1.5) is searched inside its
/// domain: with both parameters free, the l2 fit of GGX α = 0.3 is STD α = 0.3, γ = 2, where the
/// two families coincide (docs/maths.md "Student-t slope distribution").
#[test]
fn a_student_t_fit_searches_its_open_domain_and_finds_ggx_at_gamma_2() {
    let out = ndfplot(&[
        "fit",
        "-q",
        "--target",
        &ggx(0.3),
        "--family",
        "student_t",
        "--by",
        "l2",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let fit = json(text(&out.stdout).trim());
    let (alpha, gamma) = (
        fit["alpha_std"].as_f64().unwrap(),
        fit["gamma_std"].as_f64().unwrap(),
    );
    assert!(
        (alpha - 0.3).abs() < 1e-6 && (gamma - 2.0).abs() < 1e-6,
        "{fit}"
    );
}
