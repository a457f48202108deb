//! The resolve stage: the numerics and reads a validated spec leaves pending. It turns a
//! [`Scene<Spec>`] into the [`Scene`] the plan takes: fits run ([`crate::model::fit`]), Belcour
//! reconstructions get their coefficients ([`Fresnel::belcour`]), labels are written out (a
//! Belcour curve's `l2_grid` error, a fitted value and its target) and CSV data files are read.
//!
//! A problem here (a fit that cannot reach its target, an unreadable data file) is reported with
//! its source and JSON path like a spec's own; for a spec with problems, the problems of the work
//! it still describes are reported with them ([`Invalid`]), so one run names them all.

use crate::error::{Error, Result};
use crate::model::curve::Curve;
use crate::model::curve::quantity::Prepared;
use crate::model::dataset::{Dataset, Side};
use crate::model::fit;
use crate::model::fresnel::Fresnel;
use crate::model::metrics::ThetaRange;
use crate::model::metrics::sampled::nodes;
use crate::pipeline::adaptive;
use crate::problem::{Problem, Problems, excerpt, join_key};
use crate::spec::curve::{self, CurveSpec, Fitted, Label, Model, ParamValue, Part};
use crate::spec::look::PanelKind;
use crate::spec::scene::data::{CsvFile, DataSpec, MAX_DATA_POINTS, SideSpec};
use crate::spec::scene::interactive::Slider;
use crate::spec::scene::{
    DEFAULT_SAMPLES, Invalid, MAX_INTEGRALS, MAX_POINTS_PER_SCENE, Pending, Sampling, Scene,
    SceneCurve, SceneData, ScenePanel, Spec,
};
use crate::spec::source::Loaded;
use rayon::prelude::*;
use std::f64::consts::FRAC_PI_2;

/// Resolves every source the spec stage read, in parallel, reported in order. Every problem of every source is reported
/// together: a valid spec's resolve problems, an invalid spec's own problems followed by those of
/// the work it describes.
pub fn scenes(loaded: Vec<Loaded>) -> Result<Vec<Scene>> {
    let resolved: Vec<_> = loaded
        .into_par_iter()
        .map(|Loaded { source, scene }| {
            let resolved = match scene {
                Ok(spec) => self::scene(spec),
                Err(Invalid {
                    mut problems,
                    pending,
                }) => {
                    for problem in pending_problems(&pending) {
                        push_once(&mut problems, problem);
                    }
                    Err(problems)
                }
            };
            (source, resolved)
        })
        .collect();
    let mut scenes = Vec::with_capacity(resolved.len());
    let mut failures = Vec::new();
    for (source, resolved) in resolved {
        match resolved {
            Ok(scene) => scenes.push(scene),
            Err(list) => failures.push(Problems { source, list }),
        }
    }
    if failures.is_empty() {
        Ok(scenes)
    } else {
        Err(Error::Input(failures))
    }
}

/// Resolves one valid spec; every problem is returned with its JSON path.
pub fn scene(spec: Scene<Spec>) -> std::result::Result<Scene, Vec<Problem>> {
    let mut problems = Vec::new();
    let sliders = spec
        .interactive
        .as_ref()
        .map_or(&[][..], |i| &i.sliders[..]);
    let panels: Vec<ScenePanel> = spec
        .panels
        .into_iter()
        .map(|panel| {
            let data: Vec<SceneData> = panel
                .data
                .into_iter()
                .filter_map(|d| scene_data(d).map_err(|p| push_once(&mut problems, p)).ok())
                .collect();
            let mut axes = panel.axes;
            if axes.title.is_empty() {
                axes.title = data.iter().find_map(audit_title).unwrap_or_default();
            }
            ScenePanel {
                axes,
                curves: at_slider_starts(resolve_curves(&panel.curves, &mut problems), sliders),
                data,
            }
        })
        .collect();
    if !problems.is_empty() {
        return Err(problems);
    }
    if let Some(problem) = check_points(spec.sampling, &panels) {
        return Err(vec![problem]);
    }
    if let Some(problem) = check_integrals(spec.sampling, &panels) {
        return Err(vec![problem]);
    }
    Ok(Scene {
        id: spec.id,
        title: spec.title,
        rows: spec.rows,
        cols: spec.cols,
        canvas: spec.canvas,
        aspect_ratio: spec.aspect_ratio,
        sampling: spec.sampling,
        theme: spec.theme,
        panels,
        interactive: spec.interactive,
    })
}

