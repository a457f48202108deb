//! Axes in display units: automatic ranges ("PlotRange → All"), nice tick steps (degrees,
//! decimals, decades), tick labels, and the plotters coordinate that maps display values to
//! pixels.

use std::f64::consts::FRAC_PI_2;
use std::ops::Range;

use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint};
use plotters::prelude::*;

use crate::pipeline::figure::{Panel, Series};

use crate::spec::look::{Axes, Mark, Scale, TickChoice, XUnit};

use crate::pipeline::layout::{AUTO_MARGIN, widen_if_flat};

use super::ticks::{self, Ticks};

/// Degree steps that read naturally on an angle axis, finest first.
pub(super) const DEGREE_STEPS: [f64; 8] = [1.0, 2.0, 5.0, 15.0, 30.0, 45.0, 90.0, 180.0];
/// Mantissas of steps on an axis of whole numbers (indices): no 2.5.
pub(super) const WHOLE_MANTISSAS: [f64; 4] = [1.0, 2.0, 5.0, 10.0];

/// One axis in display units (degrees or radians on x; values or log₁₀ values on y).
#[derive(Clone)]
pub(super) struct Axis {
    pub(super) lo: f64,
    pub(super) hi: f64,
    /// Labelled ticks with bold grid lines.
    pub(super) ticks: Vec<f64>,
    /// The label of each of `ticks`.
    pub(super) labels: Vec<String>,
    /// Unlabelled light grid lines (log axes: 2…9 × 10ᵏ or the decades not labelled).
    pub(super) minor: Vec<f64>,
}

impl Axis {
    /// The x axis of `panel`, with at most about `max_ticks` ticks.
    ///
    /// An automatic θ range is the data's (a slope axis shows tan θ ∈ [0, 4]); an automatic plain range adds a margin (at least
    /// half a bar spacing when bars are drawn). Plain axes whose x values are all whole
    /// numbers (indices) tick at whole numbers.
    pub(super) fn x(panel: &Panel, max_ticks: f64) -> Axis {
        let axes = &panel.axes;
        let unit = axes.x_unit;
        let data = || {
            panel
                .series
                .iter()
                .flat_map(|s| s.points.iter())
                .filter_map(move |&(theta, _)| x_display(theta, axes))
        };
        let automatic = || match extent(data()) {
            None => default_x(unit),
            Some((lo, hi)) if unit == XUnit::Plain => {
                let half_bar = panel
                    .series
                    .iter()
                    .filter(|s| s.style.mark == Mark::Bars)
                    .filter_map(|s| median_spacing(s, axes))
                    .fold(0.0, f64::max)
                    / 2.0;
                let pad = (AUTO_MARGIN * (hi - lo)).max(half_bar);
                (lo - pad, hi + pad)
            }
            Some(range) => range,
        };
        let given = panel
            .axes
            .x_range
            .and_then(|(a, b)| Some((x_display(a, axes)?, x_display(b, axes)?)));
        let (lo, hi) = match given {
            Some((a, b)) => (a.min(b), a.max(b)),
            // tan θ is unbounded: the data's extent would reach 10¹⁶ at θ = π/2.
            None if unit == XUnit::Slope => default_x(unit),
            None => automatic(),
        };
        let (lo, hi) = widen_if_flat(lo, hi);
        let suffix = if unit == XUnit::Degrees { "°" } else { "" };
        if let Some(choice) = &panel.axes.x_ticks {
            let ticks = chosen(choice, axes.x_scale, (lo, hi), max_ticks, suffix);
            return Axis::from_ticks(lo, hi, ticks);
        }
        if axes.x_scale == Scale::Log {
            return Axis::from_ticks(lo, hi, ticks::log(lo, hi, max_ticks));
        }
        let whole = unit == XUnit::Plain && data().all(|v| v.fract() == 0.0);
        let ticks = match unit {
            XUnit::Degrees => {
                let most = ticks::limit(max_ticks, ticks::MAX_LINEAR_TICKS);
                let step = DEGREE_STEPS
                    .into_iter()
                    .find(|&step| {
                        (ticks::MIN_TICKS..=most).contains(&ticks::multiples(lo, hi, step).len())
                    })
                    .unwrap_or_else(|| ticks::nice_step(lo, hi, most, &ticks::NICE_MANTISSAS));
                ticks::labelled(ticks::multiples(lo, hi, step), step, "°")
            }
            XUnit::Plain if whole => {
                let most = ticks::limit(max_ticks, ticks::MAX_LINEAR_TICKS);
                let step = ticks::nice_step(lo, hi, most, &WHOLE_MANTISSAS).max(1.0);
                ticks::labelled(ticks::multiples(lo, hi, step), step, "")
            }
            // The hemisphere in radians ends at π/2: it is ticked in fractions of π, so that its
            // end is labelled.
            XUnit::Radians if lo.abs() < 1e-12 && (hi - FRAC_PI_2).abs() < 1e-12 => {
                ticks::pi(lo, hi, max_ticks)
            }
            XUnit::Radians | XUnit::Plain | XUnit::Slope => {
                ticks::linear(lo, hi, max_ticks, &ticks::NICE_MANTISSAS, "")
            }
        };
        Axis::from_ticks(lo, hi, ticks)
    }

