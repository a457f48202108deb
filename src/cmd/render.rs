//! `ndfplot render`: the command line's options to one [`crate::render`] call (files, `--check`, or
//! `-o -` to standard output).

use crate::cli::RenderArgs;
use crate::error::{Error, Result};
use crate::output::Format;
use crate::render::{self, RenderOptions};
use crate::spec::source::CanvasOverride;

/// Runs `ndfplot render` (or `render --check DIR`, or `render -o -` to stdout) with the parsed
/// `args`; `quiet` turns the progress bar off. The figure lint's warnings go to stderr, and
/// `--strict` turns any into exit 1.
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
    let (result, warnings) = match &args.check {
        Some(dir) => {
            crate::output::write::refuse_dash_folder(
                "--check",
                dir,
                "render --check compares with the files of a folder",
            )?;
            match render::check(&options, dir, args.tolerance, quiet) {
                Ok(warnings) => (Ok(()), warnings),
                Err(e) => (Err(e), Vec::new()),
            }
        }
        None if options.out.as_os_str() == "-" => match render::to_stdout(&options, quiet) {
            Ok((bytes, warnings)) => (crate::output::stdout::write_bytes(&bytes), warnings),
            Err(e) => (Err(e), Vec::new()),
        },
        None => match render::run_with_progress(&options, quiet) {
            Ok((_, stats)) => (Ok(()), stats.warnings),
            Err(e) => (Err(e), Vec::new()),
        },
    };
    // Warnings are printed under -q too: they are about the figures, not the run's progress.
    for warning in &warnings {
        eprintln!("warning: {warning}");
    }
    result?;
    if args.strict && !warnings.is_empty() {
        return Err(Error::CheckFailed(format!(
            "error: render --strict: the figure lint gave {} warning{}",
            warnings.len(),
            if warnings.len() == 1 { "" } else { "s" }
        )));
    }
    Ok(())
}
