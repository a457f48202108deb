//! The documentation's transcripts are what the current binary prints, its examples that name a
//! file are that file, and its links lead somewhere: README.md and every `docs/*.md` alike.
//!
//! The convention the documents follow:
//!
//! - A fenced block tagged ```` ```console ```` is a transcript. Each line starting with `$ ` is a
//!   command; the lines after it, up to the next command or the end of the block, are what the
//!   command prints (standard output and standard error together, in the order written). Every
//!   command of a block runs, in order, in one `sh` whose working directory is a fresh folder that
//!   holds the repository's files (`configs/`, `docs/`, `examples/`, `tests/data/`, … as links;
//!   `plots/` a folder of hard links to the committed outputs, so that commands writing there replace
//!   a link and never the repository's file), with the built binary's folder first on `PATH` and
//!   `LC_ALL=C` (so that `seq` and `printf` write `0.05`, never `0,05`). So `cd`, files a command
//!   writes and files an earlier command of the block wrote behave as on a fresh clone, whichever
//!   document the block is in. Commands write only into that folder itself or `plots/` (the other
//!   folders are the repository's own).
//! - A printed line that ends in a duration, ` in <seconds> s` (the closing line of `render`, `fit`,
//!   `compare --pairs`, `albedo`), matches the document's line whatever the seconds, as long as the
//!   document shows a duration there too.
//! - A fenced block tagged ```` ```json <path> ```` shows the repository's file `<path>` (relative to
//!   the repository's root, whichever document shows it): it must hold the same JSON value.
//! - A link `[text](path)` or `[text](path#anchor)` that is not a URL leads to a file of the
//!   repository, relative to the document, and its anchor to a heading of that file (GitHub's
//!   heading slugs: lower case, punctuation dropped, spaces as hyphens, `-1`, `-2`, … for repeats).
//!
//! What cannot run here offline, quickly and deterministically stays out of `console` blocks and is
//! tagged `sh` (or shown as plain text): `cargo` invocations, `ndfplot bench` and other timings,
//! commands that need tools beyond POSIX `sh` and coreutils, and long runs.

use crate::common::{files_in, render_into, root, scratch};
use std::path::{Path, PathBuf};
use std::process::Command;

/// A fenced block of a document.
struct Block {
    /// The document, relative to the repository's root (`README.md`, `docs/guide.md`).
    file: String,
    /// The info string after the opening fence (`console`, `json configs/x.json`, …).
    info: String,
    /// The 1-based line of the opening fence in its document.
    line: usize,
    /// The block's lines, without the fence's indentation.
    lines: Vec<String>,
}

/// Every fenced block of the document `file`, whose text is `text`, in order. A fence is a line of
/// three backticks, possibly indented (inside a list item); a closing fence is the bare backticks at
/// any indentation.
fn blocks(file: &str, text: &str) -> Vec<Block> {
    let mut blocks = Vec::new();
    let mut open: Option<(usize, Block)> = None;
    for (i, line) in text.lines().enumerate() {
        let trimmed = line.trim_start();
        let indent = line.len() - trimmed.len();
        match open.take() {
            None => {
                if let Some(info) = trimmed.strip_prefix("```") {
                    let block = Block {
                        file: file.to_string(),
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
                    "{file}:{}: a fence with text after it inside the block of line {}",
                    i + 1,
                    block.line
                );
                let cut = indent.min(fence_indent);
                block.lines.push(line[cut..].to_string());
                open = Some((fence_indent, block));
            }
        }
    }
    assert!(open.is_none(), "{file} ends inside a fenced block");
    blocks
}

/// One command of a transcript and what its document says it prints.
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
                "{}:{}: a console block starts with output, not a `$ ` command: {line:?}",
                block.file, block.line
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
const END_OF_COMMAND: &str = "\u{1e}end of a documented command\u{1e}";

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

/// `line` with a closing duration ` in <seconds> s` replaced by ` in … s`.
fn timeless(line: &str) -> std::borrow::Cow<'_, str> {
    let duration = line
        .strip_suffix(" s")
        .and_then(|rest| rest.rsplit_once(" in "))
        .filter(|(_, seconds)| seconds.parse::<f64>().is_ok());
    match duration {
        Some((head, _)) => format!("{head} in … s").into(),
        None => line.into(),
    }
}

/// A line diff of `expected` against `actual` (longest common subsequence): `-` for the document's
/// lines that are not printed, `+` for printed lines the document lacks, two spaces for the lines
/// they share.
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

/// The documents: README.md and every `docs/*.md`, by path relative to the repository's root, in
/// name order.
fn documents() -> Vec<String> {
    let mut docs: Vec<String> = std::fs::read_dir(root().join("docs"))
        .unwrap()
        .map(|entry| entry.unwrap().file_name().into_string().unwrap())
        .filter(|name| name.ends_with(".md"))
        .map(|name| format!("docs/{name}"))
        .collect();
    docs.sort();
    docs.insert(0, "README.md".to_string());
    docs
}