/// The curve a description stands for: a Belcour reconstruction's coefficients computed, a fit
/// run, a published fit's parameters looked up. Only a fit can fail.
pub fn curve(spec: &CurveSpec) -> std::result::Result<Curve, Problem> {
    Ok(match spec {
        CurveSpec::Ready(curve) => curve.clone(),
        CurveSpec::Belcour(ior) => Curve::Fresnel(Fresnel::belcour(*ior)),
        CurveSpec::Fitted(fitted) => self::fitted(fitted)?.0,
        CurveSpec::Published(preset) => Curve::Ndf(preset.ndf()),
        CurveSpec::Difference { op, a, b } => Curve::Difference {
            op: *op,
            a: Box::new(curve(a)?),
            b: Box::new(curve(b)?),
        },
        CurveSpec::Transformed {
            transform,
            curve: inner,
        } => Curve::Transformed {
            transform: *transform,
            curve: Box::new(curve(inner)?),
        },
        CurveSpec::Quantity { quantity, ndf } => Curve::Quantity {
            quantity: quantity.map_fresnel(curve)?,
            ndf: ndf_of(curve(ndf)?),
            prepared: Prepared::default(),
        },
    })
}

/// The NDF of a resolved NDF curve (what a quantity wraps: a plain, fitted or published NDF).
fn ndf_of(curve: Curve) -> crate::model::ndf::Ndf {
    match curve {
        Curve::Ndf(ndf) => ndf,
        other => unreachable!("the spec stage wraps only NDF curves in a quantity: {other:?}"),
    }
}

/// Reads a CSV data file within its [`DataScope`](crate::spec::datafile::DataScope): its two columns as
/// finite numbers, θ converted to radians and checked within [0, π/2]. Problems are reported at the
/// entry's `path` key, quoting the path (as an excerpt) and no more of the file than an excerpt of
/// its header.
pub fn csv(file: &CsvFile) -> std::result::Result<Dataset, Problem> {
    let path = &file.path;
    let (x, y) = file
        .scope
        .read(path)
        .and_then(|bytes| read_columns(&bytes, &file.x_column, &file.y_column))
        .map_err(|message| {
            Problem::new(
                &file.at,
                format!("cannot read \"{}\": {message}", excerpt(path)),
            )
        })?;
    let to_radians = if file.degrees {
        std::f64::consts::PI / 180.0
    } else {
        1.0
    };
    let x: Vec<f64> = x.into_iter().map(|v| v * to_radians).collect();
    if let Some(bad) = x.iter().find(|&&t| !(0.0..=FRAC_PI_2).contains(&t)) {
        let unit = if file.degrees {
            "degrees within [0, 90]"
        } else {
            "radians within [0, π/2]"
        };
        return Err(Problem::new(
            &file.at,
            format!(
                "θ out of range in \"{}\" (got {:?}, expected {unit})",
                excerpt(path),
                bad / to_radians
            ),
        ));
    }
    Ok(Dataset::Csv {
        path: path.clone(),
        x_column: file.x_column.clone(),
        y_column: file.y_column.clone(),
        degrees: file.degrees,
        x,
        y,
    })
}

/// Records `problem` unless an equal one is already recorded (a fit shared by several curves
/// fails once).
fn push_once(problems: &mut Vec<Problem>, problem: Problem) {
    if !problems.contains(&problem) {
        problems.push(problem);
    }
}

