//! One module per subcommand: each turns parsed arguments into output through the library.

pub mod albedo;
pub mod bench;
pub mod check;
pub mod coeffs;
pub mod compare;
pub mod completions;
pub mod eval;
pub mod fit;
pub mod render;
pub mod schema;

use crate::cli::{AlbedoArgs, CheckArgs, CoeffsArgs, Command, CompareArgs, EvalArgs, FitArgs};
use crate::error::{Error, Result};
use crate::model::curve::Curve;
use crate::model::dataset::Dataset;
use crate::model::metrics::sampled::{Operand, Samples};
use crate::output::report::ReportFormat;
use crate::output::stderr;
use crate::problem::{Problem, Problems, join_key};
use crate::spec::input::Side;
use crate::{output::stdout, pipeline::resolve, spec::input, spec::source};
use std::io::Write;
use std::path::PathBuf;

/// Runs a parsed command line; `quiet` (`-q`) leaves progress and notes off stderr (never errors or
/// warnings).
pub fn run(command: Command, quiet: bool) -> Result<()> {
    match command {
        Command::Eval(args) => run_eval(args),
        Command::Render(args) => render::run(args, quiet),
        Command::Coeffs(args) => run_coeffs(args),
        Command::Compare(args) => run_compare(args, quiet),
        Command::Fit(args) => run_fit(args, quiet),
        Command::Check(args) => run_check(args),
        Command::Albedo(args) => run_albedo(args, quiet),
        Command::List(args) if args.metals => stdout::print(&metal_listing()),
        Command::List(_) => stdout::print(&crate::spec::catalogue::listing()),
        Command::Show(args) => run_show(&args.id),
        Command::Schema => schema::run(),
        Command::Completions(args) => completions::completions(args.shell),
        Command::Man(args) => completions::man(args.dir.as_deref()),
        Command::Bench(args) => bench::run(&args.out).map(|_| ()),
    }
}

/// `symbol<TAB>names<TAB>min_nm<TAB>max_nm<TAB>samples` per measured metal, one line each, the names
/// comma-separated and the wavelengths as the table writes them (shortest round trip).
fn metal_listing() -> String {
    crate::model::metal::Metal::ALL
        .into_iter()
        .map(|metal| {
            let (min, max) = metal.range_nm();
            format!(
                "{}\t{}\t{min}\t{max}\t{}\n",
                metal.symbol(),
                metal.names().join(","),
                metal.samples()
            )
        })
        .collect()
}

/// Prints the spec of catalogue figure `id`; an unknown id is a usage error with a suggestion.
fn run_show(id: &str) -> Result<()> {
    match crate::spec::catalogue::find(id) {
        Some((_, text)) => stdout::print(text),
        None => Err(crate::error::Error::Usage(format!(
            "show: unknown catalogue id (got \"{id}\", see ndfplot list){}",
            crate::problem::suggestion(id, crate::spec::catalogue::ids())
        ))),
    }
}

fn run_eval(args: EvalArgs) -> Result<()> {
    let unit = crate::spec::angle::AngleUnit::of(args.degrees);
    let thetas = match (args.theta.strip_prefix('@'), &args.theta_column) {
        (Some(path), column) => {
            let text = input::read_file(path).map_err(|e| e.for_option("--theta"))?;
            match column {
                Some(column) => eval::parse_theta_column(&text, path, column, unit)?,
                None => eval::parse_theta_file(&text, path, unit)?,
            }
        }
        (None, Some(_)) => {
            return Err(Error::Usage(
                "--theta-column: reads a column of the CSV file --theta @FILE names (got an angle list)".into(),
            ));
        }
        (None, None) => eval::parse_theta_list(&args.theta, unit)?,
    };
    let curves = load_curves(&args.curve, "--curve")?;
    eval::check_integrals(&curves, &thetas)?;
    eval::write_table(&curves, &thetas, unit, &mut stdout::stream)?;
    stdout::flush()
}

fn run_coeffs(args: CoeffsArgs) -> Result<()> {
    let curves = load_curves(&args.curve, "--curve")?;
    let report = coeffs::report(&curves)?;
    stdout::print(&match args.format {
        ReportFormat::Json => report.json_array(),
        ReportFormat::Csv | ReportFormat::Table => report.csv(),
    })
}

