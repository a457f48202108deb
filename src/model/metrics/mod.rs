//! How far apart two curves are over θ ∈ [0, π/2] or a part of it ([`ThetaRange`]): the metrics of
//! `ndfplot compare` (docs/contracts.md),
//! and the building blocks they share with fitting and the normalization audit — the projected-area
//! integral by piecewise adaptive quadrature, and maxima located by a dense scan refined by golden-section
//! search.
//!
//! Pure f64 code over [`Curve`]s and closures: no I/O, no formatting of reports.

use crate::model::curve::Curve;
use crate::model::grid::linspace;
use crate::model::math::quad::{QuadError, integrate};
use crate::model::math::tolerance::{QUAD_REL_TOL, QUAD_REL_TOL_EMULATED};
use std::f64::consts::{FRAC_PI_2, PI};
use std::fmt;

pub mod sampled;
pub mod table;

/// Nodes of the c-grid of `l2_grid`: c_i = numpy linspace(0, 1, 1000), θ_i = arccos c_i — the Fresnel
/// notebook's grid (docs/maths.md, "The Belcour–Bati–Barla basis").
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

/// Shift of the l2_projected integrand on a quadrature piece, as a fraction of the larger of |a| and |b|
/// seen at the piece's ends and middle, m: (a − b)² carries an absolute rounding error of ~2|a − b|·ε·m,
/// which no relative tolerance beats once |a − b| ≪ m. Integrating (a − b)² + (1e-3 m)² on the piece keeps
/// that error below `QUAD_REL_TOL` of the integrand (its worst case, |a − b| = 1e-3 m, gives 2.2e-13), and
/// leaves l2_projected exact to ~1e-9 of the curves' size where its mass lies, even for nearly equal
/// curves. The shift is local because a lobe of width w holds its mass on an area ~w²: one shift for the
/// whole hemisphere, sized by the peak, would swamp the integral of any lobe narrower than ~1e-9.
const L2_SHIFT: f64 = 1e-3;

/// Both curves must exceed this for `max_log_ratio` to count a θ (docs/contracts.md): ln of anything above it
/// is finite (ln 1e-300 ≈ −690.8), while values below it are the underflowing tails of lobes whose ratio
/// says nothing about the shapes compared.
pub const LOG_RATIO_FLOOR: f64 = 1e-300;

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
    /// A sampled series has no sample inside the θ range.
    OutsideRange,
    /// No θ of the range qualifies for a maximum (every node undefined).
    Undefined,
}

impl fmt::Display for MetricError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MetricError::NonFinite { theta } => write!(f, "not finite at theta = {theta:?}"),
            MetricError::Quad(e) => write!(f, "{e}"),
            MetricError::Disjoint => write!(f, "the two series share no θ"),
            MetricError::OutsideRange => write!(f, "the series has no sample inside the θ range"),
            MetricError::Undefined => write!(f, "no θ of the range qualifies"),
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

/// A θ interval [lo, hi] with 0 ≤ lo < hi ≤ π/2, in radians: where the metrics are taken.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThetaRange {
    lo: f64,
    hi: f64,
}

impl ThetaRange {
    /// The whole hemisphere, [0, π/2].
    pub const FULL: ThetaRange = ThetaRange {
        lo: 0.0,
        hi: FRAC_PI_2,
    };

    /// [lo, hi], or `None` unless 0 ≤ lo < hi ≤ π/2.
    pub fn new(lo: f64, hi: f64) -> Option<ThetaRange> {
        (0.0 <= lo && lo < hi && hi <= FRAC_PI_2).then_some(ThetaRange { lo, hi })
    }

    /// The lower end.
    pub fn lo(self) -> f64 {
        self.lo
    }

    /// The upper end.
    pub fn hi(self) -> f64 {
        self.hi
    }

