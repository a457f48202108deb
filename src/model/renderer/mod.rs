//! What a renderer computes: the microfacet D, G1, G2 and Schlick Fresnel of seven engines (and
//! Cycles' dielectric Fresnel with its average F_avg), each as its source writes it, in its own
//! precision (docs/maths.md "Renderer emulation").
//!
//! ndfplot's families evaluate the exact functions in f64. An engine evaluates an expression of its
//! own (a vector form, a visibility term V = G2 / (4 cos θo cos θi), a spherical-Gaussian Fresnel),
//! in float32 — or in half floats on a mobile GPU's mediump path — from inputs it forms itself (a
//! float32 unit vector, a dot product), behind clamps and cut-offs (a minimum roughness, a D set to
//! 0 below a threshold). An [`Emulation`] is that computation: each engine file states its
//! recipe with the source file and line it follows, performs every operation in the engine's type
//! (Rust's `f32` and `half::f16` round after each operation, as IEEE arithmetic does), and widens
//! the result to f64. What it does not emulate: fused multiply–adds a compiler may form, and GPU
//! transcendental functions, which are taken as correctly rounded.
//!
//! The θ a curve is evaluated at becomes the engine's input as the nearest float of cos θ (and of
//! sin θ for a vector): the best input the engine could be given. A G2 from an engine that returns
//! V is converted back as G2 = 4 cos θo cos θi V with the true f64 cosines, so that the only
//! difference from the exact G2 is the engine's.
//!
//! Pure code: no I/O; names are parsed by the spec.

mod cycles;
mod filament;
mod mitsuba3;
mod pbrt_v4;
mod precision;
mod threejs;
mod unreal;

use crate::model::domain::{Bound, DomainError, Param};
use crate::model::masking::G2Model;
use crate::model::names::named;
use crate::model::ndf::Family;
use std::fmt;

named! {
    /// A renderer whose microfacet code ndfplot emulates.
    pub enum Engine {
        /// pbrt-v4 (`src/pbrt/util/scattering.h`), float32.
        PbrtV4 = "pbrt-v4",
        /// Mitsuba 3 (`include/mitsuba/render/microfacet.h`), a float32 variant.
        Mitsuba3 = "mitsuba3",
        /// Blender's Cycles (`src/kernel/closure/bsdf_microfacet.h`), float32.
        Cycles = "cycles",
        /// Filament (`shaders/src/surface_brdf.fs`) on desktop: float32.
        Filament = "filament",
        /// Filament's `TARGET_MOBILE` shaders, their mediump taken as half floats.
        FilamentMobile = "filament-mobile",
        /// Unreal Engine 4/5's default lit shading (`BRDF.ush`), float32.
        Unreal = "unreal",
        /// three.js' physical material (`bsdfs.glsl.js`, `lights_physical_*`), float32.
        Threejs = "threejs",
    }
}

impl fmt::Display for Engine {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The microfacet lobe an engine function takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Lobe {
    /// GGX (Trowbridge–Reitz).
    Ggx,
    /// Beckmann.
    Beckmann,
}

impl Lobe {
    /// The lobe of an NDF family, if engines have it.
    pub fn of(family: Family) -> Option<Lobe> {
        match family {
            Family::TrowbridgeReitz => Some(Lobe::Ggx),
            Family::Beckmann => Some(Lobe::Beckmann),
            _ => None,
        }
    }

    /// The NDF family of the lobe.
    pub fn family(self) -> Family {
        match self {
            Lobe::Ggx => Family::TrowbridgeReitz,
            Lobe::Beckmann => Family::Beckmann,
        }
    }

    fn title(self) -> &'static str {
        match self {
            Lobe::Ggx => "GGX",
            Lobe::Beckmann => "Beckmann",
        }
    }
}

