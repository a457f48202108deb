//! Unreal Engine 4/5's default lit specular. Its shader source (`Engine/Shaders/Private/BRDF.ush`,
//! `ShadingModels.ush`) is licence-gated; the recipe follows the forms Epic published and that
//! public copies and ports of `BRDF.ush` quote: Karis 2013, "Real Shading in Unreal Engine 4"
//! (SIGGRAPH course notes, eq. 2 for D) and Hammon 2017, "PBR Diffuse Lighting for GGX+Smith
//! Microsurfaces" (GDC, the joint-Smith approximation `Vis_SmithJointApprox`), in float32.
//!
//! - Roughness: a² = Pow4(r) = (r r)(r r), i.e. α = r²; r floored at 0.02 (`View.MinRoughness`,
//!   as the tomosud/brdf_view repository records it in its Unreal reproduction notes). A given α is
//!   floored at 0.02² and its a² is α α.
//! - D (`D_GGX(a2, NoH)`): d = (NoH a² − NoH) NoH + 1, D = a² / (π d d). At the floor a² = 1.6e-7
//!   lies a few float32 steps below 1, so the peak is set by how a² − 1 rounds.
//! - V (`Vis_SmithJointApprox(a2, NoV, NoL)`): a = √a², V = 0.5 / (NoL (NoV (1 − a) + a) + NoV (NoL (1 − a) + a)).
//! - F (`F_Schlick(SpecularColor, VoH)`): Fc = (1 − VoH)⁵ as x² x² x (`Pow5`), F = saturate(50 F₀.g) Fc + (1 − Fc) F₀:
//!   reflectances below 2 % are taken as pre-shadowed, so their grazing value drops to 50 F₀.

use super::precision::{cos_sin, floored_square};
use super::{Function, Lobe, Recipe, Refusal, Width};

/// Unreal Engine.
pub(super) struct Unreal;

/// `View.MinRoughness`.
const MIN_ROUGHNESS: f32 = 0.02;

/// `PI` of `Common.ush`.
const PI: f32 = std::f32::consts::PI;

/// Reflectances below 1/50 dim the grazing Fresnel.
const F90_SCALE: f32 = 50.0;

fn d(a2: f32, no_h: f32) -> f32 {
    let d = (no_h * a2 - no_h) * no_h + 1.0;
    a2 / (PI * d * d)
}

fn vis(a2: f32, no_v: f32, no_l: f32) -> f32 {
    let a = a2.sqrt();
    let vis_v = no_l * (no_v * (1.0 - a) + a);
    let vis_l = no_v * (no_l * (1.0 - a) + a);
    0.5 * (1.0 / (vis_v + vis_l))
}

fn schlick(f0: f32, vo_h: f32) -> f32 {
    let x = 1.0 - vo_h;
    let xx = x * x;
    let fc = xx * xx * x;
    (F90_SCALE * f0).clamp(0.0, 1.0) * fc + (1.0 - fc) * f0
}

impl Recipe for Unreal {
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
        let a2 = alpha * alpha;
        let (cos_o, _) = cos_sin::<f32>(theta_o);
        match function {
            Function::D(_) => f64::from(d(a2, cos_o)),
            Function::G2(_) => {
                let (cos_i, _) = cos_sin::<f32>(theta_i);
                super::g2_from_visibility(f64::from(vis(a2, cos_o, cos_i)), theta_o, theta_i)
            }
            Function::Schlick => f64::from(schlick(f0 as f32, cos_o)),
            Function::G1(_) => unreachable!("unreal has no G1"),
            Function::Dielectric => unreachable!("unreal has no dielectric Fresnel"),
        }
    }
}
