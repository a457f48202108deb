//! ndfplot: plot and compare microfacet NDFs and Fresnel reflectance, exactly and fast.
//!
//! Data flows one way: spec sources (`source`) → validated scene descriptions (`scene`, `curve`,
//! `look`) → resolved scenes, fits, coefficients and data files computed and read (`resolve`) →
//! sampling plan (`plan`) → evaluated jobs (`sample`, `adaptive`) → the figure
//! (`figure`), placed by `layout` → bytes and files (`output`); `render` runs the whole chain.
//! The maths (`ndf`, `masking`, `fresnel`, `math`) is pure f64 code with no I/O; `albedo` integrates
//! the single-scattering microfacet BRDF into directional albedos, their averages, energy-compensation
//! factors and split-sum tables; `audit` integrates the curves of scenes for `ndfplot check`.

pub mod adaptive;
pub mod albedo;
pub mod angle;
pub mod audit;
pub mod bench;
pub mod catalogue;
pub mod check_outputs;
pub mod cli;
pub mod cmd;
pub mod curve;
pub mod datafile;
pub mod dataset;
pub mod domain;
pub mod error;
pub mod figure;
pub mod fit;
pub mod fresnel;
pub mod grid;
pub mod input;
pub mod json;
pub mod keys;
pub mod layout;
pub mod look;
pub mod masking;
pub mod math;
pub mod metrics;
pub mod ndf;
pub mod output;
pub mod plan;
pub mod problem;
pub mod progress;
pub mod provenance;
pub mod published;
pub mod quantity;
pub mod render;
pub mod resolve;
pub mod sample;
pub mod scene;
pub mod schema;
pub mod source;
pub mod stdout;
pub mod transform;