/// The curves of a curve argument ([`input::load_curves`]), resolved.
fn load_curves(args: &[String], flag: &str) -> Result<Vec<Curve>> {
    input::load_curves(args, flag, std::io::stdin().lock())?
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

/// A side of `compare` as read ([`input::Side`]), resolved (a CSV series read), with its canonical
/// JSON; problems name `source` and lie under `key` (the pair's key of the side, `""` for `--a`/`--b`).
fn resolve_side(
    source: &str,
    key: &str,
    side: Side,
) -> std::result::Result<(Operand, String), Problems> {
    let problems = |p: Problem| Problems {
        source: source.to_string(),
        list: vec![Problem::new(join_key(key, &p.at), p.message)],
    };
    match side {
        Side::Curve(spec) => {
            let curve = resolve::curve(&spec).map_err(problems)?;
            let name = curve.canonical_json();
            Ok((Operand::Curve(curve), name))
        }
        Side::Csv(file) => {
            let series = resolve::csv(&file).map_err(problems)?;
            let samples = match &series {
                Dataset::Csv { x, y, .. } => Samples::new(x, y),
                _ => None,
            };
            let samples =
                samples.ok_or_else(|| problems(Problem::new("data", "expected θ and values")))?;
            Ok((Operand::Samples(samples), series.canonical_json()))
        }
    }
}

/// One side of `compare` ([`input::load_operand`]), resolved, with its canonical JSON.
fn load_operand(arg: &str, flag: &str, allow_read: &[PathBuf]) -> Result<(Operand, String)> {
    let (source, side) = input::load_operand(arg, flag, allow_read, input::read_stdin)?;
    resolve_side(&source, "", side).map_err(Error::input)
}

/// The pairs of `compare --pairs` ([`input::read_pairs`]) as they are read, each side resolved on
/// its own: one bad line does not keep the others from being compared.
fn load_pairs(
    arg: &str,
    allow_read: &[PathBuf],
) -> Result<impl Iterator<Item = Result<compare::LoadedPair>>> {
    Ok(
        input::read_pairs(arg, allow_read, std::io::stdin().lock())?.map(|record| {
            let record = record?;
            let value = record.value.and_then(|pair| {
                let ready = |(key, side)| {
                    resolve_side(&record.source, key, side)
                        .map(|(operand, json)| compare::ReadySide { key, operand, json })
                };
                Ok([ready(pair.a)?, ready(pair.b)?])
            });
            Ok(input::Record {
                source: record.source,
                line: record.line,
                value,
            })
        }),
    )
}

fn run_compare(args: CompareArgs, quiet: bool) -> Result<()> {
    let bounds: Vec<compare::Bound> = args
        .max_error
        .iter()
        .map(|b| compare::parse_bound(b))
        .collect::<Result<_>>()?;
    let span = compare::parse_span(
        args.theta_range.as_deref(),
        crate::spec::angle::AngleUnit::of(args.degrees),
    )?;
    let output = compare::Output::of(args.format, args.metric.as_deref(), span.unit)?;
    let (a, b) = match (&args.pairs, args.a.as_deref(), args.b.as_deref()) {
        (Some(pairs), None, None) => {
            let batch = compare::Batch {
                span,
                output,
                bounds,
                keep_going: args.keep_going,
            };
            return run_compare_pairs(pairs, &args.allow_read, &batch, quiet);
        }
        (None, Some(a), Some(b)) => (a, b),
        _ => {
            return Err(Error::Usage(
                "compare: give either --a and --b, or --pairs".into(),
            ));
        }
    };
    let (a, a_name) = load_operand(a, "--a", &args.allow_read)?;
    let (b, b_name) = load_operand(b, "--b", &args.allow_read)?;
    let compared = [compare::Compared {
        source: String::new(),
        a: a_name,
        b: b_name,
        metrics: compare::metrics(&a, &b, span.range)?,
    }];
    let report = match output {
        compare::Output::Metric(field) => {
            compare::one_number(field, &compared[0].metrics, &span).map_err(Error::Numerics)?
        }
        compare::Output::Json => compare::report(&compared, &span).json_lines(),
        compare::Output::Csv => compare::report(&compared, &span).csv(),
        compare::Output::Table => {
            compare::table(&compared[0], &span) + &compare::sampled_note(&a, &b)
        }
    };
    stdout::print(&report)?;
    compare::check_bounds(&compared[0].metrics, &bounds, &span)
}

/// `compare --pairs`: every pair compared ([`compare::run_pairs`]), the output printed, the closing
/// line, then the exceeded bounds on stderr and the problems of the pairs that could not be compared
/// (exit 2 when there are any and not `--keep-going`, else exit 1 when a bound is exceeded).
fn run_compare_pairs(
    arg: &str,
    allow_read: &[PathBuf],
    batch: &compare::Batch,
    quiet: bool,
) -> Result<()> {
    let started = std::time::Instant::now();
    let report = compare::run_pairs(
        load_pairs(arg, allow_read)?,
        &batch.span,
        batch.output,
        &batch.bounds,
        |text| stdout::stream(text.as_bytes()),
    )?;
    stdout::flush()?;
    let done = counted(report.compared, report.problems.len(), "pairs compared");
    stderr::summary(
        quiet,
        &format!("compare: {done}, written to stdout"),
        started,
    );
    let exceeded = report.exceeded.join("\n");
    let in_rows = matches!(batch.output, compare::Output::Json | compare::Output::Csv);
    if !report.problems.is_empty() && !batch.keep_going {
        if !exceeded.is_empty() {
            // The problems decide the exit code; the exceeded bounds are still said.
            stderr::say(&exceeded);
        }
        return Err(Error::Input(report.problems));
    }
    batch_verdict(report.problems, batch.keep_going, in_rows)?;
    if exceeded.is_empty() {
        Ok(())
    } else {
        Err(Error::CheckFailed(exceeded))
    }
}

fn run_fit(args: FitArgs, quiet: bool) -> Result<()> {
    let started = std::time::Instant::now();
    let family = fit::parse_family("--family", &args.family)?;
    let by = fit::parse_by(&args.by)?;
    let fixed = fit::parse_fixed(&args.fix)?;
    let format = fit::Format::of(args.format);
    let spec = crate::model::fit::FitSpec::new(family, &fixed, by).map_err(fit::fit_error)?;
    let report = fit::run(
        &spec,
        load_targets(&args.target, "--target")?,
        format,
        |text| stdout::stream(text.as_bytes()),
        // stderr is informative only: a closed or full stderr does not fail the fit.
        |line| {
            if !quiet {
                let _ = write!(std::io::stderr(), "{line}");
            }
        },
    )?;
    stdout::flush()?;
    if format != fit::Format::Curves {
        let done = counted(report.fitted, report.problems.len(), "targets fitted");
        stderr::summary(quiet, &format!("fit: {done}, written to stdout"), started);
    }
    batch_verdict(
        report.problems,
        args.keep_going,
        format != fit::Format::Curves,
    )
}

/// How many of a batch's records succeeded: `5 targets fitted`, or `19 of 20 targets fitted (1
/// failed)`.
fn counted(done: usize, failed: usize, what: &str) -> String {
    match failed {
        0 => format!("{done} {what}"),
        _ => format!("{done} of {} {what} ({failed} failed)", done + failed),
    }
}

/// The exit of a batch whose failed records are `problems`: 0 when there are none; with
/// `keep_going`, 0 as well (the rows say which failed, so their problems are printed only when
/// `in_rows` is false); otherwise exit 2 with every problem.
fn batch_verdict(problems: Vec<Problems>, keep_going: bool, in_rows: bool) -> Result<()> {
    if problems.is_empty() {
        return Ok(());
    }
    if !keep_going {
        return Err(Error::Input(problems));
    }
    if !in_rows {
        for p in &problems {
            stderr::say(&p.to_string());
        }
    }
    Ok(())
}

/// The curves of a curve argument ([`input::read_curves`]), each resolved on its own, with its source
/// name: one bad curve does not keep the others from being used.
fn load_targets(args: &[String], flag: &str) -> Result<impl Iterator<Item = Result<fit::Target>>> {
    Ok(
        input::read_curves(args, flag, std::io::stdin().lock())?.map(|record| {
            let record = record?;
            let value = record.value.and_then(|spec| {
                resolve::curve(&spec).map_err(|p| Problems {
                    source: record.source.clone(),
                    list: vec![p],
                })
            });
            Ok(input::Record {
                source: record.source,
                line: record.line,
                value,
            })
        }),
    )
}

fn run_check(args: CheckArgs) -> Result<()> {
    let scenes = resolve::scenes(source::load_scenes(
        &source::sources(&args.paths, &args.allow_read)?,
        source::CanvasOverride::default(),
    ))?;
    let audits = crate::pipeline::audit::audit_scenes(&scenes)?;
    stdout::print(&match args.format {
        ReportFormat::Json => check::report(&audits, args.tolerance).json_array(),
        ReportFormat::Csv => check::report(&audits, args.tolerance).csv(),
        ReportFormat::Table => check::table(&audits, args.tolerance),
    })?;
    check::verdict(&audits, args.tolerance)
}

/// `ndfplot albedo`: every argument checked (and the output folder of `-o` made writable) before
/// anything is integrated; the tables go to stdout or, with `-o`, to one file; a closing summary on
/// stderr unless `quiet`.
fn run_albedo(args: AlbedoArgs, quiet: bool) -> Result<()> {
    let started = std::time::Instant::now();
    let tables = albedo::parse_tables(&args.table)?;
    let map = crate::model::albedo::RoughnessMap::from_key(&args.map)
        .expect("clap allows only map names");
    let g2 =
        crate::model::masking::G2Model::from_name(&args.g2).expect("clap allows only G2 names");
    let family = fit::parse_family("--ndf", &args.ndf)?;
    let fixed = fit::parse_fixed(&args.fix)?;
    let fresnel = match &args.fresnel {
        Some(arg) => Some(albedo::fresnel_factor(load_curves(
            std::slice::from_ref(arg),
            "--fresnel",
        )?)?),
        None => None,
    };
    if let Some(path) = &args.against {
        let &[table] = tables.as_slice() else {
            return Err(Error::Usage(format!(
                "--table: --against audits one table (got \"{}\", expected one of e, average, dfg)",
                args.table
            )));
        };
        return run_albedo_audit(&args, path, table, g2, family, &fixed, fresnel, quiet).inspect(
            |()| {
                let audited = format!(
                    "albedo: audited {} of {}",
                    table.name(),
                    crate::problem::one_line(&path.display().to_string())
                );
                stderr::summary(quiet, &audited, started);
            },
        );
    }
    let surface = albedo::Surface::new(family, &fixed, map)?;
    let grid = albedo::grid(&tables, args.size, args.mu_count, args.r_count)?;
    let request = albedo::Request::new(tables, surface, g2, grid, fresnel)?;
    // `-o -` is standard output, as without -o.
    let destination = args
        .out
        .as_deref()
        .filter(|path| path.as_os_str() != "-")
        .map(|path| crate::output::write::split_file_path("-o", path))
        .transpose()?;
    if let Some((dir, name)) = destination {
        crate::output::write::check_writable("-o", dir, &[name])?;
    }
    let progress = crate::pipeline::progress::Progress::new(request.steps() as u64, quiet);
    progress.stage("integrating");
    let outputs = request.compute(&progress)?;
    progress.finish();
    let text = albedo::print::text(&outputs, args.format, args.shape, !args.no_comments);
    match destination {
        Some((dir, name)) => {
            crate::output::write::write_files("-o", dir, &[(name, text)]).map(drop)?
        }
        None => stdout::print(&text)?,
    }
    let place = args
        .out
        .as_deref()
        .filter(|path| path.as_os_str() != "-")
        .map_or("stdout".to_string(), |path| {
            crate::problem::one_line(&path.display().to_string()).into_owned()
        });
    stderr::summary(quiet, &albedo::print::summary(&outputs, &place), started);
    Ok(())
}

/// `albedo --against FILE`: reads the engine's table, computes the exact one on its grid, prints
/// the comparison and writes `-o DIR`'s files; exit 1 when `--max-error` is exceeded.
#[allow(clippy::too_many_arguments)]
fn run_albedo_audit(
    args: &AlbedoArgs,
    path: &std::path::Path,
    table: crate::model::albedo::Table,
    g2: crate::model::masking::G2Model,
    family: crate::model::ndf::Family,
    fixed: &[(String, f64)],
    fresnel: Option<Curve>,
    quiet: bool,
) -> Result<()> {
    let layout = crate::spec::lut::parse_layout(
        args.layout.as_deref().unwrap_or(""),
        &path.display().to_string(),
        g2,
    )
    .map_err(crate::error::Error::input)?;
    if let Some(x) = args.max_error
        && !(x >= 0.0 && x.is_finite())
    {
        return Err(crate::error::Error::Usage(format!(
            "--max-error: not a tolerance (got {x}, expected a finite number >= 0)"
        )));
    }
    let surface = albedo::Surface::new(family, fixed, layout.map)?;
    if let Some(dir) = &args.out {
        albedo::audit::check_outputs(dir)?;
    }
    let against = albedo::audit::read(
        path,
        layout,
        table,
        (args.size, args.mu_count, args.r_count),
    )?;
    let steps = against.n_mu.unwrap_or(1) * against.n_r;
    let progress = crate::pipeline::progress::Progress::new(steps as u64, quiet);
    progress.stage("integrating");
    let audit = against.audit(&surface, table, fresnel.as_ref(), &progress)?;
    progress.finish();
    if let Some(dir) = &args.out {
        audit.write(dir)?;
    }
    stdout::print(&audit.report())?;
    match args.max_error {
        Some(x) if audit.audit.max_abs > x => Err(crate::error::Error::CheckFailed(format!(
            "albedo --against: max_abs {:.3e} exceeds --max-error {x:e}",
            audit.audit.max_abs
        ))),
        _ => Ok(()),
    }
}
