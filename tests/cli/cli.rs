//! The real `ndfplot` binary on fixtures: happy paths, the output contracts of docs/contracts.md, and
//! every kind of bad input (exit 2, nothing on stdout, one line per problem on stderr).

use crate::common::{files_in, ndfplot, ndfplot_stdin, render_into, root, scratch, text};
use std::path::Path;
use std::process::{Command, Output, Stdio};

/// Asserts exit 2, empty stdout, and that every stderr line is an `error:` line and one of them
/// contains `needle`.
fn assert_input_error(output: &Output, needle: &str) {
    let err = text(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "stderr: {err}");
    assert!(output.stdout.is_empty(), "stdout: {}", text(&output.stdout));
    assert!(
        err.lines().all(|l| l.starts_with("error: ")),
        "stderr: {err}"
    );
    assert!(err.contains(needle), "expected {needle:?} in: {err}");
}

#[test]
fn eval_prints_theta_value_csv_in_round_trip_form() {
    let out = ndfplot(&[
        "eval",
        "--curve",
        r#"{"ndf":"phong","alpha_p":0}"#,
        "--theta",
        "0,0.5,1.5707963267948966",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let text = text(&out.stdout);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "theta,value");
    let pi_inv = std::f64::consts::FRAC_1_PI;
    assert_eq!(
        lines[1..],
        [
            format!("0.0,{pi_inv:?}"),
            format!("0.5,{pi_inv:?}"),
            format!("1.5707963267948966,{pi_inv:?}")
        ]
    );
}

#[test]
fn eval_linspace_degrees_and_several_curves() {
    let out = ndfplot(&[
        "eval",
        "--curve",
        r#"{"ndf":"ggx","alpha_tr":1}"#,
        "--curve",
        r#"{"ndf":"beckmann","alpha_b":0.5}"#,
        "--theta",
        "0:90:3",
        "--degrees",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let text = text(&out.stdout);
    let mut rows = text.lines();
    assert_eq!(
        rows.next().unwrap(),
        r#"theta_deg,"{""ndf"":""trowbridge_reitz"",""alpha_tr"":1.0}","{""ndf"":""beckmann"",""alpha_b"":0.5}""#
    );
    let thetas: Vec<f64> = rows
        .map(|r| r.split(',').next().unwrap().parse().unwrap())
        .collect();
    assert_eq!(thetas, [0.0, 45.0, 90.0]);
}

#[test]
fn eval_reads_curves_from_a_file_and_from_json_lines_on_stdin() {
    let dir = scratch("eval-inputs");
    let file = dir.join("curve.json");
    std::fs::write(&file, r#"{"ndf": "beckmann", "alpha_b": 0.5}"#).unwrap();
    let from_file = ndfplot(&[
        "eval",
        "--curve",
        &format!("@{}", file.display()),
        "--theta",
        "0.3",
    ]);
    let inline = ndfplot(&[
        "eval",
        "--curve",
        r#"{"ndf":"beckmann","alpha_b":0.5}"#,
        "--theta",
        "0.3",
    ]);
    assert_eq!(text(&from_file.stdout), text(&inline.stdout));
    let lines = "{\"ndf\":\"beckmann\",\"alpha_b\":0.5}\n\n{\"ndf\":\"phong\",\"alpha_p\":2}\n";
    let out = ndfplot_stdin(&["eval", "--curve", "-", "--theta", "0.3"], lines);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(
        text(&out.stdout).starts_with("theta,\"{\"\"ndf\"\":\"\"beckmann\"\""),
        "{}",
        text(&out.stdout)
    );
    let bad = ndfplot_stdin(
        &["eval", "--curve", "-", "--theta", "0.3"],
        "{\"ndf\":\"phong\",\"alpha_p\":2}\n{\"ndf\":\"phon\"}\n",
    );
    assert_input_error(&bad, "stdin:2: ndf: unknown ndf model");
}

#[test]
fn eval_values_match_the_library() {
    let thetas = "0,1e-8,0.25,1.0,1.5707963267948966";
    let out = ndfplot(&[
        "eval",
        "--curve",
        r#"{"ndf":"abc","alpha_abc1":23.5,"alpha_abc2":1.75}"#,
        "--theta",
        thetas,
    ]);
    let curve = ndfplot::pipeline::resolve::curve(
        &ndfplot::spec::curve::parse(
            &ndfplot::spec::json::parse(r#"{"ndf":"abc","alpha_abc1":23.5,"alpha_abc2":1.75}"#)
                .unwrap(),
            "",
        )
        .unwrap(),
    )
    .unwrap();
    for line in text(&out.stdout).lines().skip(1) {
        let (theta, value) = line.split_once(',').unwrap();
        let (theta, value): (f64, f64) = (theta.parse().unwrap(), value.parse().unwrap());
        assert_eq!(value.to_bits(), curve.eval(theta).to_bits(), "θ = {theta}");
    }
}

#[test]
fn eval_bad_input_exits_2_naming_the_problem() {
    let theta = ["--theta", "0.1"];
    let cases: &[(&[&str], &str)] = &[
        (
            &["--curve", r#"{"ndf":"phong","alpha_p":1"#],
            "--curve: 1:27: invalid JSON",
        ),
        (
            &["--curve", r#"{"ndf":"becmann","alpha_b":1}"#],
            "did you mean \"beckmann\"",
        ),
        (
            &["--curve", r#"{"ndf":"beckmann","alpha":1}"#],
            "--curve: alpha: unknown key",
        ),
        (
            &["--curve", r#"{"ndf":"beckmann","alpha_b":"x"}"#],
            "alpha_b: expected a number",
        ),
        (
            &["--curve", r#"{"ndf":"abc","alpha_abc1":1}"#],
            "alpha_abc2: missing parameter",
        ),
        (
            &["--curve", r#"{"ndf":"beckmann","alpha_b":-0.5}"#],
            "alpha_b: out of domain (got -0.5",
        ),
        (
            &[
                "--curve",
                r#"{"ndf":"beckmann","alpha_b":0.5,"alpha_b":0.6}"#,
            ],
            "alpha_b: duplicate key",
        ),
        (
            &["--curve", r#"{"ndf":"phong","alpha_p":1e999}"#],
            "outside the range of a double",
        ),
        (
            &["--curve", "@/nonexistent/curve.json"],
            "/nonexistent/curve.json",
        ),
    ];
    for (args, needle) in cases {
        let mut all = vec!["eval"];
        all.extend_from_slice(args);
        all.extend_from_slice(&theta);
        assert_input_error(&ndfplot(&all), needle);
    }
    let curve = r#"{"ndf":"phong","alpha_p":1}"#;
    for (list, needle) in [
        ("abc", "not a number"),
        ("0:1:0", "count must be from 1"),
        ("nan", "not a finite number"),
        ("0:1:100000000000000", "count must be from 1"),
        ("1.6", "angle out of range"),
        ("-0.1", "angle out of range"),
        ("0,1:2:3", "not both"),
    ] {
        assert_input_error(
            &ndfplot(&["eval", "--curve", curve, &format!("--theta={list}")]),
            needle,
        );
    }
}

#[test]
fn eval_reports_every_bad_curve_at_once() {
    let out = ndfplot(&[
        "eval",
        "--curve",
        r#"{"ndf":"phong","alpha_q":1}"#,
        "--curve",
        r#"{"ndf":"ggx","alpha_tr":0}"#,
        "--theta",
        "0",
    ]);
    assert_input_error(&out, "--curve[0]: alpha_q: unknown key");
    assert!(
        text(&out.stderr).contains("--curve[1]: alpha_tr: out of domain"),
        "{}",
        text(&out.stderr)
    );
}

#[test]
fn eval_into_a_closed_pipe_is_not_an_error() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_ndfplot"))
        .args([
            "eval",
            "--curve",
            r#"{"ndf":"phong","alpha_p":5}"#,
            "--theta",
            "0:1.5:2000000",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(out.stderr.is_empty(), "{}", text(&out.stderr));
}

const SPEC: &str = r#"{
  "id": "two-panels",
  "title": "Test figure",
  "panels": [
    {"curves": [{"ndf": "beckmann", "alpha_b": {"range": [0.4, 1.0, 0.1]}}]},
    {"x": {"unit": "degrees", "range": [0, 60]}, "y": {"scale": "log"},
     "curves": [{"ndf": "beckmann", "alpha_b": 0.5}, {"ndf": "phong", "alpha_p": {"from_beckmann": [0.3, 0.5]}, "style": ["thick", "dashed"]}]}
  ],
  "sampling": {"uniform": 50}
}"#;

#[test]
fn render_writes_svg_png_csv_and_csv_values_equal_eval() {
    let dir = scratch("render-basic");
    let spec = dir.join("spec.json");
    std::fs::write(&spec, SPEC).unwrap();
    let out_dir = dir.join("out");
    let out = ndfplot(&[
        "render",
        spec.to_str().unwrap(),
        "-o",
        out_dir.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(
        files_in(&out_dir),
        ["two-panels.csv", "two-panels.png", "two-panels.svg"]
    );
    let csv = std::fs::read_to_string(out_dir.join("two-panels.csv")).unwrap();
    let mut reader = csv::Reader::from_reader(csv.as_bytes());
    assert_eq!(
        reader.headers().unwrap(),
        vec!["panel", "series", "curve", "x", "y"]
    );
    let rows: Vec<csv::StringRecord> = reader.records().map(Result::unwrap).collect();
    assert_eq!(rows.len(), (7 + 3) * 50);
    let series_of_panel_0: std::collections::BTreeSet<&str> = rows
        .iter()
        .filter(|r| &r[0] == "0")
        .map(|r| r.get(1).unwrap())
        .collect();
    assert_eq!(
        series_of_panel_0.len(),
        7,
        "Range[0.4, 1.0, 0.1] gives 7 curves"
    );
    assert!(
        rows.iter()
            .any(|r| &r[2] == r#"{"ndf":"beckmann","alpha_b":1.0}"#)
    );
    // The degree panel samples only its visible range, 0 … 60°.
    let max_x = rows
        .iter()
        .filter(|r| &r[0] == "1")
        .map(|r| r[3].parse::<f64>().unwrap())
        .fold(0.0, f64::max);
    assert_eq!(max_x, 60.0 * std::f64::consts::PI / 180.0);
    // Every value equals `eval` for the same curve and θ.
    for row in rows.iter().step_by(37) {
        let eval = ndfplot(&["eval", "--curve", &row[2], "--theta", &row[3]]);
        let value = text(&eval.stdout)
            .lines()
            .nth(1)
            .unwrap()
            .split(',')
            .nth(1)
            .unwrap()
            .to_string();
        assert_eq!(value, &row[4], "{row:?}");
    }
    let svg = std::fs::read_to_string(out_dir.join("two-panels.svg")).unwrap();
    assert!(
        svg.starts_with("<svg") || svg.starts_with("<?xml"),
        "not an SVG"
    );
    // The sweep is one legend row, `α_b = 0.4 … 1`, typeset: α, then b as a subscript run, then
    // the rest; no row per member.
    assert!(
        svg.contains("Test figure")
            && svg.contains(">α</text>")
            && svg.contains(">b</text>")
            && svg.contains("> = 0.4 … 1</text>")
            && !svg.contains("> = 0.7</text>")
            && !svg.contains("α_b"),
        "labels missing from SVG"
    );
    let png = std::fs::read(out_dir.join("two-panels.png")).unwrap();
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
}

#[test]
fn render_output_is_identical_across_runs_and_thread_counts() {
    let dir = scratch("render-determinism");
    let spec = dir.join("spec.json");
    std::fs::write(&spec, SPEC).unwrap();
    let mut outputs = Vec::new();
    for (run, threads) in [("a", "2"), ("b", "2"), ("c", "1")] {
        let out_dir = dir.join(run);
        let status = Command::new(env!("CARGO_BIN_EXE_ndfplot"))
            .args([
                "render",
                spec.to_str().unwrap(),
                "-o",
                out_dir.to_str().unwrap(),
                "--format",
                "svg,png,pdf,csv",
            ])
            .env("RAYON_NUM_THREADS", threads)
            .status()
            .unwrap();
        assert!(status.success());
        let bytes: Vec<Vec<u8>> = files_in(&out_dir)
            .iter()
            .map(|f| std::fs::read(out_dir.join(f)).unwrap())
            .collect();
        assert_eq!(bytes.len(), 4, "{:?}", files_in(&out_dir));
        outputs.push(bytes);
    }
    assert_eq!(outputs[0], outputs[1]);
    assert_eq!(outputs[0], outputs[2]);
}

/// On one thread a render of the catalogue runs in two chunks of scenes (32 a chunk per worker)
/// with every encoding scheduled by its cost: its SVGs and CSVs are still the committed ones, byte
/// for byte.
#[test]
fn the_catalogue_on_one_thread_in_chunks_gives_the_committed_files() {
    let out_dir = scratch("render-one-thread").join("plots");
    let status = Command::new(env!("CARGO_BIN_EXE_ndfplot"))
        .args(["render", "-q", "--format", "svg,csv", "-o"])
        .arg(&out_dir)
        .env("RAYON_NUM_THREADS", "1")
        .status()
        .unwrap();
    assert!(status.success());
    let files = files_in(&out_dir);
    assert!(
        files.len() / 2 > 32,
        "more scenes than one chunk holds: {files:?}"
    );
    for name in files {
        let committed = std::fs::read(root().join("plots").join(&name)).unwrap();
        assert!(
            std::fs::read(out_dir.join(&name)).unwrap() == committed,
            "{name} differs from plots/{name}"
        );
    }
}

#[test]
fn render_formats_and_canvas_flags() {
    let dir = scratch("render-formats");
    let spec = dir.join("spec.json");
    std::fs::write(&spec, SPEC).unwrap();
    let out_dir = dir.join("out");
    let out = ndfplot(&[
        "render",
        spec.to_str().unwrap(),
        "-o",
        out_dir.to_str().unwrap(),
        "--format",
        "png",
        "--width",
        "400",
        "--height",
        "300",
        "--png-scale",
        "1.5",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(files_in(&out_dir), ["two-panels.png"]);
    let png = std::fs::read(out_dir.join("two-panels.png")).unwrap();
    let width = u32::from_be_bytes(png[16..20].try_into().unwrap());
    let height = u32::from_be_bytes(png[20..24].try_into().unwrap());
    assert_eq!((width, height), (600, 450));
    for list in ["gif", "pdf,gif"] {
        assert_input_error(
            &ndfplot(&["render", spec.to_str().unwrap(), "--format", list]),
            "unknown format (got \"gif\", expected a comma list of svg, png, pdf, csv, html)",
        );
    }
}

/// The `tEXt` chunks of a PNG as (keyword, text).
fn png_text(png: &[u8]) -> Vec<(String, String)> {
    let mut chunks = Vec::new();
    let mut at = 8;
    while at + 8 <= png.len() {
        let length = u32::from_be_bytes(png[at..at + 4].try_into().unwrap()) as usize;
        let data = &png[at + 8..at + 8 + length];
        if &png[at + 4..at + 8] == b"tEXt" {
            let nul = data.iter().position(|&b| b == 0).unwrap();
            chunks.push((
                String::from_utf8(data[..nul].to_vec()).unwrap(),
                String::from_utf8(data[nul + 1..].to_vec()).unwrap(),
            ));
        }
        at += 12 + length;
    }
    chunks
}

/// Lowercase hex SHA-256 of `bytes`.
fn sha256_hex(bytes: &[u8]) -> String {
    use sha2::Digest;
    sha2::Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// Whether `needle` occurs in `haystack`.
fn has_bytes(haystack: &[u8], needle: &str) -> bool {
    haystack
        .windows(needle.len())
        .any(|w| w == needle.as_bytes())
}

/// Asserts that the SVG, PNG and PDF of `id` in `dir` (those that exist) record this version and
/// `hash`, and that its CSV records nothing.
fn assert_provenance(dir: &Path, id: &str, hash: &str) {
    let version = env!("CARGO_PKG_VERSION");
    let words = format!("ndfplot-version={version} spec-sha256={hash}");
    let read = |ext: &str| std::fs::read(dir.join(format!("{id}.{ext}"))).ok();
    if let Some(svg) = read("svg") {
        let svg = String::from_utf8(svg).unwrap();
        let second = svg.lines().nth(1).unwrap();
        assert_eq!(second, format!("<metadata>{words}</metadata>"), "{id}.svg");
    }
    if let Some(png) = read("png") {
        let text = png_text(&png);
        for (key, value) in [
            ("Software", format!("ndfplot {version}")),
            ("ndfplot-version", version.to_owned()),
            ("spec-sha256", hash.to_owned()),
        ] {
            assert!(
                text.contains(&(key.to_owned(), value.clone())),
                "{id}.png: {key}={value} not in {text:?}"
            );
        }
    }
    if let Some(pdf) = read("pdf") {
        assert!(has_bytes(&pdf, &format!("/Producer(ndfplot {version})")));
        let keywords = format!("/Keywords(ndfplot-version={version}, spec-sha256={hash})");
        assert!(has_bytes(&pdf, &keywords), "{id}.pdf");
    }
    if let Some(csv) = read("csv") {
        assert!(csv.starts_with(b"panel,series,curve,x,y"), "{id}.csv");
        assert!(
            !has_bytes(&csv, "ndfplot") && !has_bytes(&csv, hash),
            "{id}.csv"
        );
    }
}

#[test]
fn render_pdf_is_a_vector_page_in_the_embedded_face() {
    let dir = scratch("render-pdf");
    let spec = dir.join("spec.json");
    std::fs::write(&spec, SPEC).unwrap();
    let configs = root().join("configs");
    let polar = configs.join("beckmann-vs-phong-polar.json");
    let surface = configs.join("gulbrandsen-manifold.json");
    let out_dir = dir.join("out");
    render_into(&[&spec, &polar, &surface], &out_dir, "pdf");
    assert_eq!(
        files_in(&out_dir),
        [
            "beckmann-vs-phong-polar.pdf",
            "gulbrandsen-manifold.pdf",
            "two-panels.pdf"
        ],
        "pdf only, as asked"
    );
    for (id, source) in [
        ("two-panels", &spec),
        ("beckmann-vs-phong-polar", &polar),
        ("gulbrandsen-manifold", &surface),
    ] {
        let pdf = std::fs::read(out_dir.join(format!("{id}.pdf"))).unwrap();
        assert!(pdf.starts_with(b"%PDF-"), "{id}");
        assert!(pdf.trim_ascii_end().ends_with(b"%%EOF"), "{id}");
        assert!(has_bytes(&pdf, "/FontFile2"), "{id}: the face is embedded");
        assert!(has_bytes(&pdf, "DejaVuSans"), "{id}");
        assert!(
            !has_bytes(&pdf, "/Subtype /Image"),
            "{id}: nothing rasterized"
        );
        assert!(!has_bytes(&pdf, "/CreationDate"), "{id}: no time stamp");
        assert_provenance(&out_dir, id, &sha256_hex(&std::fs::read(source).unwrap()));
    }
    let two_panels = std::fs::read(out_dir.join("two-panels.pdf")).unwrap();
    assert!(has_bytes(&two_panels, "/Title(Test figure)"));
    // Two columns of 480 CSS px, 337 px high, at 0.75 pt per px.
    assert!(has_bytes(&two_panels, "/MediaBox[0 0 720 252.75]"));
}

#[test]
fn render_records_the_version_and_spec_hash_in_drawn_outputs_only() {
    let dir = scratch("render-provenance");
    let spec = dir.join("spec.json");
    // Bytes as read: the hash is of the file, trailing spaces and all.
    let text = format!("{SPEC}  \n");
    std::fs::write(&spec, &text).unwrap();
    let interactive = root().join("configs/tr-vs-phong-interactive.json");
    let out_dir = dir.join("out");
    render_into(&[&spec, &interactive], &out_dir, "svg,png,pdf,csv,html");
    let id = "tr-vs-phong-interactive";
    let expected: Vec<String> = ["csv", "html", "pdf", "png", "svg"]
        .iter()
        .map(|ext| format!("{id}.{ext}"))
        .chain(
            ["csv", "pdf", "png", "svg"]
                .iter()
                .map(|ext| format!("two-panels.{ext}")),
        )
        .collect();
    assert_eq!(files_in(&out_dir), expected);
    assert_provenance(&out_dir, "two-panels", &sha256_hex(text.as_bytes()));
    let bytes = std::fs::read(&interactive).unwrap();
    assert_provenance(&out_dir, id, &sha256_hex(&bytes));
}

#[test]
fn render_without_arguments_renders_the_catalogue_into_plots() {
    let dir = scratch("render-catalogue");
    let out = Command::new(env!("CARGO_BIN_EXE_ndfplot"))
        .arg("render")
        .current_dir(&dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let files = files_in(&dir.join("plots"));
    let configs_dir = root().join("configs");
    let configs = files_in(&configs_dir);
    for config in configs.iter().filter(|c| c.ends_with(".json")) {
        let id = config.trim_end_matches(".json");
        for ext in ["svg", "png", "csv"] {
            assert!(files.contains(&format!("{id}.{ext}")), "missing {id}.{ext}");
        }
        assert!(!files.contains(&format!("{id}.pdf")), "pdf only when asked");
        // The embedded spec is the file, byte for byte: `sha256sum configs/<id>.json` verifies.
        let hash = sha256_hex(&std::fs::read(configs_dir.join(config)).unwrap());
        assert_provenance(&dir.join("plots"), id, &hash);
    }
    assert!(
        !files.iter().any(|f| f.starts_with('.')),
        "temporaries left: {files:?}"
    );
}

#[test]
fn render_bad_specs_exit_2_name_file_path_and_value_and_write_nothing() {
    let dir = scratch("render-bad");
    let cases = [
        (
            "{\n  \"id\": \"x\",\n  \"panels\": [}\n",
            "bad.json: 3:14: invalid JSON",
        ),
        (
            r#"{"id":"x","panels":[{"curves":[{"ndf":"phong","alpha_p":1}]}],"colour":"red"}"#,
            "colour: unknown key",
        ),
        (
            r#"{"id":"x","panels":[{"curves":[{"ndf":"phong","alpha_p":1,"stlye":"thick"}]}]}"#,
            "did you mean \"style\"",
        ),
        (
            r#"{"id":"x","panels":[{"curves":[{"ndf":"phong","alpha_p":[]}]}]}"#,
            "panels[0].curves[0].alpha_p: empty list",
        ),
        (
            r#"{"id":"x","panels":[{"curves":[{"ndf":"beckmann","alpha_b":{"range":[0,1,0]}}]}]}"#,
            "alpha_b.range: step must not be 0",
        ),
        (
            r#"{"id":"x","panels":[{"curves":[{"ndf":"beckmann","alpha_b":{"range":[1,0,0.1]}}]}]}"#,
            "away from stop",
        ),
        (
            r#"{"id":"x","panels":[{"curves":[{"ndf":"phong","alpha_p":{"from_beckmann":1.5}}]}]}"#,
            "alpha_p.from_beckmann: Beckmann-to-Phong conversion needs 0 < α_b ≤ 1 (got 1.5",
        ),
        (
            r#"{"id":"../x","panels":[{"curves":[{"ndf":"phong","alpha_p":1}]}]}"#,
            "id: invalid id (got \"../x\"",
        ),
        (
            r#"{"id":"/tmp/x","panels":[{"curves":[{"ndf":"phong","alpha_p":1}]}]}"#,
            "invalid id",
        ),
        (
            r#"{"id":"a/b","panels":[{"curves":[{"ndf":"phong","alpha_p":1}]}]}"#,
            "invalid id",
        ),
        (
            r#"{"id":"x","panels":[{"curves":[{"ndf":"beckmann","alpha_b":{"range":[0,1e9,1e-9]}}]}]}"#,
            "exceed the cap",
        ),
        (
            r#"{"id":"x","sampling":{"uniform":1e14},"panels":[{"curves":[{"ndf":"phong","alpha_p":1}]}]}"#,
            "sampling.uniform: out of range",
        ),
        (
            r#"{"id":"x","panels":[{"curves":[{"ndf":"phong","alpha_p":1}],"x":{"range":[0,2]}}]}"#,
            "panels[0].x.range: invalid interval",
        ),
        (
            r#"{"$schema":"s.json","id":"x","panels":[{"curves":[{"ndf":"phong","alpha_p":-1}]}]}"#,
            "panels[0].curves[0].alpha_p: out of domain",
        ),
    ];
    for (spec_text, needle) in cases {
        let spec = dir.join("bad.json");
        std::fs::write(&spec, spec_text).unwrap();
        let out_dir = dir.join("out");
        let out = ndfplot(&[
            "render",
            spec.to_str().unwrap(),
            "-o",
            out_dir.to_str().unwrap(),
        ]);
        assert_input_error(&out, needle);
        assert!(
            text(&out.stderr).contains("bad.json"),
            "{}",
            text(&out.stderr)
        );
        assert!(!out_dir.exists(), "{spec_text}: output written");
    }
}

#[test]
fn render_reports_all_problems_of_all_files_and_duplicate_ids() {
    let dir = scratch("render-many-bad");
    std::fs::write(
        dir.join("a.json"),
        r#"{"id":"same","panels":[{"curves":[{"ndf":"phong","alpha_p":1}]}]}"#,
    )
    .unwrap();
    std::fs::write(
        dir.join("b.json"),
        r#"{"id":"same","panels":[{"curves":[{"ndf":"phong","alpha_p":2}]}]}"#,
    )
    .unwrap();
    std::fs::write(
        dir.join("c.json"),
        r#"{"id":"c","panels":[{"curves":[{"ndf":"phong","alpha_p":-1},{"ndf":"ggx","alpha_tr":"x"}]}]}"#,
    )
    .unwrap();
    let out_dir = dir.join("out");
    let out = ndfplot(&[
        "render",
        dir.to_str().unwrap(),
        "-o",
        out_dir.to_str().unwrap(),
    ]);
    assert_input_error(&out, "b.json: id: duplicate id (got \"same\"");
    let err = text(&out.stderr);
    assert!(
        err.contains("c.json: panels[0].curves[0].alpha_p: out of domain"),
        "{err}"
    );
    assert!(
        err.contains("c.json: panels[0].curves[1].alpha_tr: expected a number"),
        "{err}"
    );
    assert!(!out_dir.exists());
}

#[test]
fn eval_fresnel_curves_and_their_bad_input() {
    let out = ndfplot(&[
        "eval",
        "--curve",
        r#"{"fresnel":"exact","eta":1.5}"#,
        "--theta",
        "0",
    ]);
    assert_eq!(
        text(&out.stdout),
        "theta,value\n0.0,0.04\n",
        "{}",
        text(&out.stderr)
    );
    let out = ndfplot(&[
        "eval",
        "--curve",
        r#"{"fresnel":"schlick","r":0.5,"g":0.5}"#,
        "--curve",
        r#"{"fresnel":"lazanyi_term"}"#,
        "--theta",
        "0",
    ]);
    assert!(text(&out.stdout).starts_with(r#"theta,"{""fresnel"":""schlick"",""r"":0.5,""g"":0.5,""g_remap"":false}","{""fresnel"":""lazanyi_term""}""#), "{}", text(&out.stdout));
    for (curve, needle) in [
        (
            r#"{"fresnel":"exact","r":1.0,"g":0.5}"#,
            "r: out of domain (got 1.0, expected in [0, 1))",
        ),
        (
            r#"{"fresnel":"exact","r":0.5,"g":1.5}"#,
            "g: out of domain (got 1.5",
        ),
        (
            r#"{"fresnel":"exact","eta":0,"kappa":0}"#,
            "eta: out of domain (got 0.0",
        ),
        (
            r#"{"fresnel":"exact","eta":1.5,"kappa":-1}"#,
            "kappa: out of domain (got -1.0",
        ),
        (
            r#"{"fresnel":"exact","eta":1.5,"r":0.5,"g":0.1}"#,
            "cannot be combined",
        ),
        (
            r#"{"fresnel":"basis","index":4}"#,
            "index: out of domain (got 4.0, expected 0, 1, 2 or 3)",
        ),
        (
            r#"{"fresnel":"basis","index":1.5}"#,
            "index: out of domain (got 1.5",
        ),
        (r#"{"fresnel":"exakt","eta":1.5}"#, "did you mean \"exact\""),
        (r#"{"fresnel":"exact","ndf":"phong","eta":1.5}"#, "not both"),
        (
            r#"{"fresnel":"lazanyi","f0":0.5,"a":100}"#,
            "a: out of domain (got 100.0",
        ),
        (
            r#"{"fresnel":"exact","eta":1.5,"g_remap":true}"#,
            "keys eta, g_remap cannot be combined",
        ),
        (
            r#"{"fresnel":"exact","r":0.5,"g":0.5,"g_remap":"yes"}"#,
            "g_remap: expected true or false",
        ),
    ] {
        assert_input_error(
            &ndfplot(&["eval", "--curve", curve, "--theta", "0.5"]),
            needle,
        );
    }
}

#[test]
fn coeffs_prints_the_decomposition_of_materials() {
    let out = ndfplot(&[
        "coeffs",
        "--curve",
        r#"{"fresnel":"belcour","eta":1.0,"kappa":0.0}"#,
    ]);
    assert_eq!(
        text(&out.stdout),
        "c0,c1,c2,c3,l2\n0.0,0.0,0.0,0.0,0.0\n",
        "{}",
        text(&out.stderr)
    );
    assert_input_error(
        &ndfplot(&["coeffs", "--curve", r#"{"ndf":"phong","alpha_p":1}"#]),
        "coeffs needs a material",
    );
}

#[test]
fn fit_prints_the_curve_for_eval_and_the_residual_on_stderr() {
    let out = ndfplot(&[
        "fit",
        "--target",
        r#"{"ndf":"ggx","alpha_tr":0.3}"#,
        "--family",
        "abc",
        "--fix",
        "alpha_abc2=1.75",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let line = text(&out.stdout);
    assert!(
        line.starts_with(r#"{"ndf":"abc","alpha_abc1":23.444"#)
            && line.ends_with(",\"alpha_abc2\":1.75}\n"),
        "{line}"
    );
    let residual = text(&out.stderr);
    assert!(
        residual.starts_with("residual=") && residual.trim_end().ends_with(" (d0_rel)"),
        "{residual}"
    );
    let eval = ndfplot(&["eval", "--curve", line.trim_end(), "--theta", "0"]);
    let target = ndfplot(&[
        "eval",
        "--curve",
        r#"{"ndf":"ggx","alpha_tr":0.3}"#,
        "--theta",
        "0",
    ]);
    let value = |o: &Output| {
        text(&o.stdout)
            .lines()
            .nth(1)
            .unwrap()
            .split(',')
            .nth(1)
            .unwrap()
            .parse::<f64>()
            .unwrap()
    };
    assert!((value(&eval) / value(&target) - 1.0).abs() < 1e-14);
    let l2 = ndfplot(&[
        "fit",
        "--target",
        r#"{"ndf":"ggx","alpha_tr":0.3}"#,
        "--family",
        "abc",
        "--fix",
        "alpha_abc2=1.75",
        "--by",
        "l2",
    ]);
    assert!(
        text(&l2.stderr).ends_with(" (l2_projected)\n") && text(&l2.stdout) != line,
        "{}",
        text(&l2.stderr)
    );
}

#[test]
fn fit_bad_input_exits_2_naming_the_problem() {
    let tr = r#"{"ndf":"trowbridge_reitz","alpha_tr":0.3}"#;
    for (args, needle) in [
        (
            vec!["--family", "abc", "--fix", "alpha_abc3=1"],
            "error: --fix: alpha_abc3: not a parameter of abc (got alpha_abc3=1.0",
        ),
        (
            vec!["--family", "trowbridge_reitz", "--fix", "alpha_tr=1"],
            "error: --fix: alpha_tr: no free parameter left",
        ),
        (vec!["--family", "abc"], "abc has 2 free parameters"),
        (
            vec!["--family", "abc", "--fix", "alpha_abc2=x"],
            "error: --fix: alpha_abc2: not a number (got \"x\"",
        ),
        (
            vec!["--family", "abd", "--fix", "alpha_abc2=1"],
            "did you mean \"abc\"",
        ),
        (
            vec!["--family", "phong", "--by", "l3"],
            "error: --by: l3: unknown fit method",
        ),
    ] {
        let mut all = vec!["fit", "--target", tr];
        all.extend(args);
        assert_input_error(&ndfplot(&all), needle);
    }
    let uniform = ndfplot(&[
        "fit",
        "--target",
        r#"{"ndf":"phong","alpha_p":0}"#,
        "--family",
        "torrance_sparrow",
    ]);
    assert_input_error(
        &uniform,
        "error: --target: alpha_ts: torrance_sparrow cannot reach the target's D(0) (got 0.3183098861837907",
    );
}

#[test]
fn compare_table_json_and_max_error_gate() {
    let (a, b) = (
        r#"{"ndf":"ggx","alpha_tr":0.3}"#,
        r#"{"ndf":"abc","alpha_abc1":23.5,"alpha_abc2":1.75}"#,
    );
    let table = ndfplot(&["compare", "--a", a, "--b", b]);
    assert_eq!(table.status.code(), Some(0), "{}", text(&table.stderr));
    for name in [
        "max_abs",
        "max_rel",
        "l2_projected",
        "l2_grid",
        "a_peak",
        "b_peak",
    ] {
        assert!(
            text(&table.stdout).lines().any(|l| l.starts_with(name)),
            "{name}: {}",
            text(&table.stdout)
        );
    }
    let json = ndfplot(&["compare", "--a", a, "--b", b, "--format", "json"]);
    let value: serde_json::Value = serde_json::from_str(&text(&json.stdout)).unwrap();
    assert_eq!(value["a"]["ndf"], "trowbridge_reitz");
    assert_eq!(value["a_peak_theta"], 0.0);
    let max_rel = value["max_rel"].as_f64().unwrap();
    assert!(
        max_rel > 0.0 && max_rel < 1.0 && value["l2_grid"].as_f64().unwrap() > 0.0,
        "{value}"
    );
    let pass = ndfplot(&[
        "compare",
        "--a",
        a,
        "--b",
        b,
        "--max-error",
        &format!("max_rel={}", max_rel * 1.01),
    ]);
    assert_eq!(pass.status.code(), Some(0), "{}", text(&pass.stderr));
    let fail = ndfplot(&[
        "compare",
        "--a",
        a,
        "--b",
        b,
        "--max-error",
        "max_rel=1e-6",
        "--max-error",
        "l2_grid=1e9",
    ]);
    assert_eq!(fail.status.code(), Some(1));
    assert!(
        !fail.stdout.is_empty() && text(&fail.stderr).starts_with("compare: max_rel = "),
        "{}",
        text(&fail.stderr)
    );
    assert_eq!(text(&fail.stderr).lines().count(), 1);
    assert_input_error(
        &ndfplot(&["compare", "--a", a, "--b", b, "--max-error", "max_rel="]),
        "error: --max-error: max_rel: not a number",
    );
    let fresnel = r#"{"fresnel":"exact","eta":1.5}"#;
    assert_input_error(
        &ndfplot(&["compare", "--a", a, "--b", fresnel]),
        "compare needs two curves of the same kind",
    );
    let same = ndfplot(&[
        "compare",
        "--a",
        fresnel,
        "--b",
        r#"{"fresnel":"schlick","eta":1.5}"#,
        "--format",
        "json",
    ]);
    assert_eq!(same.status.code(), Some(0), "{}", text(&same.stderr));
}

#[test]
fn check_passes_on_the_catalogue_and_fails_beyond_the_tolerance() {
    let out = ndfplot(&["check"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let table = text(&out.stdout);
    assert!(
        table
            .lines()
            .skip(1)
            .all(|l| l.starts_with("ok ") || l.starts_with("- ")),
        "{table}"
    );
    assert!(
        table.contains("hemispherical_average") && table.contains("abc-vs-tr"),
        "{table}"
    );
    // No quadrature lands every integral on exactly 1.0: a zero tolerance fails (exit 1) with the table printed.
    let strict = ndfplot(&["check", "--tolerance", "0"]);
    assert_eq!(strict.status.code(), Some(1), "{}", text(&strict.stderr));
    assert!(
        text(&strict.stdout).contains("\nFAIL ")
            && text(&strict.stderr)
                .lines()
                .any(|l| l.starts_with("check: ")),
        "{}",
        text(&strict.stderr)
    );
}

#[test]
fn scene_fits_and_differences_render_with_fitted_values_in_the_csv() {
    let dir = scratch("scene_fits");
    let spec = dir.join("fits.json");
    std::fs::write(
        &spec,
        r#"{"id": "fits", "panels": [{"curves": [
            {"ndf": "abc", "alpha_abc2": 1.75,
             "alpha_abc1": {"fit": {"target": {"ndf": "trowbridge_reitz", "alpha_tr": [0.4, 0.6]}, "by": "peak"}}},
            {"difference": "ratio", "a": {"ndf": "ggx", "alpha_tr": [0.4, 0.6]}, "b": {"ndf": "ggx", "alpha_tr": [0.5, 0.7]}}
        ]}]}"#,
    )
    .unwrap();
    let out = ndfplot(&[
        "render",
        spec.to_str().unwrap(),
        "-o",
        dir.to_str().unwrap(),
        "--format",
        "csv,svg",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let csv = std::fs::read_to_string(dir.join("fits.csv")).unwrap();
    assert!(
        csv.contains(r#""{""ndf"":""abc"",""alpha_abc1"":11.58186251432451"#),
        "{}",
        &csv[..300]
    );
    assert!(csv.contains(
        r#""{""difference"":""ratio"",""a"":{""ndf"":""trowbridge_reitz"",""alpha_tr"":0.6}"#
    ));
    let svg = std::fs::read_to_string(dir.join("fits.svg")).unwrap();
    // The fits are one legend row naming their targets, `α_{tr}` typeset with tr as a subscript
    // run, fitted values to three digits.
    assert!(
        svg.contains("> = 11.6 … 3.57 (peak fit to </text>") && svg.contains(">tr</text>"),
        "legend"
    );
    std::fs::write(
        &spec,
        r#"{"id": "fits", "panels": [{"curves": [
            {"ndf": "torrance_sparrow", "alpha_ts": {"fit": {"target": {"ndf": "phong", "alpha_p": [1, 0]}}}},
            {"difference": "minus", "a": {"ndf": "ggx", "alpha_tr": [0.4, 0.6]}, "b": {"ndf": "beckmann", "alpha_b": [0.4, 0.5, 0.6]}}
        ]}]}"#,
    )
    .unwrap();
    let bad = ndfplot(&[
        "render",
        spec.to_str().unwrap(),
        "-o",
        dir.to_str().unwrap(),
    ]);
    assert_input_error(
        &bad,
        "panels[0].curves[0].alpha_ts: fit to α_p = 0: alpha_ts: torrance_sparrow cannot reach",
    );
    assert!(
        text(&bad.stderr)
            .contains("panels[0].curves[1]: a and b pair element-wise (got 2 and 3 curves"),
        "{}",
        text(&bad.stderr)
    );
}

#[test]
fn eval_accepts_difference_series() {
    let minus =
        r#"{"difference":"minus","a":{"ndf":"phong","alpha_p":0},"b":{"ndf":"phong","alpha_p":0}}"#;
    let out = ndfplot(&["eval", "--curve", minus, "--theta", "0,1"]);
    assert_eq!(
        text(&out.stdout),
        "theta,value\n0.0,0.0\n1.0,0.0\n",
        "{}",
        text(&out.stderr)
    );
    let ratio = r#"{"difference":"ratio","a":{"ndf":"phong","alpha_p":1},"b":{"ndf":"beckmann","alpha_b":0.01}}"#;
    let out = ndfplot(&["eval", "--curve", ratio, "--theta", "0,1.5"]);
    assert_eq!(
        out.status.code(),
        Some(2),
        "ratio over a vanishing denominator is an error: {}",
        text(&out.stdout)
    );
}

#[test]
fn compare_takes_a_csv_series_as_either_side() {
    // A renderer's table: `eval` output with every value 2 % high, θ in degrees.
    let dir = scratch("compare-csv");
    let curve = r#"{"ndf":"ggx","alpha_tr":0.3}"#;
    let eval = ndfplot(&["eval", "--curve", curve, "--theta", "0:90:91", "--degrees"]);
    assert_eq!(eval.status.code(), Some(0), "{}", text(&eval.stderr));
    let mut table = String::from("deg,D\n");
    for line in text(&eval.stdout).lines().skip(1) {
        let (degrees, value) = line.split_once(',').unwrap();
        table.push_str(&format!(
            "{degrees},{}\n",
            1.02 * value.parse::<f64>().unwrap()
        ));
    }
    std::fs::write(dir.join("renderer.csv"), table).unwrap();
    let series =
        r#"{"data": "csv", "path": "renderer.csv", "x": "deg", "y": "D", "degrees": true}"#;
    std::fs::write(dir.join("series.json"), series).unwrap();
    let at_file = format!("@{}", dir.join("series.json").display());
    for (a, b) in [(at_file.as_str(), curve), (curve, at_file.as_str())] {
        let out = ndfplot(&["compare", "--a", a, "--b", b, "--format", "json"]);
        assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
        let value: serde_json::Value = serde_json::from_str(&text(&out.stdout)).unwrap();
        let max_rel = value["max_rel"].as_f64().unwrap();
        assert!((max_rel - 0.02 / 1.02).abs() < 1e-12, "{value}");
        assert_eq!(value["max_abs_theta"], 0.0, "{value}");
        let side = if a == curve { "b" } else { "a" };
        assert_eq!(value[side]["path"], "renderer.csv", "{value}");
    }
    let same = ndfplot(&["compare", "--a", &at_file, "--b", &at_file]);
    assert_eq!(same.status.code(), Some(0), "{}", text(&same.stderr));
    assert!(
        text(&same.stdout).contains("\nmax_abs       0.0 "),
        "{}",
        text(&same.stdout)
    );
    let gate = ndfplot(&[
        "compare",
        "--a",
        &at_file,
        "--b",
        curve,
        "--max-error",
        "max_rel=0.01",
    ]);
    assert_eq!(gate.status.code(), Some(1), "{}", text(&gate.stderr));

    let missing = dir.join("nowhere.csv");
    let missing = format!(r#"{{"data": "csv", "path": "{}"}}"#, missing.display());
    assert_input_error(
        &ndfplot(&["compare", "--a", &missing, "--b", curve]),
        "error: --a: path: cannot read",
    );
    let column = series.replace("\"D\"", "\"value\"");
    std::fs::write(dir.join("column.json"), column).unwrap();
    let column = format!("@{}", dir.join("column.json").display());
    assert_input_error(
        &ndfplot(&["compare", "--a", curve, "--b", &column]),
        "no column \"value\" (expected one of: deg, D)",
    );
    assert_input_error(
        &ndfplot(&[
            "compare",
            "--a",
            r#"{"data": "table", "x": [0], "y": [1]}"#,
            "--b",
            curve,
        ]),
        "error: --a: data: not a series of θ",
    );
}

#[test]
fn an_interactive_scene_static_figure_states_its_slider_positions() {
    let out = scratch("cli-interactive-title");
    let spec = root().join("configs/fresnel-interactive.json");
    let output = ndfplot(&[
        "render",
        spec.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--format",
        "svg",
    ]);
    assert_eq!(output.status.code(), Some(0), "{}", text(&output.stderr));
    let svg = std::fs::read_to_string(out.join("fresnel-interactive.svg")).unwrap();
    // η and κ are italic runs of their own: the title reads "… at η = 1.1, κ = 0".
    assert!(
        svg.contains(">) — at </text>")
            && svg.contains("> = 1.1, </text>")
            && svg.contains("> = 0</text>"),
        "no slider positions in the title"
    );
}

#[test]
fn the_catalogue_is_listed_shown_and_rendered_by_id() {
    let list = ndfplot(&["list"]);
    assert_eq!(list.status.code(), Some(0));
    let listing = text(&list.stdout);
    let configs = files_in(&root().join("configs"));
    assert_eq!(listing.lines().count(), configs.len());
    assert!(
        listing.contains("tr-ranges\tTrowbridge–Reitz (GGX)\n"),
        "{listing}"
    );

    let show = ndfplot(&["show", "tr-ranges"]);
    assert_eq!(show.status.code(), Some(0));
    let committed = std::fs::read_to_string(root().join("configs/tr-ranges.json")).unwrap();
    assert_eq!(text(&show.stdout), committed);
    let unknown = ndfplot(&["show", "tr-range"]);
    assert_eq!(unknown.status.code(), Some(2));
    assert!(text(&unknown.stderr).contains("did you mean \"tr-ranges\""));

    let out = scratch("cli-render-by-id");
    let output = ndfplot(&[
        "render",
        "tr-ranges",
        "-o",
        out.to_str().unwrap(),
        "--format",
        "csv",
    ]);
    assert_eq!(output.status.code(), Some(0), "{}", text(&output.stderr));
    assert_eq!(files_in(&out), ["tr-ranges.csv"]);
    let missing = ndfplot(&["render", "tr-rangez", "-o", out.to_str().unwrap()]);
    assert_eq!(missing.status.code(), Some(2));
    assert!(
        text(&missing.stderr).contains(
            "no such file, folder or catalogue id (see ndfplot list); did you mean \"tr-ranges\"?"
        ),
        "{}",
        text(&missing.stderr)
    );
}

/// `eval --theta @FILE --theta-column NAME` takes the angles of a CSV column (a shader's samples),
/// the same table the angles give inline; a missing column lists the columns, a bad cell names its
/// line, and the option without a file is refused. The messages name the file whole, however
/// long its path (here past 60 characters wherever the tests run).
#[test]
fn eval_reads_angles_from_a_csv_column() {
    let dir =
        scratch("eval-theta-column").join("samples-of-a-shader-exported-from-an-engine-frame");
    std::fs::create_dir_all(&dir).unwrap();
    let samples = dir.join("shader.csv");
    std::fs::write(
        &samples,
        "value,theta\n3.5,0\n0.1,pi/4\n# a note\n0.02, 1.5 \n",
    )
    .unwrap();
    let curve = r#"{"ndf":"ggx","alpha_tr":0.3}"#;
    let file = format!("@{}", samples.display());
    let column = |name: &str| {
        ndfplot(&[
            "eval",
            "--curve",
            curve,
            "--theta",
            &file,
            "--theta-column",
            name,
        ])
    };
    let from_column = column("theta");
    let inline = ndfplot(&["eval", "--curve", curve, "--theta", "0,pi/4,1.5"]);
    assert_eq!(
        from_column.status.code(),
        Some(0),
        "{}",
        text(&from_column.stderr)
    );
    assert_eq!(text(&from_column.stdout), text(&inline.stdout));
    let missing = column("thta");
    assert_eq!(missing.status.code(), Some(2));
    assert!(
        text(&missing.stderr).starts_with("error: --theta-column: ")
            && text(&missing.stderr).contains(
                "shader.csv: no column \"thta\" (expected one of: value, theta); did you mean \"theta\"?"
            ),
        "{}",
        text(&missing.stderr)
    );
    let bad = column("value");
    assert!(
        text(&bad.stderr).contains("shader.csv: line 2: angle out of range (got 3.5"),
        "{}",
        text(&bad.stderr)
    );
    let no_file = ndfplot(&[
        "eval",
        "--curve",
        curve,
        "--theta",
        "0",
        "--theta-column",
        "theta",
    ]);
    assert_eq!(no_file.status.code(), Some(2));
}

/// `eval --theta @FILE` reads one angle per line (blank lines and `#` comments skipped) and gives
/// the table the same angles give inline; a bad line is named by its number, and a file that
/// cannot be read names the option that named it.
#[test]
fn eval_reads_angles_from_a_file_one_per_line() {
    let dir = scratch("eval-theta-file");
    let angles = dir.join("angles.txt");
    std::fs::write(&angles, "# hemisphere\n0\n\npi/4\n  0.3  \n").unwrap();
    let curve = r#"{"ndf":"ggx","alpha_tr":0.3}"#;
    let from_file = ndfplot(&[
        "eval",
        "--curve",
        curve,
        "--theta",
        &format!("@{}", angles.display()),
    ]);
    let inline = ndfplot(&["eval", "--curve", curve, "--theta", "0,pi/4,0.3"]);
    assert_eq!(
        from_file.status.code(),
        Some(0),
        "{}",
        text(&from_file.stderr)
    );
    assert_eq!(text(&from_file.stdout), text(&inline.stdout));

    std::fs::write(&angles, "0\n2\n").unwrap();
    let out = ndfplot(&[
        "eval",
        "--curve",
        curve,
        "--theta",
        &format!("@{}", angles.display()),
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).contains("angles.txt:2: angle out of range (got 2"),
        "{}",
        text(&out.stderr)
    );

    for (flag, args) in [
        (
            "--theta",
            vec!["eval", "--curve", curve, "--theta", "@no-such-angles.txt"],
        ),
        (
            "--curve",
            vec!["eval", "--curve", "@no-such-curve.json", "--theta", "0"],
        ),
        (
            "--a",
            vec!["compare", "--a", "@no-such-curve.json", "--b", curve],
        ),
    ] {
        let out = ndfplot(&args);
        assert_eq!(out.status.code(), Some(2));
        assert!(
            text(&out.stderr).starts_with(&format!("error: {flag}: no-such-")),
            "{}",
            text(&out.stderr)
        );
    }
}
