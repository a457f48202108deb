//! `ndfplot man --dir DIR`: one page per subcommand, each rendered by `man -l` where `man` exists.

use crate::common::{ndfplot, scratch, text};
use std::process::Command;

#[test]
fn man_pages_render_with_their_options_and_exit_codes() {
    let dir = scratch("man-pages");
    let out = ndfplot(&["man", "--dir", dir.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let pages = [
        (
            "ndfplot.1",
            &[
                "render",
                "eval",
                "albedo",
                "EXIT STATUS",
                "SCENE FORMAT",
                "published",
            ][..],
        ),
        (
            "ndfplot-render.1",
            &[
                "--format",
                "--check",
                "--out",
                "SCENE FORMAT",
                "EXIT STATUS",
            ][..],
        ),
        (
            "ndfplot-eval.1",
            &["--curve", "--theta", "--degrees", "EXIT STATUS"][..],
        ),
        (
            "ndfplot-fit.1",
            &["--target", "--family", "--by", "EXIT STATUS"][..],
        ),
        (
            "ndfplot-albedo.1",
            &["--table", "--fresnel", "--map", "split-sum", "EXIT STATUS"][..],
        ),
        ("ndfplot-man.1", &["--dir", "EXIT STATUS"][..]),
    ];
    let man_available = Command::new("man")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    if !man_available {
        println!("man is not installed: checking the roff source only");
    }
    for (name, expected) in pages {
        let path = dir.join(name);
        let shown = if man_available {
            let rendered = Command::new("man")
                .arg("-l")
                .arg(&path)
                .env("MANWIDTH", "100")
                .env("MANPAGER", "cat")
                .env("PAGER", "cat")
                .output()
                .unwrap();
            assert!(
                rendered.status.success(),
                "{name}: {}",
                text(&rendered.stderr)
            );
            // man shows hyphens and quotes with their typographic forms on some terminals.
            String::from_utf8_lossy(&rendered.stdout).replace(['‐', '−'], "-")
        } else {
            std::fs::read_to_string(&path).unwrap().replace("\\-", "-")
        };
        assert!(!shown.trim().is_empty(), "{name} is empty");
        for word in expected {
            assert!(shown.contains(word), "{name} lacks {word}:\n{shown}");
        }
    }
    // Markdown does not render in a man page: no literal backticks on any page.
    for page in std::fs::read_dir(&dir).unwrap() {
        let page = page.unwrap().path();
        let roff = std::fs::read_to_string(&page).unwrap();
        assert!(!roff.contains('`'), "{} shows a backtick", page.display());
    }
    let printed = ndfplot(&["man"]);
    assert_eq!(
        printed.stdout,
        std::fs::read(dir.join("ndfplot.1")).unwrap()
    );
}