/// The problems of the fallible work an invalid spec describes.
fn pending_problems(pending: &[Pending]) -> Vec<Problem> {
    pending
        .iter()
        .filter_map(|work| match work {
            Pending::Fit(fitted) => self::fitted(fitted).err(),
            Pending::Csv(file) => csv(file).err(),
        })
        .collect()
}

fn scene_curve(spec: &SceneCurve<Spec>) -> std::result::Result<SceneCurve, Problem> {
    let (curve, label) = labelled(&spec.curve, &spec.label)?;
    Ok(SceneCurve {
        curve,
        label,
        style: spec.style,
    })
}

/// The default title of a panel showing an engine table's audit: its largest |engine − exact| and
/// where, the numbers `albedo --against` reports (`max |error| = 9.917×10^{−7} at μ =
/// 0.645, r = 0.161`).
fn audit_title(data: &SceneData) -> Option<String> {
    let Dataset::Audit { cells, .. } = &data.dataset else {
        return None;
    };
    let audit = crate::model::metrics::table::TableAudit::of(cells);
    let worst = cells[audit.worst];
    let sci = format!("{:.3e}", audit.max_abs);
    let (mantissa, exponent) = sci.split_once('e').unwrap_or((&sci, "0"));
    let value = match exponent {
        "0" => mantissa.to_string(),
        e => format!("{mantissa}×10^{{{}}}", e.replace('-', "−")),
    };
    Some(format!(
        "max |error| = {value} at μ = {:.3}, r = {:.3}",
        worst.mu, worst.r
    ))
}

fn scene_data(spec: SceneData<Spec>) -> std::result::Result<SceneData, Problem> {
    let (dataset, label) = match spec.dataset {
        DataSpec::Ready(dataset) => (dataset, spec.label),
        DataSpec::Csv(file) => (csv(&file)?, spec.label),
        DataSpec::Audit(table) => {
            let cells = table.audit().map_err(|e| {
                Problem::new(
                    "",
                    format!("{}: {e} (expected a convergent integral)", table.name()),
                )
            })?;
            (Dataset::Audit { table, cells }, spec.label)
        }
        DataSpec::Difference {
            op,
            a,
            b,
            template,
            at,
        } => {
            let ((a, a_text), (b, b_text)) = (side(*a)?, side(*b)?);
            if let Err(e) = nodes(&a.operand(), &b.operand(), ThetaRange::FULL) {
                return Err(Problem::new(
                    at,
                    format!("a and b have no θ in common to take their difference at ({e})"),
                ));
            }
            let text = match template {
                Some(t) => t.replace("{a}", &a_text).replace("{b}", &b_text),
                None => format!("{a_text} {} {b_text}", op.sign()),
            };
            let dataset = Dataset::Difference {
                op,
                a: Box::new(a),
                b: Box::new(b),
            };
            (dataset, text)
        }
    };
    Ok(SceneData {
        dataset,
        label,
        style: spec.style,
    })
}

/// One operand of a difference with a sampled side, resolved, and its label.
fn side(spec: SideSpec) -> std::result::Result<(Side, String), Problem> {
    match spec {
        SideSpec::Curve(c) => {
            let (curve, text) = labelled(&c.curve, &c.label)?;
            Ok((Side::Curve(curve), text))
        }
        SideSpec::Sampled { data, label } => {
            let dataset = match data {
                DataSpec::Csv(file) => csv(&file)?,
                DataSpec::Ready(dataset) => dataset,
                DataSpec::Difference { .. } | DataSpec::Audit(_) => {
                    unreachable!("a side is a series of θ")
                }
            };
            Ok((Side::Sampled(dataset), label))
        }
    }
}

/// Resolves `specs` in order; the problems of those that fail go to `problems`.
fn resolve_curves(specs: &[SceneCurve<Spec>], problems: &mut Vec<Problem>) -> Vec<SceneCurve> {
    specs
        .iter()
        .filter_map(|c| scene_curve(c).map_err(|p| push_once(problems, p)).ok())
        .collect()
}

