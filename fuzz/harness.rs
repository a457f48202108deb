//! What the fuzzer checks, shared by the fuzz target (`fuzz_targets/spec.rs`) and the corpus replay
//! test (`tests/cli/robustness.rs`).
//!
//! The first byte picks the mode. Even: the rest is a scene spec, parsed, validated and, when it
//! is small enough to keep the fuzzer fast, evaluated into its figure CSV, exactly as `render`
//! does; it may be valid or not, but it must never panic, a rejected spec must carry at least one
//! problem, and an accepted one must evaluate to finite numbers or a reported error. 1 mod 4: the
//! rest picks a curve model, a signature and parameter values (domain edges and arbitrary
//! doubles), which must either be rejected or give a finite value at every θ of [0, π/2],
//! non-negative for an NDF and within [0, 1] for the exact, Schlick and Lazanyi Fresnel curves.
//! 3 mod 4: `eval`'s path, a θ list and a curve (see [`eval`]).

use ndfplot::cmd::eval::{parse_theta_list, write_table};
use ndfplot::model::curve::Curve;
use ndfplot::model::fresnel::FresnelModel;
use ndfplot::output::{self, Format};
use ndfplot::pipeline::figure::Figure;
use ndfplot::pipeline::plan::{Outputs, plan};
use ndfplot::pipeline::provenance::Provenance;
use ndfplot::pipeline::resolve;
use ndfplot::pipeline::sample::evaluate_all;
use ndfplot::spec::angle::AngleUnit;
use ndfplot::spec::curve::{Model, ParamKind};
use ndfplot::spec::scene::Sampling;
use ndfplot::spec::source::{self, CanvasOverride};
use std::f64::consts::FRAC_PI_2;

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
    match mode % 4 {
        0 | 2 => spec(rest),
        1 => curve(rest),
        _ => eval(rest),
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
    let plan = plan(
        &scenes,
        Outputs {
            drawn: true,
            table: true,
        },
    );
    let Ok(evaluated) = evaluate_all(&plan) else {
        return;
    };
    let provenance = Provenance::of_spec(bytes);
    for (scene, feeds) in scenes
        .iter()
        .zip(plan.table.as_ref().expect("tables were planned"))
    {
        let figure = Figure::assemble(scene, &provenance, feeds, &evaluated);
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
