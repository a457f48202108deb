//! From validated specs to the evaluated figure: resolve, plan, sample (with adaptive
//! refinement), the figure and its layout, provenance, progress and the integral audit.

pub mod adaptive;
pub mod audit;
pub mod batch;
pub mod figure;
pub mod layout;
pub mod plan;
pub mod progress;
pub mod provenance;
pub mod resolve;
pub mod sample;
