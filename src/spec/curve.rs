//! The curve format shared by `eval`, `compare`, `fit` and scenes: a JSON object naming a model
//! (`"ndf": <family>` or `"fresnel": <model>`) and its parameters by the notebooks' names.
//!
//! This module owns the key rules (which keys a curve accepts, missing and exclusive keys; unknown
//! and duplicate keys are reported through [`crate::spec::keys`]), the validated description of a curve
//! ([`CurveSpec`]) and of its legend label ([`Label`]), and the canonical JSON. It computes nothing:
//! a Belcour reconstruction's coefficients and a fitted parameter are left to [`crate::pipeline::resolve`],
//! which turns a [`CurveSpec`] into the [`Curve`] the later stages evaluate. It does not expand
//! sweeps: scenes resolve the keys here, expand each parameter's values themselves, then call
//! [`Keyed::build`] per combination.

use crate::model::curve::quantity::{Quantity, ThetaI};
use crate::model::curve::{Curve, DiffOp, Kind};
use crate::model::domain::DomainError;
use crate::model::fit::By;
use crate::model::fresnel::{self, Fresnel, FresnelModel, Ior, SchlickF0};
use crate::model::metal::Metal;
use crate::model::ndf::Family;
use crate::model::published::{Channel, Preset, PresetError, Source};
use crate::model::renderer::{self, Emulation, Engine, Lobe, Refusal, Target, Width};
use crate::model::transform::Transform;
use crate::problem::{Problem, join_index, join_key, suggestion};
use crate::spec::json::{Node, Value};
use crate::spec::keys::{self, Accepted};
use crate::spec::quantity;
use serde::ser::{Serialize, SerializeMap, Serializer};

impl Curve {
    /// The model this curve belongs to; for a difference, the model of its first operand (both
    /// operands share their kind, so `model().key()` is the difference's kind, `ndf` or `fresnel`).
    pub fn model(&self) -> Model {
        match self {
            Curve::Ndf(d) => Model::Ndf(d.family()),
            Curve::Fresnel(f) => Model::Fresnel(FresnelModel::from(f)),
            Curve::Difference { a, .. } => a.model(),
            Curve::Transformed { curve, .. } => curve.model(),
            Curve::Quantity { ndf, .. } => Model::Ndf(ndf.family()),
            Curve::Emulated(emulation) => match emulation.target() {
                Target::D(lobe, _) | Target::G1(lobe, _) | Target::G2 { lobe, .. } => {
                    Model::Ndf(lobe.family())
                }
                Target::Schlick(_) => Model::Fresnel(FresnelModel::Schlick),
                Target::Dielectric(_) => Model::Fresnel(FresnelModel::Exact),
            },
        }
    }

    /// Parameters in canonical order, with their values (a quantity's, its NDF's); none for a
    /// difference (its operands carry them).
    pub fn params(&self) -> Vec<(&'static str, ParamValue)> {
        match self {
            Curve::Ndf(d) | Curve::Quantity { ndf: d, .. } => {
                let names = d.family().param_names();
                names
                    .iter()
                    .zip(d.params())
                    .map(|(&n, v)| (n, ParamValue::Number(v)))
                    .collect()
            }
            Curve::Fresnel(f) => fresnel_params(f),
            Curve::Difference { .. } | Curve::Transformed { .. } => vec![],
            Curve::Emulated(emulation) => {
                let target = emulation.target();
                let param = match (target, target.width()) {
                    (Target::Schlick(f0), _) => (fresnel::F0.name, f0),
                    (Target::Dielectric(eta), _) => {
                        return ior_params(&Ior::EtaKappa { eta, kappa: 0.0 });
                    }
                    (_, Some(Width::Roughness(r))) => (renderer::ROUGHNESS.name, r),
                    (_, Some(Width::Alpha(alpha))) => (self.model_family_param(), alpha),
                    (_, None) => unreachable!("only the Fresnel targets have no width"),
                };
                vec![(param.0, ParamValue::Number(param.1))]
            }
        }
    }

    /// Canonical curve JSON (docs/contracts.md): compact, model key first, parameters in docs/maths.md's
    /// order, numbers in shortest round-trip form, aliases replaced by canonical names. A
    /// difference is `{"difference":"minus"|"ratio"|"relative"|"log-ratio","a":{…},"b":{…}}`, a transformed curve
    /// `{"transform":"projected"|"slope","curve":{…}}`.
    pub fn canonical_json(&self) -> String {
        crate::spec::json::to_string(self)
    }
}

impl Serialize for Curve {
    /// The members of canonical curve JSON, in order (see [`Curve::canonical_json`]).
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match self {
            Curve::Difference { op, a, b } => serialize_difference(serializer, *op, a, b),
            Curve::Transformed { transform, curve } => {
                serialize_transformed(serializer, *transform, curve)
            }
            Curve::Ndf(_) | Curve::Fresnel(_) => {
                serialize_model(serializer, self.model(), &self.params())
            }
            Curve::Quantity { quantity, .. } => quantity::serialize_curve(
                serializer,
                |map| write_model(map, self.model(), &self.params()),
                quantity,
            ),
            Curve::Emulated(emulation) => {
                let mut map = serializer.serialize_map(None)?;
                write_model(&mut map, self.model(), &self.params())?;
                if let Some(quantity) = emulated_quantity(emulation) {
                    quantity::serialize_members(&mut map, &quantity)?;
                }
                map.serialize_entry(ENGINE_KEY, emulation.engine().name())?;
                map.end()
            }
        }
    }
}

impl Curve {
    /// The first parameter of the curve's NDF family (its width: `alpha_tr`, `alpha_b`).
    fn model_family_param(&self) -> &'static str {
        match self.model() {
            Model::Ndf(family) => family.param_names()[0],
            Model::Fresnel(_) => fresnel::F0.name,
        }
    }
}

/// The key naming the renderer whose computation a curve shows.
pub const ENGINE_KEY: &str = "engine";

/// The quantity other than D that an emulated NDF curve shows, as curve JSON names it (its G2 the
/// engine's).
fn emulated_quantity(emulation: &Emulation) -> Option<Quantity<Curve>> {
    match emulation.target() {
        Target::G1(..) => Some(Quantity::G1),
        Target::G2 { theta_i, .. } => Some(Quantity::G2 {
            model: emulation.engine().g2_model(),
            theta_i: theta_i.map_or(ThetaI::Same, ThetaI::Fixed),
        }),
        Target::D(..) | Target::Schlick(_) | Target::Dielectric(_) => None,
    }
}

/// `{"difference": op, "a": a, "b": b}`.
fn serialize_difference<S: Serializer, T: Serialize>(
    serializer: S,
    op: DiffOp,
    a: &T,
    b: &T,
) -> Result<S::Ok, S::Error> {
    let mut map = serializer.serialize_map(None)?;
    map.serialize_entry(DIFFERENCE_KEY, op.name())?;
    map.serialize_entry("a", a)?;
    map.serialize_entry("b", b)?;
    map.end()
}

/// `{"transform": transform, "curve": curve}`.
fn serialize_transformed<S: Serializer, T: Serialize>(
    serializer: S,
    transform: Transform,
    curve: &T,
) -> Result<S::Ok, S::Error> {
    let mut map = serializer.serialize_map(None)?;
    map.serialize_entry(TRANSFORM_KEY, transform.name())?;
    map.serialize_entry("curve", curve)?;
    map.end()
}

