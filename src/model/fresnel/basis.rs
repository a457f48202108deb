//! The Belcour–Bati–Barla four-term Fresnel basis (SIGGRAPH 2020, "Bringing an Accurate Fresnel to
//! Real-Time Rendering: a Preintegrable Decomposition"), rebuilt exactly as docs/maths.md steps 1–7 and
//! the notebook `seeds/004_a7d16ebd756ecf05.txt` do, and the projection of a material onto it.
//!
//! - Grid: 1000 nodes c_i = numpy `linspace(0, 1, 1000)` = i·(1/999), the last one exactly 1.
//! - Training set: 1000 materials (η = linspace(1.1, 3, 1000) overwritten row by row: 10 Gulbrandsen
//!   conductors with g = 1, including the r′ > 1 row at k = 10 that gives η < 0, then dielectrics
//!   1.01 … 3); each row is the normalized curve (F − F₀)/(1 − F₀) of the normative Fresnel form,
//!   rounded exactly as numpy float64 rounds it (`numpy_f64`): row k = 10 has 1 − F₀ = 2e-5, so
//!   each ulp of F moves it by ~5e-12 and the basis by up to ~1e-11, and only numpy's own rounding
//!   reproduces the published reference basis to 1e-12 (it does to ~1e-14).
//! - b₀ = 1, b₁ = |v₀|/max|v₀| from the SVD of the rows; b₂ = v₀/max|v₀|, b₃ = v₁/max|v₁| from the SVD
//!   of the rows minus b₁, each flipped so its largest-magnitude entry is +1.
//! - Critical indices: i₁ = argmax b₂ (128) and, of argmax ±b₃, the one farther from i₁ (432).
//! - Projection (`fresnel2coeffs`): c₀ = F(1), c₁ = 1 − c₀ (0 when c₀ = 0), (c₂, c₃) solve the 2×2
//!   system c₂ b₂[i] + c₃ b₃[i] = F(c_i) − (c₀ + c₁ b₁[i]) at the two critical nodes.
//! - Spectrum check (step 6): singular values of the normalized curves of 100 dielectrics
//!   η = linspace(1.01, 3, 100).
//!
//! The basis is computed by `basis/compute.rs` (the leading right singular vectors only, by
//! subspace iteration, `crate::model::math::svd`) and stored as a table that runs read
//! ([`STORED`]), and so are the spectrum's singular values, computed by one-sided Jacobi, which
//! keeps even their smallest values accurate; a test recomputes both and holds the table to them.
//! Another SVD routine moves b₁…b₃ by ~1e-14 only (reference/README.md).
//! Tabulated values between nodes are interpolated linearly in c (see [`Basis::interpolate`]). The
//! reconstruction and the basis functions are approximations and basis vectors, not reflectances:
//! they may leave [0, 1] and are never clamped.

use std::sync::OnceLock;

use super::exact::{Incidence, Index, normalized_reflectance, reflectance};
use crate::model::grid::linspace;

#[cfg(test)]
mod compute;

/// Number of grid nodes c_i (docs/maths.md step 1).
pub const GRID_SIZE: usize = 1000;

/// Index range of the dielectric training rows: η from 1.01 to 3.0 (the notebook's literals).
const DIELECTRIC_ETA_MIN: f64 = 1.01;
/// Upper end of the dielectric index range, for the training rows and the spectrum check.
const DIELECTRIC_ETA_MAX: f64 = 3.0;
/// Number of dielectrics in the spectrum check (docs/maths.md step 6).
const SPECTRUM_SIZE: usize = 100;

/// The grid c_i = numpy `linspace(0, 1, 1000)`, i.e. i·fl(1/999) with c₉₉₉ = 1 exactly.
pub fn grid() -> Vec<f64> {
    linspace(0.0, 1.0, GRID_SIZE)
}

/// The normalized curve (F(c_i) − F₀)/(1 − F₀) of the exact Fresnel form on the grid, F₀ = F(1)
/// (`exact::normalized_reflectance`): accurate to ~1e-16 even where 1 − F₀ is tiny (the training
/// row with 1 − F₀ = 2e-5, where the direct quotient carries ~4e-11 of rounding). Identically 0 for
/// η̃ = 1.
///
/// The spectrum curves (the notebook's left spectrum panel, and the matrix of the spectrum check).
/// The basis training rows are rounded like numpy's instead (`numpy_f64::training_row`), which is
/// ~1e-11 less accurate in the row with 1 − F₀ = 2e-5 but reproduces the published basis.
pub fn normalized_curve(cos_theta: &[f64], index: Index) -> Vec<f64> {
    cos_theta
        .iter()
        .map(|&c| normalized_reflectance(Incidence::from_cos(c), index))
        .collect()
}

