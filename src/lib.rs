//! ndfplot: plot and compare microfacet NDFs and Fresnel reflectance, exactly and fast.
//!
//! Data flows one way: curve/scene JSON → validated model → sampling plan → evaluated series → output.
//! The maths (`ndf`, `fresnel`, `math`) is pure f64 code with no I/O.

pub mod domain;
pub mod fresnel;
pub mod math;
pub mod ndf;
pub mod output;
