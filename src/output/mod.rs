//! Exporters: turn evaluated figures into bytes, and the one place that writes files.

pub mod csv;
pub mod plot;
pub mod write;
