//! Interactive pages: one self-contained HTML file per interactive scene that computes its curves
//! live in the browser, with a continuous slider and a number box per declared parameter, the
//! plot redrawn as they change, a legend, axis labels, a y-axis lock, a linear/log toggle for y on
//! NDF pages, "match peak" and "match L2" links on comparison pages, a permalink in the URL
//! fragment, and `window.ndfplot` for scripts (docs/contracts.md "Interactive page API").
//!
//! The page evaluates each curve with `html/maths.js`, a port of the Rust definitions `eval` uses
//! ([`maths`] embeds it with the parameter domains and the Fresnel basis, and tests their
//! agreement). This module only serializes the scene — sliders, each curve's canonical JSON at the
//! start values with the parameters its sliders drive, labels as templates, styles, axes — with the
//! script (`html/page.js`), the styles (`html/page.css`) and the template (`html/page.html`); no
//! network, fonts or libraries are needed, and the file opens from disk. With JavaScript off the
//! page shows the static figure `<id>.png` beside it. Bytes are deterministic.

mod maths;
mod mathtext;

pub use maths::REL_TOL_PAGE;

use crate::model::curve::Curve;
use crate::model::fresnel::Fresnel;
use crate::pipeline::figure::Figure;
use crate::spec::curve::Model;
use crate::spec::look::{Dash, LegendPlace, Scale, Style, XUnit};
use serde_json::{Value, json};

const TEMPLATE: &str = include_str!("html/page.html");
const SCRIPT: &str = include_str!("html/page.js");

const STYLES: &str = include_str!("html/page.css");

/// The page of `figure`, whose [`Page`](crate::pipeline::figure::Page) drives the curves of its
/// one panel; `None` for a figure without sliders.
pub fn page(figure: &Figure) -> Option<Vec<u8>> {
    let page = figure.page.as_ref()?;
    let interactive = &page.interactive;
    let axes = &figure.panels[0].axes;
    let curves: Vec<Value> = page
        .curves
        .iter()
        .zip(&interactive.entries)
        .map(|((curve, style), entry)| {
            let bindings: Vec<Value> = entry
                .bindings
                .iter()
                .map(|b| json!({"param": b.param, "slider": b.slider, "from_beckmann": b.from_beckmann}))
                .collect();
            json!({"curve": curve.canonical_json(), "label": entry.label, "style": style_json(style), "bindings": bindings})
        })
        .collect();
    let sliders: Vec<Value> = interactive
        .sliders
        .iter()
        .map(|s| json!({"name": s.name, "label": s.label, "min": s.min, "max": s.max, "start": s.start, "scale": scale_name(s.scale)}))
        .collect();
    let uses_basis = page.curves.iter().any(|(curve, _)| {
        matches!(
            curve,
            Curve::Fresnel(Fresnel::Belcour(..) | Fresnel::Basis(_))
        )
    });
    let ndf_page = page
        .curves
        .iter()
        .all(|(curve, _)| matches!(curve.model(), Model::Ndf(_)));
    let data = json!({
        "id": figure.id,
        "title": page.title,
        "panel_title": axes.title,
        "x_label": axes.x_label,
        "y_label": axes.y_label,
        "degrees": axes.x_unit == XUnit::Degrees,
        "theta": [axes.theta_range().0, axes.theta_range().1],
        "y_scale": scale_name(axes.y_scale),
        "log_toggle": ndf_page || axes.y_scale == Scale::Log,
        "y_range": axes.y_range.map(|(a, b)| [a, b]),
        "width": figure.canvas.width_px,
        "height": figure.canvas.height_px,
        "font_px": figure.canvas.font_px,
        "legend": axes.legend != LegendPlace::None,
        "tolerance": REL_TOL_PAGE,
        "sliders": sliders,
        "curves": curves,
        "domains": maths::domains(),
        "basis": uses_basis.then(|| maths::basis_json(&|values| json!(base64_f64(values)))),
    });
    // Inside <script>, "</" could close the element early: escape every '<' the JSON way.
    let data = data.to_string().replace('<', "\\u003c");
    let title = if page.title.is_empty() {
        figure.id.as_str()
    } else {
        page.title.as_str()
    };
    Some(
        fill(&[
            ("TITLE", &escape_html(title)),
            ("STYLES", STYLES),
            ("IMAGE", &escape_html(&format!("{}.png", figure.id))),
            ("DATA", &data),
            ("MATHS", &maths::script()),
            ("MATHTEXT", mathtext::SCRIPT),
            ("SCRIPT", SCRIPT),
        ])
        .into_bytes(),
    )
}

fn scale_name(scale: Scale) -> &'static str {
    match scale {
        Scale::Linear => "linear",
        Scale::Log => "log",
    }
}

/// Standard base64 (RFC 4648, with padding) of the values' little-endian f64 bytes: exact, and a
/// third the size of their decimal forms.
fn base64_f64(values: &[f64]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let bytes: Vec<u8> = values.iter().flat_map(|v| v.to_le_bytes()).collect();
    let mut text = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let n = chunk
            .iter()
            .enumerate()
            .fold(0u32, |n, (i, &b)| n | u32::from(b) << (16 - 8 * i));
        for i in 0..4 {
            if i <= chunk.len() {
                text.push(char::from(ALPHABET[(n >> (18 - 6 * i) & 0x3f) as usize]));
            } else {
                text.push('=');
            }
        }
    }
    text
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

/// The line style as the page draws it: colour, width (a multiple of the default) and dash.
fn style_json(style: &Style) -> Value {
    let c = style.colour;
    let dash = match style.dash {
        Dash::Solid => "solid",
        Dash::Dashed => "dashed",
        Dash::Dotted => "dotted",
    };
    json!({"colour": format!("#{:02x}{:02x}{:02x}", c.0, c.1, c.2), "width": style.width, "dash": dash})
}

#[cfg(test)]
mod tests {
    use super::base64_f64;

    #[test]
    fn base64_matches_rfc_4648_on_the_f64_bytes() {
        // 1.0 is 00 00 00 00 00 00 f0 3f little-endian.
        assert_eq!(base64_f64(&[1.0]), "AAAAAAAA8D8=");
        assert_eq!(base64_f64(&[]), "");
    }
}
