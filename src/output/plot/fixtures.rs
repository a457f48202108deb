//! Test figures shared by the plot writer's tests: series, panels and figures in the shapes
//! of the catalogue (NDF and Fresnel panels, marks, a surface), and helpers to read the output.

use std::f64::consts::{FRAC_PI_2, PI};
use std::sync::Arc;

use crate::pipeline::figure::{Figure, Panel, Series};
use crate::pipeline::provenance::Provenance;
use crate::spec::look::{Axes, Canvas, Dash, Mark, PanelKind, Rgb, Scale, Style, Theme, XUnit};

/// The PNG of `figure`, rasterized from its SVG as `render` does.
pub(super) fn draw_png(figure: &Figure) -> Result<Vec<u8>, super::PlotError> {
    super::png(figure, &super::svg(figure)?)
}

/// The spec text the test figures claim to come from.
pub(super) const SPEC: &[u8] = br#"{"id": "sample"}"#;

pub(super) const RED: u32 = 0xDB2E2E;
pub(super) const BLUE: u32 = 0x2689D1;
/// Dark enough for 3:1 contrast on white, so the notebook theme draws it as given.
pub(super) const ORANGE: u32 = 0xC76A00;

pub(super) fn series(
    label: &str,
    hex: u32,
    width: f64,
    dash: Dash,
    points: Vec<(f64, f64)>,
) -> Series {
    Series {
        label: label.to_owned(),
        curve: "{}".to_owned(),
        style: Style {
            colour: Rgb::from_hex(hex),
            width,
            dash,
            mark: Mark::Line,
            sweep: None,
        },
        points: Arc::new(points),
        z: None,
        grid: None,
    }
}

pub(super) fn marked(mut series: Series, mark: Mark) -> Series {
    series.style.mark = mark;
    series
}

pub(super) fn in_3d(mut series: Series, z: Vec<f64>, grid: Option<(usize, usize)>) -> Series {
    series.z = Some(Arc::new(z));
    series.grid = grid;
    series
}

pub(super) fn sampled(f: impl Fn(f64) -> f64) -> Vec<(f64, f64)> {
    (0..=200)
        .map(|i| f64::from(i) / 200.0 * FRAC_PI_2)
        .map(|theta| (theta, f(theta)))
        .collect()
}

fn beckmann(alpha_b: f64) -> Vec<(f64, f64)> {
    sampled(|theta| {
        let cos = theta.cos();
        let tan2 = theta.tan().powi(2);
        (-tan2 / (alpha_b * alpha_b)).exp() / (PI * alpha_b * alpha_b * cos.powi(4))
    })
}

pub(super) fn panel(x_unit: XUnit, y_scale: Scale, series: Vec<Series>) -> Panel {
    Panel {
        axes: Axes::cartesian("θ", "D(θ)", x_unit, y_scale),
        series,
    }
}

pub(super) fn figure(panels: Vec<Panel>) -> Figure {
    Figure {
        id: "sample".to_owned(),
        title: "NDF and Fresnel".to_owned(),
        rows: 1,
        cols: panels.len().max(1),
        canvas: Canvas {
            width_px: 400,
            height_px: 250,
            png_scale: 2.0,
            font_px: 12.0,
            print: None,
            transparent: false,
            face: crate::spec::look::Face::Sans,
        },
        theme: Theme::Notebook,
        panels,
        provenance: Provenance::of_spec(SPEC),
        page: None,
    }
}

/// A log panel in radians (a dashed series) and a linear panel in degrees (a thick one).
pub(crate) fn sample() -> Figure {
    let mut log = panel(
        XUnit::Radians,
        Scale::Log,
        vec![
            series("α_b = 0.4", RED, 1.0, Dash::Dashed, beckmann(0.4)),
            series("α_b = 0.8", BLUE, 1.0, Dash::Solid, beckmann(0.8)),
        ],
    );
    log.axes.title = "Beckmann".to_owned();
    let schlick = |f0: f64| sampled(move |theta| f0 + (1.0 - f0) * (1.0 - theta.cos()).powi(5));
    let mut fresnel = panel(
        XUnit::Degrees,
        Scale::Linear,
        vec![
            series("F₀ = 0.04", ORANGE, 2.0, Dash::Solid, schlick(0.04)),
            series("F₀ = 0.5", RED, 1.0, Dash::Dotted, schlick(0.5)),
        ],
    );
    fresnel.axes.y_label = "F".to_owned();
    figure(vec![log, fresnel])
}

