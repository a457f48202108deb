//! Special functions, quadrature, root finding and SVDs: pure f64 code, no I/O.
//!
//! - [`elementary`]: branch-free exp, log1p and sin/cos within 1 ulp, the same bits one at a time or in
//!   vector lanes, and the loop that runs them in the widest instruction set the processor has.
//! - [`special`]: exprel, the φ_k functions of exponential integrators and the scaled upper incomplete
//!   gamma function e^x Γ(s, x) for every real s, which no available crate computes for s ≤ 0.
//! - [`chebyshev`]: piecewise Chebyshev interpolants built adaptively, to tabulate a costly smooth function.
//! - [`quad`]: adaptive Gauss–Kronrod (7, 15) quadrature that resolves narrow lobes.
//! - [`gauss_legendre`]: the fixed 16-point Gauss–Legendre rule, for integrals split into panels in advance.
//! - [`roots`]: Brent's safeguarded bracketing root finder and a log-scale bracket expansion.
//! - [`simplex`]: Nelder–Mead minimization within a box, for fits of several parameters.
//! - `svd`: singular values by one-sided Jacobi rotations, accurate across many decades, and the
//!   leading right singular vectors of large matrices by subspace iteration (compiled for the
//!   tests, which recompute the stored Fresnel basis and spectrum with it).
//! - [`tolerance`]: every accuracy target of the crate's numerical tests, with its reason.

pub mod chebyshev;
pub mod elementary;
pub mod gauss_legendre;
pub mod quad;
pub mod roots;
pub mod simplex;
pub mod special;
#[cfg(test)]
pub mod svd;
pub mod tolerance;
