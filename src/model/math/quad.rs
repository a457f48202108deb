//! Adaptive Gauss–Kronrod (7, 15) quadrature: ∫ₐᵇ f(x) dx to a requested relative accuracy.
//!
//! Globally adaptive (QUADPACK `qag`, Piessens et al. 1983): keep a list of subintervals, each with its
//! 15-point Kronrod estimate and the error estimate |K₁₅ − G₇|, and bisect the one with the largest error until
//! the summed error is below `rel_tol · |integral|`. |K₁₅ − G₇| overestimates the error of K₁₅ (which is exact
//! for polynomials of degree 22), so the result is usually far more accurate than asked.
//!
//! A lobe narrower than the spacing of the first 15 nodes can be missed entirely (every node reads ~0): for
//! such integrands split [a, b] at the lobe's scale and integrate the pieces (the NDF normalization audit does).
//! Allocates its interval list; meant for set-up and audits, never per sample.

use std::cmp::Ordering;
use std::collections::BinaryHeap;
use std::fmt;

/// Kronrod abscissae on [−1, 1] (non-negative half, the last is the centre), QUADPACK `qk15`.
#[allow(clippy::excessive_precision)] // the published digits, kept verbatim for checking
const XGK: [f64; 8] = [
    0.991_455_371_120_812_639_206_854_697_526_329,
    0.949_107_912_342_758_524_526_189_684_047_851,
    0.864_864_423_359_769_072_789_712_788_640_926,
    0.741_531_185_599_394_439_863_864_773_280_788,
    0.586_087_235_467_691_130_294_144_845_693_013,
    0.405_845_151_377_397_166_906_606_412_076_961,
    0.207_784_955_007_898_467_600_689_403_773_245,
    0.0,
];

/// Kronrod weights matching [`XGK`], QUADPACK `qk15`.
#[allow(clippy::excessive_precision)] // the published digits, kept verbatim for checking
const WGK: [f64; 8] = [
    0.022_935_322_010_529_224_963_732_008_058_970,
    0.063_092_092_629_978_553_290_700_663_189_204,
    0.104_790_010_322_250_183_839_876_322_541_518,
    0.140_653_259_715_525_918_745_189_590_510_238,
    0.169_004_726_639_267_902_826_583_426_598_550,
    0.190_350_578_064_785_409_913_256_402_421_014,
    0.204_432_940_075_298_892_414_161_999_234_649,
    0.209_482_141_084_727_828_012_999_174_891_714,
];

/// 7-point Gauss weights for the abscissae XGK[1], XGK[3], XGK[5], XGK[7], QUADPACK `qk15`.
#[allow(clippy::excessive_precision)] // the published digits, kept verbatim for checking
const WG: [f64; 4] = [
    0.129_484_966_168_869_693_270_611_432_679_082,
    0.279_705_391_489_276_667_901_467_771_423_780,
    0.381_830_050_505_118_944_950_369_775_488_975,
    0.417_959_183_673_469_387_755_102_040_816_327,
];

/// Bisections allowed before giving up: enough for any integrand with a few dozen narrow features
/// (each costs ~50 bisections from [0, π/2] down to width 1e-15), far from what a smooth one needs.
const MAX_SUBINTERVALS: usize = 4000;

/// Why an integral could not be computed to the requested accuracy.
#[derive(Debug, Clone, PartialEq)]
pub enum QuadError {
    /// The integrand returned NaN or ±∞ at `x`.
    NonFinite {
        /// Where the integrand was not finite.
        x: f64,
    },
    /// The error estimate stayed above the tolerance after [`MAX_SUBINTERVALS`] bisections, or an interval
    /// became too narrow to bisect in double precision.
    NotConverged {
        /// The best estimate reached.
        estimate: f64,
        /// Its estimated absolute error.
        error: f64,
    },
}

impl fmt::Display for QuadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            QuadError::NonFinite { x } => write!(f, "integrand is not finite at x = {x:e}"),
            QuadError::NotConverged { estimate, error } => {
                write!(f, "quadrature did not converge: {estimate:e} ± {error:e}")
            }
        }
    }
}

impl std::error::Error for QuadError {}

/// One subinterval with its Kronrod estimate and error estimate.
#[derive(Debug, Clone, Copy)]
struct Piece {
    a: f64,
    b: f64,
    integral: f64,
    error: f64,
}

