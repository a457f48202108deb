//! Interactive pages: one self-contained HTML file per interactive scene, with a slider per
//! declared parameter, the plot redrawn as a slider moves, a legend, axis labels and a linear/log
//! toggle for y.
//!
//! The page draws only values the pipeline sampled with `Curve::eval` (no formula exists in its
//! script): every curve of every frame arrives as the dyadic samples of its plan job
//! ([`crate::dyadic`]), is encoded compactly ([`samples`]), then embedded with the script (`html/page.js`), the styles (`html/page.css`) and the template
//! (`html/page.html`) — no network, fonts or libraries are needed, and the file opens from disk.
//! For Belcour reconstructions each frame also carries its coefficients c₀ … c₃ (and η, κ when
//! the material is given by Gulbrandsen's r, g) for the page to print. Bytes are deterministic.

mod maths;
mod samples;

use crate::curve::Curve;
use crate::dyadic;
use crate::fresnel::{Fresnel, Ior};
use crate::look::{Dash, XUnit, Scale};
use crate::sample::Evaluated;
use crate::scene::interactive::Interactive;
use crate::scene::{Scene, SceneCurve};
use serde_json::{Value, json};

pub use samples::PRECISION;

const TEMPLATE: &str = include_str!("html/page.html");
const SCRIPT: &str = include_str!("html/page.js");
const STYLES: &str = include_str!("html/page.css");

/// The page of `scene` with its `interactive` part, from the dyadic samples `evaluated[job]` of
/// each job of `feed`, one per curve of `interactive.curves()`, in that order.
pub fn page(
    scene: &Scene,
    interactive: &Interactive,
    feed: &[usize],
    evaluated: &[Evaluated],
) -> Vec<u8> {
    let panel = &scene.panels[0];
    let range = panel.axes.theta_range();
    let encoded = feed.iter().map(|&job| {
        let samples = evaluated[job]
            .dyadic
            .as_ref()
            .expect("a page's jobs are dyadic");
        samples::base64(&samples::encode(samples))
    });
    let mut encoded = encoded.into_iter();
    let mut styles: Vec<Value> = Vec::new();
    let entries: Vec<Value> = interactive
        .entries
        .iter()
        .map(|entry| {
            let frames: Vec<Value> = entry
                .frames
                .iter()
                .map(|frame| {
                    let curves: Vec<Value> = frame
                        .iter()
                        .map(|c| {
                            let style = style_json(c);
                            let index = styles.iter().position(|s| *s == style).unwrap_or_else(|| {
                                styles.push(style);
                                styles.len() - 1
                            });
                            json!({"label": c.label, "curve": c.curve.canonical_json(), "style": index, "data": encoded.next()})
                        })
                        .collect();
                    let readout: Vec<String> = frame.iter().filter_map(|c| readout(&c.curve)).collect();
                    if readout.is_empty() { json!({"curves": curves}) } else { json!({"curves": curves, "readout": readout.join("; ")}) }
                })
                .collect();
            json!({"sliders": entry.sliders, "frames": frames})
        })
        .collect();
    let sliders: Vec<Value> = interactive
        .sliders
        .iter()
        .map(|s| json!({"name": s.name, "label": s.label, "values": s.values, "start": s.start}))
        .collect();
    let data = json!({
        "id": scene.id,
        "title": scene.title,
        "panel_title": panel.axes.title,
        "x_label": panel.axes.x_label,
        "y_label": panel.axes.y_label,
        "degrees": panel.axes.x_unit == XUnit::Degrees,
        "theta": [range.0, range.1],
        "levels": [dyadic::COARSE_LEVELS, dyadic::FINE_LEVELS],
        "log_step": samples::LOG_STEP,
        "log_decades": dyadic::LOG_DECADES,
        "precision": PRECISION,
        "y_scale": if panel.axes.y_scale == Scale::Log { "log" } else { "linear" },
        "y_range": panel.axes.y_range.map(|(a, b)| [a, b]),
        "width": scene.canvas.width_px,
        "height": scene.canvas.height_px,
        "font_px": scene.canvas.font_px,
        "legend": panel.axes.legend != crate::look::LegendPlace::None,
        "sliders": sliders,
        "styles": styles,
        "entries": entries,
    });
    // Inside <script>, "</" could close the element early: escape every '<' the JSON way.
    let data = data.to_string().replace('<', "\\u003c");
    let title = if scene.title.is_empty() {
        scene.id.as_str()
    } else {
        scene.title.as_str()
    };
    fill(&[
        ("TITLE", &escape_html(title)),
        ("STYLES", STYLES),
        ("DATA", &data),
        ("SCRIPT", SCRIPT),
    ])
    .into_bytes()
}

/// The template with each `{{NAME}}` marker (each present once, in the given order) replaced; the
/// inserted text is never scanned for markers.
fn fill(parts: &[(&str, &str)]) -> String {
    let mut page = String::new();
    let mut rest = TEMPLATE;
    for (name, text) in parts {
        let marker = format!("{{{{{name}}}}}");
        let (before, after) = rest
            .split_once(&marker)
            .expect("the template has every marker once, in order");
        page.push_str(before);
        page.push_str(text);
        rest = after;
    }
    page.push_str(rest);
    page
}

fn escape_html(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

fn style_json(curve: &SceneCurve) -> Value {
    let c = curve.style.colour;
    let dash = match curve.style.dash {
        Dash::Solid => "solid",
        Dash::Dashed => "dashed",
        Dash::Dotted => "dotted",
    };
    json!({"colour": format!("#{:02x}{:02x}{:02x}", c.0, c.1, c.2), "width": curve.style.width, "dash": dash})
}

/// The coefficients of a Belcour reconstruction (with η, κ when given by r, g), as printed.
fn readout(curve: &Curve) -> Option<String> {
    let Curve::Fresnel(Fresnel::Belcour(ior, k)) = curve else {
        return None;
    };
    let coefficients = format!(
        "c₀ = {:.4}, c₁ = {:.4}, c₂ = {:.4}, c₃ = {:.4}",
        k.c0, k.c1, k.c2, k.c3
    );
    Some(match ior {
        Ior::Gulbrandsen { .. } => {
            let (eta, kappa) = ior.complex();
            format!("η = {eta:.4}, κ = {kappa:.4}; {coefficients}")
        }
        Ior::EtaKappa { .. } => coefficients,
    })
}
