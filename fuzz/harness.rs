//! What the fuzzer checks, shared by the fuzz target (`fuzz_targets/spec.rs`) and the corpus replay
//! test (`tests/cli/robustness.rs`).
//!
//! The first byte picks the mode. Even: the rest is a scene spec, parsed, validated and, when it
//! is small enough to keep the fuzzer fast, evaluated into its figure CSV, exactly as `render`
//! does; it may be valid or not, but it must never panic, a rejected spec must carry at least one
//! problem, and an accepted one must evaluate to finite numbers or a reported error. 1 mod 8: the
//! rest picks a curve model, a signature and parameter values (domain edges and arbitrary
//! doubles), which must either be rejected or give a finite value at every θ of [0, π/2],
//! non-negative for an NDF and within [0, 1] for the exact, Schlick and Lazanyi Fresnel curves.
//! 3 mod 8: `eval`'s path, a θ list and a curve (see [`eval`]). 5 mod 8: the rest is a JSON Lines
//! batch on standard input, read as `compare --pairs -` and as `--target -` (see [`batch`]).
//! 7 mod 16: an albedo `--table` list, an engine table's `--layout` and the table file it
//! describes (see [`engine_table`]). 15 mod 16: `render --check` against hostile stored files
//! (see [`stored`]).

use ndfplot::cmd::albedo::{MAX_AXIS, parse_tables};
use ndfplot::cmd::eval::{parse_theta_list, write_table};
use ndfplot::model::curve::Curve;
use ndfplot::model::fresnel::FresnelModel;
use ndfplot::model::masking::G2Model;
use ndfplot::output::stored::{DEFAULT_TOLERANCE, compare};
use ndfplot::output::{self, Format};
use ndfplot::pipeline::figure::Figure;
use ndfplot::pipeline::plan::{Outputs, plan};
use ndfplot::pipeline::provenance::Provenance;
use ndfplot::pipeline::resolve;
use ndfplot::pipeline::sample::evaluate_all;
use ndfplot::problem::{MAX_EXCERPT_CHARS, Problems};
use ndfplot::spec::angle::AngleUnit;
use ndfplot::spec::curve::{Model, ParamKind};
use ndfplot::spec::input::{Record, read_curves, read_pairs};
use ndfplot::spec::lut::{DecodeError, Encoding, LutFile, decode, parse_layout};
use ndfplot::spec::scene::{Sampling, Scene};
use ndfplot::spec::source::{self, CanvasOverride};
use std::f64::consts::FRAC_PI_2;
use std::path::PathBuf;
use std::sync::OnceLock;

/// Most table points of a spec that is evaluated; larger valid specs are only validated.
const MAX_FUZZ_POINTS: usize = 20_000;

/// Parameter values at and around the domain edges of the models.
const EDGES: [f64; 20] = [
    0.0,
    -0.0,
    1.0,
    -1.0,
    0.5,
    2.0,
    1e-300,
    5e-324,
    1e-150,
    1e-8,
    0.999_999_999,
    1.000_000_001,
    1e4,
    1e8,
    1e150,
    1e300,
    f64::MAX,
    f64::MIN_POSITIVE,
    100.0,
    3.0,
];

/// Runs one input; panics when an invariant breaks.
pub fn run(data: &[u8]) {
    let Some((&mode, rest)) = data.split_first() else {
        return;
    };
    match mode % 16 {
        m if m % 2 == 0 => spec(rest),
        1 | 9 => curve(rest),
        3 | 11 => eval(rest),
        5 | 13 => batch(rest),
        7 => engine_table(rest),
        _ => stored(rest),
    }
}

/// Most angles of a θ list that is evaluated; longer valid lists are only parsed.
const MAX_FUZZ_THETAS: usize = 4096;

/// `eval`'s path: the text up to the first line break is a `--theta` list (in degrees when the
/// text starts with `d`), the rest a curve. A list must parse or be refused; a parsed list of a
/// valid curve must stream a table of one header and one row per angle, each with the θ and one
/// value, or report an error.
fn eval(bytes: &[u8]) {
    let Ok(text) = std::str::from_utf8(bytes) else {
        return;
    };
    let (theta, curve) = text.split_once('\n').unwrap_or((text, ""));
    let (unit, theta) = match theta.strip_prefix('d') {
        Some(rest) => (AngleUnit::Degrees, rest),
        None => (AngleUnit::Radians, theta),
    };
    let Ok(thetas) = parse_theta_list(theta, unit) else {
        return;
    };
    assert!(!thetas.is_empty(), "a parsed θ list has an angle");
    let Ok(node) = ndfplot::spec::json::parse(curve) else {
        return;
    };
    let Ok(spec) = ndfplot::spec::curve::parse(&node, "") else {
        return;
    };
    let Ok(curve) = resolve::curve(&spec) else {
        return;
    };
    if thetas.len() > MAX_FUZZ_THETAS {
        return;
    }
    let mut table = Vec::new();
    let written = write_table(&[curve], &thetas, unit, &mut |bytes| {
        table.extend_from_slice(bytes);
        Ok(true)
    });
    if written.is_ok() {
        let text = String::from_utf8(table).expect("the table is UTF-8");
        assert_eq!(text.lines().count(), thetas.len() + 1, "a row per angle");
        assert!(text.lines().skip(1).all(|row| row.split(',').count() == 2));
    }
}