/// The model key and name, then each parameter.
fn serialize_model<S: Serializer, V: Serialize>(
    serializer: S,
    model: Model,
    params: &[(&'static str, V)],
) -> Result<S::Ok, S::Error> {
    let mut map = serializer.serialize_map(None)?;
    write_model(&mut map, model, params)?;
    map.end()
}

/// Writes the model key and name, then each parameter, into `map`.
fn write_model<M: SerializeMap, V: Serialize>(
    map: &mut M,
    model: Model,
    params: &[(&'static str, V)],
) -> Result<(), M::Error> {
    map.serialize_entry(model.key(), model.name())?;
    for (name, value) in params {
        map.serialize_entry(name, value)?;
    }
    Ok(())
}

/// A validated curve as a spec describes it: every key and domain checked, nothing computed.
/// [`crate::pipeline::resolve`] turns it into a [`Curve`], computing what it leaves pending.
#[derive(Debug, Clone, PartialEq)]
pub enum CurveSpec {
    /// A curve that takes no numerics to build (NDFs, exact and approximate Fresnel curves, basis
    /// functions): evaluable as it is.
    Ready(Curve),
    /// The Belcour–Bati–Barla reconstruction of a material, by its index only; resolve computes
    /// the coefficients ([`Fresnel::belcour`]).
    Belcour(Ior),
    /// An NDF with one parameter fitted to a target curve; resolve runs the fit.
    Fitted(Box<Fitted>),
    /// A published fit to a MERL material ([`crate::model::published`]); resolve looks its parameters up.
    Published(Preset),
    /// A difference series of two curves of the same kind (see [`Curve::Difference`]).
    Difference {
        /// How the two values are combined.
        op: DiffOp,
        /// The first operand.
        a: Box<CurveSpec>,
        /// The second operand.
        b: Box<CurveSpec>,
    },
    /// An NDF seen through a view transform (see [`Curve::Transformed`]).
    Transformed {
        /// The transform.
        transform: Transform,
        /// The transformed NDF.
        curve: Box<CurveSpec>,
    },
    /// A quantity of an NDF other than D (see [`Curve::Quantity`]); the NDF may still need
    /// resolving (a fitted parameter).
    Quantity {
        /// The quantity.
        quantity: Quantity<CurveSpec>,
        /// The NDF.
        ndf: Box<CurveSpec>,
    },
}

impl CurveSpec {
    /// The model the curve belongs to, as [`Curve::model`] will give it once resolved.
    pub fn model(&self) -> Model {
        match self {
            CurveSpec::Ready(curve) => curve.model(),
            CurveSpec::Belcour(_) => Model::Fresnel(FresnelModel::Belcour),
            CurveSpec::Fitted(fitted) => Model::Ndf(fitted.family),
            CurveSpec::Published(preset) => Model::Ndf(preset.source().family()),
            CurveSpec::Difference { a, .. } => a.model(),
            CurveSpec::Transformed { curve, .. } => curve.model(),
            CurveSpec::Quantity { ndf, .. } => ndf.model(),
        }
    }

    /// What the resolved curve's values will be (see [`Curve::kind`]).
    pub fn kind(&self) -> Kind {
        match self {
            CurveSpec::Quantity { quantity, .. } => Kind::Ndf(quantity.name()),
            CurveSpec::Difference { a, .. } => a.kind(),
            other => match other.model() {
                Model::Ndf(_) => Kind::Ndf("d"),
                Model::Fresnel(_) => Kind::Fresnel,
            },
        }
    }

    /// Canonical curve JSON of the description: that of the resolved curve
    /// ([`Curve::canonical_json`]; a published fit is its family curve), a fitted parameter written as
    /// its `{"fit": …}` object.
    pub fn canonical_json(&self) -> String {
        crate::spec::json::to_string(self)
    }
}

impl Serialize for CurveSpec {
    /// The members of canonical curve JSON (see [`CurveSpec::canonical_json`]).
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match self {
            CurveSpec::Ready(curve) => curve.serialize(serializer),
            CurveSpec::Belcour(ior) => serialize_model(serializer, self.model(), &ior_params(ior)),
            CurveSpec::Fitted(fitted) => fitted.serialize(serializer),
            CurveSpec::Published(preset) => Curve::Ndf(preset.ndf()).serialize(serializer),
            CurveSpec::Difference { op, a, b } => serialize_difference(serializer, *op, a, b),
            CurveSpec::Transformed { transform, curve } => {
                serialize_transformed(serializer, *transform, curve)
            }
            CurveSpec::Quantity { quantity, ndf } => quantity::serialize_curve(
                serializer,
                |map| match &**ndf {
                    CurveSpec::Fitted(fitted) => fitted.write_members(map),
                    CurveSpec::Published(preset) => {
                        let curve = Curve::Ndf(preset.ndf());
                        write_model(map, curve.model(), &curve.params())
                    }
                    CurveSpec::Ready(curve) => write_model(map, curve.model(), &curve.params()),
                    other => unreachable!("a quantity of a non-NDF curve: {other:?}"),
                },
                quantity,
            ),
        }
    }
}

/// An NDF whose parameter `free` is fitted to `target` by `by`, its other parameters fixed: one
/// curve of a scene's `{"fit": …}` sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct Fitted {
    /// The fitted curve's family.
    pub family: Family,
    /// Index of the fitted parameter among the family's parameters.
    pub free: usize,
    /// The other parameters by name with their values, in the family's order: the fit's fixed keys.
    pub fixed: Vec<(String, f64)>,
    /// How the fit matches the target.
    pub by: By,
    /// The curve to fit.
    pub target: CurveSpec,
    /// The target's legend label, which a fit's label and its problems name.
    pub target_label: Label,
    /// JSON path of the curve entry; a fit's problem is reported at the fitted key under it.
    pub path: String,
}

impl Fitted {
    /// The fitted parameter's name.
    pub fn name(&self) -> &'static str {
        self.family.param_names()[self.free]
    }
}

impl Fitted {
    /// Writes the family and its parameters into `map`, the fitted one as
    /// `{"fit": {"target": …, "by": …}}`.
    fn write_members<M: SerializeMap>(&self, map: &mut M) -> Result<(), M::Error> {
        /// `{"target": …, "by": …}`.
        struct FitObject<'a>(&'a Fitted);
        impl Serialize for FitObject<'_> {
            fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
                let mut map = serializer.serialize_map(None)?;
                map.serialize_entry("target", &self.0.target)?;
                map.serialize_entry("by", self.0.by.name())?;
                map.end()
            }
        }
        map.serialize_entry("ndf", self.family.name())?;
        let mut fixed = self.fixed.iter();
        for (i, name) in self.family.param_names().iter().enumerate() {
            if i == self.free {
                let mut fit = std::collections::BTreeMap::new();
                fit.insert("fit", FitObject(self));
                map.serialize_entry(name, &fit)?;
            } else if let Some((_, value)) = fixed.next() {
                map.serialize_entry(name, value)?;
            }
        }
        Ok(())
    }
}

impl Serialize for Fitted {
    /// The family and its parameters, the fitted one as `{"fit": {"target": …, "by": …}}`.
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(None)?;
        self.write_members(&mut map)?;
        map.end()
    }
}

/// The placeholder of a Belcour reconstruction's `l2_grid` error in a label template.
pub const L2_PLACEHOLDER: &str = "{l2}";

/// The first `{name}` of a label `template` that is neither a parameter of `params` nor a
/// placeholder every template may hold ([`L2_PLACEHOLDER`], the albedo's average
/// [`crate::spec::quantity::E_AVG_PLACEHOLDER`]), nor a slider's `{=name}`: `None` when all are
/// known. Braces after `_`, `^` or `\` group a sub- or superscript or are escaped, and are not
/// placeholders; neither is a brace holding anything but a name's letters, digits and `_`.
pub fn unknown_placeholder<'t>(template: &'t str, params: &[&str]) -> Option<&'t str> {
    let mut previous = None;
    for (i, c) in template.char_indices() {
        let grouped = matches!(previous, Some('_' | '^' | '\\'));
        previous = Some(c);
        if c != '{' || grouped {
            continue;
        }
        let rest = &template[i + 1..];
        let Some(end) = rest.find('}') else { continue };
        let name = &rest[..end];
        let is_name =
            !name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
        let whole = &template[i..i + end + 2];
        let known = params.contains(&name)
            || whole == L2_PLACEHOLDER
            || whole == crate::spec::quantity::E_AVG_PLACEHOLDER;
        if is_name && !known {
            return Some(name);
        }
    }
    None
}

/// A curve's legend label as the spec describes it; resolve writes it out from the resolved curve
/// (a Belcour reconstruction's `l2_grid` error, a fitted value).
#[derive(Debug, Clone, PartialEq)]
pub enum Label {
    /// The automatic label: the family's legend prefix (an NDF's) or model name (a Fresnel
    /// curve's), then the parts joined by ", ", then a Belcour reconstruction's `, L2 = …`.
    Auto(Vec<Part>),
    /// A `label` template: `{l2}` becomes a Belcour reconstruction's error, `{param}` the
    /// parameter's value.
    Template {
        /// The template as written.
        template: String,
        /// Each parameter with its value; `None` for the fitted one.
        values: Vec<(&'static str, Option<ParamValue>)>,
    },
    /// The label of a difference: `<a> − <b>` (or `/`), or a template where `{a}` and `{b}` stand
    /// for the operands' labels.
    Difference {
        /// The template as written, if any.
        template: Option<String>,
        /// `−` or `/`.
        sign: &'static str,
        /// The first operand's label.
        a: Box<Label>,
        /// The second operand's label.
        b: Box<Label>,
    },
}

/// One part of an automatic label.
#[derive(Debug, Clone, PartialEq)]
pub enum Part {
    /// Text as it is, such as `α_b = 0.4`.
    Text(String),
    /// The fitted parameter with its value and target, such as `a₁ = 23.4442 (peak fit to α_tr = 0.3)`.
    Fitted,
}

fn ior_params(ior: &Ior) -> Vec<(&'static str, ParamValue)> {
    match *ior {
        Ior::EtaKappa { eta, kappa } => {
            vec![
                ("eta", ParamValue::Number(eta)),
                ("kappa", ParamValue::Number(kappa)),
            ]
        }
        Ior::Gulbrandsen { r, g, g_remap } => vec![
            ("r", ParamValue::Number(r)),
            ("g", ParamValue::Number(g)),
            ("g_remap", ParamValue::Flag(g_remap)),
        ],
    }
}

fn fresnel_params(f: &Fresnel) -> Vec<(&'static str, ParamValue)> {
    match f {
        Fresnel::Exact(ior) => ior_params(ior),
        Fresnel::Schlick(SchlickF0::F0(f0)) => vec![("f0", ParamValue::Number(*f0))],
        Fresnel::Schlick(SchlickF0::Ior(ior)) => ior_params(ior),
        Fresnel::Lazanyi { f0, a } => {
            vec![
                ("f0", ParamValue::Number(*f0)),
                ("a", ParamValue::Number(*a)),
            ]
        }
        Fresnel::LazanyiTerm => vec![],
        Fresnel::Belcour(ior, _) => ior_params(ior),
        Fresnel::Basis(index) => vec![("index", ParamValue::Number(*index as f64))],
        Fresnel::Normalized(ior) => ior_params(ior),
    }
}

/// A parameter value: a number, or a flag such as `g_remap`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ParamValue {
    /// A finite number.
    Number(f64),
    /// A boolean flag.
    Flag(bool),
}

