//! The built-in figure catalogue: the `configs/*.json` specs, embedded at build time.

include!(concat!(env!("OUT_DIR"), "/catalogue.rs"));
