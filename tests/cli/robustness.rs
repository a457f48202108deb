//! Robustness of the real binary: the malformed-spec corpus (exit 2, nothing on stdout, every line
//! naming the file and the expected message), the fuzz corpus replayed, a render killed with
//! SIGKILL mid-run (only complete files under real names; a later run removes abandoned
//! temporaries), two renders into one folder at once,
//! `render --check`, and the generated help, completions and manual page.

#[path = "../../fuzz/harness.rs"]
mod harness;

use crate::common::{files_in, ndfplot, root, scratch, text};
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

fn files_with_extension(dir: &Path, extension: &str) -> Vec<PathBuf> {
    files_in(dir)
        .into_iter()
        .map(|f| dir.join(f))
        .filter(|p| p.extension().is_some_and(|e| e == extension))
        .collect()
}

#[test]
fn every_malformed_spec_exits_2_naming_its_path_and_the_expected_message() {
    let corpus = root().join("tests/data/malformed");
    let out_dir = scratch("robustness-malformed-out");
    let cases = files_with_extension(&corpus, "json");
    assert!(cases.len() >= 50, "only {} cases", cases.len());
    for case in cases {
        let expected = std::fs::read_to_string(case.with_extension("expected"))
            .unwrap_or_else(|_| panic!("{} has no .expected file", case.display()));
        let path = case.to_str().unwrap();
        let out = ndfplot(&["render", path, "-o", out_dir.to_str().unwrap()]);
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{path}: {err}");
        assert!(
            out.stdout.is_empty(),
            "{path}: stdout {}",
            text(&out.stdout)
        );
        assert!(!err.contains("panicked"), "{path}: {err}");
        let prefix = format!("error: {path}: ");
        assert!(
            err.lines().all(|l| l.starts_with(&prefix)),
            "{path}: every line names the file:\n{err}"
        );
        for needle in expected.lines().filter(|l| !l.is_empty()) {
            assert!(
                err.contains(needle),
                "{path}: expected {needle:?} in:\n{err}"
            );
        }
        assert!(
            files_in(&out_dir).is_empty(),
            "{path}: wrote {:?}",
            files_in(&out_dir)
        );
    }
}

#[test]
fn the_fuzz_corpus_replays_without_breaking_an_invariant() {
    let corpus = root().join("fuzz/corpus/spec");
    // The committed seeds (what CI has); a local fuzzing run rewrites its other entries meanwhile.
    let seeds: Vec<String> = files_in(&corpus)
        .into_iter()
        .filter(|f| f.starts_with("seed-"))
        .collect();
    assert!(seeds.len() >= 100, "seed corpus missing");
    for name in seeds {
        let bytes = std::fs::read(corpus.join(&name)).unwrap();
        let outcome = std::panic::catch_unwind(|| harness::run(&bytes));
        assert!(
            outcome.is_ok(),
            "fuzz/corpus/spec/{name} breaks an invariant"
        );
    }
}

#[test]
fn fuzz_findings_exit_2_through_the_binary() {
    let corpus = root().join("fuzz/corpus/spec");
    let dir = scratch("robustness-findings");
    for name in files_in(&corpus)
        .into_iter()
        .filter(|f| f.starts_with("seed-finding-"))
    {
        let bytes = std::fs::read(corpus.join(&name)).unwrap();
        let spec = dir.join(format!("{name}.json"));
        std::fs::write(&spec, &bytes[1..]).unwrap();
        let out = ndfplot(&[
            "render",
            spec.to_str().unwrap(),
            "-o",
            dir.join("out").to_str().unwrap(),
            "--format",
            "csv",
        ]);
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{name}: {err}");
        assert!(
            out.stdout.is_empty() && !err.contains("panicked"),
            "{name}: {err}"
        );
        assert!(
            err.lines()
                .all(|l| l.starts_with(&format!("error: {}: ", spec.display()))),
            "{name}: {err}"
        );
    }
}

/// `count` small scenes in `dir/specs`, so that a run spends a while writing files one after
/// another; returns how many files a render of them writes.
fn write_specs(dir: &Path, count: usize) -> usize {
    let specs = dir.join("specs");
    std::fs::create_dir_all(&specs).unwrap();
    for i in 0..count {
        let spec = format!(
            r#"{{"id": "scene-{i:02}", "title": "Scene {i}", "sampling": {{"uniform": 400}}, "panels": [
                {{"curves": [{{"ndf": "beckmann", "alpha_b": {{"range": [0.1, 0.8, 0.1]}}}}]}},
                {{"y": {{"scale": "log"}}, "curves": [{{"ndf": "ggx", "alpha_tr": [0.05, 0.2, 0.{}]}}]}}]}}"#,
            i + 1
        );
        std::fs::write(specs.join(format!("scene-{i:02}.json")), spec).unwrap();
    }
    count * 3
}

fn render_into(specs: &Path, out: &Path) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_ndfplot"));
    command.args([
        "render",
        specs.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--format",
        "svg,png,csv",
    ]);
    command.stdout(Stdio::null()).stderr(Stdio::null());
    command
}

/// Asserts that every non-hidden file of `dir` is complete: identical to the finished run's, and
/// an SVG that parses, a PNG that decodes or a CSV with all its rows. Returns how many there are.
fn assert_complete(dir: &Path, reference: &Path) -> usize {
    let visible: Vec<String> = files_in(dir)
        .into_iter()
        .filter(|f| !f.starts_with('.'))
        .collect();
    for name in &visible {
        let bytes = std::fs::read(dir.join(name)).unwrap();
        let expected = std::fs::read(reference.join(name)).unwrap();
        match name.rsplit('.').next().unwrap() {
            "svg" => {
                roxmltree::Document::parse(&text(&bytes)).unwrap_or_else(|e| panic!("{name}: {e}"));
            }
            "png" => {
                let mut reader = png::Decoder::new(std::io::Cursor::new(bytes.as_slice()))
                    .read_info()
                    .unwrap();
                let mut pixels = vec![0; reader.output_buffer_size().unwrap()];
                reader
                    .next_frame(&mut pixels)
                    .unwrap_or_else(|e| panic!("{name}: {e}"));
            }
            "csv" => {
                let rows = |b: &[u8]| {
                    csv::Reader::from_reader(b)
                        .records()
                        .map(Result::unwrap)
                        .count()
                };
                assert_eq!(rows(&bytes), rows(&expected), "{name}: rows");
            }
            other => panic!("unexpected file {name} ({other})"),
        }
        assert!(bytes == expected, "{name} differs from the finished run's");
    }
    visible.len()
}

/// Sixteen specs in `dir/specs` rendered whole into `dir/reference`: what killed or interrupted
/// runs are compared with.
struct Rendered {
    /// Files a whole run writes.
    total: usize,
    specs: PathBuf,
    reference: PathBuf,
    /// How long the whole run took.
    full: Duration,
}

/// How close the bisections of a kill's moment get: aiming more finely than the jitter of
/// starting a process and waking a sleeping thread only repeats the same moment.
const AIM: Duration = Duration::from_millis(2);

