//! The command line: clap types that mirror the arguments, and nothing else.

use clap::{Args, Parser, Subcommand};
use std::path::PathBuf;

/// Plot and compare microfacet normal distribution functions and Fresnel reflectance.
#[derive(Debug, Parser)]
#[command(name = "ndfplot", version, about, propagate_version = true)]
pub struct Cli {
    /// The subcommand to run.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Evaluate curves at given angles; prints CSV on stdout.
    Eval(EvalArgs),
    /// Render scene specs (or the built-in catalogue) to SVG, PNG and CSV.
    Render(RenderArgs),
}

/// Arguments of `ndfplot render`.
#[derive(Debug, Args)]
pub struct RenderArgs {
    /// Scene spec files, or folders whose *.json are rendered in name order. None: the built-in
    /// catalogue of notebook figures.
    #[arg(value_name = "SPEC.json|DIR")]
    pub paths: Vec<PathBuf>,
    /// Output folder (created if missing); files are <DIR>/<id>.<ext>.
    #[arg(short, long, value_name = "DIR", default_value = "plots")]
    pub out: PathBuf,
    /// Formats to write, comma-separated.
    #[arg(long, value_name = "LIST", default_value = "svg,png,csv")]
    pub format: String,
    /// Figure width in CSS pixels for every scene (the height follows unless --height is given).
    #[arg(long, value_name = "PX", value_parser = float_in(16.0, 20_000.0))]
    pub width: Option<f64>,
    /// Figure height in CSS pixels for every scene.
    #[arg(long, value_name = "PX", value_parser = float_in(16.0, 20_000.0))]
    pub height: Option<f64>,
    /// PNG pixels per CSS pixel (default 2 unless the scene says otherwise).
    #[arg(long, value_name = "SCALE", value_parser = float_in(0.1, 16.0))]
    pub png_scale: Option<f64>,
    /// Base font size in CSS pixels (default 14 unless the scene says otherwise).
    #[arg(long, value_name = "PX", value_parser = float_in(4.0, 200.0))]
    pub font_px: Option<f64>,
}

/// A clap value parser for a finite number within [low, high].
fn float_in(low: f64, high: f64) -> impl Fn(&str) -> Result<f64, String> + Clone {
    move |text: &str| match text.parse::<f64>() {
        Ok(v) if (low..=high).contains(&v) => Ok(v),
        _ => Err(format!("expected a number from {low} to {high} (got \"{text}\")")),
    }
}

/// Arguments of `ndfplot eval`.
#[derive(Debug, Args)]
#[command(after_long_help = eval_help())]
pub struct EvalArgs {
    /// A curve: inline JSON such as '{"ndf":"beckmann","alpha_b":0.5}', @FILE holding one curve, or
    /// - for one curve per line on stdin (JSON Lines). Repeat for several columns.
    #[arg(long, required = true, value_name = "JSON|@FILE|-", allow_hyphen_values = true)]
    pub curve: Vec<String>,
    /// Angles: comma-separated (0,0.1,1.5707963267948966) or start:stop:count (numpy linspace,
    /// both ends included). Radians in [0, π/2] unless --degrees. Use --theta=-1 for negatives.
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    pub theta: String,
    /// Read the angles in degrees (θ = d·π/180).
    #[arg(long)]
    pub degrees: bool,
}

fn eval_help() -> String {
    let mut text = String::from("Curve models and parameter domains:\n");
    for family in crate::ndf::Family::ALL {
        text.push_str(&format!("  ndf {:<18} {}\n", family.name(), family.domain()));
    }
    text.push_str("  (ggx is an alias of trowbridge_reitz)\n");
    text.push_str(FRESNEL_HELP);
    text.push_str(
        "\nOutput: CSV with header theta,value (one curve) or theta,<curve JSON>... (several);\n\
         numbers in shortest round-trip form. Exit 2 on bad input, with one error line per problem.",
    );
    text
}

/// The Fresnel curve models and their parameter domains, for `eval --help`.
const FRESNEL_HELP: &str = "\
  fresnel exact        eta in [1e-150, 1e150], kappa in [0, 1e150] (default 0); or r in [0, 1), g in [0, 1], g_remap
  fresnel schlick      f0 in [0, 1]; or eta/kappa; or r/g/g_remap (F0 of the exact Fresnel)
  fresnel lazanyi      f0 in [0, 1], a such that 0 <= F <= 1 (a in [-5(1 - f0), a_max(f0)], a_max(0) = 4)
  fresnel lazanyi_term no parameters: c(1 - c)^6 normalized to a maximum of 1
  fresnel belcour      eta/kappa or r/g/g_remap: the four-term basis reconstruction
  fresnel basis        index 0, 1, 2 or 3: one basis function
";
