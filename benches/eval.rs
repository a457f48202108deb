//! Evaluation throughput of each NDF family: `ndfplot bench`'s curve per family
//! ([`ndfplot::cmd::bench::measure::throughput_cases`]), 1000 θ evenly spaced over [0, π/2] (ends included),
//! single-threaded: `eval_many` over the block (the path of uniform samplings and `ndfplot eval`) and
//! `eval` point by point (adaptive sampling's), which give the same bits. Criterion reports the time per
//! 1000 samples and the throughput in samples per second.
//!
//! Run: `cargo bench --bench eval`.

use criterion::{BenchmarkId, Criterion, Throughput, black_box, criterion_group, criterion_main};
use ndfplot::cmd::bench::measure::throughput_cases;
use std::f64::consts::FRAC_PI_2;

/// Samples per curve, as in a typical plot.
const SAMPLES: usize = 1000;

fn eval(c: &mut Criterion) {
    let thetas: Vec<f64> = (0..SAMPLES)
        .map(|i| FRAC_PI_2 * i as f64 / (SAMPLES - 1) as f64)
        .collect();
    let mut out = vec![0.0; SAMPLES];
    for path in ["eval_many", "eval"] {
        let mut group = c.benchmark_group(path);
        group.throughput(Throughput::Elements(SAMPLES as u64));
        for ndf in throughput_cases() {
            let id = BenchmarkId::from_parameter(ndf.family().name());
            if path == "eval_many" {
                group.bench_function(id, |b| {
                    b.iter(|| {
                        ndf.eval_many(black_box(&thetas), &mut out);
                        out[SAMPLES / 2]
                    })
                });
            } else {
                group.bench_function(id, |b| {
                    b.iter(|| {
                        thetas
                            .iter()
                            .map(|&theta| ndf.eval(black_box(theta)))
                            .sum::<f64>()
                    })
                });
            }
        }
        group.finish();
    }
}

criterion_group!(benches, eval);
criterion_main!(benches);
