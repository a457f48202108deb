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
use crate::curve::Curve;
use crate::dataset::Dataset;
use crate::error::{Error, Result};
use crate::input::Side;
use crate::metrics::sampled::{Operand, Samples};
use crate::problem::{Problem, Problems};
use crate::{input, resolve, source, stdout};
use std::io::{Read, Write};
use std::path::PathBuf;

/// Runs a parsed command line.
pub fn run(command: Command) -> Result<()> {
    match command {
        Command::Eval(args) => run_eval(args),
        Command::Render(args) => render::run(args),
        Command::Coeffs(args) => run_coeffs(args),
        Command::Compare(args) => run_compare(args),
        Command::Fit(args) => run_fit(args),
        Command::Check(args) => run_check(args),
        Command::List => stdout::print(&crate::catalogue::listing()),
        Command::Show(args) => run_show(&args.id),
        Command::Schema => schema::run(),
        Command::Completions(args) => completions::completions(args.shell),
        Command::Man(args) => completions::man(args.dir.as_deref()),
        Command::Bench(args) => bench::run(&args.out).map(|_| ()),
    }
}

/// Prints the spec of catalogue figure `id`; an unknown id is a usage error with a suggestion.
fn run_show(id: &str) -> Result<()> {
    match crate::catalogue::find(id) {
        Some((_, text)) => stdout::print(text),
        None => Err(crate::error::Error::Usage(format!(
            "show: unknown catalogue id (got \"{id}\", see ndfplot list){}",
            crate::problem::suggestion(id, crate::catalogue::ids())
        ))),
    }
}

fn read_stdin() -> std::io::Result<String> {
    let mut text = String::new();
    std::io::stdin().read_to_string(&mut text)?;
    Ok(text)
}

fn run_eval(args: EvalArgs) -> Result<()> {
    let thetas = eval::parse_theta_list(&args.theta, args.degrees)?;
    let curves = load_curves(&args.curve, "--curve")?;
    stdout::print(&eval::table(&curves, &thetas)?)
}

fn run_coeffs(args: CoeffsArgs) -> Result<()> {
    let curves = load_curves(&args.curve, "--curve")?;
    stdout::print(&coeffs::table(&curves)?)
}

/// The curves of a curve argument ([`input::load_curves`]), resolved.
fn load_curves(args: &[String], flag: &str) -> Result<Vec<Curve>> {
    input::load_curves(args, flag, read_stdin)?
        .iter()
        .map(|spec| resolve::curve(spec).map_err(|p| input_error(flag, p)))
        .collect()
}

/// A problem of the argument or file `source`.
fn input_error(source: &str, problem: Problem) -> Error {
    Error::Input(vec![Problems {
        source: source.to_string(),
        list: vec![problem],
    }])
}

/// One side of `compare` ([`input::load_operand`]), resolved (a CSV series read), with its
/// canonical JSON.
fn load_operand(arg: &str, flag: &str, allow_read: &[PathBuf]) -> Result<(Operand, String)> {
    let (source, side) = input::load_operand(arg, flag, allow_read, read_stdin)?;
    match side {
        Side::Curve(spec) => {
            let curve = resolve::curve(&spec).map_err(|p| input_error(&source, p))?;
            let name = curve.canonical_json();
            Ok((Operand::Curve(curve), name))
        }
        Side::Csv(file) => {
            let series = resolve::csv(&file).map_err(|p| input_error(&source, p))?;
            let samples = match &series {
                Dataset::Csv { x, y, .. } => Samples::new(x, y),
                _ => None,
            };
            let samples = samples.ok_or_else(|| {
                input_error(&source, Problem::new("data", "expected θ and values"))
            })?;
            Ok((Operand::Samples(samples), series.canonical_json()))
        }
    }
}

/// Loads exactly one curve from a curve argument (inline JSON, @FILE or - for one line on stdin).
fn load_one_curve(arg: &str, flag: &str) -> Result<Curve> {
    let mut curves = load_curves(&[arg.to_string()], flag)?;
    if curves.len() != 1 {
        return Err(Error::Usage(format!(
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
    let (a, a_name) = load_operand(&args.a, "--a", &args.allow_read)?;
    let (b, b_name) = load_operand(&args.b, "--b", &args.allow_read)?;
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
    // stderr is informative only: a closed or full stderr does not fail the fit.
    let _ = writeln!(std::io::stderr(), "{}", fit::residual_line(&fitted, by));
    Ok(())
}

fn run_check(args: CheckArgs) -> Result<()> {
    let scenes = resolve::scenes(source::load_scenes(
        &source::sources(&args.paths, &args.allow_read)?,
        source::CanvasOverride::default(),
    ))?;
    let audits = crate::audit::audit_scenes(&scenes)?;
    stdout::print(&check::table(&audits, args.tolerance))?;
    check::verdict(&audits, args.tolerance)
}
