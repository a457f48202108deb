//! The audit of every curve in scenes (what `ndfplot check` prints). For an NDF, 2π ∫₀^{π/2} D sin θ cos θ
//! dθ with its error estimate, which must be 1 within `--tolerance`, and the consistency of its Smith Λ:
//! the weak white furnace G1(θo) A(θo)/cos θo with the front-facing projected area A computed apart from Λ
//! ([`masking::smith_furnace`]), which must be 1 within `--tolerance` at every θo of [`FURNACE_ANGLES_DEG`];
//! for a Fresnel curve, the hemispherical average 2 ∫₀¹ F(c) c dc, reported only. A view transform of an
//! NDF, or a quantity of it (G1, albedo, …), is audited through its NDF; difference series are not audited
//! (they are not distributions).
//!
//! Owns what is audited and how; the integrals are [`crate::model::metrics::projected_integral`]'s. The
//! table and the verdict (exit 1 on a failure) are the command's (`cmd::check`).

use crate::error::{Error, Result};
use crate::model::curve::Curve;
use crate::model::masking;
use crate::model::math::tolerance::QUAD_REL_TOL;
use crate::model::metrics::{Estimate, MetricError, lobe_width, maximum, projected_integral};
use crate::model::ndf::Ndf;
use crate::spec::scene::Scene;
use rayon::prelude::*;
use std::collections::HashSet;
use std::f64::consts::PI;

/// Default `--tolerance`: the NDFs are normalized analytically to ~1e-13 and the audit integrates to
/// ~1e-12 (`QUAD_REL_TOL`), so 1e-9 flags only a real normalization error.
pub const DEFAULT_TOLERANCE: f64 = 1e-9;

/// Shift added to the integrand of the audit (see [`projected_integral`]), as a fraction of the uniform
/// NDF 1/π: pieces near grazing or beyond a narrow lobe, where D is far below it, then converge at once
/// instead of chasing relative accuracy on values ~1e-300, while the audit's accuracy moves only from
/// `QUAD_REL_TOL` to `QUAD_REL_TOL` · (1 + 1e-3).
const AUDIT_SHIFT: f64 = 1e-3 / PI;

/// What an audit row measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Measure {
    /// 2π ∫ D sin θ cos θ dθ of an NDF; should be 1.
    Normalization,
    /// 2 ∫₀¹ F(c) c dc of a Fresnel curve.
    HemisphericalAverage,
    /// The weak white furnace G1(θo) A(θo)/cos θo of an NDF's Smith Λ farthest from 1 over
    /// [`FURNACE_ANGLES_DEG`]; should be 1.
    SmithConsistency,
}

impl Measure {
    /// The name shown in the table.
    pub fn name(self) -> &'static str {
        match self {
            Measure::Normalization => "normalization",
            Measure::HemisphericalAverage => "hemispherical_average",
            Measure::SmithConsistency => "smith_consistency",
        }
    }
}

/// One audited curve.
#[derive(Debug, Clone, PartialEq)]
pub struct Audit {
    /// The first scene that shows the curve.
    pub scene: String,
    /// The curve's canonical JSON.
    pub curve: String,
    /// What was integrated.
    pub quantity: Measure,
    /// The integral and its error estimate.
    pub integral: Estimate,
}

impl Audit {
    /// |integral − 1| for a normalization or a Smith consistency, `None` for a Fresnel average.
    pub fn deviation(&self) -> Option<f64> {
        (self.quantity != Measure::HemisphericalAverage).then(|| (self.integral.value - 1.0).abs())
    }
}

/// 2π ∫₀^{π/2} d(θ) sin θ cos θ dθ of an NDF-like function d, breakpoints at the width of its peak.
pub fn normalization(d: impl Fn(f64) -> f64) -> std::result::Result<Estimate, MetricError> {
    let peak = maximum(&d, lobe_width(d(0.0)))?;
    projected_integral(d, lobe_width(peak.value), AUDIT_SHIFT)
}

