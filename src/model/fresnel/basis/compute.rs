//! How the stored table ([`super::STORED`]) is made: docs/maths.md steps 1–4 run as the notebook runs
//! them, the leading right singular vectors by the subspace iteration of [`svd`], and the singular
//! values of step 6 by its one-sided Jacobi. Compiled for the tests, which check the stored table
//! against it; with `NDFPLOT_WRITE_BASIS=1` set, `cargo test --lib stored_basis` writes the table
//! anew instead.
//!
//! The computation is sequential plain f64 arithmetic from a fixed start block, so it does not
//! depend on the thread count or on the CPU's vector instructions; the table spares a run the
//! computation (~125 ms).

use rayon::prelude::*;

use super::{
    Basis, DIELECTRIC_ETA_MAX, DIELECTRIC_ETA_MIN, GRID_SIZE, Index, grid, normalized_curve,
    spectrum_etas,
};
use crate::model::fresnel::gulbrandsen;
use crate::model::math::svd;

mod numpy_f64;

/// Number of materials in the training set (docs/maths.md step 2).
const TRAINING_SIZE: usize = 1000;

/// Share of the training set made of Gulbrandsen conductors (the notebook's `alpha = 0.01`).
const CONDUCTOR_SHARE: f64 = 0.01;

/// The notebook's offset keeping the conductors' reflectivity away from 0: r′ = r/(1 − δ) + δ, δ = 1e-5.
const REFLECTIVITY_OFFSET: f64 = 1.0e-5;

/// First index of the `linspace(1.1, 3.0, 1000)` that the notebook starts its training set from;
/// only row 0 keeps its value.
const TRAINING_ETA_START: f64 = 1.1;

/// The training materials (η, κ) of docs/maths.md step 2, built outside user validation (row k = 10 has
/// η ≈ −9.99995e-6, κ ≈ 1), with the notebook's operation order.
fn training_set() -> Vec<(f64, f64)> {
    let mut materials = vec![(TRAINING_ETA_START, 0.0)];
    for k in 1..TRAINING_SIZE {
        let r = k as f64 / TRAINING_SIZE as f64;
        materials.push(if r <= CONDUCTOR_SHARE {
            let r = r / CONDUCTOR_SHARE / (1.0 - REFLECTIVITY_OFFSET) + REFLECTIVITY_OFFSET;
            gulbrandsen::to_eta_kappa(r, 1.0)
        } else {
            let r = (r - CONDUCTOR_SHARE) / (1.0 - CONDUCTOR_SHARE);
            (
                DIELECTRIC_ETA_MIN + (DIELECTRIC_ETA_MAX - DIELECTRIC_ETA_MIN) * r,
                0.0,
            )
        });
    }
    materials
}

/// The training matrix, row-major with [`GRID_SIZE`] columns: row k is the normalized curve of
/// training material k, rounded as numpy rounds it (`numpy_f64`), so that the basis reproduces the
/// published numpy reference. Rows are computed in parallel; each is the same whichever thread
/// computes it.
fn training_matrix(cos_theta: &[f64]) -> Vec<f64> {
    let rows: Vec<Vec<f64>> = training_set()
        .par_iter()
        .map(|&(eta, kappa)| numpy_f64::training_row(cos_theta, eta, kappa))
        .collect();
    rows.concat()
}

/// `vector / max|vector|`, then negated if its largest-magnitude entry is negative, so that entry is +1.
fn normalize_to_positive_peak(vector: &[f64]) -> Vec<f64> {
    let peak = vector
        .iter()
        .copied()
        .fold(0.0, |m: f64, v| if v.abs() > m.abs() { v } else { m });
    let scale = peak.abs();
    let scaled = vector.iter().map(|v| v / scale);
    if peak < 0.0 {
        scaled.map(|v| -v).collect()
    } else {
        scaled.collect()
    }
}

/// numpy's `argmax`: the first index of the largest value.
fn argmax(values: impl Iterator<Item = f64>) -> usize {
    let mut best = (0, f64::NEG_INFINITY);
    for (i, v) in values.enumerate() {
        if v > best.1 {
            best = (i, v);
        }
    }
    best.0
}

