//! The shape of `src/`: the folders are the stages, and imports run one way.
//!
//! Reads every `crate::` and `super::` path in the code of `src/` (comments skipped), resolves
//! each to the file that defines the module it names, and checks three facts that the section
//! "Layout of the code" of docs/architecture.md states:
//! - no arrow runs upward: a file imports only from its own stage or from stages below it
//!   ([`level`] lists the order);
//! - no circle between files (a folder's `mod.rs` and the files it declares count as one room:
//!   the parent declares and re-exports its children, the children implement its traits);
//! - at most eight files at the top of `src/`.
//!
//! `cargo test --test cli structure -- --nocapture` prints the arrows between stages.

use crate::common::root;
use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::Path;

/// A stage's rank: a file may import from its own rank or a lower one. Inside `model/`, the maths
/// is layered too (special functions below families below masking below what integrates them).
fn level(module: &str) -> (u32, u32) {
    let mut parts = module.split("::");
    let top = parts.next().unwrap_or("");
    let second = parts.next().unwrap_or("");
    match top {
        "problem" | "error" => (0, 0),
        "model" => (
            1,
            match second {
                "math" | "domain" | "grid" | "names" => 0,
                "ndf" | "fresnel" | "transform" => 1,
                "masking" => 2,
                _ => 3,
            },
        ),
        "spec" => (2, 0),
        "pipeline" => (3, 0),
        "output" => (4, 0),
        "render" => (5, 0),
        "cli" => (6, 0),
        "cmd" => (7, 0),
        _ => (8, 0), // lib.rs, main.rs
    }
}

/// Every module of `src/`, by path (`model::ndf::phong`), with its source text.
fn modules() -> BTreeMap<String, String> {
    fn walk(dir: &Path, prefix: &[String], out: &mut BTreeMap<String, String>) {
        let mut entries: Vec<_> = fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
        entries.sort();
        for path in entries {
            let name = path.file_name().unwrap().to_string_lossy().into_owned();
            if path.is_dir() {
                let mut p = prefix.to_vec();
                p.push(name);
                walk(&path, &p, out);
            } else if let Some(stem) = name.strip_suffix(".rs") {
                let mut p = prefix.to_vec();
                if stem != "mod" {
                    p.push(stem.to_string());
                }
                let key = if p.is_empty() {
                    stem.to_string()
                } else {
                    p.join("::")
                };
                out.insert(key, fs::read_to_string(&path).unwrap());
            }
        }
    }
    let mut out = BTreeMap::new();
    walk(&root().join("src"), &[], &mut out);
    out
}

