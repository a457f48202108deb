//! Fixed Gauss–Legendre rules: ∫ₐᵇ f(x) dx ≈ Σᵢ wᵢ f(xᵢ), the n-point rule exact for polynomials of
//! degree 2n − 1.
//!
//! For integrands whose features are known in advance and split off into panels (the Smith Λ integrals of
//! [`crate::model::masking`] and the Phong Λ): a fixed set of 16 evaluations per panel ([`integrate`]), no
//! allocation, no error estimate; [`Rule`] gives the n-point rule for any n (the directional albedo's panels).
//! Where the features are unknown, use the adaptive [`crate::model::math::quad`].

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

/// The points of the fixed rule of [`integrate`] and [`nodes`].
pub const POINTS: usize = 2 * NODES.len();

/// The nodes of the 16-point rule on [a, b] with their weights scaled to it, (x, w (b − a)/2), in pairs
/// mirrored about the centre (c − h xᵢ, then c + h xᵢ), as [`integrate`] visits them: Σ w f(x) over them
/// is ∫ₐᵇ f.
pub fn nodes(a: f64, b: f64) -> impl Iterator<Item = (f64, f64)> {
    let (centre, half) = (0.5 * (a + b), 0.5 * (b - a));
    NODES
        .iter()
        .flat_map(move |&(x, w)| [(centre - half * x, w * half), (centre + half * x, w * half)])
}

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

/// The n-point Gauss–Legendre rule on [0, 1]: nodes xᵢ = (1 + tᵢ)/2 and weights wᵢ/2, tᵢ the zeros of
/// the Legendre polynomial Pₙ (ascending) and wᵢ = 2/((1 − tᵢ²) Pₙ'(tᵢ)²), each zero found by Newton's
/// method from Tricomi's estimate cos(π(i + 3/4)/(n + 1/2)) until the step is below 1e-16 (nodes and
/// weights then within a few ulps; the sum of the weights is 1 to rounding).
#[derive(Debug, Clone, PartialEq)]
pub struct Rule {
    /// (xᵢ, wᵢ) on [0, 1], ascending in x.
    pub points: Vec<(f64, f64)>,
}

impl Rule {
    /// The rule with n ≥ 1 points.
    pub fn new(n: usize) -> Rule {
        assert!(n >= 1, "a rule needs a point");
        let nf = n as f64;
        let mut points: Vec<(f64, f64)> = (0..n)
            .map(|i| {
                let mut t = (std::f64::consts::PI * (i as f64 + 0.75) / (nf + 0.5)).cos();
                let mut derivative = 1.0;
                for _ in 0..100 {
                    // Pₙ(t) and Pₙ'(t) by the three-term recurrence.
                    let (mut p0, mut p1) = (1.0, t);
                    for k in 2..=n {
                        let kf = k as f64;
                        (p0, p1) = (p1, ((2.0 * kf - 1.0) * t * p1 - (kf - 1.0) * p0) / kf);
                    }
                    derivative = nf * (t * p1 - p0) / (t * t - 1.0);
                    let step = p1 / derivative;
                    t -= step;
                    if step.abs() <= 1e-16 {
                        break;
                    }
                }
                let weight = 2.0 / ((1.0 - t * t) * derivative * derivative);
                (0.5 * (1.0 - t), 0.5 * weight)
            })
            .collect();
        points.sort_by(|a, b| a.0.total_cmp(&b.0));
        Rule { points }
    }

    /// ∫ₐᵇ f(x) dx by the rule (f is never evaluated at a or b).
    #[inline]
    pub fn integrate(&self, mut f: impl FnMut(f64) -> f64, a: f64, b: f64) -> f64 {
        let length = b - a;
        length
            * self
                .points
                .iter()
                .map(|&(x, w)| w * f(a + length * x))
                .sum::<f64>()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fixed_rules_nodes_integrate_as_the_rule_does() {
        // x¹⁵ − 3x⁴ + 1 on [0.2, 1.7]: degree 15 ≤ 31, so both are exact to rounding.
        let f = |x: f64| x.powi(15) - 3.0 * x.powi(4) + 1.0;
        let exact = |x: f64| x.powi(16) / 16.0 - 0.6 * x.powi(5) + x;
        let want = exact(1.7) - exact(0.2);
        let by_nodes: f64 = nodes(0.2, 1.7).map(|(x, w)| w * f(x)).sum();
        assert_eq!(nodes(0.2, 1.7).count(), POINTS);
        for got in [by_nodes, integrate(f, 0.2, 1.7)] {
            assert!((got / want - 1.0).abs() <= 1e-14, "{got} vs {want}");
        }
    }

    #[test]
    fn rules_reproduce_the_tabulated_16_point_rule_and_integrate_polynomials() {
        let rule = Rule::new(16);
        for (&(x, w), &(t, v)) in rule.points[8..].iter().zip(NODES.iter().rev()) {
            assert!(
                (2.0 * x - 1.0 - t).abs() <= 4.0 * f64::EPSILON,
                "{x} vs {t}"
            );
            assert!((2.0 * w - v).abs() <= 4.0 * f64::EPSILON, "{w} vs {v}");
        }
        for n in [1, 2, 7, 24, 64] {
            let rule = Rule::new(n);
            let degree = 2 * n as i32 - 1;
            let got = rule.integrate(|x| x.powi(degree), 0.0, 1.0);
            let want = 1.0 / f64::from(degree + 1);
            assert!((got - want).abs() <= 64.0 * f64::EPSILON, "n = {n}: {got}");
        }
    }

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
