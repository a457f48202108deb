//! `ndfplot eval`: a curve's values at given angles, as CSV on standard output (CONTRACTS.md).

use crate::curve::Curve;
use crate::error::{Error, Result};
use crate::grid::linspace;
use crate::output::csv::Table;
use std::f64::consts::FRAC_PI_2;

/// Largest θ count of a `start:stop:count` list (CONTRACTS.md).
pub const MAX_THETA_COUNT: u64 = 10_000_000;

/// A multiple of π written `pi`, `π`, `pi/2`, `3pi/4` or `0.5pi`: k·π/n with k and n positive
/// numbers (1 when absent), computed as (k·π)/n, so `pi/2` is the double nearest π/2. `None` when
/// `s` is not of that form.
pub fn pi_multiple(s: &str) -> Option<f64> {
    let s = s.trim();
    let (before, after) = s.split_once("pi").or_else(|| s.split_once('π'))?;
    let k: f64 = if before.is_empty() {
        1.0
    } else {
        before.trim_end_matches('*').parse().ok()?
    };
    let n: f64 = match after {
        "" => 1.0,
        rest => rest.strip_prefix('/')?.parse().ok()?,
    };
    (k > 0.0 && n > 0.0).then(|| k * std::f64::consts::PI / n)
}

/// Parses a θ list: comma-separated numbers or `start:stop:count` (numpy linspace), in radians
/// (any value may be a multiple of π, [`pi_multiple`]), or in degrees when `degrees`
/// (θ = d·π/180). Every θ must lie in [0, π/2].
pub fn parse_theta_list(text: &str, degrees: bool) -> Result<Vec<f64>> {
    let bad = |what: String| Error::Usage(format!("--theta: {what}"));
    let number = |s: &str| -> Result<f64> {
        if !degrees && let Some(v) = pi_multiple(s) {
            return Ok(v);
        }
        let v: f64 = s
            .trim()
            .parse()
            .map_err(|_| bad(format!("not a number (got \"{}\")", s.trim())))?;
        if v.is_finite() {
            Ok(v)
        } else {
            Err(bad(format!("not a finite number (got \"{}\")", s.trim())))
        }
    };
    let raw: Vec<f64> = if text.contains(':') {
        if text.contains(',') {
            return Err(bad(format!(
                "use either a comma list or start:stop:count, not both (got \"{}\")",
                crate::problem::excerpt(text)
            )));
        }
        let parts: Vec<&str> = text.split(':').collect();
        let [start, stop, count] = parts[..] else {
            return Err(bad(format!(
                "expected start:stop:count (got \"{}\")",
                crate::problem::excerpt(text)
            )));
        };
        let count: u64 = count.trim().parse().map_err(|_| {
            bad(format!(
                "count must be a whole number from 1 to {MAX_THETA_COUNT} (got \"{}\")",
                count.trim()
            ))
        })?;
        if !(1..=MAX_THETA_COUNT).contains(&count) {
            return Err(bad(format!(
                "count must be from 1 to {MAX_THETA_COUNT} (got {count})"
            )));
        }
        linspace(number(start)?, number(stop)?, count as usize)
    } else {
        let items: Vec<&str> = text.split(',').collect();
        if items.len() as u64 > MAX_THETA_COUNT {
            return Err(bad(format!("more than {MAX_THETA_COUNT} values")));
        }
        items.into_iter().map(number).collect::<Result<_>>()?
    };
    raw.into_iter()
        .map(|v| {
            let theta = if degrees {
                v * std::f64::consts::PI / 180.0
            } else {
                v
            };
            if (0.0..=FRAC_PI_2).contains(&theta) {
                Ok(theta)
            } else {
                let unit = if degrees {
                    "degrees, expected 0 to 90"
                } else {
                    "radians, expected 0 to 1.5707963267948966"
                };
                Err(bad(format!("angle out of range (got {v:?} {unit})")))
            }
        })
        .collect()
}

/// The CSV table: `theta,value` for one curve, else `theta,<canonical curve JSON>…`; one row per θ
/// in input order, numbers in shortest round-trip form.
pub fn table(curves: &[Curve], thetas: &[f64]) -> Result<String> {
    let header: Vec<String> = if let [_] = curves {
        vec!["theta".into(), "value".into()]
    } else {
        std::iter::once("theta".to_string())
            .chain(curves.iter().map(Curve::canonical_json))
            .collect()
    };
    let mut table = Table::new(header, thetas.len() * 24 * (curves.len() + 1));
    for &theta in thetas {
        table.number(theta);
        for curve in curves {
            let value = curve.eval(theta);
            if !value.is_finite() {
                return Err(Error::Numerics(format!(
                    "{} gave a non-finite value at theta = {theta:?}",
                    curve.canonical_json()
                )));
            }
            table.number(value);
        }
        table.end_row();
    }
    Ok(table.into_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn multiples_of_pi_are_read_in_any_position() {
        use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};
        assert_eq!(pi_multiple("pi"), Some(PI));
        assert_eq!(pi_multiple("π/2"), Some(FRAC_PI_2));
        assert_eq!(pi_multiple(" pi/4 "), Some(FRAC_PI_4));
        assert_eq!(pi_multiple("3pi/8"), Some(3.0 * PI / 8.0));
        assert_eq!(pi_multiple("0.5*pi"), Some(0.5 * PI));
        for not in ["p", "pi/", "pi/0", "-pi", "2pie", "x"] {
            assert_eq!(pi_multiple(not), None, "{not}");
        }
        assert_eq!(
            parse_theta_list("0,pi/4,pi/2", false).unwrap(),
            [0.0, FRAC_PI_4, FRAC_PI_2]
        );
        assert_eq!(
            parse_theta_list("0:pi/2:3", false).unwrap(),
            [0.0, FRAC_PI_4, FRAC_PI_2]
        );
        assert!(parse_theta_list("pi", false).is_err());
        assert!(
            parse_theta_list("pi/4", true).is_err(),
            "degrees take numbers only"
        );
    }

    #[test]
    fn theta_lists() {
        assert_eq!(
            parse_theta_list("0,0.1, 1.5707963267948966", false).unwrap(),
            [0.0, 0.1, FRAC_PI_2]
        );
        assert_eq!(
            parse_theta_list("0:90:3", true).unwrap(),
            [0.0, std::f64::consts::FRAC_PI_4, FRAC_PI_2]
        );
        assert_eq!(parse_theta_list("90", true).unwrap(), [FRAC_PI_2]);
        for bad in [
            "abc",
            "0:1:0",
            "nan",
            "0:1:100000000000000",
            "0:1",
            "0,1:2:3",
            "-0.1",
            "1.6",
            "",
            "inf",
        ] {
            assert!(parse_theta_list(bad, false).is_err(), "{bad}");
        }
    }

    #[test]
    fn several_curves_are_named_by_their_quoted_canonical_json() {
        let curves: Vec<Curve> = [
            r#"{"ndf":"phong","alpha_p":1}"#,
            r#"{"fresnel":"schlick","f0":0.04}"#,
        ]
        .iter()
        .map(|text| {
            let spec = crate::curve::parse(&crate::json::parse(text).unwrap(), "").unwrap();
            crate::resolve::curve(&spec).unwrap()
        })
        .collect();
        assert_eq!(
            table(&curves, &[0.0]).unwrap(),
            "theta,\"{\"\"ndf\"\":\"\"phong\"\",\"\"alpha_p\"\":1.0}\",\"{\"\"fresnel\"\":\"\"schlick\"\",\"\"f0\"\":0.04}\"\n\
             0.0,0.477464829275686,0.04\n"
        );
    }
}
