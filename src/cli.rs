//! The command line: clap types that mirror the arguments, and nothing else.

use crate::output::report::{RecordFormat, ReportFormat, TableShape};
use crate::output::stderr::ColorChoice;
use clap::builder::{PossibleValuesParser, TypedValueParser};
use clap::{Args, Parser, Subcommand};
use std::path::PathBuf;

/// Plot and compare microfacet normal distribution functions and Fresnel reflectance.
#[derive(Debug, Parser)]
#[command(name = "ndfplot", version, about, propagate_version = true)]
pub struct Cli {
    /// No progress bar or notes on stderr (errors and warnings are always printed); works with
    /// every command.
    #[arg(short, long, global = true)]
    pub quiet: bool,
    /// More on stderr: with render, one line per figure (size, panels, series, points, warnings,
    /// drawing time); works with every command.
    #[arg(short, long, global = true)]
    pub verbose: bool,
    /// Colour the error: and warning: labels on stderr: auto (when stderr is a terminal and
    /// NO_COLOR is unset or empty), always or never.
    #[arg(long, global = true, value_name = "WHEN", default_value = "auto", value_parser = choice(&ColorChoice::NAMES, &ColorChoice::ALL))]
    pub color: ColorChoice,
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
    /// Belcour–Bati–Barla coefficients c0..c3 and L2 error of materials; prints CSV.
    Coeffs(CoeffsArgs),
    /// Compare two curves of the same kind, or many pairs (--pairs): max_abs, max_rel, max_log_ratio,
    /// l2_projected, l2_grid, peaks.
    Compare(CompareArgs),
    /// Fit the free parameters of an NDF family to target curves; prints the fitted curves.
    Fit(FitArgs),
    /// Audit the normalization of every curve in scenes (or the built-in catalogue).
    Check(CheckArgs),
    /// Tabulate the directional albedo E(mu, r) of an NDF, its average E_avg(r) or the split-sum
    /// tables, for renderers; prints CSV.
    Albedo(AlbedoArgs),
    /// List the built-in catalogue: one id<TAB>title line per figure (or, with --metals, the
    /// measured metals).
    #[command(after_long_help = "Examples:\n  \
        ndfplot list\n  \
        ndfplot list | cut -f1 | grep interactive | xargs ndfplot render -o pages\n  \
        ndfplot list --metals")]
    List(ListArgs),
    /// Print the spec of a catalogue figure, ready to copy and edit.
    #[command(after_long_help = "Examples:\n  \
        ndfplot show gtr-gamma > my-figure.json\n  \
        ndfplot render gtr-gamma -o plots")]
    Show(ShowArgs),
    /// Print the JSON Schema of the scene spec and curve formats.
    #[command(
        after_long_help = "The root validates a scene file; a curve file (eval --curve @FILE) validates against\n\
        #/$defs/curve. The schema is generated from the validator's own key tables.\n\n\
        Examples:\n  \
        ndfplot schema > schema/ndfplot.schema.json\n  \
        Reference it from a spec for editor completion: {\"$schema\": \"../schema/ndfplot.schema.json\", \"id\": …}"
    )]
    Schema,
    /// Print a shell completion script.
    Completions(CompletionsArgs),
    /// Print the manual page (roff), or write one page per subcommand with --dir.
    #[command(after_long_help = "Examples:\n  \
        ndfplot man > ndfplot.1 && man ./ndfplot.1\n  \
        ndfplot man --dir man && man -l man/ndfplot-render.1\n  \
        ndfplot man --dir /usr/local/share/man/man1")]
    Man(ManArgs),
    /// Measure run time against error (drawing, normalization routes, throughput, Λ routes, an
    /// albedo table); writes bench.csv, bench.svg and bench.png.
    Bench(BenchArgs),
}

/// Arguments of `ndfplot list`.
#[derive(Debug, Args)]
pub struct ListArgs {
    /// List the metals a Fresnel curve may name ("metal"): one
    /// symbol<TAB>names<TAB>min_nm<TAB>max_nm<TAB>samples line each.
    #[arg(long)]
    pub metals: bool,
}

/// Arguments of `ndfplot show`.
#[derive(Debug, Args)]
pub struct ShowArgs {
    /// The catalogue id (as ndfplot list prints it).
    pub id: String,
}

/// Arguments of `ndfplot man`.
#[derive(Debug, Args)]
pub struct ManArgs {
    /// Write ndfplot.1 and one ndfplot-<subcommand>.1 per subcommand into DIR (created if needed)
    /// instead of printing the top page. A page name taken by something other than a regular file
    /// (device, FIFO, socket, folder) is refused (exit 2), and so is - (not a folder).
    #[arg(long, value_name = "DIR")]
    pub dir: Option<std::path::PathBuf>,
}

/// Arguments of `ndfplot completions`.
#[derive(Debug, Args)]
#[command(after_long_help = "Examples:\n  \
    ndfplot completions bash > ~/.local/share/bash-completion/completions/ndfplot\n  \
    ndfplot completions zsh > ~/.zfunc/_ndfplot\n  \
    ndfplot completions fish > ~/.config/fish/completions/ndfplot.fish")]
