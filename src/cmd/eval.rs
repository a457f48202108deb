//! `ndfplot eval`: a curve's values at given angles, as CSV on standard output (CONTRACTS.md).

use crate::angle::AngleUnit;
use crate::curve::Curve;
use crate::error::{Error, Result};
use crate::grid::linspace;
use crate::output::csv::Table;

/// Largest θ count of a `start:stop:count` list (CONTRACTS.md).
pub const MAX_THETA_COUNT: u64 = 10_000_000;

/// One angle of a θ list: the value as given (radians or degrees) and θ in radians.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Angle {
    /// The value in the unit it was given in, as printed in the θ column.
    pub given: f64,
    /// θ in radians, where the curves are evaluated.
    pub radians: f64,
}

/// Parses a θ list: comma-separated numbers or `start:stop:count` (numpy linspace, taken in the unit
/// given), in `unit` (radians may be multiples of π, [`crate::angle::pi_multiple`]; degrees are
/// converted as θ = d·π/180). Every θ must lie in [0, π/2].
pub fn parse_theta_list(text: &str, unit: AngleUnit) -> Result<Vec<Angle>> {
    let bad = |what: String| Error::Usage(format!("--theta: {what}"));
    let number = |s: &str| unit.parse(s).map_err(bad);
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
        .map(|given| {
            let radians = unit.check(given).map_err(bad)?;
            Ok(Angle { given, radians })
        })
        .collect()
}

/// The CSV table: `theta,value` for one curve, else `theta,<canonical curve JSON>…`; one row per θ
/// in input order, numbers in shortest round-trip form. The θ column holds the angles as given, in
/// `unit`, and is named `theta` for radians, `theta_deg` for degrees.
pub fn table(curves: &[Curve], thetas: &[Angle], unit: AngleUnit) -> Result<String> {
    let theta_name = unit.name("theta");
    let header: Vec<String> = if let [_] = curves {
        vec![theta_name, "value".into()]
    } else {
        std::iter::once(theta_name)
            .chain(curves.iter().map(Curve::canonical_json))
            .collect()
    };
    let mut table = Table::new(header, thetas.len() * 24 * (curves.len() + 1));
    for &Angle {
        given,
        radians: theta,
    } in thetas
    {
        table.number(given);
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
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_4};

    fn radians(text: &str, unit: AngleUnit) -> Result<Vec<f64>> {
        parse_theta_list(text, unit).map(|list| list.iter().map(|a| a.radians).collect())
    }

    #[test]
    fn theta_lists() {
        let rad = AngleUnit::Radians;
        assert_eq!(
            radians("0,0.1, 1.5707963267948966", rad).unwrap(),
            [0.0, 0.1, FRAC_PI_2]
        );
        assert_eq!(
            radians("0,pi/4,pi/2", rad).unwrap(),
            [0.0, FRAC_PI_4, FRAC_PI_2]
        );
        assert_eq!(
            radians("0:pi/2:3", rad).unwrap(),
            [0.0, FRAC_PI_4, FRAC_PI_2]
        );
        assert!(radians("pi", rad).is_err());
        let degrees = parse_theta_list("0:90:3", AngleUnit::Degrees).unwrap();
        assert_eq!(
            degrees
                .iter()
                .map(|a| (a.given, a.radians))
                .collect::<Vec<_>>(),
            [(0.0, 0.0), (45.0, FRAC_PI_4), (90.0, FRAC_PI_2)]
        );
        assert!(radians("pi/4", AngleUnit::Degrees).is_err());
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
            assert!(radians(bad, rad).is_err(), "{bad}");
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
        let zero = [Angle {
            given: 0.0,
            radians: 0.0,
        }];
        assert_eq!(
            table(&curves, &zero, AngleUnit::Radians).unwrap(),
            "theta,\"{\"\"ndf\"\":\"\"phong\"\",\"\"alpha_p\"\":1.0}\",\"{\"\"fresnel\"\":\"\"schlick\"\",\"\"f0\"\":0.04}\"\n\
             0.0,0.477464829275686,0.04\n"
        );
        assert!(
            table(&curves[..1], &zero, AngleUnit::Degrees)
                .unwrap()
                .starts_with("theta_deg,value\n")
        );
    }
}
