//! `ndfplot completions <shell>` and `ndfplot man`: shell completion scripts and the manual pages,
//! generated from the clap definition in [`crate::cli`], so they always match the flags. The pages
//! add what clap does not know: the exit codes (every page) and the scene format (the top page and
//! `render`'s).

use crate::cli::Cli;
use crate::error::{Error, Result};
use crate::output::stdout;
use crate::output::write::write_files;
use clap::CommandFactory;
use clap_complete::Shell;
use std::path::Path;

/// Prints the completion script for `shell`.
pub fn completions(shell: Shell) -> Result<()> {
    let mut script = Vec::new();
    clap_complete::generate(shell, &mut Cli::command(), "ndfplot", &mut script);
    stdout::print(&String::from_utf8_lossy(&script))
}

/// Prints the top manual page (roff), or with `dir` writes every page of [`man_pages`] there.
pub fn man(dir: Option<&Path>) -> Result<()> {
    if let Some(dir) = dir {
        crate::output::write::refuse_dash_folder(
            "--dir",
            dir,
            "without --dir the top page goes to standard output",
        )?;
    }
    let pages = man_pages()?;
    match dir {
        Some(dir) => write_files("--dir", dir, &pages).map(drop),
        None => stdout::print(&String::from_utf8_lossy(&pages[0].1)),
    }
}

/// Every manual page as (file name, roff): `ndfplot.1` first, then `ndfplot-<subcommand>.1` per
/// subcommand in `--help` order. Each has clap's name, synopsis, description, options (and, for the
/// top page, subcommands), the examples, then [`EXIT_STATUS`]; the top page and `render`'s also have
/// [`SCENE_FORMAT`].
pub fn man_pages() -> Result<Vec<(String, Vec<u8>)>> {
    let mut top = Cli::command().disable_help_subcommand(true);
    top.build();
    let subcommands: Vec<clap::Command> = top.get_subcommands().cloned().collect();
    std::iter::once(top)
        .chain(subcommands)
        .map(|command| {
            let with_scene_format = matches!(command.get_name(), "ndfplot" | "render");
            let man = clap_mangen::Man::new(command);
            let mut page = Vec::new();
            render_page(&man, with_scene_format, &mut page)
                .map_err(|e| Error::io(man.get_filename(), e))?;
            Ok((man.get_filename(), page))
        })
        .collect()
}

/// Writes one page: clap's sections, then ndfplot's own.
fn render_page(
    man: &clap_mangen::Man,
    with_scene_format: bool,
    out: &mut Vec<u8>,
) -> std::io::Result<()> {
    // `render` writes the sections clap has for the command (options, subcommands, examples, version).
    man.render(out)?;
    if with_scene_format {
        out.extend_from_slice(section("SCENE FORMAT", SCENE_FORMAT).as_bytes());
    }
    out.extend_from_slice(section("EXIT STATUS", EXIT_STATUS).as_bytes());
    Ok(())
}

/// A roff section: `.SH` title, then each blank-line-separated paragraph as `.PP`, lines starting
/// with two spaces as an indented `.IP` item whose tag ends at the first double space.
fn section(title: &str, text: &str) -> String {
    let mut roff = format!(".SH \"{title}\"\n");
    for paragraph in text.split("\n\n") {
        for line in paragraph.lines() {
            match line
                .strip_prefix("  ")
                .and_then(|item| item.split_once("  "))
            {
                Some((tag, body)) => {
                    roff.push_str(&format!(".TP\n{}\n{}\n", escape(tag), escape(body.trim())));
                }
                None if line == paragraph.lines().next().unwrap_or_default() => {
                    roff.push_str(&format!(".PP\n{}\n", escape(line)));
                }
                None => roff.push_str(&format!("{}\n", escape(line))),
            }
        }
    }
    roff
}

/// Text made safe for roff: backslashes and hyphens escaped, a line starting with `.` or `'`
/// protected so it is not read as a request.
fn escape(text: &str) -> String {
    let escaped = text.replace('\\', "\\e").replace('-', "\\-");
    if escaped.starts_with(['.', '\'']) {
        format!("\\&{escaped}")
    } else {
        escaped
    }
}

/// The exit codes (docs/contracts.md), one `.TP` item each.
const EXIT_STATUS: &str = "\
  0  Success; also when stdout is closed early by the reader (ndfplot eval … | head).
  1  The run worked but a check failed: the check tolerance, compare --max-error, render --check differences (including a missing or extra CSV).
  2  Bad input (spec, curve, theta list, flags), I/O errors, a solver or quadrature that did not converge. Every problem is one line on stderr: the file or argument, the JSON path, what is wrong, the value given and what was expected, with \"did you mean\" for misspelt names.";

/// A summary of the scene format; docs/reference.md and `ndfplot schema` have the whole of it.
const SCENE_FORMAT: &str = "\
A scene is a JSON file; ndfplot show ID prints a catalogue figure's as an example, and ndfplot schema prints the JSON Schema of every key.

  id  Names the output files: ^[a-z0-9][a-z0-9_-]{0,63}$.
  title  The figure title.
  layout  {\"rows\": R, \"cols\": C}; default one row of all panels.
  width, height, aspect_ratio, unit, dpi, font_px, font_pt, png_scale  Figure size and resolution.
  sampling  {\"uniform\": N} or {\"adaptive\": {\"tolerance_px\": t}}.
  theme  notebook, colour-blind or dark.
  panels  A list of panels, each with title, view (cartesian, polar), transform (projected, slope), x and y axes ({\"unit\", \"range\", \"scale\", \"label\", \"ticks\"}), legend, and curves.

A curve names its model and parameters: {\"ndf\": \"beckmann\", \"alpha_b\": 0.5}, {\"fresnel\": \"exact\", \"eta\": 1.5}, a published fit to a MERL material {\"published\": \"bagher2012-sgd\", \"material\": \"gold-metallic-paint\", \"channel\": \"red\"}, a difference {\"difference\": \"minus\" | \"ratio\", \"a\": …, \"b\": …}, a view {\"transform\": \"projected\", \"curve\": …}, or a data series {\"data\": \"csv\", \"path\": …}. A parameter may sweep: a list, {\"range\": [a, b, s]}, {\"linspace\": [a, b, n]}, {\"fit\": {\"target\": …, \"by\": \"peak\"}}; a published fit may list materials and channels. Curves also take style (thick, dashed, dotted), colour (#RRGGBB), width, mark and label.";

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_page_per_subcommand_each_with_exit_codes() {
        let pages = man_pages().unwrap();
        let names: Vec<&str> = pages.iter().map(|(name, _)| name.as_str()).collect();
        assert_eq!(names[0], "ndfplot.1");
        assert!(names.contains(&"ndfplot-render.1") && names.contains(&"ndfplot-eval.1"));
        assert!(!names.contains(&"ndfplot-help.1"));
        for (name, page) in &pages {
            let text = String::from_utf8_lossy(page);
            assert!(text.contains(".SH \"EXIT STATUS\""), "{name}");
            let scene = text.contains(".SH \"SCENE FORMAT\"");
            assert_eq!(
                scene,
                matches!(name.as_str(), "ndfplot.1" | "ndfplot-render.1"),
                "{name}"
            );
        }
    }

    #[test]
    fn roff_escapes_requests_backslashes_and_hyphens() {
        assert_eq!(escape(".x 'y' a-b \\n"), "\\&.x 'y' a\\-b \\en");
        let roff = section("T", "first line\nsecond\n\n  tag  body text");
        assert_eq!(
            roff,
            ".SH \"T\"\n.PP\nfirst line\nsecond\n.TP\ntag\nbody text\n"
        );
    }
}
