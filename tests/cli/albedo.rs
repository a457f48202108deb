//! `ndfplot albedo`: its tables equal `eval`'s albedo quantity cell by cell, the average table
//! Cycles' `table_ggx_Eavg` and the research notes' values, the roughness maps and the Fresnel
//! factor do what they say, the metadata names the table, and bad arguments exit 2 with one error
//! line naming the argument. Grids are small: every cell is a nested adaptive integral.

use crate::common::{ndfplot, root, scratch, text};

/// A table as printed: the `# key: value` metadata, the column names and the rows of numbers
/// (`NaN` for an empty field or a table name).
struct Printed {
    metadata: Vec<(String, String)>,
    columns: Vec<String>,
    rows: Vec<Vec<f64>>,
}

impl Printed {
    fn column(&self, name: &str) -> usize {
        self.columns
            .iter()
            .position(|c| c == name)
            .unwrap_or_else(|| panic!("no column {name} in {:?}", self.columns))
    }

    fn meta(&self, key: &str) -> &str {
        self.metadata
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
            .unwrap_or_else(|| panic!("no metadata {key} in {:?}", self.metadata))
    }
}

/// Runs `ndfplot albedo -q ARGS` (CSV), which must succeed with nothing on stderr.
fn albedo(args: &[&str]) -> Printed {
    let mut all = vec!["albedo", "-q"];
    all.extend(args);
    let out = ndfplot(&all);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(out.stderr.is_empty(), "{}", text(&out.stderr));
    parse(&text(&out.stdout))
}

fn parse(csv: &str) -> Printed {
    let mut lines = csv.lines();
    let mut metadata = Vec::new();
    let header = loop {
        let line = lines.next().expect("a header after the metadata");
        match line.strip_prefix("# ") {
            Some(meta) => {
                let (key, value) = meta.split_once(": ").expect("# key: value");
                metadata.push((key.to_string(), value.to_string()));
            }
            None => break line,
        }
    };
    let columns = header.split(',').map(String::from).collect();
    let rows = lines
        .map(|line| {
            line.split(',')
                .map(|f| match f {
                    // An empty cell, or a table's name in the table column.
                    "" | "e" | "average" | "dfg" | "split-sum" => f64::NAN,
                    _ => f.parse().unwrap(),
                })
                .collect()
        })
        .collect();
    Printed {
        metadata,
        columns,
        rows,
    }
}

/// `eval` of `curves` at every θ of `thetas`: one row per θ, one value per curve.
fn eval(curves: &[String], thetas: &[f64]) -> Vec<Vec<f64>> {
    let list: Vec<String> = thetas.iter().map(|t| format!("{t:?}")).collect();
    let list = list.join(",");
    let mut args = vec!["eval"];
    for curve in curves {
        args.extend(["--curve", curve.as_str()]);
    }
    args.extend(["--theta", list.as_str()]);
    let out = ndfplot(&args);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    text(&out.stdout)
        .lines()
        .skip(1)
        .map(|line| {
            line.split(',')
                .skip(1)
                .map(|f| f.parse().unwrap())
                .collect()
        })
        .collect()
}