/// The basis of docs/maths.md steps 1–4, computed: the leading right singular vectors of two
/// 1000 × 1000 matrices ([`svd::leading_right_singular_vectors`]).
pub(super) fn computed() -> Basis {
    let cos_theta = grid();
    let curves = training_matrix(&cos_theta);
    let v = svd::leading_right_singular_vectors(&curves, GRID_SIZE, 1);
    let b1 = normalize_to_positive_peak(&v[0].iter().map(|x| x.abs()).collect::<Vec<f64>>());
    let residuals: Vec<f64> = curves
        .chunks_exact(GRID_SIZE)
        .flat_map(|row| row.iter().zip(&b1).map(|(f, b)| f - b))
        .collect();
    let v = svd::leading_right_singular_vectors(&residuals, GRID_SIZE, 2);
    let b2 = normalize_to_positive_peak(&v[0]);
    let b3 = normalize_to_positive_peak(&v[1]);
    let i1 = argmax(b2.iter().copied());
    let i_plus = argmax(b3.iter().copied());
    let i_minus = argmax(b3.iter().map(|v| -v));
    let i2 = if i_plus.abs_diff(i1) > i_minus.abs_diff(i1) {
        i_plus
    } else {
        i_minus
    };
    Basis {
        cos_theta,
        functions: [vec![1.0; GRID_SIZE], b1, b2, b3],
        critical: [i1, i2],
    }
}

/// The singular values of docs/maths.md step 6, computed: those of the normalized curves
/// ([`normalized_curve`]) of the dielectrics η = linspace(1.01, 3, 100) on the grid, one row each
/// ([`svd::singular_values`]), decreasing.
pub(super) fn computed_singular_values() -> Vec<f64> {
    let cos_theta = grid();
    let matrix: Vec<f64> = spectrum_etas()
        .iter()
        .flat_map(|&eta| normalized_curve(&cos_theta, Index::new(eta, 0.0)))
        .collect();
    svd::singular_values(&matrix, GRID_SIZE)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::fresnel::basis::{basis, spectrum};

    #[test]
    fn training_row_rounds_like_numpy() {
        // The quirky row k = 10 (1 − F₀ = 2e-5) from numpy 2.4 float64/complex128 on x86-64
        // (AVX-512), exactly. The accurate values (mpmath, see the test above) differ by up to 3e-11.
        let (eta, kappa) = training_set()[10];
        let row = numpy_f64::training_row(&grid(), eta, kappa);
        let expected = [
            (1, 0.9985843570347518),
            (128, 0.8195432810768335),
            (432, 0.41773762323416164),
            (900, 0.017903384730395037),
            (998, 2.0020008408735605e-6),
        ];
        for (i, value) in expected {
            assert_eq!(row[i], value, "node {i}");
        }
        // A dielectric and a conductor row.
        let (eta, kappa) = training_set()[0];
        assert_eq!(
            numpy_f64::training_row(&grid(), eta, kappa)[500],
            0.010780166047259189
        );
        let (eta, kappa) = training_set()[5];
        assert_eq!(
            numpy_f64::training_row(&grid(), eta, kappa)[300],
            0.5194079664326562
        );
    }

    #[test]
    fn training_set_keeps_the_quirky_row() {
        let materials = training_set();
        assert_eq!(materials[0], (1.1, 0.0));
        let (eta, kappa) = materials[10];
        assert!(
            (eta + 9.99995e-6).abs() < 1e-11 && (kappa - 1.0).abs() < 1e-4,
            "{eta} {kappa}"
        );
        let (eta, kappa) = materials[11];
        assert!(
            kappa == 0.0 && eta > DIELECTRIC_ETA_MIN && eta < 1.02,
            "{eta} {kappa}"
        );
    }

    #[test]
    fn stored_basis_is_the_computed_one() {
        let computed = computed();
        let singular_values = computed_singular_values();
        if std::env::var_os("NDFPLOT_WRITE_BASIS").is_some() {
            let path = concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/src/model/fresnel/basis/stored.txt"
            );
            std::fs::write(path, super::super::stored_text(&computed, &singular_values)).unwrap();
        }
        let stored = basis();
        assert_eq!(stored.critical_indices(), computed.critical_indices());
        for k in 0..4 {
            let worst = stored
                .function(k)
                .iter()
                .zip(computed.function(k))
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max);
            // The functions peak at 1. The table was written with faer 0.24's SVDs (Lanczos
            // bidiagonalization); measured against it: b₁ 2.2e-15, b₂ 6.0e-15, b₃ 3.8e-15.
            assert!(worst <= 1e-13, "b{k}: {worst:e}");
        }
        // The computation is plain f64 arithmetic in a fixed order: the same bits on every
        // machine.
        assert_eq!(spectrum().singular_values, singular_values);
    }
}
