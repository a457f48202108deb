//! Safeguarded one-dimensional root finding: Brent's method on a sign-changing bracket, and a log-scale
//! bracket expansion for positive parameters (such as fitting one NDF's roughness to another's peak).
//!
//! Brent's method (R. P. Brent, "Algorithms for Minimization without Derivatives", 1973, ch. 4, `zeroin`)
//! combines inverse quadratic interpolation and secant steps with bisection: it never leaves the bracket,
//! and it needs at most about (log₂((b − a)/tol))² evaluations even on adversarial functions, while
//! converging superlinearly on smooth ones. No allocation.

use std::fmt;

/// Iterations allowed: bisection alone halves any double bracket to one ulp in < 2100 steps
/// (exponent range 2 · 1023 plus 53 mantissa bits), and Brent's method bisects at least every third step.
const MAX_ITERATIONS: usize = 6400;

/// Why no root was returned.
#[derive(Debug, Clone, PartialEq)]
pub enum RootError {
    /// f(a) and f(b) have the same strict sign, so the interval is not known to hold a root.
    NotBracketed {
        /// Left end.
        a: f64,
        /// Right end.
        b: f64,
        /// f(a).
        fa: f64,
        /// f(b).
        fb: f64,
    },
    /// The function returned NaN or ±∞ at `x`.
    NonFinite {
        /// Where f was not finite.
        x: f64,
    },
    /// No bracket or root within the allowed number of steps.
    NoConvergence,
}

impl fmt::Display for RootError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RootError::NotBracketed { a, b, fa, fb } => {
                write!(f, "no sign change: f({a:e}) = {fa:e}, f({b:e}) = {fb:e}")
            }
            RootError::NonFinite { x } => write!(f, "function is not finite at x = {x:e}"),
            RootError::NoConvergence => write!(f, "root search did not converge"),
        }
    }
}

impl std::error::Error for RootError {}

fn finite(f: &impl Fn(f64) -> f64, x: f64) -> Result<f64, RootError> {
    let y = f(x);
    if y.is_finite() {
        Ok(y)
    } else {
        Err(RootError::NonFinite { x })
    }
}