/// The code of a file without its comments (line comments and doc comments; string contents kept).
fn code(text: &str) -> String {
    text.lines()
        .map(|line| match line.find("//") {
            Some(i) if !line[..i].contains('"') => &line[..i],
            _ => line,
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The module paths a file names: `crate::a::b::{c, d::e}` gives `a::b::c`, `a::b::d::e`; `super::x`
/// is made absolute against the file's parent module.
fn named_paths(module: &str, text: &str) -> Vec<String> {
    let ident = |c: char| c.is_alphanumeric() || c == '_';
    let mut out = Vec::new();
    let text = code(text);
    let bytes: Vec<char> = text.chars().collect();
    let mut i = 0;
    while i < bytes.len() {
        let rest: String = bytes[i..bytes.len().min(i + 7)].iter().collect();
        let boundary = i == 0 || !ident(bytes[i - 1]) && bytes[i - 1] != ':';
        let base: Option<(Vec<String>, usize)> = if boundary && rest.starts_with("crate::") {
            Some((Vec::new(), 7))
        } else if boundary && rest.starts_with("super::") {
            let mut own: Vec<String> = module.split("::").map(String::from).collect();
            own.pop();
            Some((own, 7))
        } else {
            None
        };
        let Some((prefix, skip)) = base else {
            i += 1;
            continue;
        };
        i += skip;
        let start = i;
        // the path up to its end, braces included
        let mut depth = 0;
        while i < bytes.len() {
            let c = bytes[i];
            if c == '{' {
                depth += 1;
            } else if c == '}' {
                if depth == 0 {
                    break;
                }
                depth -= 1;
            } else if depth == 0 && !(ident(c) || c == ':') {
                break;
            }
            i += 1;
        }
        let path: String = bytes[start..i].iter().collect();
        expand(&prefix, &path, &mut out);
    }
    out
}

/// Expands one `use` tree (`a::{b, c::d}`) under `prefix` into full paths.
fn expand(prefix: &[String], tree: &str, out: &mut Vec<String>) {
    let tree = tree.trim();
    if let Some(open) = tree.find('{') {
        let head: Vec<String> = tree[..open]
            .trim_end_matches("::")
            .split("::")
            .filter(|s| !s.is_empty())
            .map(String::from)
            .collect();
        let mut base = prefix.to_vec();
        base.extend(head);
        let inner = &tree[open + 1..tree.rfind('}').unwrap_or(tree.len())];
        let mut depth = 0;
        let mut item = String::new();
        for c in inner.chars().chain(std::iter::once(',')) {
            match c {
                '{' => depth += 1,
                '}' => depth -= 1,
                _ => {}
            }
            if c == ',' && depth == 0 {
                let s = item.trim().split(" as ").next().unwrap_or("").to_string();
                if s == "self" {
                    out.push(base.join("::"));
                } else if !s.is_empty() {
                    expand(&base, &s, out);
                }
                item.clear();
            } else {
                item.push(c);
            }
        }
    } else {
        let mut full = prefix.to_vec();
        full.extend(tree.split("::").filter(|s| !s.is_empty()).map(String::from));
        out.push(full.join("::"));
    }
}

/// The module a path lands in: its longest prefix that is a module of `src/`.
fn owner<'a>(path: &str, modules: &'a BTreeMap<String, String>) -> Option<&'a str> {
    let parts: Vec<&str> = path.split("::").collect();
    (1..=parts.len())
        .rev()
        .map(|n| parts[..n].join("::"))
        .find_map(|p| modules.get_key_value(&p).map(|(k, _)| k.as_str()))
}

/// `child` is a file `parent` declares (`model::ndf::phong` of `model::ndf`).
fn declares(parent: &str, child: &str) -> bool {
    child
        .strip_prefix(parent)
        .and_then(|rest| rest.strip_prefix("::"))
        .is_some_and(|rest| !rest.contains("::"))
}

/// Every import arrow between two files, one per (from, to) pair.
fn arrows(modules: &BTreeMap<String, String>) -> BTreeSet<(String, String)> {
    let mut out = BTreeSet::new();
    for (module, text) in modules {
        for path in named_paths(module, text) {
            if let Some(to) = owner(&path, modules) {
                if to != module && !declares(module, to) && !declares(to, module) {
                    out.insert((module.clone(), to.to_string()));
                }
            }
        }
    }
    out
}

#[test]
fn imports_run_one_way_with_no_circles() {
    let modules = modules();
    let arrows = arrows(&modules);
    assert!(
        arrows.len() > 100,
        "the reader found too few imports: {}",
        arrows.len()
    );

    let upward: Vec<_> = arrows
        .iter()
        .filter(|(from, to)| level(to) > level(from))
        .collect();
    assert!(upward.is_empty(), "imports running upward: {upward:#?}");

    // circles: a depth-first search for a back edge
    let mut graph: BTreeMap<&str, Vec<&str>> = BTreeMap::new();
    for (from, to) in &arrows {
        graph.entry(from).or_default().push(to);
    }
    fn visit<'a>(
        node: &'a str,
        graph: &BTreeMap<&'a str, Vec<&'a str>>,
        state: &mut BTreeMap<&'a str, u8>,
        stack: &mut Vec<&'a str>,
    ) -> Option<Vec<String>> {
        state.insert(node, 1);
        stack.push(node);
        for &next in graph.get(node).into_iter().flatten() {
            match state.get(next) {
                Some(1) => {
                    let from = stack.iter().position(|&n| n == next).unwrap();
                    let mut circle: Vec<String> =
                        stack[from..].iter().map(|s| s.to_string()).collect();
                    circle.push(next.to_string());
                    return Some(circle);
                }
                Some(_) => {}
                None => {
                    if let Some(c) = visit(next, graph, state, stack) {
                        return Some(c);
                    }
                }
            }
        }
        stack.pop();
        state.insert(node, 2);
        None
    }
    let mut state = BTreeMap::new();
    for &node in graph.keys() {
        if !state.contains_key(node) {
            let circle = visit(node, &graph, &mut state, &mut Vec::new());
            assert!(
                circle.is_none(),
                "a circle of imports: {}",
                circle.unwrap().join(" → ")
            );
        }
    }

    // the drawing: arrows between stages
    let stage = |m: &str| -> String {
        let mut parts = m.split("::");
        let top = parts.next().unwrap_or("");
        match (top, parts.next()) {
            ("model", Some(sub)) => format!("model/{sub}"),
            (top, Some(_)) => format!("{top}/"),
            (top, None) if modules.keys().any(|k| declares(top, k)) => format!("{top}/"),
            (top, None) => format!("{top}.rs"),
        }
    };
    let mut between: BTreeMap<(String, String), usize> = BTreeMap::new();
    for (from, to) in &arrows {
        let (a, b) = (stage(from), stage(to));
        if a != b {
            *between.entry((a, b)).or_default() += 1;
        }
    }
    println!(
        "{} files, {} file-to-file imports, 0 upward, 0 circles",
        modules.len(),
        arrows.len()
    );
    for ((a, b), n) in &between {
        println!("{a:>18} → {b:<18} {n}");
    }
}

