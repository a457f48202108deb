//! Angles as the command line reads and prints them: radians (any value may be a multiple of π such as
//! `pi/2`), or degrees with `--degrees`, converted as θ = d·π/180 (docs/contracts.md). `eval --theta` and
//! `compare --theta-range` read their angles here, and name and print θ in the unit they were given in.
//!
//! Text to numbers only: no curve is evaluated and nothing is printed here.

use std::f64::consts::{FRAC_PI_2, PI};

/// The unit a command reads angles in and prints θ in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AngleUnit {
    /// Radians (the default).
    Radians,
    /// Degrees (`--degrees`).
    Degrees,
}

impl AngleUnit {
    /// [`AngleUnit::Degrees`] when `degrees` (the `--degrees` flag), else radians.
    pub fn of(degrees: bool) -> AngleUnit {
        if degrees {
            AngleUnit::Degrees
        } else {
            AngleUnit::Radians
        }
    }

    /// θ in radians of the value `v` given in this unit: v·π/180 for degrees (so 90 is exactly π/2).
    pub fn to_radians(self, v: f64) -> f64 {
        match self {
            AngleUnit::Radians => v,
            AngleUnit::Degrees => v * PI / 180.0,
        }
    }

    /// θ (radians) in this unit: θ·180/π for degrees.
    pub fn from_radians(self, theta: f64) -> f64 {
        match self {
            AngleUnit::Radians => theta,
            AngleUnit::Degrees => theta * 180.0 / PI,
        }
    }

    /// The name of a θ column or member in this unit: `base` in radians, `base` + `_deg` in degrees.
    pub fn name(self, base: &str) -> String {
        match self {
            AngleUnit::Radians => base.to_string(),
            AngleUnit::Degrees => format!("{base}_deg"),
        }
    }

    /// Reads one number in this unit: a finite decimal, or in radians also a multiple of π
    /// ([`pi_multiple`]). The message of an `Err` says what the text is not.
    pub fn parse(self, text: &str) -> Result<f64, String> {
        let text = text.trim();
        if self == AngleUnit::Radians
            && let Some(v) = pi_multiple(text)
        {
            return Ok(v);
        }
        match text.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            Ok(_) => Err(format!("not a finite number (got \"{text}\")")),
            Err(_) => Err(format!(
                "not a number (got \"{}\")",
                crate::problem::excerpt(text)
            )),
        }
    }

    /// Checks that the value `v` in this unit is an angle of [0, π/2] and returns it in radians; the
    /// message of an `Err` names the value and the accepted range in this unit.
    pub fn check(self, v: f64) -> Result<f64, String> {
        let theta = self.to_radians(v);
        if (0.0..=FRAC_PI_2).contains(&theta) {
            Ok(theta)
        } else {
            let unit = match self {
                AngleUnit::Radians => "radians, expected 0 to 1.5707963267948966",
                AngleUnit::Degrees => "degrees, expected 0 to 90",
            };
            Err(format!("angle out of range (got {v:?} {unit})"))
        }
    }
}

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
    (k > 0.0 && n > 0.0).then(|| k * PI / n)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_4;

    #[test]
    fn multiples_of_pi_are_read_in_any_position() {
        assert_eq!(pi_multiple("pi"), Some(PI));
        assert_eq!(pi_multiple("π/2"), Some(FRAC_PI_2));
        assert_eq!(pi_multiple(" pi/4 "), Some(FRAC_PI_4));
        assert_eq!(pi_multiple("3pi/8"), Some(3.0 * PI / 8.0));
        assert_eq!(pi_multiple("0.5*pi"), Some(0.5 * PI));
        for not in ["p", "pi/", "pi/0", "-pi", "2pie", "x"] {
            assert_eq!(pi_multiple(not), None, "{not}");
        }
    }

    #[test]
    fn degrees_convert_and_name_their_columns() {
        let deg = AngleUnit::Degrees;
        assert_eq!(deg.check(90.0), Ok(FRAC_PI_2));
        assert_eq!(deg.from_radians(FRAC_PI_2), 90.0);
        assert_eq!(deg.name("theta"), "theta_deg");
        assert_eq!(AngleUnit::Radians.name("theta"), "theta");
        assert!(deg.parse("pi/4").is_err(), "degrees take numbers only");
        assert!(deg.check(90.5).unwrap_err().contains("expected 0 to 90"));
        assert_eq!(AngleUnit::Radians.parse("pi/2"), Ok(FRAC_PI_2));
    }
}
