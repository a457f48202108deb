//! Placeholder: to be replaced by the stable implementation.
use crate::domain::{DomainError, check};
/// Placeholder.
#[derive(Debug, Clone, PartialEq)]
pub struct TorranceSparrow { alpha_ts: f64,  }
impl TorranceSparrow {
    /// Placeholder.
    pub fn new(alpha_ts: f64, ) -> Result<Self, DomainError> {
        check("alpha_ts", alpha_ts, |v| v > 0.0, "> 0")?;
        Ok(TorranceSparrow { alpha_ts,  })
    }
    /// Placeholder.
    pub fn eval(&self, _theta: f64) -> f64 { todo!() }
    /// Placeholder.
    pub fn alpha_ts(&self) -> f64 { self.alpha_ts }
}