impl ParamValue {
    /// The number, or 0/1 for a flag.
    pub fn number(self) -> f64 {
        match self {
            ParamValue::Number(v) => v,
            ParamValue::Flag(b) => f64::from(u8::from(b)),
        }
    }
}

impl Serialize for ParamValue {
    /// A number as a JSON number, a flag as `true`/`false`.
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match *self {
            ParamValue::Number(v) => serializer.serialize_f64(v),
            ParamValue::Flag(b) => serializer.serialize_bool(b),
        }
    }
}

/// A curve model: an NDF family or a Fresnel model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Model {
    /// An NDF family.
    Ndf(Family),
    /// A Fresnel model.
    Fresnel(FresnelModel),
}

/// The kind of value a parameter key takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ParamKind {
    /// A finite number.
    Number,
    /// `true` or `false`.
    Flag,
}

/// One accepted parameter key of a model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParamSpec {
    /// Key name.
    pub name: &'static str,
    /// JSON type of its value.
    pub kind: ParamKind,
    /// Value used when the key is absent; `None` makes the key required.
    pub default: Option<ParamValue>,
}

const fn number(name: &'static str) -> ParamSpec {
    ParamSpec {
        name,
        kind: ParamKind::Number,
        default: None,
    }
}

const ETA_KAPPA: &[ParamSpec] = &[
    number(fresnel::ETA.name),
    ParamSpec {
        name: fresnel::KAPPA.name,
        kind: ParamKind::Number,
        default: Some(ParamValue::Number(0.0)),
    },
];
const GULBRANDSEN: &[ParamSpec] = &[
    number(fresnel::REFLECTIVITY.name),
    number(fresnel::EDGE_TINT.name),
    ParamSpec {
        name: "g_remap",
        kind: ParamKind::Flag,
        default: Some(ParamValue::Flag(false)),
    },
];
const F0: &[ParamSpec] = &[number(fresnel::F0.name)];

impl Model {
    /// The model key of the curve format: `"ndf"` or `"fresnel"`.
    pub fn key(self) -> &'static str {
        match self {
            Model::Ndf(_) => "ndf",
            Model::Fresnel(_) => "fresnel",
        }
    }

    /// Canonical model name (`beckmann`, `exact`, …).
    pub fn name(self) -> &'static str {
        match self {
            Model::Ndf(family) => family.name(),
            Model::Fresnel(model) => model.name(),
        }
    }

    /// The alternative parameter sets ("signatures") the model accepts; keys of different
    /// signatures are exclusive (eta/kappa versus r/g).
    pub fn signatures(self) -> Vec<Vec<ParamSpec>> {
        match self {
            Model::Ndf(family) => {
                let mut signatures =
                    vec![family.param_names().iter().map(|&n| number(n)).collect()];
                if self.emulable() {
                    signatures.push(vec![number(renderer::ROUGHNESS.name)]);
                }
                signatures
            }
            Model::Fresnel(model) => match model {
                FresnelModel::Exact | FresnelModel::Belcour | FresnelModel::Normalized => {
                    vec![ETA_KAPPA.to_vec(), GULBRANDSEN.to_vec()]
                }
                FresnelModel::Schlick => {
                    vec![F0.to_vec(), ETA_KAPPA.to_vec(), GULBRANDSEN.to_vec()]
                }
                FresnelModel::Lazanyi => vec![vec![number(fresnel::F0.name), number("a")]],
                FresnelModel::LazanyiTerm => vec![vec![]],
                FresnelModel::Basis => vec![vec![number(fresnel::BASIS_INDEX.name)]],
            },
        }
    }

    /// Checks one value per key of `signatures()[signature]` and describes the curve; a Belcour
    /// reconstruction is described by its index, its coefficients left to resolve.
    pub fn build(self, signature: usize, values: &[ParamValue]) -> Result<CurveSpec, DomainError> {
        let n = |i: usize| values[i].number();
        let ior = |offset: usize| match (self.signatures()[signature][offset]).name {
            "eta" => Ior::eta_kappa(n(offset), n(offset + 1)),
            _ => Ior::gulbrandsen(
                n(offset),
                n(offset + 1),
                values[offset + 2] == ParamValue::Flag(true),
            ),
        };
        let fresnel = match self {
            Model::Ndf(family) => {
                let numbers: Vec<f64> = values.iter().map(|v| v.number()).collect();
                return Ok(CurveSpec::Ready(Curve::Ndf(family.build(&numbers)?)));
            }
            Model::Fresnel(model) => match model {
                FresnelModel::Belcour => return Ok(CurveSpec::Belcour(ior(0)?)),
                FresnelModel::Exact => Fresnel::Exact(ior(0)?),
                FresnelModel::Schlick if signature == 0 => Fresnel::schlick(n(0))?,
                FresnelModel::Schlick => Fresnel::Schlick(SchlickF0::Ior(ior(0)?)),
                FresnelModel::Lazanyi => Fresnel::lazanyi(n(0), n(1))?,
                FresnelModel::LazanyiTerm => Fresnel::LazanyiTerm,
                FresnelModel::Normalized => Fresnel::Normalized(ior(0)?),
                FresnelModel::Basis => Fresnel::basis(whole_index(n(0))?)?,
            },
        };
        Ok(CurveSpec::Ready(Curve::Fresnel(fresnel)))
    }

    /// The index into [`Model::signatures`] of the signature `eta`/`kappa`, for the Fresnel models
    /// that take an index of refraction that way (and so a metal's measured one).
    pub fn eta_signature(self) -> Option<usize> {
        self.signatures()
            .iter()
            .position(|s| s.first().is_some_and(|p| p.name == fresnel::ETA.name))
    }

    /// Whether a renderer can compute curves of this model (`"engine"`): the GGX and Beckmann
    /// lobes, Schlick's Fresnel and the exact (dielectric) Fresnel.
    pub fn emulable(self) -> bool {
        match self {
            Model::Ndf(family) => Lobe::of(family).is_some(),
            Model::Fresnel(model) => matches!(model, FresnelModel::Schlick | FresnelModel::Exact),
        }
    }

    /// Whether the parameters `params` (one of [`Model::signatures`]) take `"engine"`: an
    /// emulable NDF's width (α or roughness), Schlick's F₀, or the exact Fresnel's η (and κ,
    /// which must be 0).
    pub fn takes_engine(self, params: &[ParamSpec]) -> bool {
        match self {
            Model::Fresnel(FresnelModel::Exact) => {
                params.first().is_some_and(|p| p.name == fresnel::ETA.name)
            }
            _ => {
                self.emulable()
                    && matches!(params, [p] if p.name != fresnel::ETA.name && p.name != fresnel::REFLECTIVITY.name)
            }
        }
    }

    /// Whether the parameters `params` need `"engine"`: the roughness, which only an engine maps to α.
    pub fn needs_engine(params: &[ParamSpec]) -> bool {
        matches!(params, [p] if p.name == renderer::ROUGHNESS.name)
    }

    /// Looks a model up from its key (`ndf`/`fresnel`) and name, aliases included.
    pub fn from_key_and_name(key: &str, name: &str) -> Option<Model> {
        match key {
            "ndf" => Family::from_name(name).map(Model::Ndf),
            _ => FresnelModel::all()
                .find(|m| m.name().eq_ignore_ascii_case(name))
                .map(Model::Fresnel),
        }
    }

    /// Accepted names under a model key, for suggestions.
    pub fn names(key: &str) -> Vec<&'static str> {
        match key {
            "ndf" => Family::NAMES.to_vec(),
            _ => FresnelModel::all().map(FresnelModel::name).collect(),
        }
    }
}