fn rendered_whole(dir: &Path) -> Rendered {
    let total = write_specs(dir, 16);
    let (specs, reference) = (dir.join("specs"), dir.join("reference"));
    let start = Instant::now();
    assert!(render_into(&specs, &reference).status().unwrap().success());
    let full = start.elapsed();
    assert_eq!(files_in(&reference).len(), total);
    Rendered {
        total,
        specs,
        reference,
        full,
    }
}

/// SIGINT and SIGTERM at any moment of a render leave no temporary behind: the run removes the
/// temporaries it is writing and exits 128 + the signal (130, 143); the files it had renamed are
/// complete. The moment is bisected between "nothing written" and "all written" as above.
#[test]
fn an_interrupted_render_removes_its_temporaries_and_leaves_only_complete_files() {
    let dir = scratch("robustness-interrupt");
    let Rendered {
        total,
        specs,
        reference,
        full,
    } = rendered_whole(&dir);
    let (mut early, mut late) = (Duration::ZERO, full + full / 2);
    for attempt in 0..12 {
        if late - early < AIM {
            break;
        }
        let signal = if attempt % 2 == 0 {
            libc::SIGINT
        } else {
            libc::SIGTERM
        };
        let out = dir.join(format!("attempt-{attempt}"));
        let at = (early + late) / 2;
        let mut child = render_into(&specs, &out).spawn().unwrap();
        std::thread::sleep(at);
        let pid = libc::pid_t::try_from(child.id()).unwrap();
        // SAFETY: signals the child this test started and has not yet waited for.
        assert_eq!(unsafe { libc::kill(pid, signal) }, 0);
        let status = child.wait().unwrap();
        assert!(
            matches!(status.code(), Some(0)) || status.code() == Some(128 + signal),
            "attempt {attempt}: {status:?}"
        );
        let hidden: Vec<String> = files_in(&out)
            .into_iter()
            .filter(|f| f.starts_with('.'))
            .collect();
        assert!(hidden.is_empty(), "attempt {attempt} left {hidden:?}");
        match assert_complete(&out, &reference) {
            0 => early = at,
            n if n == total => late = at,
            _ => {}
        }
    }
}

#[test]
fn a_render_killed_mid_run_leaves_only_complete_files_and_a_later_run_removes_old_temporaries() {
    let dir = scratch("robustness-kill");
    let Rendered {
        total,
        specs,
        reference,
        full,
    } = rendered_whole(&dir);

    // Bisect the kill time between "nothing written yet" and "everything written" until a kill
    // lands while the files are being written, or the two are within [`AIM`]; every attempt
    // checks what the kill left.
    let (mut early, mut late) = (Duration::ZERO, full + full / 2);
    let mut partial = None;
    let mut last = None;
    for attempt in 0..16 {
        if late - early < AIM {
            break;
        }
        let out = dir.join(format!("attempt-{attempt}"));
        last = Some(out.clone());
        let at = (early + late) / 2;
        let mut child = render_into(&specs, &out).spawn().unwrap();
        std::thread::sleep(at);
        child.kill().unwrap();
        child.wait().unwrap();
        match assert_complete(&out, &reference) {
            0 => early = at,
            n if n == total => late = at,
            _ => {
                partial = Some(out);
                break;
            }
        }
    }
    // Every attempt above already checked what its kill left. Landing inside the short writing
    // phase depends on the machine's load; when no attempt did, the clean-up check below still
    // runs on the last attempt's folder.
    let out = partial.unwrap_or_else(|| {
        eprintln!(
            "note: no kill landed while files were being written; checked kills at other moments"
        );
        last.expect("at least one attempt")
    });

    // The next run replaces every file. It removes the temporaries of its files older than an hour
    // (left by a killed run), and leaves younger ones, which may belong to a run still writing.
    std::fs::create_dir_all(&out).unwrap();
    let plant = |name: &str, age: Duration| {
        let path = out.join(name);
        std::fs::write(&path, "panel,series,curve,x,y\n0,0,").unwrap();
        let file = std::fs::File::options().write(true).open(&path).unwrap();
        file.set_modified(std::time::SystemTime::now() - age)
            .unwrap();
    };
    plant(".scene-00.csv.abc123.tmp", Duration::from_secs(7200));
    plant(".scene-01.csv.def456.tmp", Duration::ZERO);
    plant(".unrelated.csv.ghi789.tmp", Duration::from_secs(7200));
    // A user's file that merely starts and ends like a temporary of an output is not one.
    plant(".scene-02.csv.my-backup.tmp", Duration::from_secs(7200));
    let rerun = render_into(&specs, &out)
        .stderr(Stdio::piped())
        .output()
        .unwrap();
    assert!(
        rerun.status.success(),
        "{}",
        String::from_utf8_lossy(&rerun.stderr)
    );
    let hidden: Vec<String> = files_in(&out)
        .into_iter()
        .filter(|f| f.starts_with('.'))
        .collect();
    assert!(
        !hidden.contains(&".scene-00.csv.abc123.tmp".to_string()),
        "{hidden:?}"
    );
    assert!(
        hidden.contains(&".scene-01.csv.def456.tmp".to_string()),
        "{hidden:?}"
    );
    assert!(
        hidden.contains(&".unrelated.csv.ghi789.tmp".to_string()),
        "{hidden:?}"
    );
    assert!(
        hidden.contains(&".scene-02.csv.my-backup.tmp".to_string()),
        "{hidden:?}"
    );
    assert!(hidden.iter().all(|f| f.ends_with(".tmp")), "{hidden:?}");
    assert_eq!(assert_complete(&out, &reference), total);
}

#[test]
fn two_renders_into_one_folder_both_succeed_with_complete_files() {
    let dir = scratch("robustness-concurrent");
    let total = write_specs(&dir, 12);
    let specs = dir.join("specs");
    let reference = dir.join("reference");
    assert!(render_into(&specs, &reference).status().unwrap().success());
    // A symbolic link where a temporary used to be named is never written through.
    let out = dir.join("out");
    std::fs::create_dir_all(&out).unwrap();
    let victim = dir.join("victim.txt");
    std::fs::write(&victim, "untouched").unwrap();
    std::os::unix::fs::symlink(&victim, out.join(".scene-00.csv.tmp")).unwrap();
    for round in 0..5 {
        let children: Vec<_> = (0..2)
            .map(|_| {
                render_into(&specs, &out)
                    .stderr(Stdio::piped())
                    .spawn()
                    .unwrap()
            })
            .collect();
        for child in children {
            let result = child.wait_with_output().unwrap();
            assert!(
                result.status.success(),
                "round {round}: {}",
                String::from_utf8_lossy(&result.stderr)
            );
        }
        assert_eq!(assert_complete(&out, &reference), total, "round {round}");
        let hidden: Vec<String> = files_in(&out)
            .into_iter()
            .filter(|f| f.starts_with('.'))
            .collect();
        assert_eq!(hidden, [".scene-00.csv.tmp"], "round {round}");
    }
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "untouched");
}

