//! Sampling: the batch path (`Ndf::eval_grid`) against the accurate `eval` over every family's domain,
//! adaptive sampling of drawn curves (within tolerance, few samples), the spec's `sampling` key, and
//! the plan skipping what a run does not need (formats not requested, jobs shared between panels).

use ndfplot::adaptive::{self, Frame, max_deviation_px};
use ndfplot::cmd::render::{self, CanvasOverride, Format, RenderOptions};
use ndfplot::ndf::{Family, Ndf};
use ndfplot::plan::{Job, Outputs, plan};
use ndfplot::sample::{eval_grid_parallel, evaluate_all};
use ndfplot::series::YScale;
use std::f64::consts::FRAC_PI_2;
use std::path::PathBuf;

/// Accuracy bound of Trowbridge–Reitz, relative (the reference tests' bound).
const TR_TOL: f64 = 1e-13;
/// Accuracy bound of the other families, relative.
const OTHER_TOL: f64 = 1e-12;
/// Below this |D| errors are absolute (MATH.md's convention).
const TINY: f64 = 1e-280;
/// Relative step of the finite difference that estimates d ln D/d ln θ.
const DIFF_STEP: f64 = 1e-6;
/// The batch path's abscissa is θ₀ + iΔθ to within this many ulp of θ (two roundings: seed and step).
const THETA_ULPS: f64 = 4.0;

fn log_grid(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    let (l, h) = (lo.log10(), hi.log10());
    (0..n)
        .map(|i| {
            10f64
                .powf(l + (h - l) * i as f64 / (n - 1) as f64)
                .clamp(lo, hi)
        })
        .collect()
}

/// Parameter points spanning each family's accepted domain on log grids, bounds included.
fn domain(family: Family) -> Vec<Vec<f64>> {
    let one = |lo: f64, hi: f64, n: usize| {
        log_grid(lo, hi, n)
            .into_iter()
            .map(|v| vec![v])
            .collect::<Vec<_>>()
    };
    match family {
        Family::Phong => [vec![vec![0.0]], one(1e-6, 1e8, 15)].concat(),
        Family::Beckmann | Family::TrowbridgeReitz => one(1e-150, 1e4, 31),
        Family::TorranceSparrow => one(1e-150, 1e150, 31),
        Family::Abc => {
            let a = log_grid(1e-100, 1e100, 9);
            a.iter()
                .flat_map(|&a1| [0.01, 0.5, 1.0, 1.75, 2.0, 10.0, 1e3].map(|a2| vec![a1, a2]))
                .collect()
        }
        Family::Sgd => {
            let a = log_grid(1e-6, 1e6, 9);
            a.iter()
                .flat_map(|&a1| [-10.0, -1.0, 0.0, 0.5, 1.0, 1.5, 10.0].map(|a2| vec![a1, a2]))
                .collect()
        }
    }
}

/// Largest violation (≤ 1 passes) of |batch − eval| ≤ tol·max(|eval|, TINY) + the change of D under a
/// THETA_ULPS-ulp move of θ, over a grid of `n` points on [θ₀, θ₁].
fn batch_violation(ndf: &Ndf, (theta0, theta1): (f64, f64), n: usize, tol: f64) -> (f64, f64) {
    let dtheta = (theta1 - theta0) / (n - 1) as f64;
    let mut out = vec![0.0; n];
    eval_grid_parallel(ndf, theta0, dtheta, &mut out);
    let mut worst = (0.0, 0.0);
    for (i, &got) in out.iter().enumerate() {
        let theta = theta0 + i as f64 * dtheta;
        let want = ndf.eval(theta);
        let (up, down) = (
            ndf.eval((theta * (1.0 + DIFF_STEP)).min(FRAC_PI_2)),
            ndf.eval(theta * (1.0 - DIFF_STEP)),
        );
        let moved = (up - down).abs() / (2.0 * DIFF_STEP) * THETA_ULPS * f64::EPSILON;
        let allowed = tol * want.abs().max(TINY) + moved;
        let violation = (got - want).abs() / allowed;
        assert!(
            got.is_finite() && got >= 0.0,
            "{ndf:?} at θ = {theta}: {got}"
        );
        if violation > worst.0 {
            worst = (violation, theta);
        }
    }
    worst
}