/// A basis index given as a JSON number: it must be a whole number in [`fresnel::BASIS_INDEX`]
/// (0, 1, 2 or 3).
fn whole_index(value: f64) -> Result<usize, DomainError> {
    if value.fract() == 0.0 && fresnel::BASIS_INDEX.contains(value) {
        Ok(value as usize)
    } else {
        Err(DomainError::new("index", value, "0, 1, 2 or 3"))
    }
}

/// A curve object whose keys have been checked: the model, the chosen signature and, per key of
/// that signature, the node given for it (`None` where the default applies).
#[derive(Debug, Clone)]
pub struct Keyed<'a> {
    /// The model.
    pub model: Model,
    /// Index into `model.signatures()`.
    pub signature: usize,
    /// The signature's keys.
    pub params: Vec<ParamSpec>,
    /// Per key, its node in the document, or `None` when absent (a default applies).
    pub nodes: Vec<Option<&'a Node>>,
    /// The quantity of an NDF curve other than D ([`crate::spec::quantity`]).
    pub quantity: Option<Quantity<CurveSpec>>,
    /// The renderer whose computation the curve shows (`"engine"`).
    pub engine: Option<Engine>,
}

impl Keyed<'_> {
    /// Describes the curve ([`Model::build`]) and the quantity it shows, reporting a domain error
    /// at the path of the offending key.
    pub fn build(&self, values: &[ParamValue], path: &str) -> Result<CurveSpec, Problem> {
        if let Some(engine) = self.engine {
            return self.emulated(engine, values, path);
        }
        let curve = self
            .model
            .build(self.signature, values)
            .map_err(|e| domain_problem(&e, path))?;
        self.showing_quantity(curve, path)
    }

    /// `ndf` (this entry's NDF, built or fitted) showing the entry's quantity, if it names one
    /// other than D; a quantity the family cannot show is reported at `path`.
    pub fn showing_quantity(&self, ndf: CurveSpec, path: &str) -> Result<CurveSpec, Problem> {
        if let Some(engine) = self.engine {
            return Err(Problem::new(
                join_key(path, ENGINE_KEY),
                format!(
                    "a curve as an engine computes it takes its parameter as written, not fitted (got engine \"{engine}\")"
                ),
            ));
        }
        match (&self.quantity, self.model) {
            (Some(quantity), Model::Ndf(family)) => {
                quantity.check_family(family, path)?;
                Ok(CurveSpec::Quantity {
                    quantity: quantity.clone(),
                    ndf: Box::new(ndf),
                })
            }
            _ => Ok(ndf),
        }
    }
}

impl Keyed<'_> {
    /// The curve `engine` computes for this entry's model, quantity and first parameter (α,
    /// roughness, F₀ or η, whose κ must then be 0); a refusal is reported at the key it concerns.
    fn emulated(
        &self,
        engine: Engine,
        values: &[ParamValue],
        path: &str,
    ) -> Result<CurveSpec, Problem> {
        let key = self.params[0].name;
        let value = values[0].number();
        let width = if key == renderer::ROUGHNESS.name {
            Width::Roughness(value)
        } else {
            Width::Alpha(value)
        };
        let target = match (self.model, &self.quantity) {
            (Model::Fresnel(FresnelModel::Exact), _) => {
                let kappa = values[1].number();
                if kappa != 0.0 {
                    return Err(Problem::new(
                        join_key(path, fresnel::KAPPA.name),
                        format!(
                            "an engine's exact Fresnel is a dielectric's (got kappa {kappa:?} with engine \"{engine}\", expected 0 or no kappa)"
                        ),
                    ));
                }
                Target::Dielectric(value)
            }
            (Model::Fresnel(_), _) => Target::Schlick(value),
            (Model::Ndf(family), quantity) => {
                let lobe = Lobe::of(family).expect("read_keys() checked the family");
                match quantity {
                    None => Target::D(lobe, width),
                    Some(Quantity::G1) => Target::G1(lobe, width),
                    Some(Quantity::G2 { theta_i, .. }) => Target::G2 {
                        lobe,
                        width,
                        theta_i: match theta_i {
                            ThetaI::Same => None,
                            ThetaI::Fixed(theta) => Some(*theta),
                        },
                    },
                    Some(_) => unreachable!("read_keys() checked the quantity"),
                }
            }
        };
        let emulation = Emulation::new(engine, target).map_err(|refusal| match refusal {
            Refusal::Domain(e) => Problem::new(
                join_key(path, key),
                format!("out of domain (got {:?}, expected {})", e.value, e.expected),
            ),
            other => Problem::new(join_key(path, ENGINE_KEY), other.to_string()),
        })?;
        Ok(CurveSpec::Ready(Curve::Emulated(emulation)))
    }
}

/// Reads the `"engine"` of a curve object of `model` at `path`: a name of [`Engine`], any case; the
/// model must be one an engine computes ([`Model::emulable`]) with parameters that take it, and a
/// quantity it has (D, G1 or G2, its G2 the engine's). `None` when the key is absent.
fn read_engine(
    members: &[(String, Node)],
    model: Model,
    params: &[ParamSpec],
    path: &str,
    problems: &mut Vec<Problem>,
) -> Option<Engine> {
    let get = |key: &str| members.iter().find(|(k, _)| k == key).map(|(_, n)| n);
    let Some(node) = get(ENGINE_KEY) else {
        if Model::needs_engine(params) {
            problems.push(Problem::new(
                join_key(path, renderer::ROUGHNESS.name),
                format!(
                    "a roughness maps to α by an engine's convention: name one with \"engine\" (expected \"{}\" without an engine)",
                    model.signatures()[0][0].name
                ),
            ));
        }
        return None;
    };
    let at = join_key(path, ENGINE_KEY);
    let names: Vec<&str> = Engine::NAMES.iter().map(|(n, _)| *n).collect();
    let Value::String(name) = &node.value else {
        problems.push(Problem::new(
            at,
            format!(
                "expected an engine name (got {node}, expected one of: {})",
                names.join(", ")
            ),
        ));
        return None;
    };
    let Some(engine) = Engine::ALL
        .into_iter()
        .find(|e| e.name().eq_ignore_ascii_case(name))
    else {
        problems.push(Problem::new(
            at,
            format!(
                "unknown engine (got \"{}\", expected one of: {}){}",
                crate::problem::excerpt(name),
                names.join(", "),
                suggestion(&name.to_ascii_lowercase(), names.iter().copied())
            ),
        ));
        return None;
    };
    let before = problems.len();
    if !model.takes_engine(params) {
        let what = match model {
            Model::Ndf(family) => format!("ndf \"{}\"", family.name()),
            Model::Fresnel(m) if model.emulable() => {
                let keys: Vec<&str> = params.iter().map(|p| p.name).collect();
                format!("fresnel \"{}\" given by {}", m.name(), keys.join(", "))
            }
            Model::Fresnel(m) => format!("fresnel \"{}\"", m.name()),
        };
        problems.push(Problem::new(
            &at,
            format!(
                "an engine computes GGX and Beckmann lobes (from their α or a roughness), Schlick's Fresnel from f0 and the exact Fresnel from eta (got {what})"
            ),
        ));
    }
    if let Some(quantity) = get(quantity::QUANTITY_KEY)
        && let Value::String(q) = &quantity.value
        && !ENGINE_QUANTITIES.contains(&q.as_str())
    {
        problems.push(Problem::new(
            join_key(path, quantity::QUANTITY_KEY),
            format!(
                "an engine's curve shows one of: {} (got quantity \"{}\" with engine \"{engine}\")",
                ENGINE_QUANTITIES.join(", "),
                crate::problem::excerpt(q)
            ),
        ));
    }
    if let Some(g2) = get(quantity::G2_KEY)
        && let Value::String(g2) = &g2.value
        && g2 != engine.g2_model().name()
    {
        problems.push(Problem::new(
            join_key(path, quantity::G2_KEY),
            format!(
                "the G2 of {engine} is {} (got \"{}\"; leave \"g2\" out or name that one)",
                engine.g2_model().name(),
                crate::problem::excerpt(g2)
            ),
        ));
    }
    (problems.len() == before).then_some(engine)
}

/// The quantities an engine's curve may show.
const ENGINE_QUANTITIES: [&str; 3] = ["d", "g1", "g2"];

/// Turns a domain error into a problem at `<path>.<param>`.
pub fn domain_problem(error: &DomainError, path: &str) -> Problem {
    Problem::new(
        join_key(path, error.param),
        format!(
            "out of domain (got {:?}, expected {})",
            error.value, error.expected
        ),
    )
}

