//! Whole-process wall time of ndfplot against the matplotlib/numpy peer on the 17 figures both
//! draw (14 NDF figures and three Fresnel figures, each as SVG + PNG + CSV), and of rendering the
//! whole built-in catalogue.
//!
//! The two commands run interleaved (ndfplot, peer, ndfplot, peer, …) after one warm-up run of
//! each, so that a change in machine load hits both alike; the medians and their ratio are
//! printed. The peer is a Python script outside this repository: set `NDFPLOT_PEER` to its
//! `figures.py` and `NDFPLOT_PEER_PYTHON` to the interpreter of its environment (default
//! `python3`). Without `NDFPLOT_PEER` only ndfplot's times are printed.
//!
//! Run: `NDFPLOT_PEER=…/figures.py NDFPLOT_PEER_PYTHON=…/bin/python cargo bench --bench peer`.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

/// Timed runs per command (after one warm-up run); the median is reported.
const RUNS: usize = 7;

/// The catalogue figures the peer also draws.
const SHARED_FIGURES: [&str; 17] = [
    "phong-powers",
    "beckmann-moderate",
    "beckmann-super-rough",
    "beckmann-vs-phong",
    "ts-vs-phong",
    "ts-vs-phong-matched",
    "tr-ranges",
    "tr-vs-phong",
    "abc-grid",
    "abc-vs-tr",
    "abc-vs-phong",
    "abc-spiky-vs-tr",
    "sgd-grid",
    "sgd-vs-abc",
    "fresnel-basis",
    "fresnel-dielectrics",
    "fresnel-conductors",
];

fn main() {
    let dir = std::env::temp_dir().join(format!("ndfplot-bench-peer-{}", std::process::id()));
    let ndfplot = env!("CARGO_BIN_EXE_ndfplot");
    let configs = Path::new(env!("CARGO_MANIFEST_DIR")).join("configs");
    let mut shared = Command::new(ndfplot);
    shared
        .args(["render", "-q", "--format", "svg,png,csv", "-o"])
        .arg(dir.join("ndfplot"))
        .args(SHARED_FIGURES.map(|id| configs.join(format!("{id}.json"))));
    let peer = std::env::var_os("NDFPLOT_PEER").map(|script| {
        let python = std::env::var_os("NDFPLOT_PEER_PYTHON").unwrap_or_else(|| "python3".into());
        let mut command = Command::new(python);
        command.arg(PathBuf::from(script)).arg(dir.join("peer"));
        command
    });

    let mut commands = vec![("ndfplot, 17 figures", shared)];
    match peer {
        Some(peer) => commands.push(("peer, 17 figures", peer)),
        None => println!("NDFPLOT_PEER is not set: the peer is not run, no ratio is printed"),
    }
    let medians = interleaved_medians(&mut commands);
    for ((label, _), median) in commands.iter().zip(&medians) {
        println!("{label}: median {median:.3} s of {RUNS} runs");
    }
    if let [ours, theirs] = medians[..] {
        println!("peer / ndfplot: {:.1}×", theirs / ours);
    }

    let mut catalogue = Command::new(ndfplot);
    catalogue
        .args(["render", "-q", "-o"])
        .arg(dir.join("catalogue"));
    let catalogue_median = interleaved_medians(&mut [("catalogue", catalogue)])[0];
    println!(
        "ndfplot, whole catalogue (svg, png, csv, html): median {catalogue_median:.3} s of {RUNS} runs"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// Runs each command once to warm up, then [`RUNS`] rounds of all commands in turn, and returns
/// each command's median wall time in seconds. A command that fails stops the benchmark.
fn interleaved_medians(commands: &mut [(&str, Command)]) -> Vec<f64> {
    let mut seconds = vec![Vec::with_capacity(RUNS); commands.len()];
    for round in 0..=RUNS {
        for ((label, command), times) in commands.iter_mut().zip(&mut seconds) {
            let start = Instant::now();
            let output = command.output().expect("the command starts");
            let elapsed = start.elapsed().as_secs_f64();
            assert!(
                output.status.success(),
                "{label} failed: {}",
                String::from_utf8_lossy(&output.stderr)
            );
            if round > 0 {
                times.push(elapsed);
            }
        }
    }
    seconds
        .into_iter()
        .map(|mut times| {
            times.sort_by(f64::total_cmp);
            times[RUNS / 2]
        })
        .collect()
}
