//! Smith's Λ per family, as `ndfplot bench`'s section (d) measures it on the reference angles: each
//! family at its example parameters (`Family::example`, the ones `cargo bench --bench eval` times)
//! over 90 θo, the midpoints of 1° steps from 0.5° to 89.5°, by its own route (`Ndf::lambda`) and,
//! for the closed-form families, also by the generic quadrature (`masking::lambda_by_integral`).
//! Criterion reports the time per 90 values (and values per second); the albedo, which evaluates
//! Λ at every node, has its own bench (`cargo bench --bench albedo`).
//!
//! Run: `cargo bench --bench lambda`.

use criterion::{BenchmarkId, Criterion, Throughput, black_box, criterion_group, criterion_main};
use ndfplot::model::masking::lambda_by_integral;
use ndfplot::model::ndf::{Family, Ndf};

/// View angles per curve.
const ANGLES: usize = 90;

fn lambda(c: &mut Criterion) {
    let thetas: Vec<f64> = (0..ANGLES).map(|k| (k as f64 + 0.5).to_radians()).collect();
    let mut group = c.benchmark_group("lambda");
    group.throughput(Throughput::Elements(ANGLES as u64));
    for family in Family::ALL {
        let ndf = family
            .build(family.example())
            .expect("examples lie in the domain");
        let own: fn(&Ndf, f64) -> f64 = Ndf::lambda;
        let mut routes = vec![(
            if family.lambda_closed_form() {
                "closed_form"
            } else {
                "quadrature"
            },
            own,
        )];
        if family.lambda_closed_form() {
            routes.push(("quadrature", lambda_by_integral));
        }
        for (name, route) in routes {
            group.bench_with_input(BenchmarkId::new(name, family.name()), &ndf, |b, ndf| {
                b.iter(|| {
                    thetas
                        .iter()
                        .map(|&theta| route(ndf, black_box(theta)))
                        .sum::<f64>()
                })
            });
        }
    }
    group.finish();
}

criterion_group!(benches, lambda);
criterion_main!(benches);
