//! Where specs come from, and reading them: spec files, folders of them, or the built-in
//! catalogue; each parsed and validated into a [`Scene`], every problem of every source reported
//! together, duplicate ids across sources included.
//!
//! The spec stage's entry point for a run of several specs; it reads only the spec files named.

use crate::catalogue::CATALOGUE;
use crate::error::{Error, Result};
use crate::input::{parse_json, read_file};
use crate::problem::{Problem, Problems};
use crate::scene::{self, Scene};
use std::path::{Path, PathBuf};

/// Command-line overrides of every scene's canvas.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct CanvasOverride {
    /// Figure width in CSS pixels; the height follows proportionally unless also given.
    pub width: Option<f64>,
    /// Figure height in CSS pixels.
    pub height: Option<f64>,
    /// PNG pixels per CSS pixel.
    pub png_scale: Option<f64>,
    /// Base font size in CSS pixels.
    pub font_px: Option<f64>,
}

/// A spec's source name, text, and the folder its data paths resolve against (`None` for the
/// built-in catalogue).
pub type Source = (String, String, Option<PathBuf>);

/// The spec sources named by `paths` (files, or folders whose `*.json` are taken sorted by name),
/// or the built-in catalogue when `paths` is empty.
pub fn sources(paths: &[PathBuf]) -> Result<Vec<Source>> {
    if paths.is_empty() {
        return Ok(CATALOGUE
            .iter()
            .map(|(name, text)| (format!("configs/{name}"), text.to_string(), None))
            .collect());
    }
    let mut sources = Vec::new();
    for path in paths {
        if path.is_dir() {
            let entries =
                std::fs::read_dir(path).map_err(|e| Error::io(path.display().to_string(), e))?;
            let mut files: Vec<PathBuf> = entries
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|x| x == "json") && p.is_file())
                .collect();
            files.sort();
            for file in files {
                let name = file.display().to_string();
                sources.push((name.clone(), read_file(&name)?, Some(path.clone())));
            }
        } else {
            let name = path.display().to_string();
            let folder = path.parent().map(Path::to_path_buf).unwrap_or_default();
            sources.push((name.clone(), read_file(&name)?, Some(folder)));
        }
    }
    Ok(sources)
}

/// Parses and validates every source; all problems of all sources are reported together, and
/// duplicate ids across sources are problems too. On success there is one scene per source, in
/// the order of `sources`.
pub fn load_scenes(sources: &[Source], canvas: CanvasOverride) -> Result<Vec<Scene>> {
    let mut scenes = Vec::new();
    let mut failures = Vec::new();
    for (name, text, base_dir) in sources {
        let parsed = parse_json(text, name).and_then(|node| {
            scene::parse(&node, base_dir.as_deref()).map_err(|list| Problems {
                source: name.clone(),
                list,
            })
        });
        match parsed.and_then(|s| apply_override(s, canvas, name)) {
            Ok(scene) => {
                if let Some(first) = scenes
                    .iter()
                    .position(|(_, other): &(String, Scene)| other.id == scene.id)
                {
                    failures.push(Problems {
                        source: name.clone(),
                        list: vec![Problem::new(
                            "id",
                            format!(
                                "duplicate id (got \"{}\", already used by {})",
                                scene.id, scenes[first].0
                            ),
                        )],
                    });
                } else {
                    scenes.push((name.clone(), scene));
                }
            }
            Err(problems) => failures.push(problems),
        }
    }
    if failures.is_empty() {
        Ok(scenes.into_iter().map(|(_, s)| s).collect())
    } else {
        Err(Error::Input(failures))
    }
}

fn apply_override(
    mut scene: Scene,
    over: CanvasOverride,
    source: &str,
) -> std::result::Result<Scene, Problems> {
    let canvas = &mut scene.canvas;
    let (w, h) = (f64::from(canvas.width_px), f64::from(canvas.height_px));
    let (width, height) = match (over.width, over.height) {
        (Some(width), None) => (width, h * width / w),
        (width, height) => (width.unwrap_or(w), height.unwrap_or(h)),
    };
    canvas.width_px = width.round().max(16.0) as u32;
    canvas.height_px = height.round().max(16.0) as u32;
    canvas.png_scale = over.png_scale.unwrap_or(canvas.png_scale);
    canvas.font_px = over.font_px.unwrap_or(canvas.font_px);
    scene::check_canvas(canvas).map_err(|message| Problems {
        source: source.to_string(),
        list: vec![Problem::new("", message)],
    })?;
    Ok(scene)
}
