//! Placeholder: to be replaced by the stable implementation.
use crate::domain::{DomainError, check};
/// Placeholder.
#[derive(Debug, Clone, PartialEq)]
pub struct Beckmann { alpha_b: f64,  }
impl Beckmann {
    /// Placeholder.
    pub fn new(alpha_b: f64, ) -> Result<Self, DomainError> {
        check("alpha_b", alpha_b, |v| v > 0.0, "> 0")?;
        Ok(Beckmann { alpha_b,  })
    }
    /// Placeholder.
    pub fn eval(&self, _theta: f64) -> f64 { todo!() }
    /// Placeholder.
    pub fn alpha_b(&self) -> f64 { self.alpha_b }
}