/// The four basis functions on the grid and the two critical indices.
#[derive(Debug, Clone)]
pub struct Basis {
    cos_theta: Vec<f64>,
    functions: [Vec<f64>; 4],
    critical: [usize; 2],
}

static BASIS: OnceLock<Basis> = OnceLock::new();

/// The basis and the spectrum as [`compute`] makes them, stored: a comment line, `critical i₁ i₂`,
/// then `b1`, `b2` and `b3` each followed by its 1000 node values (b₀ = 1), then `spectrum`
/// followed by the 100 singular values of step 6, decreasing, all in shortest round-trip form.
/// Reading it takes well under a millisecond where computing it takes the training matrix and two
/// partial SVDs (~50 ms) and a full 100 × 1000 SVD (~75 ms), and every machine gets the same bits;
/// a test keeps it equal to the computation.
const STORED: &str = include_str!("basis/stored.txt");

/// The basis of docs/maths.md steps 1–4, read from [`STORED`] on first call and shared.
pub fn basis() -> &'static Basis {
    BASIS.get_or_init(|| parse_stored(STORED))
}

/// Whether [`basis`] has been read in this process: it is only when a curve needs it.
pub fn basis_is_loaded() -> bool {
    BASIS.get().is_some()
}

/// The basis written in `text` (the format of [`STORED`]). Panics on a malformed table: the only
/// table read is the one compiled in, which the tests read.
fn parse_stored(text: &str) -> Basis {
    let mut critical = [0; 2];
    let mut functions = [vec![1.0; GRID_SIZE], Vec::new(), Vec::new(), Vec::new()];
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let mut words = line.split_ascii_whitespace();
        match words.next() {
            Some("critical") => {
                for (slot, word) in critical.iter_mut().zip(words) {
                    *slot = word.parse().expect("a node index");
                }
            }
            Some(name @ ("b1" | "b2" | "b3")) => {
                let k = usize::from(name.as_bytes()[1] - b'0');
                functions[k] = words.map(|w| w.parse().expect("a number")).collect();
            }
            Some("spectrum") => {}
            _ => panic!("unexpected line in the stored basis: {line:.40}"),
        }
    }
    assert!(
        functions.iter().all(|f| f.len() == GRID_SIZE),
        "1000 values per function"
    );
    Basis {
        cos_theta: grid(),
        functions,
        critical,
    }
}

/// The singular values written in `text` (the `spectrum` line of [`STORED`]). Panics on a
/// malformed table, as [`parse_stored`] does.
fn parse_stored_spectrum(text: &str) -> Vec<f64> {
    let line = text
        .lines()
        .find_map(|l| l.strip_prefix("spectrum "))
        .expect("a spectrum line in the stored table");
    let values: Vec<f64> = line
        .split_ascii_whitespace()
        .map(|w| w.parse().expect("a number"))
        .collect();
    assert_eq!(
        values.len(),
        SPECTRUM_SIZE,
        "one singular value per dielectric"
    );
    values
}

/// `basis` and the spectrum's `singular_values` in the format of [`STORED`].
#[cfg(test)]
fn stored_text(basis: &Basis, singular_values: &[f64]) -> String {
    let mut text = String::from(
        "# The Belcour–Bati–Barla Fresnel basis b1…b3 on c_i = linspace(0, 1, 1000), its critical \
         nodes and the singular values of the spectrum check, as src/model/fresnel/basis/compute.rs \
         computes them; shortest round-trip doubles.\n",
    );
    text.push_str(&format!(
        "critical {} {}\n",
        basis.critical[0], basis.critical[1]
    ));
    for k in 1..4 {
        let values: Vec<String> = basis.functions[k]
            .iter()
            .map(|v| format!("{v:?}"))
            .collect();
        text.push_str(&format!("b{k} {}\n", values.join(" ")));
    }
    let values: Vec<String> = singular_values.iter().map(|v| format!("{v:?}")).collect();
    text.push_str(&format!("spectrum {}\n", values.join(" ")));
    text
}

impl Basis {
    /// The grid nodes c_i = numpy `linspace(0, 1, 1000)`.
    pub fn cos_theta(&self) -> &[f64] {
        &self.cos_theta
    }

    /// Basis function b_k (k ∈ 0..=3) at the grid nodes. Panics for k > 3.
    pub fn function(&self, k: usize) -> &[f64] {
        &self.functions[k]
    }

    /// The critical indices [i₁, i₂] of docs/maths.md step 4: [128, 432].
    pub fn critical_indices(&self) -> [usize; 2] {
        self.critical
    }

