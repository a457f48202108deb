//! A Fresnel weight tabulated on the basis grid and interpolated linearly in c = cos θd (the
//! Belcour–Bati–Barla basis functions and reconstructions, [`crate::model::fresnel::basis`]), as
//! the albedo integrals take it: a smooth surrogate with the same integral over every grid cell.
//!
//! The linear interpolant L has a kink at each of the 1000 nodes, where a fixed or adaptive rule
//! converges only algebraically. Write L = S + e with S the cubic spline through the nodes
//! (second derivatives M_j, ends M₀ = 2M₁ − M₂ and M_{n−1} = 2M_{n−2} − M_{n−3}): on the cell
//! [c_j, c_{j+1}] of width h, with t = (c − c_j)/h,
//! e = (h²/6) t (1 − t) [(2 − t) M_j + (1 + t) M_{j+1}], whose mean over the cell is
//! (h²/24)(M_j + M_{j+1}). The surrogate F̃ = S + (h²/12) M(c), M(c) linear between the M_j, has
//! exactly that mean on every cell, so ∫ (L − F̃) W dc = ∫ (e − ē) W dc vanishes up to
//! O(h² max|M| · h |W′|/|W| · h) for any weight W smooth over a few cells: the albedo's
//! distribution of cos θd, as wide as the lobe is. F̃ is C² but for jumps of h² |ΔM|/12 ~ 1e-10
//! in its curvature term, smooth enough for the fixed rules.

use crate::model::fresnel::basis::basis;

/// The smooth surrogate F̃ of a weight tabulated on the basis grid (module docs).
#[derive(Debug, Clone)]
pub struct Smoothed {
    nodes: &'static [f64],
    values: Vec<f64>,
    second: Vec<f64>,
}

impl Smoothed {
    /// The surrogate of the linear interpolant through `values` at the basis grid's nodes c_j
    /// ([`crate::model::fresnel::basis::Basis::cos_theta`], 1000 of them).
    pub fn new(values: Vec<f64>) -> Smoothed {
        let nodes = basis().cos_theta();
        assert_eq!(values.len(), nodes.len(), "one value per grid node");
        let second = spline_second_derivatives(nodes, &values);
        Smoothed {
            nodes,
            values,
            second,
        }
    }

    /// The surrogate of `weight` (a function of θd that is linear in cos θd between the grid
    /// nodes), from its values at the nodes.
    pub fn of(weight: impl Fn(f64) -> f64) -> Smoothed {
        Smoothed::new(
            basis()
                .cos_theta()
                .iter()
                .map(|&c| weight(c.clamp(0.0, 1.0).acos()))
                .collect(),
        )
    }

    /// The grid nodes c_j, ascending from 0 to 1.
    pub fn nodes(&self) -> &[f64] {
        self.nodes
    }

    /// The width of a grid cell, 1/999.
    pub fn cell(&self) -> f64 {
        1.0 / (self.nodes.len() - 1) as f64
    }

    /// The cell [c_j, c_{j+1}] holding c and t = (c − c_j)/(c_{j+1} − c_j).
    fn locate(&self, c: f64) -> (usize, f64) {
        let last = self.nodes.len() - 1;
        let j = ((c * last as f64).floor().max(0.0) as usize).min(last - 1);
        (j, (c - self.nodes[j]) / (self.nodes[j + 1] - self.nodes[j]))
    }

    /// The tabulated weight itself at c = cos θd ∈ [0, 1]: its linear interpolant L.
    pub fn linear_at_cos(&self, c: f64) -> f64 {
        let (j, t) = self.locate(c);
        (1.0 - t) * self.values[j] + t * self.values[j + 1]
    }

    /// F̃ at c = cos θd ∈ [0, 1]: S(c) + (h²/12) M(c).
    pub fn at_cos(&self, c: f64) -> f64 {
        let (j, t) = self.locate(c);
        let h = self.nodes[j + 1] - self.nodes[j];
        let (m0, m1) = (self.second[j], self.second[j + 1]);
        let linear = (1.0 - t) * self.values[j] + t * self.values[j + 1];
        let bend = (h * h / 6.0) * t * (1.0 - t) * ((2.0 - t) * m0 + (1.0 + t) * m1);
        let mean = (h * h / 12.0) * ((1.0 - t) * m0 + t * m1);
        linear - bend + mean
    }

