//! README's transcripts are what the current binary prints, and its examples that name a file are
//! that file.
//!
//! The convention README follows:
//!
//! - A fenced block tagged ```` ```console ```` is a transcript. Each line starting with `$ ` is a
//!   command; the lines after it, up to the next command or the end of the block, are what the
//!   command prints (standard output and standard error together, in the order written). Every
//!   command of a block runs, in order, in one `sh` whose working directory is a fresh folder that
//!   holds the repository's files (`configs/`, `examples/`, `tests/data/`, … as links; `plots/` a
//!   folder of hard links to the committed outputs, so that commands writing there replace a link and
//!   never the repository's file), with the built binary's folder first on `PATH` and `LC_ALL=C`
//!   (so that `seq` and `printf` write `0.05`, never `0,05`). So `cd`, files a command writes and
//!   files an earlier command of the block wrote behave as on a fresh clone. Commands write only into
//!   that folder itself or `plots/` (the other folders are the repository's own).
//! - A fenced block tagged ```` ```json <path> ```` shows the repository's file `<path>`: it must hold
//!   the same JSON value.
//!
//! What cannot run here offline, quickly and deterministically stays out of `console` blocks and is
//! tagged `sh` (or shown as plain text): `cargo` invocations, `ndfplot bench` and other timings,
//! commands that need tools beyond POSIX `sh` and coreutils, and long runs.

use crate::common::{root, scratch};
use std::path::{Path, PathBuf};
use std::process::Command;

/// A fenced block of README.md.
struct Block {
    /// The info string after the opening fence (`console`, `json configs/x.json`, …).
    info: String,
    /// The 1-based README line of the opening fence.
    line: usize,
    /// The block's lines, without the fence's indentation.
    lines: Vec<String>,
}

/// Every fenced block of `readme`, in order. A fence is a line of three backticks, possibly indented
/// (inside a list item); a closing fence is the bare backticks at any indentation.
fn blocks(readme: &str) -> Vec<Block> {
    let mut blocks = Vec::new();
    let mut open: Option<(usize, Block)> = None;
    for (i, line) in readme.lines().enumerate() {
        let trimmed = line.trim_start();
        let indent = line.len() - trimmed.len();
        match open.take() {
            None => {
                if let Some(info) = trimmed.strip_prefix("```") {
                    let block = Block {
                        info: info.trim().to_string(),
                        line: i + 1,
                        lines: Vec::new(),
                    };
                    open = Some((indent, block));
                }
            }
            Some((_, block)) if trimmed == "```" => blocks.push(block),
            Some((fence_indent, mut block)) => {
                assert!(
                    !trimmed.starts_with("```"),
                    "README.md:{}: a fence with text after it inside the block of line {}",
                    i + 1,
                    block.line
                );
                let cut = indent.min(fence_indent);
                block.lines.push(line[cut..].to_string());
                open = Some((fence_indent, block));
            }
        }
    }
    assert!(open.is_none(), "README.md ends inside a fenced block");
    blocks
}

/// One command of a transcript and what README says it prints.
struct Step {
    command: String,
    expected: Vec<String>,
}

/// The commands of a `console` block with their expected output.
fn steps(block: &Block) -> Vec<Step> {
    let mut steps: Vec<Step> = Vec::new();
    for line in &block.lines {
        match (line.strip_prefix("$ "), steps.last_mut()) {
            (Some(command), _) => steps.push(Step {
                command: command.to_string(),
                expected: Vec::new(),
            }),
            (None, Some(step)) => step.expected.push(line.clone()),
            (None, None) => panic!(
                "README.md:{}: a console block starts with output, not a `$ ` command: {line:?}",
                block.line
            ),
        }
    }
    steps
}

/// A fresh folder holding links to the repository's files: one per top-level entry but `.git`,
/// `target` and `plots`, and `plots/` a real folder of hard links to the committed outputs.
fn workspace(name: &str) -> PathBuf {
    let dir = scratch(name);
    let link = |from: &Path, to: &Path| std::os::unix::fs::symlink(from, to).unwrap();
    for entry in std::fs::read_dir(root()).unwrap() {
        let entry = entry.unwrap();
        let name = entry.file_name();
        if name == ".git" || name == "target" {
            continue;
        }
        if name == "plots" {
            std::fs::create_dir(dir.join("plots")).unwrap();
            // Hard links (copies across file systems), as `render --check plots` reads no
            // symbolic link; a command writing there renames over the link, never into the file.
            for output in std::fs::read_dir(entry.path()).unwrap() {
                let output = output.unwrap();
                let to = dir.join("plots").join(output.file_name());
                if output.file_type().unwrap().is_file() {
                    if std::fs::hard_link(output.path(), &to).is_err() {
                        std::fs::copy(output.path(), &to).unwrap();
                    }
                } else {
                    link(&output.path(), &to);
                }
            }
        } else {
            link(&entry.path(), &dir.join(&name));
        }
    }
    dir
}

/// The line that separates the outputs of two commands in a block's combined output.
const END_OF_COMMAND: &str = "\u{1e}end of README command\u{1e}";

