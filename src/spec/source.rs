//! Where specs come from, and reading them: spec files, folders of them, or the built-in
//! catalogue; each parsed and validated into a [`Scene<Spec>`], every problem of every source
//! kept, duplicate ids across sources included.
//!
//! The spec stage's entry point for a run of several specs; it reads only the spec files named.
//! [`crate::pipeline::resolve::scenes`] takes what it returns.

use crate::error::{Error, Result};
use crate::problem::Problem;
use crate::spec::catalogue::CATALOGUE;
use crate::spec::datafile::DataScope;
use crate::spec::input::{parse_json, read_file};
use crate::spec::look::Theme;
use crate::spec::scene::{self, Invalid, Scene, Spec};
use rayon::prelude::*;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Command-line overrides of every scene's canvas and theme.
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
    /// The theme, instead of the spec's `theme` (`render --theme`).
    pub theme: Option<Theme>,
    /// A paper preset's size, text and resolution instead of the spec's (`render --preset`); the
    /// other overrides apply after it.
    pub preset: Option<crate::spec::look::Preset>,
}

/// The name of the spec read from standard input (`render -`), as problems name it.
pub const STDIN_SOURCE: &str = "stdin";

/// A spec's source name, text, and where its data files may be read from (`None` for the
/// built-in catalogue).
pub type Source = (String, String, Option<DataScope>);

/// The spec sources named by `paths` (files, folders whose `*.json` are taken sorted by name,
/// catalogue ids — a path that exists wins over an id — or `-` once, for a spec on standard input),
/// or the whole built-in catalogue when `paths` is empty. A folder with no `*.json` is a usage
/// error, not a silent run of nothing. A spec's data files may be read from its
/// folder (the working directory for stdin) and from the folders `allow_read`.
pub fn sources(paths: &[PathBuf], allow_read: &[PathBuf]) -> Result<Vec<Source>> {
    let allowed: Arc<[PathBuf]> = Arc::from(allow_read);
    let scope = |folder: PathBuf| Some(DataScope::new(folder, allowed.clone()));
    if paths.is_empty() {
        return Ok(CATALOGUE
            .iter()
            .map(|(name, text)| (format!("configs/{name}"), text.to_string(), None))
            .collect());
    }
    let stdin_count = paths.iter().filter(|p| p.as_os_str() == "-").count();
    if stdin_count > 1 {
        return Err(Error::Usage(format!(
            "-: stdin holds one spec and is read once (got - {stdin_count} times, expected at most once)"
        )));
    }
    let mut sources = Vec::new();
    for path in paths {
        if path.as_os_str() == "-" {
            let text = crate::spec::input::read_stdin().map_err(|e| Error::io(STDIN_SOURCE, e))?;
            sources.push((STDIN_SOURCE.to_string(), text, scope(PathBuf::from("."))));
        } else if path.is_dir() {
            let entries =
                std::fs::read_dir(path).map_err(|e| Error::io(path.display().to_string(), e))?;
            let mut files: Vec<PathBuf> = entries
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|x| x == "json") && p.is_file())
                .collect();
            if files.is_empty() {
                return Err(Error::Usage(format!(
                    "{}: no spec to render (got a folder with no *.json file, expected at least one)",
                    crate::problem::excerpt(&path.display().to_string())
                )));
            }
            files.sort();
            for file in files {
                let name = file.display().to_string();
                sources.push((name.clone(), read_file(&name)?, scope(path.clone())));
            }
        } else if let Some((file, text)) = path
            .to_str()
            .filter(|_| !path.exists())
            .and_then(crate::spec::catalogue::find)
        {
            sources.push((format!("configs/{file}"), text.to_string(), None));
        } else if !path.exists() {
            let name = path.display().to_string();
            return Err(Error::Usage(format!(
                "{name}: no such file, folder or catalogue id (see ndfplot list){}",
                crate::problem::suggestion(&name, crate::spec::catalogue::ids())
            )));
        } else {
            let name = path.display().to_string();
            let folder = path.parent().map(Path::to_path_buf).unwrap_or_default();
            sources.push((name.clone(), read_file(&name)?, scope(folder)));
        }
    }
    Ok(sources)
}

/// One source as the spec stage leaves it.
#[derive(Debug, Clone)]
pub struct Loaded {
    /// The source's name, as problems name it.
    pub source: String,
    /// Its validated scene, or its problems with the work it still describes.
    pub scene: std::result::Result<Scene<Spec>, Invalid>,
}

/// Parses and validates every source, in the order of `sources`; a source's problems (invalid
/// JSON, invalid spec, a canvas override out of range, an id already used by an earlier source)
/// are kept with it. Nothing is computed and no data file is read.
pub fn load_scenes(sources: &[Source], canvas: CanvasOverride) -> Vec<Loaded> {
    let invalid = |list| Invalid {
        problems: list,
        pending: Vec::new(),
    };
    let mut loaded: Vec<Loaded> = sources
        .par_iter()
        .map(|(name, text, data)| Loaded {
            source: name.clone(),
            scene: parse_json(text, name)
                .map_err(|p| invalid(p.list))
                .and_then(|node| scene::parse(&node, data.as_ref()))
                .and_then(|s| apply_override(s, canvas).map_err(|p| invalid(vec![p]))),
        })
        .collect();
    // The first source of each id, in source order; a later one is refused.
    let mut first: HashMap<String, String> = HashMap::new();
    for load in &mut loaded {
        let Ok(scene) = &load.scene else { continue };
        if let Some(earlier) = first.get(&scene.id) {
            let problem = Problem::new(
                "id",
                format!(
                    "duplicate id (got \"{}\", already used by {earlier})",
                    scene.id
                ),
            );
            load.scene = Err(invalid(vec![problem]));
        } else {
            first.insert(scene.id.clone(), load.source.clone());
        }
    }
    loaded
}

fn apply_override(
    mut scene: Scene<Spec>,
    over: CanvasOverride,
) -> std::result::Result<Scene<Spec>, Problem> {
    if let Some(preset) = over.preset {
        (scene.rows, scene.cols) = preset.grid(scene.panels.len(), (scene.rows, scene.cols));
        let titles = crate::spec::look::Titles {
            figure: scene.title.clone(),
            panels: scene.panels.iter().map(|p| p.axes.title.clone()).collect(),
        };
        scene.canvas = preset.canvas((scene.rows, scene.cols), scene.aspect_ratio, &titles);
    }
    let canvas = &mut scene.canvas;
    let (w, h) = (f64::from(canvas.width_px), f64::from(canvas.height_px));
    let (width, height) = match (over.width, over.height) {
        (Some(width), None) => (width, h * width / w),
        (width, height) => (width.unwrap_or(w), height.unwrap_or(h)),
    };
    if over.width.is_some() || over.height.is_some() {
        // A size in pixels replaces a printed one.
        canvas.print = None;
    }
    canvas.width_px = width.round().max(16.0) as u32;
    canvas.height_px = height.round().max(16.0) as u32;
    canvas.png_scale = over.png_scale.unwrap_or(canvas.png_scale);
    canvas.font_px = over.font_px.unwrap_or(canvas.font_px);
    scene.theme = over.theme.unwrap_or(scene.theme);
    scene::check_canvas(canvas).map_err(|message| Problem::new("", message))?;
    Ok(scene)
}