/// Applies the (7, 15) rule to [a, b]: (K₁₅, |K₁₅ − G₇|), or the first non-finite abscissa.
fn gauss_kronrod_15(f: &impl Fn(f64) -> f64, a: f64, b: f64) -> Result<Piece, QuadError> {
    let centre = 0.5 * (a + b);
    let half = 0.5 * (b - a);
    let eval = |x: f64| {
        let y = f(x);
        if y.is_finite() {
            Ok(y)
        } else {
            Err(QuadError::NonFinite { x })
        }
    };
    let f_centre = eval(centre)?;
    let mut kronrod = WGK[7] * f_centre;
    let mut gauss = WG[3] * f_centre;
    for (j, (&x, &w)) in XGK[..7].iter().zip(&WGK[..7]).enumerate() {
        let pair = eval(centre - half * x)? + eval(centre + half * x)?;
        kronrod += w * pair;
        if j % 2 == 1 {
            gauss += WG[j / 2] * pair;
        }
    }
    Ok(Piece {
        a,
        b,
        integral: kronrod * half,
        error: ((kronrod - gauss) * half).abs(),
    })
}

/// ∫ₐᵇ f(x) dx with estimated relative error ≤ `rel_tol` (a < b, both finite; `rel_tol` ≥ ~1e-15).
///
/// Converges also when the integral is exactly 0 (all pieces exactly 0). Errors if f is not finite at a node
/// or the tolerance cannot be met within [`MAX_SUBINTERVALS`] bisections.
///
/// The piece bisected next is the one of largest error (the latest of equal ones), taken from a heap; the
/// sums tested against `rel_tol` are the pieces' sums in their order, and past [`EXACT_SUMS`] pieces running
/// sums stand in for them between every [`RESYNC`]-th bisection, the ordered sums confirming convergence
/// before it is reported: O(n log n) for an integrand that needs thousands of pieces instead of O(n²).
pub fn integrate(f: impl Fn(f64) -> f64, a: f64, b: f64, rel_tol: f64) -> Result<f64, QuadError> {
    let mut pieces = vec![gauss_kronrod_15(&f, a, b)?];
    let mut worst = BinaryHeap::from([Worst::of(&pieces[0], 0)]);
    let ordered = |pieces: &[Piece]| -> (f64, f64) {
        (
            pieces.iter().map(|p| p.integral).sum(),
            pieces.iter().map(|p| p.error).sum(),
        )
    };
    let (mut integral, mut error) = ordered(&pieces);
    let mut since_sync = 0;
    loop {
        if error <= rel_tol * integral.abs() {
            if since_sync == 0 {
                return Ok(integral);
            }
            (integral, error) = ordered(&pieces);
            since_sync = 0;
            continue;
        }
        let index = worst.pop().expect("every piece is in the heap").index;
        let old = pieces[index];
        let (a, b) = (old.a, old.b);
        let mid = 0.5 * (a + b);
        if pieces.len() >= MAX_SUBINTERVALS || mid <= a || mid >= b {
            if since_sync > 0 {
                (integral, error) = ordered(&pieces);
            }
            return Err(QuadError::NotConverged {
                estimate: integral,
                error,
            });
        }
        let (left, right) = (gauss_kronrod_15(&f, a, mid)?, gauss_kronrod_15(&f, mid, b)?);
        pieces[index] = left;
        pieces.push(right);
        worst.push(Worst::of(&left, index));
        worst.push(Worst::of(&right, pieces.len() - 1));
        since_sync += 1;
        if pieces.len() <= EXACT_SUMS || since_sync >= RESYNC {
            (integral, error) = ordered(&pieces);
            since_sync = 0;
        } else {
            integral += (left.integral + right.integral) - old.integral;
            error += (left.error + right.error) - old.error;
        }
    }
}

/// Pieces up to which [`integrate`] sums every piece after each bisection (a smooth integrand's whole
/// run).
const EXACT_SUMS: usize = 64;

/// Bisections between two ordered sums of [`integrate`] past [`EXACT_SUMS`] pieces: the running sums'
/// rounding drift stays far below any tolerance over this many updates.
const RESYNC: usize = 64;

/// A piece's place in [`integrate`]'s heap: ordered by error, then by index, so the top is the piece
/// of largest error and the latest of equal ones.
#[derive(Debug, Clone, Copy)]
struct Worst {
    error: f64,
    index: usize,
}