/// `curves` with each slider's `{=name}` in their labels written as the slider's start value:
/// what a static output shows of a label the interactive page updates as the slider moves.
fn at_slider_starts(mut curves: Vec<SceneCurve>, sliders: &[Slider]) -> Vec<SceneCurve> {
    for curve in &mut curves {
        for slider in sliders {
            let placeholder = format!("{{={}}}", slider.name);
            if curve.label.contains(&placeholder) {
                let start = crate::spec::numbers::significant(slider.start, TEMPLATE_DIGITS);
                curve.label = curve.label.replace(&placeholder, &start);
            }
        }
    }
    curves
}

/// A fit's outcome: the fitted value and the legend text of its target.
struct FitOutcome {
    value: f64,
    target_label: String,
}

/// Runs a fit and builds the fitted NDF; a fit that cannot reach its target is reported at the
/// fitted key.
fn fitted(fitted: &Fitted) -> std::result::Result<(Curve, FitOutcome), Problem> {
    let (target, target_label) = labelled(&fitted.target, &fitted.target_label)?;
    let at = join_key(&fitted.path, fitted.name());
    let value = fit::fit(&target, fitted.family, &fitted.fixed, fitted.by)
        .map_err(|e| {
            Problem::new(
                &at,
                format!("fit to {target_label}: {}: {}", e.key, e.message),
            )
        })?
        .free[0]
        .1;
    let mut values: Vec<f64> = fitted.fixed.iter().map(|(_, v)| *v).collect();
    values.insert(fitted.free, value);
    let ndf = fitted
        .family
        .build(&values)
        .map_err(|e| curve::domain_problem(&e, &fitted.path))?;
    Ok((
        Curve::Ndf(ndf),
        FitOutcome {
            value,
            target_label,
        },
    ))
}

/// A scene curve's curve and its label written out, from their descriptions.
fn labelled(spec: &CurveSpec, label: &Label) -> std::result::Result<(Curve, String), Problem> {
    match (spec, label) {
        // A view transform leaves the label of its curve as it is.
        (CurveSpec::Transformed { transform, curve }, _) => {
            let (curve, text) = labelled(curve, label)?;
            let curve = Curve::Transformed {
                transform: *transform,
                curve: Box::new(curve),
            };
            Ok((curve, text))
        }
        (
            CurveSpec::Difference { op, a, b },
            Label::Difference {
                template,
                sign,
                a: a_label,
                b: b_label,
            },
        ) => {
            let (a, a_text) = labelled(a, a_label)?;
            let (b, b_text) = labelled(b, b_label)?;
            let text = match template {
                Some(t) => t.replace("{a}", &a_text).replace("{b}", &b_text),
                None => format!("{a_text} {sign} {b_text}"),
            };
            let curve = Curve::Difference {
                op: *op,
                a: Box::new(a),
                b: Box::new(b),
            };
            Ok((curve, text))
        }
        // A quantity's automatic label adds the options that are not its defaults.
        // A template's {e_avg} is an albedo's average.
        (CurveSpec::Quantity { quantity, ndf }, _) => {
            let (inner, mut text) = labelled(ndf, label)?;
            let quantity = quantity.map_fresnel(curve)?;
            let ndf = ndf_of(inner);
            let prepared = Prepared::default();
            match label {
                Label::Auto(_) => {
                    for part in crate::spec::quantity::label_parts(&quantity) {
                        if !text.is_empty() {
                            text += ", ";
                        }
                        text += &part;
                    }
                }
                _ if text.contains(crate::spec::quantity::E_AVG_PLACEHOLDER) => {
                    if let Some(average) = quantity.label_average(&ndf, &prepared) {
                        text = text.replace(
                            crate::spec::quantity::E_AVG_PLACEHOLDER,
                            &format!("{average:.4}"),
                        );
                    }
                }
                _ => {}
            }
            Ok((
                Curve::Quantity {
                    quantity,
                    ndf,
                    prepared,
                },
                text,
            ))
        }
        (CurveSpec::Fitted(fitted), _) => {
            let (curve, outcome) = self::fitted(fitted)?;
            let text = text(label, &curve, Some((fitted, &outcome)));
            Ok((curve, text))
        }
        _ => {
            let curve = curve(spec)?;
            let text = text(label, &curve, None);
            Ok((curve, text))
        }
    }
}

