//! pbrt-v4's `TrowbridgeReitzDistribution` (mmp/pbrt-v4 @5f7a606, `src/pbrt/util/scattering.h`), with
//! `Float = float` (the default: `PBRT_FLOAT_AS_DOUBLE` is OFF, `CMakeLists.txt` l.19).
//!
//! - Roughness: `RoughnessToAlpha` is √r (l.197; l.191-195 note r² would be the perceptual choice,
//!   kept as √r so existing scenes render unchanged — pbrt-v4 issue #479).
//! - α: an isotropic lobe with α < 1e-3 is `EffectivelySmooth` (l.137) and rendered as a perfect
//!   mirror; D is never evaluated for it, so such a curve is refused. The constructor's α ≥ 1e-4
//!   (l.120-121) only bites on the other axis of an anisotropic lobe.
//! - The vector helpers of `vecmath.h` (l.1683-1714): cos²θ = z², sin²θ = max(0, 1 − cos²θ),
//!   tan²θ = sin²θ / cos²θ, cos φ = clamp(x / √(sin²θ), −1, 1) (1 when sin θ = 0), sin φ likewise from y.
//! - D (l.125-134): 0 where tan²θ is infinite or cos⁴θ < 1e-16 (θ > 89.9943°, where the exact D
//!   tends to α²/π), else 1 / (π α α cos⁴θ (1 + e)²), e = tan²θ ((cos φ/α)² + (sin φ/α)²).
//!   The 1 − cos²θ of sin²θ cancels near the normal: at α = 0.001 D is ~12 % off near its half-width.
//! - Λ (l.143-149): 0 where tan²θ is infinite, else (√(1 + α² tan²θ) − 1)/2 with
//!   α² = (cos φ α)² + (sin φ α)²; G1 = 1/(1 + Λ) (l.140); G = 1/(1 + Λ(ωo) + Λ(ωi)) (l.152).
//! - No Schlick: pbrt-v4's Fresnel is exact (`FrDielectric`, `FrComplex`).

use super::precision::cos_sin;
use super::{Function, Lobe, Recipe, Refusal, Width};

/// pbrt-v4.
pub(super) struct PbrtV4;

/// Below this α an isotropic lobe is `EffectivelySmooth` (l.137).
const SMOOTH_ALPHA: f32 = 1e-3;

/// D is 0 where cos⁴θ is below this (l.130).
const COS4_CUTOFF: f32 = 1e-16;

/// pbrt's `Pi` as a `Float`.
const PI: f32 = std::f32::consts::PI;

/// The float32 unit vector (sin θ, 0, cos θ) pbrt's helpers read.
struct Vector {
    x: f32,
    y: f32,
    z: f32,
}

impl Vector {
    fn at(theta: f64) -> Vector {
        let (z, x) = cos_sin::<f32>(theta);
        Vector { x, y: 0.0, z }
    }

    fn cos2(&self) -> f32 {
        self.z * self.z
    }

    fn sin2(&self) -> f32 {
        f32::max(0.0, 1.0 - self.cos2())
    }

    fn tan2(&self) -> f32 {
        self.sin2() / self.cos2()
    }

    /// `CosPhi` and `SinPhi`.
    fn cos_sin_phi(&self) -> (f32, f32) {
        let sin_theta = self.sin2().sqrt();
        if sin_theta == 0.0 {
            (1.0, 0.0)
        } else {
            (
                (self.x / sin_theta).clamp(-1.0, 1.0),
                (self.y / sin_theta).clamp(-1.0, 1.0),
            )
        }
    }
}

fn d(alpha: f32, w: &Vector) -> f32 {
    let tan2 = w.tan2();
    if tan2.is_infinite() {
        return 0.0;
    }
    let cos4 = w.cos2() * w.cos2();
    if cos4 < COS4_CUTOFF {
        return 0.0;
    }
    let (cos_phi, sin_phi) = w.cos_sin_phi();
    let e = tan2 * ((cos_phi / alpha) * (cos_phi / alpha) + (sin_phi / alpha) * (sin_phi / alpha));
    let one_e = 1.0 + e;
    1.0 / (PI * alpha * alpha * cos4 * (one_e * one_e))
}

fn lambda(alpha: f32, w: &Vector) -> f32 {
    let tan2 = w.tan2();
    if tan2.is_infinite() {
        return 0.0;
    }
    let (cos_phi, sin_phi) = w.cos_sin_phi();
    let alpha2 = (cos_phi * alpha) * (cos_phi * alpha) + (sin_phi * alpha) * (sin_phi * alpha);
    ((1.0 + alpha2 * tan2).sqrt() - 1.0) / 2.0
}

impl Recipe for PbrtV4 {
    const FUNCTIONS: &'static [Function] = &[
        Function::D(Lobe::Ggx),
        Function::G1(Lobe::Ggx),
        Function::G2(Lobe::Ggx),
    ];
    const ROUGHNESS_MAP: &'static str = "α = √r";

    fn alpha(width: Width) -> Result<f64, Refusal> {
        let alpha = match width {
            Width::Alpha(alpha) => alpha as f32,
            Width::Roughness(r) => (r as f32).sqrt(),
        };
        if alpha < SMOOTH_ALPHA {
            return Err(Refusal::Smooth(format!(
                "pbrt-v4 renders α < 0.001 as a perfect mirror and never evaluates D or G for it (got α = {})",
                f64::from(alpha)
            )));
        }
        Ok(f64::from(alpha))
    }

    fn eval(function: Function, alpha: f64, _f0: f64, theta_o: f64, theta_i: f64) -> f64 {
        let alpha = alpha as f32;
        let wo = Vector::at(theta_o);
        f64::from(match function {
            Function::D(_) => d(alpha, &wo),
            Function::G1(_) => 1.0 / (1.0 + lambda(alpha, &wo)),
            Function::G2(_) => {
                let wi = Vector::at(theta_i);
                1.0 / (1.0 + lambda(alpha, &wo) + lambda(alpha, &wi))
            }
            Function::Schlick | Function::Dielectric => {
                unreachable!("pbrt-v4's Fresnel is not emulated")
            }
        })
    }
}
