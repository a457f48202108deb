//! How far apart two curves are over θ ∈ [0, π/2]: the metrics of `ndfplot compare` (CONTRACTS.md),
//! and the building blocks they share with fitting and the normalization audit — the projected-area
//! integral by piecewise adaptive quadrature, and maxima located by a dense scan refined by golden-section
//! search.
//!
//! Pure f64 code over [`Curve`]s and closures: no I/O, no formatting of reports.

use crate::curve::Curve;
use crate::grid::linspace;
use crate::math::quad::{QuadError, integrate};
use crate::math::tolerance::QUAD_REL_TOL;
use std::f64::consts::{FRAC_PI_2, PI};
use std::fmt;

pub mod sampled;

/// Nodes of the c-grid of `l2_grid`: c_i = numpy linspace(0, 1, 1000), θ_i = arccos c_i — the Fresnel
/// notebook's grid (MATH.md, "The Belcour–Bati–Barla basis").
pub const L2_GRID_NODES: usize = 1000;

/// Uniform θ nodes of the scan that precedes the refinement of a maximum: 2048 intervals of ~7.7e-4 rad,
/// finer than any off-normal feature of the catalogue's lobes; narrower lobes at the normal or at grazing
/// are caught by the geometric breakpoints added to the scan.
const SCAN_NODES: usize = 2049;

/// Geometric ratio between successive quadrature breakpoints: pieces span a factor 4 in θ (or in π/2 − θ),
/// so that a lobe of any width meets a piece of comparable width.
const BREAK_RATIO: f64 = 4.0;

/// First breakpoint below the lobe width, as a fraction of it: three factors of [`BREAK_RATIO`], so the
/// lobe's core lies inside pieces that resolve it.
const BREAK_BELOW_WIDTH: f64 = 1.0 / 64.0;

/// Closest approach of the grazing breakpoints to π/2, 4⁻²⁴ ≈ 3.6e-15 rad: ~16 doubles from π/2, below the
/// narrowest grazing lobe accepted (~1e-4 rad wide) by eleven orders of magnitude.
const GRAZING_BREAK_MIN: f64 = 3.552713678800501e-15;

/// Absolute θ tolerance of the golden-section refinement of a maximum: the location of a smooth maximum is
/// determined only to ~√ε ≈ 1.5e-8 relative by its values, so 1e-12 rad is past anything meaningful while
/// the value there is exact to rounding.
const ARGMAX_TOL: f64 = 1e-12;

/// Shift of the l2_projected integrand, as a fraction of the larger peak P: (a − b)² carries an absolute
/// rounding error of ~2|a − b|·ε·P, which no relative tolerance beats once |a − b| ≪ P. Integrating
/// (a − b)² + (1e-3 P)² keeps that error below `QUAD_REL_TOL` of the integrand everywhere (its worst case,
/// |a − b| = 1e-3 P, gives 2.2e-13), and leaves l2_projected exact to ~1e-9 P even for nearly equal curves.
const L2_SHIFT: f64 = 1e-3;

/// 1/φ, the golden-section step.
const INV_PHI: f64 = 0.618_033_988_749_894_9;

/// Why a metric could not be computed.
#[derive(Debug, Clone, PartialEq)]
pub enum MetricError {
    /// A curve (or the compared expression) is NaN or infinite at θ.
    NonFinite {
        /// Where.
        theta: f64,
    },
    /// An integral did not converge.
    Quad(QuadError),
    /// Two sampled series share no θ.
    Disjoint,
}

impl fmt::Display for MetricError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MetricError::NonFinite { theta } => write!(f, "not finite at theta = {theta:?}"),
            MetricError::Quad(e) => write!(f, "{e}"),
            MetricError::Disjoint => write!(f, "the two series share no θ"),
        }
    }
}

impl std::error::Error for MetricError {}

impl From<QuadError> for MetricError {
    fn from(e: QuadError) -> Self {
        match e {
            QuadError::NonFinite { x } => MetricError::NonFinite { theta: x },
            other => MetricError::Quad(other),
        }
    }
}

/// An integral with its estimated absolute error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate {
    /// The value.
    pub value: f64,
    /// Estimated absolute error: `QUAD_REL_TOL · |piece|` summed over converged pieces (the quadrature's
    /// own estimate is below it) plus the error estimates of pieces accepted without converging.
    pub error: f64,
}

/// The width of a lobe of peak `peak` holding unit projected mass, w = 1/√(π · peak), capped at π/2: the
/// scale at which quadrature breakpoints and scan nodes are placed.
pub fn lobe_width(peak: f64) -> f64 {
    if peak > 0.0 {
        (1.0 / (PI * peak)).sqrt().min(FRAC_PI_2)
    } else {
        FRAC_PI_2
    }
}

