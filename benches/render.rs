//! Wall time of rendering the whole built-in catalogue (SVG, PNG and CSV), split by stage:
//! reading, planning and evaluating; drawing and encoding every output (rasterization, PNG
//! compression and CSV formatting included, each file written to its temporary as it is done);
//! renaming the files into place. Two variants: the default (curves drawn adaptively, tables on a
//! uniform grid) and every scene's sampling set to `{"uniform": 1000}`, the fixed grid a notebook
//! draws.
//! Prints the median of [`RUNS`] runs per stage.
//!
//! Run: `cargo bench --bench render`.

use ndfplot::output::Format;
use ndfplot::render::{self, RenderOptions, RenderStats};
use ndfplot::spec::catalogue::CATALOGUE;
use ndfplot::spec::source::CanvasOverride;
use std::path::{Path, PathBuf};
use std::time::Duration;

/// Runs per variant; the median is reported, so one disturbed run does not move it.
const RUNS: usize = 7;

fn main() {
    let dir = std::env::temp_dir().join(format!("ndfplot-bench-render-{}", std::process::id()));
    let uniform = dir.join("uniform");
    std::fs::create_dir_all(&uniform).expect("temporary folder is writable");
    for (name, text) in CATALOGUE {
        let mut forced: serde_json::Value =
            serde_json::from_str(text).expect("catalogue specs are JSON");
        forced["sampling"] = serde_json::json!({"uniform": 1000});
        std::fs::write(uniform.join(name), forced.to_string())
            .expect("temporary folder is writable");
    }
    report("default (adaptive drawing)", Vec::new(), &dir);
    report("uniform 1000", vec![uniform], &dir);
    std::fs::remove_dir_all(&dir).ok();
}

/// Renders `paths` (the built-in catalogue when empty) [`RUNS`] times and prints the median of
/// each stage and of their sum.
fn report(label: &str, paths: Vec<PathBuf>, dir: &Path) {
    let options = RenderOptions {
        paths,
        out: dir.join("out"),
        formats: vec![Format::Svg, Format::Png, Format::Csv],
        canvas: CanvasOverride::default(),
        allow_read: Vec::new(),
    };
    let runs: Vec<RenderStats> = (0..RUNS)
        .map(|_| {
            render::run_with_stats(&options)
                .expect("the catalogue renders")
                .1
        })
        .collect();
    let median = |stage: fn(&RenderStats) -> Duration| {
        let mut seconds: Vec<f64> = runs.iter().map(|s| stage(s).as_secs_f64()).collect();
        seconds.sort_by(f64::total_cmp);
        seconds[RUNS / 2]
    };
    println!(
        "{label}: total {:.3} s = evaluation {:.3} s + drawing and encoding {:.3} s + writing {:.3} s \
         (medians of {RUNS}; {} curve evaluations)",
        median(|s| s.evaluation + s.drawing + s.writing),
        median(|s| s.evaluation),
        median(|s| s.drawing),
        median(|s| s.writing),
        runs[0].evaluations
    );
}