#[test]
fn batch_path_equals_eval_over_every_domain() {
    for family in Family::ALL {
        let tol = if family == Family::TrowbridgeReitz {
            TR_TOL
        } else {
            OTHER_TOL
        };
        for params in domain(family) {
            let ndf = family.build(&params).unwrap();
            for range in [(0.0, FRAC_PI_2), (0.0, 0.01), (1.5, FRAC_PI_2)] {
                let (violation, theta) = batch_violation(&ndf, range, 2001, tol);
                assert!(
                    violation <= 1.0,
                    "{ndf:?} over {range:?}: {violation}× the bound at θ = {theta}"
                );
            }
        }
    }
}

#[test]
fn batch_path_is_independent_of_the_split_into_tasks() {
    let ndf = Family::Beckmann.build(&[0.3]).unwrap();
    let n = 3 * ndfplot::sample::PARALLEL_CHUNK + 5;
    let dtheta = FRAC_PI_2 / (n - 1) as f64;
    let mut parallel = vec![0.0; n];
    eval_grid_parallel(&ndf, 0.0, dtheta, &mut parallel);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let mut single = vec![0.0; n];
    pool.install(|| eval_grid_parallel(&ndf, 0.0, dtheta, &mut single));
    assert_eq!(parallel, single);
}

fn frame() -> Frame {
    Frame {
        theta_range: (0.0, FRAC_PI_2),
        width_px: 600.0,
        height_px: 370.0,
        y_scale: YScale::Linear,
        y_range: None,
        tolerance_px: 0.25,
        geometry: adaptive::Geometry::Angle,
    }
}

/// The narrow lobes of the issue: drawn within 0.25 px with a few hundred samples at most.
#[test]
fn narrow_lobes_are_drawn_within_a_quarter_pixel() {
    for (family, alpha) in [
        (Family::Phong, 2048.0),
        (Family::TrowbridgeReitz, 0.01),
        (Family::Beckmann, 0.001),
    ] {
        let ndf = family.build(&[alpha]).unwrap();
        let f = |t: f64| ndf.eval(t);
        let start = adaptive::initial(&f, frame().theta_range, &[]);
        let extent = adaptive::extent([start.points.as_slice()]);
        let refined = adaptive::sample(&f, &frame(), start, extent);
        let error = max_deviation_px(&f, &frame().map(extent), &refined.points, 64);
        assert!(error <= 0.25, "{ndf:?}: {error} px");
        assert!(
            refined.points.len() <= 400,
            "{ndf:?}: {} points",
            refined.points.len()
        );
    }
}

#[test]
fn flat_curves_keep_the_initial_grid() {
    let ndf = Family::TrowbridgeReitz.build(&[1.0]).unwrap();
    let f = |t: f64| ndf.eval(t);
    let start = adaptive::initial(&f, frame().theta_range, &[]);
    let extent = adaptive::extent([start.points.as_slice()]);
    let refined = adaptive::sample(&f, &frame(), start, extent);
    assert_eq!(refined.points.len(), adaptive::INITIAL_POINTS);
}

fn scene(sampling: &str) -> String {
    format!(
        r#"{{"id":"s","title":"t",{sampling}"panels":[
            {{"curves":[{{"ndf":"phong","alpha_p":2048}},{{"ndf":"beckmann","alpha_b":0.4}}]}},
            {{"curves":[{{"ndf":"phong","alpha_p":2048}},{{"ndf":"beckmann","alpha_b":0.4}}]}}]}}"#
    )
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("ndfplot-sampling-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn load(dir: &PathBuf, text: &str) -> Vec<ndfplot::scene::Scene> {
    let path = dir.join("s.json");
    std::fs::write(&path, text).unwrap();
    render::load_scenes(
        &render::sources(&[path]).unwrap(),
        CanvasOverride::default(),
    )
    .unwrap()
}

