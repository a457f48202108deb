//! Placeholder: to be replaced by the stable implementation.
use crate::domain::{DomainError, check};
/// Placeholder.
#[derive(Debug, Clone, PartialEq)]
pub struct Abc { alpha_abc1: f64, alpha_abc2: f64,  }
impl Abc {
    /// Placeholder.
    pub fn new(alpha_abc1: f64, alpha_abc2: f64, ) -> Result<Self, DomainError> {
        check("alpha_abc1", alpha_abc1, |v| v > 0.0, "> 0")?;
        check("alpha_abc2", alpha_abc2, |v| v > 0.0, "> 0")?;
        Ok(Abc { alpha_abc1, alpha_abc2,  })
    }
    /// Placeholder.
    pub fn eval(&self, _theta: f64) -> f64 { todo!() }
    /// Placeholder.
    pub fn alpha_abc1(&self) -> f64 { self.alpha_abc1 }
    /// Placeholder.
    pub fn alpha_abc2(&self) -> f64 { self.alpha_abc2 }
}