/// One function of an engine's microfacet model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Function {
    /// The distribution D(θm).
    D(Lobe),
    /// The masking G1(θo).
    G1(Lobe),
    /// The masking–shadowing G2(θo, θi), from the engine's G or its V.
    G2(Lobe),
    /// Schlick's Fresnel F(θ) with a given F₀.
    Schlick,
    /// The exact Fresnel reflectance F(θ) of a dielectric of relative index η.
    Dielectric,
}

impl fmt::Display for Function {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Function::D(lobe) => write!(f, "{} D", lobe.title()),
            Function::G1(lobe) => write!(f, "{} G1", lobe.title()),
            Function::G2(lobe) => write!(f, "{} G2", lobe.title()),
            Function::Schlick => f.write_str("Schlick F"),
            Function::Dielectric => f.write_str("dielectric F"),
        }
    }
}

/// The width of the lobe as a curve gives it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Width {
    /// The family's α, which the engine takes as its own α (after its clamps).
    Alpha(f64),
    /// The artist's roughness r ∈ [0, 1], mapped by the engine's convention ([`Engine::roughness_map`]).
    Roughness(f64),
}

/// The roughness r a curve may give instead of α.
pub const ROUGHNESS: Param = Param {
    name: "roughness",
    symbol: "r",
    min: Bound::inclusive(0.0, "a roughness is not negative"),
    max: Bound::inclusive(1.0, "engines clamp or define roughness within [0, 1]"),
};

/// The α an engine curve may give: within the GGX and Beckmann domains, and where every engine's
/// float32 arithmetic stays finite (1/(π α²) and α² tan²θ at θ = fl(π/2), where tan²θ ≈ 2.7e32,
/// stay below f32's 3.4e38).
pub const ALPHA: Param = Param {
    name: "alpha",
    symbol: "α",
    min: Bound::inclusive(1e-15, "the engines' float32 D(0) = 1/(π α²) overflows"),
    max: Bound::inclusive(100.0, "α² tan²θ overflows float32 near grazing"),
};

/// Schlick's F₀ an engine curve gives.
pub const F0: Param = Param {
    name: "f0",
    symbol: "F₀",
    min: Bound::inclusive(0.0, "a reflectance is not negative"),
    max: Bound::inclusive(1.0, "a reflectance is at most 1"),
};

/// The relative index η an engine's dielectric Fresnel takes: the user's domain, up to where η² in
/// float32 stays finite (3.4e38).
pub const ETA: Param = Param {
    name: "eta",
    symbol: "η",
    min: crate::model::fresnel::ETA.min,
    max: Bound::inclusive(1e18, "η² overflows float32"),
};

/// What an emulated curve shows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Target {
    /// The NDF D(θm) of a lobe of this width.
    D(Lobe, Width),
    /// The masking G1(θo).
    G1(Lobe, Width),
    /// The masking–shadowing G2(θo, θi); `theta_i` `None` is θi = θo.
    G2 {
        /// The lobe.
        lobe: Lobe,
        /// Its width.
        width: Width,
        /// The light's angle θi, radians; `None` for θi = θo.
        theta_i: Option<f64>,
    },
    /// Schlick's Fresnel with this F₀.
    Schlick(f64),
    /// The dielectric Fresnel with this relative index η.
    Dielectric(f64),
}

impl Target {
    /// The engine function the target needs.
    pub fn function(&self) -> Function {
        match *self {
            Target::D(lobe, _) => Function::D(lobe),
            Target::G1(lobe, _) => Function::G1(lobe),
            Target::G2 { lobe, .. } => Function::G2(lobe),
            Target::Schlick(_) => Function::Schlick,
            Target::Dielectric(_) => Function::Dielectric,
        }
    }

    /// The lobe's width, for every target but the Fresnel ones.
    pub fn width(&self) -> Option<Width> {
        match *self {
            Target::D(_, width) | Target::G1(_, width) | Target::G2 { width, .. } => Some(width),
            Target::Schlick(_) | Target::Dielectric(_) => None,
        }
    }