impl Worst {
    fn of(piece: &Piece, index: usize) -> Worst {
        Worst {
            error: piece.error,
            index,
        }
    }
}

impl PartialEq for Worst {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Worst {}

impl PartialOrd for Worst {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Worst {
    fn cmp(&self, other: &Self) -> Ordering {
        self.error
            .total_cmp(&other.error)
            .then(self.index.cmp(&other.index))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// The relative accuracy these tests ask for and check: 1e-13, close to what summing ~100 positive
    /// terms in double precision can guarantee.
    const TOL: f64 = 1e-13;

    #[test]
    fn weights_integrate_constants_exactly() {
        let kronrod = WGK[7] + 2.0 * WGK[..7].iter().sum::<f64>();
        let gauss = WG[3] + 2.0 * WG[..3].iter().sum::<f64>();
        assert!((kronrod - 2.0).abs() <= 4.0 * f64::EPSILON);
        assert!((gauss - 2.0).abs() <= 4.0 * f64::EPSILON);
    }

    #[test]
    fn kronrod_rule_is_exact_for_degree_22() {
        let piece = gauss_kronrod_15(&|x: f64| x.powi(22), 0.0, 1.0).unwrap();
        assert!((piece.integral - 1.0 / 23.0).abs() <= 1e-15);
    }

    #[test]
    fn smooth_integrals_reach_the_tolerance() {
        let sin = integrate(f64::sin, 0.0, PI, TOL).unwrap();
        assert!((sin - 2.0).abs() <= 2.0 * TOL);
        let gaussian = integrate(|x: f64| (-x * x).exp(), -10.0, 10.0, TOL).unwrap();
        assert!((gaussian / PI.sqrt() - 1.0).abs() <= TOL);
    }

    #[test]
    fn resolves_a_narrow_interior_lobe() {
        // ∫ exp(−((x − 0.3)/w)²) over [0, 1] = w√π for w = 1e-3 (the tails beyond the ends are < e^{−4.9e5}).
        let w = 1e-3;
        let lobe = integrate(|x: f64| (-((x - 0.3) / w).powi(2)).exp(), 0.0, 1.0, TOL).unwrap();
        assert!((lobe / (w * PI.sqrt()) - 1.0).abs() <= TOL);
    }

    #[test]
    fn integrable_endpoint_singularity_converges() {
        // ∫₀¹ x^{−1/2} dx = 2; the nodes never touch x = 0.
        let v = integrate(|x: f64| 1.0 / x.sqrt(), 0.0, 1.0, 1e-10).unwrap();
        assert!((v - 2.0).abs() <= 1e-9);
    }

    #[test]
    fn many_sharp_peaks_converge_past_the_running_sums() {
        // Σ (|x − c_k| + δ)^{−1/2} over 21 points inside [0, 1], δ = 1e-12: each peak costs dozens of
        // bisections, so the run goes far past EXACT_SUMS pieces; each term integrates to
        // 2(√(c + δ) + √(1 − c + δ) − 2√δ).
        let delta = 1e-12;
        let centres: Vec<f64> = (0..21).map(|k| (k as f64 + 0.3183) / 21.0).collect();
        let f = |x: f64| {
            centres
                .iter()
                .map(|c| 1.0 / ((x - c).abs() + delta).sqrt())
                .sum::<f64>()
        };
        let exact: f64 = centres
            .iter()
            .map(|c| 2.0 * ((c + delta).sqrt() + (1.0 - c + delta).sqrt() - 2.0 * delta.sqrt()))
            .sum();
        let v = integrate(f, 0.0, 1.0, 1e-10).unwrap();
        assert!((v / exact - 1.0).abs() <= 1e-9, "{v} against {exact}");
    }

    #[test]
    fn zero_integrand_is_zero() {
        assert_eq!(integrate(|_| 0.0, 0.0, 1.0, TOL), Ok(0.0));
    }

    #[test]
    fn non_finite_integrand_is_an_error() {
        let err =
            integrate(|x: f64| if x > 0.5 { f64::NAN } else { 1.0 }, 0.0, 1.0, TOL).unwrap_err();
        assert!(matches!(err, QuadError::NonFinite { x } if x > 0.5));
    }
}
