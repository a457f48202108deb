//! Layout: where a figure's parts go — the default canvas, each panel's estimated plot area,
//! title bands, font sizes, and the displayed y range of an axis ("PlotRange → All").
//!
//! The one place that states these rules: the spec reads the default canvas from here, the
//! adaptive sampler asks it for a panel's plot area, and the exporters read the ranges and font
//! sizes from it. The plot area the sampler is given is an estimate taken on the small side of
//! what the drawing measures with real text metrics: a larger plot area would only make the
//! sampling tolerance stricter. It computes geometry only; it evaluates and draws nothing.

use crate::spec::look::Scale;

/// Approximate horizontal space of a panel cell that is not plot area (y tick labels, y label,
/// margins), in base font sizes; the drawing measures it exactly, so it is taken on the small
/// side: a wider plot area than the real one only makes the sampling tolerance stricter.
const NON_PLOT_WIDTH_EM: f64 = 4.0;
/// Approximate vertical space of a panel cell that is not plot area (panel title, x tick labels,
/// x label, margins), in base font sizes; small for the same reason.
const NON_PLOT_HEIGHT_EM: f64 = 4.0;
/// Height of the figure title band in base font sizes: the title ([`crate::spec::look::FIGURE_TITLE_EM`]) plus
/// spacing.
const FIGURE_TITLE_BAND_EM: f64 = 2.0;

/// The estimated plot area (width, height) in output pixels of one panel cell of a
/// `width_px × height_px` figure with `rows × cols` cells and base font `font_px`, drawn at
/// `scale` output pixels per CSS pixel: the cell minus the non-plot margins (and the figure
/// title band when `titled`), at least one pixel each way.
pub fn plot_area(
    (width_px, height_px): (f64, f64),
    (rows, cols): (usize, usize),
    font_px: f64,
    titled: bool,
    scale: f64,
) -> (f64, f64) {
    let title = if titled {
        FIGURE_TITLE_BAND_EM * font_px
    } else {
        0.0
    };
    let cell_w = width_px / cols.max(1) as f64;
    let cell_h = (height_px - title) / rows.max(1) as f64;
    (
        ((cell_w - NON_PLOT_WIDTH_EM * font_px) * scale).max(1.0),
        ((cell_h - NON_PLOT_HEIGHT_EM * font_px) * scale).max(1.0),
    )
}

/// Fraction of the data span added above an automatic linear range, and below it when the
/// data go negative (a range of non-negative data starts at 0).
pub const AUTO_MARGIN: f64 = 0.05;
/// Most decades an automatic log radius of a polar panel spans below the decade of the
/// maximum: deeper tails would squeeze the lobe into a ring near the rim.
pub const POLAR_DECADES: f64 = 4.0;

impl Scale {
    /// `v` in display units: `v` on a linear scale, log₁₀ `v` on a log scale; `None` when it
    /// cannot be drawn (not finite, or ≤ 0 on a log scale).
    pub fn display(self, v: f64) -> Option<f64> {
        match self {
            Scale::Linear => v.is_finite().then_some(v),
            Scale::Log => (v > 0.0 && v.is_finite()).then(|| v.log10()),
        }
    }

    /// The displayed range in display units ("PlotRange → All"): `given` (data units, either
    /// order; ignored unless both ends can be displayed), else from the data `extent` (display
    /// units, `None` for no data). Linear: from 0 when the data are ≥ 0, else [`AUTO_MARGIN`] of
    /// the span below the minimum, to [`AUTO_MARGIN`] of the span above the maximum; (0, 1)
    /// without data. Log: the decade at or below the minimum to the decade at or above the
    /// maximum, at least one decade; (0, 1) without data. An empty range (a flat curve) is
    /// opened around its value: ±1 at 0, else ±half its magnitude. The ends stay finite.
    pub fn range(self, given: Option<(f64, f64)>, extent: Option<(f64, f64)>) -> (f64, f64) {
        match (self, self.shown(given)) {
            (_, Some((lo, hi))) => widen_if_flat(lo, hi),
            (Scale::Linear, None) => {
                let Some((lo, hi)) = extent else {
                    return (0.0, 1.0);
                };
                let lo = lo.min(0.0);
                // Halved before subtracting: data near ±f64::MAX (a relative difference whose
                // divisor nearly vanished) must not give an infinite span or end.
                let margin = AUTO_MARGIN * 2.0 * (hi / 2.0 - lo / 2.0);
                let lo = if lo == 0.0 {
                    0.0
                } else {
                    (lo - margin).max(f64::MIN)
                };
                widen_if_flat(lo, (hi + margin).min(f64::MAX))
            }
            (Scale::Log, None) => match extent {
                Some((lo, hi)) => {
                    let (lo, hi) = (lo.floor(), hi.ceil());
                    (lo, hi.max(lo + 1.0))
                }
                None => (0.0, 1.0),
            },
        }
    }

