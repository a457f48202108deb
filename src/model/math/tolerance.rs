//! The accuracy targets of ndfplot's numerical code, in one place, each with the reason for its value,
//! and the two ways a value is measured against another ([`relative_difference`], and
//! [`floored_relative_difference`] for reference values that may underflow). Every comparison in the
//! crate, its benchmarks and its tests goes through these; nothing here does I/O.
//!
//! The NDF and special-function tests compare against 50-digit mpmath values computed from the exact
//! doubles of their inputs (`tests/data/reference/`, `tests/data/ndf_extreme.csv`,
//! `tests/data/fresnel_near_one.csv`).

/// Relative error allowed for Trowbridge–Reitz values: a rational function of sin²θ and cos²θ with no
/// exponential, so only a handful of roundings (≈ 1e-15) separate it from the exact value.
pub const REL_TOL_TROWBRIDGE_REITZ: f64 = 1e-13;

/// Relative error allowed for Phong, Beckmann, Torrance–Sparrow, ABC and SGD values: each exponentiates a
/// computed exponent E, so its error floor is |E| · ε, and |E| reaches ~1450 where D is still a normal
/// double (1450 · 2.2e-16 ≈ 3e-13, kept under this bound with margin).
pub const REL_TOL_NDF: f64 = 1e-12;

/// Relative error allowed for exact Fresnel values and the curves built on it (Schlick's F₀ from an
/// index, the normalized curve (F − F₀)/(1 − F₀) at every angle): the cancellation-free forms of `fresnel::exact` take a
/// complex square root and a few products and quotients, ~1e-15 in practice, also near η̃ = 1.
pub const REL_TOL_FRESNEL: f64 = 1e-13;

/// Below this magnitude reference values are compared absolutely: they sit near or below the smallest
/// normal double (2.2e-308) where relative precision is lost to gradual underflow.
pub const ABS_FLOOR: f64 = 1e-280;

/// |a − b| / max(|a|, |b|): symmetric, scale-free, at most 2 for finite values of opposite signs;
/// 0 when a == b (both 0 included, so two vanishing curves agree). This is `compare`'s `max_rel`
/// (docs/contracts.md) and `render --check`'s measure.
#[inline]
pub fn relative_difference(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        (a - b).abs() / a.abs().max(b.abs())
    }
}

/// [`relative_difference`] where max(|a|, |b|) > [`ABS_FLOOR`], and the absolute difference |a − b|
/// at or below it, where relative precision is lost to gradual underflow (docs/maths.md's convention for
/// reference values and measured errors).
#[inline]
pub fn floored_relative_difference(a: f64, b: f64) -> f64 {
    if a.abs().max(b.abs()) > ABS_FLOOR {
        relative_difference(a, b)
    } else {
        (a - b).abs()
    }
}

/// Allowed deviation of 2π ∫₀^{π/2} D sin θ cos θ dθ from 1: near grazing the double spacing of θ
/// (2.2e-16) limits how finely a lobe of width w is sampled to ~2.2e-16 / w relative, ≈ 2e-12 for the
/// narrowest grazing lobes accepted (w ≈ 1e-4); 1e-10 leaves room for the quadrature's own error.
pub const NORMALIZATION_TOL: f64 = 1e-10;

/// Relative accuracy asked of the adaptive quadrature when auditing normalization: two orders of magnitude
/// below [`NORMALIZATION_TOL`], still well above the ~1e-15 round-off of summing positive terms.
pub const QUAD_REL_TOL: f64 = 1e-12;

/// Relative accuracy asked of the adaptive quadrature of a curve a renderer computes: its values step
/// at float32 rounding (6e-8 relative; half floats 5e-4, where the quadrature's estimate of a step
/// function still settles within this), so no rule converges to [`QUAD_REL_TOL`] on it.
pub const QUAD_REL_TOL_EMULATED: f64 = 1e-5;

