//! The integration tests that run the real `ndfplot` binary or its render pipeline: the command
//! line and its contracts, the albedo tables, batch and multi-parameter fits, robustness against
//! bad input and interruption, the JSON Schema, panel views, sampling, the lazily computed Fresnel
//! basis, interactive pages in a browser, and the documentation's transcripts, examples and links.

#[path = "../common/mod.rs"]
mod common;

mod albedo;
mod browser;
mod cli;
mod compare;
mod conventions;
mod difference;
mod engine;
mod fit;
mod heatmap;
mod lazy_basis;
mod lint;
mod lut_audit;
mod man;
mod published;
mod quantity;
mod readme;
mod robustness;
mod sampling;
mod schema;
mod structure;
mod views;
