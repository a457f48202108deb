//! The figure CSV (CONTRACTS.md): long format, one row per sampled point,
//! `panel,series,curve,x,y` (plus `z` when the figure has surface panels) with numbers in
//! shortest round-trip form.

use crate::cmd::eval::csv_field;
use crate::figure::Figure;
use std::fmt::Write;

/// The CSV bytes of a figure: header `panel,series,curve,x,y` (and `,z` when any series has z
/// values), then every point of every series, panels and series in order; `x` is θ in radians
/// for curves. Series without z leave the z field empty.
pub fn figure_csv(figure: &Figure) -> Vec<u8> {
    let points: usize = figure
        .panels
        .iter()
        .flat_map(|p| &p.series)
        .map(|s| s.points.len())
        .sum();
    let with_z = figure
        .panels
        .iter()
        .flat_map(|p| &p.series)
        .any(|s| s.z.is_some());
    let mut out = String::with_capacity(64 + points * 80);
    out.push_str(if with_z {
        "panel,series,curve,x,y,z\n"
    } else {
        "panel,series,curve,x,y\n"
    });
    for (p, panel) in figure.panels.iter().enumerate() {
        for (s, series) in panel.series.iter().enumerate() {
            let curve = csv_field(&series.curve);
            for (i, &(x, y)) in series.points.iter().enumerate() {
                write!(out, "{p},{s},{curve},{x:?},{y:?}")
                    .expect("writing to a String cannot fail");
                match series.z.as_ref().map(|z| z[i]) {
                    Some(z) => writeln!(out, ",{z:?}"),
                    None if with_z => writeln!(out, ","),
                    None => writeln!(out),
                }
                .expect("writing to a String cannot fail");
            }
        }
    }
    out.into_bytes()
}
