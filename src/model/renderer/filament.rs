//! Filament's standard lit surface (google/filament @04d50d4, `shaders/src/surface_brdf.fs`, lines
//! counted in that file) as its material compiler builds it by default: on desktop at
//! `FILAMENT_QUALITY_HIGH` in float32 (`Filament<f32>`), on mobile (`TARGET_MOBILE`) at
//! `FILAMENT_QUALITY_LOW` in half floats (`Filament<f16>`), the precision mediump may have on a
//! mobile GPU. (`CodeGenerator::generateQualityDefine` in `libs/filamat/src/shaders/CodeGenerator.cpp`
//! maps the default quality to HIGH for the desktop shader model and to LOW for the mobile one.)
//!
//! - Roughness: perceptual roughness r clamped to [MIN_PERCEPTUAL_ROUGHNESS, 1], α = r²
//!   (`shaders/src/common_material.fs` l.1-8, `perceptualRoughnessToRoughness`); the minimum is
//!   0.045 on desktop and 0.089 on mobile, "such that r⁴ > 0 in fp16". A given α is floored at the
//!   square of that minimum.
//! - D (`D_GGX`, l.54-79, at both qualities): 1 − NoH² as written on desktop, as |n × h|² on
//!   mobile (Lagrange's identity, to keep mediump accurate near the normal); a = NoH α;
//!   k = min(α / (1 − NoH² + a²), 453.5) ("prevents fp16 overflow", applied on desktop too);
//!   D = k (k (1/π)). The clamp caps the peak at 453.5²/π = 65 464 for α < 1/453.5 — at the desktop
//!   minimum α = 0.002025 the exact peak is 77 625 (−15.7 %).
//! - V, chosen by quality (l.31-39): at HIGH `V_SmithGGXCorrelated` (l.102-113): a² = α²,
//!   λV = NoL √((NoV − a² NoV) NoV + a²), λL likewise, V = 0.5 / (λV + λL); at LOW
//!   `V_SmithGGXCorrelated_Fast` (l.115-120, Hammon 2017): V = 0.5 / mix(2 NoL NoV, NoL + NoV, α),
//!   GLSL's mix(x, y, a) = x (1 − a) + y a. On mobile the divisor is floored at 7.7e-6
//!   (`PREVENT_DIV0`, `common_math.glsl`). NoV is clamped at 1e-4 (`clampNoV`,
//!   `common_material.fs` l.10-15).
//! - F (`fresnel()` in the same file): at HIGH f90 = saturate(dot(f0, vec3(50 · 0.33))) and
//!   `F_Schlick(f0, f90, VoH)` (l.145-148) = f0 + (f90 − f0) (1 − VoH)⁵ with x⁵ = x² x² x (`pow5`);
//!   for a grey f0 the dot product sums three channels: f90 = saturate(49.5 f0), 1 for every
//!   f0 ≥ 0.0202. At LOW f90 = 1 and `F_Schlick(f0, VoH)` (l.150-153): f = pow(1 − VoH, 5),
//!   F = f + f0 (1 − f), `pow` taken as correctly rounded.

use super::precision::{Real, cos_sin, floored_square};
use super::{Function, Lobe, Recipe, Refusal, Width};
use half::f16;
use std::marker::PhantomData;

/// Filament computing in `T`: f32 on desktop, f16 for mobile's mediump.
pub(super) struct Filament<T>(PhantomData<T>);

/// What differs between the desktop and mobile shaders.
pub(super) trait Target: Real {
    /// `TARGET_MOBILE`, and with it `FILAMENT_QUALITY_LOW`, the mobile default.
    const MOBILE: bool;
    /// `MIN_PERCEPTUAL_ROUGHNESS`.
    const MIN_PERCEPTUAL_ROUGHNESS: f64;
    /// The engine's name, for messages.
    const NAME: &'static str;
}

impl Target for f32 {
    const MOBILE: bool = false;
    const MIN_PERCEPTUAL_ROUGHNESS: f64 = 0.045;
    const NAME: &'static str = "filament";
}

impl Target for f16 {
    const MOBILE: bool = true;
    const MIN_PERCEPTUAL_ROUGHNESS: f64 = 0.089;
    const NAME: &'static str = "filament-mobile";
}