/// Relative error allowed for Smith's Λ by a closed form (Trowbridge–Reitz, Beckmann, Phong) against the
/// 40-digit references: like D, each exponentiates or subtracts a computed value, Beckmann's bracket cancels
/// by up to 2a² ≤ 128 below its asymptotic series and Λ's condition in θo reaches ~2a² ≈ 1400 in the far
/// tail, so a few 1e-14 are expected and 1e-12 holds with margin.
pub const REL_TOL_LAMBDA_CLOSED_FORM: f64 = 1e-12;

/// Relative error allowed for Smith's Λ by docs/maths.md's 1D integral (`masking::lambda_integral`, the only route
/// of Torrance–Sparrow, ABC, SGD and GTR): geometric panels of a fixed 16-point rule carry no error
/// estimate. Worst measured against the references: 2.4e-13 (SGD) for those families, 1.4e-12 for a
/// super-rough Beckmann lobe (α_b = 5 at θo = 1°) and 9e-13 against the closed forms over their whole domains;
/// the bound leaves a margin of ~7 above that, where a badly placed panel (2e-9 with a panel ratio of 4)
/// would show at once.
pub const REL_TOL_LAMBDA_INTEGRAL: f64 = 1e-11;

/// Absolute error allowed for G1 = 1/(1 + Λ) from the albedo's tabulated Λ (`masking::LambdaTable`, built to
/// `masking::table::TABLE_TOLERANCE` = 1e-12) against each family's own Λ, over every domain grid: worst measured
/// 5.6e-13 (Phong α_p = 0.001 next to the normal), 1e-13 for the other families; every G2 and so every albedo
/// moves by at most this much.
pub const LAMBDA_TABLE_TOL: f64 = 5e-12;

/// Allowed deviation from 1 of the weak white furnace G1 · A/cos θo (`masking::smith_furnace`), where Λ
/// itself is at least this large: A is an adaptive quadrature to QUAD_REL_TOL and D's normalization holds to
/// NORMALIZATION_TOL, so 1e-9 leaves room for both; below it the check cannot see Λ at all.
pub const SMITH_FURNACE_TOL: f64 = 1e-9;

/// Relative error allowed for the special functions of [`crate::model::math::special`] against mpmath: their
/// series, recurrences and continued fractions each lose a few ulps, ~1e-15 in practice.
pub const REL_TOL_SPECIAL: f64 = 1e-14;

/// The tolerance of the directional albedo (`albedo`), in units of E: its fixed rules' value is
/// taken where it is within 30 times this of the level before, and each nested adaptive integral of
/// the fallback is held to it. The Gauss–Kronrod error estimate overstates the error of smooth
/// integrands by orders of magnitude, so 1e-12 lands E, E_avg and the split-sum tables well inside
/// [`ALBEDO_TOL`], while staying above the ~1e-15 round-off floor that would stall the bisection.
pub const ALBEDO_QUAD_REL_TOL: f64 = 1e-12;

/// Absolute error allowed for directional albedos E(μ), averages E_avg and split-sum values against
/// exact or independent references: E ≤ 1, and the nested quadrature holds ~1e-12 per level, so
/// 1e-10 leaves two orders of margin for the accumulated error of three nested integrals.
pub const ALBEDO_TOL: f64 = 1e-10;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn relative_difference_is_symmetric_and_zero_when_equal() {
        assert_eq!(relative_difference(0.0, 0.0), 0.0);
        assert_eq!(relative_difference(1.0, 0.0), 1.0);
        assert_eq!(relative_difference(-1.0, 1.0), 2.0);
        assert_eq!(relative_difference(2.0, 1.0), 0.5);
        assert_eq!(relative_difference(1.0, 2.0), 0.5);
    }

    #[test]
    fn below_the_floor_the_difference_is_absolute() {
        assert_eq!(floored_relative_difference(2e-300, 1e-300), 1e-300);
        assert_eq!(floored_relative_difference(0.0, 0.0), 0.0);
        assert_eq!(floored_relative_difference(2.0, 1.0), 0.5);
        assert_eq!(floored_relative_difference(2e-280, 0.0), 1.0);
    }
}
