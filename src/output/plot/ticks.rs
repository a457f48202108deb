//! Tick locators and formatters, in the manner of matplotlib's `MaxNLocator` and `LogLocator`.
//!
//! - Linear: the finest "nice" step (mantissa × 10ⁿ) whose multiples in the range number at most the
//!   room allows (between [`MIN_TICKS`] and [`MAX_LINEAR_TICKS`]); labels with the fewest decimals that
//!   write every tick exactly, one format for the whole axis.
//! - Log (values are base-10 exponents): every decade, or every n-th decade so that the labels fit;
//!   the decades not labelled, or 2…9 × 10ᵏ when every decade is, as minor ticks. When fewer than
//!   [`FEW_DECADES`] decades show, 2 and 5 × 10ᵏ (or all of 2…9 × 10ᵏ, room permitting) are labelled
//!   too, written as plain decimals (`0.5`) inside [`PLAIN_MIN`, `PLAIN_MAX`] and as `5×10⁻⁶` outside.

/// Fewest labelled ticks an axis is given, however little room it has.
pub(super) const MIN_TICKS: usize = 3;
/// Most labelled ticks on a linear axis, however much room it has.
pub(super) const MAX_LINEAR_TICKS: usize = 8;
/// Most labelled ticks on a log axis.
pub(super) const MAX_LOG_TICKS: usize = 12;
/// Below this many decades a log axis also labels values between decades.
pub(super) const FEW_DECADES: f64 = 3.0;
/// At most this many decades get minor ticks at 2…9 × 10ᵏ.
pub(super) const MAX_MINOR_DECADES: f64 = 8.0;
/// Log-axis values in [PLAIN_MIN, PLAIN_MAX] are written as plain decimals when intermediate values
/// are labelled.
pub(super) const PLAIN_MIN: f64 = 1e-4;
/// See [`PLAIN_MIN`].
pub(super) const PLAIN_MAX: f64 = 1e5;
/// Mantissas of "nice" linear steps.
pub(super) const NICE_MANTISSAS: [f64; 5] = [1.0, 2.0, 2.5, 5.0, 10.0];
/// Most unlabelled decade lines on a log axis that labels every n-th decade.
const MAX_DECADE_LINES: usize = 24;
/// Mantissas of the strides between labelled decades (whole numbers of decades).
const DECADE_STRIDES: [f64; 4] = [1.0, 2.0, 5.0, 10.0];
/// Slack in units of the step when deciding whether a multiple lies inside a range.
const EDGE_SLACK: f64 = 1e-9;

/// Denominators d of π/d steps on a radian axis, coarsest first.
const PI_DIVISORS: [u32; 6] = [1, 2, 4, 6, 8, 12];
/// Most labelled ticks of a π-multiple axis: `3π/8` labels are wide, and five reach π/8 steps on
/// the hemisphere.
const MAX_PI_TICKS: usize = 5;

/// Labelled ticks with their labels, and unlabelled minor ticks, in display units.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Ticks {
    /// Labelled tick positions, ascending.
    pub(super) major: Vec<f64>,
    /// One label per major tick.
    pub(super) labels: Vec<String>,
    /// Unlabelled tick positions.
    pub(super) minor: Vec<f64>,
}

/// How many labelled ticks `room` (the number of label-widths that fit along the axis) allows, within
/// [[`MIN_TICKS`], `most`].
pub(super) fn limit(room: f64, most: usize) -> usize {
    (room.floor().max(0.0) as usize).clamp(MIN_TICKS, most)
}

/// The multiples of `step` in `[lo, hi]`.
pub(super) fn multiples(lo: f64, hi: f64, step: f64) -> Vec<f64> {
    let first = (lo / step - EDGE_SLACK).ceil() as i64;
    let last = (hi / step + EDGE_SLACK).floor() as i64;
    (first..=last).map(|i| i as f64 * step).collect()
}

/// The finest step `m × 10ⁿ` (m from `mantissas`) with [`MIN_TICKS`] to `most` multiples in
/// `[lo, hi]`; when no step gives that many, the coarsest with at least [`MIN_TICKS`].
/// A span wider than the largest double (ends of opposite sign near ±f64::MAX) counts as f64::MAX.
pub(super) fn nice_step(lo: f64, hi: f64, most: usize, mantissas: &[f64]) -> f64 {
    let span = hi - lo;
    if span.is_nan() || span <= 0.0 {
        return 1.0;
    }
    let span = span.min(f64::MAX);
    let first = (span / (most as f64 * 10.0)).log10().floor() as i32;
    let steps: Vec<f64> = (first..=first.saturating_add(4))
        .flat_map(|e| mantissas.iter().map(move |&m| m * 10f64.powi(e)))
        .collect();
    let count = |step: f64| multiples(lo, hi, step).len();
    steps
        .iter()
        .copied()
        .find(|&step| (MIN_TICKS..=most).contains(&count(step)))
        .or_else(|| steps.iter().rev().copied().find(|&s| count(s) >= MIN_TICKS))
        .unwrap_or(span)
}

