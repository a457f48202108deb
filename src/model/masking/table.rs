//! Smith's Λ of one surface tabulated once, for integrals that evaluate it at thousands of angles
//! (the albedo's inner nodes): most families take Λ by a quadrature of its own
//! ([`crate::model::ndf::lambda_integral`], ~10–25 µs a value), the table in ~30 ns one at a time
//! and a few ns a value in a block ([`LambdaTable::lambda_at_cos_many`]).
//!
//! The table holds g(t) = G1/t, G1 = 1/(1 + Λ), in the variable
//! t = cos θ / (cos θ + w sin θ) ∈ [0, 1] (t = 1 at the normal, 0 at grazing; cot θ = w t/(1 − t)),
//! w the lobe's width as a slope: for a lobe whose slopes scale with w, G1 is then one fixed sigmoid
//! in t whatever w is, and Trowbridge–Reitz's G1 = 2t/(t + √(t² + (1 − t)²)) (w = α) is analytic
//! with its nearest singularities at t = (1 ± i)/2. Near grazing G1 vanishes like cos θ, so dividing
//! by t keeps Λ = 1/(t g) − 1 accurate relative to itself where it is large: g is held to an
//! absolute [`TABLE_TOLERANCE`] (it is ~1, w/C at grazing with C = lim cos θ Λ). g is interpolated by
//! [`Piecewise`] Chebyshev pieces, built adaptively from values of Λ at interior points only.
//!
//! Accuracy: every quantity built on G2 = 1/(1 + Λo + Λi) or G1o G1i moves by at most the error of
//! G1, about [`TABLE_TOLERANCE`] (where G1 itself is far smaller, as for a lobe so rough that Λ is
//! huge at every θ > 0, Λ is not accurate relative to itself); tests/numerics/masking.rs checks
//! the table against each family's own Λ over its parameter domain. A lobe narrower than ~1e-5
//! in slope is not tabulated: θ in doubles resolves its grazing end too coarsely for the pieces
//! to converge, as do Λ values whose own quadrature noise exceeds the tolerance.

use crate::model::math::chebyshev::Piecewise;

/// The target absolute error of the tabulated g = G1/t (the sum of each piece's last two Chebyshev
/// coefficients), so of G1 = t g, far below the albedo's tolerance of 1e-10.
pub const TABLE_TOLERANCE: f64 = 1e-12;

/// t = cos θ/(cos θ + w sin θ) at θ ∈ (0, π/2] (0 at π/2), from the angle the build takes Λ at.
#[inline]
fn t_of(theta: f64, width: f64) -> f64 {
    let (sin, cos) = theta.sin_cos();
    let cos = cos.max(0.0);
    cos / (cos + width * sin)
}

/// Λ(θ) of one surface by a Chebyshev table of G1 (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct LambdaTable {
    width: f64,
    g: Piecewise,
}

impl LambdaTable {
    /// The table of `lambda` (Λ(θ) for θ ∈ [0, π/2], ≥ 0, finite inside the interval) for a lobe
    /// of width `width` (a slope, > 0: the median slope serves). `None` when G1 is not smooth
    /// enough in t to tabulate to [`TABLE_TOLERANCE`] (then Λ is taken directly).
    pub fn build(lambda: impl Fn(f64) -> f64, width: f64) -> Option<LambdaTable> {
        assert!(
            width > 0.0 && width.is_finite(),
            "the lobe width is a positive slope, got {width}"
        );
        // θ in doubles resolves cot θ near grazing only to an ulp of π/2, so t is recomputed from
        // the θ Λ is taken at: g is then G1/t of one and the same direction, smooth to rounding.
        let g = |t: f64| {
            let theta = (1.0 - t).atan2(width * t);
            1.0 / ((1.0 + lambda(theta)) * t_of(theta, width))
        };
        let g = Piecewise::build(g, 0.0, 1.0, |_, _| TABLE_TOLERANCE)?;
        Some(LambdaTable { width, g })
    }

    /// Λ at μ = cos θ ∈ [0, 1]: 1/(t g(t)) − 1 with t = μ/(μ + w √((1 − μ)(1 + μ))), never
    /// below 0; exactly 0 at μ = 1 (the normal) and +∞ at μ = 0 (grazing).
    #[inline]
    pub fn lambda_at_cos(&self, mu: f64) -> f64 {
        let mu = mu.clamp(0.0, 1.0);
        let t = self.t_of_cos(mu);
        lambda_of(mu, t, self.g.eval(t))
    }

    /// `out[k]` = [`LambdaTable::lambda_at_cos`]`(mus[k])`, the same bits, in vector lanes inside
    /// [`crate::model::math::elementary::widest`] ([`Piecewise::eval_many`]); `mus` at most 64 long.
    #[inline(always)]
    pub fn lambda_at_cos_many(&self, mus: &[f64], out: &mut [f64]) {
        const MOST: usize = 64;
        assert!(
            mus.len() <= MOST && mus.len() == out.len(),
            "one output per μ, at most {MOST}"
        );
        let mut ts = [0.0; MOST];
        let ts = &mut ts[..mus.len()];
        for (t, &mu) in ts.iter_mut().zip(mus) {
            *t = self.t_of_cos(mu.clamp(0.0, 1.0));
        }
        self.g.eval_many(ts, out);
        for ((lambda, &mu), &t) in out.iter_mut().zip(mus).zip(ts.iter()) {
            *lambda = lambda_of(mu.clamp(0.0, 1.0), t, *lambda);
        }
    }

    /// t = μ/(μ + w √((1 − μ)(1 + μ))) at μ ∈ [0, 1].
    #[inline(always)]
    fn t_of_cos(&self, mu: f64) -> f64 {
        mu / (mu + self.width * ((1.0 - mu) * (1.0 + mu)).sqrt())
    }
}

/// Λ = 1/(t g) − 1, never below 0, from μ ∈ [0, 1], its t and g(t); exactly 0 at μ = 1.
#[inline(always)]
fn lambda_of(mu: f64, t: f64, g: f64) -> f64 {
    let lambda = (1.0 / (t * g) - 1.0).max(0.0);
    if mu == 1.0 { 0.0 } else { lambda }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::math::elementary::widest_many;

    /// The block path gives the bits of [`LambdaTable::lambda_at_cos`] at every μ, the ends, values
    /// just outside [0, 1] (clamped) and the last double below 1 included.
    #[test]
    fn a_block_gives_the_bits_of_single_values() {
        // Trowbridge–Reitz at α = 0.3: Λ = (√(1 + α² tan²θ) − 1)/2.
        let alpha: f64 = 0.3;
        let lambda =
            |theta: f64| (0.5 * ((1.0 + (alpha * theta.tan()).powi(2)).sqrt() - 1.0)).max(0.0);
        let table = LambdaTable::build(lambda, alpha).expect("a smooth G1");
        let mut mus: Vec<f64> = (0..60).map(|k| f64::from(k) / 59.0).collect();
        mus.extend([-0.1, 1.1, 1e-12, 1.0 - f64::EPSILON / 2.0]);
        for chunk in mus.chunks(64) {
            let many = widest_many(
                chunk,
                #[inline(always)]
                |mus, out| table.lambda_at_cos_many(mus, out),
            );
            for (&mu, &got) in chunk.iter().zip(&many) {
                assert_eq!(got.to_bits(), table.lambda_at_cos(mu).to_bits(), "μ = {mu}");
            }
        }
        assert_eq!(table.lambda_at_cos(1.0), 0.0);
        assert_eq!(table.lambda_at_cos(0.0), f64::INFINITY);
    }
}