/// Checks the keys of the curve object `node` at JSON path `path`: exactly one model key with a
/// known name, no duplicate keys, no unknown keys (beyond `extra_keys`, which the caller handles,
/// such as a scene's `style`), no keys from exclusive signatures mixed, no required key missing.
/// Every problem is reported.
pub fn read_keys<'a>(
    node: &'a Node,
    path: &str,
    extra_keys: &[&str],
) -> Result<Keyed<'a>, Vec<Problem>> {
    let Value::Object(members) = &node.value else {
        let got = node.to_string();
        return Err(vec![Problem::new(
            path,
            format!("expected a curve object (got {got})"),
        )]);
    };
    let mut model_problems = Vec::new();
    // Beside "ndf", an object under "fresnel" is an albedo's Fresnel factor, not a model key.
    let has_ndf = members.iter().any(|(k, _)| k == "ndf");
    let model_keys: Vec<&(String, Node)> = members
        .iter()
        .filter(|(k, v)| {
            k == "ndf" || (k == "fresnel" && !(has_ndf && matches!(v.value, Value::Object(_))))
        })
        .collect();
    let model = match model_keys.as_slice() {
        [] => {
            model_problems.push(Problem::new(
                path,
                format!("missing key \"ndf\" or \"fresnel\" naming the curve's model (got {node}, expected {{\"ndf\": <family>, …}} or {{\"fresnel\": <model>, …}})"),
            ));
            None
        }
        [(key, name_node)] => model_from_node(key, name_node, path, &mut model_problems),
        [(first, _), (second, _), ..] if first != second => {
            model_problems.push(Problem::new(
                path,
                format!("a curve has either \"ndf\" or \"fresnel\", not both (got {node})"),
            ));
            None
        }
        [(key, name_node), ..] => model_from_node(key, name_node, path, &mut model_problems),
    };
    let Some(model) = model else {
        // Without a model the accepted keys are unknown; only duplicates can be told.
        let mut problems = keys::validate(members, path, None);
        problems.extend(model_problems);
        return Err(problems);
    };
    let signatures = model.signatures();
    let quantity_keys: &[&str] = match model {
        Model::Ndf(_) => quantity::KEYS,
        Model::Fresnel(_) => &[],
    };
    let all_keys: Vec<&str> = signatures
        .iter()
        .flatten()
        .map(|p| p.name)
        .chain(quantity_keys.iter().copied())
        .chain(model.emulable().then_some(ENGINE_KEY))
        .chain(extra_keys.iter().copied())
        .collect();
    let object = format!("{} \"{}\"", model.key(), model.name());
    // A model no engine computes still takes "engine" past the key check, to be refused by name
    // ([`read_engine`]), but does not list it.
    let accepted = Accepted {
        object: Some(&object),
        listed: &all_keys,
        unlisted: &[model.key(), ENGINE_KEY],
    };
    let mut problems = keys::validate(members, path, Some(&accepted));
    if !problems.is_empty() {
        return Err(problems);
    }
    let given: Vec<&(String, Node)> = members
        .iter()
        .filter(|(k, _)| {
            k != model.key()
                && k != ENGINE_KEY
                && !extra_keys.contains(&k.as_str())
                && !quantity_keys.contains(&k.as_str())
        })
        .collect();
    let Some(signature) = signatures
        .iter()
        .position(|sig| given.iter().all(|(k, _)| sig.iter().any(|p| p.name == k)))
    else {
        let keys: Vec<&str> = given.iter().map(|(k, _)| k.as_str()).collect();
        let alternatives: Vec<String> = signatures
            .iter()
            .map(|sig| sig.iter().map(|p| p.name).collect::<Vec<_>>().join("/"))
            .collect();
        return Err(vec![Problem::new(
            path,
            format!(
                "keys {} cannot be combined (expected one of: {})",
                keys.join(", "),
                alternatives.join(" or ")
            ),
        )]);
    };
    let params = signatures[signature].clone();
    let nodes: Vec<Option<&Node>> = params
        .iter()
        .map(|p| given.iter().find(|(k, _)| k == p.name).map(|(_, n)| n))
        .collect();
    let quantity = match model {
        Model::Ndf(_) => quantity::parse(members, path, albedo_fresnel).unwrap_or_else(|found| {
            problems.extend(found);
            None
        }),
        Model::Fresnel(_) => None,
    };
    let engine = read_engine(members, model, &params, path, &mut problems);
    for (spec, node) in params.iter().zip(&nodes) {
        if node.is_none() && spec.default.is_none() {
            problems.push(Problem::new(
                join_key(path, spec.name),
                format!(
                    "missing parameter for {} \"{}\" (expected {})",
                    model.key(),
                    model.name(),
                    kind_name(spec.kind)
                ),
            ));
        }
    }
    if problems.is_empty() {
        Ok(Keyed {
            model,
            signature,
            params,
            nodes,
            quantity,
            engine,
        })
    } else {
        Err(problems)
    }
}

fn model_from_node(
    key: &str,
    node: &Node,
    path: &str,
    problems: &mut Vec<Problem>,
) -> Option<Model> {
    let at = join_key(path, key);
    let names = Model::names(key);
    let Value::String(name) = &node.value else {
        problems.push(Problem::new(
            at,
            format!(
                "expected a model name (got {node}, expected one of: {})",
                names.join(", ")
            ),
        ));
        return None;
    };
    let model = Model::from_key_and_name(key, name);
    if model.is_none() {
        problems.push(Problem::new(
            at,
            format!(
                "unknown {key} model (got \"{}\", expected one of: {}){}",
                crate::problem::excerpt(name),
                names.join(", "),
                suggestion(name, names.iter().copied())
            ),
        ));
    }
    model
}

/// The key of a transformed curve, `{"transform": "projected" | "slope", "curve": <NDF curve>}`.
pub const TRANSFORM_KEY: &str = "transform";
/// Keys of a transformed curve.
pub const TRANSFORM_KEYS: &[&str] = &[TRANSFORM_KEY, "curve"];

fn parse_transformed(members: &[(String, Node)], path: &str) -> Result<CurveSpec, Vec<Problem>> {
    let accepted = Accepted {
        object: Some("a transformed curve"),
        listed: TRANSFORM_KEYS,
        unlisted: &[],
    };
    let mut problems = keys::validate(members, path, Some(&accepted));
    let names: Vec<&str> = Transform::NAMES.iter().map(|(n, _)| *n).collect();
    let transform = members
        .iter()
        .find(|(k, _)| k == TRANSFORM_KEY)
        .and_then(|(_, node)| match &node.value {
            Value::String(name) => Transform::from_name(name),
            _ => None,
        });
    if transform.is_none() {
        let node = &members
            .iter()
            .find(|(k, _)| k == TRANSFORM_KEY)
            .expect("caller checked the key")
            .1;
        problems.push(Problem::new(
            join_key(path, TRANSFORM_KEY),
            format!(
                "unknown transform (got {node}, expected one of: {})",
                names.join(", ")
            ),
        ));
    }
    let curve_path = join_key(path, "curve");
    let curve = match members.iter().find(|(k, _)| k == "curve") {
        Some((_, node)) => parse(node, &curve_path)
            .map_err(|p| problems.extend(p))
            .ok(),
        None => {
            problems.push(Problem::new(
                curve_path.clone(),
                "missing the curve to transform (expected an NDF curve object)",
            ));
            None
        }
    };
    match (transform, curve) {
        (Some(transform), Some(curve)) if problems.is_empty() => {
            transformed(transform, curve, &curve_path).map_err(|p| vec![p])
        }
        _ => Err(problems),
    }
}

/// `curve` seen through `transform`; only NDFs have view transforms.
pub fn transformed(
    transform: Transform,
    curve: CurveSpec,
    path: &str,
) -> Result<CurveSpec, Problem> {
    if curve.kind() != Kind::Ndf("d") {
        return Err(Problem::new(
            path,
            format!(
                "the {} view applies to NDF curves showing D (got {})",
                transform.name(),
                curve.canonical_json()
            ),
        ));
    }
    Ok(CurveSpec::Transformed {
        transform,
        curve: Box::new(curve),
    })
}

/// What a value of `kind` is, for messages.
fn kind_name(kind: ParamKind) -> &'static str {
    match kind {
        ParamKind::Number => "a number",
        ParamKind::Flag => "true or false",
    }
}

/// Reads a single (non-swept) parameter value of the given kind.
pub fn scalar(node: &Node, kind: ParamKind, path: &str) -> Result<ParamValue, Problem> {
    match (&node.value, kind) {
        (Value::Number(n), ParamKind::Number) => Ok(ParamValue::Number(n.value)),
        (Value::Bool(b), ParamKind::Flag) => Ok(ParamValue::Flag(*b)),
        (value, ParamKind::Number) => Err(Problem::new(
            path,
            format!("expected a number (got {} {node})", value.kind()),
        )),
        (value, ParamKind::Flag) => Err(Problem::new(
            path,
            format!("expected true or false (got {} {node})", value.kind()),
        )),
    }
}