    /// The axis over `[lo, hi]` with `ticks`.
    fn from_ticks(lo: f64, hi: f64, ticks: Ticks) -> Axis {
        Axis {
            lo,
            hi,
            ticks: ticks.major,
            labels: ticks.labels,
            minor: ticks.minor,
        }
    }

    /// The value axis of `panel`, with at most about `max_ticks` ticks, over
    /// [`Scale::range`]. An automatic linear range includes 0 when bars are drawn.
    pub(super) fn y(panel: &Panel, max_ticks: f64) -> Axis {
        let bars = panel.series.iter().any(|s| s.style.mark == Mark::Bars);
        let base = (bars && panel.axes.y_scale == Scale::Linear).then_some(0.0);
        let data = extent(values(panel).chain(base));
        let range = panel.axes.y_scale.range(panel.axes.y_range, data);
        match &panel.axes.y_ticks {
            Some(choice) => Axis::from_ticks(
                range.0,
                range.1,
                chosen(choice, panel.axes.y_scale, range, max_ticks, ""),
            ),
            None => Axis::values(panel.axes.y_scale, range, max_ticks),
        }
    }

    /// The radius axis of a polar panel, with at most about `max_ticks` ticks, over
    /// [`Scale::radial_range`]: the centre is its low end, the rim its high end.
    pub(super) fn radius(panel: &Panel, max_ticks: f64) -> Axis {
        let range = panel
            .axes
            .y_scale
            .radial_range(panel.axes.y_range, extent(values(panel)));
        Axis::values(panel.axes.y_scale, range, max_ticks)
    }

    /// An axis of values on `scale` over `(lo, hi)` (display units): [`ticks::linear`] or
    /// [`ticks::log`] ticks.
    fn values(scale: Scale, (lo, hi): (f64, f64), max_ticks: f64) -> Axis {
        let ticks = match scale {
            Scale::Linear => ticks::linear(lo, hi, max_ticks, &ticks::NICE_MANTISSAS, ""),
            Scale::Log => ticks::log(lo, hi, max_ticks),
        };
        Axis::from_ticks(lo, hi, ticks)
    }

    /// The z axis of a surface panel: `given` or the extent of the series' z values, as a
    /// linear [`Scale::range`].
    pub(super) fn z(panel: &Panel, given: Option<(f64, f64)>, max_ticks: f64) -> Axis {
        let data = panel
            .series
            .iter()
            .filter_map(|s| s.z.as_deref())
            .flatten()
            .copied()
            .filter(|v| v.is_finite());
        let range = Scale::Linear.range(given, extent(data));
        Axis::values(Scale::Linear, range, max_ticks)
    }

    /// The colour axis of a heat-map panel: `given` or the extent of the series' finite z values
    /// exactly (colours span the data, no margin), linear.
    pub(super) fn colour(panel: &Panel, given: Option<(f64, f64)>, max_ticks: f64) -> Axis {
        let data = panel
            .series
            .iter()
            .filter_map(|s| s.z.as_deref())
            .flatten()
            .copied()
            .filter(|v| v.is_finite());
        let (lo, hi) = given.or(extent(data)).unwrap_or((0.0, 1.0));
        let (lo, hi) = widen_if_flat(lo.min(hi), lo.max(hi));
        Axis::values(Scale::Linear, (lo, hi), max_ticks)
    }

    /// The label of tick `v` (one of `ticks`); empty for any other value.
    pub(super) fn label(&self, v: f64) -> String {
        self.ticks
            .iter()
            .position(|&t| t == v)
            .map_or_else(String::new, |i| self.labels[i].clone())
    }
}

