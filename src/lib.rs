//! ndfplot: plot and compare microfacet NDFs and Fresnel reflectance, exactly and fast.
//!
//! The folders are the stages, and data flows one way through them:
//! - [`model`]: the mathematics — NDF families, masking, Fresnel, special functions and quadrature,
//!   metrics, albedo, fits, published presets, the resolved curve and its evaluation. Pure f64 code,
//!   no I/O.
//! - [`spec`]: the JSON format — the reader with positions, keys and problems, spec sources and the
//!   built-in catalogue, curve and scene specs, the figure vocabulary, the JSON Schema. No numerics.
//! - [`pipeline`]: from validated specs to the evaluated figure — resolve, plan, sample, adaptive
//!   refinement, the figure, its layout, provenance, progress and the integral audit.
//! - [`output`]: one module per format, and the one writer of files and standard output.
//! - [`cmd`]: one module per subcommand, from parsed arguments to output through the stages.
//!
//! At the top: [`problem`] and [`error`] (the diagnostics every stage reports with), [`render`]
//! (the render conductor over the stages) and [`cli`] (the command line).

pub mod cli;
pub mod cmd;
pub mod error;
pub mod model;
pub mod output;
pub mod pipeline;
pub mod problem;
pub mod render;
pub mod spec;