/// Breakpoints of [0, π/2]: 0, π/2, geometric steps from `width`/64 up to π/2, and towards π/2 down to
/// [`GRAZING_BREAK_MIN`], sorted.
fn breakpoints(width: f64) -> Vec<f64> {
    let mut breaks = vec![0.0, FRAC_PI_2];
    let mut t = width * BREAK_BELOW_WIDTH;
    while t < FRAC_PI_2 {
        if t > 0.0 {
            breaks.push(t);
        }
        t *= BREAK_RATIO;
    }
    let mut d = 0.5;
    while d >= GRAZING_BREAK_MIN {
        breaks.push(FRAC_PI_2 - d);
        d /= BREAK_RATIO;
    }
    breaks.sort_by(f64::total_cmp);
    breaks.dedup();
    breaks
}

/// 2π ∫₀^{π/2} f(θ) sin θ cos θ dθ (the projected-area integral of MATH.md) by adaptive Gauss–Kronrod
/// quadrature over pieces broken geometrically around `width` (see [`lobe_width`]) and towards grazing,
/// each to relative accuracy `QUAD_REL_TOL`.
///
/// `shift` ≥ 0 is added to f on every piece and its exact integral (π · shift over [0, π/2]) subtracted
/// again: it turns the relative tolerance into an absolute one of ~`QUAD_REL_TOL` · π · shift where f is
/// small against it (0 for a purely relative accuracy).
///
/// Pieces next to π/2 may hold ~1e-30 of the total, sampled by θ only a few ulps apart, where relative
/// convergence is out of reach: such a piece is accepted when the errors of all unconverged pieces together
/// stay within `QUAD_REL_TOL` of the whole integral.
pub fn projected_integral(
    f: impl Fn(f64) -> f64,
    width: f64,
    shift: f64,
) -> Result<Estimate, MetricError> {
    let integrand = |theta: f64| (f(theta) + shift) * theta.sin() * theta.cos();
    let (mut total, mut converged_error, mut loose_error) = (0.0, 0.0, 0.0);
    for piece in breakpoints(width).windows(2) {
        let (a, b) = (piece[0], piece[1]);
        // ∫ₐᵇ shift · sin θ cos θ dθ = shift · (sin²b − sin²a)/2.
        let shifted = 0.5 * shift * (b.sin().powi(2) - a.sin().powi(2));
        match integrate(integrand, a, b, QUAD_REL_TOL) {
            Ok(v) => {
                total += v - shifted;
                converged_error += QUAD_REL_TOL * v.abs();
            }
            Err(QuadError::NotConverged { estimate, error }) => {
                total += estimate - shifted;
                loose_error += error;
            }
            Err(e) => return Err(e.into()),
        }
    }
    if loose_error > QUAD_REL_TOL * total.abs() {
        return Err(MetricError::Quad(QuadError::NotConverged {
            estimate: 2.0 * PI * total,
            error: 2.0 * PI * loose_error,
        }));
    }
    Ok(Estimate {
        value: 2.0 * PI * total,
        error: 2.0 * PI * (converged_error + loose_error),
    })
}

/// A maximum of a function over θ: where it is and its value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Extremum {
    /// θ of the maximum in radians (the smallest such θ found when several nodes tie).
    pub theta: f64,
    /// The maximum value.
    pub value: f64,
}

/// The maximum of `f` over an interval [a, b] known to hold a single maximum, by golden-section search
/// to within `tol` in x; the endpoints count as candidates, so a maximum at an end is returned exactly.
/// `fa` and `fb` are f(a) and f(b).
pub fn golden_section_max<E>(
    mut f: impl FnMut(f64) -> Result<f64, E>,
    (a, fa): (f64, f64),
    (b, fb): (f64, f64),
    tol: f64,
) -> Result<Extremum, E> {
    let mut best = if fb > fa {
        Extremum {
            theta: b,
            value: fb,
        }
    } else {
        Extremum {
            theta: a,
            value: fa,
        }
    };
    let (mut lo, mut hi) = (a, b);
    let mut x1 = hi - INV_PHI * (hi - lo);
    let mut x2 = lo + INV_PHI * (hi - lo);
    let (mut f1, mut f2) = (f(x1)?, f(x2)?);
    while (hi - lo).abs() > tol {
        if f1 >= f2 {
            (hi, x2, f2) = (x2, x1, f1);
            x1 = hi - INV_PHI * (hi - lo);
            f1 = f(x1)?;
        } else {
            (lo, x1, f1) = (x1, x2, f2);
            x2 = lo + INV_PHI * (hi - lo);
            f2 = f(x2)?;
        }
        if x1 == x2 {
            break;
        }
    }
    for (x, v) in [(x1, f1), (x2, f2)] {
        if v > best.value || (v == best.value && x < best.theta) {
            best = Extremum { theta: x, value: v };
        }
    }
    Ok(best)
}

