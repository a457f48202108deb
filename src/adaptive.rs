//! Adaptive sampling of drawn curves: a polyline refined where it bends, judged in output pixels.
//!
//! Owns the data-to-pixel transform estimated for a panel ([`Frame`], [`PixelMap`]), the bisection
//! ([`refine`]) and the error measure of a polyline against its curve ([`max_deviation_px`]). It
//! evaluates only what it is handed as a closure; it must not know about scenes, files or formats.
//!
//! Refinement: start from [`INITIAL_POINTS`] evenly spaced θ (so that a lobe a few grid steps wide
//! cannot fall between samples unseen) plus the θ where the curve is known to peak, then repeatedly
//! take the interval whose probes lie farthest (in pixels, perpendicular to the chord) from the chord
//! and split it, until every interval is within the tolerance or the budget of evaluations is spent.
//! Each interval is probed at its thirds and split into three there (the probes become points): a
//! single midpoint can lie on the chord by symmetry where the curve turns (the flank of a narrow lobe:
//! Phong 2048 between 0 and 0.05 rad), two probes cannot both do so. On a parabola the deviation at
//! a third is 8/9 of the largest, so probes are held to 8/9 of the tolerance.

use crate::series::YScale;
use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// Evenly spaced samples before any refinement. 33 points (32 intervals of π/64 ≈ 0.05 rad over
/// [0, π/2]) put a sample within 0.025 rad of any lobe; together with the peak sample, the chord test
/// then sees every lobe of the catalogue, down to GGX α = 0.01 and Beckmann α = 0.001 at θ = 0.
pub const INITIAL_POINTS: usize = 33;
/// Most evaluations one curve may take: far above what 0.25 px needs on a 20 000 px figure
/// (a few hundred per lobe), a guard against curves that never settle (discontinuities).
pub const MAX_EVALUATIONS: usize = 100_000;
/// Deviation at a third of an interval relative to the largest deviation, for a parabola:
/// t(1 − t) at t = 1/3 over its value 1/4 at t = 1/2.
const THIRD_TO_MAX: f64 = 8.0 / 9.0;
/// Intervals narrower than this many pixels are not split: the polyline cannot bend visibly
/// within them, and a jump (a discontinuity) would otherwise take the whole budget.
const MIN_SPLIT_PX: f64 = 1e-3;
/// Approximate horizontal space of a panel cell that is not plot area (y tick labels, y label,
/// margins), in base font sizes; plot.rs measures it exactly when drawing, so it is taken on the
/// small side: a wider plot area than the real one only makes the tolerance stricter.
const NON_PLOT_WIDTH_EM: f64 = 4.0;
/// Approximate vertical space of a panel cell that is not plot area (panel title, x tick labels, x
/// label, margins), in base font sizes; small for the same reason.
const NON_PLOT_HEIGHT_EM: f64 = 4.0;
/// Height of the figure title band in base font sizes (title size 1.4 plus spacing).
const FIGURE_TITLE_EM: f64 = 2.0;
/// Fraction of the data span added to an automatic linear range: the plot writer's rule.
const AUTO_MARGIN: f64 = 0.05;
/// Relative growth of the automatic y span after refinement that triggers a second refinement
/// (a peak the initial grid missed changes the pixel scale by more than this).
const RESCALE_THRESHOLD: f64 = 0.01;

/// The pixel geometry of one panel before its y range is known.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    /// θ interval shown (radians), the x axis.
    pub theta_range: (f64, f64),
    /// Plot area width in output pixels.
    pub width_px: f64,
    /// Plot area height in output pixels.
    pub height_px: f64,
    /// y scale of the panel.
    pub y_scale: YScale,
    /// Given y range, `None` = automatic from the data.
    pub y_range: Option<(f64, f64)>,
    /// Tolerance in output pixels.
    pub tolerance_px: f64,
}

