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

use crate::model::curve::Curve;
use crate::pipeline::layout;
use crate::spec::look::{PanelKind, Scale, XUnit};
use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// Evenly spaced samples before any refinement. 33 points (32 intervals of π/64 ≈ 0.05 rad over
/// [0, π/2]) put a sample within 0.025 rad of any lobe; together with the peak sample, the chord test
/// then sees every lobe of the catalogue, down to GGX α = 0.01 and Beckmann α = 0.001 at θ = 0.
pub const INITIAL_POINTS: usize = 33;
/// Most evaluations one curve may take: far above what 0.25 px needs on a 20 000 px figure
/// (a few hundred per lobe), a guard against curves that never settle (discontinuities).
pub const MAX_EVALUATIONS: usize = 100_000;
/// Most evaluations one curve whose every value is an integral (an albedo) may take: such curves
/// are smooth, drawn with a few dozen points, and the cap bounds a scene's integration work
/// ([`crate::spec::scene::MAX_INTEGRALS`]).
pub const MAX_INTEGRAL_EVALUATIONS: usize = 1000;
/// Deviation at a third of an interval relative to the largest deviation, for a parabola:
/// t(1 − t) at t = 1/3 over its value 1/4 at t = 1/2.
const THIRD_TO_MAX: f64 = 8.0 / 9.0;
/// Intervals narrower than this many pixels are not split: the polyline cannot bend visibly
/// within them, and a jump (a discontinuity) would otherwise take the whole budget.
const MIN_SPLIT_PX: f64 = 1e-3;
/// Relative growth of the automatic y span after refinement that triggers a second refinement
/// (a peak the initial grid missed changes the pixel scale by more than this).
const RESCALE_THRESHOLD: f64 = 0.01;

/// How a panel places (θ, v) in pixels.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Geometry {
    /// x linear in θ (radians or degrees axes), y linear in the displayed value.
    #[default]
    Angle,
    /// x linear in tan θ (slope axes), y linear in the displayed value.
    Slope,
    /// A polar panel: the point at radius r(v) and angle θ from the vertical,
    /// r(v) · (sin θ, cos θ), the radial range filling the plot area's inscribed half-disc.
    Polar,
}

impl Geometry {
    /// The geometry of a panel of `kind` with x axis `x_unit`: polar panels are [`Geometry::Polar`],
    /// slope axes [`Geometry::Slope`], everything else [`Geometry::Angle`].
    pub fn of(kind: &PanelKind, x_unit: XUnit) -> Geometry {
        match (kind, x_unit) {
            (PanelKind::Polar, _) => Geometry::Polar,
            (_, XUnit::Slope) => Geometry::Slope,
            _ => Geometry::Angle,
        }
    }
}

/// The pixel geometry of one panel before its y range is known.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    /// θ interval shown (radians): the x axis, or the polar panel's angles either side of the normal.
    pub theta_range: (f64, f64),
    /// Plot area width in output pixels.
    pub width_px: f64,
    /// Plot area height in output pixels.
    pub height_px: f64,
    /// x scale of a cartesian panel, applied to θ or tan θ (linear on a polar panel).
    pub x_scale: Scale,
    /// y scale of the panel (the radius scale of a polar panel).
    pub y_scale: Scale,
    /// Given y range, `None` = automatic from the data.
    pub y_range: Option<(f64, f64)>,
    /// Tolerance in output pixels.
    pub tolerance_px: f64,
    /// How (θ, v) become pixels.
    pub geometry: Geometry,
}

impl Frame {
    /// The frame of panel cell `(rows, cols)` of a `width_px × height_px` figure with base font
    /// `font_px`, drawn at `scale` output pixels per CSS pixel: the plot area
    /// [`layout::plot_area`] estimates for it.
    #[allow(clippy::too_many_arguments)]
    pub fn of_cell(
        (width_px, height_px): (f64, f64),
        (rows, cols): (usize, usize),
        font_px: f64,
        titled: bool,
        scale: f64,
        (theta_range, geometry, x_scale): ((f64, f64), Geometry, Scale),
        (y_scale, y_range): (Scale, Option<(f64, f64)>),
        tolerance_px: f64,
    ) -> Frame {
        let (width_px, height_px) =
            layout::plot_area((width_px, height_px), (rows, cols), font_px, titled, scale);
        Frame {
            theta_range,
            width_px,
            height_px,
            x_scale,
            y_scale,
            y_range,
            tolerance_px,
            geometry,
        }
    }