pub(super) const BLACK: u32 = 0x000000;
pub(super) const STEEL: u32 = 0x1F77B4;

/// Singular values of a Fresnel curve matrix, normalized by their sum: the first three
/// from docs/maths.md's spectrum check, then a geometric tail.
fn spectrum() -> Vec<f64> {
    let mut values = vec![0.91356, 0.97961 - 0.91356, 0.99477 - 0.97961];
    let tail = 1.0 - 0.99477;
    values.extend((1..=17).map(|k| tail * 0.5f64.powi(k) / (1.0 - 0.5f64.powi(17))));
    values
}

/// A smooth stand-in for the Gulbrandsen coefficient manifold: (c₀, c₂, c₃) at (r, g).
fn manifold(r: f64, g: f64) -> [f64; 3] {
    let c0 = r + 0.2 * g * r * (1.0 - r);
    let c2 = 0.3 * (PI * r).sin() * (2.0 * g - 1.0) * (1.0 - 0.3 * r);
    let c3 = 0.8 * (g - 0.5) * (1.0 - r) * (PI * r).cos();
    [c0, c2, c3]
}

/// `n` values evenly spaced over [0, 1].
fn unit_steps(n: usize) -> impl Iterator<Item = f64> + Clone {
    (0..n).map(move |i| i as f64 / (n - 1) as f64)
}

/// The manifold over an `n × n` (r, g) grid, row-major in r.
pub(super) fn manifold_grid(n: usize) -> Vec<[f64; 3]> {
    let gs = unit_steps(n);
    unit_steps(n)
        .flat_map(|r| gs.clone().map(move |g| manifold(r, g)))
        .collect()
}

/// The edge of the manifold at edge tint `g`, sampled at 100 values of r.
pub(super) fn manifold_edge(g: f64) -> Vec<[f64; 3]> {
    unit_steps(100).map(|r| manifold(r, g)).collect()
}

pub(super) fn xy(points: &[[f64; 3]]) -> Vec<(f64, f64)> {
    points.iter().map(|p| (p[0], p[1])).collect()
}

pub(super) fn zs(points: &[[f64; 3]]) -> Vec<f64> {
    points.iter().map(|p| p[2]).collect()
}

pub(super) fn surface_kind(z_range: Option<(f64, f64)>) -> PanelKind {
    PanelKind::Surface {
        z_label: "c₃".to_owned(),
        z_range,
        elevation_deg: 65.0,
        azimuth_deg: -45.0,
    }
}

