//! Published fits of NDF families to the 100 MERL materials, as presets: the tables of
//! `data/published/bbm-fits/` (BSD-3-Clause, bsdfbenchmark/bbm; notice in `data/published/README.md`),
//! embedded verbatim and read into family curves on first use.
//!
//! Each source's parameters map onto an ndfplot family exactly, checked against the source's own
//! definition (bbm's `include/ndf/*.h`, `include/bsdfmodel/*.h`) and docs/maths.md:
//! - `bagher2012-sgd` (per RGB channel): bbm's D = K e^{−(α + x/α)} / ((α + x/α)^p π cos⁴θ) with
//!   x = tan²θ. Since (a₁² + x)/a₁ = α + x/α and (a₁² + x)^{a₂} = α^p (α + x/α)^p, docs/maths.md's SGD with
//!   a₁ = α, a₂ = p is the same lobe with K = 1/(α Γ(1 − p, α)): `alpha` → `alpha_sgd1`, `p` →
//!   `alpha_sgd2`, and the file's `K` (6 digits) must come out of it, as a test checks.
//! - `low2012-abc`: Low et al.'s S = (1 + B(1 − cos θ))^{−C}, unnormalized (their `A` scales it), is
//!   docs/maths.md's ABC lobe u: `B` → `alpha_abc1`, `C` → `alpha_abc2`; one lobe per material.
//! - `low2012-cook-torrance`, `ngan2005-cook-torrance`: Beckmann's exp(−tan²θ/m²)/(m² cos⁴θ) (Low's
//!   without the 1/π, which their scale absorbs): `roughness` m → `alpha_b`.
//! - `ngan2005-blinn-phong`: Ngan et al.'s Blinn–Phong lobe cosⁿθ_h about the half vector, so
//!   `sharpness` n → `alpha_p`. (bbm evaluates it as a lobe about the mirror direction, whose exponent
//!   would be about a quarter of the half-vector one; the fitted values are half-vector exponents: with
//!   Ngan's own Cook–Torrance roughness m, n / (2/m² − 2) has a median of 1.3 over the 86 materials, as
//!   a test checks.)
//!
//! This module holds the data and looks fits up; the curve format ([`crate::spec::curve`]) parses the
//! names and [`crate::pipeline::resolve`] turns a [`Preset`] into its curve.

use crate::model::ndf::{Family, Ndf};
use std::sync::OnceLock;

/// A source of published fits (`"published": "<name>"`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Source {
    /// Bagher, Soler, Holzschuch 2012: Shifted Gamma, per RGB channel.
    Bagher2012Sgd,
    /// Low, Kronander, Ynnerman, Unger 2012: ABC ("Low microfacet"), E2 fits.
    Low2012Abc,
    /// Low et al. 2012: Cook–Torrance (Beckmann), E2 fits.
    Low2012CookTorrance,
    /// Ngan, Durand, Matusik 2005: Cook–Torrance (Beckmann).
    Ngan2005CookTorrance,
    /// Ngan et al. 2005: Blinn–Phong.
    Ngan2005BlinnPhong,
}

impl Source {
    /// Every source, in the order messages list them.
    pub const ALL: [Source; 5] = [
        Source::Bagher2012Sgd,
        Source::Low2012Abc,
        Source::Low2012CookTorrance,
        Source::Ngan2005CookTorrance,
        Source::Ngan2005BlinnPhong,
    ];

