//! Placeholder: to be replaced by the stable implementation.
use crate::domain::{DomainError, check};
/// Placeholder.
#[derive(Debug, Clone, PartialEq)]
pub struct Sgd { alpha_sgd1: f64, alpha_sgd2: f64,  }
impl Sgd {
    /// Placeholder.
    pub fn new(alpha_sgd1: f64, alpha_sgd2: f64, ) -> Result<Self, DomainError> {
        check("alpha_sgd1", alpha_sgd1, |v| v > 0.0, "> 0")?;
        check("alpha_sgd2", alpha_sgd2, |v| v > 0.0, "> 0")?;
        Ok(Sgd { alpha_sgd1, alpha_sgd2,  })
    }
    /// Placeholder.
    pub fn eval(&self, _theta: f64) -> f64 { todo!() }
    /// Placeholder.
    pub fn alpha_sgd1(&self) -> f64 { self.alpha_sgd1 }
    /// Placeholder.
    pub fn alpha_sgd2(&self) -> f64 { self.alpha_sgd2 }
}