const SPEC: &str = r#"{"id": "checked", "sampling": {"uniform": 50}, "panels": [
    {"curves": [{"ndf": "beckmann", "alpha_b": [0.3, 0.6]}, {"fresnel": "schlick", "f0": 0.04}]}]}"#;

/// Renders SPEC's CSV into a fresh folder; returns (spec path, output folder).
fn rendered(name: &str) -> (PathBuf, PathBuf) {
    let dir = scratch(&format!("robustness-{name}"));
    let spec = dir.join("spec.json");
    std::fs::write(&spec, SPEC).unwrap();
    let plots = dir.join("plots");
    let out = ndfplot(&[
        "render",
        spec.to_str().unwrap(),
        "-o",
        plots.to_str().unwrap(),
        "--format",
        "csv",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    (spec, plots)
}

fn check(spec: &Path, plots: &Path, extra: &[&str]) -> Output {
    let mut args = vec![
        "render",
        spec.to_str().unwrap(),
        "--check",
        plots.to_str().unwrap(),
    ];
    args.extend(extra);
    ndfplot(&args)
}

#[test]
fn render_check_passes_an_untouched_tree_and_catches_a_relative_change_of_1e_9() {
    let (spec, plots) = rendered("check");
    let before = files_in(&plots);
    let out = check(&spec, &plots, &[]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}{}",
        text(&out.stdout),
        text(&out.stderr)
    );
    assert!(
        text(&out.stdout).contains("all 1 CSVs match"),
        "{}",
        text(&out.stdout)
    );

    // Change one y value by 1e-9 relative.
    let csv_path = plots.join("checked.csv");
    let csv = std::fs::read_to_string(&csv_path).unwrap();
    let mut lines: Vec<String> = csv.lines().map(str::to_string).collect();
    let fields: Vec<&str> = lines[60].rsplitn(2, ',').collect();
    let y: f64 = fields[0].parse().unwrap();
    lines[60] = format!("{},{:?}", fields[1], y * (1.0 + 1e-9));
    std::fs::write(&csv_path, lines.join("\n") + "\n").unwrap();

    let out = check(&spec, &plots, &[]);
    let report = text(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{report}");
    assert!(report.contains("checked.csv: panel 0, series 1 {\"ndf\":\"beckmann\",\"alpha_b\":0.6}: y differs by 1.000e-9 relative"), "{report}");
    assert!(report.contains("1 of 50 rows differ"), "{report}");
    assert!(
        text(&out.stderr).contains("render --check"),
        "{}",
        text(&out.stderr)
    );
    // Within a looser tolerance it passes; --check never writes.
    assert_eq!(
        check(&spec, &plots, &["--tolerance", "1e-8"]).status.code(),
        Some(0)
    );
    assert_eq!(files_in(&plots), before);
    assert_eq!(
        std::fs::read_to_string(&csv_path).unwrap(),
        lines.join("\n") + "\n"
    );
}

#[test]
fn render_check_reports_missing_and_extra_csvs() {
    let (spec, plots) = rendered("check-files");
    std::fs::copy(plots.join("checked.csv"), plots.join("stale.csv")).unwrap();
    let out = check(&spec, &plots, &[]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text(&out.stdout).contains("stale.csv: extra in"),
        "{}",
        text(&out.stdout)
    );
    std::fs::remove_file(plots.join("stale.csv")).unwrap();
    std::fs::remove_file(plots.join("checked.csv")).unwrap();
    let out = check(&spec, &plots, &[]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text(&out.stdout).contains("checked.csv: missing from"),
        "{}",
        text(&out.stdout)
    );
    assert!(
        files_in(&plots).is_empty(),
        "--check wrote {:?}",
        files_in(&plots)
    );
}

/// An output folder the system cannot create names the option it came from, not only the path.
#[test]
fn an_output_folder_that_cannot_be_made_names_its_option() {
    let dir = scratch("robustness-o-error");
    std::fs::write(dir.join("file"), "x").unwrap();
    let inside = dir.join("file").join("sub");
    let out = ndfplot(&["render", "tr-vs-phong", "-o", inside.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = text(&out.stderr);
    assert!(
        err.starts_with(&format!("error: -o: {}: ", inside.display())),
        "{err}"
    );
    // A link to nothing is named as such, not "File exists".
    let dangling = dir.join("dangling");
    let _ = std::fs::remove_file(&dangling);
    std::os::unix::fs::symlink(dir.join("nowhere"), &dangling).unwrap();
    let out = ndfplot(&["render", "tr-vs-phong", "-o", dangling.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = text(&out.stderr);
    assert!(
        err.contains("not a folder (got a symbolic link to nothing"),
        "{err}"
    );
}

/// `-v` says one line per figure before the closing line; `--color always` paints the labels of
/// ndfplot's own messages (even into a pipe, and whatever NO_COLOR says), `never` and the default
/// into a pipe do not.
#[test]
fn verbose_lines_and_coloured_labels_are_on_stderr_only() {
    let out = ndfplot(&[
        "render",
        "tr-vs-phong",
        "abc-grid",
        "-o",
        scratch("verbose").to_str().unwrap(),
        "-v",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(out.stdout.is_empty());
    let stderr = text(&out.stderr);
    let lines: Vec<&str> = stderr.lines().collect();
    assert!(
        lines[0].starts_with(
            "render: configs/tr-vs-phong.json: tr-vs-phong: 1280 × 460 px, 2 panels, 22 series, "
        ),
        "{stderr}"
    );
    // Then what the drawing chose: each panel's legend, where and at what size.
    assert_eq!(
        lines[1],
        "render: configs/tr-vs-phong.json: panels[0]: legend of 3 entries inside the plot, clear of the curves, 1 column at 100 % size"
    );
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("render: configs/abc-grid.json: abc-grid: ")),
        "{stderr}"
    );
    assert!(
        lines
            .last()
            .unwrap()
            .starts_with("render: 2 figures, 6 files (2 svg, 2 png, 2 csv) written to "),
        "{stderr}"
    );
    let bad = r#"{"ndf":"ggx","alpha_tr":-1}"#;
    let painted = ndfplot(&["eval", "--curve", bad, "--theta", "0", "--color", "always"]);
    assert!(
        text(&painted.stderr).starts_with("\x1b[1;31merror:\x1b[0m --curve: alpha_tr: "),
        "{:?}",
        text(&painted.stderr)
    );
    let forced = crate::common::ndfplot_stdin_env(
        &["eval", "--curve", bad, "--theta", "0", "--color", "always"],
        "",
        &[("NO_COLOR", "1")],
    );
    assert_eq!(
        forced.stderr, painted.stderr,
        "--color always wins over NO_COLOR"
    );
    for plain in [&["--color", "never"][..], &[]] {
        let out = ndfplot(&[&["eval", "--curve", bad, "--theta", "0"][..], plain].concat());
        assert!(
            text(&out.stderr).starts_with("error: --curve: alpha_tr: "),
            "{plain:?}"
        );
    }
}

#[test]
fn stdout_carries_results_only_and_no_bar_is_drawn_without_a_terminal() {
    let (spec, plots) = rendered("quiet");
    for flags in [&[][..], &["-q"][..]] {
        let mut args = vec![
            "render",
            spec.to_str().unwrap(),
            "-o",
            plots.to_str().unwrap(),
        ];
        args.extend(flags);
        let out = ndfplot(&args);
        assert_eq!(out.status.code(), Some(0));
        // No bar: stderr holds only the closing line, and nothing under -q.
        let stderr = text(&out.stderr);
        let closing = stderr.starts_with("render: 1 figure, ")
            && stderr.ends_with(" s\n")
            && stderr.lines().count() == 1;
        assert!(
            out.stdout.is_empty()
                && (if flags.is_empty() {
                    closing
                } else {
                    stderr.is_empty()
                }),
            "{flags:?}: {}{stderr}",
            text(&out.stdout),
        );
    }
}

#[test]
fn every_subcommand_help_has_an_example_and_completions_and_man_are_generated() {
    use clap::CommandFactory;
    let cli = ndfplot::cli::Cli::command();
    let names: Vec<String> = cli
        .get_subcommands()
        .map(|s| s.get_name().to_string())
        .collect();
    assert!(names.len() >= 9, "{names:?}");
    for name in names {
        let out = ndfplot(&[&name, "--help"]);
        assert_eq!(out.status.code(), Some(0), "{name}");
        let help = text(&out.stdout);
        let example = ["Example:\n  ndfplot ", "Examples:\n  ndfplot "]
            .iter()
            .any(|e| help.contains(e));
        assert!(example, "{name} --help has no example:\n{help}");
    }
    for shell in ["bash", "zsh", "fish", "elvish", "powershell"] {
        let out = ndfplot(&["completions", shell]);
        assert_eq!(out.status.code(), Some(0), "{shell}");
        assert!(text(&out.stdout).contains("render"), "{shell}");
    }
    let out = ndfplot(&["man"]);
    assert_eq!(out.status.code(), Some(0));
    assert!(
        text(&out.stdout).contains(".TH ndfplot"),
        "{}",
        text(&out.stdout)
    );
    let out = ndfplot(&["completions", "tcsh"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
}

#[test]
fn data_paths_stay_in_the_spec_folder_unless_allowed_and_errors_never_quote_the_file() {
    let dir = scratch("robustness-data-paths");
    let (specs, shared) = (dir.join("specs"), dir.join("shared"));
    std::fs::create_dir_all(&specs).unwrap();
    std::fs::create_dir_all(&shared).unwrap();
    std::fs::write(shared.join("data.csv"), "theta,SECRET_TOKEN=1\n0,1\n").unwrap();
    std::os::unix::fs::symlink(shared.join("data.csv"), specs.join("link.csv")).unwrap();
    let fifo = Command::new("mkfifo")
        .arg(specs.join("fifo.csv"))
        .status()
        .unwrap();
    assert!(fifo.success());
    let spec = |name: &str, path: &str| {
        let file = specs.join(format!("{name}.json"));
        std::fs::write(
            &file,
            format!(
                r#"{{"id": "{name}", "panels": [{{"curves": [{{"data": "csv", "path": "{path}", "y": "SECRET_TOKEN=1"}}]}}]}}"#
            ),
        )
        .unwrap();
        file
    };
    let out = dir.join("out");
    let render = |spec: &Path, extra: &[&str]| {
        let mut args = vec![
            "render",
            spec.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--format",
            "csv",
        ];
        args.extend(extra);
        ndfplot(&args)
    };
    for (name, path, message) in [
        ("parent", "../shared/data.csv", "leaves the spec's folder"),
        (
            "link",
            "link.csv",
            "leaves the spec's folder through a symbolic link",
        ),
        ("fifo", "fifo.csv", "not a regular file"),
    ] {
        let file = spec(name, path);
        let result = render(&file, &[]);
        let err = text(&result.stderr);
        assert_eq!(result.status.code(), Some(2), "{name}: {err}");
        assert!(
            err.starts_with(&format!(
                "error: {}: panels[0].curves[0].path: cannot read \"{path}\": {message}",
                file.display()
            )),
            "{name}: {err}"
        );
    }
    // The folder given with --allow-read opens to both the relative path and the link.
    let allow = ["--allow-read", shared.to_str().unwrap()];
    for name in ["parent", "link"] {
        let result = render(&specs.join(format!("{name}.json")), &allow);
        assert_eq!(result.status.code(), Some(0), "{}", text(&result.stderr));
    }

    // compare's operand: an inline series resolves against the working directory.
    let compare = |a: &str, extra: &[&str]| {
        let mut args = vec![
            "compare",
            "--a",
            a,
            "--b",
            r#"{"ndf": "ggx", "alpha_tr": 0.3}"#,
        ];
        args.extend(extra);
        Command::new(env!("CARGO_BIN_EXE_ndfplot"))
            .args(&args)
            .current_dir(&specs)
            .env_clear()
            .env("A_CANARY", "do-not-print".repeat(100))
            .output()
            .unwrap()
    };
    let result = compare(
        r#"{"data": "csv", "path": "/proc/self/environ", "y": "x"}"#,
        &[],
    );
    let err = text(&result.stderr);
    assert_eq!(result.status.code(), Some(2), "{err}");
    assert!(
        err.contains("leaves the spec's folder") && !err.contains("do-not-print"),
        "{err}"
    );
    let result = compare(
        r#"{"data": "csv", "path": "/proc/self/environ", "y": "x"}"#,
        &["--allow-read", "/proc/self"],
    );
    let err = text(&result.stderr);
    assert_eq!(result.status.code(), Some(2), "{err}");
    // Allowed, the file is read, and the message quotes a bounded excerpt of its header only.
    assert!(err.lines().count() == 1 && err.len() < 300, "{err}");
    let result = compare(
        r#"{"data": "csv", "path": "../shared/data.csv", "y": "SECRET_TOKEN=1"}"#,
        &[],
    );
    assert_eq!(result.status.code(), Some(2));
    assert!(text(&result.stderr).contains("leaves the spec's folder"));
}

#[test]
fn render_check_catches_a_change_of_the_drawing_alone() {
    let dir = scratch("robustness-check-drawing");
    let spec = dir.join("spec.json");
    let titled = SPEC.replace(
        r#""id": "checked","#,
        r#""id": "checked", "title": "Before","#,
    );
    std::fs::write(&spec, &titled).unwrap();
    let plots = dir.join("plots");
    crate::common::render_into(&[&spec], &plots, "svg,csv");
    assert_eq!(check(&spec, &plots, &[]).status.code(), Some(0));
    for (from, to) in [
        ("Before", "After"),
        (r#""f0": 0.04}"#, r##""f0": 0.04, "colour": "#DC322F"}"##),
        (
            r#""id": "checked","#,
            r#""id": "checked", "theme": "dark","#,
        ),
    ] {
        std::fs::write(&spec, titled.replace(from, to)).unwrap();
        let out = check(&spec, &plots, &[]);
        let report = text(&out.stdout);
        assert_eq!(
            out.status.code(),
            Some(1),
            "{to}: {report}{}",
            text(&out.stderr)
        );
        assert!(
            report.starts_with("checked.svg: the drawing differs though every value matches")
                && report.contains("1 figure differs")
                && report.contains("0 in their values")
                && report.contains("1 in their drawing only"),
            "{to}: {report}"
        );
    }
}

/// Waits for `child` at most `limit`; kills it and fails when it runs longer.
fn finish_within(mut child: std::process::Child, limit: Duration, what: &str) -> Output {
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > limit {
            child.kill().unwrap();
            child.wait().unwrap();
            panic!("{what} still running after {limit:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

#[test]
fn a_fifo_spec_a_full_stderr_and_an_unwritable_bench_folder_fail_at_once() {
    let dir = scratch("robustness-fail-fast");
    let run = |args: &[&str], stderr: Stdio| {
        Command::new(env!("CARGO_BIN_EXE_ndfplot"))
            .args(args)
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(stderr)
            .spawn()
            .unwrap()
    };
    let limit = Duration::from_secs(30);

    let fifo = dir.join("spec.json");
    assert!(
        Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap()
            .success()
    );
    let out = dir.join("out");
    let args = [
        "render",
        fifo.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ];
    let result = finish_within(run(&args, Stdio::piped()), limit, "render of a FIFO");
    assert_eq!(result.status.code(), Some(2));
    assert!(
        text(&result.stderr).contains("not a regular file"),
        "{}",
        text(&result.stderr)
    );

    let full = || {
        Stdio::from(
            std::fs::File::options()
                .write(true)
                .open("/dev/full")
                .unwrap(),
        )
    };
    let bad = run(
        &["eval", "--curve", r#"{"ndf": "nope"}"#, "--theta", "0"],
        full(),
    );
    assert_eq!(finish_within(bad, limit, "eval").status.code(), Some(2));
    let fit = [
        "fit",
        "--target",
        r#"{"ndf": "ggx", "alpha_tr": 0.3}"#,
        "--family",
        "beckmann",
    ];
    let result = finish_within(run(&fit, full()), limit, "fit");
    assert_eq!(result.status.code(), Some(0));
    assert!(text(&result.stdout).starts_with(r#"{"ndf":"beckmann""#));

    let file = dir.join("file.txt");
    std::fs::write(&file, "").unwrap();
    let under_a_file = file.join("bench");
    let args = ["bench", "-o", under_a_file.to_str().unwrap()];
    let result = finish_within(run(&args, Stdio::piped()), limit, "bench");
    assert_eq!(result.status.code(), Some(2), "{}", text(&result.stderr));
}

#[test]
fn thousands_of_threads_asked_for_under_a_memory_limit_are_capped_not_a_crash() {
    let out = scratch("robustness-threads");
    let script = format!(
        "ulimit -v 1500000 && RAYON_NUM_THREADS=5000 exec {} render tr-ranges -q -o {}",
        env!("CARGO_BIN_EXE_ndfplot"),
        out.display()
    );
    let result = Command::new("sh").args(["-c", &script]).output().unwrap();
    assert_eq!(result.status.code(), Some(0), "{}", text(&result.stderr));
    assert!(
        text(&result.stderr).contains("RAYON_NUM_THREADS=5000 is more than 64; using 64"),
        "{}",
        text(&result.stderr)
    );
    assert_eq!(
        files_in(&out),
        ["tr-ranges.csv", "tr-ranges.png", "tr-ranges.svg"]
    );
}

#[test]
fn a_spec_with_a_hundred_thousand_problems_prints_the_first_hundred_and_a_count() {
    let dir = scratch("robustness-many-problems");
    let entry = r#"{"ndf": "phong", "alpha_p": -1}"#;
    let curves = vec![entry; 100_000].join(",");
    let spec = dir.join("many.json");
    std::fs::write(
        &spec,
        format!(r#"{{"id": "many", "panels": [{{"curves": [{curves}]}}]}}"#),
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
    let lines: Vec<&str> = stderr.lines().collect();
    assert_eq!(lines.len(), 101, "{}", lines.last().unwrap());
    assert!(lines[99].contains("panels[0].curves[99].alpha_p: out of domain"));
    assert!(
        lines[100].ends_with("many.json: 99900 more problems not shown"),
        "{}",
        lines[100]
    );
}

/// Spec files, `@FILE` arguments and standard input larger than 16 MiB are refused (exit 2, the
/// input named) before they are parsed, and an output is written for none of them.
#[test]
fn inputs_over_the_size_cap_are_refused_by_name() {
    let dir = scratch("robustness-input-cap");
    let big = dir.join("big.json");
    // Valid JSON (one string) one byte over the cap.
    let cap = ndfplot::spec::input::MAX_INPUT_BYTES as usize;
    let mut spec = vec![b'a'; cap - 1];
    spec[0] = b'"';
    spec.push(b'"');
    spec.push(b' ');
    std::fs::write(&big, &spec).unwrap();
    let out = dir.join("out");
    let path = big.to_str().unwrap();
    let at_file = format!("@{path}");
    for (args, stdin, source) in [
        (
            vec!["render", path, "-o", out.to_str().unwrap()],
            None,
            path,
        ),
        (
            vec!["eval", "--curve", at_file.as_str(), "--theta", "0"],
            None,
            path,
        ),
        (
            vec!["eval", "--curve", "-", "--theta", "0"],
            Some(&spec),
            "stdin",
        ),
        (
            vec!["render", "-", "-o", out.to_str().unwrap()],
            Some(&spec),
            "stdin",
        ),
        (vec!["compare", "--pairs", path], None, path),
        (vec!["compare", "--pairs", "-"], Some(&spec), "stdin"),
    ] {
        let result = match stdin {
            Some(bytes) => crate::common::ndfplot_stdin(&args, std::str::from_utf8(bytes).unwrap()),
            None => ndfplot(&args),
        };
        let stderr = text(&result.stderr);
        assert_eq!(result.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(
            stderr.contains(&format!("{source}: input too large")) && stderr.contains("16 MiB"),
            "{args:?}: {stderr}"
        );
    }
    assert!(files_in(&out).is_empty(), "nothing written");
}

/// What a planted link or file must never bring to the output: set in the environment of the
/// checking run (so `/proc/self/environ` holds it) and written in a file outside the checked folder.
const PLANTED: &str = "planted-secret-7f3a";

/// Runs `render SPEC --check PLOTS` with [`PLANTED`] in its environment; fails the test if it runs
/// for more than 30 s (a FIFO in the folder must not block it).
fn check_hostile(spec: &Path, plots: &Path) -> Output {
    let child = Command::new(env!("CARGO_BIN_EXE_ndfplot"))
        .args([
            "render",
            spec.to_str().unwrap(),
            "--check",
            plots.to_str().unwrap(),
        ])
        .env("NDFPLOT_PLANTED", PLANTED)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    finish_within(child, Duration::from_secs(30), "render --check")
}

/// Whether the tests run as root, who alone may create device nodes.
fn is_root() -> bool {
    std::fs::read_to_string("/proc/self/status").is_ok_and(|s| {
        s.lines()
            .any(|l| l.starts_with("Uid:") && l.split_whitespace().nth(1) == Some("0"))
    })
}

#[test]
fn render_check_reads_only_regular_files_in_its_folder_and_names_what_it_refuses() {
    let (spec, plots) = rendered("check-hostile");
    let csv = plots.join("checked.csv");
    let svg = plots.join("checked.svg");
    let outside = plots.parent().unwrap().join("outside.csv");
    std::fs::write(&outside, format!("{PLANTED}\n")).unwrap();
    let passwd_first_line = std::fs::read_to_string("/etc/passwd")
        .ok()
        .and_then(|t| t.lines().next().map(str::to_string));
    let refused = |what: &str, name: &str, needle: &str| {
        let out = check_hostile(&spec, &plots);
        let (stdout, stderr) = (text(&out.stdout), text(&out.stderr));
        assert_eq!(out.status.code(), Some(2), "{what}: {stdout}{stderr}");
        assert!(
            stderr.contains(name) && stderr.contains(needle),
            "{what}: {stderr}"
        );
        let all = stdout + &stderr;
        assert!(!all.contains(PLANTED), "{what}: {all}");
        if let Some(line) = &passwd_first_line {
            assert!(!all.contains(line.as_str()), "{what}: {all}");
        }
    };
    std::fs::rename(&csv, plots.join("kept")).unwrap();
    for target in [
        Path::new("/proc/self/environ"),
        Path::new("/etc/passwd"),
        &outside,
    ] {
        std::os::unix::fs::symlink(target, &csv).unwrap();
        refused(
            &format!("a link to {}", target.display()),
            "checked.csv",
            "symbolic link",
        );
        std::fs::remove_file(&csv).unwrap();
    }
    assert!(Command::new("mkfifo").arg(&csv).status().unwrap().success());
    refused("a FIFO", "checked.csv", "not a regular file");
    std::fs::remove_file(&csv).unwrap();
    std::fs::create_dir(&csv).unwrap();
    refused("a folder", "checked.csv", "not a regular file");
    std::fs::remove_dir(&csv).unwrap();
    if is_root() {
        // /dev/zero's numbers: reading it would never end.
        let made = Command::new("mknod")
            .arg(&csv)
            .args(["c", "1", "5"])
            .status();
        assert!(made.unwrap().success());
        refused("a device", "checked.csv", "not a regular file");
        std::fs::remove_file(&csv).unwrap();
    } else {
        eprintln!("note: not root, so no device node was planted in the checked folder");
    }
    // The stored SVG is read through the same door.
    std::fs::rename(plots.join("kept"), &csv).unwrap();
    std::os::unix::fs::symlink(&outside, &svg).unwrap();
    refused("an SVG linked out", "checked.svg", "symbolic link");
    std::fs::remove_file(&svg).unwrap();
    assert_eq!(check_hostile(&spec, &plots).status.code(), Some(0));
}

#[test]
fn render_check_quotes_stored_text_only_in_short_escaped_excerpts_and_bounds_what_it_reads() {
    let (spec, plots) = rendered("check-echo");
    let csv = plots.join("checked.csv");
    let original = std::fs::read_to_string(&csv).unwrap();
    let long = "L".repeat(500);
    let first_row = original.lines().nth(1).unwrap().to_string();
    let first_curve = first_row.split(",0.0,").next().unwrap().to_string();
    for (what, stored) in [
        (
            "a header",
            format!(
                "panel,series,curve,x,\x1b[2J{long}\n{}",
                &original[original.find('\n').unwrap() + 1..]
            ),
        ),
        (
            "a curve cell",
            original.replacen(&first_curve, &format!("0,0,\x1b]0;owned\x07{long}"), 1),
        ),
        (
            "an index cell",
            original.replacen(
                &first_row,
                &first_row.replacen('0', &format!("\x1b[31m{long}"), 1),
                1,
            ),
        ),
        (
            "a value cell",
            original.replacen(
                &first_row,
                &format!("{first_curve},0.0,\u{202e}\x1b[8m{long}"),
                1,
            ),
        ),
    ] {
        std::fs::write(&csv, &stored).unwrap();
        std::fs::write(plots.join("evil\x1b[2J\u{7}.csv"), "").unwrap();
        let out = check_hostile(&spec, &plots);
        let all = text(&out.stdout) + &text(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{what}: {all}");
        assert!(
            !all.contains(&long)
                && !all.chars().any(|c| c.is_control() && c != '\n')
                && !all.contains('\u{202e}'),
            "{what}: {all:?}"
        );
        assert!(
            all.contains("evil\\u001b[2J\\u0007.csv: extra in"),
            "{what}: {all}"
        );
        assert!(
            all.lines().all(|l| l.chars().count() < 400),
            "{what}: {all}"
        );
    }
    // A stored file far larger than any that could match is a difference, not read.
    std::fs::write(&csv, "").unwrap();
    std::fs::File::options()
        .write(true)
        .open(&csv)
        .unwrap()
        .set_len(64 << 20)
        .unwrap();
    let out = check_hostile(&spec, &plots);
    let stdout = text(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{stdout}{}", text(&out.stderr));
    assert!(
        stdout.contains("checked.csv: stored file too large to match") && stdout.len() < 4096,
        "{}",
        &stdout[..stdout.len().min(4096)]
    );
}

/// Runs the binary with `args` in the working directory `dir`, killed after 60 s.
fn run_in(dir: &Path, args: &[&str]) -> Output {
    let child = Command::new(env!("CARGO_BIN_EXE_ndfplot"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    finish_within(child, Duration::from_secs(60), &args.join(" "))
}

#[test]
fn no_writer_replaces_what_is_not_a_regular_file() {
    use std::os::unix::fs::FileTypeExt;
    let dir = scratch("robustness-special-targets");
    std::fs::write(dir.join("spec.json"), SPEC).unwrap();
    let fifo = |path: &Path| assert!(Command::new("mkfifo").arg(path).status().unwrap().success());
    // Each special file, planted where an output goes; (description, plant, still-there check).
    let mut planted: Vec<(&str, Box<dyn Fn(&Path)>, fn(&std::fs::FileType) -> bool)> = vec![
        ("a FIFO", Box::new(fifo), |t| t.is_fifo()),
        (
            "a folder",
            Box::new(|p: &Path| std::fs::create_dir(p).unwrap()),
            |t| t.is_dir(),
        ),
        (
            "a socket",
            Box::new(|p: &Path| {
                std::mem::forget(std::os::unix::net::UnixListener::bind(p).unwrap())
            }),
            |t| t.is_socket(),
        ),
    ];
    if is_root() {
        planted.push((
            "a character device",
            Box::new(|p: &Path| {
                // /dev/null's numbers.
                let made = Command::new("mknod").arg(p).args(["c", "1", "3"]).status();
                assert!(made.unwrap().success());
            }),
            |t| t.is_char_device(),
        ));
    } else {
        eprintln!("note: not root, so no device node was planted where an output goes");
    }
    for (i, (what, plant, still)) in planted.iter().enumerate() {
        let out_dir = dir.join(format!("out-{i}"));
        std::fs::create_dir(&out_dir).unwrap();
        let cases: [(&str, Vec<String>, &str); 3] = [
            (
                "table.csv",
                ["albedo", "--size", "2", "-o", "OUT/table.csv"]
                    .map(String::from)
                    .to_vec(),
                "-o",
            ),
            (
                "checked.csv",
                ["render", "spec.json", "-o", "OUT", "--format", "svg,csv"]
                    .map(String::from)
                    .to_vec(),
                "-o",
            ),
            (
                "ndfplot-render.1",
                ["man", "--dir", "OUT"].map(String::from).to_vec(),
                "--dir",
            ),
        ];
        for (name, args, flag) in cases {
            let target = out_dir.join(name);
            plant(&target);
            let args: Vec<String> = args
                .iter()
                .map(|a| a.replace("OUT", out_dir.to_str().unwrap()))
                .collect();
            let args: Vec<&str> = args.iter().map(String::as_str).collect();
            let out = run_in(&dir, &args);
            let err = text(&out.stderr);
            assert_eq!(out.status.code(), Some(2), "{what} at {name}: {err}");
            assert!(
                err.contains(&format!(
                    "error: {flag}: {}: not a regular file",
                    target.display()
                )) && err.contains(what),
                "{what} at {name}: {err}"
            );
            let kind = std::fs::symlink_metadata(&target).unwrap().file_type();
            assert!(still(&kind), "{what} at {name} was replaced");
            assert_eq!(
                files_in(&out_dir),
                [name],
                "{what} at {name}: wrote beside it"
            );
            let _ = std::fs::remove_file(&target).or_else(|_| std::fs::remove_dir(&target));
        }
    }
}

#[test]
fn dash_is_standard_output_or_refused_never_a_file_named_dash() {
    let dir = scratch("robustness-dash");
    let out = run_in(&dir, &["albedo", "--size", "2", "-o", "-"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(text(&out.stdout).contains("mu,r,alpha,E,turquin_f0_1"));
    for (args, flag) in [
        (&["man", "--dir", "-"][..], "--dir"),
        (&["bench", "-o", "-"][..], "-o"),
        (&["render", "--check", "-"][..], "--check"),
    ] {
        let out = run_in(&dir, args);
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(
            err.starts_with(&format!("error: {flag}: - is not a folder")),
            "{args:?}: {err}"
        );
        assert!(out.stdout.is_empty(), "{args:?}");
    }
    assert!(files_in(&dir).is_empty(), "wrote {:?}", files_in(&dir));
}

#[test]
fn objects_with_tens_of_thousands_of_keys_report_the_first_problems_and_a_count() {
    // The key check is linear (a hash set of the keys seen): 200 000 keys take seconds where the
    // pairwise check took minutes. That is a measurement, not asserted here; this checks what the
    // messages say at a size a pairwise check would already feel.
    let dir = scratch("robustness-many-keys");
    let n = 20_000;
    let keys: String = (0..n).map(|i| format!(r#","k{i}":0"#)).collect();
    let spec = dir.join("keys.json");
    std::fs::write(
        &spec,
        format!(
            r#"{{"id":"keys"{keys},"panels":[{{"curves":[{{"ndf":"beckmann","alpha_b":0.5{keys},"k7":1}}]}}]}}"#
        ),
    )
    .unwrap();
    let pairs = dir.join("pairs.jsonl");
    std::fs::write(
        &pairs,
        format!(
            r#"{{"a":{{"ndf":"beckmann","alpha_b":0.5}},"b":{{"ndf":"ggx","alpha_tr":0.5}}{keys}}}"#
        ),
    )
    .unwrap();
    let out = run_in(&dir, &["render", "keys.json", "-o", "out"]);
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.starts_with("error: keys.json: k0: unknown key (got 0, expected one of: $schema, id,"),
        "{}",
        &err[..err.len().min(600)]
    );
    assert!(
        err.contains(&format!(
            "keys.json: {} more problems not shown",
            2 * n + 1 - 100
        )),
        "{}",
        &err[err.len().saturating_sub(600)..]
    );
    let out = run_in(&dir, &["compare", "--pairs", "pairs.jsonl"]);
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("pairs.jsonl:1: k0: unknown key for a pair (got 0, expected one of: a, b, target, fit, line, family, residual, metric, status, error)"),
        "{}",
        &err[..err.len().min(600)]
    );
}

#[test]
fn a_leading_utf8_byte_order_mark_is_skipped_on_every_json_input() {
    const BOM: &str = "\u{feff}";
    let dir = scratch("robustness-bom");
    std::fs::write(dir.join("spec.json"), format!("{BOM}{SPEC}")).unwrap();
    let curve = r#"{"ndf": "beckmann", "alpha_b": 0.5}"#;
    std::fs::write(dir.join("curve.json"), format!("{BOM}{curve}\n")).unwrap();
    std::fs::write(
        dir.join("pairs.jsonl"),
        format!("{BOM}{{\"a\": {curve}, \"b\": {curve}}}\n"),
    )
    .unwrap();
    let run = |args: &[&str], stdin: &str| {
        let mut child = Command::new(env!("CARGO_BIN_EXE_ndfplot"))
            .args(args)
            .current_dir(&dir)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        use std::io::Write;
        child
            .stdin
            .take()
            .unwrap()
            .write_all(stdin.as_bytes())
            .unwrap();
        let out = child.wait_with_output().unwrap();
        assert_eq!(
            out.status.code(),
            Some(0),
            "{args:?}: {}",
            text(&out.stderr)
        );
        text(&out.stdout)
    };
    run(&["render", "spec.json", "-o", "out", "--format", "csv"], "");
    run(
        &["render", "-", "-o", "stdin", "--format", "csv"],
        &format!("{BOM}{SPEC}"),
    );
    assert_eq!(
        std::fs::read(dir.join("out/checked.csv")).unwrap(),
        std::fs::read(dir.join("stdin/checked.csv")).unwrap()
    );
    let value = run(&["eval", "--curve", "@curve.json", "--theta", "0"], "");
    assert_eq!(
        value,
        run(
            &["eval", "--curve", "-", "--theta", "0"],
            &format!("{BOM}{curve}\n")
        )
    );
    assert!(
        run(
            &["compare", "--pairs", "pairs.jsonl", "--format", "csv"],
            ""
        )
        .lines()
        .count()
            == 2
    );
    assert!(
        run(
            &["compare", "--pairs", "-", "--format", "csv"],
            &format!("{BOM}{{\"a\": {curve}, \"b\": {curve}}}\n")
        )
        .lines()
        .count()
            == 2
    );
    let fit = run(
        &["fit", "--target", "-", "--family", "ggx", "--format", "csv"],
        &format!("{BOM}{curve}\n"),
    );
    assert!(fit.contains("trowbridge_reitz"), "{fit}");
}

#[test]
fn drawn_text_longer_than_the_cap_is_refused_by_its_path() {
    let dir = scratch("robustness-long-text");
    let spec = dir.join("long.json");
    let long = "x".repeat(ndfplot::spec::scene::reader::MAX_TEXT_CHARS + 1);
    std::fs::write(
        &spec,
        format!(
            r#"{{"id": "long", "title": "{long}", "panels": [{{"curves": [{{"ndf": "ggx", "alpha_tr": 0.3, "label": "{long}"}}]}}]}}"#
        ),
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
    for path in ["title", "panels[0].curves[0].label"] {
        assert!(
            stderr.contains(&format!(
                "{path}: text too long (got 1001 characters, expected at most 1000)"
            )),
            "{path} in {stderr}"
        );
    }
    assert!(!dir.join("out").exists(), "nothing written");
}

/// Integration is budgeted before it starts: a 107-byte spec sweeping 1000 albedo curves (some
/// two million double integrals) and an `eval` of an albedo at 200 000 angles are refused with
/// the cap named, exit 2, nothing written; a scene under the cap renders.
#[test]
fn integration_past_its_budget_is_refused_before_any_is_computed() {
    let dir = scratch("robustness-integral-budget");
    let spec = r#"{"id":"m","panels":[{"curves":[{"ndf":"ggx","alpha_tr":{"linspace":[0.01,1,1000]},"quantity":"albedo"}]}]}"#;
    std::fs::write(dir.join("many.json"), spec).unwrap();
    let out = run_in(&dir, &["render", "many.json", "-o", "out"]);
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("many.json: panels[0]: too much integration in one scene (got 1000 curves")
            && err.contains(&format!(
                "expected at most {}",
                ndfplot::spec::scene::MAX_INTEGRALS
            )),
        "{err}"
    );
    assert!(!dir.join("out").exists(), "wrote {:?}", files_in(&dir));

    let albedo = r#"{"ndf":"ggx","alpha_tr":0.3,"quantity":"albedo"}"#;
    let out = ndfplot(&["eval", "--curve", albedo, "--theta", "0:1:200000"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty(), "no row before the refusal");
    assert!(
        text(&out.stderr)
            .contains("--theta: too much integration (got 200000 angles × 1 albedo curves"),
        "{}",
        text(&out.stderr)
    );

    let few = spec
        .replace("1000]", "3]")
        .replace(r#""id":"m","#, r#""id":"m","sampling":{"uniform":20},"#);
    std::fs::write(dir.join("few.json"), few).unwrap();
    let out = run_in(
        &dir,
        &["render", "few.json", "-o", "out", "--format", "csv"],
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
}

/// Every echo of an input is one excerpt: a 1 MB unknown key, a 10 000-digit number and a raw
/// escape character are quoted in at most 60 characters, escaped; a folder holding no spec is a
/// usage error, not a silent run of nothing.
#[test]
fn messages_quote_long_keys_numbers_and_control_characters_as_short_escaped_excerpts() {
    let dir = scratch("robustness-excerpts");
    let key = "k".repeat(1 << 20);
    std::fs::write(
        dir.join("key.json"),
        format!(r#"{{"id":"x","{key}":1,"panels":[]}}"#),
    )
    .unwrap();
    std::fs::write(
        dir.join("number.json"),
        format!(r#"{{"id":"x","width":{}}}"#, "9".repeat(10_000)),
    )
    .unwrap();
    std::fs::write(dir.join("escape.json"), "{\"id\":\u{1b}[31m}").unwrap();
    for (spec, expected) in [
        (
            "key.json",
            format!("key.json: {}…: unknown key", "k".repeat(60)),
        ),
        (
            "number.json",
            format!("invalid JSON: number {}… is outside", "9".repeat(60)),
        ),
        ("escape.json", r"unexpected character '\u001b'".to_owned()),
    ] {
        let out = run_in(&dir, &["render", spec, "-o", "out"]);
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{spec}");
        assert!(err.len() < 1000, "{spec}: {} bytes of messages", err.len());
        assert!(err.contains(&expected), "{spec}: {err}");
        assert!(
            !err.contains('\u{1b}'),
            "{spec}: a raw escape reached the terminal"
        );
    }
    std::fs::create_dir_all(dir.join("empty")).unwrap();
    let out = run_in(&dir, &["render", "empty", "-o", "out"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).contains("empty: no spec to render (got a folder with no *.json file"),
        "{}",
        text(&out.stderr)
    );
}

/// One JSON Lines reader for every batch input: a line that is not UTF-8 is that line's error,
/// and the lines around it are still answered (`compare --pairs` from a file, with a byte order
/// mark and CRLF line ends).
#[test]
fn a_line_that_is_not_utf8_fails_alone_in_a_json_lines_batch() {
    let dir = scratch("robustness-jsonl-utf8");
    let pair = br#"{"a":{"ndf":"ggx","alpha_tr":0.3},"b":{"ndf":"beckmann","alpha_b":0.3}}"#;
    let mut bytes = b"\xef\xbb\xbf".to_vec();
    bytes.extend_from_slice(pair);
    bytes.extend_from_slice(b"\r\n\xff\xfe not text\r\n");
    bytes.extend_from_slice(pair);
    bytes.extend_from_slice(b"\n");
    std::fs::write(dir.join("pairs.jsonl"), bytes).unwrap();
    let out = run_in(
        &dir,
        &["compare", "--pairs", "pairs.jsonl", "--metric", "max_abs"],
    );
    assert_eq!(out.status.code(), Some(2));
    // One line per pair, the failed one's empty.
    let answered = text(&out.stdout);
    let lines: Vec<&str> = answered.lines().collect();
    assert_eq!(lines.len(), 3, "{answered}");
    assert!(lines[0] == lines[2] && lines[1].is_empty(), "{answered}");
    assert!(
        text(&out.stderr).contains("pairs.jsonl:2: column 1: not UTF-8 text"),
        "{}",
        text(&out.stderr)
    );
}

/// `--check` writes nothing, so an output named with it is refused rather than ignored
/// (`render - -o - --check DIR` printed nothing and compared).
#[test]
fn render_check_refuses_an_output_it_would_ignore() {
    for out in ["-", "elsewhere"] {
        let result = ndfplot(&["render", "tr-vs-phong", "-o", out, "--check", "plots"]);
        assert_eq!(result.status.code(), Some(2), "-o {out}");
        assert!(
            text(&result.stderr).contains("cannot be used with '--check <DIR>'"),
            "{}",
            text(&result.stderr)
        );
        assert!(result.stdout.is_empty());
    }
}
