//! The fixed 16-point Gauss–Legendre rule: ∫ₐᵇ f(x) dx ≈ Σᵢ wᵢ f(xᵢ), exact for polynomials of degree 31.
//!
//! For integrands whose features are known in advance and split off into panels (the Smith Λ integrals of
//! [`crate::model::masking`] and the Phong Λ): a fixed set of 16 evaluations per panel, no allocation, no
//! error estimate. Where the features are unknown, use the adaptive [`crate::model::math::quad`].

/// Non-negative abscissae of the 16-point rule on [−1, 1] with their weights (the rule is symmetric),
/// computed by Newton's method on P₁₆ with mpmath at 40 digits and rounded to 21.
#[allow(clippy::excessive_precision)] // mpmath values, kept at the printed 21 digits
const NODES: [(f64, f64); 8] = [
    (0.989400934991649932596, 0.0271524594117540948518),
    (0.944575023073232576078, 0.0622535239386478928628),
    (0.86563120238783174388, 0.0951585116824927848099),
    (0.755404408355003033895, 0.124628971255533872052),
    (0.617876244402643748447, 0.149595988816576732082),
    (0.458016777657227386342, 0.169156519395002538189),
    (0.28160355077925891323, 0.182603415044923588867),
    (0.0950125098376374401853, 0.189450610455068496285),
];

/// ∫ₐᵇ f(x) dx by the 16-point Gauss–Legendre rule (a < b; f is never evaluated at a or b).
#[inline]
pub fn integrate(mut f: impl FnMut(f64) -> f64, a: f64, b: f64) -> f64 {
    let (centre, half) = (0.5 * (a + b), 0.5 * (b - a));
    let sum: f64 = NODES
        .iter()
        .map(|&(x, w)| w * (f(centre - half * x) + f(centre + half * x)))
        .sum();
    half * sum
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integrates_polynomials_of_degree_31_exactly() {
        let got = integrate(|x| x.powi(30) + x.powi(31), -1.0, 1.0);
        assert!((got - 2.0 / 31.0).abs() <= 4.0 * f64::EPSILON, "{got}");
        let got = integrate(|x| x.exp(), 0.0, 1.0);
        assert!(
            (got - (1f64.exp() - 1.0)).abs() <= 4.0 * f64::EPSILON,
            "{got}"
        );
    }
}