fn spec(bytes: &[u8]) {
    let Ok(text) = std::str::from_utf8(bytes) else {
        return;
    };
    let sources = [("fuzz.json".to_string(), text.to_string(), None)];
    let scenes = match resolve::scenes(source::load_scenes(&sources, CanvasOverride::default())) {
        Ok(scenes) => scenes,
        Err(error) => {
            let message = error.to_string();
            assert!(
                message.lines().count() > 0
                    && message.lines().all(|l| l.starts_with("error: fuzz.json")),
                "{message}"
            );
            return;
        }
    };
    let points: usize = scenes
        .iter()
        .flat_map(|s| {
            let samples = match s.sampling.for_table() {
                Sampling::Uniform(n) => n,
                _ => 1000,
            };
            s.panels.iter().map(move |p| {
                p.curves.len() * samples + p.data.iter().map(|d| d.dataset.len()).sum::<usize>()
            })
        })
        .sum();
    if points > MAX_FUZZ_POINTS {
        return;
    }
    let Some(figures) = figures(&scenes, bytes) else {
        return;
    };
    for figure in figures {
        let csv = output::encode(&figure, Format::Csv)
            .expect("CSV encoding cannot fail")
            .expect("every figure has a CSV");
        let text = String::from_utf8(csv).expect("the CSV is UTF-8");
        assert!(
            !text.contains("NaN") && !text.contains("inf"),
            "non-finite value in {text}"
        );
    }
}

/// The figures of `scenes` read from the spec `bytes`, planned, evaluated and assembled as
/// `render` does; `None` when evaluating reports an error.
fn figures(scenes: &[Scene], bytes: &[u8]) -> Option<Vec<Figure>> {
    let plan = plan(
        scenes,
        Outputs {
            drawn: true,
            table: true,
        },
    );
    let evaluated = evaluate_all(&plan).ok()?;
    let provenance = Provenance::of_spec(bytes);
    Some(
        scenes
            .iter()
            .zip(plan.table.as_ref().expect("tables were planned"))
            .map(|(scene, feeds)| Figure::assemble(scene, &provenance, feeds, &evaluated))
            .collect(),
    )
}

/// Reads bytes from the front of a slice, zeros once it is exhausted.
struct Bytes<'a>(&'a [u8]);

impl Bytes<'_> {
    fn byte(&mut self) -> u8 {
        let (&first, rest) = self.0.split_first().unwrap_or((&0, &[]));
        self.0 = rest;
        first
    }

    fn number(&mut self) -> f64 {
        let pick = self.byte();
        if pick < 128 {
            return EDGES[usize::from(pick) % EDGES.len()];
        }
        let value = f64::from_bits(u64::from_le_bytes(std::array::from_fn(|_| self.byte())));
        if value.is_finite() {
            value
        } else {
            f64::from(pick)
        }
    }
}

