//! One module per subcommand: each turns parsed arguments into output through the library.

pub mod bench;
pub mod check;
pub mod coeffs;
pub mod compare;
pub mod completions;
pub mod eval;
pub mod fit;
pub mod render;
pub mod schema;

use crate::cli::{CheckArgs, CoeffsArgs, Command, CompareArgs, EvalArgs, FitArgs};
use crate::error::Result;
use crate::{input, source, stdout};
use std::io::Read;

/// Runs a parsed command line.
pub fn run(command: Command) -> Result<()> {
    match command {
        Command::Eval(args) => run_eval(args),
        Command::Render(args) => render::run(args),
        Command::Coeffs(args) => run_coeffs(args),
        Command::Compare(args) => run_compare(args),
        Command::Fit(args) => run_fit(args),
        Command::Check(args) => run_check(args),
        Command::Schema => schema::run(),
        Command::Completions(args) => completions::completions(args.shell),
        Command::Man => completions::man(),
        Command::Bench(args) => bench::run(&args.out).map(|_| ()),
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

fn run_coeffs(args: CoeffsArgs) -> Result<()> {
    let curves = input::load_curves(&args.curve, "--curve", read_stdin)?;
    stdout::print(&coeffs::table(&curves)?)
}

/// Loads exactly one curve from a curve argument (inline JSON, @FILE or - for one line on stdin).
fn load_one_curve(arg: &str, flag: &str) -> Result<crate::curve::Curve> {
    let mut curves = input::load_curves(&[arg.to_string()], flag, read_stdin)?;
    if curves.len() != 1 {
        return Err(crate::error::Error::Usage(format!(
            "{flag}: expected one curve (got {})",
            curves.len()
        )));
    }
    Ok(curves.remove(0))
}

fn run_compare(args: CompareArgs) -> Result<()> {
    let bounds: Vec<compare::Bound> = args
        .max_error
        .iter()
        .map(|b| compare::parse_bound(b))
        .collect::<Result<_>>()?;
    let (a, a_name) = input::load_operand(&args.a, "--a", read_stdin)?;
    let (b, b_name) = input::load_operand(&args.b, "--b", read_stdin)?;
    let metrics = compare::metrics(&a, &b)?;
    let report = if args.format == "json" {
        compare::json(&a_name, &b_name, &metrics)
    } else {
        compare::table(&a_name, &b_name, &metrics)
    };
    stdout::print(&report)?;
    compare::check_bounds(&metrics, &bounds)
}

fn run_fit(args: FitArgs) -> Result<()> {
    let family = fit::parse_family(&args.family)?;
    let by = fit::parse_by(&args.by)?;
    let fixed = fit::parse_fixed(&args.fix)?;
    let target = load_one_curve(&args.target, "--target")?;
    let fitted = fit::run(&target, family, &fixed, by)?;
    stdout::print(&fit::stdout_line(&fitted))?;
    eprintln!("{}", fit::residual_line(&fitted, by));
    Ok(())
}

fn run_check(args: CheckArgs) -> Result<()> {
    let scenes = source::load_scenes(
        &source::sources(&args.paths)?,
        source::CanvasOverride::default(),
    )?;
    let audits = crate::audit::audit_scenes(&scenes)?;
    stdout::print(&check::table(&audits, args.tolerance))?;
    check::verdict(&audits, args.tolerance)
}
