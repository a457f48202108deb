//! The directional albedo's quadrature: one E(μo) per family at its example parameters
//! (`Family::example`, the ones `cargo bench --bench eval` times) and both G2 models, at an oblique
//! view (μo = 0.5) and at the extremes of the domain (GGX α = 1e-4 and α = 3 at μo = 1e-6, 0.5 and
//! 1); one E with the Belcour–Bati–Barla reconstruction of glass as the Fresnel weight (its smooth
//! surrogate built per value, as a curve does); and the 8 × 8 GGX tables e, average and split-sum.
//! Surfaces are built outside the timed loop; criterion reports the time per value or table.
//!
//! Run: `cargo bench --bench albedo`.

use criterion::{BenchmarkId, Criterion, black_box, criterion_group, criterion_main};
use ndfplot::model::albedo::{
    RoughnessMap, albedo_table, average_albedo_table, split_sum_tables, surface_of, tabulated,
};
use ndfplot::model::fresnel::{Fresnel, Ior};
use ndfplot::model::masking::G2Model;
use ndfplot::model::ndf::Family;

fn per_family(c: &mut Criterion) {
    let mut group = c.benchmark_group("albedo_value");
    for family in Family::ALL {
        let ndf = family
            .build(family.example())
            .expect("examples lie in the domain");
        for g2 in [G2Model::HeightCorrelated, G2Model::Separable] {
            let surface = surface_of(ndf.clone(), g2);
            let id = BenchmarkId::new(g2.name(), family.name());
            group.bench_function(id, |b| {
                b.iter(|| surface.albedo(black_box(0.5), None).expect("converges"))
            });
        }
    }
    for alpha in [1e-4, 3.0] {
        let ndf = Family::TrowbridgeReitz
            .build(&[alpha])
            .expect("in the domain");
        let surface = surface_of(ndf, G2Model::HeightCorrelated);
        for mu in [1e-6, 0.5, 1.0] {
            let id = BenchmarkId::new(format!("ggx_{alpha}"), mu);
            group.bench_function(id, |b| {
                b.iter(|| surface.albedo(black_box(mu), None).expect("converges"))
            });
        }
    }
    group.finish();
}

fn belcour(c: &mut Criterion) {
    let ndf = Family::TrowbridgeReitz
        .build(&[0.5])
        .expect("in the domain");
    let surface = surface_of(ndf, G2Model::HeightCorrelated);
    let glass = Fresnel::belcour(Ior::eta_kappa(1.5, 0.0).expect("a valid index"));
    c.bench_function("albedo_value/belcour_glass_ggx_0.5_mu_0.54", |b| {
        b.iter(|| {
            let weight = tabulated(&glass).expect("a tabulated curve");
            surface
                .albedo_tabulated(black_box(1f64.cos()), &weight)
                .expect("converges")
        })
    });
}

fn tables(c: &mut Criterion) {
    let surface = |alpha: f64| {
        (alpha > 0.0).then(|| {
            let ndf = Family::TrowbridgeReitz
                .build(&[alpha])
                .expect("in the domain");
            surface_of(ndf, G2Model::HeightCorrelated)
        })
    };
    let mut group = c.benchmark_group("albedo_table_8x8");
    group.sample_size(10);
    let map = RoughnessMap::Squared;
    group.bench_function("e", |b| {
        b.iter(|| albedo_table(8, 8, map, surface, None, None).expect("converges"))
    });
    group.bench_function("average", |b| {
        b.iter(|| average_albedo_table(8, map, surface, None, None).expect("converges"))
    });
    group.bench_function("split_sum", |b| {
        b.iter(|| split_sum_tables(8, 8, map, surface, None).expect("converges"))
    });
    group.finish();
}

criterion_group!(benches, per_family, belcour, tables);
criterion_main!(benches);