pub struct CompletionsArgs {
    /// The shell to complete for.
    #[arg(value_name = "SHELL")]
    pub shell: clap_complete::Shell,
}

/// Arguments of `ndfplot coeffs`.
#[derive(Debug, Args)]
#[command(
    after_long_help = "Output: CSV c0,c1,c2,c3,l2, one row per curve; with --format json a JSON array of\n\
    objects with the same names, one per curve.\n\n\
    Examples:\n  \
    ndfplot coeffs --curve '{\"fresnel\":\"belcour\",\"eta\":0.29,\"kappa\":2.86}'\n  \
    ndfplot coeffs --curve '{\"fresnel\":\"belcour\",\"r\":0.5,\"g\":0.2,\"g_remap\":true}'"
)]
pub struct CoeffsArgs {
    /// A material as a Fresnel curve: '{"fresnel":"belcour","eta":1.5,"kappa":0}' (or r/g, or an
    /// "exact" curve), @FILE, or - for JSON Lines on stdin. Repeat for several rows.
    #[arg(
        long,
        required = true,
        value_name = "JSON|@FILE|-",
        allow_hyphen_values = true
    )]
    pub curve: Vec<String>,
    /// Output: CSV, or a JSON array of one object per curve.
    #[arg(long, value_name = "FORMAT", default_value = "csv",
        value_parser = choice(&ReportFormat::NAMES, &[ReportFormat::Csv, ReportFormat::Json]))]
    pub format: ReportFormat,
}

/// Arguments of `ndfplot render`.
#[derive(Debug, Args)]
#[command(
    after_long_help = "Every spec is validated before anything is evaluated or written; files are written as\n\
    hidden temporaries and renamed into place (with -o -, the one output goes to stdout). A spec read\n\
    from stdin (-) resolves its data paths against the working directory. With --check nothing is written: the CSVs and SVGs are\n\
    re-rendered and compared with DIR's, every CSV cell and, for figures whose values match, the\n\
    drawing of the stored SVG (exit 1 on any difference, a missing or an extra CSV). DIR is untrusted:\n\
    only its regular files are read, never through a symbolic link (a link, FIFO, device or folder under\n\
    a compared name exits 2), up to 8 times the rendered file's size plus 1 MiB (a larger one differs,\n\
    unread); stored text is quoted only in short excerpts, control characters escaped.\n\n\
    Caps (exit 2 before anything is computed): 10 000 curves and 5 000 000 table points a scene, and\n\
    100 000 integrals a scene (albedo curves: each counts its table's samples plus up to 1033 drawn).\n\n\
    Examples:\n  \
    ndfplot render\n  \
    ndfplot render abc-vs-tr my-scenes/ -o out --format svg,csv\n  \
    ndfplot render beckmann-vs-phong -o out --format pdf --preset paper-column\n  \
    ndfplot show gtr-gamma | ndfplot render - -o - --format svg --theme dark > gtr-gamma-dark.svg\n  \
    ndfplot render --check plots\n  \
    ndfplot render tr-vs-phong --check plots --tolerance 1e-9"
)]
pub struct RenderArgs {
    /// Scene spec files, folders whose *.json are rendered in name order, catalogue ids, or - for a
    /// spec on stdin. None: the built-in catalogue of notebook figures.
    #[arg(value_name = "SPEC.json|DIR|ID|-")]
    pub paths: Vec<PathBuf>,
    /// Output folder (created if missing); files are <DIR>/<id>.<ext>, and a name taken by something
    /// other than a regular file or a link (device, FIFO, socket, folder) is refused before any file
    /// is written (exit 2). - writes the one figure in the one --format to stdout instead (exit 2
    /// for several figures or formats).
    #[arg(
        short,
        long,
        value_name = "DIR|-",
        default_value = "plots",
        allow_hyphen_values = true
    )]
    pub out: PathBuf,
    /// Formats to write, comma-separated, from svg, png, pdf, csv, html; html only for scenes
    /// with sliders, pdf only when listed.
    #[arg(long, value_name = "LIST", default_value = "svg,png,csv,html")]
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
    /// Write nothing: re-render the CSVs and SVGs and compare them with those in DIR (exit 1 on a
    /// difference in values or drawing); -o is refused with it (exit 2), as it writes.
    #[arg(long, value_name = "DIR", conflicts_with = "out")]
    pub check: Option<PathBuf>,
    /// Largest accepted relative difference of a CSV value under --check.
    #[arg(long, value_name = "X", requires = "check", default_value_t = crate::output::stored::DEFAULT_TOLERANCE, value_parser = float_in(0.0, 1.0))]
    pub tolerance: f64,
    /// Override every scene's theme: notebook, colour-blind (or color-blind) or dark.
    #[arg(long, value_name = "NAME", value_parser = clap::builder::PossibleValuesParser::new(crate::spec::scene::THEMES))]
    pub theme: Option<String>,
    /// Size every scene for a paper: paper-column (3.3 in wide) or paper-page (7 in wide), 8 pt
    /// text, 300 dpi, the height from the panel rows; --width, --height, --png-scale and
    /// --font-px still apply after it.
    #[arg(long, value_name = "NAME", value_parser = clap::builder::PossibleValuesParser::new(crate::spec::scene::PRESETS))]
    pub preset: Option<String>,
    /// Exit 1 when the figure lint warns about any figure (the outputs are still written).
    /// Warnings (warning: FILE: panels[i]: …: plot areas squeezed, text overlapping or clipped,
    /// too few ticks, low contrast, legends alike or not where asked) are printed either way.
    #[arg(long)]
    pub strict: bool,
    /// Also allow data files ({"data": "csv", "path": …}) inside DIR; by default a data path must stay
    /// inside the folder of the spec naming it. Repeatable.
    #[arg(long = "allow-read", value_name = "DIR")]
    pub allow_read: Vec<PathBuf>,
}

