//! Placeholder: to be replaced by the stable implementation.
use crate::domain::{DomainError, check};
/// Placeholder.
#[derive(Debug, Clone, PartialEq)]
pub struct TrowbridgeReitz { alpha_tr: f64,  }
impl TrowbridgeReitz {
    /// Placeholder.
    pub fn new(alpha_tr: f64, ) -> Result<Self, DomainError> {
        check("alpha_tr", alpha_tr, |v| v > 0.0, "> 0")?;
        Ok(TrowbridgeReitz { alpha_tr,  })
    }
    /// Placeholder.
    pub fn eval(&self, _theta: f64) -> f64 { todo!() }
    /// Placeholder.
    pub fn alpha_tr(&self) -> f64 { self.alpha_tr }
}
