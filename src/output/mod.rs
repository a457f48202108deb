//! Exporters: turn evaluated figures into bytes, and the one place that writes files.

pub mod csv;
pub mod html;
pub mod pdf;
pub mod plot;
pub mod plot3d;
pub mod write;