/// A clap value parser of one of `offered`, a choice named by its `names` table (a `named!` enum's
/// `NAMES`): `--help` lists the offered names and the parsed value is the typed choice.
fn choice<T: Copy + PartialEq + Send + Sync + 'static>(
    names: &'static [(&'static str, T)],
    offered: &'static [T],
) -> impl TypedValueParser<Value = T> {
    let offered_names = names
        .iter()
        .filter(|(_, v)| offered.contains(v))
        .map(|(n, _)| *n);
    PossibleValuesParser::new(offered_names).map(move |name| {
        names
            .iter()
            .find(|(n, _)| *n == name)
            .map(|&(_, v)| v)
            .expect("clap accepts only the offered names")
    })
}

/// A clap value parser for a finite number within [low, high].
fn float_in(low: f64, high: f64) -> impl Fn(&str) -> Result<f64, String> + Clone {
    move |text: &str| match text.parse::<f64>() {
        Ok(v) if (low..=high).contains(&v) => Ok(v),
        _ => Err(format!(
            "expected a number from {low} to {high} (got \"{text}\")"
        )),
    }
}

/// Arguments of `ndfplot eval`.
#[derive(Debug, Args)]
#[command(after_long_help = eval_help())]
pub struct EvalArgs {
    /// A curve: inline JSON such as '{"ndf":"beckmann","alpha_b":0.5}', @FILE holding one curve, or
    /// - for one curve per line on stdin (JSON Lines). Repeat for several columns.
    #[arg(
        long,
        required = true,
        value_name = "JSON|@FILE|-",
        allow_hyphen_values = true
    )]
    pub curve: Vec<String>,
    /// Angles: comma-separated (0,0.1,pi/2) or start:stop:count (numpy linspace, both ends
    /// included; 0:pi/2:91), or @FILE with one angle per line (blank lines and # comments
    /// skipped). Radians in [0, π/2], any of them a multiple of π (pi, pi/2, 3pi/8), unless
    /// --degrees. Use --theta=-1 for negatives.
    #[arg(long, value_name = "LIST|@FILE", allow_hyphen_values = true)]
    pub theta: String,
    /// With --theta @FILE: FILE is a CSV with a header row, and the angles are its column NAME (a
    /// shader's or renderer's samples, evaluated at their own θ).
    #[arg(long = "theta-column", value_name = "NAME")]
    pub theta_column: Option<String>,
    /// Read the angles in degrees (θ = d·π/180) and print them as given, in a column named theta_deg.
    #[arg(long)]
    pub degrees: bool,
}

/// `fit --family`'s help: the registry's canonical family names.
fn family_help() -> String {
    let names: Vec<&str> = crate::model::ndf::Family::ALL
        .iter()
        .map(|f| f.name())
        .collect();
    format!("The NDF family to fit ({})", names.join(", "))
}

fn eval_help() -> String {
    let mut text = String::from("Curve models and parameter domains:\n");
    for family in crate::model::ndf::Family::ALL {
        text.push_str(&format!(
            "  ndf {:<18} {}\n",
            family.name(),
            family.domain()
        ));
    }
    for family in crate::model::ndf::Family::ALL {
        for alias in family.aliases() {
            text.push_str(&format!("  ({alias} is an alias of {})\n", family.name()));
        }
    }
    text.push_str(FRESNEL_HELP);
    text.push_str(QUANTITY_HELP);
    text.push_str(
        "\nOutput: CSV with header theta,value (one curve) or theta,<curve JSON>... (several), theta_deg\n\
         instead of theta with --degrees;\n\
         numbers in shortest round-trip form. Exit 2 on bad input, with one error line per problem.\n\
         Caps: 10 000 000 angles; 100 000 integrals (angles x albedo curves), refused before any row.\n\n\
         Examples:\n  \
         ndfplot eval --curve '{\"ndf\":\"beckmann\",\"alpha_b\":0.5}' --theta 0:1.5707963267948966:5\n  \
         ndfplot eval --curve '{\"ndf\":\"ggx\",\"alpha_tr\":0.2}' --curve @curve.json --theta 0,30,60,90 --degrees\n  \
         cat curves.jsonl | ndfplot eval --curve - --theta 0:1.5707963267948966:1000 > table.csv",
    );
    text
}

