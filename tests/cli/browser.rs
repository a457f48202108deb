//! Interactive pages: the catalogue's pages are self-contained, small and deterministic, bad
//! slider declarations exit 2 naming their path, and, in Debian's Chromium driven headless from
//! here (no npm step: one `chromium --headless --dump-dom` of a page holding every catalogue page
//! in a frame, with a checking script run in each), every catalogue page is visited
//! through `window.ndfplot`: each parameter is set to both ends of its slider and to a typed value
//! off any grid, and every curve the page then reports must equal the library's evaluation (what
//! `ndfplot eval` prints) to [`REL_TOL_PAGE`]; on comparison pages the peak-match link must agree
//! with `ndfplot fit --by peak`. Each page can also be captured at 360 and 1280 px wide into the
//! target folder. Without /usr/bin/chromium the browser part prints why it was skipped.

use crate::common::{files_in, ndfplot, render_into, root, scratch};
use ndfplot::model::curve::Curve;
use ndfplot::model::fresnel::Fresnel;
use ndfplot::model::math::tolerance::floored_relative_difference;
use ndfplot::output::html::REL_TOL_PAGE;
use ndfplot::spec::curve::{CurveSpec, parse};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

const CHROMIUM: &str = "/usr/bin/chromium";
/// Largest page: the Fresnel pages embed the basis (32 KB of base64) beside the page maths.
const MAX_PAGE_BYTES: usize = 150_000;

/// Runs once every frame has loaded: in each page (frame `i` of the frames), visits every
/// parameter's ends and an off-grid value (the geometric or arithmetic mean of the range's ends,
/// nudged by 1.2345e-3 relative), turns each match link on, and writes every state's `current()`
/// into `<pre id="check-i">` of the holding page.
const CHECK_SCRIPT: &str = r#"<script>
window.addEventListener("load", () => {
  Array.from(document.querySelectorAll("iframe")).forEach((frame, i) => {
    const api = frame.contentWindow.ndfplot;
    const states = [];
    const record = (what) => states.push({ what, current: api.current() });
    try {
      record("start");
      for (const p of api.params()) {
        const start = p.value;
        const typed = (p.scale === "log" ? Math.sqrt(p.min * p.max) : (p.min + p.max) / 2) * (1 + 1.2345e-3);
        for (const v of [p.min, p.max, typed]) {
          const problem = api.set(p.name, v);
          if (problem === null) record(p.name + " = " + v);
          else states.push({ what: p.name + " = " + v, problem });
        }
        api.set(p.name, start);
      }
      if (api.match("peak")) record("peak match");
    } catch (error) {
      states.push({ what: "the check", problem: String(error) });
    }
    const pre = document.createElement("pre");
    pre.id = "check-" + i;
    pre.textContent = JSON.stringify(states);
    document.body.append(pre);
  });
});
</script>"#;