impl Frame {
    /// The frame of panel cell `(rows, cols)` of a `width_px × height_px` figure with base font
    /// `font_px`, drawn at `scale` output pixels per CSS pixel: the cell minus [`NON_PLOT_WIDTH_EM`]
    /// and [`NON_PLOT_HEIGHT_EM`] (and the title band when `titled`), at least one pixel.
    #[allow(clippy::too_many_arguments)]
    pub fn of_cell(
        (width_px, height_px): (f64, f64),
        (rows, cols): (usize, usize),
        font_px: f64,
        titled: bool,
        scale: f64,
        theta_range: (f64, f64),
        (y_scale, y_range): (YScale, Option<(f64, f64)>),
        tolerance_px: f64,
    ) -> Frame {
        let title = if titled {
            FIGURE_TITLE_EM * font_px
        } else {
            0.0
        };
        let cell_w = width_px / cols.max(1) as f64;
        let cell_h = (height_px - title) / rows.max(1) as f64;
        Frame {
            theta_range,
            width_px: ((cell_w - NON_PLOT_WIDTH_EM * font_px) * scale).max(1.0),
            height_px: ((cell_h - NON_PLOT_HEIGHT_EM * font_px) * scale).max(1.0),
            y_scale,
            y_range,
            tolerance_px,
        }
    }

    /// The pixel map once the panel's data extent `(lo, hi)` is known (ignored for a given range).
    /// The automatic range follows the plot writer: linear from 0 (or 5% below a negative minimum) to
    /// 5% above the maximum; log from the decade below the minimum to the decade above the maximum.
    pub fn map(&self, extent: Option<(f64, f64)>) -> PixelMap {
        let display = |v: f64| match self.y_scale {
            YScale::Linear => v,
            YScale::Log => v.log10(),
        };
        let (lo, hi) = match (self.y_range, extent) {
            (Some((a, b)), _) => (display(a.min(b)), display(a.max(b))),
            (None, None) => (0.0, 1.0),
            (None, Some((lo, hi))) => match self.y_scale {
                YScale::Linear => {
                    let lo = if lo >= 0.0 {
                        0.0
                    } else {
                        lo - AUTO_MARGIN * (hi - lo)
                    };
                    (lo, hi + AUTO_MARGIN * (hi - lo))
                }
                YScale::Log => {
                    let (lo, hi) = (display(lo).floor(), display(hi).ceil());
                    (lo, hi.max(lo + 1.0))
                }
            },
        };
        let span = if hi - lo > f64::MIN_POSITIVE && (hi - lo) > 1e-12 * lo.abs().max(hi.abs()) {
            hi - lo
        } else {
            lo.abs().max(1.0)
        };
        PixelMap {
            theta_lo: self.theta_range.0,
            px_per_theta: self.width_px
                / (self.theta_range.1 - self.theta_range.0).max(f64::MIN_POSITIVE),
            y_lo: lo,
            y_hi: lo + span,
            px_per_y: self.height_px / span,
            log: self.y_scale == YScale::Log,
        }
    }
}

/// The data-to-pixel transform of a panel: θ → x px, value → y px (clamped to the visible range,
/// since the plot clips there).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PixelMap {
    theta_lo: f64,
    px_per_theta: f64,
    y_lo: f64,
    y_hi: f64,
    px_per_y: f64,
    log: bool,
}

impl PixelMap {
    /// (x, y) in pixels of the point (θ, v); a non-finite v stays non-finite.
    pub fn px(&self, theta: f64, v: f64) -> (f64, f64) {
        let y = if self.log {
            if v > 0.0 {
                v.log10()
            } else if v.is_nan() {
                v
            } else {
                self.y_lo
            }
        } else {
            v
        };
        let y = if y.is_nan() {
            y
        } else {
            y.clamp(self.y_lo, self.y_hi)
        };
        (
            (theta - self.theta_lo) * self.px_per_theta,
            (y - self.y_lo) * self.px_per_y,
        )
    }
}

/// Distance in pixels from `p` to the segment `a`–`b`.
fn distance_to_segment(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let length2 = dx * dx + dy * dy;
    let t = if length2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / length2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
}

