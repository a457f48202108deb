//! Embeds the figure catalogue: every `configs/*.json`, sorted by name, becomes an entry of
//! `CATALOGUE` in `$OUT_DIR/catalogue.rs`, so `ndfplot render` needs no files at run time.

use std::{env, fs, path::Path};

fn main() {
    // Read at run time: a build script compiled for one checkout may be run for another that shares
    // its target directory, and must embed the configs of the package it is building.
    let manifest_dir = env::var("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR");
    let dir = Path::new(&manifest_dir).join("configs");
    println!("cargo:rerun-if-changed={}", dir.display());
    let mut names: Vec<String> = fs::read_dir(&dir)
        .map(|entries| {
            entries
                .filter_map(|e| e.ok())
                .filter_map(|e| e.file_name().into_string().ok())
                .filter(|n| n.ends_with(".json"))
                .collect()
        })
        .unwrap_or_default();
    names.sort();
    let mut code = String::from(
        "/// The built-in catalogue: (file name, spec text) per `configs/*.json`, sorted by name.\n",
    );
    code.push_str("pub const CATALOGUE: &[(&str, &str)] = &[\n");
    for name in &names {
        let path = dir.join(name);
        println!("cargo:rerun-if-changed={}", path.display());
        code.push_str(&format!(
            "    ({name:?}, include_str!({:?})),\n",
            path.display().to_string()
        ));
    }
    code.push_str("];\n");
    let out = Path::new(&env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("catalogue.rs");
    fs::write(out, code).expect("OUT_DIR is writable");
}
