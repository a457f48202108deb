//! Piecewise Chebyshev interpolation of a smooth function on an interval, built adaptively: a
//! function that costs a quadrature per value (Smith's Λ of most families) is sampled a few hundred
//! times once and then evaluated in nanoseconds.
//!
//! On each piece [a, b] the function is interpolated at the n = [`NODES`] Chebyshev points of the
//! first kind, x_k = cos(π (k + ½)/n) mapped to [a, b] (never an end of the piece, so a function
//! singular at an end of the whole interval is never evaluated there), as p(x) = Σ_j c_j T_j(x) with
//! c_j = (2/n) Σ_k f(x_k) cos(π j (k + ½)/n) (c_0 halved), evaluated by Clenshaw's recurrence. For a
//! function analytic around the piece the coefficients decay geometrically, so the piece is accepted
//! when its last two are below the tolerance (the error of p is then about their size), or below the
//! rounding noise of the sums that give them ([`NOISE`] times the largest value), and p agrees with f
//! to that bound at the two points x = ±½ between nodes (a feature the nodes straddle would leave
//! small coefficients); otherwise it is halved.

use std::f64::consts::PI;

/// Chebyshev points per piece (the interpolant's degree plus one): fewer make more pieces, more make
/// every evaluation's Clenshaw chain longer; 12 evaluated Smith's Λ tables fastest (10 no longer
/// reached 1e-12 on noisy values, 16 was 5 % slower).
pub const NODES: usize = 12;

/// The rounding noise of a coefficient, relative to the largest value on its piece: each is a sum of
/// [`NODES`] products, so its error is a few times NODES ulps.
const NOISE: f64 = 4.0 * NODES as f64 * f64::EPSILON;

/// The deepest halving of the whole interval: pieces narrower than 2^-40 of it mean the function is
/// not smooth there, and the build gives up.
const MAX_DEPTH: u32 = 40;

/// The most pieces a build may make before it gives up (each costs [`NODES`] + 2 values).
const MAX_PIECES: usize = 256;

/// A function on [lo, hi] as Chebyshev interpolants on adjacent pieces.
#[derive(Debug, Clone, PartialEq)]
pub struct Piecewise {
    /// The left end of every piece, ascending; the first is lo.
    starts: Vec<f64>,
    /// Per piece: its centre, 2/(its width) and its [`NODES`] coefficients.
    pieces: Vec<Piece>,
}

#[derive(Debug, Clone, PartialEq)]
struct Piece {
    centre: f64,
    inverse_half_width: f64,
    coefficients: [f64; NODES],
}

impl Piecewise {
    /// The interpolant of `f` on [lo, hi] whose every piece [a, b]'s last two coefficients sum to at
    /// most `tolerance(a, b)` in magnitude, or to [`NOISE`] times the piece's largest value if that
    /// is more, and whose values at x = ±½ are within that bound of f's (an absolute error of about
    /// that size where f is analytic around the piece). `None` if a value of f is not finite, or the pieces would be more than
    /// [`MAX_PIECES`] or narrower than 2^-[`MAX_DEPTH`] of the interval (f not smooth enough).
    pub fn build(
        f: impl Fn(f64) -> f64,
        lo: f64,
        hi: f64,
        tolerance: impl Fn(f64, f64) -> f64,
    ) -> Option<Piecewise> {
        assert!(lo < hi, "an interval [{lo}, {hi}] with lo < hi");
        let mut table = Piecewise {
            starts: Vec::new(),
            pieces: Vec::new(),
        };
        // Depth-first from the left, so the pieces come out in order.
        let mut pending = vec![(lo, hi, 0u32)];
        while let Some((a, b, depth)) = pending.pop() {
            let (piece, largest) = Piece::interpolate(&f, a, b)?;
            let bound = tolerance(a, b).max(NOISE * largest);
            let tail = piece.coefficients[NODES - 2].abs() + piece.coefficients[NODES - 1].abs();
            let centre = 0.5 * (a + b);
            let checks = [centre - 0.25 * (b - a), centre + 0.25 * (b - a)];
            if tail <= bound
                && checks
                    .iter()
                    .all(|&x| (piece.eval(x) - f(x)).abs() <= bound)
            {
                table.starts.push(a);
                table.pieces.push(piece);
                if table.pieces.len() > MAX_PIECES {
                    return None;
                }
            } else if depth >= MAX_DEPTH {
                return None;
            } else {
                let mid = 0.5 * (a + b);
                pending.push((mid, b, depth + 1));
                pending.push((a, mid, depth + 1));
            }
        }
        Some(table)
    }

    /// The number of pieces.
    pub fn pieces(&self) -> usize {
        self.pieces.len()
    }

    /// The interpolant at x (clamped to the interval's pieces: the first piece's polynomial below lo,
    /// the last's above hi).
    #[inline]
    pub fn eval(&self, x: f64) -> f64 {
        // A branch-free count: the pieces are few (4–30 at ordinary parameters), and a binary
        // search's mispredicted branches cost more than comparing them all.
        let index = self
            .starts
            .iter()
            .filter(|&&start| start <= x)
            .count()
            .max(1)
            - 1;
        self.pieces[index].eval(x)
    }

