//! The curve maths a live page runs (`maths.js`, a port of the Rust definitions `ndfplot eval`
//! uses) and the data it needs from the Rust side: every parameter domain from the family registry
//! and the Fresnel validation, and the Belcour–Bati–Barla basis. The test here keeps the two
//! implementations within [`REL_TOL_PAGE`] of each other over every family's whole domain.
//! Serialization only: nothing here evaluates a curve outside its test.

use crate::model::domain::Param;
use crate::model::fresnel::{self, basis};
use crate::model::ndf::Family;
use serde_json::{Map, Value, json};

/// The page's port of the curve definitions, without the families' formulas.
const SCRIPT: &str = include_str!("maths.js");

/// Where [`SCRIPT`] takes the families' formulas.
const NDF_FORMULAS: &str = "NDF_FORMULAS";

/// The page's curve maths: [`SCRIPT`] with every registered family's D
/// ([`Family::page_formula`]) in its table, by canonical name; defines
/// `ndfplotMaths(domains, basis)`.
pub fn script() -> String {
    let formulas: Vec<String> = Family::ALL
        .iter()
        .map(|family| {
            let formula = family.page_formula().trim_end();
            let (comments, expression): (Vec<&str>, Vec<&str>) =
                formula.lines().partition(|line| line.starts_with("//"));
            let mut lines: Vec<String> = comments.iter().map(|l| format!("    {l}")).collect();
            for (i, line) in expression.iter().enumerate() {
                lines.push(match i {
                    0 => format!("    {:?}: {line}", family.name()),
                    _ if line.is_empty() => String::new(),
                    _ => format!("    {line}"),
                });
            }
            lines.join("\n")
        })
        .collect();
    SCRIPT.replacen(
        NDF_FORMULAS,
        &format!("{{\n{},\n  }}", formulas.join(",\n")),
        1,
    )
}

/// Largest relative difference between a page's value and `ndfplot eval`'s (floored below
/// [`crate::model::math::tolerance::ABS_FLOOR`]): both sides exponentiate exponents of up to ~1450 whose
/// libm roundings differ by an ulp or two between the browser and the platform (fdlibm against
/// glibc), ≤ 1450 · 4.4e-16 ≈ 6e-13.
pub const REL_TOL_PAGE: f64 = 1e-12;

/// One domain as `maths.js` checks it: `{min, max, min_inclusive, max_inclusive, expected}`, where
/// `expected` is the text an out-of-domain message shows (`in [1e-150, 1e4]`).
fn domain(min: f64, min_inclusive: bool, max: f64, max_inclusive: bool, expected: String) -> Value {
    json!({"min": min, "max": max, "min_inclusive": min_inclusive, "max_inclusive": max_inclusive, "expected": expected})
}

fn param_domain(param: &Param) -> Value {
    domain(
        param.min.value,
        param.min.inclusive,
        param.max.value,
        param.max.inclusive,
        param.interval(),
    )
}

/// Every model's parameter domains, `{model: {param: domain}}`: the NDF families' from the registry,
/// the Fresnel models' from the constants `Ior` and `Fresnel` validate with (`fresnel::ETA`, …;
/// Lazanyi's `a` depends on f0 and is checked by the page itself).
pub fn domains() -> Value {
    let mut all = Map::new();
    for family in Family::ALL {
        let params: Map<String, Value> = family
            .params()
            .iter()
            .map(|p| (p.name.to_string(), param_domain(p)))
            .collect();
        all.insert(family.name().to_string(), Value::Object(params));
    }
    let ior: Map<String, Value> = [
        fresnel::ETA,
        fresnel::KAPPA,
        fresnel::REFLECTIVITY,
        fresnel::EDGE_TINT,
        fresnel::F0,
    ]
    .iter()
    .map(|p| (p.name.to_string(), param_domain(p)))
    .collect();
    let ior = Value::Object(ior);
    for model in [
        "exact",
        "schlick",
        "lazanyi",
        "lazanyi_term",
        "belcour",
        "basis",
    ] {
        all.insert(model.to_string(), ior.clone());
    }
    Value::Object(all)
}