    /// The radial range of a polar panel in display units: the centre's value to the rim's.
    /// As [`Scale::range`], except that an automatic log range starts at most
    /// [`POLAR_DECADES`] below the decade of the maximum (values below it sit at the centre).
    pub fn radial_range(self, given: Option<(f64, f64)>, extent: Option<(f64, f64)>) -> (f64, f64) {
        let (lo, hi) = self.range(given, extent);
        match (self, self.shown(given), extent) {
            (Scale::Log, None, Some((_, max))) => (lo.max(max.floor() - POLAR_DECADES), hi),
            _ => (lo, hi),
        }
    }

    /// A given range in display units, low end first, if both ends can be displayed.
    fn shown(self, given: Option<(f64, f64)>) -> Option<(f64, f64)> {
        let (a, b) = given?;
        let (a, b) = (self.display(a)?, self.display(b)?);
        Some((a.min(b), a.max(b)))
    }
}

/// `(lo, hi)`, or when it is empty (a flat curve, a single point) a range around its value:
/// ±1 at 0, else ±half its magnitude.
pub fn widen_if_flat(lo: f64, hi: f64) -> (f64, f64) {
    if hi - lo > 1e-12 * lo.abs().max(hi.abs()) && hi - lo > f64::MIN_POSITIVE {
        return (lo, hi);
    }
    let pad = if lo == 0.0 { 1.0 } else { lo.abs() * 0.5 };
    (lo - pad, hi + pad)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn automatic_ranges_follow_the_plot_range_rule() {
        let (lo, hi) = Scale::Linear.range(None, Some((1.0, 3.0)));
        assert!(
            lo == 0.0 && (hi - 3.15).abs() < 1e-12,
            "margin of the span from 0"
        );
        let (lo, hi) = Scale::Linear.range(None, Some((-1.0, 1.0)));
        assert!((lo + 1.1).abs() < 1e-12 && (hi - 1.1).abs() < 1e-12);
        assert_eq!(Scale::Linear.range(None, Some((0.0, 0.0))), (-1.0, 1.0));
        assert_eq!(Scale::Linear.range(Some((2.0, 1.0)), None), (1.0, 2.0));
        assert_eq!(Scale::Log.range(None, Some((-2.7, 1.2))), (-3.0, 2.0));
        assert_eq!(Scale::Log.range(None, Some((1.0, 1.0))), (1.0, 2.0));
        assert_eq!(
            Scale::Log.range(Some((0.0, 10.0)), None),
            (0.0, 1.0),
            "0 has no log"
        );
        assert_eq!(Scale::Log.range(Some((1e-3, 10.0)), None), (-3.0, 1.0));
        // Data near the largest doubles keep finite ends (no margin beyond them).
        assert_eq!(
            Scale::Linear.range(None, Some((-1.7e308, 1.7e308))),
            (f64::MIN, f64::MAX)
        );
    }

    #[test]
    fn polar_log_radii_reach_at_most_four_decades_below_the_peak() {
        assert_eq!(
            Scale::Log.radial_range(None, Some((-9.0, 1.2))),
            (-3.0, 2.0)
        );
        assert_eq!(
            Scale::Log.radial_range(None, Some((-1.5, 1.2))),
            (-2.0, 2.0)
        );
        assert_eq!(
            Scale::Log.radial_range(Some((1e-6, 10.0)), Some((-9.0, 1.2))),
            (-6.0, 1.0)
        );
        assert_eq!(
            Scale::Linear.radial_range(None, Some((0.0, 2.0))),
            Scale::Linear.range(None, Some((0.0, 2.0)))
        );
    }
}
