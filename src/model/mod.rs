//! The mathematics: NDF families, masking, Fresnel, special functions and quadrature, metrics,
//! albedo, fits, published presets and measured metals. Pure f64 code: no I/O, no JSON, no drawing.

pub mod albedo;
pub mod curve;
pub mod dataset;
pub mod domain;
pub mod engine_table;
pub mod fit;
pub mod fresnel;
pub mod grid;
pub mod masking;
pub mod math;
pub mod metal;
pub mod metrics;
pub mod names;
pub mod ndf;
pub mod published;
pub mod renderer;
pub mod transform;
