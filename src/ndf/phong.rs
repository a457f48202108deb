//! Placeholder: to be replaced by the stable implementation.
use crate::domain::{DomainError, check};
/// Placeholder.
#[derive(Debug, Clone, PartialEq)]
pub struct Phong { alpha_p: f64,  }
impl Phong {
    /// Placeholder.
    pub fn new(alpha_p: f64, ) -> Result<Self, DomainError> {
        check("alpha_p", alpha_p, |v| v > 0.0, "> 0")?;
        Ok(Phong { alpha_p,  })
    }
    /// Placeholder.
    pub fn eval(&self, _theta: f64) -> f64 { todo!() }
    /// Placeholder.
    pub fn alpha_p(&self) -> f64 { self.alpha_p }
}
