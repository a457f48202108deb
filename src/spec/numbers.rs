//! Numbers for people: the one way a number is written in legend labels, tick labels, panel
//! titles and messages. Canonical JSON writes numbers in shortest round-trip form instead
//! (`crate::spec::json`).

/// A number for people: at most 6 significant digits, trailing zeros dropped (`10.499999999999998` → `10.5`).
pub fn pretty(value: f64) -> String {
    significant(value, 6)
}

/// Significant digits of a number ndfplot computed for a legend (a converted or fitted parameter):
/// enough to tell curves apart, few enough to read; exact values are in the CSV.
pub const LEGEND_DIGITS: usize = 3;

/// `value` to at most `digits` (≥ 1) significant digits, trailing zeros dropped; exponent form
/// below 10⁻⁴ and from 10⁶ (`2.5e-7`).
pub fn significant(value: f64, digits: usize) -> String {
    if value == 0.0 {
        return "0".into();
    }
    let digits = digits.max(1);
    // The magnitude after rounding: 9.9996 to 4 digits is 10.00, one decade up.
    let rounded: f64 = format!("{value:.*e}", digits - 1).parse().unwrap_or(value);
    let magnitude = rounded.abs().log10().floor();
    if !(-4.0..6.0).contains(&magnitude) {
        let text = format!("{value:.*e}", digits - 1);
        let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
        let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
        return format!("{mantissa}e{exponent}");
    }
    let decimals = (digits as f64 - 1.0 - magnitude).max(0.0) as usize;
    let text = format!("{rounded:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pretty_numbers() {
        assert_eq!(pretty(10.499999999999998), "10.5");
        assert_eq!(pretty(0.2027), "0.2027");
        assert_eq!(pretty(2048.0), "2048");
        assert_eq!(pretty(70312.0), "70312");
        assert_eq!(pretty(1e-7), "1e-7");
        assert_eq!(pretty(0.0068), "0.0068");
        assert_eq!(significant(20.2222, LEGEND_DIGITS), "20.2");
        assert_eq!(significant(0.00683542, LEGEND_DIGITS), "0.00684");
        assert_eq!(significant(0.469136, LEGEND_DIGITS), "0.469");
        assert_eq!(significant(198.0, LEGEND_DIGITS), "198");
        assert_eq!(significant(70312.0, LEGEND_DIGITS), "70300");
        assert_eq!(significant(9.9996, 4), "10");
        assert_eq!(significant(-2.5e-7, LEGEND_DIGITS), "-2.5e-7");
    }
}
