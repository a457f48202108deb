//! Value grids with exact end points: numpy's `linspace` and Mathematica's `Range`, as
//! docs/contracts.md fixes them.

use std::fmt;

/// Relative slack on (b − a)/s when counting `Range` values, so that floating drift in
/// `(1.0 − 0.4)/0.1 = 5.999999999999999` never drops the end value (docs/contracts.md).
pub const RANGE_COUNT_SLACK: f64 = 1e-9;

/// Largest number of decimals for which `Range` values are rounded to the literals' precision;
/// beyond it a double cannot carry the decimals anyway (docs/contracts.md).
pub const RANGE_MAX_DECIMALS: usize = 15;

/// Why a grid could not be built.
#[derive(Debug, Clone, PartialEq)]
pub enum GridError {
    /// A bound or step is NaN or infinite.
    NotFinite,
    /// `Range` step 0.
    ZeroStep,
    /// `Range` step points away from the stop value.
    WrongSign,
    /// More values than the cap allows.
    TooMany {
        /// Values the grid would have.
        count: f64,
        /// The cap.
        cap: usize,
    },
}

impl fmt::Display for GridError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GridError::NotFinite => write!(f, "start, stop and step must be finite numbers"),
            GridError::ZeroStep => write!(f, "step must not be 0"),
            GridError::WrongSign => write!(f, "step points away from stop, which gives no values"),
            GridError::TooMany { count, cap } => {
                write!(f, "{count:.0} values exceed the cap of {cap}")
            }
        }
    }
}

/// numpy's `linspace(start, stop, count)`: θ_i = start + i·(stop − start)/(count − 1) for
/// i < count − 1 and the last value exactly `stop`; `count = 1` gives `[start]`.
pub fn linspace(start: f64, stop: f64, count: usize) -> Vec<f64> {
    (0..count)
        .map(|i| linspace_at(start, stop, count, i))
        .collect()
}

/// The `i`-th of [`linspace`]`(start, stop, count)` (`i` < `count`) without the others:
/// start + i·step with step = (stop − start)/(count − 1), the last exactly `stop`, the only one of
/// a count of 1 `start`.
pub fn linspace_at(start: f64, stop: f64, count: usize, i: usize) -> f64 {
    if count == 1 {
        start
    } else if i + 1 == count {
        stop
    } else {
        start + i as f64 * ((stop - start) / (count - 1) as f64)
    }
}

/// Mathematica's `Range[start, stop, step]`, made exact (docs/contracts.md):
/// n = floor((stop − start)/step + 1e-9) + 1 values v_k = start + k·step, each rounded to
/// `decimals` places when given (≤ 15), and the last value exactly `stop` when (stop − start)/step
/// is within 1e-9 of an integer. At most `cap` values.
pub fn range(
    start: f64,
    stop: f64,
    step: f64,
    decimals: Option<usize>,
    cap: usize,
) -> Result<Vec<f64>, GridError> {
    if !(start.is_finite() && stop.is_finite() && step.is_finite()) {
        return Err(GridError::NotFinite);
    }
    if step == 0.0 {
        return Err(GridError::ZeroStep);
    }
    let steps = (stop - start) / step;
    if steps < -RANGE_COUNT_SLACK {
        return Err(GridError::WrongSign);
    }
    let count = (steps + RANGE_COUNT_SLACK).floor() + 1.0;
    if count.is_nan() || count > cap as f64 {
        return Err(GridError::TooMany { count, cap });
    }
    let count = count as usize;
    let ends_on_stop = (steps - steps.round()).abs() <= RANGE_COUNT_SLACK;
    let round = |v: f64| match decimals {
        Some(d) if d <= RANGE_MAX_DECIMALS => format!("{v:.d$}").parse().unwrap_or(v),
        _ => v,
    };
    let mut values: Vec<f64> = (0..count).map(|k| round(start + k as f64 * step)).collect();
    if ends_on_stop {
        values[count - 1] = stop;
    }
    Ok(values)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linspace_matches_numpy() {
        assert_eq!(linspace(0.0, 1.0, 5), [0.0, 0.25, 0.5, 0.75, 1.0]);
        assert_eq!(linspace(2.0, 3.0, 1), [2.0]);
        let theta = linspace(0.0, std::f64::consts::FRAC_PI_2, 7);
        assert_eq!(theta[6], std::f64::consts::FRAC_PI_2);
        // numpy.linspace(0, 1, 1000)[1] == 0.001001001001001001
        assert_eq!(linspace(0.0, 1.0, 1000)[1], 0.001001001001001001);
    }

    #[test]
    fn range_keeps_end_value_and_rounds_to_literal_decimals() {
        assert_eq!(
            range(0.4, 1.0, 0.1, Some(1), 100).unwrap(),
            [0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0]
        );
        assert_eq!(
            range(0.0, 1.0, 0.3, Some(1), 100).unwrap(),
            [0.0, 0.3, 0.6, 0.9]
        );
        assert_eq!(
            range(1.0, 7.0, 1.0, Some(0), 100).unwrap(),
            [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]
        );
        assert_eq!(
            range(0.2, 0.5, 0.1, Some(1), 100).unwrap(),
            [0.2, 0.3, 0.4, 0.5]
        );
        assert_eq!(
            range(1.0, 0.0, -0.25, Some(2), 100).unwrap(),
            [1.0, 0.75, 0.5, 0.25, 0.0]
        );
        // Without rounding (exponent literals) the drift stays, but the end value is exact.
        let raw = range(0.4, 1.0, 1e-1, None, 100).unwrap();
        assert_eq!((raw.len(), raw[2], raw[6]), (7, 0.6000000000000001, 1.0));
        assert_eq!(range(0.5, 0.5, 1.0, Some(1), 10).unwrap(), [0.5]);
    }

    #[test]
    fn range_rejects_bad_steps_and_huge_counts() {
        assert_eq!(range(0.0, 1.0, 0.0, None, 10), Err(GridError::ZeroStep));
        assert_eq!(range(0.0, 1.0, -0.1, None, 10), Err(GridError::WrongSign));
        assert!(matches!(
            range(0.0, 1e9, 1e-9, None, 10_000),
            Err(GridError::TooMany { .. })
        ));
        assert_eq!(
            range(0.0, f64::NAN, 1.0, None, 10),
            Err(GridError::NotFinite)
        );
    }
}