fn read(file: &str) -> String {
    std::fs::read_to_string(root().join(file)).unwrap_or_else(|e| panic!("{file}: {e}"))
}

/// Every fenced block of every document.
fn document_blocks() -> Vec<Block> {
    documents()
        .iter()
        .flat_map(|file| blocks(file, &read(file)))
        .collect()
}

#[test]
fn every_documented_transcript_is_what_the_binary_prints() {
    let console: Vec<Block> = document_blocks()
        .into_iter()
        .filter(|b| b.info == "console")
        .collect();
    for file in ["README.md", "docs/guide.md", "docs/reference.md"] {
        assert!(
            console.iter().any(|b| b.file == file),
            "{file} has console blocks"
        );
    }
    let failures: Vec<String> = std::thread::scope(|scope| {
        let runs: Vec<_> = console
            .iter()
            .map(|block| {
                scope.spawn(move || {
                    let steps = steps(block);
                    let name = block.file.replace('/', "-");
                    let dir = workspace(&format!("transcripts/{name}-{}", block.line));
                    let outputs = run(&steps, &dir);
                    let mut failures = Vec::new();
                    for (k, step) in steps.iter().enumerate() {
                        let actual = outputs.get(k).cloned().unwrap_or_default();
                        let same = actual.len() == step.expected.len()
                            && actual
                                .iter()
                                .zip(&step.expected)
                                .all(|(a, e)| timeless(a) == timeless(e));
                        if !same {
                            failures.push(format!(
                                "{}:{} `$ {}` prints otherwise (- document, + printed):\n{}",
                                block.file,
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
fn every_documented_example_that_names_a_file_is_that_file() {
    let parse = |text: &str, what: &str| -> serde_json::Value {
        serde_json::from_str(text).unwrap_or_else(|e| panic!("{what}: {e}"))
    };
    let mut checked = 0;
    for block in document_blocks() {
        let Some(path) = block.info.strip_prefix("json ") else {
            continue;
        };
        let path = path.trim();
        let at = format!("{}:{}", block.file, block.line);
        let file = std::fs::read_to_string(root().join(path))
            .unwrap_or_else(|e| panic!("{at} names {path}: {e}"));
        let shown = parse(&block.lines.join("\n"), &at);
        assert_eq!(shown, parse(&file, path), "{at} is not {path}");
        checked += 1;
    }
    assert!(checked > 0, "the documents show files of the repository");
}

/// The text of `markdown` outside fenced blocks and inline code spans, line by line (code is blanked,
/// so line numbers stay those of the document).
fn prose(markdown: &str) -> Vec<String> {
    let mut fenced = false;
    markdown
        .lines()
        .map(|line| {
            if line.trim_start().starts_with("```") {
                fenced = !fenced;
                return String::new();
            }
            if fenced {
                return String::new();
            }
            // Inline code: text between backtick runs of equal length.
            let mut out = String::new();
            let mut rest = line;
            while let Some(start) = rest.find('`') {
                out.push_str(&rest[..start]);
                let ticks = rest[start..].chars().take_while(|&c| c == '`').count();
                let after = &rest[start + ticks..];
                let fence = "`".repeat(ticks);
                match after.find(&fence) {
                    Some(end) => rest = &after[end + ticks..],
                    None => {
                        rest = after;
                        break;
                    }
                }
            }
            out.push_str(rest);
            out
        })
        .collect()
}

/// GitHub's anchor of a heading's text: lower case, every character but letters, digits, `_`, `-`
/// and spaces dropped, spaces as hyphens.
fn slug(heading: &str) -> String {
    heading
        .to_lowercase()
        .chars()
        .filter(|&c| c.is_alphanumeric() || matches!(c, '_' | '-' | ' '))
        .map(|c| if c == ' ' { '-' } else { c })
        .collect()
}

/// The anchors of a document's headings (outside fenced blocks), with `-1`, `-2`, … for repeats.
fn anchors(markdown: &str) -> Vec<String> {
    let mut seen: Vec<String> = Vec::new();
    let mut out = Vec::new();
    let mut fenced = false;
    for line in markdown.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if fenced || !line.starts_with('#') {
            continue;
        }
        let level = line.chars().take_while(|&c| c == '#').count();
        let Some(text) = line[level..].strip_prefix(' ') else {
            continue;
        };
        // A heading's link text counts, its target does not.
        let mut plain = String::new();
        let mut rest = text.trim();
        while let Some(open) = rest.find("](") {
            plain.push_str(&rest[..open]);
            rest = &rest[open + 2..];
            rest = &rest[rest.find(')').map_or(rest.len(), |close| close + 1)..];
        }
        plain.push_str(rest);
        let base = slug(&plain.replace('[', ""));
        let repeats = seen.iter().filter(|s| **s == base).count();
        out.push(if repeats == 0 {
            base.clone()
        } else {
            format!("{base}-{repeats}")
        });
        seen.push(base);
    }
    out
}

/// The targets of the links and images of `markdown`'s prose, with their 1-based line:
/// `[text](target)`, `![alt](target)`, a title after the target dropped.
fn links(markdown: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    for (i, line) in prose(markdown).iter().enumerate() {
        let mut rest = line.as_str();
        while let Some(open) = rest.find("](") {
            rest = &rest[open + 2..];
            let end = rest.find(')').unwrap_or(rest.len());
            let target = rest[..end].split_whitespace().next().unwrap_or("");
            out.push((i + 1, target.to_string()));
            rest = &rest[end..];
        }
    }
    out
}

#[test]
fn every_local_link_of_the_documents_leads_to_a_file_and_heading() {
    let mut problems = Vec::new();
    let mut checked = 0;
    for file in documents() {
        let text = read(&file);
        let folder = Path::new(&file).parent().unwrap_or(Path::new(""));
        for (line, target) in links(&text) {
            if target.contains("://") || target.starts_with("mailto:") {
                continue;
            }
            let (path, anchor) = match target.split_once('#') {
                Some((path, anchor)) => (path, Some(anchor)),
                None => (target.as_str(), None),
            };
            let at = format!("{file}:{line}: ({target})");
            let resolved = if path.is_empty() {
                root().join(&file)
            } else {
                root().join(folder).join(path)
            };
            if !resolved.exists() {
                problems.push(format!("{at}: no file {}", resolved.display()));
                continue;
            }
            checked += 1;
            let Some(anchor) = anchor else { continue };
            let is_markdown = resolved.extension().is_some_and(|e| e == "md");
            if !is_markdown {
                problems.push(format!("{at}: an anchor into a file that is not Markdown"));
                continue;
            }
            let target_text = std::fs::read_to_string(&resolved).unwrap();
            if !anchors(&target_text).iter().any(|a| a == anchor) {
                problems.push(format!("{at}: no heading with the anchor #{anchor}"));
            }
        }
    }
    assert!(problems.is_empty(), "\n{}", problems.join("\n"));
    assert!(checked > 100, "only {checked} links found");
}

/// Every figure the documents show from `docs/img/` is what its spec in `docs/examples/` (same id)
/// draws now: the committed SVG byte for byte (the PNG beside it is that SVG rasterized).
#[test]
fn every_documented_figure_is_what_its_spec_draws() {
    let out = scratch("documented-figures");
    let mut checked = 0;
    for name in files_in(&root().join("docs/img")) {
        let Some(id) = name.strip_suffix(".svg") else {
            continue;
        };
        let spec = root().join(format!("docs/examples/{id}.json"));
        assert!(
            spec.is_file(),
            "docs/img/{name} has no spec docs/examples/{id}.json"
        );
        render_into(&[&spec], &out, "svg");
        let drawn = std::fs::read(out.join(&name)).unwrap();
        let committed = std::fs::read(root().join("docs/img").join(&name)).unwrap();
        assert!(
            drawn == committed,
            "docs/img/{name} is not what docs/examples/{id}.json draws now: \
             ndfplot render docs/examples/{id}.json -o docs/img --format svg,png"
        );
        checked += 1;
    }
    assert!(checked > 0, "the documents show figures from docs/img/");
}

#[test]
fn readme_stays_under_forty_kilobytes() {
    let size = std::fs::metadata(root().join("README.md")).unwrap().len();
    assert!(
        size < 40_000,
        "README.md has {size} bytes: move detail into docs/ (expected under 40 000)"
    );
}

#[test]
fn anchors_are_github_heading_slugs() {
    let doc = "# Speed and accuracy: `ndfplot bench`\n\
               ## Masking–shadowing and albedo\n\
               ```\n# table: e\n```\n\
               ### Smith masking and Λ\n\
               ## Usage\n## Usage\n\
               ## See [the guide](guide.md)\n";
    assert_eq!(
        anchors(doc),
        [
            "speed-and-accuracy-ndfplot-bench",
            "maskingshadowing-and-albedo",
            "smith-masking-and-λ",
            "usage",
            "usage-1",
            "see-the-guide"
        ]
    );
    assert_eq!(
        links("[![a](x.png)](x.svg) `[c](not.md)` [d](y.md#z \"title\")\n```\n[e](code.md)\n```"),
        [
            (1, "x.png".to_string()),
            (1, "x.svg".to_string()),
            (1, "y.md#z".to_string())
        ]
    );
}

#[test]
fn a_closing_duration_matches_any_seconds() {
    assert_eq!(
        timeless("fit: 5 targets fitted, written to stdout in 0.41 s"),
        timeless("fit: 5 targets fitted, written to stdout in 12.30 s")
    );
    assert_ne!(
        timeless("fit: 5 targets fitted in 0.41 s"),
        timeless("fit: 6 targets fitted in 0.41 s")
    );
    assert_eq!(timeless("D in s"), "D in s");
}

#[test]
fn the_diff_marks_missing_and_extra_lines() {
    let lines = |s: &str| s.lines().map(String::from).collect::<Vec<_>>();
    assert_eq!(
        diff(&lines("a\nb\nc"), &lines("a\nx\nc\nd")),
        "  a\n+ x\n- b\n  c\n+ d\n"
    );
}