fn curve(bytes: &[u8]) {
    let mut input = Bytes(bytes);
    let models = ndfplot::spec::schema::models();
    let model = models[usize::from(input.byte()) % models.len()];
    let signatures = model.signatures();
    let params = &signatures[usize::from(input.byte()) % signatures.len()];
    let mut text = format!("{{\"{}\":\"{}\"", model.key(), model.name());
    for param in params {
        match param.kind {
            ParamKind::Number => {
                text.push_str(&format!(",\"{}\":{:?}", param.name, input.number()))
            }
            ParamKind::Flag => {
                text.push_str(&format!(",\"{}\":{}", param.name, input.byte() % 2 == 1))
            }
        }
    }
    text.push('}');
    let node = ndfplot::spec::json::parse(&text).expect("the generated curve is valid JSON");
    let Ok(spec) = ndfplot::spec::curve::parse(&node, "") else {
        return;
    };
    let curve = resolve::curve(&spec).expect("a curve argument has no fit to fail");
    let just_below = f64::from_bits(FRAC_PI_2.to_bits() - 1);
    let mut thetas = vec![
        0.0,
        5e-324,
        1e-300,
        1e-8,
        0.5,
        1.0,
        FRAC_PI_2 - 1e-9,
        just_below,
        FRAC_PI_2,
    ];
    thetas.extend((0..8).map(|_| {
        f64::from(u16::from_le_bytes([input.byte(), input.byte()])) / f64::from(u16::MAX)
            * FRAC_PI_2
    }));
    let bounded = matches!(
        model,
        Model::Fresnel(FresnelModel::Exact | FresnelModel::Schlick | FresnelModel::Lazanyi)
    );
    for theta in thetas {
        let value = curve.eval(theta);
        assert!(
            value.is_finite(),
            "{} at θ = {theta:?} gives {value:?}",
            curve.canonical_json()
        );
        if matches!(curve, Curve::Ndf(_)) {
            assert!(
                value >= 0.0,
                "{} at θ = {theta:?} gives {value:?}",
                curve.canonical_json()
            );
        }
        if bounded {
            assert!(
                (0.0..=1.0 + 1e-12).contains(&value),
                "{} at θ = {theta:?} gives {value:?}",
                curve.canonical_json()
            );
        }
    }
}

/// Whether `text` holds a control character other than the line breaks between report lines.
fn has_raw_control(text: &str) -> bool {
    text.chars().any(|c| c != '\n' && c.is_control())
}

/// The source of `render --check`'s comparison, whose message wording a stored file may repeat.
const STORED_SOURCE: &str = include_str!("../src/output/stored.rs");

/// The source of the engine-table decoder, whose message wording a table file may repeat.
const LUT_SOURCE: &str = include_str!("../src/spec/lut.rs");

/// The source of the image-table decoder, likewise.
const LUT_IMAGE_SOURCE: &str = include_str!("../src/spec/lut_image.rs");

/// Panics when a line of `report` quotes more than [`MAX_EXCERPT_CHARS`] consecutive characters
/// of the untrusted `quoted` that none of the `trusted` texts (what the run itself produced, and
/// the wording of the messages) holds. An excerpt ends at its `…`, and the quote before it may
/// match the text beside it in the file: a run holding `…` is not counted, and a run is counted
/// from three characters past the limit.
fn assert_excerpts_only(report: &str, quoted: &str, trusted: &[&str]) {
    for line in report.lines() {
        let chars = unescaped(line);
        for window in chars.windows(MAX_EXCERPT_CHARS + 4) {
            if window.contains(&'…') {
                continue;
            }
            let window: String = window.iter().collect();
            assert!(
                !quoted.contains(&window) || trusted.iter().any(|t| t.contains(&window)),
                "a line quotes more than an excerpt of the stored content: {line}"
            );
        }
    }
}

/// The characters of `line` with the escapes of [`ndfplot::problem::one_line`] turned back into
/// the characters they stand for.
fn unescaped(line: &str) -> Vec<char> {
    let mut out = Vec::new();
    let mut rest = line;
    while let Some(c) = rest.chars().next() {
        let (ch, len) = match rest.get(..6).and_then(|e| e.strip_prefix("\\u")) {
            Some(hex) => match u32::from_str_radix(hex, 16).ok().and_then(char::from_u32) {
                Some(ch) => (ch, 6),
                None => (c, c.len_utf8()),
            },
            None => match rest.get(..2) {
                Some("\\n") => ('\n', 2),
                Some("\\r") => ('\r', 2),
                Some("\\t") => ('\t', 2),
                _ => (c, c.len_utf8()),
            },
        };
        out.push(ch);
        rest = &rest[len..];
    }
    out
}

/// The invariants of one batch's records: each either read or carrying at least one problem,
/// printed without raw control characters, under its source `stdin:<line>`, the lines increasing
/// and within the input's `lines`.
fn check_records<T>(
    records: impl Iterator<Item = ndfplot::error::Result<Record<T>>>,
    lines: usize,
) {
    let mut last = 0;
    for record in records {
        let record = record.expect("an input within the cap is read to its end");
        assert!(
            record.line > last && record.line <= lines,
            "line {} after {last} of {lines}",
            record.line
        );
        last = record.line;
        assert_eq!(record.source, format!("stdin:{}", record.line));
        if let Err(problems) = &record.value {
            assert!(!problems.list.is_empty(), "a refused record has a problem");
            check_problems(problems);
        }
    }
}