/// The fewest decimals (at most 12) that write every value of `ticks` exactly, to `1e-9` of `step`.
pub(super) fn decimals(ticks: &[f64], step: f64) -> usize {
    (0..12)
        .find(|&d| {
            let scale = 10f64.powi(d as i32);
            ticks
                .iter()
                .all(|t| ((t * scale).round() / scale - t).abs() <= EDGE_SLACK * step)
        })
        .unwrap_or(12)
}

/// `v` with `decimals` decimals and `suffix`, a true minus sign, and no "−0".
pub(super) fn fixed(v: f64, decimals: usize, suffix: &str) -> String {
    let text = format!("{v:.decimals$}");
    let negative_zero = text
        .trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.');
    let text = if negative_zero {
        text.trim_start_matches('-').to_string()
    } else {
        text.replace('-', "−")
    };
    format!("{text}{suffix}")
}

/// Linear ticks over `[lo, hi]`: the finest nice step fitting `room`, labels with one number of
/// decimals and `suffix` (`°`).
pub(super) fn linear(lo: f64, hi: f64, room: f64, mantissas: &[f64], suffix: &str) -> Ticks {
    let step = nice_step(lo, hi, limit(room, MAX_LINEAR_TICKS), mantissas);
    labelled(multiples(lo, hi, step), step, suffix)
}

/// `major` labelled with the fewest decimals that write each exactly (multiples of `step`).
pub(super) fn labelled(major: Vec<f64>, step: f64, suffix: &str) -> Ticks {
    let d = decimals(&major, step);
    let largest = major.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let huge = largest >= SCIENTIFIC_FROM || (largest > 0.0 && largest < SCIENTIFIC_BELOW);
    // A value within rounding of 0 (a multiple computed as −1e-17) is written 0.
    let labels = major
        .iter()
        .map(|&v| if v.abs() < EDGE_SLACK * step { 0.0 } else { v })
        .map(|v| match huge {
            true => scientific_linear(v, suffix),
            false => fixed(v, d, suffix),
        })
        .collect();
    Ticks {
        major,
        labels,
        minor: Vec::new(),
    }
}

/// Linear ticks from this magnitude on are written `m×10ᵏ` (all of an axis's labels, so they
/// compare at a glance): a plain decimal of 10⁸ has nine digits, of 10³⁰⁸ three hundred.
const SCIENTIFIC_FROM: f64 = 1e7;

/// Linear ticks all below this magnitude are written `m×10ᵏ` too: a plain decimal of 2×10⁻⁷ has
/// six zeros to count.
const SCIENTIFIC_BELOW: f64 = 1e-4;

/// `v` as `m×10ᵏ` with m to at most four significant digits (`1.5×10³⁰⁸`, `10⁸`, `−2×10⁷`, `0`).
fn scientific_linear(v: f64, suffix: &str) -> String {
    if v == 0.0 {
        return format!("0{suffix}");
    }
    let text = format!("{:.3e}", v.abs());
    let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
    let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
    let power = format!("10{}", superscript(exponent.parse().unwrap_or(0)));
    let sign = if v < 0.0 { "−" } else { "" };
    match mantissa {
        "1" => format!("{sign}{power}{suffix}"),
        m => format!("{sign}{m}×{power}{suffix}"),
    }
}

/// Superscript form of an integer exponent (`-3` → `⁻³`).
fn superscript(exponent: i64) -> String {
    const DIGITS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    exponent
        .to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            d => DIGITS[d.to_digit(10).unwrap_or(0) as usize],
        })
        .collect()
}

/// `m × 10ᵏ` for a mantissa m ∈ 1…9 and a decade k: `10ᵏ` when m = 1, else `m×10ᵏ`.
fn scientific(m: u32, k: i64) -> String {
    if m == 1 {
        format!("10{}", superscript(k))
    } else {
        format!("{m}×10{}", superscript(k))
    }
}