/// The ticks a spec chose for an axis over `(lo, hi)` (display units) on `scale`: at most `n` nice
/// ticks for a count, the given values inside the range (on a log axis labelled as its own
/// ticks are when they are m × 10ᵏ), or multiples of π/d as `room` allows.
fn chosen(
    choice: &TickChoice,
    scale: Scale,
    (lo, hi): (f64, f64),
    room: f64,
    suffix: &str,
) -> Ticks {
    match (choice, scale) {
        (TickChoice::Pi, _) => ticks::pi(lo, hi, room),
        (TickChoice::Count(n), Scale::Linear) => {
            let step = ticks::nice_step(lo, hi, *n, &ticks::NICE_MANTISSAS);
            ticks::labelled(ticks::multiples(lo, hi, step), step, suffix)
        }
        (TickChoice::Count(n), Scale::Log) => ticks::log(lo, hi, *n as f64),
        (TickChoice::At(values), Scale::Linear) => {
            let inside: Vec<f64> = values
                .iter()
                .copied()
                .filter(|v| (lo..=hi).contains(v))
                .collect();
            let step = inside
                .windows(2)
                .map(|w| w[1] - w[0])
                .fold(hi - lo, f64::min);
            ticks::labelled(inside, step, suffix)
        }
        (TickChoice::At(values), Scale::Log) => {
            let inside: Vec<f64> = values
                .iter()
                .copied()
                .filter(|v| (lo..=hi).contains(&v.log10()))
                .collect();
            Ticks {
                major: inside.iter().map(|v| v.log10()).collect(),
                labels: ticks::given_log_labels(&inside),
                minor: Vec::new(),
            }
        }
    }
}

/// The axis as a plotters coordinate: linear in display units, ticks as bold key points and
/// the minor lines as light ones.
impl Ranged for Axis {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        let t = (value - self.lo) / (self.hi - self.lo);
        limit.0 + (f64::from(limit.1 - limit.0) * t).round() as i32
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.minor.clone()
        } else {
            self.ticks.clone()
        }
    }

    fn range(&self) -> Range<f64> {
        self.lo..self.hi
    }
}

/// θ (radians; the plain value on a plain axis) in the display units of `axes`: in its unit
/// (degrees, tan θ), then log₁₀ on a log axis; `None` when it cannot be drawn.
pub(super) fn x_display(theta: f64, axes: &Axes) -> Option<f64> {
    let x = match axes.x_unit {
        XUnit::Degrees => theta.to_degrees(),
        XUnit::Slope => theta.tan(),
        XUnit::Radians | XUnit::Plain => theta,
    };
    axes.x_scale.display(x)
}

/// The x range shown when a panel has no data: 0 to π/2; a slope axis' range when none is
/// given: tan θ from 0 to 4.
pub(super) fn default_x(unit: XUnit) -> (f64, f64) {
    match unit {
        XUnit::Degrees => (0.0, 90.0),
        XUnit::Radians => (0.0, FRAC_PI_2),
        XUnit::Plain => (0.0, 1.0),
        XUnit::Slope => (0.0, 4.0),
    }
}

/// The values of every series of `panel` in display units, where they can be drawn.
fn values(panel: &Panel) -> impl Iterator<Item = f64> + '_ {
    panel
        .series
        .iter()
        .flat_map(|s| s.points.iter())
        .filter_map(|&(_, v)| panel.axes.y_scale.display(v))
}

/// Minimum and maximum of `values`, `None` when empty.
pub(super) fn extent(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    values.fold(None, |acc, v| match acc {
        None => Some((v, v)),
        Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
    })
}