/// `D_GGX`'s cap on k (l.76).
const K_MAX: f64 = 453.5;
/// `MIN_N_DOT_V` (`common_material.fs` l.10).
const MIN_N_DOT_V: f64 = 1e-4;
/// `PREVENT_DIV0`'s floor of V's divisor on mobile, "nextafter(0.5 / MEDIUMP_FLT_MAX, 1.0) in fp16".
const V_DIVISOR_MIN: f64 = 0.0000077;
/// Filament's `PI`, 3.14159265359 (`common_math.glsl`), which rounds to the float32 π.
const PI: f32 = std::f32::consts::PI;

fn d<T: Target>(alpha: T, theta: f64) -> T {
    let (no_h, sin_h) = cos_sin::<T>(theta);
    let one_minus_no_h_squared = if T::MOBILE {
        // |n × h|² with n = (0, 0, 1), h = (sin θ, 0, cos θ): the cross product is (0, sin θ, 0).
        sin_h * sin_h
    } else {
        T::of(1.0) - no_h * no_h
    };
    let a = no_h * alpha;
    let k = (alpha / (one_minus_no_h_squared + a * a)).min(T::of(K_MAX));
    let inv_pi = T::of(f64::from(1.0 / PI));
    k * (k * inv_pi)
}

fn v<T: Target>(alpha: T, theta_o: f64, theta_i: f64) -> T {
    let no_v = cos_sin::<T>(theta_o).0.max(T::of(MIN_N_DOT_V));
    let no_l = cos_sin::<T>(theta_i).0;
    let divisor = if T::MOBILE {
        // V_SmithGGXCorrelated_Fast: mix(2 NoL NoV, NoL + NoV, α).
        let one = T::of(1.0);
        T::of(2.0) * no_l * no_v * (one - alpha) + (no_l + no_v) * alpha
    } else {
        let a2 = alpha * alpha;
        let lambda_v = no_l * ((no_v - a2 * no_v) * no_v + a2).sqrt();
        let lambda_l = no_v * ((no_l - a2 * no_l) * no_l + a2).sqrt();
        lambda_v + lambda_l
    };
    if T::MOBILE {
        T::of(0.5) / divisor.max(T::of(V_DIVISOR_MIN))
    } else {
        T::of(0.5) / divisor
    }
}

fn schlick<T: Target>(f0: T, theta: f64) -> T {
    let vo_h = cos_sin::<T>(theta).0;
    if T::MOBILE {
        // F_Schlick(f0, VoH): f90 = 1, f = pow(1 − VoH, 5), correctly rounded.
        let f = T::of((T::of(1.0) - vo_h).widen().powi(5));
        return f + f0 * (T::of(1.0) - f);
    }
    let per_channel = T::of(f64::from(50.0_f32 * 0.33_f32));
    // dot(vec3(f0), vec3(16.5)), summed channel by channel.
    let f90 =
        (f0 * per_channel + f0 * per_channel + f0 * per_channel).clamp(T::of(0.0), T::of(1.0));
    let x = T::of(1.0) - vo_h;
    let x2 = x * x;
    f0 + (f90 - f0) * (x2 * x2 * x)
}

impl<T: Target> Recipe for Filament<T> {
    const FUNCTIONS: &'static [Function] = &[
        Function::D(Lobe::Ggx),
        Function::G2(Lobe::Ggx),
        Function::Schlick,
    ];
    const ROUGHNESS_MAP: &'static str = "α = r²";

    fn alpha(width: Width) -> Result<f64, Refusal> {
        Ok(floored_square(width, T::of(T::MIN_PERCEPTUAL_ROUGHNESS)))
    }

    fn eval(function: Function, alpha: f64, f0: f64, theta_o: f64, theta_i: f64) -> f64 {
        let alpha = T::of(alpha);
        match function {
            Function::D(_) => d(alpha, theta_o).widen(),
            Function::G2(_) => {
                super::g2_from_visibility(v(alpha, theta_o, theta_i).widen(), theta_o, theta_i)
            }
            Function::Schlick => schlick(T::of(f0), theta_o).widen(),
            Function::G1(_) => unreachable!("{} has no G1", T::NAME),
            Function::Dielectric => unreachable!("{} has no dielectric Fresnel", T::NAME),
        }
    }
}