/// `m × 10ᵏ` as a plain decimal (`0.05`, `200`).
fn plain(m: u32, k: i64) -> String {
    if k >= 0 {
        format!("{m}{}", "0".repeat(k as usize))
    } else {
        format!("0.{}{m}", "0".repeat((-k - 1) as usize))
    }
}

/// The labels of log ticks at `m × 10ᵏ` on an axis spanning `decades`, all in one format: plain
/// decimals when fewer than [`FEW_DECADES`] show and every value lies within
/// [`PLAIN_MIN`]…[`PLAIN_MAX`], powers of ten otherwise.
fn log_labels(values: &[(u32, i64)], decades: f64) -> Vec<String> {
    let all_plain = values.iter().all(|&(m, k)| {
        let v = f64::from(m) * 10f64.powi(k as i32);
        (PLAIN_MIN..=PLAIN_MAX).contains(&v)
    });
    let plain_labels = decades < FEW_DECADES && all_plain;
    values
        .iter()
        .map(|&(m, k)| {
            if plain_labels {
                plain(m, k)
            } else {
                scientific(m, k)
            }
        })
        .collect()
}

/// Ticks at multiples of π/d over `[lo, hi]` (radians): the finest d of [`PI_DIVISORS`] with at
/// most as many ticks as `room` allows (and [`MAX_PI_TICKS`]), else the coarsest; labelled as
/// reduced fractions of π (`0`, `π/8`, `π/4`, `3π/8`, `π/2`, `π`, `−π/4`).
pub(super) fn pi(lo: f64, hi: f64, room: f64) -> Ticks {
    let most = limit(room, MAX_PI_TICKS);
    let count = |d: u32| multiples(lo, hi, std::f64::consts::PI / f64::from(d)).len();
    let d = PI_DIVISORS
        .iter()
        .rev()
        .copied()
        .find(|&d| count(d) <= most)
        .unwrap_or(PI_DIVISORS[0]);
    let step = std::f64::consts::PI / f64::from(d);
    let major = multiples(lo, hi, step);
    let labels = major
        .iter()
        .map(|&v| pi_fraction((v / step).round() as i64, i64::from(d)))
        .collect();
    Ticks {
        major,
        labels,
        minor: Vec::new(),
    }
}

/// `k`π/`d` written as a reduced fraction: `0`, `π`, `3π`, `π/4`, `3π/8`, `−π/2`.
fn pi_fraction(k: i64, d: i64) -> String {
    fn gcd(a: i64, b: i64) -> i64 {
        if b == 0 { a } else { gcd(b, a % b) }
    }
    if k == 0 {
        return "0".to_owned();
    }
    let g = gcd(k.abs(), d);
    let (n, d) = (k.abs() / g, d / g);
    let sign = if k < 0 { "−" } else { "" };
    let numerator = if n == 1 {
        "π".to_owned()
    } else {
        format!("{n}π")
    };
    if d == 1 {
        format!("{sign}{numerator}")
    } else {
        format!("{sign}{numerator}/{d}")
    }
}

/// Labels for ticks a spec placed at `values` (> 0) on a log axis: in the format of [`log`]'s own
/// labels for the decades the values span when every value is m × 10ᵏ with m ∈ 1…9 (to 1e-9),
/// else each value in its shortest form.
pub(super) fn given_log_labels(values: &[f64]) -> Vec<String> {
    let decade_form = |v: f64| {
        let k = v.log10().floor();
        let m = v / 10f64.powf(k);
        let whole = m.round();
        ((m - whole).abs() < 1e-9 && (1.0..=9.0).contains(&whole))
            .then_some((whole as u32, k as i64))
    };
    match values
        .iter()
        .map(|&v| decade_form(v))
        .collect::<Option<Vec<_>>>()
    {
        Some(forms) => {
            let decade = |pick: fn(i64, i64) -> i64| forms.iter().map(|f| f.1).reduce(pick);
            let span = decade(i64::max)
                .zip(decade(i64::min))
                .map_or(0, |(hi, lo)| hi - lo);
            log_labels(&forms, span as f64)
        }
        None => values
            .iter()
            .map(|&v| crate::spec::numbers::pretty(v))
            .collect(),
    }
}