/// The text of an automatic or template label of `curve`, with the outcome of its fit if it has
/// one.
fn text(label: &Label, curve: &Curve, fit: Option<(&Fitted, &FitOutcome)>) -> String {
    match label {
        Label::Auto(parts) => {
            let parts: Vec<String> = parts
                .iter()
                .map(|part| match (part, fit) {
                    (Part::Text(text), _) => text.clone(),
                    (Part::Fitted, Some((fitted, outcome))) => format!(
                        "{} = {} ({} fit to {})",
                        curve::symbol(fitted.name()),
                        crate::spec::numbers::significant(
                            outcome.value,
                            crate::spec::numbers::LEGEND_DIGITS
                        ),
                        fitted.by.name(),
                        outcome.target_label
                    ),
                    (Part::Fitted, None) => {
                        unreachable!("the spec stage gives a fitted part only to a fitted curve")
                    }
                })
                .chain(engine_part(curve))
                .collect();
            with_family_prefix(curve, &parts.join(", "), fit.is_some())
        }
        Label::Template { template, values } => {
            // A fitted value is computed: shown to the legend's digits, as written values are not.
            let fitted_value = fit.map(|(_, outcome)| {
                ParamValue::Number(
                    crate::spec::numbers::significant(
                        outcome.value,
                        crate::spec::numbers::LEGEND_DIGITS,
                    )
                    .parse()
                    .unwrap_or(outcome.value),
                )
            });
            let values: Vec<(&str, ParamValue)> = values
                .iter()
                .filter_map(|(name, value)| Some((*name, value.or(fitted_value)?)))
                .collect();
            fill_template(template, curve, &values)
        }
        Label::Difference { .. } => {
            unreachable!("the spec stage gives a difference label only to a difference")
        }
    }
}

/// The engine of a curve a renderer computes, as the last part of its automatic label.
fn engine_part(curve: &Curve) -> Option<String> {
    match curve {
        Curve::Emulated(emulation) => Some(emulation.engine().name().to_string()),
        _ => None,
    }
}

/// Prefixes the family's [`legend_prefix`](crate::model::ndf::Family::legend_prefix) where it has one,
/// and a `fitted` curve's family title where it has none (`Beckmann α_b = 0.3 (peak fit to …)`): a
/// fit's label names what was fitted. Belcour reconstructions also show their `l2_grid` error, to
/// two decimals as the notebook prints it.
fn with_family_prefix(curve: &Curve, text: &str, fitted: bool) -> String {
    match curve.model() {
        Model::Ndf(family) => match family.legend_prefix() {
            Some(prefix) => format!("{prefix} {text}"),
            None if fitted => format!("{} {text}", family.title()),
            None => text.to_string(),
        },
        Model::Fresnel(model) => {
            let l2 = belcour_l2(curve).map_or(String::new(), |l2| format!(", L2 = {l2:.2}"));
            format!("{} {text}{l2}", crate::spec::look::literal(model.name()))
                .trim_end()
                .to_string()
        }
    }
}

/// The `l2_grid` error of a Belcour reconstruction against the exact Fresnel.
fn belcour_l2(curve: &Curve) -> Option<f64> {
    match curve {
        Curve::Fresnel(Fresnel::Belcour(ior, coefficients)) => {
            Some(coefficients.l2_grid(ior.index()))
        }
        _ => None,
    }
}

