//! Blender Cycles' microfacet closure (blender/cycles @97dbe6f, `src/kernel/closure/bsdf_microfacet.h`),
//! float32, isotropic path (l.743-747: D and Λ from α² = αx αy and the cosines with the normal).
//!
//! - Roughness: the Principled BSDF sets αx = αy = r² (`src/kernel/svm/closure.h` l.306-307).
//! - α: αx αy ≤ 2e-10 is "almost specular" (l.673-676): the closure has no eval, so such a curve is refused.
//! - D (`bsdf_D`, l.645-655): cos² = min(cos²θ, 1); GGX α² / (π (1 − cos² + α² cos²)²),
//!   Beckmann 1 / (exp((1 − cos²)/(cos² α²)) π α² cos⁴).
//! - Λ (`bsdf_lambda`, l.617-620, from l.599-614): t = α² max(1/cos² − 1, 0); GGX (√(1 + t) − 1)/2;
//!   Beckmann 0 for t < 0.39, else Walter's rational ((0.396a − 1.259)a + 1)/((2.181a + 3.535)a),
//!   a = 1/√t.
//! - G1 = 1/(1 + Λ) (l.631-634); the BSDF divides by 1 + Λ(θo) + Λ(θi) (l.772): G2 height-correlated.
//! - Schlick: the metallic F82-tint model `fresnel_f82` (`src/kernel/closure/bsdf_util.h` l.186-192)
//!   with a white tint (B = 0): s = saturate(1 − cos θ), F = clamp(mix(F₀, 1, s⁴ s), 0, 1); its
//!   F_avg `fresnel_f82_Fss` (l.140-143) mix(F₀, 1, 1/21) − B/126, with B = 0.
//! - Dielectric: `fresnel_dielectric_cos` (`bsdf_util.h` l.111-124): c = |cos θ|,
//!   g² = η² − 1 + c²; F = ½ A² (1 + B²) with A = (g − c)/(g + c), B = (c(g + c) − 1)/(c(g − c) + 1)
//!   where g² > 0, else 1 (total internal reflection). Its F_avg is not integrated but fitted,
//!   `fresnel_dielectric_Fss` (l.126-137, after Kulla and Conty 2017): (η − 1)/(4.08567 + 1.00071 η)
//!   for η ≥ 1, 0.997118 + η (0.1014 − η (0.965241 + 0.130607 η)) below.

use super::precision::cos_sin;
use super::{Function, Lobe, Recipe, Refusal, Width};

/// Cycles.
pub(super) struct Cycles;

/// αx αy at or below this is "almost specular" (l.675).
const ALMOST_SPECULAR: f32 = 2e-10;

/// `M_PI_F`.
const PI: f32 = std::f32::consts::PI;

/// Below this α² tan²θ the Beckmann Λ is 0 (l.605-608: a ≥ 1.6).
const BECKMANN_LAMBDA_ZERO: f32 = 0.39;

fn d(lobe: Lobe, alpha2: f32, cos_nh: f32) -> f32 {
    let cos_nh2 = (cos_nh * cos_nh).min(1.0);
    let one_minus_cos_nh2 = 1.0 - cos_nh2;
    match lobe {
        Lobe::Beckmann => {
            1.0 / ((one_minus_cos_nh2 / (cos_nh2 * alpha2)).exp()
                * PI
                * alpha2
                * (cos_nh2 * cos_nh2))
        }
        Lobe::Ggx => {
            let s = one_minus_cos_nh2 + alpha2 * cos_nh2;
            alpha2 / (PI * (s * s))
        }
    }
}

fn lambda(lobe: Lobe, alpha2: f32, cos_n: f32) -> f32 {
    let t = alpha2 * (1.0 / (cos_n * cos_n) - 1.0).max(0.0);
    match lobe {
        Lobe::Ggx => 0.5 * ((1.0 + t).sqrt() - 1.0),
        Lobe::Beckmann => {
            if t < BECKMANN_LAMBDA_ZERO {
                return 0.0;
            }
            let a = 1.0 / t.sqrt();
            ((0.396 * a - 1.259) * a + 1.0) / ((2.181 * a + 3.535) * a)
        }
    }
}

/// `fresnel_f82` with B = 0.
fn schlick(f0: f32, cos_i: f32) -> f32 {
    let s = (1.0 - cos_i).clamp(0.0, 1.0);
    let s5 = (s * s) * (s * s) * s;
    // Cycles' mix(a, b, t) = a + t (b − a) (`src/util/math_base.h` l.403-406).
    let f_schlick = f0 + s5 * (1.0 - f0);
    f_schlick.clamp(0.0, 1.0)
}

/// `fresnel_dielectric_cos`.
fn dielectric(cos_i: f32, eta: f32) -> f32 {
    let c = cos_i.abs();
    let g2 = eta * eta - 1.0 + c * c;
    if g2 <= 0.0 {
        return 1.0;
    }
    let g = g2.sqrt();
    let a = (g - c) / (g + c);
    let b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    0.5 * a * a * (1.0 + b * b)
}

/// `fresnel_dielectric_Fss`: the fitted F_avg of a dielectric.
fn dielectric_average(eta: f32) -> f32 {
    if eta < 1.0 {
        0.997118 + eta * (0.1014 - eta * (0.965241 + eta * 0.130607))
    } else {
        (eta - 1.0) / (4.08567 + 1.00071 * eta)
    }
}

impl Recipe for Cycles {
    const FUNCTIONS: &'static [Function] = &[
        Function::D(Lobe::Ggx),
        Function::D(Lobe::Beckmann),
        Function::G1(Lobe::Ggx),
        Function::G1(Lobe::Beckmann),
        Function::G2(Lobe::Ggx),
        Function::G2(Lobe::Beckmann),
        Function::Schlick,
        Function::Dielectric,
    ];
    const ROUGHNESS_MAP: &'static str = "α = r²";

    fn alpha(width: Width) -> Result<f64, Refusal> {
        let alpha = match width {
            Width::Alpha(alpha) => alpha as f32,
            Width::Roughness(r) => (r as f32) * (r as f32),
        };
        if alpha * alpha <= ALMOST_SPECULAR {
            return Err(Refusal::Smooth(format!(
                "cycles renders α² ≤ 2e-10 as a perfect mirror and never evaluates D or G for it (got α = {})",
                f64::from(alpha)
            )));
        }
        Ok(f64::from(alpha))
    }

    fn eval(function: Function, alpha: f64, f0: f64, theta_o: f64, theta_i: f64) -> f64 {
        let alpha = alpha as f32;
        let alpha2 = alpha * alpha;
        let (cos_o, _) = cos_sin::<f32>(theta_o);
        f64::from(match function {
            Function::D(lobe) => d(lobe, alpha2, cos_o),
            Function::G1(lobe) => 1.0 / (1.0 + lambda(lobe, alpha2, cos_o)),
            Function::G2(lobe) => {
                let (cos_i, _) = cos_sin::<f32>(theta_i);
                1.0 / (1.0 + lambda(lobe, alpha2, cos_o) + lambda(lobe, alpha2, cos_i))
            }
            Function::Schlick => schlick(f0 as f32, cos_o),
            Function::Dielectric => dielectric(cos_o, f0 as f32),
        })
    }

    fn fresnel_average(function: Function, f0: f64) -> Option<f64> {
        let f0 = f0 as f32;
        match function {
            // mix(F₀, 1, 1/21) − B/126 with B = 0.
            Function::Schlick => Some(f64::from(f0 + (1.0 / 21.0) * (1.0 - f0))),
            Function::Dielectric => Some(f64::from(dielectric_average(f0))),
            _ => None,
        }
    }
}
