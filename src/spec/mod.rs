//! The JSON format: the reader with positions, key checks, spec sources and the built-in
//! catalogue, curve and scene specs, the figure vocabulary and the JSON Schema. It validates; it
//! computes no curve.

pub mod angle;
pub mod catalogue;
pub mod curve;
pub mod datafile;
pub mod input;
pub mod json;
pub mod keys;
pub mod look;
pub mod lut;
pub mod lut_image;
pub mod numbers;
pub mod quantity;
pub mod scene;
pub mod schema;
pub mod source;
