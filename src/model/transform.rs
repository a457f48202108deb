//! View transforms of NDF values: the quantities papers plot besides D(θ) itself.
//!
//! Pure f64 code. A transform maps (θ, D(θ)) to the plotted value; the x axis that goes with it
//! (θ, or tan θ for the slope view) is the plot's business.

use crate::model::names::named;
use std::f64::consts::FRAC_PI_2;

named! {
    /// A value transform applied to an NDF.
    pub enum Transform {
        /// D(θ) cos θ: the projected-area density, which integrates to 1/(2π) against sin θ dθ
        /// (BRDF Explorer's "× N·L").
        Projected = "projected",
        /// The slope-space density P₂₂ = D(θ) cos⁴θ at slope tan θ (Bagher et al. 2012's native view,
        /// ∫∫ P₂₂ dp dq = 1).
        Slope = "slope",
    }
}

impl Transform {
    /// The transformed value at θ of an NDF whose value there is `d`. At θ = π/2 (the double
    /// nearest it) cos θ is taken as 0, the limit, so grazing values are exactly 0.
    #[inline]
    pub fn apply(self, theta: f64, d: f64) -> f64 {
        let cos_theta = if theta >= FRAC_PI_2 { 0.0 } else { theta.cos() };
        match self {
            Transform::Projected => d * cos_theta,
            Transform::Slope => {
                let cos2 = cos_theta * cos_theta;
                d * cos2 * cos2
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn transforms_weight_by_cosines() {
        assert_eq!(Transform::Projected.apply(0.0, 2.0), 2.0);
        assert_eq!(Transform::Slope.apply(0.0, 2.0), 2.0);
        let theta = std::f64::consts::FRAC_PI_3;
        assert!((Transform::Projected.apply(theta, 1.0) - 0.5).abs() < 1e-15);
        assert!((Transform::Slope.apply(theta, 1.0) - 0.0625).abs() < 1e-15);
        assert_eq!(Transform::Projected.apply(FRAC_PI_2, 5.0), 0.0);
        assert_eq!(Transform::from_name("slope"), Some(Transform::Slope));
    }
}
