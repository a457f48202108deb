//! `ndfplot render`: the command line's options to one [`crate::render`] call (files, `--check`, or
//! `-o -` to standard output).

use crate::cli::RenderArgs;
use crate::error::Result;
use crate::output::Format;
use crate::render::{self, RenderOptions};
use crate::spec::source::CanvasOverride;

/// Runs `ndfplot render` (or `render --check DIR`, or `render -o -` to stdout) with the parsed
/// `args`; `quiet` turns the progress bar off.
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
        },
        allow_read: args.allow_read,
    };
    match &args.check {
        Some(dir) => {
            crate::output::write::refuse_dash_folder(
                "--check",
                dir,
                "render --check compares with the files of a folder",
            )?;
            render::check(&options, dir, args.tolerance, quiet)
        }
        None if options.out.as_os_str() == "-" => {
            crate::output::stdout::write_bytes(&render::to_stdout(&options, quiet)?)
        }
        None => render::run_with_progress(&options, quiet).map(|_| ()),
    }
}