/// A refused input's problems: each with a message, printed one per line, no raw control
/// character.
fn check_problems(problems: &Problems) {
    assert!(problems.list.iter().all(|p| !p.message.is_empty()));
    let printed = problems.to_string();
    assert!(!has_raw_control(&printed), "{printed:?}");
}

/// A JSON Lines batch on standard input, read as `compare --pairs -` and as `--target -`: never a
/// panic; the whole call fails only when no line holds anything, and otherwise yields one record
/// per non-blank line (see [`check_records`]).
fn batch(bytes: &[u8]) {
    let lines = bytes.split(|&b| b == b'\n').count();
    let content = bytes.strip_prefix("\u{feff}".as_bytes()).unwrap_or(bytes);
    let blank = content.trim_ascii().is_empty();
    match read_pairs("-", &[], std::io::Cursor::new(bytes.to_vec())) {
        Ok(pairs) => check_records(pairs, lines),
        Err(error) => assert!(blank, "{error}"),
    }
    match read_curves(
        &["-".into()],
        "--target",
        std::io::Cursor::new(bytes.to_vec()),
    ) {
        Ok(curves) => check_records(curves, lines),
        Err(error) => assert!(blank, "{error}"),
    }
}

/// The table file names whose extensions pick each kind of file (an image is one by its first
/// bytes under any name too).
const TABLE_PATHS: [&str; 8] = [
    "e.csv", "e.txt", "e.h", "e.cpp", "e.bin", "e", "e.png", "e.exr",
];

/// An albedo engine table: the first byte picks the file name (its kind) and the G2 model, the text
/// up to the first line break is both a `--table` list and a `--layout`, the rest the table file.
/// The list parses into distinct tables, one per name, or errs naming `--table`; the layout parses
/// into a consistent layout or errs with a message; the file decodes under it, or errs with a
/// message without raw control characters that quotes at most an excerpt of the file.
fn engine_table(bytes: &[u8]) {
    let mut input = Bytes(bytes);
    let pick = usize::from(input.byte());
    let path = TABLE_PATHS[pick % TABLE_PATHS.len()];
    let g2 = if pick / TABLE_PATHS.len() % 2 == 0 {
        G2Model::HeightCorrelated
    } else {
        G2Model::Separable
    };
    let rest = input.0;
    let split = rest.iter().position(|&b| b == b'\n').unwrap_or(rest.len());
    let (line, file) = (&rest[..split], rest.get(split + 1..).unwrap_or(&[]));
    let Ok(line) = std::str::from_utf8(line) else {
        return;
    };
    match parse_tables(line) {
        Ok(tables) => {
            assert_eq!(tables.len(), line.split(',').count(), "one table per name");
            assert!(
                tables
                    .iter()
                    .enumerate()
                    .all(|(i, t)| !tables[..i].contains(t)),
                "each table once"
            );
        }
        Err(error) => assert!(error.to_string().contains("--table"), "{error}"),
    }
    let layout = match parse_layout(line, path, g2) {
        Ok(layout) => layout,
        Err(problems) => {
            assert!(!problems.list.is_empty(), "a refused layout has a problem");
            check_problems(&problems);
            return;
        }
    };
    // Without `channels=` the channel is checked against the file's own count (an image's).
    assert!(layout.rows != layout.cols);
    assert!(layout.channel < layout.channels || !layout.given.contains(&"channels"));
    assert!((0.0..1.0).contains(&layout.clamp));
    assert!(!(layout.file == LutFile::Raw && layout.encoding == Encoding::Text));
    match decode(file, &layout, MAX_AXIS) {
        Ok(decoded) => {
            let image = matches!(decoded.layout.file, LutFile::Png | LutFile::Exr);
            if let Some((rows, width)) = decoded.shape {
                let per_cell = if image { decoded.layout.channels } else { 1 };
                assert_eq!(
                    rows * width * per_cell,
                    decoded.values.len(),
                    "the shape holds every value"
                );
                if image {
                    assert!(rows.max(width) <= MAX_AXIS, "an image within the axis cap");
                }
            }
        }
        Err(DecodeError::File(message) | DecodeError::Layout(_, message)) => {
            assert!(
                !message.is_empty() && !has_raw_control(&message),
                "{message:?}"
            );
            assert_excerpts_only(
                &message,
                &String::from_utf8_lossy(file),
                &[LUT_SOURCE, LUT_IMAGE_SOURCE],
            );
        }
    }
}

