//! The engines' number types: float32 (`f32`) and the half floats a mobile GPU may use for mediump
//! (`half::f16`), behind one trait so that a shader's recipe is written once for both.
//!
//! Each operation rounds to the type, as IEEE arithmetic does. `half::f16` computes in f32 and
//! rounds back; for +, −, ×, ÷ and √ that double rounding is exact (f32's 24 bits are at least
//! 2 × 11 + 2, Figueroa 1995), so every operation is correctly rounded to half precision.

use super::Width;
use half::f16;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A floating-point type an engine computes in.
pub(super) trait Real:
    Copy
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The value nearest to `x` (a literal of the engine's source, or an input).
    fn of(x: f64) -> Self;
    /// The value, exactly, as f64.
    fn widen(self) -> f64;
    /// √x, correctly rounded.
    fn sqrt(self) -> Self;
    /// The smaller of two values.
    fn min(self, other: Self) -> Self {
        if other < self { other } else { self }
    }
    /// The larger of two values.
    fn max(self, other: Self) -> Self {
        if other > self { other } else { self }
    }
    /// `self` clamped into [lo, hi], GLSL's `clamp`.
    fn clamp(self, lo: Self, hi: Self) -> Self {
        self.max(lo).min(hi)
    }
}

/// α as an engine that maps α = r² forms it in `T`: the roughness r clamped to [`r_min`, 1] and
/// squared, or an α given directly clamped to [`r_min`², 1] — the floors of Filament, Unreal and
/// three.js.
pub(super) fn floored_square<T: Real>(width: Width, r_min: T) -> f64 {
    let one = T::of(1.0);
    let alpha = match width {
        Width::Alpha(alpha) => T::of(alpha).clamp(r_min * r_min, one),
        Width::Roughness(r) => {
            let r = T::of(r).clamp(r_min, one);
            r * r
        }
    };
    alpha.widen()
}

impl Real for f32 {
    fn of(x: f64) -> f32 {
        x as f32
    }
    fn widen(self) -> f64 {
        f64::from(self)
    }
    fn sqrt(self) -> f32 {
        f32::sqrt(self)
    }
}

impl Real for f16 {
    fn of(x: f64) -> f16 {
        f16::from_f64(x)
    }
    fn widen(self) -> f64 {
        self.to_f64()
    }
    fn sqrt(self) -> f16 {
        f16::from_f32(self.to_f32().sqrt())
    }
}

/// cos θ and sin θ of θ ∈ [0, π/2], each the nearest value of type `T`: the components of the unit
/// vector (sin θ, 0, cos θ) as the engine holds it, or a dot product it is given.
pub(super) fn cos_sin<T: Real>(theta: f64) -> (T, T) {
    (T::of(theta.cos()), T::of(theta.sin()))
}
