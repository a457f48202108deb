//! The basis training rows (F(c) − F₀)/(1 − F₀) rounded exactly as numpy float64 / complex128
//! rounds them, so that the basis reproduces the published reference (tests/data/reference,
//! generated with numpy following the notebook) to ~1e-15 instead of ~1e-11.
//!
//! Why this exists: one training row (k = 10, η ≈ −1e-5, κ ≈ 1) has 1 − F₀ = 2e-5, so each ulp of
//! F or F₀ (1.1e-16) moves that row by ~5.5e-12 and the basis b₂, b₃ by up to ~1e-11. Any correctly
//! rounded or cancellation-free evaluation (`exact`) lands a few ulps away from numpy's value at
//! ~10% of the nodes. This module is used for the training matrix only; user-facing curves keep the
//! accurate form of `exact`.
//!
//! What numpy computes (the reference's procedure, recovered bit for bit: for η̃ = η + iκ as a
//! Python complex and c a float64 array, F₀ from the same function at c = [1.0]):
//!
//! ```text
//! e2 = eta_tilde**2
//! w  = np.sqrt(e2 - (1 - c**2))
//! rs = (c - w) / (c + w)
//! rp = (e2*c - w) / (e2*c + w)
//! F  = (np.abs(rs)**2 + np.abs(rp)**2) / 2
//! ```
//!
//! and which operations it performs for that, as replicated here:
//! - η̃²: CPython's complex power with exponent 2 is one complex product (re² − im², re·im + im·re).
//! - Real ± complex: the real operand is cast to complex (imaginary part 0); products of a real
//!   with a complex are then exact-zero cross terms, so numpy's FMA-based SIMD complex multiply
//!   rounds them like the plain products e2.re·c, e2.im·c.
//! - Complex division: Smith's algorithm, as numpy's `CDOUBLE_divide` loop (no FMA).
//! - `np.sqrt` of complex128: the C library's `csqrt`; glibc's algorithm (hypot, then the larger of
//!   the two root parts by a real square root and the other one from 2 Re √z · Im √z = Im z).
//!   `f64::hypot` is the same C library `hypot` on Linux.
//! - `np.abs` of complex128: numpy's SIMD loop (`loops_unary_complex`), not `hypot`:
//!   max · √(fma(ratio, ratio, 1)), ratio = min/max of |re|, |im| (the x86-64 AVX2/AVX-512 path).
//! - `**2` on float64 is a plain square; the rest are single float64 operations in source order.

/// A complex128 as numpy stores it.
#[derive(Debug, Clone, Copy)]
struct Complex128 {
    re: f64,
    im: f64,
}

impl Complex128 {
    const fn new(re: f64, im: f64) -> Complex128 {
        Complex128 { re, im }
    }

    /// The plain complex product (CPython's `_Py_c_prod`).
    fn mul(self, other: Complex128) -> Complex128 {
        Complex128::new(
            self.re * other.re - self.im * other.im,
            self.re * other.im + self.im * other.re,
        )
    }

    /// `self * x` for a float64 `x` cast to complex: both cross terms are exact zeros.
    fn scale(self, x: f64) -> Complex128 {
        Complex128::new(self.re * x, self.im * x)
    }

    fn sub(self, other: Complex128) -> Complex128 {
        Complex128::new(self.re - other.re, self.im - other.im)
    }

    fn add(self, other: Complex128) -> Complex128 {
        Complex128::new(self.re + other.re, self.im + other.im)
    }

    /// numpy's complex division (Smith's algorithm, `CDOUBLE_divide` in umath `loops`).
    fn div(self, other: Complex128) -> Complex128 {
        let (ar, ai, br, bi) = (self.re, self.im, other.re, other.im);
        if br.abs() >= bi.abs() {
            if br == 0.0 && bi == 0.0 {
                return Complex128::new(ar / br.abs(), ai / br.abs());
            }
            let rat = bi / br;
            let scl = 1.0 / (br + bi * rat);
            Complex128::new((ar + ai * rat) * scl, (ai - ar * rat) * scl)
        } else {
            let rat = br / bi;
            let scl = 1.0 / (bi + br * rat);
            Complex128::new((ar * rat + ai) * scl, (ai * rat - ar) * scl)
        }
    }

    /// numpy's `np.abs` for complex128 (SIMD loop): max · √(fma(r, r, 1)), r = min/max.
    fn abs(self) -> f64 {
        let (re, im) = (self.re.abs(), self.im.abs());
        let larger = re.max(im);
        let smaller = re.min(im);
        if larger == 0.0 {
            return 0.0;
        }
        let ratio = smaller / larger;
        ratio.mul_add(ratio, 1.0).sqrt() * larger
    }

    /// glibc's `csqrt` (math/s_csqrt_template.c) for finite arguments of moderate size (no
    /// rescaling: |re|, |im| within [2 · f64::MIN_POSITIVE, f64::MAX/4], as in the training set).
    fn sqrt(self) -> Complex128 {
        let (re, im) = (self.re, self.im);
        if im == 0.0 {
            return if re < 0.0 {
                Complex128::new(0.0, (-re).sqrt().copysign(im))
            } else {
                Complex128::new(re.sqrt().abs(), 0.0_f64.copysign(im))
            };
        }
        if re == 0.0 {
            let r = (0.5 * im.abs()).sqrt();
            return Complex128::new(r, r.copysign(im));
        }
        let d = re.hypot(im);
        let (r, s) = if re > 0.0 {
            let r = (0.5 * (d + re)).sqrt();
            (r, 0.5 * (im / r))
        } else {
            let s = (0.5 * (d - re)).sqrt();
            ((0.5 * (im / s)).abs(), s)
        };
        Complex128::new(r, s.copysign(im))
    }
}

/// F(c) of docs/maths.md's normative form in numpy's float64 rounding (see the module documentation).
fn reflectance(c: f64, eta2: Complex128) -> f64 {
    let c_complex = Complex128::new(c, 0.0);
    let w = eta2.sub(Complex128::new(1.0 - c * c, 0.0)).sqrt();
    let r_s = c_complex.sub(w).div(c_complex.add(w));
    let eta2_c = eta2.scale(c);
    let r_p = eta2_c.sub(w).div(eta2_c.add(w));
    let (abs_s, abs_p) = (r_s.abs(), r_p.abs());
    (abs_s * abs_s + abs_p * abs_p) / 2.0
}

/// The training row (F(c_i) − F₀)/(1 − F₀), F₀ = F(1), of the material η̃ = η + iκ, rounded as
/// numpy rounds it.
pub(super) fn training_row(cos_theta: &[f64], eta: f64, kappa: f64) -> Vec<f64> {
    let eta_tilde = Complex128::new(eta, kappa);
    let eta2 = eta_tilde.mul(eta_tilde);
    let f0 = reflectance(1.0, eta2);
    cos_theta
        .iter()
        .map(|&c| (reflectance(c, eta2) - f0) / (1.0 - f0))
        .collect()
}
