//! `ndfplot albedo --against FILE --layout …`: Cycles' `table_ggx_E` (tests/data/cycles_ggx_E.csv,
//! Apache-2.0, Blender Foundation; Monte Carlo values printed to 6 decimals) audited against the exact
//! table within 2e-6, a copy perturbed at one cell found at that cell in either orientation, every
//! encoding decoded to the numbers written (each encoded here by its IEEE or unorm definition), the
//! `-o` files, `--max-error`'s exit status and bad files refused naming the file.

use crate::common::{csv_records, ndfplot, scratch, text};
use std::path::Path;

/// Cycles' 32 × 32 `table_ggx_E`, rows y (μ = y/31), columns x (r = x/31).
fn cycles() -> Vec<Vec<f64>> {
    let mut table = vec![vec![f64::NAN; 32]; 32];
    for record in csv_records("tests/data/cycles_ggx_E.csv") {
        if &record[0] == "ggx_E" {
            let (y, x): (usize, usize) = (record[1].parse().unwrap(), record[2].parse().unwrap());
            table[y][x] = record[3].parse().unwrap();
        }
    }
    table
}

/// An 8 × 8 exact GGX E table as `albedo --table e --size 8` writes it, rows μ = i/7, columns
/// r = j/7: a table whose exact counterpart the audit computes in a 16th of the time of Cycles'
/// 32 × 32, for tests of how a file is read rather than of how close a table is.
fn small() -> Vec<Vec<f64>> {
    let out = ndfplot(&["albedo", "-q", "--table", "e", "--size", "8"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let e: Vec<f64> = text(&out.stdout)
        .lines()
        .filter(|l| !l.starts_with('#'))
        .skip(1)
        .map(|l| l.split(',').nth(3).unwrap().parse().unwrap())
        .collect();
    assert_eq!(e.len(), 64);
    e.chunks(8).map(<[f64]>::to_vec).collect()
}

/// The table as a CSV matrix, one line per row.
fn csv_matrix(table: &[Vec<f64>]) -> String {
    table
        .iter()
        .map(|row| row.iter().map(f64::to_string).collect::<Vec<_>>().join(",") + "\n")
        .collect()
}

/// `albedo --against PATH --layout LAYOUT ARGS`: (exit code, stdout, stderr).
fn audit(path: &Path, layout: &str, args: &[&str]) -> (Option<i32>, String, String) {
    let mut all = vec![
        "albedo",
        "-q",
        "--against",
        path.to_str().unwrap(),
        "--layout",
        layout,
    ];
    all.extend(args);
    let out = ndfplot(&all);
    (out.status.code(), text(&out.stdout), text(&out.stderr))
}

/// The number after `key: ` in the report.
fn field(report: &str, key: &str) -> f64 {
    let line = report
        .lines()
        .find_map(|l| l.strip_prefix(&format!("{key}: ")))
        .unwrap_or_else(|| panic!("no {key} in {report}"));
    line.split_whitespace().next().unwrap().parse().unwrap()
}

#[test]
fn cycles_table_is_within_2e_6_of_the_exact_one() {
    let dir = scratch("lut_audit_cycles");
    let path = dir.join("ggx_E.csv");
    std::fs::write(&path, csv_matrix(&cycles())).unwrap();
    let out = dir.join("out");
    let (code, report, stderr) = audit(
        &path,
        "clamp=1e-4",
        &["--max-error", "2e-6", "-o", out.to_str().unwrap()],
    );
    assert_eq!(code, Some(0), "{stderr}{report}");
    assert!(field(&report, "max_abs") <= 2e-6, "{report}");
    assert!(report.contains("cells: 32 x 32 (32 mu x 32 r)"), "{report}");
    let cells = std::fs::read_to_string(out.join("audit.csv")).unwrap();
    assert_eq!(cells.lines().count(), 1 + 1024);
    assert!(cells.starts_with("mu,r,alpha,engine,exact,error\n"));
    for name in ["audit.svg", "audit.png"] {
        assert!(out.join(name).is_file(), "{name}");
    }
    // Without the clamp the μ = 0 row is the limit μ → 0⁺ (E = 1), which Cycles does not store:
    // its (μ = 1e-4, α = 1/31²) value 0.980405 is 0.0196 below it.
    let (code, report, _) = audit(&path, "", &["--max-error", "2e-6"]);
    assert_eq!(code, Some(1), "{report}");
    assert!(
        report.contains("max_abs: 1.960e-2 at mu = 0.000000, r = 0.032258"),
        "{report}"
    );
}

#[test]
fn a_table_perturbed_at_one_cell_is_caught_at_that_cell() {
    let dir = scratch("lut_audit_perturbed");
    let mut table = cycles();
    table[7][19] += 0.01;
    let path = dir.join("mu_rows.csv");
    std::fs::write(&path, csv_matrix(&table)).unwrap();
    let (code, report, _) = audit(&path, "clamp=1e-4", &[]);
    assert_eq!(code, Some(0));
    let at = format!("at mu = {:.6}, r = {:.6}", 7.0 / 31.0, 19.0 / 31.0);
    assert!(
        report.contains(&format!("max_abs: 1.000e-2 {at}")),
        "{report}"
    );
    // The transposed file, one line per r, with rows=r.
    let transposed: Vec<Vec<f64>> = (0..32)
        .map(|x| (0..32).map(|y| table[y][x]).collect())
        .collect();
    let path = dir.join("r_rows.csv");
    std::fs::write(&path, csv_matrix(&transposed)).unwrap();
    let (_, report, _) = audit(&path, "rows=r,cols=mu,clamp=1e-4", &[]);
    assert!(
        report.contains(&format!("max_abs: 1.000e-2 {at}")),
        "{report}"
    );
}

/// The nearest IEEE binary16 of v ∈ [2⁻¹⁴, 1] (a normal half): v = (1 + m/1024) 2^e, m rounded
/// to nearest, ties to even; and its value.
fn half(v: f64) -> (u16, f64) {
    let e = v.log2().floor() as i32;
    let scaled = (v / 2f64.powi(e) - 1.0) * 1024.0;
    let mut m = scaled.round();
    if (scaled - scaled.floor() - 0.5).abs() < 1e-12 && m % 2.0 != 0.0 {
        m -= 1.0;
    }
    let (e, m) = if m >= 1024.0 { (e + 1, 0.0) } else { (e, m) };
    (
        (((e + 15) as u16) << 10) | m as u16,
        (1.0 + m / 1024.0) * 2f64.powi(e),
    )
}

/// (layout, file name, bytes, the values they hold, the largest rounding error).
type Case = (&'static str, &'static str, Vec<u8>, Vec<f64>, f64);

#[test]
fn every_encoding_decodes_to_the_numbers_written() {
    let dir = scratch("lut_audit_encodings");
    let table = small();
    let values: Vec<f64> = table.concat();
    let f32s: Vec<f64> = values.iter().map(|&v| f64::from(v as f32)).collect();
    let halves: Vec<(u16, f64)> = values.iter().map(|&v| half(v)).collect();
    let unorm8: Vec<u8> = values.iter().map(|&v| (v * 255.0).round() as u8).collect();
    let unorm16: Vec<u16> = values
        .iter()
        .map(|&v| (v * 65535.0).round() as u16)
        .collect();
    let cases: Vec<Case> = vec![
        (
            "encoding=f32",
            "e.bin",
            values.iter().flat_map(|&v| (v as f32).to_le_bytes()).collect(),
            f32s,
            3e-8,
        ),
        (
            "encoding=f16",
            "e.bin",
            halves.iter().flat_map(|&(h, _)| h.to_le_bytes()).collect(),
            halves.iter().map(|&(_, v)| v).collect(),
            2f64.powi(-12),
        ),
        (
            "encoding=unorm8",
            "e.bin",
            unorm8.clone(),
            unorm8.iter().map(|&k| f64::from(k) / 255.0).collect(),
            0.5 / 255.0,
        ),
        (
            "encoding=unorm16",
            "e.raw",
            unorm16.iter().flat_map(|k| k.to_le_bytes()).collect(),
            unorm16.iter().map(|&k| f64::from(k) / 65535.0).collect(),
            0.5 / 65535.0,
        ),
        (
            "encoding=unorm16",
            "e.h",
            format!(
                "/* 1 - E? no: E as unorm16 */\nstatic const unsigned short table[64] = {{\n{}\n}};\n",
                unorm16.iter().map(|k| format!("{k}u")).collect::<Vec<_>>().join(", ")
            )
            .into_bytes(),
            unorm16.iter().map(|&k| f64::from(k) / 65535.0).collect(),
            0.5 / 65535.0,
        ),
        (
            "encoding=text",
            "e.csv",
            csv_matrix(&table).into_bytes(),
            values.clone(),
            0.0,
        ),
    ];
    for (layout, name, bytes, written, rounding) in cases {
        let path = dir.join(name);
        std::fs::write(&path, bytes).unwrap();
        let out = dir.join("out");
        let _ = std::fs::remove_dir_all(&out);
        let (code, report, stderr) = audit(&path, layout, &["-o", out.to_str().unwrap()]);
        assert_eq!(code, Some(0), "{layout}: {stderr}");
        let cells = std::fs::read_to_string(out.join("audit.csv")).unwrap();
        let engine: Vec<f64> = cells
            .lines()
            .skip(1)
            .map(|l| l.split(',').nth(3).unwrap().parse().unwrap())
            .collect();
        assert_eq!(engine, written, "{layout} {name}");
        assert!(
            field(&report, "max_abs") <= 1e-6 + rounding,
            "{layout}: {report}"
        );
    }
}

#[test]
fn interleaved_channels_pick_one() {
    let dir = scratch("lut_audit_channels");
    let values: Vec<f64> = cycles().concat();
    let bytes: Vec<u8> = values
        .iter()
        .flat_map(|&v| [0.25f32, v as f32])
        .flat_map(f32::to_le_bytes)
        .collect();
    let path = dir.join("rg.bin");
    std::fs::write(&path, bytes).unwrap();
    let (code, report, stderr) = audit(&path, "channels=2,channel=1,clamp=1e-4", &[]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(field(&report, "max_abs") <= 2e-6, "{report}");
}

#[test]
fn bad_tables_and_layouts_exit_2_naming_them() {
    let dir = scratch("lut_audit_bad");
    let odd = dir.join("odd.bin");
    std::fs::write(&odd, [0u8; 4099]).unwrap();
    let square = dir.join("short.csv");
    std::fs::write(&square, "0.5,0.5,0.5\n").unwrap();
    let cases: [(&Path, &str, &str); 5] = [
        (&dir, "", "a folder"),
        (&odd, "", "multiple of 4"),
        (&square, "", "the grid does not fit"),
        (&square, "colour=red", "--layout"),
        (&square, "value=dfg1", "value"),
    ];
    for (path, layout, says) in cases {
        let (code, stdout, stderr) = audit(path, layout, &[]);
        assert_eq!(code, Some(2), "{layout}: {stdout}");
        assert!(stderr.contains(says), "{layout}: {stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
}