/// A page holding each of the pages `files` (beside it) in a frame of its own, followed by
/// [`CHECK_SCRIPT`]. Chromium runs with `--allow-file-access-from-files`, so the frames are of the
/// holder's origin and reachable from its script.
fn holder(files: &[String]) -> String {
    let mut html = String::from("<!DOCTYPE html><html><body>");
    for file in files {
        html.push_str(&format!(r#"<iframe src="{file}"></iframe>"#));
    }
    html.push_str(CHECK_SCRIPT);
    html.push_str("</body></html>");
    html
}

/// The text of `<pre id="{id}">` in a DOM that Chromium dumped, unescaped.
fn pre_text(dom: &str, id: &str) -> Option<String> {
    let (_, rest) = dom.split_once(&format!(r#"<pre id="{id}">"#))?;
    Some(
        rest.split("</pre>")
            .next()?
            .replace("&quot;", "\"")
            .replace("&lt;", "<")
            .replace("&gt;", ">")
            .replace("&amp;", "&"),
    )
}

/// The environment variable that asks for screenshots of every page at 360 and 1280 px wide, in
/// `target/tmp/page-screenshots/` (`NDFPLOT_PAGE_SCREENSHOTS=1 cargo test --test cli browser`).
const SCREENSHOTS: &str = "NDFPLOT_PAGE_SCREENSHOTS";

/// Why the browser cannot run here, if it cannot.
fn missing_browser() -> Option<String> {
    (!Path::new(CHROMIUM).exists())
        .then(|| format!("{CHROMIUM} is not installed (apt-get install chromium)"))
}

fn chromium(args: &[&str]) -> std::process::Output {
    Command::new(CHROMIUM)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--hide-scrollbars",
            "--virtual-time-budget=20000",
        ])
        .args(args)
        .output()
        .unwrap()
}

/// The library's value of a page curve (canonical JSON) at θ: what `ndfplot eval` prints.
fn eval_curve(canonical: &str) -> Curve {
    let node = ndfplot::spec::json::parse(canonical).unwrap();
    match parse(&node, "").unwrap() {
        CurveSpec::Ready(curve) => curve,
        CurveSpec::Belcour(ior) => Curve::Fresnel(Fresnel::belcour(ior)),
        other => panic!("not a page curve: {other:?}"),
    }
}

/// `ndfplot fit --by peak` of the second curve's family to the first, the other parameters fixed.
fn fit_by_peak(target: &str, fitted: &str, free: &str) -> f64 {
    let fitted: serde_json::Map<String, Value> = serde_json::from_str(fitted).unwrap();
    let family = fitted["ndf"].as_str().unwrap();
    let mut args = vec![
        "fit".to_string(),
        "--target".into(),
        target.into(),
        "--family".into(),
        family.into(),
        "--by".into(),
        "peak".into(),
    ];
    for (k, v) in &fitted {
        if k != "ndf" && k != free {
            args.extend(["--fix".to_string(), format!("{k}={v}")]);
        }
    }
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let out = ndfplot(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let line: Value = serde_json::from_slice(&out.stdout).unwrap();
    line[free].as_f64().unwrap()
}

#[test]
fn every_page_draws_values_equal_to_eval_at_every_setting() {
    if let Some(why) = missing_browser() {
        eprintln!("SKIPPED every_page_draws_values_equal_to_eval_at_every_setting: {why}");
        return;
    }
    let dir = scratch("browser-pages");
    let shots = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("page-screenshots");
    std::fs::create_dir_all(&shots).unwrap();
    let ids: Vec<String> = files_in(&root().join("configs"))
        .into_iter()
        .filter(|n| n.ends_with("-interactive.json"))
        .map(|n| n.trim_end_matches(".json").to_string())
        .collect();
    assert!(ids.len() >= 10, "{ids:?}");
    let specs = interactive_specs();
    render_into(
        &specs.iter().map(PathBuf::as_path).collect::<Vec<_>>(),
        &dir,
        "html",
    );
    // Chromium starts once for the check of every page (and twice per page for the screenshots);
    // the pages' states are then compared with the library two pages at a time.
    let pages: Vec<String> = ids.iter().map(|id| format!("{id}.html")).collect();
    let checked = dir.join("check.html");
    std::fs::write(&checked, holder(&pages)).unwrap();
    let out = chromium(&[
        "--allow-file-access-from-files",
        "--dump-dom",
        checked.to_str().unwrap(),
    ]);
    let dom = String::from_utf8_lossy(&out.stdout);
    let texts: Vec<String> = (0..ids.len())
        .map(|i| {
            pre_text(&dom, &format!("check-{i}")).unwrap_or_else(|| {
                panic!(
                    "{}: the check did not run: {}",
                    ids[i],
                    String::from_utf8_lossy(&out.stderr)
                )
            })
        })
        .collect();
    let check_page = |(id, text): (&String, &String)| {
        let states: Vec<Value> = serde_json::from_str(text).unwrap();
        let mut worst = 0.0f64;
        for state in &states {
            let what = state["what"].as_str().unwrap();
            assert!(
                state.get("problem").is_none(),
                "{id}: {what}: {}",
                state["problem"]
            );
            for curve in state["current"]["curves"].as_array().unwrap() {
                let canonical = curve["curve"].as_str().unwrap();
                let evaluated = eval_curve(canonical);
                let thetas = curve["theta"].as_array().unwrap();
                let values = curve["value"].as_array().unwrap();
                assert!(thetas.len() > 1000, "{id}: {what}: {} points", thetas.len());
                for (theta, value) in thetas.iter().zip(values) {
                    let theta = theta.as_f64().unwrap();
                    let (got, want) = (value.as_f64().unwrap_or(f64::NAN), evaluated.eval(theta));
                    let difference = floored_relative_difference(got, want);
                    worst = worst.max(difference);
                    assert!(
                        difference <= REL_TOL_PAGE,
                        "{id}: {what}: {canonical} at θ = {theta:?}: page {got:?}, eval {want:?}"
                    );
                }
            }
            if what == "peak match" {
                let curves = state["current"]["curves"].as_array().unwrap();
                let (target, fitted) = (
                    curves[0]["curve"].as_str().unwrap(),
                    curves[1]["curve"].as_str().unwrap(),
                );
                let fitted_map: serde_json::Map<String, Value> =
                    serde_json::from_str(fitted).unwrap();
                let free = fitted_map.keys().nth(1).unwrap().clone();
                let want = fit_by_peak(target, fitted, &free);
                let got = fitted_map[&free].as_f64().unwrap();
                assert!(
                    floored_relative_difference(got, want) <= 1e-9,
                    "{id}: page matched {free} = {got}, fit gives {want}"
                );
            }
        }
        println!(
            "{id}: {} states, largest page-vs-eval difference {worst:.2e}",
            states.len()
        );
        // Screenshots are for people to look at, not checked: taken only when asked for.
        if std::env::var_os(SCREENSHOTS).is_none() {
            return;
        }
        for width in [360, 1280] {
            let shot = shots.join(format!("{id}-{width}.png"));
            let out = chromium(&[
                &format!("--window-size={width},900"),
                &format!("--screenshot={}", shot.display()),
                dir.join(format!("{id}.html")).to_str().unwrap(),
            ]);
            assert!(
                shot.exists(),
                "{id}: no screenshot: {}",
                String::from_utf8_lossy(&out.stderr)
            );
        }
    };
    let checks: Vec<(&String, &String)> = ids.iter().zip(&texts).collect();
    std::thread::scope(|scope| {
        for half in checks.chunks(checks.len().div_ceil(2)) {
            scope.spawn(|| half.iter().copied().for_each(check_page));
        }
    });
}

/// The catalogue's specs with sliders, the ones that have a page.
fn interactive_specs() -> Vec<PathBuf> {
    files_in(&root().join("configs"))
        .into_iter()
        .filter(|n| n.contains("interactive"))
        .map(|n| root().join("configs").join(n))
        .collect()
}

#[test]
fn catalogue_pages_are_self_contained_small_and_deterministic() {
    let dir = scratch("interactive-catalogue");
    let mut runs = Vec::new();
    // Only specs with sliders have a page; the whole catalogue renders none besides theirs.
    let specs = interactive_specs();
    for run in ["a", "b"] {
        let out_dir = dir.join(run);
        render_into(
            &specs.iter().map(PathBuf::as_path).collect::<Vec<_>>(),
            &out_dir,
            "html",
        );
        let mut pages: Vec<(String, Vec<u8>)> = std::fs::read_dir(&out_dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .map(|p| {
                (
                    p.file_name().unwrap().to_string_lossy().into_owned(),
                    std::fs::read(&p).unwrap(),
                )
            })
            .collect();
        pages.sort();
        runs.push(pages);
    }
    let names: Vec<&str> = runs[0].iter().map(|(n, _)| n.as_str()).collect();
    let interactive: Vec<String> = files_in(&root().join("configs"))
        .into_iter()
        .filter(|n| n.contains("interactive"))
        .map(|n| n.replace(".json", ".html"))
        .collect();
    assert!(
        interactive.len() >= 10 && interactive.iter().all(|n| names.contains(&n.as_str())),
        "{names:?}"
    );
    assert_eq!(runs[0], runs[1], "pages differ between runs");
    for (name, bytes) in &runs[0] {
        let text = std::str::from_utf8(bytes).unwrap();
        assert!(
            bytes.len() <= MAX_PAGE_BYTES,
            "{name}: {} bytes",
            bytes.len()
        );
        // Nothing to fetch: no external URL besides the SVG namespace name, no src attributes.
        let urls = text.matches("http").count();
        let namespaces = text.matches("http://www.w3.org/2000/svg").count();
        assert_eq!(urls, namespaces, "{name} names a URL");
        // The one reference is the static figure beside the page, shown only without JavaScript.
        let image = format!(
            r#"<img id="static" src="{}""#,
            name.replace(".html", ".png")
        );
        assert!(text.contains(&image), "{name} has no static fallback");
        assert!(
            text.matches(" src=").count() == 1
                && !text.contains("@import")
                && !text.contains("url("),
            "{name} loads a resource"
        );
    }
}

#[test]
fn bad_interactive_declarations_exit_2_naming_the_path() {
    let dir = scratch("interactive-bad");
    let slider = r#"{"params": [{"name": "a", "range": [0.2, 1.0]}]}"#;
    let beckmann = r#"{"ndf": "beckmann", "alpha_b": {"slider": "a"}}"#;
    for (interactive, curve, needle) in [
        (
            slider,
            r#"{"ndf": "beckmann", "alpha_b": {"slider": "b"}}"#,
            r#"panels[0].curves[0].alpha_b.slider: unknown slider (got "b", expected one of: a)"#,
        ),
        (
            r#"{"params": [{"name": "a", "range": [1.0, 0.2]}]}"#,
            beckmann,
            "interactive.params[0].range: invalid interval",
        ),
        (
            r#"{"params": [{"name": "a", "range": [0.01, 1]}, {"name": "b", "range": [0, 20]}]}"#,
            r#"{"ndf": "sgd", "alpha_sgd1": {"slider": "a"}, "alpha_sgd2": {"slider": "b"}}"#,
            "panels[0].curves[0].alpha_sgd2: out of domain (got 20.0, expected in [-10, 10]",
        ),
    ] {
        let spec = dir.join("bad.json");
        let text = format!(
            r#"{{"id": "bad", "interactive": {interactive}, "panels": [{{"curves": [{curve}]}}]}}"#
        );
        std::fs::write(&spec, text).unwrap();
        let out_dir = dir.join("out");
        let out = ndfplot(&[
            "render",
            spec.to_str().unwrap(),
            "-o",
            out_dir.to_str().unwrap(),
        ]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(
            err.contains(&format!("error: {}: {needle}", spec.display())),
            "expected {needle:?} in {err}"
        );
        assert!(!out_dir.exists(), "a bad spec wrote files");
    }
}

/// A label's `{=name}` is the slider's value: the page keeps the placeholder and updates it as the
/// slider moves; the static outputs write the slider's start value in its place.
#[test]
fn a_slider_placeholder_shows_the_start_value_in_static_outputs() {
    let dir = crate::common::scratch("browser-slider-label");
    let spec = dir.join("slid.json");
    std::fs::write(
        &spec,
        r#"{"id": "slid", "interactive": {"params": [{"name": "a", "range": [0.1, 1.0], "start": 0.3}]},
            "panels": [{"curves": [{"ndf": "beckmann", "alpha_b": {"slider": "a"}, "label": "slid to {=a}"},
                                   {"ndf": "ggx", "alpha_tr": 0.5}]}]}"#,
    )
    .unwrap();
    crate::common::render_into(&[&spec], &dir, "svg,html");
    let svg = std::fs::read_to_string(dir.join("slid.svg")).unwrap();
    assert!(
        svg.contains(">slid to 0.3<"),
        "the legend shows the start value"
    );
    assert!(!svg.contains("{=a}"));
    let page = std::fs::read_to_string(dir.join("slid.html")).unwrap();
    assert!(
        page.contains("slid to {=a}"),
        "the page keeps the placeholder"
    );
}