    /// The name in curve JSON.
    pub fn name(self) -> &'static str {
        match self {
            Source::Bagher2012Sgd => "bagher2012-sgd",
            Source::Low2012Abc => "low2012-abc",
            Source::Low2012CookTorrance => "low2012-cook-torrance",
            Source::Ngan2005CookTorrance => "ngan2005-cook-torrance",
            Source::Ngan2005BlinnPhong => "ngan2005-blinn-phong",
        }
    }

    /// Looks a source up by name, in any case.
    pub fn from_name(name: &str) -> Option<Source> {
        Source::ALL
            .into_iter()
            .find(|s| s.name().eq_ignore_ascii_case(name))
    }

    /// How legends name the source: authors, year and fitted model.
    pub fn title(self) -> &'static str {
        match self {
            Source::Bagher2012Sgd => "Bagher 2012 SGD",
            Source::Low2012Abc => "Low 2012 ABC",
            Source::Low2012CookTorrance => "Low 2012 Cook–Torrance",
            Source::Ngan2005CookTorrance => "Ngan 2005 Cook–Torrance",
            Source::Ngan2005BlinnPhong => "Ngan 2005 Blinn–Phong",
        }
    }

    /// The family the source's lobes belong to.
    pub fn family(self) -> Family {
        match self {
            Source::Bagher2012Sgd => Family::Sgd,
            Source::Low2012Abc => Family::Abc,
            Source::Low2012CookTorrance | Source::Ngan2005CookTorrance => Family::Beckmann,
            Source::Ngan2005BlinnPhong => Family::Phong,
        }
    }

    /// Whether the source fits each RGB channel separately (a preset then names its channel).
    pub fn per_channel(self) -> bool {
        self == Source::Bagher2012Sgd
    }

    /// The materials the source fits, in file order.
    pub fn materials(self) -> impl Iterator<Item = &'static str> {
        table(self).iter().map(|fit| fit.material)
    }

    /// The source's embedded table, its fitted model's name in it, and the table's parameter names
    /// in the family's order.
    fn layout(self) -> (&'static str, &'static str, &'static [&'static str]) {
        match self {
            Source::Bagher2012Sgd => (
                include_str!("../../data/published/bbm-fits/bagher_sgd.fit"),
                "Bagher",
                &["alpha", "p"],
            ),
            Source::Low2012Abc => (
                include_str!("../../data/published/bbm-fits/low_lowmicrofacet_E2.fit"),
                "LowMicrofacetFit",
                &["B", "C"],
            ),
            Source::Low2012CookTorrance => (
                include_str!("../../data/published/bbm-fits/low_cooktorrance_E2.fit"),
                "LowCookTorrance",
                &["roughness"],
            ),
            Source::Ngan2005CookTorrance => (
                include_str!("../../data/published/bbm-fits/ngan_cooktorrance.fit"),
                "NganCookTorrance",
                &["roughness"],
            ),
            Source::Ngan2005BlinnPhong => (
                include_str!("../../data/published/bbm-fits/ngan_blinnphong.fit"),
                "NganBlinnPhong",
                &["sharpness"],
            ),
        }
    }
}

/// An RGB channel of a per-channel fit (`"channel": "red"`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Channel {
    /// The first value of each per-channel list.
    Red,
    /// The second.
    Green,
    /// The third.
    Blue,
}

impl Channel {
    /// Every channel, in the tables' order.
    pub const ALL: [Channel; 3] = [Channel::Red, Channel::Green, Channel::Blue];

    /// The name in curve JSON.
    pub fn name(self) -> &'static str {
        match self {
            Channel::Red => "red",
            Channel::Green => "green",
            Channel::Blue => "blue",
        }
    }

    /// Looks a channel up by name, in any case.
    pub fn from_name(name: &str) -> Option<Channel> {
        Channel::ALL
            .into_iter()
            .find(|c| c.name().eq_ignore_ascii_case(name))
    }

    fn index(self) -> usize {
        self as usize
    }
}

/// Why a (source, material, channel) triple names no fit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PresetError {
    /// The source has no fit for the material.
    UnknownMaterial,
    /// The source fits per channel and no channel was given.
    ChannelRequired,
    /// The source fits one lobe per material and a channel was given.
    ChannelRefused,
}

/// One published fit: a source's lobe for a material (and channel, for a per-channel source).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Preset {
    source: Source,
    /// Index of the material's line in the source's table.
    index: usize,
    channel: Option<Channel>,
}

impl Preset {
    /// The fit of `material` by `source`; `channel` is required exactly when the source fits per
    /// channel.
    pub fn new(
        source: Source,
        material: &str,
        channel: Option<Channel>,
    ) -> Result<Preset, PresetError> {
        let index = table(source)
            .iter()
            .position(|fit| fit.material == material)
            .ok_or(PresetError::UnknownMaterial)?;
        match (source.per_channel(), channel) {
            (true, None) => Err(PresetError::ChannelRequired),
            (false, Some(_)) => Err(PresetError::ChannelRefused),
            _ => Ok(Preset {
                source,
                index,
                channel,
            }),
        }
    }

    /// The source.
    pub fn source(&self) -> Source {
        self.source
    }