/// The Fresnel curve models and their parameter domains, for `eval --help`.
const FRESNEL_HELP: &str = "  fresnel exact        eta in [1e-150, 1e150], kappa in [0, 1e150] (default 0); or r in [0, 1), g in [0, 1], g_remap
  fresnel schlick      f0 in [0, 1]; or eta/kappa; or r/g/g_remap (F0 of the exact Fresnel)
  fresnel lazanyi      f0 in [0, 1], a such that 0 <= F <= 1 (a in [-5(1 - f0), a_max(f0)], a_max(0) = 4)
  fresnel lazanyi_term no parameters: c(1 - c)^6 normalized to a maximum of 1
  fresnel belcour      eta/kappa or r/g/g_remap: the four-term basis reconstruction
  fresnel basis        index 0, 1, 2 or 3: one basis function
  fresnel normalized   eta/kappa or r/g/g_remap: (F - F0)/(1 - F0), the basis training curves
";

/// What an NDF curve may show besides D ([`crate::spec::quantity`]), for `eval --help`.
const QUANTITY_HELP: &str = "
An NDF curve may add \"quantity\" (theta is then the view angle theta_o):
  d        D(theta) (default)
  lambda   Smith Lambda(theta_o)
  g1       G1 = 1/(1 + Lambda(theta_o))
  g2       G2(theta_o, theta_i); \"g2\": height-correlated (default) or separable, \"theta_i\": radians
           or \"same\" (default)
  albedo   directional albedo E(cos theta_o) of f = F D G2 / (4 cos theta_o cos theta_i); \"g2\" as above,
           \"fresnel\": a Fresnel curve object (default F = 1)
  furnace  weak white furnace G1_used (1 + Lambda); \"g1\": smith (default, exactly 1),
           walter-rational or beckmann-equivalent (at the family's Beckmann-equivalent roughness)
  e.g. '{\"ndf\":\"ggx\",\"alpha_tr\":0.3,\"quantity\":\"albedo\",\"fresnel\":{\"fresnel\":\"exact\",\"eta\":1.5}}'
";

/// Arguments of `ndfplot compare`.
#[derive(Debug, Args)]
#[command(
    after_long_help = "Metrics over theta in [0, pi/2], or in --theta-range (docs/contracts.md):\n  \
    max_abs        max |a - b|, with the theta where it is reached\n  \
    max_rel        max |a - b| / max(|a|, |b|) (0 where both are 0), with its theta\n  \
    max_log_ratio  max |ln(a/b)| where both a and b exceed 1e-300, with its theta; undefined\n                 \
    (JSON null, empty CSV field) when they never both do\n  \
    l2_projected   sqrt(2 pi integral (a - b)^2 sin cos dtheta), adaptive quadrature\n  \
    l2_grid        Euclidean norm of a - b on theta_i = arccos(linspace(0, 1, 1000))\n  \
    a_peak/b_peak  the maxima of a and b, with their theta\n\n\
    --format json prints one object and --format csv one header and one row, with a, b, theta_from,\n\
    theta_to and each number by name (max_abs, max_abs_theta, ...); --metric NAME prints only that\n\
    number. With --degrees every theta is read and printed in degrees and named *_deg.\n\n\
    --pairs FILE|- compares every pair of a JSON Lines input ({\"a\": …, \"b\": …} or fit's\n\
    {\"target\": …, \"fit\": …} records) in parallel and writes them in input order: --format json one\n\
    object per line, --format csv a header and one row per pair, --metric one number per line, and\n\
    by default a table of one row per pair (its source line, the five metrics, both sides). JSON and\n\
    CSV records start with line (the pair's input line) and end with status (ok or error) and error\n\
    (why, on one line). A line that cannot be read or compared is such a row (an empty line with\n\
    --metric) and one error line naming it (stdin:<line> or <FILE>:<line>); the others are still\n\
    written, and the exit code is 2 (0 with --keep-going, which leaves the errors to the rows). A\n\
    closing line on stderr says how many pairs were written and how long it took (-q: none).\n\n\
    Exit 1 when a --max-error bound is exceeded (or bounds an undefined max_log_ratio), 2 on bad\n\
    input (an NDF against a Fresnel curve, an unknown --metric name).\n\n\
    Examples:\n  \
    ndfplot compare --a '{\"ndf\":\"trowbridge_reitz\",\"alpha_tr\":0.3}' --b '{\"ndf\":\"abc\",\"alpha_abc1\":23.5,\"alpha_abc2\":1.75}'\n  \
    ndfplot compare --a @a.json --b @b.json --theta-range 0:50 --degrees --metric max_log_ratio\n  \
    ndfplot compare --a @a.json --b @b.json --format json --max-error max_rel=1e-3 --max-error l2_projected=0.01\n  \
    ndfplot fit --target - --family abc --by l2 --format jsonl < targets.jsonl | ndfplot compare --pairs - --format csv"
)]
pub struct CompareArgs {
    /// The first side: a curve, or a CSV series {"data": "csv", "path": …, "x": …, "y": …}, as
    /// inline JSON, @FILE or - (one line on stdin).
    #[arg(
        long,
        value_name = "JSON|@FILE|-",
        allow_hyphen_values = true,
        required_unless_present = "pairs",
        requires = "b"
    )]
    pub a: Option<String>,
    /// The second side; two curves must be of the same kind.
    #[arg(
        long,
        value_name = "JSON|@FILE|-",
        allow_hyphen_values = true,
        required_unless_present = "pairs",
        requires = "a"
    )]
    pub b: Option<String>,
    /// Compare many pairs instead of --a and --b: a JSON Lines file, or - for stdin, one pair per
    /// line, {"a": <side>, "b": <side>} or a record of fit --format jsonl ({"target": …, "fit": …});
    /// each side as --a takes it (a CSV path resolves against the file's folder, or the working
    /// directory for -). One row (table row, JSON line, CSV row, --metric number) per pair, in input
    /// order.
    #[arg(
        long,
        value_name = "FILE|-",
        allow_hyphen_values = true,
        conflicts_with_all = ["a", "b"]
    )]
    pub pairs: Option<String>,
    /// Take every metric (and the peaks) over A ≤ theta ≤ B only: radians (pi/4 and other multiples
    /// of pi as --theta of eval reads them), or degrees with --degrees.
    #[arg(long = "theta-range", value_name = "A:B")]
    pub theta_range: Option<String>,
    /// Read --theta-range in degrees, and print every theta in degrees (named *_deg).
    #[arg(long)]
    pub degrees: bool,
    /// Output: a readable table, one JSON object (per line, one per pair), or CSV (a header and one
    /// row per pair) for scripts.
    #[arg(long, value_name = "FORMAT", default_value = "table",
        value_parser = choice(&ReportFormat::NAMES, &ReportFormat::ALL))]
    pub format: ReportFormat,
    /// Print only this number (max_abs, max_rel_theta, max_log_ratio, l2_projected, a_peak, …;
    /// any name of --format json); exit 2 when it is undefined.
    #[arg(long, value_name = "NAME", conflicts_with = "format")]
    pub metric: Option<String>,
    /// Fail (exit 1) when a metric exceeds a bound, as <metric>=<number> (for any pair of --pairs);
    /// repeatable.
    #[arg(long = "max-error", value_name = "METRIC=X")]
    pub max_error: Vec<String>,
    /// Also allow data files ({"data": "csv", "path": …}) inside DIR; by default a data path must stay
    /// inside the folder it resolves against (an @FILE's or the --pairs file's folder, else the
    /// working directory). Repeatable.
    #[arg(long = "allow-read", value_name = "DIR")]
    pub allow_read: Vec<PathBuf>,
    /// With --pairs: exit 0 even when some pairs could not be compared (their rows say status error).
    #[arg(long = "keep-going", requires = "pairs")]
    pub keep_going: bool,
}