    /// `out[k]` = [`Piecewise::eval`]`(xs[k])`, the same bits (the lengths must be equal), written so
    /// that it runs in vector lanes inside [`crate::model::math::elementary::widest`]: a block's
    /// pieces are counted one start at a time for all its points, then each point's coefficients
    /// are gathered into its Clenshaw recurrence.
    #[inline(always)]
    pub fn eval_many(&self, xs: &[f64], out: &mut [f64]) {
        const BLOCK: usize = 64;
        assert_eq!(xs.len(), out.len(), "one output per argument");
        let Some(last) = self.pieces.len().checked_sub(1) else {
            return;
        };
        for (xs, out) in xs.chunks(BLOCK).zip(out.chunks_mut(BLOCK)) {
            let mut counts = [0usize; BLOCK];
            let counts = &mut counts[..xs.len()];
            for &start in &self.starts {
                for (count, &x) in counts.iter_mut().zip(xs) {
                    *count += usize::from(start <= x);
                }
            }
            for ((out, &x), &count) in out.iter_mut().zip(xs).zip(counts.iter()) {
                *out = self.pieces[(count.max(1) - 1).min(last)].eval(x);
            }
        }
    }
}

impl Piece {
    /// The interpolant of f at the Chebyshev points of [a, b] and the largest |f| there; `None` if
    /// a value is not finite.
    fn interpolate(f: &impl Fn(f64) -> f64, a: f64, b: f64) -> Option<(Piece, f64)> {
        let centre = 0.5 * (a + b);
        let half_width = 0.5 * (b - a);
        let n = NODES as f64;
        let mut values = [0.0; NODES];
        for (k, value) in values.iter_mut().enumerate() {
            let x = (PI * (k as f64 + 0.5) / n).cos();
            *value = f(centre + half_width * x);
            if !value.is_finite() {
                return None;
            }
        }
        let mut coefficients = [0.0; NODES];
        for (j, c) in coefficients.iter_mut().enumerate() {
            let sum: f64 = values
                .iter()
                .enumerate()
                .map(|(k, v)| v * (PI * j as f64 * (k as f64 + 0.5) / n).cos())
                .sum();
            *c = 2.0 * sum / n;
        }
        coefficients[0] *= 0.5;
        let largest = values.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let piece = Piece {
            centre,
            inverse_half_width: 1.0 / half_width,
            coefficients,
        };
        Some((piece, largest))
    }

    /// Σ c_j T_j(y) at y = (x − centre)/(half width), by Clenshaw's recurrence.
    #[inline(always)]
    fn eval(&self, x: f64) -> f64 {
        let y = (x - self.centre) * self.inverse_half_width;
        let two_y = 2.0 * y;
        let (mut b1, mut b2) = (0.0, 0.0);
        for &c in self.coefficients[1..].iter().rev() {
            // (c − b2) is ready a step early: the chain through b1 is one product and one sum.
            let b0 = (c - b2) + two_y * b1;
            b2 = b1;
            b1 = b0;
        }
        self.coefficients[0] + y * b1 - b2
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_analytic_function_is_interpolated_to_the_tolerance() {
        // 1/(1 + 25 x²) (Runge's function) on [-1, 1]: poles at ±i/5, so several pieces are needed.
        let f = |x: f64| 1.0 / (1.0 + 25.0 * x * x);
        let table = Piecewise::build(f, -1.0, 1.0, |_, _| 1e-14).expect("smooth");
        assert!(
            table.pieces() > 2 && table.pieces() < 64,
            "{}",
            table.pieces()
        );
        for k in 0..=1000 {
            let x = -1.0 + 2.0 * k as f64 / 1000.0;
            assert!((table.eval(x) - f(x)).abs() <= 1e-13, "x = {x}");
        }
    }

    /// The block path gives the bits of the point-by-point one, in the widest instruction set and
    /// for every block length (whole and partial vectors, more than one block of 64), outside the
    /// interval and at NaN included.
    #[test]
    fn a_block_gives_the_bits_of_single_values() {
        use crate::model::math::elementary::widest_many;
        let f = |x: f64| 1.0 / (1.0 + 25.0 * x * x);
        let table = Piecewise::build(f, -1.0, 1.0, |_, _| 1e-14).expect("smooth");
        let mut xs: Vec<f64> = (0..150)
            .map(|k| -1.2 + 2.4 * f64::from(k) / 149.0)
            .collect();
        xs.extend([-1.0, 1.0, 0.0, f64::NAN]);
        for len in [1, 7, 8, 9, 48, 64, 65, xs.len()] {
            let many = widest_many(
                &xs[..len],
                #[inline(always)]
                |xs, out| table.eval_many(xs, out),
            );
            for (&x, &got) in xs.iter().zip(&many) {
                assert_eq!(
                    got.to_bits(),
                    table.eval(x).to_bits(),
                    "x = {x}, {len} long"
                );
            }
        }
    }

    #[test]
    fn a_polynomial_of_low_degree_takes_one_piece_and_its_own_values() {
        let f = |x: f64| 3.0 * x * x * x - x + 0.5;
        let table = Piecewise::build(f, 0.0, 2.0, |_, _| 1e-15).expect("smooth");
        assert_eq!(table.pieces(), 1);
        for x in [0.0, 0.3, 1.0, 1.7, 2.0] {
            assert!(
                (table.eval(x) - f(x)).abs() <= 1e-13 * f(x).abs().max(1.0),
                "x = {x}"
            );
        }
    }

    #[test]
    fn a_function_that_is_not_smooth_or_not_finite_is_refused() {
        assert!(Piecewise::build(|x: f64| x.abs().sqrt(), -1.0, 1.0, |_, _| 1e-14).is_none());
        assert!(Piecewise::build(|x: f64| 1.0 / (x - 0.3), 0.0, 1.0, |_, _| 1e-14).is_none());
    }
}