/// Parses one plain curve object (every parameter a single value), as `eval` takes it, or a
/// difference `{"difference": "minus"|"ratio"|"relative"|"log-ratio", "a": <curve>, "b": <curve>}` of two such curves,
/// into its description ([`crate::pipeline::resolve::curve`] makes it a [`Curve`]).
pub fn parse(node: &Node, path: &str) -> Result<CurveSpec, Vec<Problem>> {
    if is_metal(node) {
        let keys = metal_keys(node, path, &[], false)?;
        let wavelength = scalar(
            keys.wavelength,
            ParamKind::Number,
            &join_key(path, WAVELENGTH_KEY),
        )
        .map_err(|p| vec![p])?;
        return metal_curve(keys.model, keys.metals[0], wavelength.number(), path)
            .map(|(curve, _)| curve)
            .map_err(|p| vec![p]);
    }
    if is_published(node) {
        let choices = published(node, path, quantity::KEYS)?;
        return match choices.as_slice() {
            [one] => published_showing(node, path, one.preset),
            _ => Err(vec![Problem::new(
                path,
                format!(
                    "a list of materials or channels sweeps in scenes only (got {node}, expected one published fit)"
                ),
            )]),
        };
    }
    if let Value::Object(members) = &node.value
        && members.iter().any(|(k, _)| k == TRANSFORM_KEY)
    {
        return parse_transformed(members, path);
    }
    if is_difference(node) {
        let (op, a, b) = difference_parts(node, path, &[])?;
        let (a, b) = (
            parse(a, &join_key(path, "a")),
            parse(b, &join_key(path, "b")),
        );
        return match (a, b) {
            (Ok(a), Ok(b)) => difference(op, a, b, path).map_err(|p| vec![p]),
            (a, b) => Err(a.err().into_iter().chain(b.err()).flatten().collect()),
        };
    }
    let keyed = read_keys(node, path, &[])?;
    let mut values = Vec::new();
    let mut problems = Vec::new();
    for (spec, node) in keyed.params.iter().zip(&keyed.nodes) {
        match node {
            None => values.push(
                spec.default
                    .expect("read_keys() reports missing required keys"),
            ),
            Some(node) => match scalar(node, spec.kind, &join_key(path, spec.name)) {
                Ok(value) => values.push(value),
                Err(problem) => problems.push(problem),
            },
        }
    }
    if !problems.is_empty() {
        return Err(problems);
    }
    keyed.build(&values, path).map_err(|p| vec![p])
}

/// The model key of a published fit: `{"published": <source>, "material": <MERL name>, "channel": …}`.
pub const PUBLISHED_KEY: &str = "published";
/// Keys of a published fit besides the caller's extra keys.
pub const PUBLISHED_KEYS: &[&str] = &[PUBLISHED_KEY, "material", "channel"];

/// Whether `node` is a published-fit object (has the key `"published"`).
pub fn is_published(node: &Node) -> bool {
    matches!(&node.value, Value::Object(members) if members.iter().any(|(k, _)| k == PUBLISHED_KEY))
}

/// One fit a published-fit object names, with its legend text.
#[derive(Debug, Clone, PartialEq)]
pub struct PublishedChoice {
    /// The fit.
    pub preset: Preset,
    /// `<source title>`, then the material when the object lists several, then the channel when
    /// given: `Bagher 2012 SGD, red`.
    pub label: String,
}

/// The published fit `preset` of the object `node` at `path` showing the quantity its
/// [`quantity::KEYS`] name (checked against the source's family), or D without them.
pub fn published_showing(
    node: &Node,
    path: &str,
    preset: Preset,
) -> Result<CurveSpec, Vec<Problem>> {
    let ndf = CurveSpec::Published(preset);
    let Value::Object(members) = &node.value else {
        return Ok(ndf);
    };
    match quantity::parse(members, path, albedo_fresnel)? {
        None => Ok(ndf),
        Some(quantity) => {
            quantity
                .check_family(preset.source().family(), path)
                .map_err(|p| vec![p])?;
            Ok(CurveSpec::Quantity {
                quantity,
                ndf: Box::new(ndf),
            })
        }
    }
}

/// Checks the published-fit object `node` at `path` (keys [`PUBLISHED_KEYS`] plus `extra_keys`, which
/// the caller handles) and names its fits: `material` and `channel` are each a name or a non-empty
/// list of names, giving their product in document order, the later key varying fastest. A source that
/// fits per channel requires `channel`, any other refuses it; unknown names get a "did you mean".
/// Every problem is reported.
pub fn published(
    node: &Node,
    path: &str,
    extra_keys: &[&str],
) -> Result<Vec<PublishedChoice>, Vec<Problem>> {
    let (members, mut problems) = keyed_object(
        node,
        path,
        [PUBLISHED_KEYS, extra_keys],
        &[],
        "a published fit",
    )?;
    let get = |key: &str| members.iter().find(|(k, _)| k == key).map(|(_, n)| n);
    let source_names: Vec<&str> = Source::ALL.iter().map(|s| s.name()).collect();
    let source = names_at(
        get(PUBLISHED_KEY).expect("is_published() was checked"),
        &join_key(path, PUBLISHED_KEY),
        "source",
        &source_names,
        false,
        &mut problems,
    )
    .and_then(|names| Source::from_name(names[0].0));
    let material_path = join_key(path, "material");
    let materials = match (source, get("material")) {
        (_, None) => {
            problems.push(Problem::new(
                &material_path,
                "missing the MERL material of the published fit (expected a name such as \"gold-metallic-paint\")",
            ));
            None
        }
        (Some(source), Some(node)) => {
            let names: Vec<&str> = source.materials().collect();
            names_at(
                node,
                &material_path,
                "material",
                &names,
                true,
                &mut problems,
            )
        }
        (None, Some(_)) => None,
    };
    let channel_path = join_key(path, "channel");
    let channel_names: Vec<&str> = Channel::ALL.iter().map(|c| c.name()).collect();
    let channels = match (source, get("channel")) {
        (Some(source), None) if source.per_channel() => {
            problems.push(Problem::new(
                &channel_path,
                format!(
                    "missing channel: \"{}\" fits each RGB channel separately (expected one of: {})",
                    source.name(),
                    channel_names.join(", ")
                ),
            ));
            None
        }
        (Some(source), Some(node)) if !source.per_channel() => {
            problems.push(Problem::new(
                &channel_path,
                format!(
                    "\"{}\" fits one lobe per material, not per channel (got {node}, expected no \"channel\")",
                    source.name()
                ),
            ));
            None
        }
        (_, Some(node)) => names_at(
            node,
            &channel_path,
            "channel",
            &channel_names,
            true,
            &mut problems,
        )
        .map(|names| {
            names
                .into_iter()
                .map(|(n, _)| Channel::from_name(n))
                .collect()
        }),
        (_, None) => Some(vec![None]),
    };
    let (Some(source), Some(materials), Some(channels)) = (source, materials, channels) else {
        return Err(problems);
    };
    if !problems.is_empty() {
        return Err(problems);
    }
    let materials_vary =
        materials.len() > 1 || matches!(get("material").map(|n| &n.value), Some(Value::Array(_)));
    let channel_first = match (get("channel"), get("material")) {
        (Some(c), Some(m)) => (c.line, c.col) < (m.line, m.col),
        _ => false,
    };
    let mut pairs = Vec::with_capacity(materials.len() * channels.len());
    if channel_first {
        for &channel in &channels {
            pairs.extend(materials.iter().map(|&(m, _)| (m, channel)));
        }
    } else {
        for &(m, _) in &materials {
            pairs.extend(channels.iter().map(|&channel| (m, channel)));
        }
    }
    pairs
        .into_iter()
        .map(|(material, channel)| {
            let preset = Preset::new(source, material, channel).map_err(|e| {
                let reason = match e {
                    PresetError::UnknownMaterial => "unknown material",
                    PresetError::ChannelRequired => "missing channel",
                    PresetError::ChannelRefused => "channel refused",
                };
                vec![Problem::new(path, reason)]
            })?;
            let mut label = source.title().to_string();
            if materials_vary {
                label = format!("{label}, {material}");
            }
            if let Some(channel) = channel {
                label = format!("{label}, {}", channel.name());
            }
            Ok(PublishedChoice { preset, label })
        })
        .collect()
}