/// Most significant digits of a number a label template shows.
const TEMPLATE_DIGITS: usize = 4;

/// Replaces `{param}` in a label template by the parameter's value (`"TS {alpha_ts}"`), and `{l2}`
/// by a Belcour reconstruction's error (two decimals, as the notebook prints it).
fn fill_template(template: &str, curve: &Curve, values: &[(&str, ParamValue)]) -> String {
    let mut label = template.to_string();
    if let Some(l2) = belcour_l2(curve) {
        label = label.replace(curve::L2_PLACEHOLDER, &format!("{l2:.2}"));
    }

    for (name, value) in values {
        let text = match value {
            // Written values keep four digits (`0.2027`), converted ones lose the rest
            // (`20.2222` → `20.22`); the CSV has them exactly.
            ParamValue::Number(v) => crate::spec::numbers::significant(*v, TEMPLATE_DIGITS),
            ParamValue::Flag(b) => b.to_string(),
        };
        label = label.replace(&format!("{{{name}}}"), &text);
    }
    label
}

/// A problem when a scene's table would exceed [`MAX_POINTS_PER_SCENE`]: curves × uniform samples
/// plus the points of its data series, known once its data files are read.
fn check_points(sampling: Sampling, panels: &[ScenePanel]) -> Option<Problem> {
    let per_curve = match sampling.for_table() {
        Sampling::Uniform(n) => n,
        _ => 0,
    };
    let curves: usize = panels.iter().map(|p| p.curves.len()).sum();
    let data: usize = panels
        .iter()
        .flat_map(|p| &p.data)
        .map(|d| d.dataset.len())
        .sum();
    let total = curves.saturating_mul(per_curve).saturating_add(data);
    (total > MAX_POINTS_PER_SCENE).then(|| {
        Problem::new(
            "sampling",
            format!("too many points in one scene (got {curves} curves × {per_curve} samples + {data} data points = {total}, expected at most {MAX_POINTS_PER_SCENE})"),
        )
    })
}

/// A problem when a scene would compute more than [`MAX_INTEGRALS`] integrals (albedo values):
/// each curve's integrals per value × (its table's samples + the most its drawing evaluates).
/// Named at the first panel with curves of integrals, before any is computed.
fn check_integrals(sampling: Sampling, panels: &[ScenePanel]) -> Option<Problem> {
    let table = match sampling.for_table() {
        Sampling::Uniform(n) => n,
        _ => DEFAULT_SAMPLES,
    };
    let mut total = 0usize;
    let mut curves = 0usize;
    let mut first = None;
    for (p, panel) in panels.iter().enumerate() {
        let drawn = match (sampling.for_drawing(), &panel.axes.kind) {
            (Sampling::Uniform(n), _) => n,
            (_, PanelKind::Surface { .. } | PanelKind::Heatmap { .. }) => DEFAULT_SAMPLES,
            _ => adaptive::INITIAL_POINTS + adaptive::MAX_INTEGRAL_EVALUATIONS,
        };
        for shown in &panel.curves {
            let per_value = shown.curve.integrals_per_value();
            if per_value == 0 {
                continue;
            }
            first.get_or_insert(p);
            curves += 1;
            total = total.saturating_add(per_value.saturating_mul(table.saturating_add(drawn)));
        }
    }
    let p = first?;
    (total > MAX_INTEGRALS).then(|| {
        Problem::new(
            format!("panels[{p}]"),
            format!("too much integration in one scene (got {curves} curves of albedo values needing up to {total} integrals, expected at most {MAX_INTEGRALS}: fewer curves, or fewer samples with \"sampling\")"),
        )
    })
}

