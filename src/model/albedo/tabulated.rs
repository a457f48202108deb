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

use std::sync::OnceLock;

use crate::model::fresnel::basis::basis;

/// The smooth surrogate F̃ of a weight tabulated on the basis grid (module docs).
#[derive(Debug, Clone)]
pub struct Smoothed {
    nodes: &'static [f64],
    values: Vec<f64>,
    /// Per cell j, F̃ as a cubic in x = c − c_j: [c_j, a₀, a₁, a₂, a₃], F̃ = a₀ + x (a₁ + x (a₂ + x a₃))
    /// ([`cell_cubic`]), so that one value is a locate, five loads and three fused steps, in vector
    /// lanes over a block ([`Smoothed::at_cos_many`]).
    cubics: Vec<[f64; 5]>,
}

impl Smoothed {
    /// The surrogate of the linear interpolant through `values` at the basis grid's nodes c_j
    /// ([`crate::model::fresnel::basis::Basis::cos_theta`], 1000 of them).
    pub fn new(values: Vec<f64>) -> Smoothed {
        let nodes = basis().cos_theta();
        assert_eq!(values.len(), nodes.len(), "one value per grid node");
        let second = spline_second_derivatives(nodes, &values);
        let cubics = (0..nodes.len() - 1)
            .map(|j| {
                cell_cubic(
                    nodes[j],
                    nodes[j + 1],
                    values[j],
                    values[j + 1],
                    second[j],
                    second[j + 1],
                )
            })
            .collect();
        Smoothed {
            nodes,
            values,
            cubics,
        }
    }

    /// The surrogate of Σ_k `weights`[k] b_k, a combination of the Belcour–Bati–Barla basis
    /// functions ([`crate::model::fresnel::basis::Basis::function`]; a reconstruction c₀ … c₃,
    /// or one b_k): the same combination of the basis functions' surrogates, built once. F̃ is
    /// linear in the node values — the spline's M_j solve a linear system, and each cell's cubic
    /// is linear in y and M — so this is [`Smoothed::new`] of the combined values up to rounding,
    /// for 4 × 5 products a cell instead of the spline's solve. The values are combined as
    /// [`crate::model::fresnel::basis::Coefficients::reconstruction`] combines them.
    pub fn of_basis(weights: [f64; 4]) -> Smoothed {
        static SURROGATES: OnceLock<[Smoothed; 4]> = OnceLock::new();
        let parts = SURROGATES
            .get_or_init(|| std::array::from_fn(|k| Smoothed::new(basis().function(k).to_vec())));
        let combine = |part: &dyn Fn(&Smoothed) -> f64| {
            weights[0] * part(&parts[0])
                + weights[1] * part(&parts[1])
                + weights[2] * part(&parts[2])
                + weights[3] * part(&parts[3])
        };
        let nodes = parts[0].nodes;
        let values = (0..nodes.len())
            .map(|j| combine(&|p: &Smoothed| p.values[j]))
            .collect();
        let cubics = (0..nodes.len() - 1)
            .map(|j| {
                let mut cubic = [nodes[j], 0.0, 0.0, 0.0, 0.0];
                for (i, a) in cubic.iter_mut().enumerate().skip(1) {
                    *a = combine(&|p: &Smoothed| p.cubics[j][i]);
                }
                cubic
            })
            .collect();
        Smoothed {
            nodes,
            values,
            cubics,
        }
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
        let j = self.cell_of(c);
        (j, (c - self.nodes[j]) / (self.nodes[j + 1] - self.nodes[j]))
    }

    /// The index j of the cell [c_j, c_{j+1}] holding c: ⌊999 c⌋, clamped to the cells (a negative
    /// or NaN product saturates to 0 in the cast), without a branch.
    #[inline(always)]
    fn cell_of(&self, c: f64) -> usize {
        let cells = self.cubics.len();
        ((c * cells as f64) as usize).min(cells - 1)
    }

    /// The tabulated weight itself at c = cos θd ∈ [0, 1]: its linear interpolant L.
    pub fn linear_at_cos(&self, c: f64) -> f64 {
        let (j, t) = self.locate(c);
        (1.0 - t) * self.values[j] + t * self.values[j + 1]
    }

    /// 2 ∫₀¹ L(c) c dc, the cosine-weighted average of the interpolant L: on each cell
    /// (y_j + y_{j+1}) (c_j + c_{j+1}) h/4 + (y_{j+1} − y_j) h²/12 (L c is a quadratic there), h the
    /// cell's width.
    pub fn average(&self) -> f64 {
        let sum: f64 = (0..self.nodes.len() - 1)
            .map(|j| {
                let (c0, c1) = (self.nodes[j], self.nodes[j + 1]);
                let (y0, y1) = (self.values[j], self.values[j + 1]);
                let h = c1 - c0;
                0.25 * (y0 + y1) * (c0 + c1) * h + (y1 - y0) * h * h / 12.0
            })
            .sum();
        2.0 * sum
    }

