//! `ndfplot render`: the command line's options to one [`crate::render`] call (files, `--check`, or
//! `-o -` to standard output).

use crate::cli::RenderArgs;
use crate::error::{Error, Result};
use crate::output::Format;
use crate::output::stderr;
use crate::render::{self, RenderOptions, RenderStats};
use crate::spec::source::CanvasOverride;

/// Runs `ndfplot render` (or `render --check DIR`, or `render -o -` to stdout) with the parsed
/// `args`; `quiet` turns the progress bar and the closing line off. The figure lint's warnings go
/// to stderr, then `-v`'s line per figure and the closing line (how many figures, what was written
/// where, how long); `--strict` turns any warning into exit 1.
pub fn run(args: RenderArgs, quiet: bool) -> Result<()> {
    let options = RenderOptions {
        paths: args.paths,
        out: args.out,
        formats: Format::parse_list(&args.format)?,
        canvas: CanvasOverride {
            width: args.width,
            height: args.height,
            png_scale: args.png_scale,
            font_px: args.font_px,
            theme: args.theme.as_deref().map(crate::spec::scene::theme_named),
            preset: args
                .preset
                .as_deref()
                .and_then(crate::spec::look::Preset::named),
        },
        allow_read: args.allow_read,
    };
    let started = std::time::Instant::now();
    let shown =
        |path: &std::path::Path| crate::problem::one_line(&path.display().to_string()).into_owned();
    let (result, stats, done) = match &args.check {
        Some(dir) => {
            crate::output::write::refuse_dash_folder(
                "--check",
                dir,
                "render --check compares with the files of a folder",
            )?;
            match render::check(&options, dir, args.tolerance, quiet) {
                Ok(stats) => {
                    let done = format!(" compared with {}", shown(dir));
                    (Ok(()), stats, done)
                }
                Err(e) => (Err(e), RenderStats::default(), String::new()),
            }
        }
        None if options.out.as_os_str() == "-" => match render::to_stdout(&options, quiet) {
            Ok((bytes, stats)) => (
                crate::output::stdout::write_bytes(&bytes),
                stats,
                " written to stdout".to_string(),
            ),
            Err(e) => (Err(e), RenderStats::default(), String::new()),
        },
        None => match render::run_with_progress(&options, quiet) {
            Ok((written, stats)) => {
                let done = format!(
                    ", {} written to {}",
                    files(&written, &stats),
                    shown(&options.out)
                );
                (Ok(()), stats, done)
            }
            Err(e) => (Err(e), RenderStats::default(), String::new()),
        },
    };
    // Warnings are printed under -q too: they are about the figures, not the run's progress.
    for warning in &stats.warnings {
        stderr::warning(warning);
    }
    result?;
    for figure in &stats.figures {
        stderr::detail(&figure.line());
    }
    let warnings = &stats.warnings;
    let counted = match warnings.len() {
        0 => String::new(),
        1 => " (1 warning)".to_string(),
        n => format!(" ({n} warnings)"),
    };
    let figures = match stats.scenes {
        1 => "1 figure".to_string(),
        n => format!("{n} figures"),
    };
    stderr::summary(quiet, &format!("render: {figures}{counted}{done}"), started);
    if args.strict && !warnings.is_empty() {
        return Err(Error::CheckFailed(format!(
            "error: render --strict: the figure lint gave {} warning{}",
            warnings.len(),
            if warnings.len() == 1 { "" } else { "s" }
        )));
    }
    Ok(())
}

/// The files of a run in words: `192 files (48 csv, 48 pdf, 48 png, 48 svg)`.
fn files(written: &[std::path::PathBuf], stats: &RenderStats) -> String {
    let formats: Vec<String> = stats
        .produced
        .iter()
        .map(|(format, n)| format!("{n} {}", format.extension()))
        .collect();
    let count = match written.len() {
        1 => "1 file".to_string(),
        n => format!("{n} files"),
    };
    format!("{count} ({})", formats.join(", "))
}
