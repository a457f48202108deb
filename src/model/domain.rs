//! Parameter domains and the error a model constructor returns when a value lies outside one.
//!
//! Pure data: a model file states each parameter's domain once, as a [`Param`] with the reason for
//! each bound; its constructor validates with [`Param::check`], and whatever shows or searches a
//! domain (error messages, `--help`, fit search ranges, the JSON Schema, docs/reference.md's table, tests) reads
//! that same [`Param`]. The curve parser attaches the JSON path and file to a [`DomainError`].

use std::fmt;

/// One end of a parameter's domain.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bound {
    /// The bound; `f64::MAX` (or `-f64::MAX`) for a side where every finite value is accepted.
    pub value: f64,
    /// Whether `value` itself is accepted.
    pub inclusive: bool,
    /// Why values beyond the bound are refused (or, for an open side, why every finite value works).
    pub reason: &'static str,
}

impl Bound {
    /// A bound that `value` itself satisfies.
    pub const fn inclusive(value: f64, reason: &'static str) -> Bound {
        Bound {
            value,
            inclusive: true,
            reason,
        }
    }

    /// A bound that `value` itself violates.
    pub const fn exclusive(value: f64, reason: &'static str) -> Bound {
        Bound {
            value,
            inclusive: false,
            reason,
        }
    }

    /// Whether this side accepts every finite value (the bound is ±`f64::MAX`, inclusive).
    pub fn is_open(&self) -> bool {
        self.inclusive && self.value.abs() == f64::MAX
    }
}

/// A model parameter: its canonical name and its domain, min ≤ (or <) value ≤ (or <) max, finite.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Param {
    /// Canonical parameter name as written in the curve JSON.
    pub name: &'static str,
    /// How legends write it (`α_b`, `a₁`).
    pub symbol: &'static str,
    /// The lower end of the domain.
    pub min: Bound,
    /// The upper end of the domain.
    pub max: Bound,
}

impl Param {
    /// Whether `value` is finite and inside both bounds.
    pub fn contains(&self, value: f64) -> bool {
        let above = if self.min.inclusive {
            value >= self.min.value
        } else {
            value > self.min.value
        };
        let below = if self.max.inclusive {
            value <= self.max.value
        } else {
            value < self.max.value
        };
        value.is_finite() && above && below
    }

    /// `value` if [`contains`](Self::contains) it, else the error naming the parameter and its bounds.
    pub fn check(&self, value: f64) -> Result<f64, DomainError> {
        if self.contains(value) {
            Ok(value)
        } else {
            Err(DomainError::new(self.name, value, self.expected()))
        }
    }

    /// The domain in short: `in [1e-150, 1e4]`, `in (0, 1e100]`, or `≥ 0` for a side open to every
    /// finite value.
    pub fn interval(&self) -> String {
        let (min, max) = (short(self.min.value), short(self.max.value));
        match (self.min.is_open(), self.max.is_open()) {
            (true, true) => "finite".into(),
            (false, true) => format!("{} {min}", if self.min.inclusive { "≥" } else { ">" }),
            (true, false) => format!("{} {max}", if self.max.inclusive { "≤" } else { "<" }),
            (false, false) => format!(
                "in {}{min}, {max}{}",
                if self.min.inclusive { "[" } else { "(" },
                if self.max.inclusive { "]" } else { ")" }
            ),
        }
    }

    /// What a rejected value should have been, with the reason for each closed bound:
    /// `in [1e-150, 1e4] (smaller: …; larger: …)`.
    pub fn expected(&self) -> String {
        let reasons: Vec<String> = [("smaller", &self.min), ("larger", &self.max)]
            .into_iter()
            .filter(|(_, bound)| !bound.is_open())
            .map(|(side, bound)| format!("{side}: {}", bound.reason))
            .collect();
        let finite = if self.min.is_open() || self.max.is_open() {
            " and finite"
        } else {
            ""
        };
        format!("{}{finite} ({})", self.interval(), reasons.join("; "))
    }
}

/// The shorter of `v`'s decimal and exponent forms (`0`, `-10`, `0.5`, `1e4`, `1e-150`), the decimal
/// one on a tie.
fn short(v: f64) -> String {
    let (decimal, exponent) = (format!("{v}"), format!("{v:e}"));
    if exponent.len() < decimal.len() {
        exponent
    } else {
        decimal
    }
}

/// A parameter value that a model cannot accept.
///
/// `param` is the canonical parameter name (`alpha_b`, `eta`, …), `value` the rejected value and
/// `expected` a short statement of the bound, e.g. `"> 0"` or `"finite and ≤ 1e8"`.
#[derive(Debug, Clone, PartialEq)]
pub struct DomainError {
    /// Canonical parameter name as written in the curve JSON.
    pub param: &'static str,
    /// The rejected value.
    pub value: f64,
    /// The bound the value violates, phrased as what was expected.
    pub expected: String,
}

impl DomainError {
    /// Builds the error for `param = value`, which should have satisfied `expected`.
    pub fn new(param: &'static str, value: f64, expected: impl Into<String>) -> Self {
        DomainError {
            param,
            value,
            expected: expected.into(),
        }
    }
}

impl fmt::Display for DomainError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}: out of domain (got {:?}, expected {})",
            self.param, self.value, self.expected
        )
    }
}

impl std::error::Error for DomainError {}

/// Checks that `value` is finite and strictly inside `(low, high]`-style bounds described by `expected`.
///
/// Returns `Err` naming `param` when `value` is NaN, infinite, or `ok(value)` is false.
pub fn check(
    param: &'static str,
    value: f64,
    ok: impl Fn(f64) -> bool,
    expected: &str,
) -> Result<f64, DomainError> {
    if value.is_finite() && ok(value) {
        Ok(value)
    } else {
        Err(DomainError::new(param, value, expected))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const ALPHA: Param = Param {
        name: "alpha",
        symbol: "α",
        min: Bound::exclusive(0.0, "no lobe"),
        max: Bound::inclusive(1e4, "too close to grazing"),
    };

    #[test]
    fn bounds_are_checked_and_stated_with_their_reasons() {
        assert!(ALPHA.contains(1e4) && ALPHA.contains(5e-324));
        for bad in [0.0, -1.0, 10000.000000000002, f64::NAN, f64::INFINITY] {
            assert!(ALPHA.check(bad).is_err(), "{bad}");
        }
        assert_eq!(
            ALPHA.check(0.0).unwrap_err().to_string(),
            "alpha: out of domain (got 0.0, expected in (0, 1e4] (smaller: no lobe; larger: too close to grazing))"
        );
        let open = Param {
            max: Bound::inclusive(f64::MAX, "any finite value works"),
            min: Bound::inclusive(-10.0, "unverified"),
            ..ALPHA
        };
        assert_eq!(open.interval(), "≥ -10");
        assert_eq!(open.expected(), "≥ -10 and finite (smaller: unverified)");
        assert!(open.contains(f64::MAX) && !open.contains(f64::INFINITY));
    }
}