    /// The MERL material's name.
    pub fn material(&self) -> &'static str {
        table(self.source)[self.index].material
    }

    /// The channel, for a per-channel source.
    pub fn channel(&self) -> Option<Channel> {
        self.channel
    }

    /// The fitted lobe as a curve of the source's family, its parameters converted as the module
    /// header states.
    pub fn ndf(&self) -> Ndf {
        table(self.source)[self.index].lobes[self.channel.map_or(0, Channel::index)].clone()
    }
}

/// One line of a table: a material and its lobes (three for a per-channel source, else one).
#[derive(Debug)]
struct Fit {
    material: &'static str,
    lobes: Vec<Ndf>,
}

/// The fits of `source`, read from its embedded table on first use.
fn table(source: Source) -> &'static [Fit] {
    static TABLES: [OnceLock<Vec<Fit>>; 5] = [const { OnceLock::new() }; 5];
    let index = Source::ALL
        .iter()
        .position(|&s| s == source)
        .expect("ALL lists every source");
    TABLES[index].get_or_init(|| read_table(source))
}

/// Reads every `<material> = Aggregate(Lambertian(…), <Model>(…, name = value | [r, g, b], …))`
/// line of the source's table into lobes; comment lines (`#`) are skipped. A line whose parameters
/// cannot be read or lie outside the family's domain is left out (a test checks that every line of
/// every table is read).
fn read_table(source: Source) -> Vec<Fit> {
    let (text, model, names) = source.layout();
    let channels = if source.per_channel() { 3 } else { 1 };
    text.lines()
        .filter(|line| !line.starts_with('#') && !line.trim().is_empty())
        .filter_map(|line| {
            let (material, rest) = line.split_once(" = ")?;
            let model_text = &rest[rest.find(&format!("{model}("))?..];
            let columns: Vec<Vec<f64>> = names
                .iter()
                .map(|name| attribute(model_text, name))
                .collect::<Option<_>>()?;
            let lobes = (0..channels)
                .map(|c| {
                    let params: Vec<f64> = columns
                        .iter()
                        .map(|values| values.get(c).copied())
                        .collect::<Option<_>>()?;
                    source.family().build(&params).ok()
                })
                .collect::<Option<Vec<Ndf>>>()?;
            Some(Fit {
                material: material.trim(),
                lobes,
            })
        })
        .collect()
}