    /// The pixel map once the panel's data `extent` is known (ignored for a given range). The
    /// displayed range is the plot writer's: [`Scale::range`], or [`Scale::radial_range`] for a
    /// polar panel, whose radius range fills the largest half-disc of the plot area that shows
    /// the θ range either side of the normal.
    pub fn map(&self, extent: Option<Extent>) -> PixelMap {
        let data = extent.and_then(|e| e.display(self.y_scale));
        let (y_lo, y_hi) = match self.geometry {
            Geometry::Polar => self.y_scale.radial_range(self.y_range, data),
            Geometry::Angle | Geometry::Slope => self.y_scale.range(self.y_range, data),
        };
        let (a, b) = self.theta_range;
        let cartesian = |tan: bool| {
            let axis = Axis {
                tan,
                log: self.x_scale == Scale::Log,
            };
            let (lo, hi) = (axis.x(a), axis.x(b));
            XMap::Cartesian {
                axis,
                lo,
                px_per: self.width_px / (hi - lo).max(f64::MIN_POSITIVE),
            }
        };
        let (x, y_px) = match self.geometry {
            Geometry::Angle => (cartesian(false), self.height_px),
            Geometry::Slope => (cartesian(true), self.height_px),
            Geometry::Polar => {
                let half_width = b.clamp(0.0, std::f64::consts::FRAC_PI_2).sin();
                let radius =
                    (self.width_px / 2.0 / half_width.max(f64::MIN_POSITIVE)).min(self.height_px);
                (XMap::Polar, radius)
            }
        };
        PixelMap {
            x,
            y_lo,
            y_hi,
            px_per_y: y_px / (y_hi - y_lo),
            log: self.y_scale == Scale::Log,
        }
    }
}

/// The displayed x of a cartesian panel as a function of θ: θ or tan θ, then log₁₀ on a log axis.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Axis {
    tan: bool,
    log: bool,
}

impl Axis {
    /// The displayed x of θ (up to the unit's constant factor, which the pixel scale absorbs).
    fn x(self, theta: f64) -> f64 {
        let x = if self.tan { theta.tan() } else { theta };
        if self.log { x.log10() } else { x }
    }

    /// The θ of a displayed x: the inverse of [`Axis::x`].
    fn theta(self, x: f64) -> f64 {
        let x = if self.log { 10f64.powf(x) } else { x };
        if self.tan { x.atan() } else { x }
    }
}

/// How θ becomes a pixel coordinate.
#[derive(Debug, Clone, Copy, PartialEq)]
enum XMap {
    /// x = (axis.x(θ) − lo) · px_per.
    Cartesian { axis: Axis, lo: f64, px_per: f64 },
    /// The y pixel distance is a radius, turned by θ from the vertical.
    Polar,
}

/// The data-to-pixel transform of a panel: (θ, v) → pixels, the value clamped to the visible
/// range since the plot clips there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PixelMap {
    x: XMap,
    y_lo: f64,
    y_hi: f64,
    px_per_y: f64,
    log: bool,
}

impl PixelMap {
    /// (x, y) in pixels of the point (θ, v); a non-finite v stays non-finite.
    pub fn px(&self, theta: f64, v: f64) -> (f64, f64) {
        let y_px = self.y_px(v);
        match self.x {
            XMap::Cartesian { axis, lo, px_per } => ((axis.x(theta) - lo) * px_per, y_px),
            XMap::Polar => {
                let (sin, cos) = theta.sin_cos();
                (y_px * sin, y_px * cos)
            }
        }
    }