/// Arguments of `ndfplot fit`.
#[derive(Debug, Args)]
#[command(after_long_help = "Methods:\n  \
    peak  D_fit(0) = D_target(0), the value at the normal (the notebook's manual peak matching)\n  \
    max   max over theta of D_fit = the target's maximum (differs for lobes peaking off the normal)\n  \
    l2    minimize l2_projected between the fit and the target\n\
    peak and max match one number: all parameters but one must be fixed. l2 fits every parameter\n\
    not fixed (Nelder-Mead in log coordinates within the family's domain, from several starts).\n\n\
    Output without --format: per target, the fitted curve as one line of canonical curve JSON on\n\
    stdout (feed it to eval) and residual=<x> (d0_rel | dmax_rel | l2_projected) on stderr.\n\
    --format csv|jsonl: one record per target with the columns (JSON fields)\n  \
    line,family,<each parameter of the family>,residual,metric,status,target,fit,error\n\
    line: the target's line (--target -) or position among --target arguments; target and fit:\n\
    canonical curve JSON; status: ok or error; error: why, on one line (empty when ok). Targets are\n\
    fitted in parallel and written in input order. A target that cannot be fitted is a row with\n\
    status error and an error line on stderr naming it (stdin:<line>); the others are still\n\
    written, and the exit code is 2 (0 with --keep-going, which leaves the errors to the rows).\n\
    A closing line on stderr says how many records were written and how long it took (-q: none).\n\n\
    Examples:\n  \
    ndfplot fit --target '{\"ndf\":\"trowbridge_reitz\",\"alpha_tr\":0.3}' --family abc --fix alpha_abc2=1.75\n  \
    ndfplot fit --target '{\"ndf\":\"trowbridge_reitz\",\"alpha_tr\":0.3}' --family abc --by l2\n  \
    cat targets.jsonl | ndfplot fit --target - --family abc --fix alpha_abc2=1.75 --format csv > fits.csv\n  \
    ndfplot eval --curve \"$(ndfplot fit --target @phong.json --family torrance_sparrow --by l2)\" --theta 0:1.5707963267948966:5")]