/// The median gap between the distinct x values of `series` (display units), if it has two.
pub(super) fn median_spacing(series: &Series, axes: &Axes) -> Option<f64> {
    let mut xs: Vec<f64> = series
        .points
        .iter()
        .filter_map(|&(theta, _)| x_display(theta, axes))
        .collect();
    xs.sort_by(f64::total_cmp);
    let mut gaps: Vec<f64> = xs
        .windows(2)
        .map(|w| w[1] - w[0])
        .filter(|&g| g > 0.0)
        .collect();
    gaps.sort_by(f64::total_cmp);
    gaps.get(gaps.len() / 2).copied()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::plot::fixtures::{RED, panel, series};
    use crate::spec::look::Dash;
    use std::f64::consts::PI;

    #[test]
    fn degree_axes_tick_at_angles() {
        let axis = Axis::x(&panel(XUnit::Degrees, Scale::Linear, vec![]), 10.0);
        assert_eq!(axis.ticks, [0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 90.0]);
        assert_eq!(axis.label(45.0), "45°");
        let narrow = Axis::x(&panel(XUnit::Degrees, Scale::Linear, vec![]), 4.0);
        assert_eq!(narrow.ticks, [0.0, 30.0, 60.0, 90.0]);
    }

    #[test]
    fn log_x_axes_tick_at_decades_in_the_axis_unit() {
        let curve = vec![series(
            "s",
            RED,
            1.0,
            Dash::Solid,
            vec![(1e-3, 1.0), (1.0, 0.1)],
        )];
        let mut p = panel(XUnit::Radians, Scale::Linear, curve);
        p.axes.x_scale = Scale::Log;
        p.axes.x_range = Some((1e-3, 1.0));
        let axis = Axis::x(&p, 8.0);
        assert!((axis.lo + 3.0).abs() < 1e-12 && axis.hi.abs() < 1e-12);
        assert_eq!(axis.ticks, [-3.0, -2.0, -1.0, 0.0]);
        assert_eq!(axis.labels, ["10⁻³", "10⁻²", "10⁻¹", "10⁰"]);
        assert_eq!(axis.minor.len(), 3 * 8, "2…9 × 10ᵏ in each decade");
        // θ = 0 cannot be drawn on it.
        assert_eq!(x_display(0.0, &p.axes), None);
        assert_eq!(x_display(0.1, &p.axes), Some(-1.0));
        p.axes.x_unit = XUnit::Degrees;
        assert!((x_display(10f64.to_radians(), &p.axes).unwrap() - 1.0).abs() < 1e-15);
    }

    #[test]
    fn slope_axes_tick_in_tan_theta() {
        let curve = vec![series(
            "s",
            RED,
            1.0,
            Dash::Solid,
            vec![(0.0, 1.0), (1.5, 0.1)],
        )];
        let mut p = panel(XUnit::Slope, Scale::Linear, curve);
        let automatic = Axis::x(&p, 6.0);
        assert_eq!((automatic.lo, automatic.hi), (0.0, 4.0));
        assert_eq!(automatic.ticks, [0.0, 1.0, 2.0, 3.0, 4.0]);
        p.axes.x_range = Some((0.0, 3.0f64.atan()));
        let given = Axis::x(&p, 8.0);
        assert!(given.lo == 0.0 && (given.hi - 3.0).abs() < 1e-12);
        assert_eq!(given.ticks, [0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0]);
        assert_eq!(given.label(1.5), "1.5");
    }

    #[test]
    fn automatic_ranges_show_every_point() {
        let values = |v: &[f64]| {
            let points = v
                .iter()
                .enumerate()
                .map(|(i, &y)| (i as f64 * 0.1, y))
                .collect();
            vec![series("s", RED, 1.0, Dash::Solid, points)]
        };
        let linear = |v: &[f64]| Axis::y(&panel(XUnit::Radians, Scale::Linear, values(v)), 8.0);
        let positive = linear(&[1.0, 3.0, 2.0]);
        assert_eq!(positive.lo, 0.0);
        assert!((positive.hi - 3.0 * (1.0 + AUTO_MARGIN)).abs() < 1e-12);
        let signed = linear(&[-1.0, 1.0]);
        assert!((signed.lo + 1.1).abs() < 1e-12 && (signed.hi - 1.1).abs() < 1e-12);
        let flat = linear(&[1.0 / PI, 1.0 / PI]);
        assert!(flat.lo == 0.0 && flat.hi > 1.0 / PI);
        let zero = linear(&[0.0, 0.0]);
        assert!(zero.lo < 0.0 && zero.hi > 0.0);

        // Zeros (an underflowed curve) and non-finite values (a ratio whose divisor underflowed)
        // are left out: the range is the finite positive values', decades 10⁻³ to 10².
        let log = Axis::y(
            &panel(
                XUnit::Radians,
                Scale::Log,
                values(&[0.0, 2e-3, 40.0, f64::INFINITY, f64::NAN, 0.0]),
            ),
            8.0,
        );
        assert_eq!((log.lo, log.hi), (-3.0, 2.0));
        assert_eq!(log.ticks, [-3.0, -2.0, -1.0, 0.0, 1.0, 2.0]);
        assert_eq!(log.label(-3.0), "10⁻³");
        assert_eq!(log.minor.len(), 5 * 8);
    }
}