    /// The interval [c_i, c_{i+1}] holding `cos_theta` and the weight t = (c − c_i)/(c_{i+1} − c_i).
    ///
    /// The weight uses the stored node values, so c = c_i gives t = 0 exactly; both differences are
    /// exact for i ≥ 1 (Sterbenz). A cos θ that misses its node by δ (cos(arccos c_i) ≠ c_i, |δ| of a
    /// few ulps) lands in either neighbouring interval, and the continuity of the interpolant bounds
    /// the error by |δ| · max|b′| ≲ 4.4e-16 · 42 ≈ 2e-14 (the steepest segment is b₃ between c₀, c₁).
    fn locate(&self, cos_theta: f64) -> (usize, f64) {
        let last = GRID_SIZE - 1;
        // A negative or NaN product saturates to 0 in the cast.
        let i = ((cos_theta * last as f64).floor() as usize).min(last - 1);
        let c = &self.cos_theta;
        (i, (cos_theta - c[i]) / (c[i + 1] - c[i]))
    }

    /// b_k at an arbitrary c = cos θ ∈ [0, 1] by linear interpolation in c between the grid nodes:
    /// (1 − t) b_k[i] + t b_k[i+1]. Equals the node value exactly at c = c_i. Panics for k > 3.
    pub fn interpolate(&self, k: usize, cos_theta: f64) -> f64 {
        let (i, t) = self.locate(cos_theta);
        let b = &self.functions[k];
        (1.0 - t) * b[i] + t * b[i + 1]
    }
}

/// The four coefficients of a material in the basis: F̂ = c₀ + c₁ b₁ + c₂ b₂ + c₃ b₃.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Coefficients {
    /// c₀ = F(θ = 0), the normal-incidence reflectance.
    pub c0: f64,
    /// c₁ = 1 − c₀ (0 when c₀ = 0).
    pub c1: f64,
    /// Weight of b₂, fitted at the critical nodes.
    pub c2: f64,
    /// Weight of b₃, fitted at the critical nodes.
    pub c3: f64,
}

/// The notebook's `fresnel2coeffs` (docs/maths.md step 5) for the exact Fresnel of `index` η̃ = η + iκ:
/// c₀ = F(1), c₁ = 1 − c₀ (0 when c₀ = 0), and (c₂, c₃) from the 2×2 system at the critical nodes,
/// solved by Cramer's rule. Computes the basis on first use.
pub fn coeffs(index: Index) -> Coefficients {
    let basis = basis();
    let [b1, b2, b3] = [basis.function(1), basis.function(2), basis.function(3)];
    let [i1, i2] = basis.critical;
    let c0 = reflectance(Incidence::NORMAL, index);
    let c1 = if c0 != 0.0 { 1.0 - c0 } else { 0.0 };
    let df1 = reflectance(Incidence::from_cos(basis.cos_theta[i1]), index) - (c0 + c1 * b1[i1]);
    let df2 = reflectance(Incidence::from_cos(basis.cos_theta[i2]), index) - (c0 + c1 * b1[i2]);
    let det = b2[i1] * b3[i2] - b3[i1] * b2[i2];
    let c2 = (df1 * b3[i2] - df2 * b3[i1]) / det;
    let c3 = (b2[i1] * df2 - b2[i2] * df1) / det;
    Coefficients { c0, c1, c2, c3 }
}

impl Coefficients {
    /// The reconstruction from the tabulated values b0..b3[i] (the notebook's evaluation order).
    fn combine(&self, b: [f64; 4]) -> f64 {
        self.c0 * b[0] + self.c1 * b[1] + self.c2 * b[2] + self.c3 * b[3]
    }

    /// The reconstruction F̂_i = c₀ + c₁ b₁[i] + c₂ b₂[i] + c₃ b₃[i] at the 1000 grid nodes.
    pub fn reconstruction(&self) -> Vec<f64> {
        let f = &basis().functions;
        (0..GRID_SIZE)
            .map(|i| self.combine([f[0][i], f[1][i], f[2][i], f[3][i]]))
            .collect()
    }

    /// F̂ at an arbitrary c = cos θ ∈ [0, 1], interpolated linearly in c between the grid nodes with
    /// the weights of [`Basis::interpolate`]; equals F̂_i exactly at c = c_i.
    pub fn interpolate(&self, cos_theta: f64) -> f64 {
        let basis = basis();
        let (i, t) = basis.locate(cos_theta);
        let f = &basis.functions;
        let node = |j: usize| self.combine([f[0][j], f[1][j], f[2][j], f[3][j]]);
        (1.0 - t) * node(i) + t * node(i + 1)
    }

    /// `l2_grid` = ‖F − F̂‖₂ over the 1000 grid nodes, F the exact Fresnel of `index` η̃ = η + iκ (the
    /// notebook's L2).
    pub fn l2_grid(&self, index: Index) -> f64 {
        let basis = basis();
        let reconstruction = self.reconstruction();
        let sum_sq: f64 = basis
            .cos_theta
            .iter()
            .zip(&reconstruction)
            .map(|(&c, f_hat)| (reflectance(Incidence::from_cos(c), index) - f_hat).powi(2))
            .sum();
        sum_sq.sqrt()
    }
}