pub struct FitArgs {
    /// A target NDF: inline JSON, @FILE or - (one curve per line on stdin, JSON Lines). Repeatable.
    #[arg(
        long,
        value_name = "JSON|@FILE|-",
        allow_hyphen_values = true,
        required = true
    )]
    pub target: Vec<String>,
    #[arg(long, value_name = "NAME", help = family_help())]
    pub family: String,
    /// Fix a parameter of the family as key=value; the others are fitted. Repeatable.
    #[arg(long, value_name = "KEY=VALUE", allow_hyphen_values = true)]
    pub fix: Vec<String>,
    /// What to match: peak (D(0)), max (the maxima) or l2 (least l2_projected).
    #[arg(long, value_name = "METHOD", default_value = "peak")]
    pub by: String,
    /// Write one record per target, each parameter in its own column: jsonl or csv.
    #[arg(long, value_name = "FORMAT", value_parser = choice(&RecordFormat::NAMES, &RecordFormat::ALL))]
    pub format: Option<RecordFormat>,
    /// Exit 0 even when some targets could not be fitted (their records say status error).
    #[arg(long = "keep-going")]
    pub keep_going: bool,
}

/// Arguments of `ndfplot check`.
#[derive(Debug, Args)]
#[command(
    after_long_help = "For every distinct NDF of the scenes: 2 pi integral D sin cos dtheta over [0, pi/2] by\n\
    adaptive quadrature, with its error estimate and |integral - 1|, and its Smith consistency: the weak\n\
    white furnace G1(theta_o) A(theta_o) / cos theta_o farthest from 1 over theta_o in 0..89.9 degrees,\n\
    the front-facing projected area A integrated apart from Lambda; for every Fresnel curve the\n\
    hemispherical average 2 integral_0^1 F(c) c dc (reported, not checked). Difference series are skipped.\n\
    --format json prints a JSON array of one object per row and --format csv CSV, with the table's\n\
    column names (deviation null or empty for a Fresnel average, curve as JSON).\n\
    Exit 1 when an NDF's normalization or Smith consistency is off by more than --tolerance.\n\n\
    Examples:\n  \
    ndfplot check\n  \
    ndfplot check abc-vs-tr my-scenes/ --tolerance 1e-12\n  \
    ndfplot check --format csv > normalization.csv"
)]
pub struct CheckArgs {
    /// Scene spec files, or folders whose *.json are checked in name order. None: the built-in catalogue.
    #[arg(value_name = "SPEC.json|DIR")]
    pub paths: Vec<PathBuf>,
    /// Largest accepted |2 pi integral D sin cos dtheta - 1| and Smith-consistency deviation from 1.
    #[arg(long, value_name = "X", default_value_t = crate::pipeline::audit::DEFAULT_TOLERANCE, value_parser = float_in(0.0, 1.0))]
    pub tolerance: f64,
    /// Output: a readable table, a JSON array of one object per row, or CSV.
    #[arg(long, value_name = "FORMAT", default_value = "table",
        value_parser = choice(&ReportFormat::NAMES, &ReportFormat::ALL))]
    pub format: ReportFormat,
    /// Also allow data files ({"data": "csv", "path": …}) inside DIR; by default a data path must stay
    /// inside the folder of the spec naming it. Repeatable.
    #[arg(long = "allow-read", value_name = "DIR")]
    pub allow_read: Vec<PathBuf>,
}

