//! Mitsuba 3's `MicrofacetDistribution` (mitsuba-renderer/mitsuba3 @b45b0a9,
//! `include/mitsuba/render/microfacet.h`) in a float32 variant (`scalar_rgb`, `llvm_ad_rgb`).
//!
//! - Roughness: `roughconductor` and `roughdielectric` take α itself (α = r).
//! - D (`eval`, l.185-207), from the microfacet normal m: GGX 1/(π α² ((mx/α)² + (my/α)² + mz²)²),
//!   Beckmann exp(−((mx/α)² + (my/α)²)/cos²θ)/(π α² cos⁴θ); returned as 0 unless D cos θ > 1e-20
//!   ("prevent potential numerical issues in other stages"), which zeroes a narrow Beckmann lobe far
//!   from grazing (α = 0.1 beyond ≈ 35.3°).
//! - `smith_g1` (l.341-361): t = ((α vx)² + (α vy)²)/vz²; GGX 2/(1 + √(1 + t)); Beckmann Walter's
//!   rational at a = 1/√t, 1 for a ≥ 1.6; 1 where (α vx)² + (α vy)² = 0; 0 for a back-facing v.
//! - G (l.329-331): separable, G1(ωi) G1(ωo).
//! - Its Schlick lives inside the principled BSDF (`principledhelpers.h` l.141-170), driven by η,
//!   not F₀: not emulated.

use super::precision::cos_sin;
use super::{Function, G2Model, Lobe, Recipe, Refusal, Width};

/// Mitsuba 3.
pub(super) struct Mitsuba3;

/// D is returned as 0 unless D cos θ exceeds this (l.206).
const D_COS_FLOOR: f32 = 1e-20;

/// `dr::Pi<Float>`.
const PI: f32 = std::f32::consts::PI;

fn d(lobe: Lobe, alpha: f32, theta: f64) -> f32 {
    let (z, x) = cos_sin::<f32>(theta);
    let y = 0.0_f32;
    let alpha_uv = alpha * alpha;
    let cos_theta = z;
    let cos_theta_2 = cos_theta * cos_theta;
    let result = match lobe {
        Lobe::Beckmann => {
            let s = (x / alpha) * (x / alpha) + (y / alpha) * (y / alpha);
            (-s / cos_theta_2).exp() / (PI * alpha_uv * (cos_theta_2 * cos_theta_2))
        }
        Lobe::Ggx => {
            let s = (x / alpha) * (x / alpha) + (y / alpha) * (y / alpha) + z * z;
            1.0 / (PI * alpha_uv * (s * s))
        }
    };
    if result * cos_theta > D_COS_FLOOR {
        result
    } else {
        0.0
    }
}

/// Walter's rational Beckmann G1 is 1 from this a on (l.351).
const WALTER_MAX_A: f32 = 1.6;

fn smith_g1(lobe: Lobe, alpha: f32, theta: f64) -> f32 {
    let (vz, vx) = cos_sin::<f32>(theta);
    let vy = 0.0_f32;
    let xy_alpha_2 = (alpha * vx) * (alpha * vx) + (alpha * vy) * (alpha * vy);
    let tan_theta_alpha_2 = xy_alpha_2 / (vz * vz);
    let mut result = match lobe {
        Lobe::Beckmann => {
            let a = 1.0 / tan_theta_alpha_2.sqrt();
            let a_sqr = a * a;
            if a >= WALTER_MAX_A {
                1.0
            } else {
                (3.535 * a + 2.181 * a_sqr) / (1.0 + 2.276 * a + 2.577 * a_sqr)
            }
        }
        Lobe::Ggx => 2.0 / (1.0 + (1.0 + tan_theta_alpha_2).sqrt()),
    };
    if xy_alpha_2 == 0.0 {
        result = 1.0;
    }
    // dot(v, m) cos θv with m the normal: vz².
    if vz * vz <= 0.0 {
        result = 0.0;
    }
    result
}

impl Recipe for Mitsuba3 {
    const FUNCTIONS: &'static [Function] = &[
        Function::D(Lobe::Ggx),
        Function::D(Lobe::Beckmann),
        Function::G1(Lobe::Ggx),
        Function::G1(Lobe::Beckmann),
        Function::G2(Lobe::Ggx),
        Function::G2(Lobe::Beckmann),
    ];
    const ROUGHNESS_MAP: &'static str = "α = r";
    const G2: G2Model = G2Model::Separable;

    fn alpha(width: Width) -> Result<f64, Refusal> {
        let alpha = match width {
            Width::Alpha(alpha) | Width::Roughness(alpha) => alpha as f32,
        };
        if alpha <= 0.0 {
            return Err(Refusal::Smooth(
                "mitsuba3 renders α = 0 as a smooth conductor, without a microfacet lobe".into(),
            ));
        }
        Ok(f64::from(alpha))
    }

    fn eval(function: Function, alpha: f64, _f0: f64, theta_o: f64, theta_i: f64) -> f64 {
        let alpha = alpha as f32;
        f64::from(match function {
            Function::D(lobe) => d(lobe, alpha, theta_o),
            Function::G1(lobe) => smith_g1(lobe, alpha, theta_o),
            Function::G2(lobe) => smith_g1(lobe, alpha, theta_i) * smith_g1(lobe, alpha, theta_o),
            Function::Schlick | Function::Dielectric => {
                unreachable!("mitsuba3's Fresnel is not emulated")
            }
        })
    }
}