/// Runs the commands of a block in order in one `sh` in `dir` (standard error into standard output)
/// and returns each one's output lines.
fn run(steps: &[Step], dir: &Path) -> Vec<Vec<String>> {
    let mut script = String::from("exec 2>&1\n");
    for step in steps {
        script.push_str(&step.command);
        script.push_str(&format!("\nprintf '\\n%s\\n' '{END_OF_COMMAND}'\n"));
    }
    let binary = Path::new(env!("CARGO_BIN_EXE_ndfplot")).parent().unwrap();
    let path = std::env::join_paths(std::iter::once(binary.to_path_buf()).chain(
        std::env::split_paths(&std::env::var_os("PATH").unwrap_or_default()),
    ))
    .unwrap();
    let output = Command::new("sh")
        .args(["-c", &script])
        .current_dir(dir)
        .env("PATH", path)
        .env("LC_ALL", "C")
        .output()
        .expect("sh runs");
    let text = String::from_utf8_lossy(&output.stdout);
    let mut outputs: Vec<Vec<String>> = text
        .split(&format!("\n{END_OF_COMMAND}\n"))
        .map(|out| out.lines().map(str::to_string).collect())
        .collect();
    outputs.truncate(steps.len());
    outputs
}

/// A line diff of `expected` against `actual` (longest common subsequence): `-` for README's lines
/// that are not printed, `+` for printed lines README lacks, two spaces for the lines they share.
fn diff(expected: &[String], actual: &[String]) -> String {
    let (n, m) = (expected.len(), actual.len());
    let mut common = vec![vec![0usize; m + 1]; n + 1];
    for i in (0..n).rev() {
        for j in (0..m).rev() {
            common[i][j] = if expected[i] == actual[j] {
                common[i + 1][j + 1] + 1
            } else {
                common[i + 1][j].max(common[i][j + 1])
            };
        }
    }
    let (mut i, mut j, mut out) = (0, 0, String::new());
    while i < n || j < m {
        if i < n && j < m && expected[i] == actual[j] {
            out.push_str(&format!("  {}\n", expected[i]));
            (i, j) = (i + 1, j + 1);
        } else if j < m && (i == n || common[i][j + 1] >= common[i + 1][j]) {
            out.push_str(&format!("+ {}\n", actual[j]));
            j += 1;
        } else {
            out.push_str(&format!("- {}\n", expected[i]));
            i += 1;
        }
    }
    out
}

fn readme_blocks() -> Vec<Block> {
    blocks(&std::fs::read_to_string(root().join("README.md")).unwrap())
}

#[test]
fn every_readme_transcript_is_what_the_binary_prints() {
    let console: Vec<Block> = readme_blocks()
        .into_iter()
        .filter(|b| b.info == "console")
        .collect();
    assert!(!console.is_empty(), "README.md has console blocks");
    let failures: Vec<String> = std::thread::scope(|scope| {
        let runs: Vec<_> = console
            .iter()
            .map(|block| {
                scope.spawn(move || {
                    let steps = steps(block);
                    let dir = workspace(&format!("readme/{}", block.line));
                    let outputs = run(&steps, &dir);
                    let mut failures = Vec::new();
                    for (k, step) in steps.iter().enumerate() {
                        let actual = outputs.get(k).cloned().unwrap_or_default();
                        if actual != step.expected {
                            failures.push(format!(
                                "README.md:{} `$ {}` prints otherwise (- README, + printed):\n{}",
                                block.line,
                                step.command,
                                diff(&step.expected, &actual)
                            ));
                        }
                    }
                    failures
                })
            })
            .collect();
        runs.into_iter()
            .flat_map(|run| run.join().unwrap())
            .collect()
    });
    assert!(failures.is_empty(), "\n{}", failures.join("\n"));
}

#[test]
fn every_readme_example_that_names_a_file_is_that_file() {
    let parse = |text: &str, what: &str| -> serde_json::Value {
        serde_json::from_str(text).unwrap_or_else(|e| panic!("{what}: {e}"))
    };
    let mut checked = 0;
    for block in readme_blocks() {
        let Some(path) = block.info.strip_prefix("json ") else {
            continue;
        };
        let file = std::fs::read_to_string(root().join(path.trim()))
            .unwrap_or_else(|e| panic!("README.md:{} names {path}: {e}", block.line));
        let shown = parse(
            &block.lines.join("\n"),
            &format!("README.md:{}", block.line),
        );
        assert_eq!(
            shown,
            parse(&file, path),
            "README.md:{} is not {path}",
            block.line
        );
        checked += 1;
    }
    assert!(checked > 0, "README.md shows files of the repository");
}

#[test]
fn the_diff_marks_missing_and_extra_lines() {
    let lines = |s: &str| s.lines().map(String::from).collect::<Vec<_>>();
    assert_eq!(
        diff(&lines("a\nb\nc"), &lines("a\nx\nc\nd")),
        "  a\n+ x\n- b\n  c\n+ d\n"
    );
}