/// Arguments of `ndfplot albedo`.
#[derive(Debug, Args)]
#[command(
    after_long_help = "Tables of the single-scattering microfacet BRDF f = F D G2 / (4 cos theta_o cos theta_i)\n\
    (docs/maths.md \"Masking–shadowing and albedo\"), on Cycles' grid: mu = cos theta_o = i/(n_mu - 1),\n\
    r = j/(n_r - 1), alpha = r^2 (--map r2), r (--map r) or sqrt(r) (--map sqrt); r maps to the family's\n\
    first parameter.\n\
    The mu = 0 row is the limit mu -> 0+, the r = 0 column the family's lobe at alpha = 0: the mirror\n\
    limit alpha -> 0+ (E = F(theta_o)) for a width, the uniform lobe 1/pi for phong and abc; gtr with\n\
    gamma_gtr < 1, whose lobe tends to (1 - gamma)/(pi sin^(2 gamma) theta), is refused.\n\n\
    Tables (--table, comma-separated for several in one output, e.g. e,average; CSV columns):\n  \
    e          mu,r,alpha,E,turquin_f0_1: E(mu) and Turquin's compensation factor 1/E (F0 = 1);\n             \
    with --fresnel mu,r,alpha,E_F, the albedo with F(theta_d)\n  \
    average    r,alpha,E_avg,kulla_conty_norm: E_avg = 2 integral E(mu) mu dmu and Kulla-Conty's\n             \
    1/(pi (1 - E_avg)) (empty, JSON null, where E_avg = 1); with --fresnel also F_avg and\n             \
    F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)) (E_avg stays F = 1). E_avg is within 1e-8\n             \
    (fixed rules in mu on its own nodes; the other tables within 1e-10)\n  \
    split-sum  mu,r,alpha,E_0,E_1,E_2,E_3: Belcour-Bati-Barla tables, E_k the albedo with F = b_k, so\n             \
    that E_F = sum c_k E_k for F = sum c_k b_k (see coeffs); no --fresnel\n  \
    dfg        mu,r,alpha,DFG1,DFG2: the split-sum pair of Schlick's Fresnel, DFG1 = E_F with\n             \
    F = 1 - Fc, DFG2 = E_F with F = Fc, Fc = (1 - cos theta_d)^5; no --fresnel\n\n\
    Auditing an engine's table (--against FILE --layout KEY=VALUE,...; tables e, average, dfg):\n\
    FILE is a CSV matrix (.csv, .txt), a C/C++ header holding one array (.h, .hpp, .c, .cpp, .inc)\n\
    or raw little-endian binary (anything else); regular files up to 64 MiB. Layout keys, defaults first:\n  \
    rows=mu|r cols=r|mu  the axis along each line of the file and along its columns\n  \
    grid=endpoints|centers  i/(n - 1) (Cycles) or texel centres (i + 1/2)/n (Filament, Unreal)\n  \
    map=r2|alpha|sqrt    alpha = r^2, the axis is alpha, alpha = sqrt(r)\n  \
    value=e|1-e|dfg1|dfg2  E (E_avg for average) or 1 - E; DFG1 or DFG2 with --table dfg\n  \
    encoding=text|f32|f16|unorm8|unorm16  raw files default to f32; unorm k/255, k/65535\n  \
    g2=(--g2)|height-correlated|separable   fresnel=none|given (given: the --fresnel curve)\n  \
    file=(extension)|csv|header|raw   clamp=0 (coordinates evaluated at max(c, clamp); Cycles 1e-4)\n  \
    channels=1 channel=0  numbers per cell (an RG or RGBA texture) and which one is audited\n\
    The grid is --size or --mu-count/--r-count when given, else the CSV's lines, else a square.\n\
    Prints max_abs, rms and max_rel (cells with |exact| >= 1e-3) with the worst cell (mu, r, engine,\n\
    exact); -o DIR writes audit.csv (every cell) and the heat map audit.svg/audit.png of\n\
    engine - exact; --max-error X exits 1 when max_abs > X.\n\n\
    The CSV starts with # lines naming the table, NDF, G2, map, Fresnel, grid, limits and accuracy\n\
    (a key whose value differs between tables once per table: # accuracy (average): ...);\n\
    --no-comments leaves them out, the header then the first line. Several tables share one CSV:\n\
    long, a leading table column and the union of their columns (empty where a table has none).\n\
    --shape matrix: per value a block, header the value's name then the r values, one row per mu\n\
    led by mu; the average one block, header r then the r values, one row per value led by its\n\
    name; blocks separated by an empty line. --format json prints one object per table with the\n\
    same keys, then \"columns\" and \"rows\" (long) or \"mu\", \"r\" and \"values\" (matrix: per value\n\
    an array per mu of the values per r); several tables, one object keyed by table name.\n\
    Unless -q, one closing line on stderr: what was written, where and how long it took.\n\
    Cells are computed in parallel; a progress bar shows on a terminal unless -q. Exit 2 on bad\n\
    input (unknown family, missing --fix, grid over the cap, a parameter out of its domain) or a\n\
    quadrature that does not converge.\n\n\
    Examples:\n  \
    ndfplot albedo > ggx_E.csv\n  \
    ndfplot albedo --table e,average -o ggx.csv\n  \
    ndfplot albedo --table average --size 32 --format json\n  \
    ndfplot albedo --shape matrix --no-comments --size 16 > ggx_E_16.csv\n  \
    ndfplot albedo --ndf beckmann --map r --fresnel '{\"fresnel\":\"exact\",\"eta\":1.5}' --size 16\n  \
    ndfplot albedo --ndf gtr --fix gamma_gtr=1.5 --table split-sum --mu-count 16 --r-count 16 -o gtr_split.csv\n  \
    ndfplot albedo --against ggx_E.csv --layout clamp=1e-4 --max-error 2e-6"
)]
pub struct AlbedoArgs {
    /// The NDF family, by name or alias (ggx); r maps to its first parameter, the others take --fix.
    #[arg(long, value_name = "FAMILY", default_value = "trowbridge_reitz")]
    pub ndf: String,
    /// Fix a parameter of the family other than its first as NAME=VALUE. Repeatable.
    #[arg(long, value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub fix: Vec<String>,
    /// How the roughness r maps to the first parameter: r2 (alpha = r^2, as Cycles, Filament, glTF),
    /// r (alpha = r) or sqrt (alpha = sqrt(r), pbrt-v4's RoughnessToAlpha). With --against the
    /// layout's map.
    #[arg(long, value_name = "MAP", default_value = "r2",
        value_parser = clap::builder::PossibleValuesParser::new(crate::model::albedo::RoughnessMap::KEYS.map(|(key, _)| key)))]
    pub map: String,
    /// Points on both axes, mu and r (2 to 1024; default 32, as Cycles).
    #[arg(long, value_name = "N", conflicts_with_all = ["mu_count", "r_count"])]
    pub size: Option<usize>,
    /// Points on the mu axis (2 to 1024; default 32); not for --table average.
    #[arg(long, value_name = "N")]
    pub mu_count: Option<usize>,
    /// Points on the r axis (2 to 1024; default 32).
    #[arg(long, value_name = "N")]
    pub r_count: Option<usize>,
    /// How masking and shadowing combine into G2.
    #[arg(long, value_name = "MODEL", default_value = "height-correlated",
        value_parser = clap::builder::PossibleValuesParser::new(crate::model::masking::G2Model::NAMES.map(|(name, _)| name)))]
    pub g2: String,
    /// A Fresnel factor F(theta_d) inside the integral: a Fresnel curve as inline JSON
    /// ('{"fresnel":"exact","eta":1.5}') or @FILE. Default F = 1.
    #[arg(long, value_name = "JSON|@FILE")]
    pub fresnel: Option<String>,
    /// The tables, comma-separated, each at most once (case-insensitive): e (E per mu and r),
    /// average (E_avg per r), split-sum (E_0..E_3 per mu and r), dfg (the split-sum pair DFG1, DFG2
    /// per mu and r); e.g. e,average. All on one grid, in one output.
    #[arg(long, value_name = "TABLE[,TABLE...]", default_value = "e")]
    pub table: String,
    /// The layout: long (one row per (mu, r) cell) or matrix (rows by mu, one column per r).
    #[arg(long, value_name = "SHAPE", default_value = "long",
        value_parser = choice(&TableShape::NAMES, &TableShape::ALL))]
    pub shape: TableShape,
    /// CSV without the # metadata lines: the header is the first line (--format json still
    /// carries the metadata).
    #[arg(long)]
    pub no_comments: bool,
    /// Output: CSV with # metadata lines, or JSON (an object per table).
    #[arg(long, value_name = "FORMAT", default_value = "csv",
        value_parser = choice(&ReportFormat::NAMES, &[ReportFormat::Csv, ReportFormat::Json]))]
    pub format: ReportFormat,
    /// Write the table to FILE (atomically: a temporary renamed into place) instead of stdout; an
    /// existing FILE that is not a regular file (device, FIFO, socket, folder) is refused (exit 2).
    /// - is stdout. With --against, a folder DIR for audit.csv, audit.svg and audit.png.
    #[arg(short, long, value_name = "FILE")]
    pub out: Option<PathBuf>,
    /// Audit an engine's table: compare FILE with the exact table on the engine's grid, as
    /// --layout describes it (see --help).
    #[arg(long, value_name = "FILE")]
    pub against: Option<PathBuf>,
    /// What --against's numbers are: KEY=VALUE,... (rows, cols, grid, map, value, encoding, g2,
    /// fresnel, file, clamp, channels, channel; see --help).
    #[arg(long, value_name = "KEY=VALUE,...", requires = "against")]
    pub layout: Option<String>,
    /// With --against: exit 1 when max_abs exceeds X.
    #[arg(long, value_name = "X", requires = "against")]
    pub max_error: Option<f64>,
}