    /// F̃ at the angle θd ∈ [0, π/2].
    pub fn at(&self, theta_d: f64) -> f64 {
        self.at_cos(theta_d.cos())
    }
}

/// The second derivatives M_j of the cubic spline through (x_j, y_j), with the ends extrapolated
/// linearly (M₀ = 2M₁ − M₂, M_{n−1} = 2M_{n−2} − M_{n−3}), by the Thomas algorithm on the
/// interior equations h_{j−1} M_{j−1} + 2(h_{j−1} + h_j) M_j + h_j M_{j+1} = 6 (Δ_j − Δ_{j−1}).
fn spline_second_derivatives(x: &[f64], y: &[f64]) -> Vec<f64> {
    let n = x.len();
    let h: Vec<f64> = x.windows(2).map(|w| w[1] - w[0]).collect();
    let slope: Vec<f64> = (0..n - 1).map(|j| (y[j + 1] - y[j]) / h[j]).collect();
    // Unknowns M_1 … M_{n−2}; row k (k = 1 … n−2) as (sub, diag, sup, rhs).
    let m = n - 2;
    let mut sub = vec![0.0; m];
    let mut diag = vec![0.0; m];
    let mut sup = vec![0.0; m];
    let mut rhs = vec![0.0; m];
    for r in 0..m {
        let j = r + 1;
        sub[r] = h[j - 1];
        diag[r] = 2.0 * (h[j - 1] + h[j]);
        sup[r] = h[j];
        rhs[r] = 6.0 * (slope[j] - slope[j - 1]);
    }
    // M₀ = 2M₁ − M₂ folds into the first row, M_{n−1} = 2M_{n−2} − M_{n−3} into the last.
    diag[0] += 2.0 * sub[0];
    sup[0] -= sub[0];
    diag[m - 1] += 2.0 * sup[m - 1];
    sub[m - 1] -= sup[m - 1];
    for r in 1..m {
        let factor = sub[r] / diag[r - 1];
        diag[r] -= factor * sup[r - 1];
        rhs[r] -= factor * rhs[r - 1];
    }
    let mut inner = vec![0.0; m];
    inner[m - 1] = rhs[m - 1] / diag[m - 1];
    for r in (0..m - 1).rev() {
        inner[r] = (rhs[r] - sup[r] * inner[r + 1]) / diag[r];
    }
    let mut second = Vec::with_capacity(n);
    second.push(2.0 * inner[0] - inner[1]);
    second.extend_from_slice(&inner);
    second.push(2.0 * inner[m - 1] - inner[m - 2]);
    second
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_spline_of_a_cubic_is_the_cubic_and_cell_means_match_the_interpolant() {
        // A cubic is reproduced by the spline with linearly extrapolated ends (its M is linear),
        // so F̃ = p + (h²/12) p″; and on every cell ∫ F̃ = ∫ L (both by Simpson's rule, exact
        // for the cubic F̃ and the linear L).
        let p = |c: f64| 0.3 - c + 2.0 * c * c - 0.7 * c * c * c;
        let p2 = |c: f64| 4.0 - 4.2 * c;
        let nodes = basis().cos_theta();
        let smoothed = Smoothed::new(nodes.iter().map(|&c| p(c)).collect());
        for j in [0, 1, 500, 997, 998] {
            let (a, b) = (nodes[j], nodes[j + 1]);
            let h = b - a;
            let mid = 0.5 * (a + b);
            let want = p(mid) + h * h / 12.0 * p2(mid);
            assert!((smoothed.at_cos(mid) - want).abs() <= 1e-13, "cell {j}");
            let surrogate =
                h / 6.0 * (smoothed.at_cos(a) + 4.0 * smoothed.at_cos(mid) + smoothed.at_cos(b));
            let linear = h / 2.0 * (p(a) + p(b));
            assert!(
                (surrogate - linear).abs() <= 1e-17,
                "cell {j}: {surrogate} vs {linear}"
            );
        }
    }
}
