//! The integration tests of the numerical library: NDF and Fresnel values against the 50-digit
//! references of `tests/data`, their invariants over whole parameter domains, fits and metrics, and
//! the stress runs over 10⁵ parameter points per family (`cargo test --release --test numerics
//! stress -- --ignored` for the full runs).

#[path = "../common/mod.rs"]
mod common;

mod albedo;
mod fit;
mod fresnel_properties;
mod fresnel_reference;
mod masking;
mod metals;
mod ndf_properties;
mod ndf_reference;
mod stress;
