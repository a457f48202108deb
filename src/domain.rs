//! The error a model constructor returns when a parameter lies outside its domain.
//!
//! Pure data: the maths modules build it, the curve parser attaches the JSON path and file.

use std::fmt;

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