#[test]
fn default_sampling_draws_adaptively_and_tabulates_uniformly() {
    let dir = temp_dir("default");
    let scenes = load(&dir, &scene(""));
    let plan = plan(
        &scenes,
        Outputs {
            drawn: true,
            table: true,
        },
        false,
    );
    let drawn = plan.drawn.as_ref().unwrap();
    let table = plan.table.as_ref().unwrap();
    // Identical panels share their jobs: 2 adaptive + 2 uniform in all.
    assert_eq!(plan.jobs.len(), 4);
    assert_eq!(drawn[0][0], drawn[0][1]);
    assert!(
        drawn[0][0]
            .iter()
            .all(|&j| matches!(plan.jobs[j], Job::Adaptive { .. }))
    );
    assert!(
        table[0][0]
            .iter()
            .all(|&j| matches!(plan.jobs[j], Job::Uniform { samples: 1000, .. }))
    );
    let evaluated = evaluate_all(&plan).unwrap();
    for &j in &drawn[0][0] {
        assert!(
            evaluated[j].points.len() < 1000,
            "{} points",
            evaluated[j].points.len()
        );
    }
}

#[test]
fn explicit_sampling_applies_to_tables_too() {
    let dir = temp_dir("explicit");
    let uniform = load(&dir, &scene(r#""sampling":{"uniform":50},"#));
    let p = plan(
        &uniform,
        Outputs {
            drawn: true,
            table: true,
        },
        false,
    );
    assert_eq!(p.drawn, p.table);
    assert!(
        p.jobs
            .iter()
            .all(|j| matches!(j, Job::Uniform { samples: 50, .. }))
    );
    let adaptive = load(
        &dir,
        &scene(r#""sampling":{"adaptive":{"tolerance_px":0.5}},"#),
    );
    let p = plan(
        &adaptive,
        Outputs {
            drawn: true,
            table: true,
        },
        false,
    );
    assert_eq!(p.drawn, p.table);
    assert!(p.jobs.iter().all(|j| matches!(j, Job::Adaptive { .. })));
    assert_eq!(p.frames[0].tolerance_px, 0.5);
}

#[test]
fn sampling_key_errors_name_the_problem() {
    let dir = temp_dir("errors");
    for (sampling, needle) in [
        (
            r#""sampling":{"uniform":50,"adaptive":{}},"#,
            "exactly one of",
        ),
        (
            r#""sampling":{"adaptive":{"tolerance_px":0}},"#,
            "tolerance_px",
        ),
        (r#""sampling":{"adaptive":{"tol":1}},"#, "tol"),
    ] {
        let path = dir.join("s.json");
        std::fs::write(&path, scene(sampling)).unwrap();
        let error = render::load_scenes(
            &render::sources(&[path]).unwrap(),
            CanvasOverride::default(),
        )
        .unwrap_err();
        assert!(error.to_string().contains(needle), "{sampling}: {error}");
    }
}

#[test]
fn a_run_produces_only_the_requested_formats_and_needed_jobs() {
    let dir = temp_dir("formats");
    let spec = dir.join("s.json");
    std::fs::write(&spec, scene("")).unwrap();
    let options = |formats: Vec<Format>| RenderOptions {
        paths: vec![spec.clone()],
        out: dir.join("out"),
        formats,
        canvas: CanvasOverride::default(),
    };
    let (_, svg_only) = render::run_with_stats(&options(vec![Format::Svg])).unwrap();
    assert_eq!(
        svg_only.produced,
        [1, 0, 0, 0],
        "an svg-only run never rasterizes nor tabulates"
    );
    let (_, pdf_only) = render::run_with_stats(&options(vec![Format::Pdf])).unwrap();
    assert_eq!(
        pdf_only.produced,
        [0, 0, 1, 0],
        "a pdf-only run converts the drawing, never rasterizes nor tabulates"
    );
    assert_eq!(
        pdf_only.evaluations, svg_only.evaluations,
        "a PDF is sampled as the SVG it is drawn from"
    );
    let (_, csv_only) = render::run_with_stats(&options(vec![Format::Csv])).unwrap();
    assert_eq!(csv_only.produced, [0, 0, 0, 1]);
    // A CSV-only run evaluates the two uniform curves once each, however many panels show them.
    assert_eq!(csv_only.evaluations, 2 * 1000);
    let scenes = load(&dir, &scene(""));
    assert!(
        plan(
            &scenes,
            Outputs {
                drawn: false,
                table: true
            },
            false
        )
        .drawn
        .is_none()
    );
}