#[test]
fn at_most_eight_files_at_the_top_of_src() {
    let top: Vec<String> = fs::read_dir(root().join("src"))
        .unwrap()
        .map(|e| e.unwrap())
        .filter(|e| e.path().is_file())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    assert!(
        top.len() <= 8,
        "{} files at the top of src/: {top:?}",
        top.len()
    );
}

#[test]
fn the_reader_resolves_grouped_and_relative_paths() {
    let mut out = Vec::new();
    expand(&[], "model::{ndf::Family, fresnel::{self, Ior}}", &mut out);
    assert_eq!(
        out,
        [
            "model::ndf::Family",
            "model::fresnel",
            "model::fresnel::Ior"
        ]
    );
    let paths = named_paths(
        "model::ndf::phong",
        "use super::Distribution; // crate::spec::x\nuse crate::model::math::special::ln_gamma;",
    );
    assert_eq!(
        paths,
        ["model::ndf::Distribution", "model::math::special::ln_gamma"]
    );
}

/// Every document the code cites is in the repository, and every section it cites by name
/// (`docs/maths.md "Fresnel"`) is a heading there.
#[test]
fn cited_documents_and_sections_exist() {
    let mut cited = 0;
    for (module, text) in modules() {
        for (i, _) in text.match_indices("docs/") {
            let rest = &text[i..];
            let name: String = rest
                .chars()
                .take_while(|c| c.is_alphanumeric() || matches!(c, '/' | '.' | '_' | '-'))
                .collect();
            let name = name.trim_end_matches('.');
            if !name.ends_with(".md") {
                continue;
            }
            let doc = fs::read_to_string(root().join(name)).unwrap_or_else(|_| {
                panic!("{module} cites {name}, which is not in the repository")
            });
            cited += 1;
            if let Some(section) = rest[name.len()..].strip_prefix(" \"") {
                let section = &section[..section.find('"').unwrap_or(0)];
                assert!(
                    doc.lines()
                        .any(|l| l.starts_with('#') && l.contains(section)),
                    "{module} cites {name} \"{section}\", which has no such heading"
                );
            }
        }
    }
    assert!(cited > 50, "only {cited} citations found");
}