    /// The Fresnel parameter the engine takes: F₀ for Schlick, η for the dielectric (0 for a lobe).
    fn fresnel(&self) -> f64 {
        match *self {
            Target::Schlick(value) | Target::Dielectric(value) => value,
            _ => 0.0,
        }
    }
}

/// Why an engine cannot emulate a curve.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Refusal {
    /// The engine has no such function.
    #[error("{engine} has no {wanted} (it has: {})", has(*engine))]
    Missing {
        /// The engine.
        engine: Engine,
        /// The function asked for.
        wanted: Function,
    },
    /// A value outside its domain.
    #[error("{0}")]
    Domain(DomainError),
    /// A roughness the engine does not shade with this function (a perfect mirror's).
    #[error("{0}")]
    Smooth(String),
}

fn has(engine: Engine) -> String {
    engine
        .functions()
        .iter()
        .map(Function::to_string)
        .collect::<Vec<_>>()
        .join(", ")
}

/// One engine's recipe: what it has, how it maps roughness to α, and its functions.
trait Recipe {
    /// The functions the engine has.
    const FUNCTIONS: &'static [Function];
    /// Its roughness convention, for messages and docs (`α = √r`).
    const ROUGHNESS_MAP: &'static str;
    /// Its G2 model.
    const G2: G2Model = G2Model::HeightCorrelated;
    /// The α the engine shades with for this width — rounded to its precision, after its clamps,
    /// widened exactly to f64 — or the reason it shades none.
    fn alpha(width: Width) -> Result<f64, Refusal>;
    /// `function` at θo (θi for G2), with the engine's α (from [`Recipe::alpha`]) or its Fresnel
    /// parameter `f0` (F₀ for Schlick, η for the dielectric Fresnel).
    fn eval(function: Function, alpha: f64, f0: f64, theta_o: f64, theta_i: f64) -> f64;
    /// The average F_avg = 2 ∫₀¹ F(μ) μ dμ the engine itself uses for the Fresnel `function` with
    /// parameter `f0` (a fit of its own), or `None` when it uses none.
    fn fresnel_average(_function: Function, _f0: f64) -> Option<f64> {
        None
    }
}

/// Calls `$body` with `$r` the recipe type of `$engine`.
macro_rules! with_recipe {
    ($engine:expr, $r:ident => $body:expr) => {
        match $engine {
            Engine::PbrtV4 => {
                type $r = pbrt_v4::PbrtV4;
                $body
            }
            Engine::Mitsuba3 => {
                type $r = mitsuba3::Mitsuba3;
                $body
            }
            Engine::Cycles => {
                type $r = cycles::Cycles;
                $body
            }
            Engine::Filament => {
                type $r = filament::Filament<f32>;
                $body
            }
            Engine::FilamentMobile => {
                type $r = filament::Filament<half::f16>;
                $body
            }
            Engine::Unreal => {
                type $r = unreal::Unreal;
                $body
            }
            Engine::Threejs => {
                type $r = threejs::Threejs;
                $body
            }
        }
    };
}

impl Engine {
    /// The functions the engine has, in the order messages list them.
    pub fn functions(self) -> &'static [Function] {
        with_recipe!(self, R => R::FUNCTIONS)
    }

    /// How the engine maps an artist's roughness r to α (`α = r²`).
    pub fn roughness_map(self) -> &'static str {
        with_recipe!(self, R => R::ROUGHNESS_MAP)
    }

    /// How the engine combines masking and shadowing in G2.
    pub fn g2_model(self) -> G2Model {
        with_recipe!(self, R => R::G2)
    }

    /// The α the engine shades with for `width`, widened to f64.
    pub fn alpha(self, width: Width) -> Result<f64, Refusal> {
        match width {
            Width::Alpha(alpha) => ALPHA.check(alpha).map_err(Refusal::Domain)?,
            Width::Roughness(r) => ROUGHNESS.check(r).map_err(Refusal::Domain)?,
        };
        with_recipe!(self, R => R::alpha(width))
    }
}