    /// Whether lo ≤ θ ≤ hi.
    pub fn contains(self, theta: f64) -> bool {
        (self.lo..=self.hi).contains(&theta)
    }
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

/// Breakpoints of `range`: its ends, and those inside it of the breakpoints of [0, π/2] — geometric steps
/// from `width`/64 up to π/2, and towards π/2 down to [`GRAZING_BREAK_MIN`] — sorted.
fn breakpoints(width: f64, range: ThetaRange) -> Vec<f64> {
    let mut breaks = vec![range.lo, range.hi];
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
    breaks.retain(|&t| range.contains(t));
    breaks.sort_by(f64::total_cmp);
    breaks.dedup();
    breaks
}

/// 2π ∫₀^{π/2} f(θ) sin θ cos θ dθ (the projected-area integral of docs/maths.md) by adaptive Gauss–Kronrod
/// quadrature over pieces broken geometrically around `width` (see [`lobe_width`]) and towards grazing,
/// each to relative accuracy `QUAD_REL_TOL`.
///
/// `shift` ≥ 0 is added to f on every piece and its exact integral (π · shift over [0, π/2]) subtracted
/// again: it turns the relative tolerance into an absolute one of ~`QUAD_REL_TOL` · π · shift where f is
/// small against it (0 for a purely relative accuracy). [`projected_integral_over`] takes a shift per
/// piece.
///
/// Pieces next to π/2 may hold ~1e-30 of the total, sampled by θ only a few ulps apart, where relative
/// convergence is out of reach: such a piece is accepted when the errors of all unconverged pieces together
/// stay within `QUAD_REL_TOL` of the whole integral.
pub fn projected_integral(
    f: impl Fn(f64) -> f64,
    width: f64,
    shift: f64,
) -> Result<Estimate, MetricError> {
    projected_integral_over(f, ThetaRange::FULL, width, |_, _| shift, QUAD_REL_TOL)
}

/// [`projected_integral`] over `range` only, to relative accuracy `tol`: 2π ∫ f(θ) sin θ cos θ dθ from lo
/// to hi, the pieces those of [0, π/2] cut at lo and hi; the shift on a piece [a, b] is `shift(a, b)`.
pub fn projected_integral_over(
    f: impl Fn(f64) -> f64,
    range: ThetaRange,
    width: f64,
    shift: impl Fn(f64, f64) -> f64,
    tol: f64,
) -> Result<Estimate, MetricError> {
    let (mut total, mut converged_error, mut loose_error) = (0.0, 0.0, 0.0);
    for piece in breakpoints(width, range).windows(2) {
        let (a, b) = (piece[0], piece[1]);
        let shift = shift(a, b);
        let integrand = |theta: f64| (f(theta) + shift) * theta.sin() * theta.cos();
        let shifted = shift * projected_area(a, b);
        match integrate(integrand, a, b, tol) {
            Ok(v) => {
                total += v - shifted;
                converged_error += tol * v.abs();
            }
            Err(QuadError::NotConverged { estimate, error }) => {
                total += estimate - shifted;
                loose_error += error;
            }
            Err(e) => return Err(e.into()),
        }
    }
    if loose_error > tol * total.abs() {
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

/// ∫ₐᵇ sin θ cos θ dθ = (sin²b − sin²a)/2, as sin(b − a) sin(b + a)/2: without the cancellation of
/// the difference of squares, which loses every digit of a piece a few ulps wide next to π/2. Past
/// π/4, sin(b + a) = sin((π/2 − a) + (π/2 − b)) with π/2 − θ exact (Sterbenz, plus the low part of
/// π/2), as b + a rounded next to π would leave it only the digits of its distance from π.
fn projected_area(a: f64, b: f64) -> f64 {
    /// π/2 − `FRAC_PI_2`: the part of π/2 a double cannot hold.
    const FRAC_PI_2_LOW: f64 = 6.123_233_995_736_766e-17;
    let from_grazing = |t: f64| (FRAC_PI_2 - t) + FRAC_PI_2_LOW;
    let sum_sin = if a + b > FRAC_PI_2 {
        (from_grazing(a) + from_grazing(b)).sin()
    } else {
        (a + b).sin()
    };
    0.5 * (b - a).sin() * sum_sin
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
    maximum_over(f, ThetaRange::FULL, width)
}

/// [`maximum`] over `range` only: the scan's uniform nodes span the range, the breakpoints are those inside it.
pub fn maximum_over(
    f: impl Fn(f64) -> f64,
    range: ThetaRange,
    width: f64,
) -> Result<Extremum, MetricError> {
    maximum_where(|t| Some(f(t)), range, width)?.ok_or(MetricError::Undefined)
}

/// The maximum over `range` of a function defined on part of it: `f` gives `None` where it is undefined.
/// The scan of [`maximum_over`] keeps the nodes where f is defined, and the golden-section refinement
/// around the best of them counts an undefined θ as −∞. `Ok(None)` when f is defined at no node; an error
/// if f is defined but not finite at a visited θ.
pub fn maximum_where(
    f: impl Fn(f64) -> Option<f64>,
    range: ThetaRange,
    width: f64,
) -> Result<Option<Extremum>, MetricError> {
    let finite = |theta: f64| match f(theta) {
        Some(v) if !v.is_finite() => Err(MetricError::NonFinite { theta }),
        Some(v) => Ok(v),
        None => Ok(f64::NEG_INFINITY),
    };
    let mut nodes = linspace(range.lo, range.hi, SCAN_NODES);
    nodes.extend(breakpoints(width, range));
    nodes.sort_by(f64::total_cmp);
    nodes.dedup();
    let values: Vec<f64> = nodes.iter().map(|&t| finite(t)).collect::<Result<_, _>>()?;
    let best = (0..nodes.len()).fold(0, |best, i| if values[i] > values[best] { i } else { best });
    if values[best] == f64::NEG_INFINITY {
        return Ok(None);
    }
    let left = best.saturating_sub(1);
    let right = (best + 1).min(nodes.len() - 1);
    let refined = golden_section_max(
        finite,
        (nodes[left], values[left]),
        (nodes[right], values[right]),
        ARGMAX_TOL,
    )?;
    Ok(Some(if refined.value > values[best] {
        refined
    } else {
        Extremum {
            theta: nodes[best],
            value: values[best],
        }
    }))
}

/// The peak of a curve over [0, π/2] (see [`maximum`]), with the breakpoints placed at the width of a lobe
/// of its value at the normal.
pub fn peak(curve: &Curve) -> Result<Extremum, MetricError> {
    peak_over(curve, ThetaRange::FULL)
}

/// [`peak`] over `range` only.
pub fn peak_over(curve: &Curve, range: ThetaRange) -> Result<Extremum, MetricError> {
    maximum_over(|t| curve.eval(t), range, lobe_width(curve.eval(0.0)))
}

/// `l2_projected` = sqrt(2π ∫₀^{π/2} (a − b)² sin θ cos θ dθ), breakpoints at the narrower of the lobe
/// widths of the two peaks `peak_a`, `peak_b`; exactly 0 for identical curves.
pub fn l2_projected_with(
    a: &Curve,
    b: &Curve,
    peak_a: f64,
    peak_b: f64,
) -> Result<f64, MetricError> {
    l2_projected_over(a, b, ThetaRange::FULL, peak_a, peak_b)
}

/// [`l2_projected_with`] over `range` only: sqrt(2π ∫ (a − b)² sin θ cos θ dθ) from lo to hi, integrated
/// as P² ∫ ((a − b)/P)² with P the larger peak, so that no square overflows (lobes as narrow as the
/// families allow peak near 1e300), under the local shift of [`L2_SHIFT`]. An integral that does not
/// converge errs with its estimate and error as l2 values (`QuadError::NotConverged`).
pub fn l2_projected_over(
    a: &Curve,
    b: &Curve,
    range: ThetaRange,
    peak_a: f64,
    peak_b: f64,
) -> Result<f64, MetricError> {
    if a == b {
        return Ok(0.0);
    }
    let width = lobe_width(peak_a).min(lobe_width(peak_b));
    let scale = match peak_a.abs().max(peak_b.abs()) {
        p if p > 0.0 && p.is_finite() => p,
        _ => 1.0,
    };
    // A first look at each piece, at its ends and middle: the curves' size m there, and Simpson's
    // estimate of the piece's share of the integral, whose sum T₀ sizes the error budget.
    let look = |t: f64| {
        let (va, vb) = (a.eval(t) / scale, b.eval(t) / scale);
        (
            va.abs().max(vb.abs()),
            (va - vb).powi(2) * t.sin() * t.cos(),
        )
    };
    let pieces: Vec<(f64, f64, f64)> = breakpoints(width, range)
        .windows(2)
        .map(|piece| {
            let (lo, hi) = (piece[0], piece[1]);
            let [(m0, f0), (m1, f1), (m2, f2)] = [lo, 0.5 * (lo + hi), hi].map(look);
            (
                lo,
                m0.max(m1).max(m2),
                (hi - lo) * (f0 + 4.0 * f1 + f2) / 6.0,
            )
        })
        .collect();
    let total: f64 = pieces.iter().map(|p| p.2).sum();
    let share = if total.is_finite() {
        total / pieces.len().max(1) as f64
    } else {
        0.0
    };
    // On each piece, the larger of the local shift of [`L2_SHIFT`] and the density that gives the
    // piece an even share of the whole integral's error budget: a piece holding next to nothing of
    // the integral (a tail where the curves' difference is rounding noise) then converges at once
    // instead of chasing a relative accuracy nothing depends on.
    let shift = |lo: f64, hi: f64| {
        let Ok(i) = pieces.binary_search_by(|p| p.0.total_cmp(&lo)) else {
            return 0.0;
        };
        let m = pieces[i].1;
        let local = if m.is_finite() {
            (L2_SHIFT * m).powi(2)
        } else {
            0.0
        };
        let area = projected_area(lo, hi);
        if area > 0.0 {
            local.max(share / area)
        } else {
            local
        }
    };
    // A renderer's curve steps at its float32 (or half) rounding: its square integrates only to
    // the accuracy of its values.
    let tol = if a.emulated() || b.emulated() {
        QUAD_REL_TOL_EMULATED
    } else {
        QUAD_REL_TOL
    };
    let squared = projected_integral_over(
        |t| ((a.eval(t) - b.eval(t)) / scale).powi(2),
        range,
        width,
        shift,
        tol,
    );
    let l2 = |squared: f64| scale * squared.max(0.0).sqrt();
    match squared {
        Ok(squared) => Ok(l2(squared.value)),
        // Unconverged, the estimate and its error in l2's own units: P √I ± P (√(I + e) − √I).
        Err(MetricError::Quad(QuadError::NotConverged { estimate, error })) => {
            Err(MetricError::Quad(QuadError::NotConverged {
                estimate: l2(estimate),
                error: l2(estimate + error) - l2(estimate),
            }))
        }
        Err(e) => Err(e),
    }
}

/// `l2_projected` of two curves (see [`l2_projected_with`]), their peaks taken as their values at the
/// normal.
pub fn l2_projected(a: &Curve, b: &Curve) -> Result<f64, MetricError> {
    l2_projected_with(a, b, a.eval(0.0), b.eval(0.0))
}

/// The nodes of `l2_grid` inside `range`: θ_i = arccos c_i, c_i = linspace(0, 1, [`L2_GRID_NODES`]).
pub fn l2_grid_nodes(range: ThetaRange) -> impl Iterator<Item = f64> {
    linspace(0.0, 1.0, L2_GRID_NODES)
        .into_iter()
        .map(f64::acos)
        .filter(move |&theta| range.contains(theta))
}

/// `l2_grid` = ‖a − b‖₂ over the nodes of [`l2_grid_nodes`] inside `range`.
pub fn l2_grid(a: &Curve, b: &Curve, range: ThetaRange) -> Result<f64, MetricError> {
    let differences = l2_grid_nodes(range)
        .map(|theta| match a.eval(theta) - b.eval(theta) {
            d if d.is_finite() => Ok(d),
            _ => Err(MetricError::NonFinite { theta }),
        })
        .collect::<Result<Vec<f64>, _>>()?;
    Ok(scaled_norm(&differences, |d, _| d * d))
}

/// √(Σᵢ g(dᵢ/s, i)) · s with s = max |dᵢ| (or 1 when every dᵢ is 0): a 2-norm of finite values, or a
/// weighted one when g weighs the squares, whose squares neither overflow (|d| up to the largest double)
/// nor underflow.
pub fn scaled_norm(d: &[f64], g: impl Fn(f64, usize) -> f64) -> f64 {
    let s = match d.iter().fold(0.0f64, |m, v| m.max(v.abs())) {
        0.0 => 1.0,
        s => s,
    };
    let sum: f64 = d.iter().enumerate().map(|(i, v)| g(v / s, i)).sum();
    s * sum.max(0.0).sqrt()
}

/// The pointwise difference behind `max_rel`: |a − b| / max(|a|, |b|), 0 where both are 0.
pub use crate::model::math::tolerance::relative_difference;

/// The pointwise difference behind `max_log_ratio`: |ln a − ln b| = |ln(a/b)| where both a and b exceed
/// [`LOG_RATIO_FLOOR`], `None` elsewhere (taken as a difference of logarithms, so a/b never overflows).
pub fn log_ratio(a: f64, b: f64) -> Option<f64> {
    (a > LOG_RATIO_FLOOR && b > LOG_RATIO_FLOOR).then(|| (a.ln() - b.ln()).abs())
}

/// The metrics of `ndfplot compare` (docs/contracts.md), over one θ range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Comparison {
    /// The θ range the metrics were taken over.
    pub range: ThetaRange,
    /// max |a − b| over θ.
    pub max_abs: f64,
    /// θ of `max_abs`.
    pub max_abs_theta: f64,
    /// max |a − b| / max(|a|, |b|) over θ (0 where both are 0).
    pub max_rel: f64,
    /// θ of `max_rel`.
    pub max_rel_theta: f64,
    /// max |ln(a/b)| over the θ where both exceed [`LOG_RATIO_FLOOR`], with its θ; `None` when there is
    /// no such θ.
    pub max_log_ratio: Option<Extremum>,
    /// sqrt(2π ∫ (a − b)² sin θ cos θ dθ).
    pub l2_projected: f64,
    /// ‖a − b‖₂ on the nodes of the 1000-node c-grid inside the range.
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
    /// `max_log_ratio`.
    MaxLogRatio,
    /// `l2_projected`.
    L2Projected,
    /// `l2_grid`.
    L2Grid,
}

impl Metric {
    /// Every metric, in output order.
    pub const ALL: [Metric; 5] = [
        Metric::MaxAbs,
        Metric::MaxRel,
        Metric::MaxLogRatio,
        Metric::L2Projected,
        Metric::L2Grid,
    ];

    /// The metric's name in output and flags.
    pub fn name(self) -> &'static str {
        match self {
            Metric::MaxAbs => "max_abs",
            Metric::MaxRel => "max_rel",
            Metric::MaxLogRatio => "max_log_ratio",
            Metric::L2Projected => "l2_projected",
            Metric::L2Grid => "l2_grid",
        }
    }

    /// Looks a metric up by name, in any case.
    pub fn from_name(name: &str) -> Option<Metric> {
        Metric::ALL
            .into_iter()
            .find(|m| m.name().eq_ignore_ascii_case(name))
    }

    /// The metric's value in a comparison; `None` for a `max_log_ratio` without a qualifying θ.
    pub fn of(self, c: &Comparison) -> Option<f64> {
        match self {
            Metric::MaxAbs => Some(c.max_abs),
            Metric::MaxRel => Some(c.max_rel),
            Metric::MaxLogRatio => c.max_log_ratio.map(|m| m.value),
            Metric::L2Projected => Some(c.l2_projected),
            Metric::L2Grid => Some(c.l2_grid),
        }
    }
}

/// Every metric of two curves over `range`. Maxima are located by [`maximum_where`], with breakpoints
/// at the narrower of the two lobe widths.
pub fn compare(a: &Curve, b: &Curve, range: ThetaRange) -> Result<Comparison, MetricError> {
    let a_peak = peak_over(a, range)?;
    let b_peak = peak_over(b, range)?;
    let width = lobe_width(a_peak.value).min(lobe_width(b_peak.value));
    let abs = maximum_over(|t| (a.eval(t) - b.eval(t)).abs(), range, width)?;
    let rel = maximum_over(|t| relative_difference(a.eval(t), b.eval(t)), range, width)?;
    let max_log_ratio = maximum_where(|t| log_ratio(a.eval(t), b.eval(t)), range, width)?;
    Ok(Comparison {
        range,
        max_abs: abs.value,
        max_abs_theta: abs.theta,
        max_rel: rel.value,
        max_rel_theta: rel.theta,
        max_log_ratio,
        l2_projected: l2_projected_over(a, b, range, a_peak.value, b_peak.value)?,
        l2_grid: l2_grid(a, b, range)?,
        a_peak,
        b_peak,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ndf::Family;

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
    fn the_projected_area_of_a_piece_next_to_grazing_keeps_its_digits() {
        // (sin²b − sin²a)/2 = (cos²a − cos²b)/2, cos a ≈ 2d and cos b ≈ d apart by a factor of 4 (no
        // cancellation) for a = π/2 − 2d, b = π/2 − d; the difference of sines squared keeps nothing.
        for d in [1e-3, 1e-8, 1e-12, 1e-14] {
            let (a, b) = (FRAC_PI_2 - 2.0 * d, FRAC_PI_2 - d);
            let exact = 0.5 * (a.cos().powi(2) - b.cos().powi(2));
            let area = projected_area(a, b);
            assert!(
                (area / exact - 1.0).abs() < 1e-13,
                "d = {d}: {area} vs {exact}"
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
        let c = compare(&a, &a, ThetaRange::FULL).unwrap();
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
        let c = compare(&a, &b, ThetaRange::FULL).unwrap();
        assert_eq!((c.max_abs_theta, c.max_rel_theta), (FRAC_PI_2, FRAC_PI_2));
        assert!((c.max_rel - 1.0).abs() < 1e-15);
    }

    #[test]
    fn log_ratio_needs_both_sides_above_the_floor() {
        assert_eq!(log_ratio(2.0, 1.0), Some(2f64.ln()));
        assert_eq!(log_ratio(1.0, 2.0), Some(2f64.ln()));
        assert_eq!(
            log_ratio(1e300, 1e-299),
            Some((1e300f64).ln() - (1e-299f64).ln())
        );
        assert_eq!(log_ratio(1.0, LOG_RATIO_FLOOR), None);
        assert_eq!(log_ratio(0.0, 0.0), None);
    }

    #[test]
    fn a_theta_range_limits_every_metric() {
        // Phong α_p = 1 against the uniform 1/π: a/b = 1.5 cos θ and |a − b| = |1.5 c − 1|/π, both
        // largest at θ = 0 on [0, 1]; 2π ∫ (a − b)² sin θ cos θ dθ = (2/π) [F(1) − F(cos 1)] with
        // F(c) = 0.5625 c⁴ − c³ + 0.5 c².
        let (a, b) = (ndf(Family::Phong, &[1.0]), ndf(Family::Phong, &[0.0]));
        let range = ThetaRange::new(0.0, 1.0).unwrap();
        let c = compare(&a, &b, range).unwrap();
        assert_eq!(c.range, range);
        assert_eq!(c.max_abs_theta, 0.0);
        assert!((c.max_abs - 0.5 / PI).abs() < 1e-15, "{c:?}");
        let log = c.max_log_ratio.unwrap();
        assert_eq!(log.theta, 0.0);
        assert!((log.value - 1.5f64.ln()).abs() < 1e-15, "{log:?}");
        let f = |c: f64| 0.5625 * c.powi(4) - c.powi(3) + 0.5 * c * c;
        let exact = ((2.0 / PI) * (f(1.0) - f(1f64.cos()))).sqrt();
        assert!(
            (c.l2_projected / exact - 1.0).abs() < 1e-10,
            "{}",
            c.l2_projected
        );
        // Over the whole hemisphere a → 0 at grazing: the log ratio is largest there, ln(1.5 cos(π/2)).
        let full = compare(&a, &b, ThetaRange::FULL)
            .unwrap()
            .max_log_ratio
            .unwrap();
        assert_eq!(full.theta, FRAC_PI_2);
        assert!(
            (full.value + (1.5 * FRAC_PI_2.cos()).ln()).abs() < 1e-12,
            "{full:?}"
        );
    }

    #[test]
    fn log_ratio_is_undefined_where_a_lobe_has_underflowed() {
        // Beckmann α_b = 0.001 is exp(−tan²θ/α²) ≈ e^{−2.4e6} = 0 beyond θ = 1.
        let (a, b) = (
            ndf(Family::Beckmann, &[0.001]),
            ndf(Family::TrowbridgeReitz, &[0.3]),
        );
        let c = compare(&a, &b, ThetaRange::new(1.0, FRAC_PI_2).unwrap()).unwrap();
        assert_eq!(c.max_log_ratio, None);
        assert_eq!(Metric::MaxLogRatio.of(&c), None);
        assert_eq!(c.max_rel, 1.0);
        assert!(ThetaRange::new(1.0, 1.0).is_none() && ThetaRange::new(-0.1, 1.0).is_none());
    }
}