    /// F̃ at c = cos θd ∈ [0, 1]: S(c) + (h²/12) M(c), by its cell's cubic ([`cell_cubic`]).
    #[inline(always)]
    pub fn at_cos(&self, c: f64) -> f64 {
        let [node, a0, a1, a2, a3] = self.cubics[self.cell_of(c)];
        let x = c - node;
        a0 + x * (a1 + x * (a2 + x * a3))
    }

    /// `out[k]` = [`Smoothed::at_cos`]`(cs[k])`, the same bits (the lengths must be equal), a loop
    /// without branches that runs in vector lanes inside
    /// [`crate::model::math::elementary::widest`] (a gather of each cell's cubic).
    #[inline(always)]
    pub fn at_cos_many(&self, cs: &[f64], out: &mut [f64]) {
        assert_eq!(cs.len(), out.len(), "one output per argument");
        for (out, &c) in out.iter_mut().zip(cs) {
            *out = self.at_cos(c);
        }
    }

    /// F̃ at the angle θd ∈ [0, π/2].
    pub fn at(&self, theta_d: f64) -> f64 {
        self.at_cos(theta_d.cos())
    }
}

/// F̃ on the cell [c_j, c_{j+1}] (width h, values y_j, y_{j+1}, spline second derivatives M_j,
/// M_{j+1}) as [c_j, a₀, a₁, a₂, a₃], F̃ = a₀ + a₁ x + a₂ x² + a₃ x³ in x = c − c_j: the spline's
/// Taylor coefficients at c_j, y_j, (y_{j+1} − y_j)/h − h (2M_j + M_{j+1})/6, M_j/2 and
/// (M_{j+1} − M_j)/(6h), plus those of (h²/12) M(c), h² M_j/12 and h (M_{j+1} − M_j)/12.
fn cell_cubic(c0: f64, c1: f64, y0: f64, y1: f64, m0: f64, m1: f64) -> [f64; 5] {
    let h = c1 - c0;
    [
        c0,
        y0 + h * h * m0 / 12.0,
        (y1 - y0) / h - h * (5.0 * m0 + m1) / 12.0,
        0.5 * m0,
        (m1 - m0) / (6.0 * h),
    ]
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

    #[test]
    fn the_average_is_the_interpolants_cosine_weighted_integral() {
        // A basis reconstruction's interpolant against Simpson's rule on 64 intervals per cell
        // (exact for L c, a quadratic on each cell, up to rounding).
        let weight = Smoothed::of_basis([0.04, 0.3, -0.2, 0.1]);
        let nodes = weight.nodes();
        let mut direct = 0.0;
        for j in 0..nodes.len() - 1 {
            let (a, b) = (nodes[j], nodes[j + 1]);
            let n = 64;
            let h = (b - a) / n as f64;
            let f = |c: f64| weight.linear_at_cos(c.clamp(a, b)) * c;
            let mut cell = f(a) + f(b);
            for i in 1..n {
                cell += if i % 2 == 1 { 4.0 } else { 2.0 } * f(a + i as f64 * h);
            }
            direct += cell * h / 3.0;
        }
        let average = weight.average();
        assert!(
            (average - 2.0 * direct).abs() <= 1e-14,
            "{average} vs {}",
            2.0 * direct
        );
    }

    #[test]
    fn a_block_gives_the_bits_of_single_values() {
        use crate::model::math::elementary::widest_many;
        let smoothed = Smoothed::of_basis([0.04, 0.96, 0.3, -0.2]);
        let nodes = basis().cos_theta();
        // Nodes, the points between them, the ends and just beyond them (the end cells' cubics).
        let mut cs: Vec<f64> = (0..120).map(|k| f64::from(k) / 119.0).collect();
        cs.extend([
            nodes[1],
            nodes[998],
            0.5 * (nodes[998] + 1.0),
            -1e-17,
            1.0 + 1e-16,
        ]);
        for chunk in cs.chunks(64) {
            let many = widest_many(
                chunk,
                #[inline(always)]
                |cs, out| smoothed.at_cos_many(cs, out),
            );
            for (&c, &got) in chunk.iter().zip(&many) {
                assert_eq!(got.to_bits(), smoothed.at_cos(c).to_bits(), "c = {c}");
            }
        }
    }

    #[test]
    fn a_combination_of_the_basis_is_the_surrogate_of_its_values() {
        // The surrogate is linear in the node values: combining the basis functions' surrogates
        // gives the one built from the combined values, up to rounding, and the same interpolant.
        let weights = [0.04, 0.96, 0.31, -0.17];
        let combined = Smoothed::of_basis(weights);
        let values: Vec<f64> = (0..basis().cos_theta().len())
            .map(|j| (0..4).map(|k| weights[k] * basis().function(k)[j]).sum())
            .collect();
        let direct = Smoothed::new(values);
        for k in 0..=2000 {
            let c = f64::from(k) / 2000.0;
            let (got, want) = (combined.at_cos(c), direct.at_cos(c));
            assert!((got - want).abs() <= 1e-14, "c = {c}: {got} vs {want}");
            let (got, want) = (combined.linear_at_cos(c), direct.linear_at_cos(c));
            assert!((got - want).abs() <= 1e-15, "c = {c}: {got} vs {want}");
        }
    }
}