/// The small scene whose figure the stored files are compared with: two panels, a handful of
/// samples each.
const STORED_SCENE: &str = r#"{"id": "fuzz", "sampling": {"uniform": 5}, "panels": [
  {"title": "D", "curves": [{"ndf": "beckmann", "alpha_b": 0.5}, {"ndf": "phong", "alpha_p": 8}]},
  {"title": "F", "curves": [{"fresnel": "schlick", "f0": 0.04}]}
]}"#;

/// The CSV and SVG `render` makes of [`STORED_SCENE`], made once.
fn stored_scene() -> &'static (Vec<u8>, Vec<u8>) {
    static RENDERED: OnceLock<(Vec<u8>, Vec<u8>)> = OnceLock::new();
    RENDERED.get_or_init(|| {
        let sources = [("fuzz.json".to_string(), STORED_SCENE.to_string(), None)];
        let scenes = resolve::scenes(source::load_scenes(&sources, CanvasOverride::default()))
            .expect("the stored scene is valid");
        let figure = &figures(&scenes, STORED_SCENE.as_bytes()).expect("it evaluates")[0];
        let encoded = |format| {
            output::encode(figure, format)
                .expect("the figure encodes")
                .expect("it has the format")
        };
        (encoded(Format::Csv), encoded(Format::Svg))
    })
}

/// A folder of the system's temporary folder for this process and thread, holding the stored
/// files of one input while it runs (removed after it).
fn stored_dir() -> PathBuf {
    let thread = format!("{:?}", std::thread::current().id());
    let dir = std::env::temp_dir().join(format!(
        "ndfplot-fuzz-stored-{}-{}",
        std::process::id(),
        thread.trim_start_matches("ThreadId(").trim_end_matches(')')
    ));
    std::fs::create_dir_all(&dir).expect("the temporary folder is writable");
    dir
}

/// `render --check` against hostile stored files. The first byte picks what the rest is, 0: the
/// stored CSV of the scene's figure; 1: its stored SVG (next to a matching CSV); 2: the rendered
/// and the stored CSV at once; 3: the rendered and the stored SVG at once. Never a panic; a stored
/// file equal to the rendered one always matches (an unreadable rendered CSV being an error, or
/// reported as an unreadable stored one); and no report line holds a raw control character or quotes more than an excerpt of a stored
/// file.
fn stored(bytes: &[u8]) {
    let Some((&pick, rest)) = bytes.split_first() else {
        return;
    };
    let (csv, svg) = stored_scene();
    let (rendered, stored) = match pick % 4 {
        0 => ([csv.as_slice(), svg], [rest, svg]),
        1 => ([csv.as_slice(), svg], [csv.as_slice(), rest]),
        2 => ([rest, svg.as_slice()], [rest, svg]),
        _ => ([csv.as_slice(), rest], [csv.as_slice(), rest]),
    };
    let dir = stored_dir();
    let names = ["fuzz.csv", "fuzz.svg"];
    for (name, content) in names.iter().zip(stored) {
        std::fs::write(dir.join(name), content).expect("the stored file is written");
    }
    let outputs: Vec<(String, Vec<u8>)> = names
        .iter()
        .zip(rendered)
        .map(|(name, content)| (name.to_string(), content.to_vec()))
        .collect();
    let outcome = compare(&dir, &outputs, DEFAULT_TOLERANCE);
    std::fs::remove_dir_all(&dir).expect("the temporary folder is removed");
    let (report, ok) = match outcome {
        Ok(result) => result,
        Err(error) => {
            assert_eq!(
                pick % 4,
                2,
                "only a rendered CSV may be unreadable: {error}"
            );
            return;
        }
    };
    // A stored CSV equal to an unreadable rendered one is reported unreadable, not an error.
    let unreadable = pick % 4 == 2 && report.starts_with("fuzz.csv: stored CSV unreadable");
    if pick % 4 >= 2 && !unreadable {
        assert!(
            ok,
            "a stored file equal to the rendered one differs: {report}"
        );
    }
    assert!(!has_raw_control(&report), "{report:?}");
    let shown = dir.display().to_string();
    let mut trusted = vec![STORED_SOURCE, shown.as_str()];
    let rendered: Vec<String> = rendered
        .iter()
        .map(|r| String::from_utf8_lossy(r).into_owned())
        .collect();
    if pick % 4 < 2 {
        trusted.extend(rendered.iter().map(String::as_str));
    }
    // The last line is the summary: counts and the folder, no stored text.
    let (details, _summary) = report.trim_end().rsplit_once('\n').unwrap_or(("", &report));
    for content in stored {
        assert_excerpts_only(details, &String::from_utf8_lossy(content), &trusted);
    }
}
