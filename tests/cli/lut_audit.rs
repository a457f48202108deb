//! `ndfplot albedo --against FILE --layout …`: Cycles' `table_ggx_E` (data/published/cycles/ggx_E.csv,
//! Apache-2.0, Blender Foundation; Monte Carlo values printed to 6 decimals) audited against the exact
//! table within 2e-6, a copy perturbed at one cell found at that cell in either orientation, every
//! encoding decoded to the numbers written (each encoded here by its IEEE or unorm definition), the
//! `-o` files, `--max-error`'s exit status and bad files refused naming the file. The PNG and
//! OpenEXR files are written here by the `png` and `exr` crates' encoders from the CSV's numbers,
//! so what they hold is known independently of ndfplot's decoder.

use crate::common::{csv_records, ndfplot, scratch, text};
use std::path::Path;

/// Cycles' 32 × 32 `table_ggx_E`, rows y (μ = y/31), columns x (r = x/31).
fn cycles() -> Vec<Vec<f64>> {
    let mut table = vec![vec![f64::NAN; 32]; 32];
    for record in csv_records("data/published/cycles/ggx_E.csv") {
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
    // 1 − 0.980405 = 0.019595: the four printed digits sit on a rounding boundary.
    assert!(
        (field(&report, "max_abs") - 0.019595).abs() <= 1e-5,
        "{report}"
    );
    assert!(
        report.contains(" at mu = 0.000000, r = 0.032258 (engine 0.9804050, exact 1.0000000)"),
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

/// `table` (rows μ, columns r) as a grey PNG of `depth` bits: k = round(v (2^depth − 1)).
fn png_table(table: &[Vec<f64>], depth: png::BitDepth) -> Vec<u8> {
    let (rows, cols) = (table.len() as u32, table[0].len() as u32);
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, cols, rows);
    encoder.set_color(png::ColorType::Grayscale);
    encoder.set_depth(depth);
    let mut writer = encoder.write_header().unwrap();
    let data: Vec<u8> = table
        .concat()
        .iter()
        .flat_map(|&v| match depth {
            png::BitDepth::Sixteen => ((v * 65535.0).round() as u16).to_be_bytes().to_vec(),
            _ => vec![(v * 255.0).round() as u8],
        })
        .collect();
    writer.write_image_data(&data).unwrap();
    writer.finish().unwrap();
    out
}

/// `table` (rows μ, columns r) as a one-channel (`Y`) OpenEXR image of halves or floats.
fn exr_table(table: &[Vec<f64>], half: bool) -> Vec<u8> {
    use exr::prelude::{AnyChannel, AnyChannels, FlatSamples, Image, SmallVec, WritableImage, f16};
    let values = table.concat();
    let samples = if half {
        FlatSamples::F16(values.iter().map(|&v| f16::from_f64(v)).collect())
    } else {
        FlatSamples::F32(values.iter().map(|&v| v as f32).collect())
    };
    let channels = AnyChannels::sort(SmallVec::from_vec(vec![AnyChannel::new("Y", samples)]));
    let image = Image::from_channels((table[0].len(), table.len()), channels);
    let mut out = std::io::Cursor::new(Vec::new());
    image.write().to_buffered(&mut out).unwrap();
    out.into_inner()
}

/// Cycles' table as a 16-bit and an 8-bit PNG and as half and float OpenEXR: each audited within
/// the table's own 2e-6 plus its encoding's rounding (half a unorm step; half a half-float ulp,
/// 2⁻¹² of values below 1), its encoding read from the file.
#[test]
fn png_and_exr_tables_are_audited_within_their_quantization() {
    let dir = scratch("lut_audit_images");
    let table = cycles();
    let cases = [
        (
            "e16.png",
            png_table(&table, png::BitDepth::Sixteen),
            0.5 / 65535.0,
            "encoding=unorm16",
        ),
        (
            "e8.png",
            png_table(&table, png::BitDepth::Eight),
            0.5 / 255.0,
            "encoding=unorm8",
        ),
        (
            "half.exr",
            exr_table(&table, true),
            2f64.powi(-12),
            "encoding=f16",
        ),
        (
            "float.exr",
            exr_table(&table, false),
            2f64.powi(-25),
            "encoding=f32",
        ),
    ];
    for (name, bytes, rounding, encoding) in cases {
        // Named .bin: the kind comes from the first bytes, not the name.
        let path = dir.join(format!("{name}.bin"));
        std::fs::write(&path, bytes).unwrap();
        let (code, report, stderr) = audit(&path, "clamp=1e-4", &[]);
        assert_eq!(code, Some(0), "{name}: {stderr}");
        assert!(report.contains(encoding), "{name}: {report}");
        assert!(report.contains("cells: 32 x 32 (32 mu x 32 r)"), "{report}");
        assert!(
            field(&report, "max_abs") <= 2e-6 + rounding,
            "{name}: {report}"
        );
    }
    let mut perturbed = table.clone();
    perturbed[7][19] += 0.01;
    let at = format!("at mu = {:.6}, r = {:.6}", 7.0 / 31.0, 19.0 / 31.0);
    for (name, bytes) in [
        (
            "perturbed.png",
            png_table(&perturbed, png::BitDepth::Sixteen),
        ),
        ("perturbed.exr", exr_table(&perturbed, false)),
    ] {
        let path = dir.join(name);
        std::fs::write(&path, bytes).unwrap();
        let (_, report, stderr) = audit(&path, "clamp=1e-4", &[]);
        assert!(
            report.contains(&format!("max_abs: 1.000e-2 {at}")),
            "{name}: {stderr}{report}"
        );
    }
}

#[test]
fn bad_images_and_contradicting_layouts_exit_2_naming_them() {
    let dir = scratch("lut_audit_bad_images");
    let small = small();
    let good_png = png_table(&small, png::BitDepth::Sixteen);
    let good_exr = exr_table(&small, true);
    let mut nan = small.clone();
    nan[2][3] = f64::NAN;
    let wide: Vec<Vec<f64>> = vec![vec![0.5; 2000]; 2];
    let files: [(&str, Vec<u8>); 6] = [
        ("good.png", good_png.clone()),
        ("good.exr", good_exr.clone()),
        ("truncated.png", good_png[..good_png.len() / 2].to_vec()),
        ("truncated.exr", good_exr[..good_exr.len() / 2].to_vec()),
        ("nan.exr", exr_table(&nan, false)),
        ("wide.png", png_table(&wide, png::BitDepth::Eight)),
    ];
    for (name, bytes) in &files {
        std::fs::write(dir.join(name), bytes).unwrap();
    }
    std::fs::write(dir.join("fake.png"), "0.5,0.5\n0.5,0.5\n").unwrap();
    let cases = [
        (
            "truncated.png",
            "",
            "truncated.png: not a readable PNG image",
        ),
        (
            "truncated.exr",
            "",
            "truncated.exr: not a readable OpenEXR image",
        ),
        ("nan.exr", "", "nan.exr: cell 19 is not finite"),
        (
            "wide.png",
            "",
            "image size out of range (got 2000 x 2 pixels",
        ),
        ("fake.png", "", "not a PNG file"),
        (
            "good.png",
            "encoding=f32",
            "--layout: encoding: the image stores unorm16",
        ),
        (
            "good.exr",
            "channels=3",
            "--layout: channels: the image has 1 channels",
        ),
        (
            "good.png",
            "channel=G",
            "--layout: channel: no such channel in the image (got channel=1",
        ),
        (
            "good.exr",
            "file=csv",
            "--layout: file: the file is an OpenEXR image",
        ),
        (
            "good.exr",
            "encoding=text",
            "--layout: encoding: text in a binary file",
        ),
    ];
    for (name, layout, says) in cases {
        let (code, stdout, stderr) = audit(&dir.join(name), layout, &[]);
        assert_eq!(code, Some(2), "{name} {layout}: {stdout}");
        assert!(
            stderr.contains(says),
            "{name} {layout}: {says:?} in {stderr}"
        );
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
}

/// Adobe openpbr-bsdf's ideal-metal table as shipped (data/published/openpbr/, Apache-2.0, Adobe):
/// the header itself, `#include`d text without braces.
const OPENPBR: &str = "data/published/openpbr/openpbr_ideal_metal_energy_complement_data.h";

/// Adobe's layout: one line per r = √α = i/31 over μ = j/31, unorm16 of 1 − E, separable G2
/// (`impl/openpbr_lobe_utils.h` l.136-139, `impl/openpbr_microfacet_multiple_scattering_data.h`
/// l.52-58 at adobe/openpbr-bsdf a29da96).
const OPENPBR_LAYOUT: &str = "rows=r,cols=mu,value=1-e,encoding=unorm16,g2=separable";

/// Adobe's 32 × 32 numbers k/65535, [r index][μ index], read here from the header's text.
fn openpbr() -> Vec<Vec<f64>> {
    let text = std::fs::read_to_string(crate::common::root().join(OPENPBR)).unwrap();
    let numbers: Vec<f64> = text
        .lines()
        .filter(|l| !l.trim().starts_with("//"))
        .flat_map(|l| l.split(','))
        .map(|k| k.trim().parse::<u16>().unwrap() as f64 / 65535.0)
        .collect();
    assert_eq!(numbers.len(), 1024);
    numbers.chunks(32).map(<[f64]>::to_vec).collect()
}

/// `audit.csv`'s cells as (μ, r, engine, exact, error).
fn audit_cells(dir: &Path) -> Vec<[f64; 5]> {
    csv_records(dir.join("audit.csv").to_str().unwrap())
        .iter()
        .map(|r| {
            let n = |i: usize| r[i].parse::<f64>().unwrap();
            [n(0), n(1), n(3), n(4), n(5)]
        })
        .collect()
}

/// Adobe's table against the exact separable 1 − E. References: at α = 1 the GGX D is 1/π and
/// G1(μ) = 2μ/(1 + μ), so E(μ) = ∫ D G1(μ) G1(μi)/(4μ) dωi = G1(μ)/(4πμ) · 2π ∫₀¹ G1(t) dt
/// = 2(1 − ln 2)/(1 + μ): 1 − E(1) = ln 2, 1 − E(0⁺) = 2 ln 2 − 1; the small-α cells are float64 quadratures of the
/// exact separable E done apart from ndfplot (α = (5/31)², μ = 1: 7.04e-4; μ = 20/31:
/// 1.228e-3; α = (8/31)², μ = 1: 4.928e-3).
#[test]
fn adobe_openpbr_metal_table_is_separable_1_minus_e_low_at_small_alpha() {
    let dir = scratch("lut_audit_openpbr");
    let path = crate::common::root().join(OPENPBR);
    let table = openpbr();
    let out = dir.join("clamped");
    let (code, report, stderr) = audit(
        &path,
        &format!("{OPENPBR_LAYOUT},clamp=1e-3"),
        &["-o", out.to_str().unwrap()],
    );
    assert_eq!(code, Some(0), "{stderr}{report}");
    assert!(report.contains("cells: 32 x 32 (32 mu x 32 r)"), "{report}");
    assert!(!report.contains("note:"), "{report}");
    let cells = audit_cells(&out);
    let ln2 = std::f64::consts::LN_2;
    // File order: one line per r; the α = 1 line against 1 − 2(1 − ln 2)/(1 + μ), μ = 0 taken at
    // the clamp 1e-3, within two unorm16 steps (Monte Carlo noise).
    for (j, cell) in cells[31 * 32..].iter().enumerate() {
        let mu = (j as f64 / 31.0).max(1e-3);
        let exact = 1.0 - 2.0 * (1.0 - ln2) / (1.0 + mu);
        assert_eq!(cell[2], table[31][j]);
        assert!((cell[3] - exact).abs() <= 1e-9, "{cell:?} {exact}");
        assert!((cell[2] - exact).abs() <= 2.0 / 65535.0, "{cell:?} {exact}");
    }
    // (α = 1, μ = 1): the table's 45425/65535 = 0.693141 against ln 2 = 0.693147.
    assert_eq!(table[31][31], 45425.0 / 65535.0);
    assert!((cells[1023][3] - ln2).abs() <= 1e-12);
    // Its μ = 0 column holds E at μ ≈ 1e-3, not the limit μ → 0⁺: solving the table's
    // 1 − E = 0.386893 for μ gives 9.8e-4 (the limit would be 2 ln 2 − 1 = 0.386294).
    let mu = 2.0 * (1.0 - ln2) / (1.0 - table[31][0]) - 1.0;
    assert!((0.0009..0.0011).contains(&mu), "{mu}");
    // α ≥ 0.27 (r ≥ 17/31), μ > 0: within 1.8e-5 (1.2 unorm16 steps), 5e-6 root mean square.
    let rough: Vec<f64> = cells
        .iter()
        .filter(|c| c[1] * c[1] >= 0.27 && c[0] > 0.0)
        .map(|c| c[4])
        .collect();
    assert_eq!(rough.len(), 15 * 31);
    let rms = (rough.iter().map(|e| e * e).sum::<f64>() / rough.len() as f64).sqrt();
    assert!(rough.iter().all(|e| e.abs() <= 1.8e-5), "{rough:?}");
    assert!(rms <= 6e-6, "{rms}");
    // Small α: Monte Carlo values far below the exact ones, up to 96 % (all of it at α = (5/31)²,
    // μ = 1, where the table holds 0); the worst absolute error 1.45e-3 is still small.
    let at = |i: usize, j: usize| cells[i * 32 + j];
    for (i, j, engine, exact) in [
        (5, 31, 0.0, 7.04e-4),
        (5, 20, 3.20e-4, 1.228e-3),
        (8, 31, 0.004211, 0.004928),
    ] {
        let cell = at(i, j);
        assert!((cell[2] - engine).abs() <= 1e-6, "{cell:?}");
        assert!((cell[3] - exact).abs() <= 1e-6, "{cell:?} {exact}");
    }
    assert!(
        (0.0014..0.0015).contains(&field(&report, "max_abs")),
        "{report}"
    );
    assert!(
        report.contains("max_abs: 1.449e-3 at mu = 0.967742, r = 0.193548"),
        "{report}"
    );
    // Without the clamp the μ = 0 column is compared with the limit μ → 0⁺, and the report says
    // the engine may have tabulated it elsewhere.
    let (_, report, _) = audit(&path, OPENPBR_LAYOUT, &[]);
    assert!(
        report.contains("max_abs: 5.462e-2 at mu = 0.000000"),
        "{report}"
    );
    assert!(
        report.contains("note: the worst cell is at mu = 0"),
        "{report}"
    );
    // Height-correlated G2 at grazing is another function: with Cycles' clamp 1e-4 the α = 1,
    // μ = 0 cell differs by 0.386 = 0.386893 (Adobe) − 0.000921 (Cycles' table_ggx_E there,
    // 1 − 0.999079).
    let (_, report, _) = audit(
        &path,
        "rows=r,cols=mu,value=1-e,encoding=unorm16,g2=height-correlated,clamp=1e-4",
        &[],
    );
    let cycles_loss = 1.0 - cycles()[0][31];
    let worst = field(&report, "max_abs");
    assert!(
        report.contains("at mu = 0.000000, r = 1.000000"),
        "{report}"
    );
    assert!(
        (worst - (table[31][0] - cycles_loss)).abs() <= 1e-4,
        "{report}"
    );
}

/// The catalogue's `lut-audit-cycles` and `lut-audit-openpbr` heat maps show the numbers
/// `albedo --against` reports for the same tables: each cell's z is |engine − exact| of
/// `audit.csv`, bit for bit, and the panel title states the report's max_abs.
#[test]
fn the_catalogue_heat_maps_show_what_albedo_against_reports() {
    let dir = scratch("lut_audit_catalogue");
    let figure = dir.join("figure");
    let out = ndfplot(&[
        "render",
        "lut-audit-cycles",
        "lut-audit-openpbr",
        "-o",
        figure.to_str().unwrap(),
        "--format",
        "csv,svg",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let cycles_path = dir.join("ggx_E.csv");
    std::fs::write(&cycles_path, csv_matrix(&cycles())).unwrap();
    let openpbr_layout = format!("{OPENPBR_LAYOUT},clamp=1e-3");
    for (id, path, layout) in [
        ("lut-audit-cycles", cycles_path, "clamp=1e-4"),
        (
            "lut-audit-openpbr",
            crate::common::root().join(OPENPBR),
            openpbr_layout.as_str(),
        ),
    ] {
        let cells = dir.join(id);
        let (code, report, stderr) = audit(&path, layout, &["-o", cells.to_str().unwrap()]);
        assert_eq!(code, Some(0), "{stderr}");
        let order = |v: &mut Vec<(f64, f64, f64)>| v.sort_by(|a, b| a.partial_cmp(b).unwrap());
        let mut audited: Vec<(f64, f64, f64)> = audit_cells(&cells)
            .iter()
            .map(|c| (c[0], c[1], c[4].abs()))
            .collect();
        let mut drawn: Vec<(f64, f64, f64)> =
            csv_records(figure.join(format!("{id}.csv")).to_str().unwrap())
                .iter()
                .map(|r| {
                    let n = |i: usize| r[i].parse::<f64>().unwrap();
                    (n(3), n(4), n(5))
                })
                .collect();
        assert_eq!(drawn.len(), 1024);
        order(&mut audited);
        order(&mut drawn);
        assert_eq!(drawn, audited, "{id}");
        let max_abs = field(&report, "max_abs");
        let mantissa = format!("{max_abs:.3e}");
        let mantissa = mantissa.split('e').next().unwrap();
        let svg = std::fs::read_to_string(figure.join(format!("{id}.svg"))).unwrap();
        assert!(
            svg.contains(&format!("max |error| = {mantissa}×10")),
            "{id} {mantissa}"
        );
    }
}