/// The values of attribute `name` in a model's argument list: `name = 0.5` gives `[0.5]`,
/// `name = [1, 2, 3]` gives `[1, 2, 3]`. The name must follow `(` or a space, so `p` is not found
/// inside `alpha`'s neighbours and `K` is not `k`.
fn attribute(model_text: &str, name: &str) -> Option<Vec<f64>> {
    let pattern = format!("{name} = ");
    let start = model_text
        .match_indices(&pattern)
        .map(|(i, _)| i)
        .find(|&i| i > 0 && matches!(model_text.as_bytes()[i - 1], b'(' | b' '))?;
    let value = &model_text[start + pattern.len()..];
    let text = match value.strip_prefix('[') {
        Some(list) => &list[..list.find(']')?],
        None => &value[..value.find([',', ')'])?],
    };
    text.split(',').map(|v| v.trim().parse().ok()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lines(source: Source) -> usize {
        let (text, _, _) = source.layout();
        text.lines()
            .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
            .count()
    }

    #[test]
    fn every_line_of_every_table_is_read_into_its_family() {
        for source in Source::ALL {
            let expected = match source {
                Source::Ngan2005CookTorrance | Source::Ngan2005BlinnPhong => 86,
                _ => 100,
            };
            assert_eq!(lines(source), expected, "{}", source.name());
            assert_eq!(table(source).len(), expected, "{}", source.name());
            for fit in table(source) {
                assert!(
                    fit.lobes
                        .iter()
                        .all(|lobe| lobe.family() == source.family())
                );
            }
        }
    }

    #[test]
    fn conversions_take_the_tables_values_unchanged() {
        let gold = |source, channel| {
            Preset::new(source, "gold-metallic-paint", channel)
                .unwrap()
                .ndf()
                .params()
        };
        assert_eq!(
            gold(Source::Bagher2012Sgd, Some(Channel::Blue)),
            [0.109623, 0.661313]
        );
        assert_eq!(gold(Source::Low2012Abc, None), [53.738525, 1.51173]);
        assert_eq!(gold(Source::Low2012CookTorrance, None), [0.218404]);
        assert_eq!(gold(Source::Ngan2005CookTorrance, None), [0.241]);
        assert_eq!(gold(Source::Ngan2005BlinnPhong, None), [41.9]);
    }

    #[test]
    fn channels_are_required_exactly_for_per_channel_sources() {
        let preset = |source, channel| Preset::new(source, "gray-plastic", channel);
        assert_eq!(
            preset(Source::Bagher2012Sgd, None),
            Err(PresetError::ChannelRequired)
        );
        assert_eq!(
            preset(Source::Low2012Abc, Some(Channel::Red)),
            Err(PresetError::ChannelRefused)
        );
        assert!(preset(Source::Ngan2005BlinnPhong, None).is_ok());
        assert_eq!(
            Preset::new(Source::Low2012Abc, "gold-metalic-paint", None),
            Err(PresetError::UnknownMaterial)
        );
    }

    /// The SGD table prints K = 1/(α Γ(1 − p, α)) to 6 significant digits. Through the converted lobe,
    /// D(0) = e^{−α} K / (π α^p) (bbm's form at θ = 0), so K = π D(0) e^α α^p must round to the printed
    /// value: within half a unit of its 6th digit (plus 1e-9 relative for the f64 evaluation).
    #[test]
    fn sgd_normalization_k_of_the_table_comes_out_of_the_conversion() {
        let (text, model, _) = Source::Bagher2012Sgd.layout();
        let mut checked = 0;
        for line in text.lines().filter(|l| !l.starts_with('#')) {
            let (material, rest) = line.split_once(" = ").unwrap();
            let printed = attribute(&rest[rest.find(model).unwrap()..], "K").unwrap();
            for channel in Channel::ALL {
                let lobe = Preset::new(Source::Bagher2012Sgd, material, Some(channel))
                    .unwrap()
                    .ndf();
                let [alpha, p] = lobe.params()[..] else {
                    unreachable!()
                };
                let k = std::f64::consts::PI * lobe.eval(0.0) * alpha.exp() * alpha.powf(p);
                let printed = printed[channel.index()];
                let half_unit = 0.5 * 10f64.powf(printed.abs().log10().floor() - 5.0);
                assert!(
                    (k - printed).abs() <= half_unit + 1e-9 * printed.abs(),
                    "{material} {}: K = {k} from the conversion, {printed} printed",
                    channel.name()
                );
                checked += 1;
            }
        }
        assert_eq!(checked, 300);
    }

    /// Ngan's Blinn–Phong exponents are half-vector exponents, like α_p: against Walter's equivalence
    /// α_p = 2/m² − 2 with Ngan's own Cook–Torrance roughness m of the same material, their median ratio
    /// is near 1 (1.3), where exponents of a lobe about the mirror direction would give about 1/4.
    #[test]
    fn ngan_blinn_phong_sharpness_is_a_half_vector_exponent() {
        let mut ratios: Vec<f64> = Source::Ngan2005BlinnPhong
            .materials()
            .map(|material| {
                let phong = Preset::new(Source::Ngan2005BlinnPhong, material, None)
                    .unwrap()
                    .ndf()
                    .params()[0];
                let m = Preset::new(Source::Ngan2005CookTorrance, material, None)
                    .unwrap()
                    .ndf()
                    .params()[0];
                phong / (2.0 / (m * m) - 2.0)
            })
            .collect();
        ratios.sort_by(f64::total_cmp);
        let median = ratios[ratios.len() / 2];
        assert!((0.9..1.6).contains(&median), "median ratio {median}");
    }

    #[test]
    fn attributes_are_found_by_whole_name() {
        let text = "Bagher(albedo = [1, 2, 3], alpha = [0.5, 0.25, 2], p = [1, 2, 3], K = [7, 8, 9], k = [0, 0, 0])";
        assert_eq!(attribute(text, "p"), Some(vec![1.0, 2.0, 3.0]));
        assert_eq!(attribute(text, "K"), Some(vec![7.0, 8.0, 9.0]));
        assert_eq!(attribute("M(B = 53.7, C = 1.5)", "C"), Some(vec![1.5]));
        assert_eq!(attribute("M(B = 53.7, C = 1.5)", "eta"), None);
    }
}
