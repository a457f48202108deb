//! three.js' physical material (mrdoob/three.js, `src/renderers/shaders/ShaderChunk/`), float32
//! (WebGL highp).
//!
//! - Roughness: `material.roughness = max(roughnessFactor, 0.0525)` ("the base mip of a 256
//!   cubemap"), plus the screen-space geometry roughness (0 on a flat surface), then min(·, 1)
//!   (`lights_physical_fragment.glsl.js`); α = r² (`alpha = pow2(roughness)`, "UE4's roughness"). A
//!   given α is clamped to [0.0525², 1].
//! - D (`D_GGX(alpha, dotNH)`): a² = α², denom = NoH² (a² − 1) + 1, D = (1/π) a² / denom².
//! - V (`V_GGX_SmithCorrelated(alpha, dotNL, dotNV)`): gv = NoL √(a² + (1 − a²) NoV²), gl likewise,
//!   V = 0.5 / max(gv + gl, EPSILON = 1e-6).
//! - F (`F_Schlick(f0, f90, dotVH)` in `bsdfs.glsl.js`): the spherical-Gaussian form of Karis 2013,
//!   w = exp2((−5.55473 VoH − 6.98316) VoH), F = f0 (1 − w) + f90 w with f90 = 1 (the default
//!   `specularIntensity`). It runs up to 6.9 % above the (1 − VoH)⁵ form at F₀ = 0.04, VoH = 0.633.

use super::precision::{cos_sin, floored_square};
use super::{Function, Lobe, Recipe, Refusal, Width};

/// three.js.
pub(super) struct Threejs;

/// The roughness floor of `lights_physical_fragment.glsl.js`.
const MIN_ROUGHNESS: f32 = 0.0525;

/// `RECIPROCAL_PI` of `common.glsl.js`, 0.3183098861837907, which rounds to the float32 1/π.
const RECIPROCAL_PI: f32 = std::f32::consts::FRAC_1_PI;

/// `EPSILON` of `common.glsl.js`.
const EPSILON: f32 = 1e-6;

/// The spherical-Gaussian exponent's coefficients (Karis 2013, from Unreal's 2013 notes).
const SG_A: f32 = -5.55473;
const SG_B: f32 = 6.98316;

fn d(alpha: f32, no_h: f32) -> f32 {
    let a2 = alpha * alpha;
    let denom = no_h * no_h * (a2 - 1.0) + 1.0;
    RECIPROCAL_PI * a2 / (denom * denom)
}

fn v(alpha: f32, no_l: f32, no_v: f32) -> f32 {
    let a2 = alpha * alpha;
    let gv = no_l * (a2 + (1.0 - a2) * (no_v * no_v)).sqrt();
    let gl = no_v * (a2 + (1.0 - a2) * (no_l * no_l)).sqrt();
    0.5 / (gv + gl).max(EPSILON)
}

fn schlick(f0: f32, vo_h: f32) -> f32 {
    let fresnel = ((SG_A * vo_h - SG_B) * vo_h).exp2();
    let f90 = 1.0;
    f0 * (1.0 - fresnel) + (f90 * fresnel)
}

impl Recipe for Threejs {
    const FUNCTIONS: &'static [Function] = &[
        Function::D(Lobe::Ggx),
        Function::G2(Lobe::Ggx),
        Function::Schlick,
    ];
    const ROUGHNESS_MAP: &'static str = "α = r²";

    fn alpha(width: Width) -> Result<f64, Refusal> {
        Ok(floored_square(width, MIN_ROUGHNESS))
    }

    fn eval(function: Function, alpha: f64, f0: f64, theta_o: f64, theta_i: f64) -> f64 {
        let alpha = alpha as f32;
        let (cos_o, _) = cos_sin::<f32>(theta_o);
        match function {
            Function::D(_) => f64::from(d(alpha, cos_o)),
            Function::G2(_) => {
                let (cos_i, _) = cos_sin::<f32>(theta_i);
                super::g2_from_visibility(f64::from(v(alpha, cos_i, cos_o)), theta_o, theta_i)
            }
            Function::Schlick => f64::from(schlick(f0 as f32, cos_o)),
            Function::G1(_) => unreachable!("threejs has no G1"),
            Function::Dielectric => unreachable!("threejs has no dielectric Fresnel"),
        }
    }
}