/// A plain-axis spectrum (bars, line with dots, a dashed level), a 2500-point scatter with
/// two lines, and a 20 × 20 surface with two 3D lines.
pub(super) fn fresnel_sample() -> Figure {
    let values = spectrum();
    let index = |i: usize| i as f64;
    let bars: Vec<(f64, f64)> = values
        .iter()
        .enumerate()
        .map(|(i, &v)| (index(i), v))
        .collect();
    let cumulative: Vec<(f64, f64)> = values
        .iter()
        .scan(0.0, |sum, &v| {
            *sum += v;
            Some(*sum)
        })
        .enumerate()
        .map(|(i, v)| (index(i), v))
        .collect();
    let mut spectrum = panel(
        XUnit::Plain,
        Scale::Linear,
        vec![
            marked(series("sₖ / Σs", STEEL, 1.0, Dash::Solid, bars), Mark::Bars),
            marked(
                series("cumulative", ORANGE, 1.0, Dash::Solid, cumulative),
                Mark::LinePoints,
            ),
            series(
                "0.99",
                RED,
                1.0,
                Dash::Dashed,
                vec![(0.0, 0.99), (19.0, 0.99)],
            ),
        ],
    );
    spectrum.axes.title = "Spectrum".to_owned();
    spectrum.axes.x_label = "Number of basis elements".to_owned();
    spectrum.axes.y_label = "Cumulative singular values".to_owned();

    let dielectric = manifold_edge(0.0);
    let conductor = manifold_edge(1.0);
    let mut scatter = panel(
        XUnit::Plain,
        Scale::Linear,
        vec![
            marked(
                series("", STEEL, 1.0, Dash::Solid, xy(&manifold_grid(50))),
                Mark::Points,
            ),
            series("g = 0", RED, 1.0, Dash::Solid, xy(&dielectric)),
            series("g = 1", BLACK, 1.0, Dash::Solid, xy(&conductor)),
        ],
    );
    scatter.axes.title = "Gulbrandsen parametrization".to_owned();
    scatter.axes.x_label = "c₀".to_owned();
    scatter.axes.y_label = "c₂".to_owned();
    scatter.axes.x_range = Some((0.0, 1.0));
    scatter.axes.y_range = Some((-0.35, 0.35));

    let grid = manifold_grid(20);
    let mut surface = panel(
        XUnit::Plain,
        Scale::Linear,
        vec![
            in_3d(
                series("manifold", STEEL, 1.0, Dash::Solid, xy(&grid)),
                zs(&grid),
                Some((20, 20)),
            ),
            in_3d(
                series("g = 0", RED, 1.0, Dash::Solid, xy(&dielectric)),
                zs(&dielectric),
                None,
            ),
            in_3d(
                series("g = 1", BLACK, 1.0, Dash::Solid, xy(&conductor)),
                zs(&conductor),
                None,
            ),
        ],
    );
    surface.axes.kind = surface_kind(Some((-1.0, 1.0)));
    surface.axes.title = "Coefficient manifold".to_owned();
    surface.axes.x_label = "c₀".to_owned();
    surface.axes.y_label = "c₂".to_owned();
    surface.axes.x_range = Some((0.0, 1.0));
    surface.axes.y_range = Some((-0.4, 0.4));

    let mut figure = figure(vec![spectrum, scatter, surface]);
    figure.title = "Fresnel decomposition".to_owned();
    figure.canvas.width_px = 1350;
    figure.canvas.height_px = 450;
    figure
}

pub(super) fn decode(bytes: &[u8]) -> (u32, u32, Vec<u8>) {
    let mut reader = png::Decoder::new(std::io::Cursor::new(bytes))
        .read_info()
        .expect("PNG header");
    let mut pixels = vec![0; reader.output_buffer_size().expect("a decodable size")];
    let info = reader.next_frame(&mut pixels).expect("PNG data");
    pixels.truncate(info.buffer_size());
    (info.width, info.height, pixels)
}

pub(super) fn polylines_in(svg: &str, hex: u32) -> usize {
    let stroke = format!(r##"stroke="#{hex:06X}""##);
    svg.lines()
        .filter(|l| l.starts_with("<polyline") && l.contains(&stroke))
        .count()
}

/// Phong's lobe (α_p + 2)/(2π) cos^α_p θ over [0, π/2].
pub(super) fn phong(alpha_p: f64) -> Vec<(f64, f64)> {
    sampled(|theta| (alpha_p + 2.0) / (2.0 * PI) * theta.cos().powf(alpha_p))
}

/// Two polar panels: Beckmann lobes on a linear radius in degrees, and Phong lobes on a log
/// radius in radians.
pub(super) fn polar_sample() -> Figure {
    let polar = |title: &str, x_unit, y_scale, series| {
        let mut p = panel(x_unit, y_scale, series);
        p.axes.kind = PanelKind::Polar;
        p.axes.title = title.to_owned();
        p
    };
    let beckmann = vec![
        series("α_b = 0.4", RED, 1.0, Dash::Dashed, beckmann(0.4)),
        series("α_b = 0.8", BLUE, 1.0, Dash::Solid, beckmann(0.8)),
    ];
    let phong = vec![
        series("α_p = 10", RED, 2.0, Dash::Solid, phong(10.0)),
        series("α_p = 100", ORANGE, 1.0, Dash::Solid, phong(100.0)),
    ];
    let mut figure = figure(vec![
        polar("Beckmann", XUnit::Degrees, Scale::Linear, beckmann),
        polar("Phong, log radius", XUnit::Radians, Scale::Log, phong),
    ]);
    figure.title = "Lobes in the plane of incidence".to_owned();
    figure.canvas.width_px = 900;
    figure.canvas.height_px = 400;
    figure
}
