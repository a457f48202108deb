//! The figure CSV (CONTRACTS.md): long format, one row per sampled point,
//! `panel,series,curve,x,y` with numbers in shortest round-trip form.

use crate::cmd::eval::csv_field;
use crate::series::Figure;
use std::fmt::Write;

/// The CSV bytes of a figure: header `panel,series,curve,x,y`, then every point of every series,
/// panels and series in order; `x` is θ in radians.
pub fn figure_csv(figure: &Figure) -> Vec<u8> {
    let points: usize = figure.panels.iter().flat_map(|p| &p.series).map(|s| s.points.len()).sum();
    let mut out = String::with_capacity(64 + points * 80);
    out.push_str("panel,series,curve,x,y\n");
    for (p, panel) in figure.panels.iter().enumerate() {
        for (s, series) in panel.series.iter().enumerate() {
            let curve = csv_field(&series.curve);
            for &(x, y) in series.points.iter() {
                writeln!(out, "{p},{s},{curve},{x:?},{y:?}").expect("writing to a String cannot fail");
            }
        }
    }
    out.into_bytes()
}
