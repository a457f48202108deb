//! Heat-map panels of albedo series: the table's values are those of `ndfplot eval`, and renders
//! are byte-for-byte repeatable.

use crate::common::{ndfplot, render_into, scratch, text};

/// A one-panel heat map of E over a `n` × `n` grid, GGX, α = r².
fn spec(n: usize) -> String {
    format!(
        r#"{{"id": "heat", "panels": [{{"kind": "heatmap",
            "curves": [{{"data": "albedo", "ndf": "ggx", "map": "r2", "value": "E", "mu": {n}, "r": {n}}}]}}]}}"#
    )
}

#[test]
fn albedo_table_values_equal_eval_at_theta_acos_mu() {
    let dir = scratch("heatmap-csv");
    let path = dir.join("heat.json");
    std::fs::write(&path, spec(3)).unwrap();
    render_into(&[&path], &dir, "csv");
    let mut reader = csv::ReaderBuilder::new()
        .comment(Some(b'#'))
        .from_path(dir.join("heat.csv"))
        .unwrap();
    let rows: Vec<(f64, f64, f64)> = reader
        .records()
        .map(|r| {
            let r = r.unwrap();
            let at = |i: usize| r[i].parse::<f64>().unwrap();
            assert_eq!(&r[2], r#"{"data":"albedo","ndf":"trowbridge_reitz","map":"r2","g2":"height-correlated","value":"E","mu":3,"r":3}"#);
            (at(3), at(4), at(5))
        })
        .collect();
    // Rows μ (x), columns r (y), on Cycles' grid.
    let grid: Vec<(f64, f64)> = rows.iter().map(|&(x, y, _)| (x, y)).collect();
    let nodes = [0.0, 0.5, 1.0];
    let expected: Vec<(f64, f64)> = nodes
        .iter()
        .flat_map(|&mu| nodes.iter().map(move |&r| (mu, r)))
        .collect();
    assert_eq!(grid, expected);
    for &(mu, r, e) in &rows {
        if r == 0.0 || mu == 0.0 {
            // The mirror limit, and the grazing limit of height-correlated G2 without Fresnel.
            assert!((e - 1.0).abs() < 1e-12, "E({mu}, {r}) = {e}");
            continue;
        }
        let curve = format!(
            r#"{{"ndf":"ggx","alpha_tr":{:?},"quantity":"albedo"}}"#,
            r * r
        );
        let theta = format!("{:?}", mu.acos());
        let out = ndfplot(&["eval", "--curve", &curve, "--theta", &theta]);
        assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
        let stdout = text(&out.stdout);
        let value: f64 = stdout
            .lines()
            .nth(1)
            .unwrap()
            .split(',')
            .nth(1)
            .unwrap()
            .parse()
            .unwrap();
        assert!(
            (value - e).abs() < 1e-12,
            "E({mu}, {r}): table {e}, eval {value}"
        );
    }
    // Cycles' E(μ = 1, r = 1) = 1 − ln 2.
    assert!((rows[8].2 - 0.306853).abs() < 1e-6, "{:?}", rows[8]);
}

#[test]
fn heat_maps_render_identically_twice() {
    let dir = scratch("heatmap-twice");
    let path = dir.join("heat.json");
    std::fs::write(&path, spec(5)).unwrap();
    let (a, b) = (dir.join("a"), dir.join("b"));
    render_into(&[&path], &a, "svg,png,csv");
    render_into(&[&path], &b, "svg,png,csv");
    for name in ["heat.svg", "heat.png", "heat.csv"] {
        let (x, y) = (
            std::fs::read(a.join(name)).unwrap(),
            std::fs::read(b.join(name)).unwrap(),
        );
        assert!(x == y, "{name} differs between two renders");
    }
    let svg = String::from_utf8(std::fs::read(a.join("heat.svg")).unwrap()).unwrap();
    // The colour bar's ends are viridis' ends.
    for colour in ["#440154", "#FDE725"] {
        assert!(svg.contains(colour), "{colour}");
    }
}