    /// The value's pixel distance from the bottom of the y axis (from the centre of a polar
    /// panel), clamped to the visible range.
    fn y_px(&self, v: f64) -> f64 {
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
        (y - self.y_lo) * self.px_per_y
    }

    /// How far in pixels the drawn point `p` lies from the chord `a`–`b`. On a polar panel, the
    /// larger of that and the same distance in the unrolled plane (θ at the rim's scale, radius):
    /// a lobe much narrower than its interval folds onto the normal in the disc, where probes
    /// at the interval's thirds see almost nothing, but not in the unrolled plane, whose
    /// distances bound the disc's (the disc scales θ by the radius, at most the rim's).
    fn deviation(&self, a: (f64, f64), p: (f64, f64), b: (f64, f64)) -> f64 {
        let drawn = distance_to_segment(self.px(p.0, p.1), self.px(a.0, a.1), self.px(b.0, b.1));
        match self.x {
            XMap::Polar => {
                let rim = (self.y_hi - self.y_lo) * self.px_per_y;
                let unrolled = |(theta, v): (f64, f64)| (rim * theta, self.y_px(v));
                drawn.max(distance_to_segment(unrolled(p), unrolled(a), unrolled(b)))
            }
            XMap::Cartesian { .. } => drawn,
        }
    }

    /// How far apart in pixels θ = `a` and θ = `b` can be drawn whatever their values: their
    /// x distance, or on a polar panel the arc between them at the rim.
    fn reach_px(&self, a: f64, b: f64) -> f64 {
        match self.x {
            XMap::Cartesian { axis, px_per, .. } => (axis.x(b) - axis.x(a)).abs() * px_per,
            XMap::Polar => (b - a).abs() * (self.y_hi - self.y_lo) * self.px_per_y,
        }
    }

    /// The θ at a third and two thirds of the way from `a` to `b` along the x axis (in the
    /// displayed x of a cartesian panel: tan θ on a slope axis, log₁₀ on a log axis; in θ on a
    /// polar panel), where [`THIRD_TO_MAX`] holds.
    fn thirds(&self, a: f64, b: f64) -> [f64; 2] {
        match self.x {
            XMap::Cartesian { axis, .. } => {
                let (xa, xb) = (axis.x(a), axis.x(b));
                [(2.0 * xa + xb) / 3.0, (xa + 2.0 * xb) / 3.0].map(|x| axis.theta(x))
            }
            XMap::Polar => [(2.0 * a + b) / 3.0, (a + 2.0 * b) / 3.0],
        }
    }
}

/// Distance in pixels from `p` to the segment `a`–`b` (to `a` when the segment is a point).
pub fn distance_to_segment(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
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
    let mut thetas = crate::model::grid::linspace(a, b, INITIAL_POINTS);
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
        let thirds = map.thirds(a.0, b.0);
        let ordered = a.0 < thirds[0] && thirds[0] < thirds[1] && thirds[1] < b.0;
        if map.reach_px(a.0, b.0) < MIN_SPLIT_PX || !ordered || *spent + 2 > budget {
            return None;
        }
        *spent += 2;
        let probes = thirds.map(|t| (t, f(t)));
        let deviation = probes
            .iter()
            .map(|&p| map.deviation(a, p, b))
            .fold(0.0, f64::max);
        // Where the curve stops being finite, the edge is found by bisection; an interval
        // finite nowhere is not drawn, so it needs no more points.
        let finite = [a, probes[0], probes[1], b].map(|p| p.1.is_finite());
        let deviation = if !finite.contains(&true) {
            0.0
        } else if finite.contains(&false) {
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

/// The values of a panel's polylines as far as its automatic y range needs them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Extent {
    /// Least finite value.
    pub min: f64,
    /// Greatest finite value.
    pub max: f64,
    /// Least positive finite value, the low end of what a log scale shows.
    pub min_positive: Option<f64>,
}

impl Extent {
    /// The extent in display units of `scale` ([`Scale::display`]): (min, max) on a linear
    /// scale, the logarithms of the least positive value and the maximum on a log scale;
    /// `None` when no value can be displayed.
    pub fn display(&self, scale: Scale) -> Option<(f64, f64)> {
        match scale {
            Scale::Linear => Some((self.min, self.max)),
            Scale::Log => Some((scale.display(self.min_positive?)?, scale.display(self.max)?)),
        }
    }
}

/// The extent of the finite values of several polylines; `None` when there is none.
pub fn extent<'a>(polylines: impl IntoIterator<Item = &'a [(f64, f64)]>) -> Option<Extent> {
    polylines
        .into_iter()
        .flatten()
        .map(|p| p.1)
        .filter(|v| v.is_finite())
        .fold(None, |acc: Option<Extent>, v| {
            let positive = (v > 0.0).then_some(v);
            Some(match acc {
                None => Extent {
                    min: v,
                    max: v,
                    min_positive: positive,
                },
                Some(e) => Extent {
                    min: e.min.min(v),
                    max: e.max.max(v),
                    min_positive: match (e.min_positive, positive) {
                        (Some(a), Some(b)) => Some(a.min(b)),
                        (a, b) => a.or(b),
                    },
                },
            })
        })
}

