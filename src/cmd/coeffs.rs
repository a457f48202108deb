//! `ndfplot coeffs`: the Belcour–Bati–Barla decomposition of materials, as CSV (docs/contracts.md) or a JSON
//! array of the same rows.

use crate::error::{Error, Result};
use crate::model::curve::Curve;
use crate::model::fresnel::{Fresnel, Ior, basis};
use crate::output::report::{Cell, Report};

/// The material (complex index) behind a curve that names one: `belcour` or `exact`.
fn material(curve: &Curve) -> Option<Ior> {
    match curve {
        Curve::Fresnel(Fresnel::Belcour(ior, _) | Fresnel::Exact(ior)) => Some(*ior),
        _ => None,
    }
}

/// The report `c0,c1,c2,c3,l2` with one row per curve: the coefficients of the decomposition
/// (the notebook's `fresnel2coeffs`) and the `l2_grid` error of the reconstruction against the
/// exact Fresnel, numbers in shortest round-trip form (zeros unsigned).
pub fn report(curves: &[Curve]) -> Result<Report> {
    let mut report = Report::new(["c0", "c1", "c2", "c3", "l2"]);
    for curve in curves {
        let ior = material(curve).ok_or_else(|| {
            Error::Usage(format!(
                "--curve: fresnel: coeffs needs a material (got {}, expected a \"belcour\" or \"exact\" Fresnel curve)",
                curve.canonical_json()
            ))
        })?;
        let index = ior.index();
        let c = basis::coeffs(index);
        let l2 = c.l2_grid(index);
        // `+ 0.0` turns a −0.0 from the 2×2 solve into 0.0: the coefficient is zero, not signed.
        let coefficients = [c.c0, c.c1, c.c2, c.c3].map(|v| Cell::Number(v + 0.0));
        report.push(coefficients.into_iter().chain([Cell::Number(l2)]).collect());
    }
    Ok(report)
}