/// Log ticks over exponents `[lo, hi]` (display units of a log axis).
pub(super) fn log(lo: f64, hi: f64, room: f64) -> Ticks {
    let most = limit(room, MAX_LOG_TICKS);
    let decades = hi - lo;
    let stride = nice_step(lo, hi, most, &DECADE_STRIDES).max(1.0);
    let between = |mantissas: &[u32]| -> Vec<(u32, i64)> {
        (lo.floor() as i64..=hi.ceil() as i64)
            .flat_map(|k| mantissas.iter().map(move |&m| (m, k)))
            .filter(|&(m, k)| {
                let v = k as f64 + f64::from(m).log10();
                v >= lo - EDGE_SLACK && v <= hi + EDGE_SLACK
            })
            .collect()
    };
    let at = |(m, k): (u32, i64)| k as f64 + f64::from(m).log10();
    // Fewer than FEW_DECADES decades: label 1, 2, 5 × 10ᵏ, or every 1…9 × 10ᵏ where they fit.
    let labelled_values: Vec<(u32, i64)> = if decades < FEW_DECADES {
        [&[1, 2, 3, 4, 5, 6, 7, 8, 9][..], &[1, 2, 5], &[1, 3], &[1]]
            .into_iter()
            .map(between)
            .find(|v| v.len() <= most && v.len() >= 2)
            .unwrap_or_else(|| between(&[1]))
    } else {
        multiples(lo, hi, stride)
            .into_iter()
            .map(|v| (1, v.round() as i64))
            .collect()
    };
    let labels = log_labels(&labelled_values, decades);
    let major: Vec<f64> = labelled_values.iter().map(|&p| at(p)).collect();
    let minor = if stride > 1.0 && decades >= FEW_DECADES {
        // Every decade, or every n-th where that many lines would grey the plot over.
        let step = nice_step(0.0, decades, MAX_DECADE_LINES, &DECADE_STRIDES)
            .max(1.0)
            .min(stride);
        multiples(lo, hi, step)
            .into_iter()
            .filter(|v| !major.iter().any(|m| (m - v).abs() < EDGE_SLACK))
            .collect()
    } else if decades <= MAX_MINOR_DECADES {
        between(&[1, 2, 3, 4, 5, 6, 7, 8, 9])
            .into_iter()
            .map(at)
            .filter(|v| !major.iter().any(|m| (m - v).abs() < EDGE_SLACK))
            .collect()
    } else {
        Vec::new()
    };
    Ticks {
        major,
        labels,
        minor,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    #[test]
    fn a_range_as_wide_as_the_doubles_gets_a_few_finite_ticks() {
        // A relative difference whose divisor nearly vanishes spans ±1e308: the span overflows.
        let t = linear(-1e308, 1e308, 400.0, &[1.0, 2.0, 5.0], "");
        assert!(
            (MIN_TICKS..=MAX_LINEAR_TICKS).contains(&t.major.len())
                && t.major.iter().all(|v| v.is_finite()),
            "{:?}",
            t.major
        );
        assert_eq!(nice_step(1.0, 1.0, 5, &[1.0]), 1.0, "an empty span");
        assert!(
            t.labels.iter().all(|l| l.chars().count() <= 12),
            "{:?}",
            t.labels
        );
        assert_eq!(
            [1.5e308, 1e8, -2e7, 0.0].map(|v| scientific_linear(v, "")),
            ["1.5×10³⁰⁸", "10⁸", "−2×10⁷", "0"]
        );
    }

    #[test]
    fn many_decades_get_a_bounded_number_of_unlabelled_lines() {
        // 300 decades (a Beckmann tail): labels every 100, lines every 20, not 300 of them.
        let t = log(-300.0, 0.0, 6.0);
        assert_eq!(t.major, [-300.0, -200.0, -100.0, 0.0]);
        assert!(
            (5..=MAX_DECADE_LINES).contains(&t.minor.len()),
            "{:?}",
            t.minor
        );
        assert!(t.minor.contains(&-20.0) && !t.minor.contains(&-1.0));
        // A few decades labelled every other one keep a line at each decade.
        let t = log(-8.0, 2.0, 6.0);
        assert!(t.minor.contains(&-7.0));
    }

    #[test]
    fn pi_ticks_are_reduced_fractions_of_pi_at_the_finest_step_that_fits() {
        let half = std::f64::consts::FRAC_PI_2;
        let hemisphere = pi(0.0, half, 10.0);
        assert_eq!(hemisphere.labels, ["0", "π/8", "π/4", "3π/8", "π/2"]);
        assert!((hemisphere.major[4] - half).abs() < 1e-15);
        assert_eq!(pi(0.0, half, 3.0).labels, ["0", "π/4", "π/2"]);
        assert_eq!(pi(-half, half, 3.0).labels, ["−π/2", "0", "π/2"]);
        assert_eq!(
            pi(0.0, 2.0 * std::f64::consts::PI, 5.0).labels,
            ["0", "π/2", "π", "3π/2", "2π"]
        );
        assert_eq!(pi_fraction(6, 4), "3π/2");
        assert_eq!(pi_fraction(4, 2), "2π");
    }

    #[test]
    fn linear_axes_get_four_to_eight_nice_ticks_in_one_format() {
        let t = linear(0.0, FRAC_PI_2, 10.0, &NICE_MANTISSAS, "");
        assert_eq!(
            t.labels,
            ["0.0", "0.2", "0.4", "0.6", "0.8", "1.0", "1.2", "1.4"]
        );
        let t = linear(0.0, 100.0, 5.0, &NICE_MANTISSAS, "");
        assert_eq!(t.labels, ["0", "25", "50", "75", "100"]);
        let t = linear(0.45, 1.0, 8.0, &NICE_MANTISSAS, "");
        assert_eq!(t.labels, ["0.5", "0.6", "0.7", "0.8", "0.9", "1.0"]);
        let t = linear(-1.1, 1.1, 6.0, &NICE_MANTISSAS, "");
        assert_eq!(t.labels, ["−1.0", "−0.5", "0.0", "0.5", "1.0"]);
        // Little room still gives three labelled ticks; much room at most eight.
        assert!(linear(0.0, 10.0, 1.0, &NICE_MANTISSAS, "").major.len() >= MIN_TICKS);
        for hi in [0.3, 1.0, 7.0, 13.0, 1e-5, 3e7] {
            for room in [2.0, 4.0, 6.0, 8.0, 20.0] {
                let n = linear(0.0, hi, room, &NICE_MANTISSAS, "").major.len();
                assert!(
                    (MIN_TICKS..=MAX_LINEAR_TICKS).contains(&n),
                    "{hi} {room}: {n}"
                );
            }
        }
    }

    #[test]
    fn decimals_are_the_fewest_that_write_each_tick_exactly() {
        assert_eq!(decimals(&[0.0, 25.0, 50.0], 25.0), 0);
        assert_eq!(decimals(&[0.0, 0.25, 0.5], 0.25), 2);
        assert_eq!(decimals(&[0.0, 0.5, 1.0], 0.5), 1);
        assert_eq!(fixed(-0.0, 1, ""), "0.0");
        assert_eq!(fixed(-2.5, 1, "°"), "−2.5°");
    }

    #[test]
    fn log_axes_label_decades_or_every_nth_with_minor_ticks_between() {
        let t = log(-4.0, 2.0, 8.0);
        assert_eq!(
            t.labels,
            ["10⁻⁴", "10⁻³", "10⁻²", "10⁻¹", "10⁰", "10¹", "10²"]
        );
        assert_eq!(t.minor.len(), 6 * 8);
        let t = log(-4.0, 2.0, 4.0);
        assert_eq!(t.labels, ["10⁻⁴", "10⁻²", "10⁰", "10²"]);
        assert_eq!(t.minor, [-3.0, -1.0, 1.0]);
        let t = log(-300.0, 0.0, 6.0);
        assert!(
            t.major.len() >= MIN_TICKS && t.major.len() <= 6,
            "{:?}",
            t.labels
        );
    }

    #[test]
    fn log_axes_over_few_decades_label_values_between_them() {
        let t = log(0.5f64.log10(), 0.0, 10.0);
        assert_eq!(t.labels, ["0.5", "0.6", "0.7", "0.8", "0.9", "1"]);
        let t = log(-2.0, 0.0, 8.0);
        assert_eq!(t.labels, ["0.01", "0.02", "0.05", "0.1", "0.2", "0.5", "1"]);
        let t = log(-2.0, 0.0, 6.0);
        assert_eq!(t.labels, ["0.01", "0.03", "0.1", "0.3", "1"]);
        let t = log(-7.0, -5.0, 8.0);
        assert_eq!(
            t.labels,
            [
                "10⁻⁷",
                "2×10⁻⁷",
                "5×10⁻⁷",
                "10⁻⁶",
                "2×10⁻⁶",
                "5×10⁻⁶",
                "10⁻⁵"
            ]
        );
        for (lo, hi) in [(-0.1, 0.0), (-1.0, 1.0), (-2.9, 0.0)] {
            assert!(log(lo, hi, 6.0).major.len() >= 2, "{lo} {hi}");
        }
    }
}
