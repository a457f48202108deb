//! The measurements of `ndfplot bench`: run time against error for drawing (uniform grids against
//! adaptive sampling), for normalization routes, evaluation throughput per family, Smith Λ routes
//! (closed forms against quadrature) and one full albedo table.
//!
//! Owns the timing loop and the measured cases. Every duration comes from a [`Clock`] it is handed,
//! so tests pass a fake clock and get deterministic results; it writes nothing (the subcommand turns
//! [`Row`]s into a CSV and a figure). Timings are never part of the catalogue or of `render --check`.

use crate::model::albedo::{
    AlbedoTable, Density, Lambda, Microfacet, RoughnessMap, albedo_table, surface_of,
};
use crate::model::masking::{G2Model, lambda_by_integral};
use crate::model::math::quad::{QuadError, integrate};
use crate::model::math::special::upper_gamma_scaled;
use crate::model::math::tolerance::floored_relative_difference;
use crate::model::ndf::{Abc, Family, Ndf, TorranceSparrow};
use crate::output::csv::Table;
use crate::pipeline::adaptive::{self, Frame, PixelMap};
use crate::spec::look::Scale;
use rayon::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI};
use std::time::{Duration, Instant};

/// A monotonic clock: the time elapsed since some fixed origin.
pub trait Clock {
    /// Time since the clock's origin.
    fn now(&self) -> Duration;
}

/// The system's monotonic clock.
#[derive(Debug, Clone, Copy)]
pub struct SystemClock(Instant);

impl SystemClock {
    /// A clock whose origin is now.
    pub fn new() -> SystemClock {
        SystemClock(Instant::now())
    }
}

impl Default for SystemClock {
    fn default() -> Self {
        SystemClock::new()
    }
}

impl Clock for SystemClock {
    fn now(&self) -> Duration {
        self.0.elapsed()
    }
}

/// How long and how often each case is timed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// A timed batch repeats the case until it has run at least this long.
    pub min_batch: Duration,
    /// Batches per case; the median batch is reported (robust to a shared machine's noise).
    pub batches: usize,
    /// Points of the throughput grids.
    pub throughput_points: usize,
}

impl Settings {
    /// The settings of `ndfplot bench`: 50 ms batches, median of 5, grids of 2²⁰ points (8 MiB:
    /// beyond the per-core caches, so that the memory write is part of a sample's cost), or of two
    /// [`TASK_POINTS`] tasks per rayon thread where that is more, so that the all-threads rows
    /// keep every thread busy.
    pub fn standard() -> Settings {
        Settings {
            min_batch: Duration::from_millis(50),
            batches: 5,
            throughput_points: THROUGHPUT_POINTS
                .max(2 * rayon::current_num_threads() * TASK_POINTS),
        }
    }
}

/// The smallest throughput grid of `ndfplot bench`.
const THROUGHPUT_POINTS: usize = 1 << 20;

/// Points per parallel task of the all-threads throughput rows: 2¹⁶ points at 3–30 ns each take
/// 0.2–2 ms, so rayon's few-µs cost of handing out a task stays below 1 %.
const TASK_POINTS: usize = 1 << 16;

/// One measured case.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// `drawing`, `normalization`, `throughput`, `lambda` or `albedo_table`.
    pub section: &'static str,
    /// What is measured: a curve in canonical JSON, or a family name.
    pub case: String,
    /// The method: `uniform`, `adaptive`, `uniform_needed` (the fewest uniform samples within
    /// [`DRAWING_TOLERANCE_PX`]), a normalization route, `eval_1_thread`, `eval_all_threads`, a Λ
    /// route (`closed_form`, `quadrature`), `table`.
    pub method: String,
    /// The method's setting: N for uniform grids, the tolerance in px for adaptive sampling, the
    /// quadrature tolerance, the thread count; 0 for a route without one.
    pub setting: f64,
    /// Samples (points drawn, D values written, Λ values or table cells computed); 1 for a
    /// normalization.
    pub samples: usize,
    /// Median seconds per run of the case (per Λ value for `lambda`, per table for
    /// `albedo_table`).
    pub seconds: f64,
    /// Drawing: the polyline's largest deviation from the curve in pixels. Normalization: relative
    /// error against the reference. Throughput: largest relative difference from `eval` point by
    /// point (0: the block path on every thread count computes the same bits). Λ: largest floored relative error
    /// against the references. Albedo table: largest absolute difference from Cycles' table.
    pub error: f64,
}