/// A curve as an engine computes it: validated, its α formed as the engine forms it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Emulation {
    engine: Engine,
    target: Target,
    /// The engine's α (0 for Schlick).
    alpha: f64,
}

impl Emulation {
    /// `target` as `engine` computes it; refused when the engine lacks the function or shades no
    /// such lobe, or a value lies outside its domain.
    pub fn new(engine: Engine, target: Target) -> Result<Emulation, Refusal> {
        let wanted = target.function();
        if !engine.functions().contains(&wanted) {
            return Err(Refusal::Missing { engine, wanted });
        }
        let alpha = match target {
            Target::Schlick(f0) => {
                F0.check(f0).map_err(Refusal::Domain)?;
                0.0
            }
            Target::Dielectric(eta) => {
                ETA.check(eta).map_err(Refusal::Domain)?;
                0.0
            }
            Target::G2 {
                theta_i: Some(theta_i),
                ..
            } if !(0.0..=std::f64::consts::FRAC_PI_2).contains(&theta_i) => {
                return Err(Refusal::Domain(DomainError::new(
                    "theta_i",
                    theta_i,
                    "radians in [0, π/2]",
                )));
            }
            _ => engine.alpha(
                target
                    .width()
                    .expect("only the Fresnel targets have no width"),
            )?,
        };
        Ok(Emulation {
            engine,
            target,
            alpha,
        })
    }

    /// The engine.
    pub fn engine(&self) -> Engine {
        self.engine
    }

    /// What the curve shows.
    pub fn target(&self) -> Target {
        self.target
    }

    /// The α the engine shades with, widened to f64 (0 for a Fresnel target).
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// The engine's value at θ ∈ [0, π/2] (θo for G1 and G2, the angle of incidence for Fresnel),
    /// widened to f64.
    pub fn eval(&self, theta: f64) -> f64 {
        let theta_i = match self.target {
            Target::G2 { theta_i, .. } => theta_i.unwrap_or(theta),
            _ => theta,
        };
        let f0 = self.target.fresnel();
        with_recipe!(self.engine, R => R::eval(self.target.function(), self.alpha, f0, theta, theta_i))
    }

    /// The average F_avg = 2 ∫₀¹ F(μ) μ dμ of a Fresnel target as the engine computes it when
    /// it has a formula of its own (Cycles' Kulla–Conty fit for a dielectric), widened to f64;
    /// `None` for a lobe, or when the engine would integrate its F.
    pub fn fresnel_average(&self) -> Option<f64> {
        let function = self.target.function();
        let f0 = self.target.fresnel();
        with_recipe!(self.engine, R => R::fresnel_average(function, f0))
    }
}

/// A G2 from an engine's visibility V = G2 / (4 cos θo cos θi), with the true cosines.
fn g2_from_visibility(v: f64, theta_o: f64, theta_i: f64) -> f64 {
    4.0 * theta_o.cos() * theta_i.cos() * v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_engine_refuses_what_it_lacks_by_name() {
        let err = Emulation::new(Engine::PbrtV4, Target::Schlick(0.04)).unwrap_err();
        assert_eq!(
            err.to_string(),
            "pbrt-v4 has no Schlick F (it has: GGX D, GGX G1, GGX G2)"
        );
        let beckmann = Target::D(Lobe::Beckmann, Width::Alpha(0.1));
        assert!(Emulation::new(Engine::Mitsuba3, beckmann).is_ok());
        assert!(Emulation::new(Engine::Threejs, beckmann).is_err());
    }

    #[test]
    fn names_round_trip() {
        for (name, engine) in Engine::NAMES {
            assert_eq!(Engine::from_name(name), Some(engine));
            assert!(!engine.functions().is_empty());
        }
    }
}