/// Whether the automatic y span of `after` is smaller than that of `before` by more than
/// [`RESCALE_THRESHOLD`] in pixels per unit, i.e. the refinement must be judged again.
pub fn needs_rescale(before: &PixelMap, after: &PixelMap) -> bool {
    after.px_per_y > before.px_per_y * (1.0 + RESCALE_THRESHOLD)
}

/// The most evaluations `curve`'s adaptive sampling takes: [`MAX_INTEGRAL_EVALUATIONS`] for a
/// curve of integrals, [`MAX_EVALUATIONS`] otherwise.
pub fn budget(curve: &Curve) -> usize {
    if curve.integrals_per_value() > 0 {
        MAX_INTEGRAL_EVALUATIONS
    } else {
        MAX_EVALUATIONS
    }
}

/// Samples `f` over `frame` adaptively: initial points, the panel's pixel map from `panel_extent`
/// (the extent of every curve of the panel, initial points included), then [`refine`].
pub fn sample(
    f: &dyn Fn(f64) -> f64,
    frame: &Frame,
    start: Refined,
    panel_extent: Option<Extent>,
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
            x_scale: Scale::Linear,
            y_scale: Scale::Linear,
            y_range,
            tolerance_px: 0.25,
            geometry: Geometry::Angle,
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

    /// Samples `f` adaptively in `frame` and returns the drawn error in pixels under the same
    /// frame's map, and the number of points.
    fn drawn_error(f: &dyn Fn(f64) -> f64, frame: &Frame, hints: &[f64]) -> (f64, usize) {
        let start = initial(f, frame.theta_range, hints);
        let e = extent([start.points.as_slice()]);
        let refined = sample(f, frame, start, e);
        let map = frame.map(extent([refined.points.as_slice()]));
        (
            max_deviation_px(f, &map, &refined.points, 16),
            refined.points.len(),
        )
    }

    #[test]
    fn geometries_follow_the_panel() {
        use crate::spec::look::PanelKind;
        assert_eq!(
            Geometry::of(&PanelKind::Polar, XUnit::Degrees),
            Geometry::Polar
        );
        assert_eq!(
            Geometry::of(&PanelKind::Cartesian, XUnit::Slope),
            Geometry::Slope
        );
        assert_eq!(
            Geometry::of(&PanelKind::Cartesian, XUnit::Radians),
            Geometry::Angle
        );
    }

    #[test]
    fn polar_and_slope_maps_place_points_like_the_plot() {
        let polar = Frame {
            geometry: Geometry::Polar,
            y_range: Some((0.0, 1.0)),
            ..frame(None)
        };
        // The rim's radius is the inscribed half-disc's: min(400 / 2, 250).
        let map = polar.map(None);
        let (x, y) = map.px(0.0, 1.0);
        assert!(x.abs() < 1e-12 && (y - 200.0).abs() < 1e-9);
        let (x, y) = map.px(std::f64::consts::FRAC_PI_2, 0.5);
        assert!((x - 100.0).abs() < 1e-9 && y.abs() < 1e-9);
        let slope = Frame {
            geometry: Geometry::Slope,
            theta_range: (0.0, 3.0f64.atan()),
            ..frame(Some((0.0, 1.0)))
        };
        let (x, _) = slope.map(None).px(1.0f64.atan(), 0.5);
        assert!((x - 400.0 / 3.0).abs() < 1e-9, "x linear in tan θ");
    }

    #[test]
    fn log_x_maps_place_decades_evenly_and_keep_the_tolerance() {
        // θ from 10⁻³ to 1: three decades over 400 px.
        let log_theta = Frame {
            x_scale: Scale::Log,
            theta_range: (1e-3, 1.0),
            ..frame(Some((0.0, 1.0)))
        };
        let map = log_theta.map(None);
        for (theta, x) in [(1e-3, 0.0), (1e-2, 400.0 / 3.0), (1.0, 400.0)] {
            assert!((map.px(theta, 0.5).0 - x).abs() < 1e-9, "θ = {theta}");
        }
        let [a, b] = map.thirds(1e-3, 1.0);
        assert!((a - 1e-2).abs() < 1e-15 && (b - 1e-1).abs() < 1e-14);
        // tan θ from 10⁻² to 10²: x = 100 px per decade.
        let log_slope = Frame {
            geometry: Geometry::Slope,
            x_scale: Scale::Log,
            theta_range: (1e-2f64.atan(), 1e2f64.atan()),
            ..frame(Some((0.0, 1.0)))
        };
        let (x, _) = log_slope.map(None).px(1.0f64.atan(), 0.5);
        assert!((x - 200.0).abs() < 1e-9, "x linear in log₁₀ tan θ");
        // A lobe whose features are spread over decades of θ is drawn within tolerance.
        let lobe = |t: f64| 1.0 / (1.0 + (t / 0.003).powi(2));
        let (error, points) = drawn_error(&lobe, &log_theta, &[]);
        assert!(error <= 0.25 * 1.05, "{error} px, {points} points");
        assert!(points < 2000, "{points} points");
    }

    #[test]
    fn a_narrow_lobe_is_drawn_within_tolerance_in_polar_and_slope_panels() {
        let lobe = |t: f64| (-(t / 0.01).powi(2)).exp();
        for (y_scale, y_range) in [(Scale::Linear, None), (Scale::Log, Some((1e-4, 1.0)))] {
            let polar = Frame {
                geometry: Geometry::Polar,
                y_scale,
                y_range,
                ..frame(None)
            };
            let (error, points) = drawn_error(&lobe, &polar, &[0.0]);
            assert!(
                error <= 0.25 * 1.05,
                "{y_scale:?}: {error} px, {points} points"
            );
            assert!(points < 2000, "{points} points");
        }
        // A lobe narrow in slope space: P₂₂-like exp(−tan²θ / 0.05²) over tan θ ∈ [0, 3].
        let sloped = |t: f64| (-(t.tan() / 0.05).powi(2)).exp();
        let slope = Frame {
            geometry: Geometry::Slope,
            theta_range: (0.0, 3.0f64.atan()),
            ..frame(None)
        };
        let (error, points) = drawn_error(&sloped, &slope, &[0.0]);
        assert!(error <= 0.25 * 1.05, "{error} px, {points} points");
    }

    #[test]
    fn log_extents_skip_values_that_cannot_be_shown() {
        let points = [(0.0, 0.0), (0.5, 1e-3), (1.0, 20.0)];
        let e = extent([points.as_slice()]).unwrap();
        assert_eq!(e.min_positive, Some(1e-3));
        assert_eq!(e.display(Scale::Log), Some((-3.0, 20f64.log10())));
        let log = Frame {
            x_scale: Scale::Linear,
            y_scale: Scale::Log,
            ..frame(None)
        };
        let map = log.map(Some(e));
        assert_eq!((map.y_lo, map.y_hi), (-3.0, 2.0));
        assert!(map.px(0.3, 0.0).1 == 0.0, "zero sits at the bottom");
    }
}
