//! `ndfplot check`: the audit table of [`crate::pipeline::audit`] on stdout and its verdict (exit 1 when an NDF's
//! normalization or Smith consistency is off by more than `--tolerance`).

use crate::error::{Error, Result};
use crate::output::report::{Cell, Report};
use crate::pipeline::audit::Audit;

/// The columns of the table and of `--format json|csv`.
const COLUMNS: [&str; 7] = [
    "status",
    "quantity",
    "integral",
    "error_estimate",
    "deviation",
    "scene",
    "curve",
];

/// An audit's status: `ok`, `FAIL` (off by more than `tolerance`), or `-` for a Fresnel average.
fn status(audit: &Audit, tolerance: f64) -> &'static str {
    match audit.deviation() {
        Some(d) if d > tolerance => "FAIL",
        Some(_) => "ok",
        None => "-",
    }
}

/// The table: a header, then per curve its status (`ok`, `FAIL`, or `-` for a Fresnel average), the
/// quantity, the integral, its error estimate, |integral − 1|, the scene and the curve.
pub fn table(audits: &[Audit], tolerance: f64) -> String {
    let [
        status_name,
        quantity,
        integral,
        error,
        deviation,
        scene,
        curve,
    ] = COLUMNS;
    let mut out = format!(
        "{status_name:<7}{quantity:<23}{integral:<21}{error:<25}{deviation:<25}{scene:<22}{curve}\n"
    );
    for a in audits {
        let status = status(a, tolerance);
        let deviation = a
            .deviation()
            .map_or_else(|| "-".to_string(), |d| format!("{d:?}"));
        out.push_str(&format!(
            "{status:<7}{:<23}{:<21}{:<25}{:<25}{:<22}{}\n",
            a.quantity.name(),
            format!("{:?}", a.integral.value),
            format!("{:?}", a.integral.error),
            deviation,
            a.scene,
            a.curve
        ));
    }
    out
}

/// The rows of the table for `--format json|csv`, one per curve: the table's columns, numbers in
/// round-trip form, `deviation` missing (JSON `null`, empty CSV field) for a Fresnel average and
/// `curve` as JSON.
pub fn report(audits: &[Audit], tolerance: f64) -> Report {
    let mut report = Report::new(COLUMNS);
    for a in audits {
        report.push(vec![
            Cell::Text(status(a, tolerance).into()),
            Cell::Text(a.quantity.name().into()),
            Cell::Number(a.integral.value),
            Cell::Number(a.integral.error),
            a.deviation().map_or(Cell::Missing, Cell::Number),
            Cell::Text(a.scene.clone()),
            Cell::Json(a.curve.clone()),
        ]);
    }
    report
}

/// `Err(CheckFailed)` (exit 1) when an NDF's normalization or Smith consistency is off by more than
/// `tolerance` from 1.
pub fn verdict(audits: &[Audit], tolerance: f64) -> Result<()> {
    let checked = audits.iter().filter(|a| a.deviation().is_some()).count();
    let failed = audits
        .iter()
        .filter(|a| a.deviation().is_some_and(|d| d > tolerance))
        .count();
    if failed == 0 {
        Ok(())
    } else {
        Err(Error::CheckFailed(format!(
            "check: {failed} of {checked} NDF audits (normalization, Smith consistency) are off by more than --tolerance {tolerance:?} from 1"
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ndf::{Distribution, Phong};
    use crate::pipeline::audit::{DEFAULT_TOLERANCE, Measure, normalization};

    #[test]
    fn an_unnormalized_lobe_fails_the_check_with_exit_1() {
        let phong = Phong::new(20.0).unwrap();
        let good = normalization(|t| phong.eval(t)).unwrap();
        let bad = normalization(|t| 1.001 * phong.eval(t)).unwrap();
        let row = |integral| Audit {
            scene: "s".into(),
            curve: "c".into(),
            quantity: Measure::Normalization,
            integral,
        };
        let audits = [row(good), row(bad)];
        assert!(
            (good.value - 1.0).abs() < 1e-12 && good.error < 1e-11,
            "{good:?}"
        );
        assert!((bad.value - 1.001).abs() < 1e-12, "{bad:?}");
        let err = verdict(&audits, DEFAULT_TOLERANCE).unwrap_err();
        assert_eq!(err.exit_code(), 1);
        assert!(err.to_string().contains("1 of 2 NDF audits"), "{err}");
        let text = table(&audits, DEFAULT_TOLERANCE);
        assert!(
            text.lines().nth(1).unwrap().starts_with("ok ")
                && text.lines().nth(2).unwrap().starts_with("FAIL"),
            "{text}"
        );
    }
}
