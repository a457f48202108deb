//! One module per subcommand: each turns parsed arguments into output through the library.

pub mod eval;
pub mod render;

use crate::cli::{Command, EvalArgs, RenderArgs};
use crate::error::Result;
use crate::{input, stdout};
use std::io::Read;

/// Runs a parsed command line.
pub fn run(command: Command) -> Result<()> {
    match command {
        Command::Eval(args) => run_eval(args),
        Command::Render(args) => run_render(args),
    }
}

fn read_stdin() -> std::io::Result<String> {
    let mut text = String::new();
    std::io::stdin().read_to_string(&mut text)?;
    Ok(text)
}

fn run_eval(args: EvalArgs) -> Result<()> {
    let thetas = eval::parse_theta_list(&args.theta, args.degrees)?;
    let curves = input::load_curves(&args.curve, "--curve", read_stdin)?;
    stdout::print(&eval::table(&curves, &thetas)?)
}

fn run_render(args: RenderArgs) -> Result<()> {
    let options = render::RenderOptions {
        paths: args.paths,
        out: args.out,
        formats: render::Format::parse_list(&args.format)?,
        canvas: render::CanvasOverride {
            width: args.width,
            height: args.height,
            png_scale: args.png_scale,
            font_px: args.font_px,
        },
    };
    render::run(&options).map(|_| ())
}
