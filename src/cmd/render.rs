//! `ndfplot render`: the command line's options to one [`crate::render`] call.

use crate::cli::RenderArgs;
use crate::error::Result;
use crate::output::Format;
use crate::render::{self, RenderOptions};
use crate::source::CanvasOverride;

/// Runs `ndfplot render` (or `render --check DIR`) with the parsed `args`.
pub fn run(args: RenderArgs) -> Result<()> {
    let options = RenderOptions {
        paths: args.paths,
        out: args.out,
        formats: Format::parse_list(&args.format)?,
        canvas: CanvasOverride {
            width: args.width,
            height: args.height,
            png_scale: args.png_scale,
            font_px: args.font_px,
        },
        allow_read: args.allow_read,
    };
    match &args.check {
        Some(dir) => render::check(&options, dir, args.tolerance, args.quiet),
        None => render::run_with_progress(&options, args.quiet).map(|_| ()),
    }
}
