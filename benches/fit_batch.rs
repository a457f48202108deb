//! Wall time of fitting ABC (a₂ = 1.75 fixed, by peak and by l2) to 20 GGX roughnesses
//! α = 0.05, 0.10, …, 1.0: one `ndfplot fit --target - --format jsonl` process reading the 20 targets
//! as JSON Lines, against the shell loop it replaces (`for a in …; do ndfplot fit --target …; done`,
//! 20 processes). Both run the benchmark build of the binary; prints the median of [`RUNS`] runs each.
//! α = 1 is the uniform lobe, which ABC reaches only as a₁ → 0: both variants report it as an error
//! (exit 2) after fitting the other 19, so both do the same work.
//!
//! Run: `cargo bench --bench fit_batch`.

#[path = "../tests/common/mod.rs"]
mod common;

use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Runs per variant; the median is reported, so one disturbed run does not move it.
const RUNS: usize = 11;

/// The binary under test.
const NDFPLOT: &str = env!("CARGO_BIN_EXE_ndfplot");

/// The fit's arguments after the target.
const FIT: [&str; 4] = ["--family", "abc", "--fix", "alpha_abc2=1.75"];

fn main() {
    let alphas: Vec<String> = (1..=20).map(|i| format!("{:?}", i as f64 / 20.0)).collect();
    let targets: Vec<String> = alphas
        .iter()
        .map(|a| format!(r#"{{"ndf":"trowbridge_reitz","alpha_tr":{a}}}"#))
        .collect();
    let jsonl: String = targets.iter().map(|t| format!("{t}\n")).collect();
    println!(
        "fit ABC (alpha_abc2 = 1.75) to {} GGX targets, median of {RUNS} runs",
        targets.len()
    );
    for by in ["peak", "l2"] {
        let batch = median(|| batch(&jsonl, by));
        let looped = median(|| shell_loop(&alphas, by));
        println!(
            "  by {by:<4}  one process (--target -): {:>8.1} ms   shell loop (20 processes): {:>8.1} ms   ({:.1}x)",
            ms(batch),
            ms(looped),
            looped.as_secs_f64() / batch.as_secs_f64()
        );
    }
}

/// One `fit --target - --format jsonl` process fed `jsonl` on stdin.
fn batch(jsonl: &str, by: &str) -> Duration {
    let args = [
        &["fit", "--target", "-", "--by", by, "--format", "jsonl"][..],
        &FIT,
    ]
    .concat();
    let start = Instant::now();
    let output = common::ndfplot_stdin(&args, jsonl);
    let elapsed = start.elapsed();
    assert_eq!(
        output.status.code(),
        Some(2),
        "only the uniform target fails"
    );
    elapsed
}

/// `sh -c 'for a in …; do ndfplot fit --target …; done'`: one process per target, as a script would.
fn shell_loop(alphas: &[String], by: &str) -> Duration {
    let script = format!(
        r#"for a in {}; do "$0" fit --target "{{\"ndf\":\"trowbridge_reitz\",\"alpha_tr\":$a}}" --by {by} {}; done"#,
        alphas.join(" "),
        FIT.join(" ")
    );
    let start = Instant::now();
    let status = Command::new("sh")
        .args(["-c", &script, NDFPLOT])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .expect("sh runs");
    assert_eq!(status.code(), Some(2), "the last, uniform target fails");
    start.elapsed()
}

/// The median of [`RUNS`] timings of `run`.
fn median(mut run: impl FnMut() -> Duration) -> Duration {
    let mut times: Vec<Duration> = (0..RUNS).map(|_| run()).collect();
    times.sort();
    times[RUNS / 2]
}

fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}