/// The names `node` gives at `path`: one name, or (where `lists`) a non-empty list of names, each one
/// of `known` (else a problem with a "did you mean"). `what` names the value in messages. Returns
/// each name with its path, or `None` after recording the problems.
fn names_at<'k>(
    node: &Node,
    path: &str,
    what: &str,
    known: &[&'k str],
    lists: bool,
    problems: &mut Vec<Problem>,
) -> Option<Vec<(&'k str, String)>> {
    let items: Vec<(&Node, String)> = match &node.value {
        Value::Array(items) if lists && !items.is_empty() => items
            .iter()
            .enumerate()
            .map(|(i, item)| (item, join_index(path, i)))
            .collect(),
        Value::String(_) => vec![(node, path.to_string())],
        _ => {
            let expected = if lists {
                format!("a {what} name or a non-empty list of them")
            } else {
                format!("a {what} name")
            };
            problems.push(Problem::new(
                path,
                format!("expected {expected} (got {node})"),
            ));
            return None;
        }
    };
    let before = problems.len();
    let mut names = Vec::with_capacity(items.len());
    for (item, at) in items {
        let Value::String(name) = &item.value else {
            problems.push(Problem::new(
                at,
                format!("expected a {what} name (got {item})"),
            ));
            continue;
        };
        match known.iter().find(|k| k.eq_ignore_ascii_case(name)) {
            Some(&found) => names.push((found, at)),
            None => {
                let listed = if known.len() > 8 {
                    format!("one of the {} names the source fits", known.len())
                } else {
                    format!("one of: {}", known.join(", "))
                };
                problems.push(Problem::new(
                    at,
                    format!(
                        "unknown {what} (got \"{}\", expected {listed}){}",
                        crate::problem::excerpt(name),
                        suggestion(name, known.iter().copied())
                    ),
                ))
            }
        }
    }
    (problems.len() == before).then_some(names)
}

/// The key naming a measured metal in a Fresnel curve: `{"fresnel": "exact", "metal": "Au",
/// "wavelength_nm": 550}`.
pub const METAL_KEY: &str = "metal";
/// The key of the wavelength, in nm, at which a metal's index is taken.
pub const WAVELENGTH_KEY: &str = "wavelength_nm";
/// Keys of a metal's Fresnel curve besides the caller's extra keys.
pub const METAL_KEYS: &[&str] = &["fresnel", METAL_KEY, WAVELENGTH_KEY];
/// The keys that give an index directly, which a metal's measured index replaces.
const INDEX_KEYS: &[&str] = &["eta", "kappa", "r", "g", "g_remap"];

/// Whether `node` is a metal's Fresnel curve (has the key `"metal"` and no `"ndf"`).
pub fn is_metal(node: &Node) -> bool {
    matches!(&node.value, Value::Object(members)
        if members.iter().any(|(k, _)| k == METAL_KEY) && !members.iter().any(|(k, _)| k == "ndf"))
}

/// A metal's Fresnel curve as its object names it, its wavelength not yet read.
#[derive(Debug, Clone)]
pub struct MetalKeys<'a> {
    /// The Fresnel model, one that takes an index (η, κ).
    pub model: Model,
    /// The metals, in document order (one unless listed).
    pub metals: Vec<Metal>,
    /// The node of `wavelength_nm`.
    pub wavelength: &'a Node,
}

/// Checks the metal's Fresnel object `node` at `path` (keys [`METAL_KEYS`] plus `extra_keys`, which
/// the caller handles): a Fresnel model that takes an index (η, κ), one metal by symbol or English
/// name in any case (or, where `lists`, a non-empty list of them; an unknown one gets a "did you
/// mean"), and a `wavelength_nm`. Keys that give the index directly (`eta`, `kappa`, `r`, `g`,
/// `g_remap`) are refused by name. Every problem is reported.
pub fn metal_keys<'a>(
    node: &'a Node,
    path: &str,
    extra_keys: &[&str],
    lists: bool,
) -> Result<MetalKeys<'a>, Vec<Problem>> {
    // The index keys pass the key check unlisted, to be refused by name below.
    let (members, mut problems) = keyed_object(
        node,
        path,
        [METAL_KEYS, extra_keys],
        INDEX_KEYS,
        "a metal's Fresnel curve",
    )?;
    let get = |key: &str| members.iter().find(|(k, _)| k == key).map(|(_, n)| n);
    let given: Vec<&str> = INDEX_KEYS
        .iter()
        .copied()
        .filter(|k| get(k).is_some())
        .collect();
    for key in &given {
        let drop: Vec<String> = given.iter().map(|k| format!("\"{k}\"")).collect();
        problems.push(Problem::new(
            join_key(path, key),
            format!(
                "\"metal\" gives the index from measured data (got {}; drop {}, or drop \"metal\" to give the index yourself)",
                get(key).expect("listed as given"),
                drop.join(" and ")
            ),
        ));
    }
    let model = match get("fresnel") {
        None => {
            problems.push(Problem::new(
                join_key(path, "fresnel"),
                "missing the Fresnel model of the metal (expected one of: exact, schlick, belcour, normalized)",
            ));
            None
        }
        Some(name) => model_from_node("fresnel", name, path, &mut problems),
    };
    let takes_index = |model: Model| model.eta_signature().is_some();
    if let Some(model) = model
        && !takes_index(model)
    {
        let takers: Vec<&str> = FresnelModel::all()
            .map(Model::Fresnel)
            .filter(|&m| takes_index(m))
            .map(Model::name)
            .collect();
        problems.push(Problem::new(
            join_key(path, "fresnel"),
            format!(
                "fresnel \"{}\" takes no index of refraction, so no \"metal\" (expected one of: {})",
                model.name(),
                takers.join(", ")
            ),
        ));
    }
    let metals = metals_at(
        get(METAL_KEY).expect("is_metal() was checked"),
        &join_key(path, METAL_KEY),
        lists,
        &mut problems,
    );
    let wavelength = get(WAVELENGTH_KEY);
    if wavelength.is_none() {
        problems.push(Problem::new(
            join_key(path, WAVELENGTH_KEY),
            "missing the wavelength at which the metal's index is taken (expected a number of nm, such as 550)",
        ));
    }
    match (model, metals, wavelength) {
        (Some(model), Some(metals), Some(wavelength)) if problems.is_empty() => Ok(MetalKeys {
            model,
            metals,
            wavelength,
        }),
        _ => Err(problems),
    }
}

/// The metals `node` names at `path`: a symbol or English name in any case, or (where `lists`) a
/// non-empty list of them; `None` after recording the problems.
fn metals_at(
    node: &Node,
    path: &str,
    lists: bool,
    problems: &mut Vec<Problem>,
) -> Option<Vec<Metal>> {
    let items: Vec<(&Node, String)> = match &node.value {
        Value::Array(items) if lists && !items.is_empty() => items
            .iter()
            .enumerate()
            .map(|(i, item)| (item, join_index(path, i)))
            .collect(),
        _ => vec![(node, path.to_string())],
    };
    let names: Vec<&str> = Metal::all_names().collect();
    let lower: Vec<String> = names.iter().map(|n| n.to_ascii_lowercase()).collect();
    let before = problems.len();
    let mut metals = Vec::with_capacity(items.len());
    for (item, at) in items {
        let Value::String(name) = &item.value else {
            let expected = if lists {
                "a metal's symbol or name, or a non-empty list of them"
            } else {
                "a metal's symbol or name"
            };
            problems.push(Problem::new(
                at,
                format!("expected {expected} (got {item})"),
            ));
            continue;
        };
        match Metal::from_name(name) {
            Some(metal) => metals.push(metal),
            None => {
                // Suggested in the case the list writes it (Au, gold), whatever the case typed.
                let near = crate::problem::did_you_mean(
                    &name.to_ascii_lowercase(),
                    lower.iter().map(String::as_str),
                )
                .and_then(|n| lower.iter().position(|l| l == n))
                .map_or_else(String::new, |i| format!("; did you mean \"{}\"?", names[i]));
                problems.push(Problem::new(
                    at,
                    format!(
                        "unknown metal (got \"{}\", expected one of: {}){near}",
                        crate::problem::excerpt(name),
                        names.join(", ")
                    ),
                ));
            }
        }
    }
    (problems.len() == before).then_some(metals)
}

/// The Fresnel curve of `model` for `metal`'s measured index at `wavelength_nm` ([`Metal::index_at`]),
/// with its automatic legend text (`exact, Au 550 nm`); a wavelength outside the metal's data is
/// refused at `path`'s `wavelength_nm` with the data's range.
pub fn metal_curve(
    model: Model,
    metal: Metal,
    wavelength_nm: f64,
    path: &str,
) -> Result<(CurveSpec, String), Problem> {
    let (min, max) = metal.range_nm();
    let at = join_key(path, WAVELENGTH_KEY);
    let (eta, kappa) = metal.index_at(wavelength_nm).ok_or_else(|| {
        Problem::new(
            &at,
            format!(
                "outside the measured data of {} (got {wavelength_nm:?}, expected in [{min:?}, {max:?}] nm)",
                metal.symbol()
            ),
        )
    })?;
    let signature = model
        .eta_signature()
        .expect("metal_keys() checked that the model takes an index");
    let curve = model
        .build(
            signature,
            &[ParamValue::Number(eta), ParamValue::Number(kappa)],
        )
        .map_err(|e| domain_problem(&e, path))?;
    let label = format!(
        "{}, {} {} nm",
        model.name(),
        metal.symbol(),
        crate::spec::numbers::pretty(wavelength_nm)
    );
    Ok((curve, label))
}