/// A root of f in [a, b] (either order) to within `x_tol` + 2ε|x|, given f(a) and f(b) of opposite signs
/// (or one of them 0).
///
/// Errors with [`RootError::NotBracketed`] when there is no sign change, [`RootError::NonFinite`] when f is
/// NaN or infinite at an evaluated point.
pub fn brent(f: impl Fn(f64) -> f64, a: f64, b: f64, x_tol: f64) -> Result<f64, RootError> {
    let (mut a, mut b) = (a, b);
    let (mut fa, mut fb) = (finite(&f, a)?, finite(&f, b)?);
    if fa == 0.0 {
        return Ok(a);
    }
    if fb == 0.0 {
        return Ok(b);
    }
    if fa.signum() == fb.signum() {
        return Err(RootError::NotBracketed { a, b, fa, fb });
    }
    // c is the previous iterate with f(c) of the sign opposite to f(b); [b, c] always brackets the root.
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for _ in 0..MAX_ITERATIONS {
        if fb.signum() == fc.signum() {
            (c, fc) = (a, fa);
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            (a, fa) = (b, fb);
            (b, fb) = (c, fc);
            (c, fc) = (a, fa);
        }
        let tol = 2.0 * f64::EPSILON * b.abs() + 0.5 * x_tol;
        let m = 0.5 * (c - b);
        if m.abs() <= tol || fb == 0.0 {
            return Ok(b);
        }
        if e.abs() >= tol && fa.abs() > fb.abs() {
            // Interpolate: secant when only two distinct points, inverse quadratic otherwise.
            let s = fb / fa;
            let (mut p, mut q) = if a == c {
                (2.0 * m * s, 1.0 - s)
            } else {
                let q = fa / fc;
                let r = fb / fc;
                (
                    s * (2.0 * m * q * (q - r) - (b - a) * (r - 1.0)),
                    (q - 1.0) * (r - 1.0) * (s - 1.0),
                )
            };
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            // Accept the step only if it falls well inside the bracket and shrinks faster than bisection.
            if 2.0 * p < (3.0 * m * q - (tol * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        (a, fa) = (b, fb);
        b += if d.abs() > tol { d } else { tol.copysign(m) };
        fb = finite(&f, b)?;
    }
    Err(RootError::NoConvergence)
}

/// A bracket [lo, hi] ⊂ (0, ∞) with f(lo) and f(hi) of opposite signs (or one of them 0), found by
/// stepping geometrically outwards from x0 > 0: lo = x0 / factorⁿ, hi = x0 · factorⁿ, n = 1, 2, … up to
/// `max_steps` (factor > 1).
///
/// Meant for positive scale parameters, whose natural spacing is logarithmic. Errors with
/// [`RootError::NoConvergence`] if no sign change appears, [`RootError::NonFinite`] if f is not finite at a
/// visited point.
pub fn expand_bracket_log(
    f: impl Fn(f64) -> f64,
    x0: f64,
    factor: f64,
    max_steps: usize,
) -> Result<(f64, f64), RootError> {
    debug_assert!(
        x0 > 0.0 && factor > 1.0,
        "expand_bracket_log needs x0 > 0 and factor > 1"
    );
    let f0 = finite(&f, x0)?;
    if f0 == 0.0 {
        return Ok((x0, x0));
    }
    let (mut lo, mut hi) = (x0, x0);
    for _ in 0..max_steps {
        let (next_lo, next_hi) = (lo / factor, hi * factor);
        if finite(&f, next_lo)?.signum() != f0.signum() {
            return Ok((next_lo, lo));
        }
        if finite(&f, next_hi)?.signum() != f0.signum() {
            return Ok((hi, next_hi));
        }
        (lo, hi) = (next_lo, next_hi);
    }
    Err(RootError::NoConvergence)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Tolerance asked of `brent` in these tests: a few ulps of the O(1) roots.
    const X_TOL: f64 = 1e-15;

    #[test]
    fn finds_a_simple_root() {
        let r = brent(|x| x * x - 2.0, 0.0, 2.0, X_TOL).unwrap();
        assert!((r - std::f64::consts::SQRT_2).abs() <= 4.0 * f64::EPSILON);
    }

    #[test]
    fn accepts_the_bracket_in_either_order() {
        let r = brent(f64::cos, 3.0, 1.0, X_TOL).unwrap();
        assert!((r - std::f64::consts::FRAC_PI_2).abs() <= 4.0 * f64::EPSILON);
    }

    #[test]
    fn survives_a_flat_then_steep_function() {
        // x^9 is flat near its root at 0, where interpolation steps are poor; the safeguard still converges.
        let calls = std::cell::Cell::new(0);
        let flat = |x: f64| {
            calls.set(calls.get() + 1);
            (x - 0.1).powi(9)
        };
        let r = brent(flat, -1.0, 3.0, 1e-12).unwrap();
        assert!((r - 0.1).abs() <= 1e-12, "got {r}");
        assert!(calls.get() < 200, "{} evaluations", calls.get());
    }

    #[test]
    fn returns_an_endpoint_root_immediately() {
        assert_eq!(brent(|x| x - 1.0, 1.0, 5.0, X_TOL), Ok(1.0));
    }

    #[test]
    fn rejects_an_interval_without_a_sign_change() {
        assert!(matches!(
            brent(|x| x * x + 1.0, -1.0, 1.0, X_TOL),
            Err(RootError::NotBracketed { .. })
        ));
    }

    #[test]
    fn reports_a_non_finite_function() {
        assert!(matches!(
            brent(|x: f64| x.ln(), -1.0, 2.0, X_TOL),
            Err(RootError::NonFinite { .. })
        ));
    }

    #[test]
    fn discontinuous_sign_change_is_located() {
        let r = brent(|x: f64| if x < 0.3 { -1.0 } else { 1.0 }, 0.0, 1.0, 1e-12).unwrap();
        assert!((r - 0.3).abs() <= 1e-12);
    }

    #[test]
    fn expands_a_log_bracket_both_ways() {
        let (lo, hi) = expand_bracket_log(|x: f64| x.ln() - 1e3_f64.ln(), 1.0, 2.0, 60).unwrap();
        assert!(lo < 1e3 && 1e3 < hi && hi / lo <= 2.0 + 1e-15);
        let (lo, hi) = expand_bracket_log(|x: f64| 1e-7 - x, 1.0, 10.0, 60).unwrap();
        assert!(lo <= 1e-7 && 1e-7 <= hi);
        let root = brent(|x: f64| 1e-7 - x, lo, hi, 1e-22).unwrap();
        assert!((root / 1e-7 - 1.0).abs() <= 1e-14);
    }

    #[test]
    fn log_bracket_gives_up_without_a_sign_change() {
        assert_eq!(
            expand_bracket_log(|x: f64| x + 1.0, 1.0, 2.0, 10),
            Err(RootError::NoConvergence)
        );
    }
}