/// Every E-like cell (column `value`) of a long-format table equals `eval` of the albedo quantity
/// of GGX at its α (`extra` adds keys to the curve: a G2 model, a Fresnel factor) at θ = acos μ,
/// to 1e-12; the r = 0 column is `mirror(θ)`.
fn assert_matches_eval(table: &Printed, value: &str, extra: &str, mirror: impl Fn(f64) -> f64) {
    let (mu, r, alpha, e) = (
        table.column("mu"),
        table.column("r"),
        table.column("alpha"),
        table.column(value),
    );
    let mut alphas: Vec<f64> = table.rows.iter().map(|row| row[alpha]).collect();
    alphas.sort_by(f64::total_cmp);
    alphas.dedup();
    alphas.retain(|&a| a > 0.0);
    let mut thetas: Vec<f64> = table.rows.iter().map(|row| row[mu].acos()).collect();
    thetas.sort_by(f64::total_cmp);
    thetas.dedup();
    let curves: Vec<String> = alphas
        .iter()
        .map(|a| format!(r#"{{"ndf":"ggx","alpha_tr":{a:?},"quantity":"albedo"{extra}}}"#))
        .collect();
    let values = eval(&curves, &thetas);
    for row in &table.rows {
        let theta = row[mu].acos();
        let expected = if row[r] == 0.0 {
            mirror(theta)
        } else {
            let i = thetas.iter().position(|&t| t == theta).unwrap();
            let j = alphas.iter().position(|&a| a == row[alpha]).unwrap();
            values[i][j]
        };
        assert!(
            (row[e] - expected).abs() <= 1e-12,
            "mu = {}, r = {}: {} vs eval {expected}",
            row[mu],
            row[r],
            row[e]
        );
    }
}

#[test]
fn the_e_table_is_evals_albedo_at_every_cell_with_turquins_factor() {
    let table = albedo(&["--size", "4"]);
    assert_eq!(table.columns, ["mu", "r", "alpha", "E", "turquin_f0_1"]);
    assert_eq!(table.rows.len(), 16);
    assert_matches_eval(&table, "E", "", |_| 1.0);
    let (mu, r, alpha, e, factor) = (0, 1, 2, 3, 4);
    for (k, row) in table.rows.iter().enumerate() {
        // Rows by μ, then r, on i/3 and j/3; α = r².
        assert_eq!(row[mu], (k / 4) as f64 / 3.0);
        assert_eq!(row[r], (k % 4) as f64 / 3.0);
        assert_eq!(row[alpha], row[r] * row[r]);
        assert!((row[factor] * row[e] - 1.0).abs() <= 1e-14, "{row:?}");
    }
    let last = table.rows.last().unwrap();
    assert_eq!((last[mu], last[r]), (1.0, 1.0));
    assert!((last[e] - (1.0 - 2f64.ln())).abs() <= 1e-10, "{}", last[e]);

    let separable = albedo(&["--size", "3", "--g2", "separable"]);
    assert_eq!(separable.meta("g2"), "separable");
    assert_matches_eval(&separable, "E", r#","g2":"separable""#, |_| 1.0);
}

#[test]
fn the_average_table_is_cycles_and_the_research_values() {
    let table = albedo(&["--table", "average", "--size", "5"]);
    assert_eq!(table.columns, ["r", "alpha", "E_avg", "kulla_conty_norm"]);
    // r = 0, 1/4, 1/2, 3/4, 1: α = 0, 0.0625, 0.25, 0.5625, 1.
    let e_avg: Vec<f64> = table.rows.iter().map(|row| row[2]).collect();
    let research = [0.987250, 0.882323, 0.656201];
    for (value, expected) in e_avg[1..4].iter().zip(research) {
        assert!((value - expected).abs() <= 1e-6, "{value} vs {expected}");
    }
    // Cycles' table_ggx_Eavg at x = 0 (r clamped to 1e-4) and x = 31 (r = 1).
    let cycles = std::fs::read_to_string(root().join("data/published/cycles/ggx_E.csv")).unwrap();
    let entry = |x: &str| -> f64 {
        let line = cycles
            .lines()
            .find(|l| l.starts_with(&format!("ggx_Eavg,,{x},")))
            .unwrap();
        line.rsplit(',').next().unwrap().parse().unwrap()
    };
    assert!((e_avg[0] - entry("0")).abs() <= 2e-6);
    assert!((e_avg[4] - entry("31")).abs() <= 2e-6, "{}", e_avg[4]);
    // Kulla–Conty's normalisation: undefined for the mirror, 1/(π(1 − E_avg)) elsewhere.
    assert!(table.rows[0][3].is_nan());
    for row in &table.rows[1..] {
        let expected = 1.0 / (std::f64::consts::PI * (1.0 - row[2]));
        assert!((row[3] - expected).abs() <= 1e-12 * expected, "{row:?}");
    }
}

#[test]
fn the_roughness_map_decides_alpha() {
    let squared = albedo(&["--size", "3"]);
    let linear = albedo(&["--map", "r", "--mu-count", "3", "--r-count", "5"]);
    assert_eq!(linear.meta("map"), "alpha = r");
    assert_eq!(squared.meta("map"), "alpha = r^2");
    assert_eq!(
        linear.meta("ndf"),
        r#"{"ndf":"trowbridge_reitz","alpha_tr":"r"}"#
    );
    for row in &linear.rows {
        assert_eq!(row[2], row[1]);
    }
    // α = 0.25 is r = 1/4 under `r` and r = 1/2 under `r2`: the same values.
    let at = |table: &Printed, r: f64| -> Vec<f64> {
        table
            .rows
            .iter()
            .filter(|row| row[1] == r)
            .map(|row| row[3])
            .collect()
    };
    assert_eq!(at(&linear, 0.25), at(&squared, 0.5));
    assert_ne!(at(&linear, 0.5), at(&squared, 0.5));
}

#[test]
fn a_fresnel_factor_turns_e_into_e_f_as_eval_computes_it() {
    let fresnel = r#"{"fresnel":"exact","eta":1.5}"#;
    let table = albedo(&["--size", "3", "--fresnel", fresnel]);
    assert_eq!(table.columns, ["mu", "r", "alpha", "E_F"]);
    assert_eq!(
        table.meta("fresnel"),
        r#"{"fresnel":"exact","eta":1.5,"kappa":0.0}"#
    );
    let f = |theta: f64| eval(&[fresnel.to_string()], &[theta])[0][0];
    assert_matches_eval(&table, "E_F", &format!(r#","fresnel":{fresnel}"#), f);

    let schlick = r#"{"fresnel":"schlick","f0":0.04}"#;
    let average = albedo(&["--table", "average", "--size", "2", "--fresnel", schlick]);
    assert_eq!(
        average.columns,
        ["r", "alpha", "E_avg", "kulla_conty_norm", "F_avg", "F_ms"]
    );
    let plain = albedo(&["--table", "average", "--size", "2"]);
    for (row, plain) in average.rows.iter().zip(&plain.rows) {
        assert_eq!(row[2], plain[2], "E_avg is the F = 1 average");
        assert!((row[4] - (0.04 + 0.96 / 21.0)).abs() <= 1e-14, "{row:?}");
        let f_ms = row[4] * row[4] * row[2] / (1.0 - row[4] * (1.0 - row[2]));
        assert!((row[5] - f_ms).abs() <= 1e-15, "{row:?}");
    }
}

#[test]
fn a_tabulated_fresnel_factor_turns_e_into_e_f_as_eval_computes_it() {
    // A Belcour–Bati–Barla reconstruction, linear between 1000 nodes in cos θd: the tables take it
    // through its smooth surrogate as eval does (the interpolant's kinks alone do not converge),
    // and F_avg is the interpolant's average 2 ∫ F(μ) μ dμ, here by Simpson's rule on each cell
    // between the nodes μ = j/999 (exact for F μ, a quadratic there).
    let fresnel = r#"{"fresnel":"belcour","eta":1.5}"#;
    let table = albedo(&["--size", "3", "--fresnel", fresnel]);
    let f = |theta: f64| eval(&[fresnel.to_string()], &[theta])[0][0];
    assert_matches_eval(&table, "E_F", &format!(r#","fresnel":{fresnel}"#), f);
    let average = albedo(&["--table", "average", "--size", "2", "--fresnel", fresnel]);
    let n = 2 * 999;
    let mus: Vec<f64> = (0..=n).map(|i| i as f64 / n as f64).collect();
    let thetas: Vec<f64> = mus.iter().map(|mu| mu.acos()).collect();
    let values = eval(&[fresnel.to_string()], &thetas);
    let g = |i: usize| values[i][0] * mus[i];
    let simpson: f64 = (0..999)
        .map(|j| (g(2 * j) + 4.0 * g(2 * j + 1) + g(2 * j + 2)) / (3.0 * n as f64))
        .sum();
    for row in &average.rows {
        assert!(
            (row[4] - 2.0 * simpson).abs() <= 1e-13,
            "{row:?} vs {}",
            2.0 * simpson
        );
    }
}

#[test]
fn the_split_sum_tables_start_with_e_and_their_mirror_column_is_the_basis() {
    let table = albedo(&["--table", "split-sum", "--mu-count", "3", "--r-count", "2"]);
    assert_eq!(
        table.columns,
        ["mu", "r", "alpha", "E_0", "E_1", "E_2", "E_3"]
    );
    assert_eq!(table.meta("table"), "split-sum");
    assert!(table.meta("accuracy").contains("1e-10"));
    let plain = albedo(&["--mu-count", "3", "--r-count", "2"]);
    let basis: Vec<String> = (0..4)
        .map(|k| format!(r#"{{"fresnel":"basis","index":{k}}}"#))
        .collect();
    for (row, plain) in table.rows.iter().zip(&plain.rows) {
        assert!((row[3] - plain[3]).abs() <= 1e-10, "{row:?} vs {plain:?}");
        if row[1] == 0.0 {
            let b = &eval(&basis, &[row[0].acos()])[0];
            for k in 0..4 {
                assert!((row[3 + k] - b[k]).abs() <= 1e-12, "{row:?} vs {b:?}");
            }
        }
    }
}

#[test]
fn metadata_names_the_table_in_csv_and_json_alike() {
    let args = ["albedo", "--size", "2"];
    let csv = albedo(&args[1..]);
    for key in [
        "table", "quantity", "ndf", "g2", "map", "fresnel", "mu_count", "r_count", "grid",
        "limits", "accuracy",
    ] {
        assert!(!csv.meta(key).is_empty(), "{key}");
    }
    assert_eq!(csv.meta("fresnel"), "none (F = 1)");
    assert_eq!(csv.meta("mu_count"), "2");
    let out = ndfplot(&["albedo", "-q", "--size", "2", "--format", "json"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["ndf"]["alpha_tr"], "r^2");
    assert_eq!(json["fresnel"], serde_json::Value::Null);
    assert_eq!(json["mu_count"], 2);
    assert_eq!(json["columns"][3], "E");
    let rows: Vec<Vec<f64>> = serde_json::from_value(json["rows"].clone()).unwrap();
    assert_eq!(rows, csv.rows);
}

#[test]
fn bad_arguments_exit_2_with_one_line_naming_them() {
    let cases: &[(&[&str], &str)] = &[
        (
            &["--ndf", "ggxx"],
            r#"error: --ndf: ggxx: unknown ndf family (got "ggxx""#,
        ),
        (
            &["--ndf", "gtr"],
            "error: --fix: gamma_gtr: missing (got no --fix gamma_gtr=…",
        ),
        (
            &["--fix", "alpha_tr=0.5"],
            "error: --fix: alpha_tr: the roughness r maps to it",
        ),
        (
            &["--ndf", "gtr", "--fix", "gamma_gtr=0"],
            "error: --fix: gamma_gtr: out of domain (got 0.0, expected",
        ),
        (
            &["--size", "1025"],
            "error: --size: points per axis out of range (got 1025, expected 2 to 1024)",
        ),
        (
            &["--mu-count", "1024", "--r-count", "512"],
            "error: --mu-count, --r-count: too many cells (got 1024 x 512 = 524288, expected at most 262144)",
        ),
        (
            &[
                "--table",
                "split-sum",
                "--fresnel",
                r#"{"fresnel":"schlick","f0":0.04}"#,
            ],
            "error: --fresnel: the split-sum tables are Fresnel-independent",
        ),
        (
            &["--fresnel", r#"{"ndf":"ggx","alpha_tr":0.3}"#],
            "error: --fresnel: the Fresnel factor is a Fresnel curve (got ndf, expected",
        ),
        (
            &["--table", "average", "--mu-count", "4"],
            "error: --mu-count: the average table has no mu axis",
        ),
        (
            &["--table", "e,average,E"],
            r#"error: --table: e given twice (got "e,average,E", expected each table at most once)"#,
        ),
        (
            // A long list is quoted as an excerpt.
            &[
                "--table",
                "e,average,average,average,average,average,average,average,average,e",
            ],
            r#"error: --table: average given twice (got "e,average,average,average,average,average,average,average,av…", expected"#,
        ),
        (
            &["--table", "e,avrage"],
            r#"error: --table: unknown table (got "avrage", expected a comma-separated list of e, average, split-sum, dfg); did you mean "average"?"#,
        ),
        (
            &["--table", "e,"],
            r#"error: --table: unknown table (got "", expected"#,
        ),
        (
            &[
                "--table",
                "e,dfg",
                "--fresnel",
                r#"{"fresnel":"schlick","f0":0.04}"#,
            ],
            "error: --fresnel: the dfg tables are Fresnel-independent",
        ),
        (
            &["--table", "e,average", "--against", "table.csv"],
            r#"error: --table: --against audits one table (got "e,average", expected one of e, average, dfg)"#,
        ),
    ];
    for (args, expected) in cases {
        let mut all = vec!["albedo"];
        all.extend(*args);
        let out = ndfplot(&all);
        let stderr = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(out.stdout.is_empty(), "{args:?}");
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
        assert!(stderr.starts_with(expected), "{args:?}: {stderr}");
    }
    let misspelt = ndfplot(&["albedo", "--ndf", "beckman"]);
    assert!(text(&misspelt.stderr).contains(r#"did you mean "beckmann"?"#));
}

#[test]
fn dash_o_writes_the_file_and_nothing_on_stdout() {
    let dir = scratch("albedo-out");
    let path = dir.join("nested").join("ggx_E.csv");
    let out = ndfplot(&["albedo", "-q", "--size", "2", "-o", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(out.stdout.is_empty() && out.stderr.is_empty());
    let printed = ndfplot(&["albedo", "-q", "--size", "2"]);
    assert_eq!(std::fs::read(&path).unwrap(), printed.stdout);
    let names: Vec<_> = std::fs::read_dir(path.parent().unwrap())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names, ["ggx_E.csv"], "no temporary is left");
}

#[test]
fn the_r_0_column_is_the_familys_own_limit_not_always_the_mirror() {
    // μ = 0, ½, 1 at θ = acos μ.
    let thetas: Vec<f64> = [0.0f64, 0.5, 1.0].iter().map(|m| m.acos()).collect();
    let uniform = eval(
        &[r#"{"ndf":"phong","alpha_p":0,"quantity":"albedo"}"#.to_string()],
        &thetas,
    );
    let uniform: Vec<f64> = uniform.iter().map(|row| row[0]).collect();
    assert!((uniform[2] - 0.3069).abs() < 1e-4, "{uniform:?}");
    // Phong's α_p = 0 is in its domain, the uniform lobe; ABC's a₁ → 0 tends to the same lobe.
    // (Their average tables take the same lobe at r = 0, but a minute to compute at r = 1.)
    for (args, limit) in [
        (&["--ndf", "phong", "--map", "r"][..], "alpha_p = 0"),
        (
            &["--ndf", "abc", "--fix", "alpha_abc2=1.75"][..],
            "the uniform lobe",
        ),
    ] {
        let mut all = args.to_vec();
        all.extend(["--size", "3"]);
        let table = albedo(&all);
        let (r, e) = (table.column("r"), table.column("E"));
        let column: Vec<f64> = table
            .rows
            .iter()
            .filter(|row| row[r] == 0.0)
            .map(|row| row[e])
            .collect();
        for (value, expected) in column.iter().zip(&uniform) {
            assert!((value - expected).abs() <= 1e-10, "{args:?}: {column:?}");
        }
        assert!(
            table.meta("limits").contains(limit),
            "{args:?}: {}",
            table.meta("limits")
        );
    }
    // GTR with γ < 1 tends to a lobe ∝ sin^(−2γ) θ, not the mirror: refused, not a wrong 1.
    let out = ndfplot(&[
        "albedo",
        "--ndf",
        "gtr",
        "--fix",
        "gamma_gtr=0.5",
        "--size",
        "2",
    ]);
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.starts_with("error: --fix: gamma_gtr: no limit at r = 0"),
        "{err}"
    );
    assert!(out.stdout.is_empty());
}

/// Parses a `--no-comments` CSV with a CSV reader: the first record is the header.
fn read_csv(text: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let mut reader = csv::ReaderBuilder::new()
        .flexible(false)
        .from_reader(text.as_bytes());
    let header = reader.headers().unwrap().iter().map(String::from).collect();
    let rows = reader
        .records()
        .map(|r| r.unwrap().iter().map(String::from).collect())
        .collect();
    (header, rows)
}

/// The standard output of `ndfplot albedo -q ARGS`, which must succeed.
fn stdout_of(args: &[&str]) -> String {
    let mut all = vec!["albedo", "-q"];
    all.extend(args);
    let out = ndfplot(&all);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{args:?}: {}",
        text(&out.stderr)
    );
    text(&out.stdout)
}

/// A field of a CSV as a number (NaN when empty).
fn number(field: &str) -> f64 {
    if field.is_empty() {
        f64::NAN
    } else {
        field.parse().unwrap()
    }
}

#[test]
fn several_tables_share_one_long_csv_under_a_table_column() {
    let both = albedo(&["--table", "E,average", "--mu-count", "3", "--r-count", "32"]);
    let e = albedo(&["--mu-count", "3", "--r-count", "32"]);
    let average = albedo(&["--table", "average", "--r-count", "32"]);
    assert_eq!(
        both.columns,
        [
            "table",
            "mu",
            "r",
            "alpha",
            "E",
            "turquin_f0_1",
            "E_avg",
            "kulla_conty_norm"
        ]
    );
    assert_eq!(both.meta("table"), "e,average");
    assert_eq!(both.meta("ndf"), e.meta("ndf"));
    assert_eq!(both.meta("mu_count (e)"), "3");
    assert!(both.meta("accuracy (average)").contains("1e-8"));
    // The table column is text: the parser reads it as NaN; e rows first, then average rows.
    assert_eq!(both.rows.len(), 3 * 32 + 32);
    let same = |a: &[f64], b: &[f64]| {
        a.iter()
            .zip(b)
            .all(|(x, y)| x == y || (x.is_nan() && y.is_nan()))
    };
    for (row, alone) in both.rows.iter().zip(&e.rows) {
        assert!(same(&row[1..6], alone), "{row:?} vs {alone:?}");
        assert!(row[6].is_nan() && row[7].is_nan());
    }
    for (row, alone) in both.rows[3 * 32..].iter().zip(&average.rows) {
        assert!(
            row[1].is_nan() && row[4].is_nan() && row[5].is_nan(),
            "{row:?}"
        );
        assert!(
            same(&row[2..4], &alone[..2]) && same(&row[6..8], &alone[2..4]),
            "{row:?}"
        );
    }
    // The average at its stated accuracy against Cycles' table_ggx_Eavg (Monte Carlo, 6 decimals:
    // its rounding plus noise, 2.5e-6), the same r = x/31 (Cycles clamps r = 0 to 1e-4).
    let cycles = std::fs::read_to_string(root().join("data/published/cycles/ggx_E.csv")).unwrap();
    let reference: Vec<f64> = cycles
        .lines()
        .filter(|l| l.starts_with("ggx_Eavg,"))
        .map(|l| l.rsplit(',').next().unwrap().parse().unwrap())
        .collect();
    assert_eq!(reference.len(), 32);
    for (row, want) in average.rows.iter().zip(&reference) {
        assert!(
            (row[2] - want).abs() <= 2.5e-6,
            "r = {}: {} vs Cycles {want}",
            row[0],
            row[2]
        );
    }
}

#[test]
fn a_matrix_cell_is_the_long_row_of_the_same_mu_and_r() {
    let long = albedo(&["--table", "e,average", "--mu-count", "3", "--r-count", "4"]);
    let matrix = stdout_of(&[
        "--table",
        "e,average",
        "--mu-count",
        "3",
        "--r-count",
        "4",
        "--shape",
        "matrix",
        "--no-comments",
    ]);
    let blocks: Vec<&str> = matrix.split("\n\n").collect();
    assert_eq!(
        blocks.len(),
        3,
        "E, turquin_f0_1, then the average: {matrix}"
    );
    let r_values = [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0];
    let header = |block: &str| -> Vec<String> { read_csv(block).0 };
    for (block, name, column) in [(blocks[0], "E", 4), (blocks[1], "turquin_f0_1", 5)] {
        let (head, rows) = read_csv(block);
        assert_eq!(head[0], name);
        let r: Vec<f64> = head[1..].iter().map(|f| number(f)).collect();
        assert_eq!(r, r_values);
        assert_eq!(rows.len(), 3);
        for row in &rows {
            let mu = number(&row[0]);
            for (j, field) in row[1..].iter().enumerate() {
                let cell = long
                    .rows
                    .iter()
                    .find(|l| l[1] == mu && l[2] == r_values[j])
                    .unwrap();
                assert_eq!(
                    number(field),
                    cell[column],
                    "{name} at mu = {mu}, r = {}",
                    r_values[j]
                );
            }
        }
    }
    // The average is one row per value over r.
    assert_eq!(header(blocks[2])[0], "r");
    let (_, rows) = read_csv(blocks[2]);
    assert_eq!(rows[0][0], "E_avg");
    assert_eq!(rows[1][0], "kulla_conty_norm");
    let averages: Vec<&Vec<f64>> = long.rows.iter().skip(12).collect();
    for (j, field) in rows[0][1..].iter().enumerate() {
        assert_eq!(number(field), averages[j][6]);
    }

    // JSON: an object per table, keyed by name, with the same numbers.
    let json: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "--table",
        "e,average",
        "--mu-count",
        "3",
        "--r-count",
        "4",
        "--shape",
        "matrix",
        "--format",
        "json",
    ]))
    .unwrap();
    assert_eq!(json["e"]["table"], "e");
    assert_eq!(json["e"]["mu"], serde_json::json!([0.0, 0.5, 1.0]));
    assert_eq!(json["average"]["r"].as_array().unwrap().len(), 4);
    assert!(json["average"].get("mu").is_none());
    for cell in long.rows.iter().take(12) {
        let (i, j) = ((cell[1] * 2.0) as usize, (cell[2] * 3.0).round() as usize);
        assert_eq!(json["e"]["values"]["E"][i][j].as_f64().unwrap(), cell[4]);
    }
    assert_eq!(
        json["average"]["values"]["kulla_conty_norm"][0],
        serde_json::Value::Null
    );
    assert_eq!(
        json["average"]["values"]["E_avg"][3].as_f64().unwrap(),
        averages[3][6]
    );
    // JSON long: each table's object is the one it prints alone.
    let keyed: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "--table", "dfg,e", "--size", "2", "--format", "json",
    ]))
    .unwrap();
    for name in ["dfg", "e"] {
        let alone: serde_json::Value = serde_json::from_str(&stdout_of(&[
            "--table", name, "--size", "2", "--format", "json",
        ]))
        .unwrap();
        assert_eq!(keyed[name], alone, "{name}");
    }
}

#[test]
fn without_comments_the_csv_is_the_header_and_rows_for_a_csv_reader() {
    for args in [
        &["--size", "3"][..],
        &["--table", "average,e", "--size", "3"][..],
    ] {
        let with = stdout_of(args);
        let mut plain_args = args.to_vec();
        plain_args.push("--no-comments");
        let plain = stdout_of(&plain_args);
        let kept: String = with
            .lines()
            .filter(|l| !l.starts_with('#'))
            .map(|l| format!("{l}\n"))
            .collect();
        assert_eq!(plain, kept, "{args:?}");
        let (header, rows) = read_csv(&plain);
        assert!(header[0] == "mu" || header[0] == "table", "{header:?}");
        assert!(rows.iter().all(|r| r.len() == header.len()));
        assert_eq!(rows.len(), if args.len() == 2 { 9 } else { 9 + 3 });
    }
}

#[test]
fn several_tables_go_to_one_file_with_a_summary_line_on_stderr() {
    let dir = scratch("albedo-several");
    let path = dir.join("ggx.csv");
    let args = [
        "albedo",
        "--table",
        "e,average",
        "--size",
        "2",
        "-o",
        path.to_str().unwrap(),
    ];
    let out = ndfplot(&args);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(out.stdout.is_empty());
    let stderr = text(&out.stderr);
    let line = stderr
        .strip_suffix(" s\n")
        .unwrap_or_else(|| panic!("{stderr}"));
    let prefix = format!(
        "albedo: wrote e (2 × 2) and average (2) to {} in ",
        path.display()
    );
    let seconds = line
        .strip_prefix(&prefix)
        .unwrap_or_else(|| panic!("{stderr}"));
    assert!(seconds.parse::<f64>().unwrap() >= 0.0, "{stderr}");
    assert_eq!(
        std::fs::read_to_string(&path).unwrap(),
        stdout_of(&["--table", "e,average", "--size", "2"])
    );
    let names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names, ["ggx.csv"], "one file, no temporary left");
    let printed = ndfplot(&["albedo", "--size", "2"]);
    assert!(text(&printed.stderr).starts_with("albedo: wrote e (2 × 2) to stdout in "));
    let quiet = ndfplot(&["albedo", "-q", "--size", "2"]);
    assert!(quiet.stderr.is_empty());
    // An audit closes with its own line: E on the 2 × 2 grid is 1 but at μ = 1, α = 1 (1 − ln 2).
    let engine = dir.join("engine.csv");
    std::fs::write(&engine, "1,1\n1,0.3068528194400549\n").unwrap();
    let audited = ndfplot(&["albedo", "--against", engine.to_str().unwrap()]);
    assert_eq!(audited.status.code(), Some(0), "{}", text(&audited.stderr));
    let stderr = text(&audited.stderr);
    let prefix = format!("albedo: audited e of {} in ", engine.display());
    assert!(
        stderr.starts_with(&prefix) && stderr.ends_with(" s\n"),
        "{stderr}"
    );
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
}