/// The maximum of `f` over [0, π/2]: a scan of uniform nodes plus the breakpoints of [`projected_integral`]
/// around `width`, then a golden-section refinement between the neighbours of the best node. Errors if f is
/// not finite at a visited θ.
pub fn maximum(f: impl Fn(f64) -> f64, width: f64) -> Result<Extremum, MetricError> {
    let finite = |theta: f64| {
        let v = f(theta);
        if v.is_finite() {
            Ok(v)
        } else {
            Err(MetricError::NonFinite { theta })
        }
    };
    let mut nodes = linspace(0.0, FRAC_PI_2, SCAN_NODES);
    nodes.extend(breakpoints(width));
    nodes.sort_by(f64::total_cmp);
    nodes.dedup();
    let values: Vec<f64> = nodes.iter().map(|&t| finite(t)).collect::<Result<_, _>>()?;
    let best = (0..nodes.len()).fold(0, |best, i| if values[i] > values[best] { i } else { best });
    let left = best.saturating_sub(1);
    let right = (best + 1).min(nodes.len() - 1);
    let refined = golden_section_max(
        finite,
        (nodes[left], values[left]),
        (nodes[right], values[right]),
        ARGMAX_TOL,
    )?;
    Ok(if refined.value > values[best] {
        refined
    } else {
        Extremum {
            theta: nodes[best],
            value: values[best],
        }
    })
}

/// The peak of a curve over [0, π/2] (see [`maximum`]), with the breakpoints placed at the width of a lobe
/// of its value at the normal.
pub fn peak(curve: &Curve) -> Result<Extremum, MetricError> {
    maximum(|t| curve.eval(t), lobe_width(curve.eval(0.0)))
}

/// `l2_projected` = sqrt(2π ∫₀^{π/2} (a − b)² sin θ cos θ dθ), breakpoints at the narrower of the lobe
/// widths of the two peaks `peak_a`, `peak_b`; exactly 0 for identical curves.
pub fn l2_projected_with(
    a: &Curve,
    b: &Curve,
    peak_a: f64,
    peak_b: f64,
) -> Result<f64, MetricError> {
    if a == b {
        return Ok(0.0);
    }
    let width = lobe_width(peak_a).min(lobe_width(peak_b));
    let shift = (L2_SHIFT * peak_a.abs().max(peak_b.abs())).powi(2);
    let squared = projected_integral(|t| (a.eval(t) - b.eval(t)).powi(2), width, shift)?;
    Ok(squared.value.max(0.0).sqrt())
}

/// `l2_projected` of two curves (see [`l2_projected_with`]), their peaks taken as their values at the
/// normal.
pub fn l2_projected(a: &Curve, b: &Curve) -> Result<f64, MetricError> {
    l2_projected_with(a, b, a.eval(0.0), b.eval(0.0))
}

/// `l2_grid` = ‖a − b‖₂ over θ_i = arccos c_i, c_i = linspace(0, 1, [`L2_GRID_NODES`]).
pub fn l2_grid(a: &Curve, b: &Curve) -> Result<f64, MetricError> {
    let mut sum = 0.0;
    for c in linspace(0.0, 1.0, L2_GRID_NODES) {
        let theta = c.acos();
        let d = a.eval(theta) - b.eval(theta);
        if !d.is_finite() {
            return Err(MetricError::NonFinite { theta });
        }
        sum += d * d;
    }
    Ok(sum.sqrt())
}

/// The pointwise difference behind `max_rel`: |a − b| / max(|a|, |b|), 0 where both are 0.
pub use crate::math::tolerance::relative_difference;

/// The metrics of `ndfplot compare` (CONTRACTS.md).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Comparison {
    /// max |a − b| over θ.
    pub max_abs: f64,
    /// θ of `max_abs`.
    pub max_abs_theta: f64,
    /// max |a − b| / max(|a|, |b|) over θ (0 where both are 0).
    pub max_rel: f64,
    /// θ of `max_rel`.
    pub max_rel_theta: f64,
    /// sqrt(2π ∫ (a − b)² sin θ cos θ dθ).
    pub l2_projected: f64,
    /// ‖a − b‖₂ on the 1000-node c-grid.
    pub l2_grid: f64,
    /// The maximum of a.
    pub a_peak: Extremum,
    /// The maximum of b.
    pub b_peak: Extremum,
}

/// A metric that `--max-error` can bound.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Metric {
    /// `max_abs`.
    MaxAbs,
    /// `max_rel`.
    MaxRel,
    /// `l2_projected`.
    L2Projected,
    /// `l2_grid`.
    L2Grid,
}