/// Median seconds per call of `f`: [`Settings::batches`] batches, each repeating `f` until
/// [`Settings::min_batch`] has passed (the repeat count doubles from 1).
pub fn time(clock: &dyn Clock, settings: &Settings, f: &mut dyn FnMut()) -> f64 {
    let mut per_call: Vec<f64> = (0..settings.batches.max(1))
        .map(|_| {
            let mut calls = 1u64;
            loop {
                let start = clock.now();
                for _ in 0..calls {
                    f();
                }
                let elapsed = clock.now().saturating_sub(start);
                if elapsed >= settings.min_batch || calls >= MAX_CALLS_PER_BATCH {
                    return elapsed.as_secs_f64() / calls as f64;
                }
                calls *= 2;
            }
        })
        .collect();
    per_call.sort_by(f64::total_cmp);
    per_call[per_call.len() / 2]
}

/// Cap on the calls of one batch, for a clock that does not advance.
const MAX_CALLS_PER_BATCH: u64 = 1 << 20;

/// The tolerance the drawing section's `uniform_needed` rows are computed for (the default).
pub const DRAWING_TOLERANCE_PX: f64 = crate::spec::scene::DEFAULT_TOLERANCE_PX;
/// Plot area of the drawing section, px: a one-panel figure of 640 × 400 px less its axes.
const DRAWING_AREA_PX: (f64, f64) = (560.0, 330.0);
/// Uniform grid sizes 2⁴ … 2¹⁶.
const UNIFORM_POWERS: std::ops::RangeInclusive<u32> = 4..=16;
/// Adaptive tolerances in px, coarse to fine.
const TOLERANCES_PX: [f64; 7] = [4.0, 2.0, 1.0, 0.5, 0.25, 0.125, 0.0625];
/// The error of a polyline is probed at about this many θ in all (at least 8 per segment).
const ERROR_PROBES: usize = 1 << 18;
/// Largest uniform grid `uniform_needed` searches.
const MAX_UNIFORM_SEARCH: usize = 1 << 22;

/// The drawing cases: the narrow lobes of the catalogue's extremes and two broad ones.
pub fn drawing_cases() -> Vec<Ndf> {
    let build = |family: Family, alpha: f64| family.build(&[alpha]).expect("in the domain");
    vec![
        build(Family::Phong, 2048.0),
        build(Family::TrowbridgeReitz, 0.01),
        build(Family::Beckmann, 0.001),
        build(Family::Beckmann, 0.5),
        build(Family::TrowbridgeReitz, 0.5),
    ]
}

fn canonical(ndf: &Ndf) -> String {
    crate::model::curve::Curve::Ndf(ndf.clone()).canonical_json()
}

/// The pixel map of a one-panel figure showing `ndf` alone, with its true extent (peak included).
fn drawing_map(ndf: &Ndf) -> (Frame, PixelMap) {
    let frame = Frame {
        theta_range: (0.0, FRAC_PI_2),
        width_px: DRAWING_AREA_PX.0,
        height_px: DRAWING_AREA_PX.1,
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        y_range: None,
        tolerance_px: DRAWING_TOLERANCE_PX,
        geometry: adaptive::Geometry::Angle,
    };
    let dense = crate::model::grid::linspace(0.0, FRAC_PI_2, ERROR_PROBES);
    let values: Vec<(f64, f64)> = dense.into_iter().map(|t| (t, ndf.eval(t))).collect();
    let map = frame.map(adaptive::extent([values.as_slice()]));
    (frame, map)
}

fn uniform_points(ndf: &Ndf, n: usize) -> Vec<(f64, f64)> {
    crate::model::grid::linspace(0.0, FRAC_PI_2, n)
        .into_iter()
        .map(|t| (t, ndf.eval(t)))
        .collect()
}

fn deviation(ndf: &Ndf, map: &PixelMap, points: &[(f64, f64)]) -> f64 {
    let probes = (ERROR_PROBES / points.len().max(2)).max(8);
    adaptive::max_deviation_px(&|t| ndf.eval(t), map, points, probes)
}

