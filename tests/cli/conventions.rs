//! Conventions every command shares: `render -` reads a spec from stdin and `-o -` writes one output
//! to stdout, `eval --degrees` prints θ in degrees, `-q` silences notes but never errors, `render
//! --theme` overrides a spec's theme, and `colour` may be spelt `color` in specs and theme names.

use crate::common::{ndfplot, ndfplot_stdin, scratch, text};
use std::process::Output;

fn ok(output: &Output) -> Vec<u8> {
    assert_eq!(output.status.code(), Some(0), "{}", text(&output.stderr));
    output.stdout.clone()
}

/// Asserts exit 2, nothing on stdout, and `needle` on stderr.
fn refused(output: &Output, needle: &str) {
    let err = text(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{err}");
    assert!(
        output.stdout.is_empty(),
        "stdout has {} bytes",
        output.stdout.len()
    );
    assert!(
        err.starts_with("error: ") && err.contains(needle),
        "{needle:?} in {err}"
    );
}

#[test]
fn render_reads_a_spec_from_stdin_and_writes_one_output_to_stdout() {
    let spec = text(&ok(&ndfplot(&["show", "gtr-gamma"])));
    let dir = scratch("conventions-stdout");
    let files = ndfplot(&[
        "render",
        "gtr-gamma",
        "-o",
        dir.to_str().unwrap(),
        "--format",
        "svg,csv",
    ]);
    ok(&files);
    for format in ["svg", "csv"] {
        let piped = ok(&ndfplot_stdin(
            &["render", "-", "-o", "-", "--format", format],
            &spec,
        ));
        let written = std::fs::read(dir.join(format!("gtr-gamma.{format}"))).unwrap();
        assert!(piped == written, "{format}: stdout differs from the file");
    }
    let png = ok(&ndfplot(&[
        "render",
        "gtr-gamma",
        "-o",
        "-",
        "--format",
        "png",
    ]));
    assert!(png.starts_with(b"\x89PNG\r\n\x1a\n"));
    let bad = ndfplot_stdin(
        &["render", "-", "-o", dir.to_str().unwrap()],
        "{\"id\": \"x\"}",
    );
    refused(&bad, "error: stdin: panels: missing");
}

#[test]
fn ambiguous_stdout_renders_are_refused_before_writing() {
    refused(
        &ndfplot(&["render", "gtr-gamma", "-o", "-"]),
        "-o -: writes one figure in one format to stdout (got 4 formats: svg,png,csv,html; expected one, e.g. --format svg)",
    );
    refused(
        &ndfplot(&[
            "render",
            "gtr-gamma",
            "abc-grid",
            "-o",
            "-",
            "--format",
            "svg",
        ]),
        "(got 2 specs; expected one spec file, catalogue id or -)",
    );
    refused(
        &ndfplot(&["render", "-o", "-", "--format", "csv"]),
        "specs; expected one",
    );
    refused(
        &ndfplot(&["render", "gtr-gamma", "-o", "-", "--format", "html"]),
        "html is written only for scenes with sliders",
    );
    refused(
        &ndfplot_stdin(&["render", "-", "-", "-o", "-", "--format", "svg"], ""),
        "stdin holds one spec and is read once (got - 2 times",
    );
}

#[test]
fn eval_with_degrees_prints_the_degrees_given() {
    let eval = |thetas: &str, extra: &[&str]| {
        let mut args = vec![
            "eval",
            "--curve",
            r#"{"ndf":"ggx","alpha_tr":0.2}"#,
            "--theta",
            thetas,
        ];
        args.extend(extra);
        text(&ok(&ndfplot(&args)))
    };
    let out = eval("0,30,60,90", &["--degrees"]);
    let radians = eval("0,pi/6,pi/3,pi/2", &[]);
    let column = |csv: &str, i: usize| -> Vec<String> {
        csv.lines()
            .map(|l| l.split(',').nth(i).unwrap().to_string())
            .collect()
    };
    assert_eq!(
        column(&out, 0),
        ["theta_deg", "0.0", "30.0", "60.0", "90.0"]
    );
    assert_eq!(column(&radians, 0)[0], "theta");
    assert_eq!(
        column(&out, 1)[1..],
        column(&radians, 1)[1..],
        "same θ, same values"
    );
}

#[test]
fn quiet_silences_notes_on_every_command_but_never_errors() {
    let fit = [
        "fit",
        "--target",
        r#"{"ndf":"ggx","alpha_tr":0.3}"#,
        "--family",
        "beckmann",
    ];
    let noisy = ndfplot(&fit);
    assert!(
        text(&noisy.stderr).starts_with("residual="),
        "{}",
        text(&noisy.stderr)
    );
    for quiet in [["-q"].as_slice(), ["--quiet"].as_slice()] {
        let mut args: Vec<&str> = fit.to_vec();
        args.extend(quiet);
        let out = ndfplot(&args);
        assert_eq!(ok(&out), noisy.stdout);
        assert!(out.stderr.is_empty(), "{}", text(&out.stderr));
        let mut before = quiet.to_vec();
        before.extend(fit);
        assert!(ndfplot(&before).stderr.is_empty(), "-q before the command");
    }
    for command in [
        vec!["eval", "-q", "--curve", "{}", "--theta", "0"],
        vec!["compare", "-q", "--a", "{}", "--b", "{}"],
        vec!["coeffs", "-q", "--curve", "{}"],
        vec!["check", "-q", "no-such-spec"],
        vec!["render", "-q", "no-such-spec"],
        vec!["show", "-q", "no-such-id"],
    ] {
        let out = ndfplot(&command);
        assert_eq!(out.status.code(), Some(2), "{command:?}");
        assert!(
            text(&out.stderr).starts_with("error: "),
            "{command:?}: errors stay"
        );
    }
    for command in ["list", "schema", "man"] {
        assert_eq!(
            ndfplot(&[command, "-q"]).status.code(),
            Some(0),
            "{command} -q"
        );
    }
}

#[test]
fn theme_flag_overrides_the_spec_and_colour_takes_both_spellings() {
    let svg = |args: &[&str]| {
        let mut all = vec!["render", "gtr-gamma", "-o", "-", "--format", "svg"];
        all.extend(args);
        text(&ok(&ndfplot(&all)))
    };
    let notebook = svg(&[]);
    let dark = svg(&["--theme", "dark"]);
    assert_ne!(notebook, dark);
    assert_eq!(
        svg(&["--theme", "notebook"]),
        notebook,
        "gtr-gamma's own theme"
    );
    assert_eq!(
        svg(&["--theme", "color-blind"]),
        svg(&["--theme", "colour-blind"])
    );
    let refused_theme = ndfplot(&[
        "render",
        "gtr-gamma",
        "-o",
        "-",
        "--format",
        "svg",
        "--theme",
        "sepia",
    ]);
    assert_eq!(refused_theme.status.code(), Some(2));
    assert!(
        text(&refused_theme.stderr).contains("colour-blind"),
        "{}",
        text(&refused_theme.stderr)
    );

    let spec = |key: &str, theme: &str| {
        format!(
            r##"{{"id": "spelt", "theme": "{theme}", "panels": [{{"curves": [{{"ndf": "phong", "alpha_p": 1, "{key}": "#123456"}}, {{"data": "table", "x": [0, 1], "y": [1, 2], "{key}": "#654321"}}]}}]}}"##
        )
    };
    let render = |text: String| {
        ok(&ndfplot_stdin(
            &["render", "-", "-o", "-", "--format", "svg"],
            &text,
        ))
    };
    let british = render(spec("colour", "colour-blind"));
    let american = render(spec("color", "color-blind"));
    let strip = |svg: Vec<u8>| {
        // The provenance line hashes the spec's bytes, which differ by the spelling.
        text(&svg)
            .lines()
            .filter(|l| !l.starts_with("<metadata>"))
            .collect::<Vec<_>>()
            .join("\n")
    };
    assert_eq!(strip(british), strip(american));
    let schema: serde_json::Value = serde_json::from_slice(&ok(&ndfplot(&["schema"]))).unwrap();
    let validator = jsonschema::validator_for(&schema).unwrap();
    for (key, theme) in [("colour", "colour-blind"), ("color", "color-blind")] {
        let instance: serde_json::Value = serde_json::from_str(&spec(key, theme)).unwrap();
        assert!(validator.is_valid(&instance), "{key}, {theme}");
    }
}