/// Arguments of `ndfplot bench`.
#[derive(Debug, Args)]
#[command(
    after_long_help = "Sections (CSV columns section,case,method,setting,samples,seconds,error):\n  \
    drawing        uniform N = 16 ... 65536 and adaptive tolerances: the drawn polyline's largest\n                 \
    deviation from the true curve in px, narrow and broad lobes; uniform_needed: the fewest\n                 \
    uniform samples within 0.25 px\n  \
    normalization  Torrance-Sparrow (Dawson/Faddeeva vs quadrature), ABC (stable vs closed form vs\n                 \
    quadrature): relative error against docs/maths.md's 15-digit values; SGD's e^a1 Gamma(1 - a2, a1)\n                 \
    (series and continued fraction vs quadrature) against mpmath\n  \
    throughput     D values written per second by eval (the path of every output) on a 2^20-point\n                 \
    grid (two 2^16-point tasks per thread if that is more), on one thread and on all threads\n                 \
    (error: largest relative difference from the one-thread values)\n  \
    lambda         Smith Lambda per family by its own route (closed form or quadrature) and, for\n                 \
    the closed forms, also by the generic quadrature: time per value and the worst relative\n                 \
    error against the 40-digit references of tests/data/reference/lambda.csv\n  \
    albedo_table   one 32 x 32 GGX albedo table (alpha = r^2, height-correlated G2, F = 1) on all\n                 \
    threads, against Cycles' table_ggx_E\n\n\
    Times are medians of 5 batches of at least 50 ms; machines shared with other work give noisy numbers.\n\n\
    Example:\n  \
    ndfplot bench -o plots/bench"
)]
pub struct BenchArgs {
    /// Output folder (created if missing) for bench.csv, bench.svg and bench.png; names taken by
    /// something other than a regular file are refused (exit 2), and so is - (not a folder).
    #[arg(short, long, value_name = "DIR", default_value = "plots/bench")]
    pub out: PathBuf,
}