/// The view angles, in degrees, at which an NDF's Smith consistency is audited: the normal, every 15° and
/// the grazing angles where Λ grows fastest.
pub const FURNACE_ANGLES_DEG: [f64; 9] = [0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 85.0, 89.0, 89.9];

/// The audit quantities of a curve: an NDF's normalization and Smith consistency (also for a view or a
/// quantity of it, through the NDF behind it; the consistency not for a lobe unbounded at grazing), a
/// Fresnel curve's average; none for a difference series or a renderer's emulation.
pub fn audit(curve: &Curve) -> Vec<std::result::Result<(Measure, Estimate), MetricError>> {
    match curve {
        // A lobe unbounded at grazing keeps mass beyond what any double θ resolves: its Smith
        // consistency is not auditable by quadrature over θ, and is left out.
        Curve::Ndf(d) => {
            std::iter::once(normalization(|t| d.eval(t)).map(|e| (Measure::Normalization, e)))
                .chain(
                    (!d.unbounded_at_grazing())
                        .then(|| smith_consistency(d).map(|e| (Measure::SmithConsistency, e))),
                )
                .collect()
        }
        // 2 ∫₀¹ F(c) c dc = (1/π) · 2π ∫₀^{π/2} F sin θ cos θ dθ.
        Curve::Fresnel(f) => vec![
            projected_integral(|t| f.eval(t), lobe_width(1.0), AUDIT_SHIFT).map(|e| {
                (
                    Measure::HemisphericalAverage,
                    Estimate {
                        value: e.value / PI,
                        error: e.error / PI,
                    },
                )
            }),
        ],
        Curve::Transformed { curve, .. } => audit(curve),
        Curve::Quantity { ndf, .. } => audit(&Curve::Ndf(ndf.clone())),
        // What an engine computes is audited against the exact curve by `compare`, not for its own sake.
        Curve::Difference { .. } | Curve::Emulated(_) => vec![],
    }
}

/// The weak white furnace of `ndf`'s Smith Λ farthest from 1 over [`FURNACE_ANGLES_DEG`], with the error
/// the front-area quadrature was asked for ([`QUAD_REL_TOL`], relative).
pub fn smith_consistency(ndf: &Ndf) -> std::result::Result<Estimate, MetricError> {
    let mut worst = 1.0_f64;
    for degrees in FURNACE_ANGLES_DEG {
        let theta = degrees.to_radians();
        let value = masking::smith_furnace(ndf, theta).map_err(MetricError::Quad)?;
        if !value.is_finite() {
            return Err(MetricError::NonFinite { theta });
        }
        if (value - 1.0).abs() > (worst - 1.0).abs() {
            worst = value;
        }
    }
    Ok(Estimate {
        value: worst,
        error: QUAD_REL_TOL * worst.abs(),
    })
}

/// Audits every distinct curve of `scenes` (first appearance order), in parallel.
pub fn audit_scenes(scenes: &[Scene]) -> Result<Vec<Audit>> {
    let mut seen = HashSet::new();
    let mut curves = Vec::new();
    for scene in scenes {
        for shown in scene.panels.iter().flat_map(|p| &p.curves) {
            let json = shown.curve.canonical_json();
            if seen.insert(json.clone()) {
                curves.push((scene.id.clone(), json, &shown.curve));
            }
        }
    }
    let audits: Vec<Vec<Audit>> = curves
        .par_iter()
        .map(|(scene, json, curve)| {
            audit(curve)
                .into_iter()
                .map(|result| {
                    let (quantity, integral) =
                        result.map_err(|e| Error::Numerics(format!("{scene}: {json}: {e}")))?;
                    Ok(Audit {
                        scene: scene.clone(),
                        curve: json.clone(),
                        quantity,
                        integral,
                    })
                })
                .collect()
        })
        .collect::<Result<_>>()?;
    Ok(audits.into_iter().flatten().collect())
}