/// The spectrum figure of docs/maths.md step 6.
#[derive(Debug, Clone)]
pub struct Spectrum {
    /// The dielectric indices η = linspace(1.01, 3, 100), κ = 0.
    pub etas: Vec<f64>,
    /// Singular values s_k of their normalized curves on the grid, decreasing.
    pub singular_values: Vec<f64>,
    /// s_k / Σ s (normalized by the sum, not the sum of squares).
    pub normalized: Vec<f64>,
    /// Running sums of `normalized`: 0.91356, 0.97961, 0.99477, …
    pub cumulative: Vec<f64>,
}

static SPECTRUM: OnceLock<Spectrum> = OnceLock::new();

/// The dielectric indices of the spectrum check, η = linspace(1.01, 3, 100), κ = 0.
fn spectrum_etas() -> Vec<f64> {
    linspace(DIELECTRIC_ETA_MIN, DIELECTRIC_ETA_MAX, SPECTRUM_SIZE)
}

/// The spectrum of docs/maths.md step 6, its singular values read from [`STORED`] on first call
/// and shared.
pub fn spectrum() -> &'static Spectrum {
    SPECTRUM.get_or_init(|| {
        let etas = spectrum_etas();
        let singular_values = parse_stored_spectrum(STORED);
        let total: f64 = singular_values.iter().sum();
        let normalized: Vec<f64> = singular_values.iter().map(|s| s / total).collect();
        let cumulative = normalized
            .iter()
            .scan(0.0, |sum, s| {
                *sum += s;
                Some(*sum)
            })
            .collect();
        Spectrum {
            etas,
            singular_values,
            normalized,
            cumulative,
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_matches_numpy_linspace() {
        let c = grid();
        assert_eq!(c.len(), GRID_SIZE);
        assert_eq!((c[0], c[1], c[999]), (0.0, 0.001001001001001001, 1.0));
    }

    #[test]
    fn normalized_curve_is_accurate_where_one_minus_f0_is_tiny() {
        // The row k = 10 of the training set (1 − F₀ = 2e-5) at nodes 1, 128, 432, 900;
        // mpmath at 50 digits from these exact doubles, rounded to the nearest double.
        let (eta, kappa) = (-9.999950000513731e-6, 0.9999999999472646);
        let c = grid();
        let row = normalized_curve(&c, Index::new(eta, kappa));
        let expected = [
            (1, 0.9985843570318703),
            (128, 0.8195432810777029),
            (432, 0.4177376232363717),
            (900, 0.017903384756318708),
        ];
        for (i, value) in expected {
            assert!(
                (row[i] - value).abs() < 1e-15,
                "node {i}: {} vs {value}",
                row[i]
            );
        }
    }

    #[test]
    fn spectrum_matches_a_bidiagonalization_svd() {
        // faer 0.24 thin SVD, f64 (Householder bidiagonalization, then divide and conquer,
        // single-threaded), of the same matrix: its 18 values above its rounding floor (its next
        // six were 2e-13 … 8e-13, i.e. up to 9e-15·s₀, the rest below 1e-15).
        const BIDIAGONALIZATION: [f64; 18] = [
            85.81489433586142,
            6.2044617043477315,
            1.4240647133081228,
            0.40160540237816716,
            0.07491044747391984,
            0.01282017776114136,
            0.0019977944500466018,
            0.00025676189406067515,
            6.681991570409983e-5,
            1.2075982987033763e-5,
            2.528917474431042e-6,
            2.3782209273595912e-7,
            2.8427935606044087e-8,
            3.239792943504047e-9,
            8.22969624744253e-10,
            1.7974217548924705e-10,
            9.958906018336693e-12,
            2.3362954474375365e-12,
        ];
        // Its values are accurate to ~ε·s₀ absolute, so the small ones are held relative to s₀
        // only (measured 1.2e-15·s₀ at most), those above 1e-4·s₀ also relative to themselves
        // (measured 4.2e-14). Against the exact singular values of the same doubles (80-digit
        // eigenvalues of the exact A·Aᵀ), one-sided Jacobi errs by 1.3e-16·s₀ at most and
        // bidiagonalization by 7.9e-15·s₀.
        let s = &spectrum().singular_values;
        for (k, (&value, reference)) in s.iter().zip(BIDIAGONALIZATION).enumerate() {
            let error = (value - reference).abs();
            assert!(error <= 1e-14 * s[0], "s{k}: {value:e} vs {reference:e}");
            if reference > 1e-4 * s[0] {
                assert!(
                    error <= 1e-13 * reference,
                    "s{k}: {value:e} vs {reference:e}"
                );
            }
        }
    }
}