/// The basis as `maths.js` takes it: `{functions: [b₀, b₁, b₂, b₃] (1000 node values each),
/// critical: [i₁, i₂]}`; `encode` writes each function (the page stores them as base64 of their
/// little-endian f64 bytes, the test as JSON numbers).
pub fn basis_json(encode: &dyn Fn(&[f64]) -> Value) -> Value {
    let basis = basis::basis();
    let functions: Vec<Value> = (0..4).map(|k| encode(basis.function(k))).collect();
    json!({"functions": functions, "critical": basis.critical_indices()})
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::curve::Curve;
    use crate::model::fresnel::{Fresnel, Ior, SchlickF0, approx};
    use crate::model::math::tolerance::floored_relative_difference;
    use std::collections::BTreeMap;
    use std::f64::consts::FRAC_PI_2;
    use std::process::Command;

    /// Runs `maths.js` on the cases: prints, per case, its canonical JSON and its values at θ.
    const HARNESS: &str = r#"
const input = JSON.parse(require("fs").readFileSync(process.argv[2], "utf8"));
const maths = ndfplotMaths(input.domains, input.basis);
const out = input.cases.map((text) => {
  const curve = maths.build(JSON.parse(text));
  if (curve.problem) return { canonical: text, problem: curve.problem };
  return { canonical: curve.canonical, values: input.thetas.map((t) => curve.eval(t)) };
});
process.stdout.write(JSON.stringify(out));
"#;

    /// `count` values from `lo` to `hi`, log-spaced when both are positive and a decade or more
    /// apart, else evenly spaced; `lo` and `hi` included.
    fn spread(lo: f64, hi: f64, count: usize) -> Vec<f64> {
        let log = lo > 0.0 && hi / lo >= 10.0;
        (0..count)
            .map(|i| {
                let t = i as f64 / (count - 1) as f64;
                match i {
                    0 => lo,
                    _ if i + 1 == count => hi,
                    _ if log => (lo.ln() + t * (hi.ln() - lo.ln())).exp(),
                    _ => lo + t * (hi - lo),
                }
            })
            .collect()
    }

    /// Values over a parameter's whole domain: its ends (the nearest accepted value at an open
    /// end, 1e300 for an unbounded one), a spread between them, and the special points of the
    /// families (1 and 2: ABC's a₂ and GTR's removable singularities; the notebook's values).
    fn domain_values(param: &Param) -> Vec<f64> {
        let lo = match (param.min.inclusive, param.min.value) {
            (true, v) => v,
            (false, 0.0) => 1e-300,
            (false, v) => v.next_up(),
        };
        let hi = if param.max.is_open() {
            1e300
        } else {
            param.max.value
        };
        let mut values = spread(lo, hi, 17);
        values.extend([0.0212, 0.0905, 0.3, 1.0, 1.75, 2.0, 23.5, 1000.0]);
        if param.max.is_open() {
            values.push(f64::MAX);
        }
        values.retain(|&v| param.contains(v));
        values.sort_by(f64::total_cmp);
        values.dedup();
        values
    }

    /// Every family at the product of its parameters' domain values.
    fn ndf_cases() -> Vec<Curve> {
        let mut curves = Vec::new();
        for family in Family::ALL {
            let axes: Vec<Vec<f64>> = family.params().iter().map(domain_values).collect();
            let mut point = vec![0usize; axes.len()];
            'product: loop {
                let values: Vec<f64> = point.iter().zip(&axes).map(|(&i, a)| a[i]).collect();
                curves.push(Curve::Ndf(family.build(&values).expect("a domain value")));
                for k in (0..axes.len()).rev() {
                    point[k] += 1;
                    if point[k] < axes[k].len() {
                        continue 'product;
                    }
                    point[k] = 0;
                }
                break;
            }
        }
        curves
    }

    /// Every Fresnel model over its domain: indices from 1e-150 to 1e150 (η near 1 included),
    /// Gulbrandsen's (r, g) with and without the remap, Schlick and Lazanyi over F₀ and a.
    fn fresnel_cases() -> Vec<Curve> {
        let etas = [
            1e-150,
            1e-3,
            0.5,
            0.99,
            1.0,
            1.0 + 1e-9,
            1.01,
            1.1,
            1.5,
            2.0,
            3.0,
            10.0,
            1e3,
            1e150,
        ];
        let kappas = [0.0, 1e-9, 0.25, 1.0, 2.86, 10.0, 1e150];
        let rs = [0.0, 1e-8, 0.04, 0.5, 0.9, 0.999];
        let gs = [0.0, 1e-6, 0.5, 1.0];
        let mut iors = Vec::new();
        for &eta in &etas {
            for &kappa in &kappas {
                iors.push(Ior::eta_kappa(eta, kappa).expect("a domain value"));
            }
        }
        for &r in &rs {
            for &g in &gs {
                for remap in [false, true] {
                    iors.push(Ior::gulbrandsen(r, g, remap).expect("a domain value"));
                }
            }
        }
        let mut curves = Vec::new();
        for &ior in &iors {
            curves.push(Fresnel::Exact(ior));
            curves.push(Fresnel::Schlick(SchlickF0::Ior(ior)));
            // Belcour reconstructions of the representable materials (|η̃| ≤ 1e3: beyond, F is 1
            // to the last bit and the projection's 2×2 system sees only rounding).
            let (eta, kappa) = ior.complex();
            if eta.hypot(kappa) <= 1e3 {
                curves.push(Fresnel::belcour(ior));
            }
        }
        for f0 in [0.0, 1e-9, 0.04, 0.5, 0.96, 1.0] {
            curves.push(Fresnel::schlick(f0).expect("a domain value"));
            let (a_min, a_max) = approx::lazanyi_a_range(f0);
            for a in spread(a_min, a_max, 5) {
                curves.push(Fresnel::lazanyi(f0, a).expect("a domain value"));
            }
        }
        curves.push(Fresnel::LazanyiTerm);
        curves.extend((0..4).map(|k| Fresnel::basis(k).expect("an index")));
        curves.into_iter().map(Curve::Fresnel).collect()
    }

    /// θ over [0, π/2]: both ends, tiny angles, an even grid, the basis nodes' angles, and the
    /// doubles just below π/2.
    fn thetas() -> Vec<f64> {
        let mut thetas = vec![0.0, 1e-300, 1e-150, 1e-8, 1e-4];
        thetas.extend((1..=96).map(|i| FRAC_PI_2 * i as f64 / 97.0));
        thetas.extend([0.128128128128128f64, 0.432432432432432, 0.999].map(f64::acos));
        thetas.extend([1e-3, 1e-6, 1e-10, 1e-15].map(|d| FRAC_PI_2 - d));
        thetas.push(FRAC_PI_2);
        thetas
    }

    #[test]
    fn the_page_maths_agrees_with_eval_over_every_domain() {
        if !matches!(Command::new("node").arg("--version").output(), Ok(out) if out.status.success())
        {
            eprintln!(
                "SKIPPED the_page_maths_agrees_with_eval_over_every_domain: node is not installed"
            );
            return;
        }
        let curves: Vec<Curve> = ndf_cases().into_iter().chain(fresnel_cases()).collect();
        let thetas = thetas();
        let input = json!({
            "domains": domains(),
            "basis": basis_json(&|values| json!(values)),
            "cases": curves.iter().map(Curve::canonical_json).collect::<Vec<_>>(),
            "thetas": thetas,
        });
        let dir = std::env::temp_dir().join(format!("ndfplot-page-maths-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let (input_path, script_path) = (dir.join("input.json"), dir.join("run.js"));
        std::fs::write(&input_path, input.to_string()).unwrap();
        std::fs::write(&script_path, format!("{}\n{HARNESS}", script())).unwrap();
        let out = Command::new("node")
            .arg(&script_path)
            .arg(&input_path)
            .output()
            .unwrap();
        std::fs::remove_dir_all(&dir).ok();
        assert!(
            out.status.success(),
            "node: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let results: Vec<Value> = serde_json::from_slice(&out.stdout).unwrap();

        let mut worst: BTreeMap<String, (f64, String)> = BTreeMap::new();
        for (curve, result) in curves.iter().zip(&results) {
            let canonical = curve.canonical_json();
            assert_eq!(
                result["canonical"],
                canonical.as_str(),
                "{:?}",
                result.get("problem")
            );
            let values = result["values"].as_array().unwrap();
            let model = canonical.split('"').nth(3).unwrap().to_string();
            for (&theta, value) in thetas.iter().zip(values) {
                let (want, got) = (curve.eval(theta), value.as_f64().unwrap_or(f64::NAN));
                let difference = floored_relative_difference(got, want);
                assert!(
                    difference <= REL_TOL_PAGE,
                    "{canonical} at θ = {theta:?}: page {got:?}, eval {want:?} ({difference:e})"
                );
                let entry = worst.entry(model.clone()).or_insert((0.0, String::new()));
                if difference > entry.0 {
                    *entry = (difference, format!("{canonical} at θ = {theta:?}"));
                }
            }
        }
        for (model, (difference, at)) in &worst {
            println!("{model}: largest page-vs-eval difference {difference:.2e} ({at})");
        }
    }
}
