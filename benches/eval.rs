//! Evaluation throughput of each NDF family: one curve, 1000 θ evenly spaced over [0, π/2] (ends included),
//! single-threaded, by `eval` per point (group `eval`) and by the vectorized batch path `eval_grid` (group
//! `eval_grid`, writing into a buffer). Criterion reports the time per 1000 samples and the throughput in
//! samples per second.
//!
//! Run: `cargo bench --bench eval`.

use criterion::{BenchmarkId, Criterion, Throughput, black_box, criterion_group, criterion_main};
use ndfplot::ndf::{Abc, Beckmann, Ndf, Phong, Sgd, TorranceSparrow, TrowbridgeReitz};
use std::f64::consts::FRAC_PI_2;

/// Samples per curve, as in a typical plot.
const SAMPLES: usize = 1000;

/// One representative curve per family, at the notebook's parameters.
fn curves() -> [Ndf; 6] {
    [
        Ndf::Phong(Phong::new(32.0).unwrap()),
        Ndf::Beckmann(Beckmann::new(0.3).unwrap()),
        Ndf::TorranceSparrow(TorranceSparrow::new(0.3097).unwrap()),
        Ndf::TrowbridgeReitz(TrowbridgeReitz::new(0.3).unwrap()),
        Ndf::Abc(Abc::new(23.5, 1.75).unwrap()),
        Ndf::Sgd(Sgd::new(0.5, 1.5).unwrap()),
    ]
}

fn eval(c: &mut Criterion) {
    let thetas: Vec<f64> = (0..SAMPLES)
        .map(|i| FRAC_PI_2 * i as f64 / (SAMPLES - 1) as f64)
        .collect();
    let mut group = c.benchmark_group("eval");
    group.throughput(Throughput::Elements(SAMPLES as u64));
    for ndf in curves() {
        group.bench_with_input(
            BenchmarkId::from_parameter(ndf.family().name()),
            &ndf,
            |b, ndf| {
                b.iter(|| {
                    thetas
                        .iter()
                        .map(|&theta| ndf.eval(black_box(theta)))
                        .sum::<f64>()
                })
            },
        );
    }
    group.finish();
}

fn eval_grid(c: &mut Criterion) {
    let dtheta = FRAC_PI_2 / (SAMPLES - 1) as f64;
    let mut out = vec![0.0; SAMPLES];
    let mut group = c.benchmark_group("eval_grid");
    group.throughput(Throughput::Elements(SAMPLES as u64));
    for ndf in curves() {
        group.bench_with_input(
            BenchmarkId::from_parameter(ndf.family().name()),
            &ndf,
            |b, ndf| {
                b.iter(|| {
                    ndf.eval_grid(0.0, black_box(dtheta), &mut out);
                    black_box(out[SAMPLES / 2])
                })
            },
        );
    }
    group.finish();
}

criterion_group!(benches, eval, eval_grid);
criterion_main!(benches);