/// The columns `x_column` and `y_column` of the CSV text `bytes` (with a header), as finite
/// numbers; a column named twice is refused, not picked. Messages quote no cell, and of the header
/// only an [`excerpt`].
fn read_columns(
    bytes: &[u8],
    x_column: &str,
    y_column: &str,
) -> std::result::Result<(Vec<f64>, Vec<f64>), String> {
    let mut csv = csv::Reader::from_reader(bytes);
    let headers = csv.headers().map_err(|e| e.to_string())?.clone();
    let column = |name: &str| {
        let mut found = headers.iter().enumerate().filter(|(_, h)| h.trim() == name);
        match (found.next(), found.next()) {
            (Some((i, _)), None) => Ok(i),
            (Some(_), Some(_)) => Err(format!(
                "column \"{}\" appears more than once in the header (expected each name once)",
                excerpt(name)
            )),
            (None, _) => {
                let names: Vec<&str> = headers.iter().map(str::trim).collect();
                Err(format!(
                    "no column \"{}\" (expected one of: {})",
                    excerpt(name),
                    excerpt(&names.join(", "))
                ))
            }
        }
    };
    let (xi, yi) = (column(x_column)?, column(y_column)?);
    let (mut x, mut y) = (Vec::new(), Vec::new());
    for (row, record) in csv.records().enumerate() {
        let record = record.map_err(|e| e.to_string())?;
        let number = |i: usize, name: &str| -> std::result::Result<f64, String> {
            let text = record.get(i).unwrap_or("").trim();
            text.parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| {
                    format!(
                        "row {}: column \"{}\" is not a finite number",
                        row + 2,
                        excerpt(name)
                    )
                })
        };
        x.push(number(xi, x_column)?);
        y.push(number(yi, y_column)?);
        if x.len() > MAX_DATA_POINTS {
            return Err(format!("more than {MAX_DATA_POINTS} rows"));
        }
    }
    if x.is_empty() {
        return Err("no data rows".into());
    }
    Ok((x, y))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spec::json;

    fn resolve(text: &str) -> std::result::Result<Scene, Vec<String>> {
        let spec = crate::spec::scene::parse(&json::parse(text).unwrap(), None).unwrap();
        scene(spec).map_err(|list| {
            list.iter()
                .map(|p| format!("{}: {}", p.at, p.message))
                .collect()
        })
    }

    #[test]
    fn labels_are_written_out_from_the_resolved_curves() {
        let scene = resolve(
            r#"{"id": "s", "panels": [{"curves": [
                {"ndf": "abc", "alpha_abc2": 1.75, "alpha_abc1": {"fit": {"target": {"ndf": "ggx", "alpha_tr": 0.4}}}},
                {"ndf": "abc", "alpha_abc2": 1.75, "label": "{alpha_abc1} by {alpha_abc2}",
                 "alpha_abc1": {"fit": {"target": {"ndf": "ggx", "alpha_tr": 0.4}}}},
                {"difference": "minus", "a": {"ndf": "ggx", "alpha_tr": [0.4, 0.6]}, "b": {"ndf": "ggx", "alpha_tr": 0.5}},
                {"ndf": "beckmann", "alpha_b": {"fit": {"target": {"ndf": "ggx", "alpha_tr": 0.3}}}},
                {"ndf": "beckmann", "alpha_b": 0.3}]}]}"#,
        )
        .unwrap();
        let labels: Vec<&str> = scene.panels[0]
            .curves
            .iter()
            .map(|c| c.label.as_str())
            .collect();
        assert!(
            labels[0].ends_with("a₁ = 11.6 (peak fit to α_{tr} = 0.4)"),
            "{labels:?}"
        );
        assert_eq!(labels[1], "11.6 by 1.75", "a fitted value to three digits");
        assert_eq!(
            labels[2..4],
            ["α_{tr} = 0.4 − α_{tr} = 0.5", "α_{tr} = 0.6 − α_{tr} = 0.5"]
        );
        // A fit names the family it fitted, even one whose parameter alone would not.
        assert_eq!(
            labels[4..],
            ["Beckmann α_b = 0.3 (peak fit to α_{tr} = 0.3)", "α_b = 0.3"]
        );
    }
}