impl Metric {
    /// Every metric, in output order.
    pub const ALL: [Metric; 4] = [
        Metric::MaxAbs,
        Metric::MaxRel,
        Metric::L2Projected,
        Metric::L2Grid,
    ];

    /// The metric's name in output and flags.
    pub fn name(self) -> &'static str {
        match self {
            Metric::MaxAbs => "max_abs",
            Metric::MaxRel => "max_rel",
            Metric::L2Projected => "l2_projected",
            Metric::L2Grid => "l2_grid",
        }
    }

    /// Looks a metric up by name.
    pub fn from_name(name: &str) -> Option<Metric> {
        Metric::ALL.into_iter().find(|m| m.name() == name)
    }

    /// The metric's value in a comparison.
    pub fn of(self, c: &Comparison) -> f64 {
        match self {
            Metric::MaxAbs => c.max_abs,
            Metric::MaxRel => c.max_rel,
            Metric::L2Projected => c.l2_projected,
            Metric::L2Grid => c.l2_grid,
        }
    }
}

/// Every metric of two curves over [0, π/2]. Maxima are located by [`maximum`], with breakpoints at the
/// narrower of the two lobe widths.
pub fn compare(a: &Curve, b: &Curve) -> Result<Comparison, MetricError> {
    let a_peak = peak(a)?;
    let b_peak = peak(b)?;
    let width = lobe_width(a_peak.value).min(lobe_width(b_peak.value));
    let abs = maximum(|t| (a.eval(t) - b.eval(t)).abs(), width)?;
    let rel = maximum(|t| relative_difference(a.eval(t), b.eval(t)), width)?;
    Ok(Comparison {
        max_abs: abs.value,
        max_abs_theta: abs.theta,
        max_rel: rel.value,
        max_rel_theta: rel.theta,
        l2_projected: l2_projected_with(a, b, a_peak.value, b_peak.value)?,
        l2_grid: l2_grid(a, b)?,
        a_peak,
        b_peak,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ndf::Family;

    fn ndf(family: Family, params: &[f64]) -> Curve {
        Curve::Ndf(family.build(params).unwrap())
    }

    #[test]
    fn projected_integral_of_ndfs_is_one() {
        for curve in [
            ndf(Family::Beckmann, &[0.01]),
            ndf(Family::Phong, &[1e6]),
            ndf(Family::TrowbridgeReitz, &[3.0]),
            ndf(Family::Sgd, &[0.1, 1.5]),
        ] {
            let mass = projected_integral(
                |t| curve.eval(t),
                lobe_width(peak(&curve).unwrap().value),
                0.0,
            )
            .unwrap();
            assert!(
                (mass.value - 1.0).abs() <= 1e-10 && mass.error < 1e-10,
                "{curve:?}: {mass:?}"
            );
        }
    }

    #[test]
    fn maximum_is_refined_off_the_grid() {
        // sin(2θ)·e^{θ} peaks where tan 2θ = −2, θ* = (π − atan 2)/2.
        let star = (PI - 2f64.atan()) / 2.0;
        let m = maximum(|t| (2.0 * t).sin() * t.exp(), FRAC_PI_2).unwrap();
        assert!((m.theta - star).abs() < 1e-7, "{m:?}");
        assert_eq!(
            maximum(|t| t.cos(), FRAC_PI_2).unwrap(),
            Extremum {
                theta: 0.0,
                value: 1.0
            }
        );
    }

    #[test]
    fn metrics_of_a_curve_with_itself_are_zero() {
        let a = ndf(Family::Abc, &[23.5, 1.75]);
        let c = compare(&a, &a).unwrap();
        assert_eq!(
            (c.max_abs, c.max_rel, c.l2_projected, c.l2_grid),
            (0.0, 0.0, 0.0, 0.0)
        );
        assert_eq!(
            c.a_peak,
            Extremum {
                theta: 0.0,
                value: a.eval(0.0)
            }
        );
    }

    #[test]
    fn l2_projected_of_uniform_against_phong() {
        // Phong α_p = 1: D = 3 cos θ/(2π); uniform 1/π. 2π ∫ (3c/(2π) − 1/π)² c dc over c ∈ [0, 1]
        // = 2π/π² ∫ (1.5c − 1)² c dc = (2/π)(9/16 − 1 + 1/2) = 1/(8π).
        let (a, b) = (ndf(Family::Phong, &[1.0]), ndf(Family::Phong, &[0.0]));
        let l2 = l2_projected(&a, &b).unwrap();
        assert!((l2 / (1.0 / (8.0 * PI)).sqrt() - 1.0).abs() < 1e-12, "{l2}");
        let c = compare(&a, &b).unwrap();
        assert_eq!((c.max_abs_theta, c.max_rel_theta), (FRAC_PI_2, FRAC_PI_2));
        assert!((c.max_rel - 1.0).abs() < 1e-15);
    }
}
