//! Numbers for people: the one way a number is written in legend labels, tick labels, panel
//! titles and messages. Canonical JSON writes numbers in shortest round-trip form instead
//! (`crate::spec::json`).

/// A number for people: at most 6 significant digits, trailing zeros dropped (`10.499999999999998` → `10.5`).
pub fn pretty(value: f64) -> String {
    if value == 0.0 {
        return "0".into();
    }
    let magnitude = value.abs().log10().floor();
    if !(-4.0..6.0).contains(&magnitude) {
        let text = format!("{value:.5e}");
        let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
        let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
        return format!("{mantissa}e{exponent}");
    }
    let decimals = (5.0 - magnitude).max(0.0) as usize;
    let text = format!("{value:.decimals$}");
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
    }
}