/// The fewest uniform samples whose polyline is within `tolerance_px`, by bisection on N (the error
/// falls with N, up to the grid's phase against the lobe, so the result is within a few % of exact).
fn uniform_needed(ndf: &Ndf, map: &PixelMap, tolerance_px: f64) -> usize {
    let (mut lo, mut hi) = (2, MAX_UNIFORM_SEARCH);
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if deviation(ndf, map, &uniform_points(ndf, mid)) <= tolerance_px {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}

/// Section (a): uniform N = 2⁴ … 2¹⁶ and adaptive tolerances against the drawn error in px.
pub fn drawing(clock: &dyn Clock, settings: &Settings, cases: &[Ndf]) -> Vec<Row> {
    let mut rows = Vec::new();
    for ndf in cases {
        let (frame, map) = drawing_map(ndf);
        let case = canonical(ndf);
        for power in UNIFORM_POWERS {
            let n = 1usize << power;
            let seconds = time(clock, settings, &mut || {
                std::hint::black_box(uniform_points(ndf, n));
            });
            let error = deviation(ndf, &map, &uniform_points(ndf, n));
            rows.push(Row {
                section: "drawing",
                case: case.clone(),
                method: "uniform".into(),
                setting: n as f64,
                samples: n,
                seconds,
                error,
            });
        }
        for tolerance_px in TOLERANCES_PX {
            let frame = Frame {
                tolerance_px,
                ..frame.clone()
            };
            let f = |t: f64| ndf.eval(t);
            let run = || {
                let start = adaptive::initial(&f, frame.theta_range, &[]);
                let extent = adaptive::extent([start.points.as_slice()]);
                adaptive::sample(&f, &frame, start, extent)
            };
            let seconds = time(clock, settings, &mut || {
                std::hint::black_box(run());
            });
            let refined = run();
            let error = deviation(ndf, &map, &refined.points);
            let samples = refined.points.len();
            rows.push(Row {
                section: "drawing",
                case: case.clone(),
                method: "adaptive".into(),
                setting: tolerance_px,
                samples,
                seconds,
                error,
            });
        }
        let n = uniform_needed(ndf, &map, DRAWING_TOLERANCE_PX);
        let seconds = time(clock, settings, &mut || {
            std::hint::black_box(uniform_points(ndf, n));
        });
        let error = deviation(ndf, &map, &uniform_points(ndf, n));
        rows.push(Row {
            section: "drawing",
            case,
            method: "uniform_needed".into(),
            setting: DRAWING_TOLERANCE_PX,
            samples: n,
            seconds,
            error,
        });
    }
    rows
}

/// Torrance–Sparrow check values of docs/maths.md (15 digits): (α_ts, N).
const TS_REFERENCE: [(f64, f64); 4] = [
    (0.2027, 0.125601275797826),
    (0.552, 0.784586975070852),
    (1.81, 2.54561914769914),
    (100.0, 3.14136216800410),
];
/// ABC check values of docs/maths.md (15 digits): (a₁, a₂, N).
const ABC_REFERENCE: [(f64, f64, f64); 4] = [
    (10.0, 1.75, 0.562584587671993),
    (23.5, 1.75, 0.282172212012306),
    (0.0212, 1000.0, 0.282651269230233),
    (3.0, 0.5, 2.32710566932577),
];
/// SGD check values: (a₁, a₂, e^{a₁} Γ(1 − a₂, a₁)), the normalizing factor of its D(0), from mpmath 1.3
/// at 40 digits (`exp(x) * gammainc(s, x)` at the exact doubles), rounded to doubles: the notebook's
/// s = 1 − a₂ = 0.5, 0 (E₁) and −0.5 at small and moderate a₁, and a₁ = 10.
const SGD_REFERENCE: [(f64, f64, f64); 5] = [
    (1.0, 0.5, 0.7578721561413121),
    (0.5, 1.0, 0.9229106324837305),
    (0.2, 1.5, 2.18996595078266),
    (0.1, 0.5, 1.2825093897118496),
    (10.0, 1.5, 0.027773264582582575),
];
/// Relative tolerances of the quadrature route.
const QUAD_TOLERANCES: [f64; 4] = [1e-6, 1e-9, 1e-12, 1e-14];
/// The references carry 15 significant digits: errors below this are not resolved.
pub const REFERENCE_RESOLUTION: f64 = 1e-15;

/// N = 2π ∫₀^{π/2} u(θ) sin θ cos θ dθ by adaptive Gauss–Kronrod at `rel_tol`; NaN if it fails.
fn quadrature(u: impl Fn(f64) -> f64, rel_tol: f64) -> f64 {
    integrate(|t| u(t) * t.sin() * t.cos(), 0.0, FRAC_PI_2, rel_tol)
        .map_or(f64::NAN, |v| 2.0 * PI * v)
}

/// e^x Γ(s, x) = ∫₀^∞ (x + u)^{s−1} e^{−u} du = ∫₀¹ (x − ln w)^{s−1} dw (w = e^{−u}) by adaptive
/// Gauss–Kronrod at `rel_tol` (the nodes are interior, so the integrable end w = 0 is never evaluated);
/// NaN if it fails.
pub fn sgd_gamma_quadrature(s: f64, x: f64, rel_tol: f64) -> f64 {
    integrate(|w| (x - w.ln()).powf(s - 1.0), 0.0, 1.0, rel_tol).unwrap_or(f64::NAN)
}

/// docs/maths.md's closed form of the ABC normalization, as the notebook wrote it:
/// N = 2π (U^{2−a₂} − 1 + a₁(a₂ − 2)) / (a₁² (a₂ − 2)(a₂ − 1)), U = 1 + a₁ (0/0 at a₂ = 1, 2).
pub fn abc_closed_form(a1: f64, a2: f64) -> f64 {
    let u = 1.0 + a1;
    2.0 * PI * (u.powf(2.0 - a2) - 1.0 + a1 * (a2 - 2.0)) / (a1 * a1 * (a2 - 2.0) * (a2 - 1.0))
}

/// Section (b): every normalization route against docs/maths.md's 15-digit values (Torrance–Sparrow, ABC)
/// and mpmath's (SGD's e^{a₁} Γ(1 − a₂, a₁)).
pub fn normalization(clock: &dyn Clock, settings: &Settings) -> Vec<Row> {
    let mut rows = Vec::new();
    // One row per setting of a route: the quadrature tolerances, or 0 for a route without one.
    let mut push =
        |case: &str, method: &str, route_settings: &[f64], f: &dyn Fn(f64) -> f64, want: f64| {
            for &setting in route_settings {
                let seconds = time(clock, settings, &mut || {
                    std::hint::black_box(f(setting));
                });
                let error = ((f(setting) - want) / want).abs();
                let error = if error.is_finite() { error } else { 1.0 };
                rows.push(Row {
                    section: "normalization",
                    case: case.to_string(),
                    method: method.into(),
                    setting,
                    samples: 1,
                    seconds,
                    error,
                });
            }
        };
    for (alpha, want) in TS_REFERENCE {
        let case = format!("{{\"ndf\":\"torrance_sparrow\",\"alpha_ts\":{alpha:?}}}");
        push(
            &case,
            "dawson_faddeeva",
            &[0.0],
            &|_| TorranceSparrow::new(alpha).map_or(f64::NAN, |d| d.normalization()),
            want,
        );
        push(
            &case,
            "quadrature",
            &QUAD_TOLERANCES,
            &|tol| quadrature(|t| (-(t / alpha).powi(2)).exp(), tol),
            want,
        );
    }
    for (a1, a2, want) in ABC_REFERENCE {
        let case = format!("{{\"ndf\":\"abc\",\"alpha_abc1\":{a1:?},\"alpha_abc2\":{a2:?}}}");
        let stable = if a1.ln_1p() <= 1.0 {
            "stable_series"
        } else {
            "stable_exprel"
        };
        push(
            &case,
            stable,
            &[0.0],
            &|_| Abc::new(a1, a2).map_or(f64::NAN, |d| d.normalization()),
            want,
        );
        push(
            &case,
            "closed_form",
            &[0.0],
            &|_| abc_closed_form(a1, a2),
            want,
        );
        push(
            &case,
            "quadrature",
            &QUAD_TOLERANCES,
            &|tol| {
                quadrature(
                    |t| (-a2 * (a1 * 2.0 * (0.5 * t).sin().powi(2)).ln_1p()).exp(),
                    tol,
                )
            },
            want,
        );
    }
    for (a1, a2, want) in SGD_REFERENCE {
        let case = format!("{{\"ndf\":\"sgd\",\"alpha_sgd1\":{a1:?},\"alpha_sgd2\":{a2:?}}}");
        push(
            &case,
            "series_continued_fraction",
            &[0.0],
            &|_| upper_gamma_scaled(1.0 - a2, a1),
            want,
        );
        push(
            &case,
            "quadrature",
            &QUAD_TOLERANCES,
            &|tol| sgd_gamma_quadrature(1.0 - a2, a1, tol),
            want,
        );
    }
    rows
}

/// The throughput cases: one curve per family at its example parameters (the numpy peer's).
pub fn throughput_cases() -> Vec<Ndf> {
    Family::ALL
        .into_iter()
        .map(|family| {
            family
                .build(family.example())
                .expect("examples lie in the domain")
        })
        .collect()
}

/// Section (c): D values written per second on a uniform grid over [0, π/2] (θ_i = iΔθ, computed
/// before timing, as the numpy peer's) by `eval_many`, the block path of uniform samplings and
/// `ndfplot eval`, on one thread and on all rayon threads (tasks of [`TASK_POINTS`]); the error
/// column compares every value with `eval`'s, point by point (0: the same bits).
pub fn throughput(clock: &dyn Clock, settings: &Settings, cases: &[Ndf]) -> Vec<Row> {
    let n = settings.throughput_points.max(2);
    let dtheta = FRAC_PI_2 / (n - 1) as f64;
    let thetas: Vec<f64> = (0..n).map(|i| i as f64 * dtheta).collect();
    let threads = rayon::current_num_threads();
    let mut out = vec![0.0; n];
    let mut rows = Vec::new();
    for ndf in cases {
        let reference: Vec<f64> = thetas.iter().map(|&theta| ndf.eval(theta)).collect();
        let name = ndf.family().name().to_string();
        let mut row =
            |method: &str, setting: usize, out: &mut Vec<f64>, run: &dyn Fn(&mut [f64])| {
                let seconds = time(clock, settings, &mut || run(out));
                let error = out
                    .iter()
                    .zip(&reference)
                    .map(|(a, b)| floored_relative_difference(*a, *b))
                    .fold(0.0, f64::max);
                rows.push(Row {
                    section: "throughput",
                    case: name.clone(),
                    method: method.into(),
                    setting: setting as f64,
                    samples: n,
                    seconds,
                    error,
                });
            };
        row("eval_1_thread", 1, &mut out, &|out| {
            ndf.eval_many(&thetas, out)
        });
        row("eval_all_threads", threads, &mut out, &|out| {
            out.par_chunks_mut(TASK_POINTS)
                .zip(thetas.par_chunks(TASK_POINTS))
                .for_each(|(chunk, thetas)| ndf.eval_many(thetas, chunk));
        });
    }
    rows
}

/// Smith Λ(θo) references: `tests/data/reference/lambda.csv` (mpmath at 40 digits, docs/maths.md's 1D
/// integral), rows `case_id,curve_json,theta_o,lambda` below a `#` provenance line.
const LAMBDA_REFERENCE: &str = include_str!("../../../tests/data/reference/lambda.csv");

/// One reference Λ value: the curve, θo and Λ(θo).
#[derive(Debug, Clone, PartialEq)]
pub struct LambdaCase {
    /// The NDF.
    pub ndf: Ndf,
    /// The view angle θo.
    pub theta_o: f64,
    /// The reference Λ(θo).
    pub lambda: f64,
}

/// The rows of the embedded Λ reference file, in file order, each curve read by the library's own
/// curve parser. Panics if the file does not parse (it is embedded, so a test catches that).
pub fn lambda_cases() -> Vec<LambdaCase> {
    let mut reader = csv::ReaderBuilder::new()
        .comment(Some(b'#'))
        .from_reader(LAMBDA_REFERENCE.as_bytes());
    reader
        .records()
        .map(|record| {
            let record = record.expect("lambda.csv is well-formed CSV");
            let node = crate::spec::json::parse(&record[1]).expect("curve_json is JSON");
            let ndf = match crate::spec::curve::parse(&node, "") {
                Ok(crate::spec::curve::CurveSpec::Ready(crate::model::curve::Curve::Ndf(ndf))) => {
                    ndf
                }
                other => panic!("lambda.csv: {} is not an NDF: {other:?}", &record[1]),
            };
            let number = |column: usize| -> f64 {
                record[column].parse().expect("lambda.csv numbers parse")
            };
            LambdaCase {
                ndf,
                theta_o: number(2),
                lambda: number(3),
            }
        })
        .collect()
}

/// Section (d): Smith's Λ per family over its rows of [`lambda_cases`]: its own route
/// ([`Ndf::lambda`], method `closed_form` or `quadrature`) and, for the closed-form families, also the
/// generic quadrature ([`lambda_by_integral`], method `quadrature`). A row's `samples` is the
/// family's reference count, `seconds` the median time of one pass over them divided by that count
/// (per Λ evaluation), `error` the largest [`floored_relative_difference`] from the references.
pub fn lambda_routes(clock: &dyn Clock, settings: &Settings, cases: &[LambdaCase]) -> Vec<Row> {
    let mut rows = Vec::new();
    for family in Family::ALL {
        let of_family: Vec<&LambdaCase> =
            cases.iter().filter(|c| c.ndf.family() == family).collect();
        if of_family.is_empty() {
            continue;
        }
        let own: fn(&Ndf, f64) -> f64 = Ndf::lambda;
        let mut routes = vec![(own, family.lambda_closed_form())];
        if family.lambda_closed_form() {
            routes.push((lambda_by_integral, false));
        }
        for (route, closed_form) in routes {
            let pass = || -> f64 {
                of_family
                    .iter()
                    .map(|c| route(&c.ndf, std::hint::black_box(c.theta_o)))
                    .sum()
            };
            let seconds = time(clock, settings, &mut || {
                std::hint::black_box(pass());
            });
            let error = of_family
                .iter()
                .map(|c| floored_relative_difference(route(&c.ndf, c.theta_o), c.lambda))
                .fold(0.0, |worst, e| {
                    if e.is_nan() {
                        f64::INFINITY
                    } else {
                        worst.max(e)
                    }
                });
            rows.push(Row {
                section: "lambda",
                case: family.name().to_string(),
                method: if closed_form {
                    "closed_form"
                } else {
                    "quadrature"
                }
                .into(),
                setting: 0.0,
                samples: of_family.len(),
                seconds: seconds / of_family.len() as f64,
                error,
            });
        }
    }
    rows
}

/// Cycles' GGX albedo table `table_ggx_E` (`data/published/cycles/ggx_E.csv`: Monte Carlo, F = 1,
/// height-correlated G2, α = r², printed to 6 decimals), rows `table,y,x,value` (μ row y, r column x).
const CYCLES_GGX_E: &str = include_str!("../../../data/published/cycles/ggx_E.csv");

/// Rows and columns of Cycles' `table_ggx_E`.
pub const CYCLES_TABLE_SIZE: usize = 32;

/// The Trowbridge–Reitz surface of width `alpha` (in its domain) with height-correlated G2, D and Λ
/// by [`Ndf::eval`] and [`Ndf::lambda`], as the `albedo` quantity builds its surface.
pub fn ggx_surface(
    alpha: f64,
) -> Microfacet<impl Density + Sync + Send, impl Lambda + Sync + Send> {
    let ndf = Family::TrowbridgeReitz
        .build(&[alpha])
        .expect("α lies in the domain");
    surface_of(ndf, G2Model::HeightCorrelated)
}

/// The Trowbridge–Reitz albedo table on Cycles' 32 × 32 grid (μ = i/31, r = j/31, α = r², F = 1)
/// of [`ggx_surface`]s; cells in parallel on all rayon threads. Errs if a quadrature fails.
pub fn ggx_albedo_table() -> Result<AlbedoTable, QuadError> {
    albedo_table(
        CYCLES_TABLE_SIZE,
        CYCLES_TABLE_SIZE,
        RoughnessMap::Squared,
        |alpha| (alpha > 0.0).then(|| ggx_surface(alpha)),
        None,
        None,
    )
}

/// The largest |E − E_Cycles| of `table` (on Cycles' grid, [`ggx_albedo_table`]) over the cells
/// whose coordinates Cycles does not clamp: its μ = 0 row and r = 0 column are the limits μ → 0⁺
/// and α → 0⁺, where Cycles evaluates μ = 1e-4 and r = 1e-4 instead, so they are left out (31 × 31
/// cells compared). Cycles' float32 coordinates differ from i/31 by < 1e-7 relative, far below
/// its Monte Carlo noise (~1e-6).
pub fn cycles_difference(table: &AlbedoTable) -> f64 {
    let mut reader = csv::ReaderBuilder::new()
        .comment(Some(b'#'))
        .from_reader(CYCLES_GGX_E.as_bytes());
    reader
        .records()
        .map(|record| record.expect("cycles_ggx_E.csv is well-formed CSV"))
        .filter(|record| &record[0] == "ggx_E")
        .filter_map(|record| {
            let index =
                |column: usize| -> usize { record[column].parse().expect("grid indices parse") };
            let (i, j) = (index(1), index(2));
            let want: f64 = record[3].parse().expect("table values parse");
            (i > 0 && j > 0).then(|| (table.get(i, j) - want).abs())
        })
        .fold(0.0, f64::max)
}

/// Section (e): one full [`ggx_albedo_table`] (about a second or two on two threads, so each batch
/// is a single table), timed like every case by [`time`], against Cycles' table
/// ([`cycles_difference`]: an absolute error). `setting` is the thread count, `samples` the 1024
/// cells. A failed quadrature gives an infinite error.
pub fn albedo_table_row(clock: &dyn Clock, settings: &Settings) -> Row {
    let mut table = None;
    let seconds = time(clock, settings, &mut || table = Some(ggx_albedo_table()));
    let error = match table {
        Some(Ok(table)) => cycles_difference(&table),
        _ => f64::INFINITY,
    };
    Row {
        section: "albedo_table",
        case: "trowbridge_reitz".into(),
        method: "table".into(),
        setting: rayon::current_num_threads() as f64,
        samples: CYCLES_TABLE_SIZE * CYCLES_TABLE_SIZE,
        seconds,
        error,
    }
}

/// Every section in order.
pub fn run(clock: &dyn Clock, settings: &Settings) -> Vec<Row> {
    let mut rows = drawing(clock, settings, &drawing_cases());
    rows.extend(normalization(clock, settings));
    rows.extend(throughput(clock, settings, &throughput_cases()));
    rows.extend(lambda_routes(clock, settings, &lambda_cases()));
    rows.push(albedo_table_row(clock, settings));
    rows
}

/// The rows as CSV: `section,case,method,setting,samples,seconds,error`, numbers in shortest
/// round-trip form (docs/contracts.md), fields quoted where they need it.
pub fn csv(rows: &[Row]) -> String {
    let header = [
        "section", "case", "method", "setting", "samples", "seconds", "error",
    ];
    let mut table = Table::new(header, 128 * rows.len());
    for r in rows {
        table.text(r.section);
        table.text(&r.case);
        table.text(&r.method);
        table.number(r.setting);
        table.count(r.samples);
        table.number(r.seconds);
        table.number(r.error);
        table.end_row();
    }
    table.into_string()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cell::Cell;

    /// A clock that advances one millisecond per call of the timed function.
    struct CallClock<'a>(&'a Cell<u64>);

    impl Clock for CallClock<'_> {
        fn now(&self) -> Duration {
            Duration::from_millis(self.0.get())
        }
    }

    #[test]
    fn time_doubles_the_calls_until_a_batch_is_long_enough() {
        let calls = Cell::new(0);
        let settings = Settings {
            min_batch: Duration::from_millis(8),
            batches: 3,
            throughput_points: 2,
        };
        let seconds = time(&CallClock(&calls), &settings, &mut || {
            calls.set(calls.get() + 1)
        });
        assert_eq!(seconds, 1e-3);
        // Each batch runs 1 + 2 + 4 + 8 calls.
        assert_eq!(calls.get(), 3 * 15);
    }

    #[test]
    fn throughput_rows_are_deterministic_under_a_fake_clock() {
        let ticks = Cell::new(0);
        let clock = CallClock(&ticks);
        let settings = Settings {
            min_batch: Duration::ZERO,
            batches: 1,
            throughput_points: 1000,
        };
        let rows = throughput(&clock, &settings, &throughput_cases());
        assert_eq!(rows.len(), 2 * Family::ALL.len());
        for row in &rows {
            assert_eq!(row.seconds, 0.0, "{row:?}");
            assert_eq!(row.error, 0.0, "{row:?}");
        }
        let text = csv(&rows);
        assert!(text.starts_with("section,case,method,setting,samples,seconds,error\nthroughput,phong,eval_1_thread,1.0,1000,0.0,0.0\n"), "{text}");
    }

    #[test]
    fn lambda_rows_time_every_route_and_hold_the_reference() {
        let ticks = Cell::new(0);
        let settings = Settings {
            min_batch: Duration::ZERO,
            batches: 1,
            throughput_points: 2,
        };
        let cases = lambda_cases();
        assert!(cases.len() > 400, "{} reference rows", cases.len());
        let rows = lambda_routes(&CallClock(&ticks), &settings, &cases);
        // Each family of the references by its own route, the closed forms also by the quadrature.
        let expected: usize = Family::ALL
            .into_iter()
            .filter(|&f| cases.iter().any(|c| c.ndf.family() == f))
            .map(|f| 1 + usize::from(f.lambda_closed_form()))
            .sum();
        assert_eq!(rows.len(), expected);
        for row in &rows {
            let family = Family::from_name(&row.case).unwrap();
            let closed_form = row.method == "closed_form";
            assert!(!closed_form || family.lambda_closed_form(), "{row:?}");
            // The quadrature's worst is Phong α_p = 20 at θo = 1e-6 (7e-10), where D's argument
            // rounds near grazing (tests/numerics/masking.rs); the closed forms hold
            // REL_TOL_LAMBDA_CLOSED_FORM.
            let tol = if closed_form {
                crate::model::math::tolerance::REL_TOL_LAMBDA_CLOSED_FORM
            } else {
                1e-9
            };
            assert!(row.error <= tol, "{row:?}");
            assert_eq!(row.seconds, 0.0, "{row:?}");
            let count = cases.iter().filter(|c| c.ndf.family() == family).count();
            assert_eq!(row.samples, count, "{row:?}");
        }
    }

    #[test]
    fn the_cycles_difference_leaves_out_the_clamped_row_and_column() {
        let n = CYCLES_TABLE_SIZE;
        let mut reader = csv::ReaderBuilder::new()
            .comment(Some(b'#'))
            .from_reader(CYCLES_GGX_E.as_bytes());
        let mut values = vec![f64::NAN; n * n];
        for record in reader.records().map(Result::unwrap) {
            if &record[0] == "ggx_E" {
                let (i, j): (usize, usize) =
                    (record[1].parse().unwrap(), record[2].parse().unwrap());
                values[i * n + j] = record[3].parse().unwrap();
            }
        }
        let grid: Vec<f64> = (0..n).map(|i| i as f64 / (n - 1) as f64).collect();
        let mut table = AlbedoTable {
            map: RoughnessMap::Squared,
            mu: grid.clone(),
            roughness: grid,
            values,
        };
        assert_eq!(cycles_difference(&table), 0.0);
        // The μ = 0 row and r = 0 column are limits Cycles does not tabulate.
        table.values[3] = 1.0;
        table.values[3 * n] = 1.0;
        assert_eq!(cycles_difference(&table), 0.0);
        table.values[3 * n + 5] += 1e-3;
        assert!((cycles_difference(&table) - 1e-3).abs() < 1e-12);
    }

    #[test]
    fn both_sgd_gamma_routes_match_mpmath() {
        for (a1, a2, want) in SGD_REFERENCE {
            let s = 1.0 - a2;
            for got in [
                upper_gamma_scaled(s, a1),
                sgd_gamma_quadrature(s, a1, QUAD_TOLERANCES[3]),
            ] {
                assert!(
                    ((got - want) / want).abs() <= crate::model::math::tolerance::REL_TOL_SPECIAL,
                    "a1 = {a1}, a2 = {a2}: {got} vs {want}"
                );
            }
        }
    }

    #[test]
    fn closed_form_fails_where_the_stable_form_does_not() {
        assert!(abc_closed_form(1.0, 2.0).is_nan());
        assert!(Abc::new(1.0, 2.0).unwrap().normalization().is_finite());
    }
}