/// The model key of a difference series in the curve format.
pub const DIFFERENCE_KEY: &str = "difference";

/// Keys of a difference object besides the caller's extra keys.
pub const DIFFERENCE_KEYS: &[&str] = &[DIFFERENCE_KEY, "a", "b"];

/// An object's members with the problems of its keys, as [`keyed_object`] returns them.
type KeyedMembers<'a> = (&'a [(String, Node)], Vec<Problem>);

/// The members of the curve object `node` at `path` that accepts the keys of `listed` (its own
/// and the extra keys the caller handles) and, without listing them in messages, `unlisted`, with
/// the problems of its keys ([`keys::validate`]; `object` names it in them); a value that is not
/// an object is the one problem.
fn keyed_object<'a>(
    node: &'a Node,
    path: &str,
    listed: [&[&str]; 2],
    unlisted: &[&str],
    object: &str,
) -> Result<KeyedMembers<'a>, Vec<Problem>> {
    let Value::Object(members) = &node.value else {
        return Err(vec![Problem::new(
            path,
            format!("expected a curve object (got {node})"),
        )]);
    };
    let allowed: Vec<&str> = listed.concat();
    let accepted = Accepted {
        object: Some(object),
        listed: &allowed,
        unlisted,
    };
    let problems = keys::validate(members, path, Some(&accepted));
    Ok((members, problems))
}

/// Whether `node` is a difference object (has the key `"difference"`).
pub fn is_difference(node: &Node) -> bool {
    matches!(&node.value, Value::Object(members) if members.iter().any(|(k, _)| k == DIFFERENCE_KEY))
}

/// Checks the keys of the difference object `node` at `path` (`difference`, `a`, `b`, plus
/// `extra_keys` that the caller handles) and reads its operation; returns it with the operand
/// nodes. Every problem is reported.
pub fn difference_parts<'a>(
    node: &'a Node,
    path: &str,
    extra_keys: &[&str],
) -> Result<(DiffOp, &'a Node, &'a Node), Vec<Problem>> {
    let (members, mut problems) = keyed_object(
        node,
        path,
        [DIFFERENCE_KEYS, extra_keys],
        &[],
        "a difference",
    )?;
    let get = |key: &str| members.iter().find(|(k, _)| k == key).map(|(_, n)| n);
    let names: Vec<&str> = DiffOp::ALL.iter().map(|op| op.name()).collect();
    let op_node = get(DIFFERENCE_KEY).expect("is_difference() was checked");
    let op = match &op_node.value {
        Value::String(name) => {
            let op = DiffOp::ALL.into_iter().find(|op| op.name() == name);
            if op.is_none() {
                problems.push(Problem::new(
                    join_key(path, DIFFERENCE_KEY),
                    format!(
                        "unknown difference (got \"{}\", expected one of: {}){}",
                        crate::problem::excerpt(name),
                        names.join(", "),
                        suggestion(name, names.iter().copied())
                    ),
                ));
            }
            op
        }
        _ => {
            problems.push(Problem::new(
                join_key(path, DIFFERENCE_KEY),
                format!(
                    "expected an operation name (got {op_node}, expected one of: {})",
                    names.join(", ")
                ),
            ));
            None
        }
    };
    for key in ["a", "b"] {
        if get(key).is_none() {
            problems.push(Problem::new(
                join_key(path, key),
                "missing operand of the difference (expected a curve object)",
            ));
        }
    }
    match (op, get("a"), get("b")) {
        (Some(op), Some(a), Some(b)) if problems.is_empty() => Ok((op, a, b)),
        _ => Err(problems),
    }
}

/// The difference series `op(a, b)`; a and b must be of the same kind (two NDFs or two Fresnel
/// curves), else the problem is reported at `path`.
pub fn difference(
    op: DiffOp,
    a: CurveSpec,
    b: CurveSpec,
    path: &str,
) -> Result<CurveSpec, Problem> {
    let (kind_a, kind_b) = (a.kind(), b.kind());
    if kind_a != kind_b {
        return Err(Problem::new(
            join_key(path, "b"),
            format!(
                "a difference needs two curves of the same kind (got {} against {}, expected two NDFs showing the same quantity or two Fresnel curves)",
                kind_a.describe(),
                kind_b.describe()
            ),
        ));
    }
    Ok(CurveSpec::Difference {
        op,
        a: Box::new(a),
        b: Box::new(b),
    })
}

/// The legend symbol of a parameter as its domain states it: an NDF family's (`alpha_b` → `α_b`) or a
/// Fresnel one's (`eta` → `η`); any other name as it is.
pub fn symbol(param: &str) -> &str {
    Family::ALL
        .iter()
        .flat_map(|family| family.params())
        .chain(fresnel::PARAMS)
        .chain([&renderer::ROUGHNESS])
        .find(|p| p.name == param)
        .map_or(param, |p| p.symbol)
}

/// The nested Fresnel curve of an albedo: a plain Fresnel curve object.
fn albedo_fresnel(node: &Node, path: &str) -> Result<CurveSpec, Vec<Problem>> {
    let spec = parse(node, path)?;
    if spec.kind() != Kind::Fresnel {
        return Err(vec![Problem::new(
            path,
            format!(
                "an albedo's Fresnel factor is a Fresnel curve (got {}, expected {{\"fresnel\": <model>, …}})",
                spec.canonical_json()
            ),
        )]);
    }
    Ok(spec)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spec::json;

    fn problems(text: &str) -> Vec<Problem> {
        parse(&json::parse(text).unwrap(), "").unwrap_err()
    }

    #[test]
    fn key_errors_name_the_key_and_suggest() {
        let p = problems(r#"{"ndf":"beckman","alpha_b":0.5}"#);
        assert_eq!(p[0].at, "ndf");
        assert!(p[0].message.contains("did you mean \"beckmann\""), "{p:?}");
        let p = problems(r#"{"ndf":"beckmann","alpha_bb":0.5}"#);
        assert_eq!(p[0].at, "alpha_bb");
        assert!(p[0].message.contains("did you mean \"alpha_b\""), "{p:?}");
        let p = problems(r#"{"ndf":"abc","alpha_abc1":1}"#);
        assert_eq!(
            (p[0].at.as_str(), p[0].message.contains("missing")),
            ("alpha_abc2", true)
        );
        let p = problems(r#"{"ndf":"phong","alpha_p":1,"alpha_p":2}"#);
        assert_eq!(
            (p[0].at.as_str(), p[0].message.as_str()),
            (
                "alpha_p",
                "duplicate key (got a second value 2, expected each key once)"
            )
        );
        let p = problems(r#"{"ndf":"phong","alpha_p":"1"}"#);
        assert!(p[0].message.contains("expected a number"), "{p:?}");
        let p = problems(r#"{"ndf":"phong","alpha_p":-1}"#);
        assert_eq!(p[0].at, "alpha_p");
        assert!(p[0].message.contains("got -1.0"), "{p:?}");
        let p = problems(r#"{"alpha_p":1}"#);
        assert!(p[0].message.contains("missing key \"ndf\""), "{p:?}");
        let p = problems(r#"[1]"#);
        assert!(p[0].message.contains("expected a curve object"), "{p:?}");
    }

    #[test]
    fn canonical_json_uses_canonical_names_and_order() {
        let curve = parse(&json::parse(r#"{"alpha_tr":0.5,"ndf":"ggx"}"#).unwrap(), "").unwrap();
        assert_eq!(
            curve.canonical_json(),
            r#"{"ndf":"trowbridge_reitz","alpha_tr":0.5}"#
        );
        let curve = parse(
            &json::parse(r#"{"ndf":"abc","alpha_abc2":2,"alpha_abc1":1e-7}"#).unwrap(),
            "",
        )
        .unwrap();
        assert_eq!(
            curve.canonical_json(),
            r#"{"ndf":"abc","alpha_abc1":1e-7,"alpha_abc2":2.0}"#
        );
    }
    #[test]
    fn label_placeholders_are_parameters_or_known_and_groups_are_not_placeholders() {
        let params = ["alpha_tr"];
        assert_eq!(unknown_placeholder("α_{tr} = {alpha_tr}", &params), None);
        assert_eq!(
            unknown_placeholder("x^{2}, {l2}, {e_avg}, {=a}", &params),
            None
        );
        assert_eq!(unknown_placeholder("\\{alpha_x}, {a b}, {", &params), None);
        assert_eq!(
            unknown_placeholder("{alpha_tr} {alpha_x}", &params),
            Some("alpha_x")
        );
        assert_eq!(unknown_placeholder("{alpha}", &params), Some("alpha"));
    }
}