/// An interval waiting to be judged: its ends, its evaluated probes at its thirds and how far the
/// farther probe lies from the chord (NaN when a value is not finite: split first, so that the sampler
/// reports it).
struct Candidate {
    deviation: f64,
    a: (f64, f64),
    probes: [(f64, f64); 2],
    b: (f64, f64),
}

impl Candidate {
    fn priority(&self) -> f64 {
        if self.deviation.is_nan() {
            f64::INFINITY
        } else {
            self.deviation
        }
    }
}

impl PartialEq for Candidate {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for Candidate {}
impl PartialOrd for Candidate {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Candidate {
    /// Largest deviation first; ties by θ so that the result never depends on heap internals.
    fn cmp(&self, other: &Self) -> Ordering {
        self.priority()
            .total_cmp(&other.priority())
            .then(other.a.0.total_cmp(&self.a.0))
    }
}

/// A refined polyline and the number of curve evaluations it took.
#[derive(Debug, Clone, PartialEq)]
pub struct Refined {
    /// (θ, value) with θ increasing.
    pub points: Vec<(f64, f64)>,
    /// Evaluations of the curve, including the initial points.
    pub evaluations: usize,
}

/// The initial samples of `f` over `theta_range`: [`INITIAL_POINTS`] evenly spaced θ plus the
/// `hints` inside the range (θ where the curve peaks), sorted.
pub fn initial(f: &dyn Fn(f64) -> f64, theta_range: (f64, f64), hints: &[f64]) -> Refined {
    let (a, b) = theta_range;
    let mut thetas = crate::grid::linspace(a, b, INITIAL_POINTS);
    thetas.extend(hints.iter().copied().filter(|t| (a..=b).contains(t)));
    thetas.sort_by(f64::total_cmp);
    thetas.dedup();
    let points: Vec<(f64, f64)> = thetas.into_iter().map(|t| (t, f(t))).collect();
    Refined {
        evaluations: points.len(),
        points,
    }
}

/// Refines `start` (sorted by θ) until the probes of every interval are within
/// [`THIRD_TO_MAX`] × `tolerance_px` of its chord under `map`, or `budget` more evaluations are
/// spent. Every returned point is (θ, f(θ)).
pub fn refine(
    f: &dyn Fn(f64) -> f64,
    map: &PixelMap,
    tolerance_px: f64,
    budget: usize,
    start: Refined,
) -> Refined {
    let mut spent = 0;
    let mut points = start.points;
    let judge = |a: (f64, f64), b: (f64, f64), spent: &mut usize| -> Option<Candidate> {
        let (pa, pb) = (map.px(a.0, a.1), map.px(b.0, b.1));
        let thirds = [(2.0 * a.0 + b.0) / 3.0, (a.0 + 2.0 * b.0) / 3.0];
        let ordered = a.0 < thirds[0] && thirds[0] < thirds[1] && thirds[1] < b.0;
        if (pb.0 - pa.0).abs() < MIN_SPLIT_PX || !ordered || *spent + 2 > budget {
            return None;
        }
        *spent += 2;
        let probes = thirds.map(|t| (t, f(t)));
        let deviation = probes
            .iter()
            .map(|p| distance_to_segment(map.px(p.0, p.1), pa, pb))
            .fold(0.0, f64::max);
        let deviation = if probes.iter().any(|p| !p.1.is_finite()) {
            f64::NAN
        } else {
            deviation
        };
        Some(Candidate {
            deviation,
            a,
            probes,
            b,
        })
    };
    let mut heap: BinaryHeap<Candidate> = points
        .windows(2)
        .filter_map(|w| judge(w[0], w[1], &mut spent))
        .collect();
    while let Some(worst) = heap.pop() {
        if worst.deviation <= THIRD_TO_MAX * tolerance_px {
            break;
        }
        let [p1, p2] = worst.probes;
        points.extend([p1, p2]);
        for (a, b) in [(worst.a, p1), (p1, p2), (p2, worst.b)] {
            heap.extend(judge(a, b, &mut spent));
        }
    }
    points.sort_by(|p, q| p.0.total_cmp(&q.0));
    Refined {
        points,
        evaluations: start.evaluations + spent,
    }
}

/// The y extent (min, max of finite values) of several polylines; `None` when there is none.
pub fn extent<'a>(polylines: impl IntoIterator<Item = &'a [(f64, f64)]>) -> Option<(f64, f64)> {
    polylines
        .into_iter()
        .flatten()
        .map(|p| p.1)
        .filter(|v| v.is_finite())
        .fold(None, |acc, v| match acc {
            None => Some((v, v)),
            Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
        })
}

/// Whether the automatic y span of `after` is smaller than that of `before` by more than
/// [`RESCALE_THRESHOLD`] in pixels per unit, i.e. the refinement must be judged again.
pub fn needs_rescale(before: &PixelMap, after: &PixelMap) -> bool {
    after.px_per_y > before.px_per_y * (1.0 + RESCALE_THRESHOLD)
}

/// Samples `f` over `frame` adaptively: initial points, the panel's pixel map from `panel_extent`
/// (the extent of every curve of the panel, initial points included), then [`refine`].
pub fn sample(
    f: &dyn Fn(f64) -> f64,
    frame: &Frame,
    start: Refined,
    panel_extent: Option<(f64, f64)>,
) -> Refined {
    let map = frame.map(panel_extent);
    refine(f, &map, frame.tolerance_px, MAX_EVALUATIONS, start)
}

/// The largest distance, in pixels, between the polyline `points` and the true curve `f`, probed at
/// `probes` evenly spaced interior θ of every segment (and at the points themselves, which lie on the
/// curve by construction of every sampler here).
pub fn max_deviation_px(
    f: &dyn Fn(f64) -> f64,
    map: &PixelMap,
    points: &[(f64, f64)],
    probes: usize,
) -> f64 {
    points
        .windows(2)
        .map(|w| {
            let (pa, pb) = (map.px(w[0].0, w[0].1), map.px(w[1].0, w[1].1));
            (1..=probes)
                .map(|k| {
                    let theta = w[0].0 + (w[1].0 - w[0].0) * k as f64 / (probes + 1) as f64;
                    distance_to_segment(map.px(theta, f(theta)), pa, pb)
                })
                .fold(0.0, f64::max)
        })
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame(y_range: Option<(f64, f64)>) -> Frame {
        Frame {
            theta_range: (0.0, std::f64::consts::FRAC_PI_2),
            width_px: 400.0,
            height_px: 250.0,
            y_scale: YScale::Linear,
            y_range,
            tolerance_px: 0.25,
        }
    }

    #[test]
    fn a_straight_line_keeps_its_initial_points() {
        let f = |t: f64| 2.0 * t + 1.0;
        let start = initial(&f, (0.0, 1.0), &[]);
        let refined = sample(
            &f,
            &frame(None),
            start.clone(),
            extent([start.points.as_slice()]),
        );
        assert_eq!(refined.points.len(), INITIAL_POINTS);
    }

    #[test]
    fn a_narrow_gaussian_is_drawn_within_tolerance() {
        let f = |t: f64| (-(t / 0.01).powi(2)).exp();
        let start = initial(&f, (0.0, std::f64::consts::FRAC_PI_2), &[0.0]);
        let fr = frame(None);
        let e = extent([start.points.as_slice()]);
        let refined = sample(&f, &fr, start, e);
        let error = max_deviation_px(&f, &fr.map(e), &refined.points, 16);
        assert!(
            error <= 0.25 * 1.05,
            "error {error} px with {} points",
            refined.points.len()
        );
        assert!(
            refined.points.len() < 200,
            "{} points",
            refined.points.len()
        );
    }

    #[test]
    fn the_budget_bounds_the_evaluations() {
        let f = |t: f64| (1.0 / (t + 1e-9)).sin();
        let start = initial(&f, (0.0, 1.0), &[]);
        let refined = refine(&f, &frame(Some((-1.0, 1.0))).map(None), 1e-3, 500, start);
        assert_eq!(refined.evaluations, INITIAL_POINTS + 500);
    }
}
