//! Exporters: pure serializers from an evaluated [`Figure`] to bytes — SVG, PNG, PDF, CSV and the
//! interactive HTML page, the machine-readable command reports of [`report`] — and [`write`], the one
//! place that writes files.
//!
//! Nothing here evaluates a curve or decides what to compute: every value written comes from the
//! figure it is handed.

pub mod csv;
pub mod html;
pub mod pdf;
pub mod plot;
pub mod plot3d;
pub mod report;
pub mod stderr;
pub mod stdout;
pub mod stored;
pub mod svg_tree;
pub mod write;

use crate::error::{Error, Result};
use crate::model::names::named;
use crate::pipeline::figure::Figure;
use csv::figure_csv;

/// What a format is encoded from: the figure whose curves were sampled for drawing (adaptively,
/// over the visible range) or the one sampled as a table (uniform θ grids).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Points {
    /// The drawn figure.
    Drawn,
    /// The tabulated figure.
    Table,
}

named! {
    /// An output format of `render`, named by its file extension.
    #[derive(PartialOrd, Ord)]
    pub enum Format {
        /// Scalable vector graphics with text kept as text.
        Svg = "svg",
        /// Raster image with text drawn from the embedded font.
        Png = "png",
        /// One-page vector PDF of the SVG, text in the embedded font; only when asked for.
        Pdf = "pdf",
        /// The sampled points, long format (docs/contracts.md).
        Csv = "csv",
        /// A self-contained interactive page, for figures with sliders only.
        Html = "html",
    }
}

impl Format {
    /// File extension: the format's name.
    pub fn extension(self) -> &'static str {
        self.name()
    }

    /// Whether the format is converted from the figure's SVG drawing ([`draw`]): SVG, PNG, PDF.
    pub fn from_drawing(self) -> bool {
        match self {
            Format::Svg | Format::Png | Format::Pdf => true,
            Format::Csv | Format::Html => false,
        }
    }

    /// Which figure the format is encoded from: the CSV tabulates; the drawings, and the page
    /// (whose static figure and axes are the drawing's), draw.
    pub fn points(self) -> Points {
        match self {
            Format::Csv => Points::Table,
            Format::Svg | Format::Png | Format::Pdf | Format::Html => Points::Drawn,
        }
    }

    /// Parses a comma-separated list such as `svg,csv`.
    pub fn parse_list(text: &str) -> Result<Vec<Format>> {
        let mut formats = Vec::new();
        for word in text.split(',').map(str::trim) {
            let format = Format::from_name(word).ok_or_else(|| {
                let names: Vec<&str> = Format::NAMES.iter().map(|(n, _)| *n).collect();
                Error::Usage(format!(
                    "--format: unknown format (got \"{word}\", expected a comma list of {})",
                    names.join(", ")
                ))
            })?;
            if !formats.contains(&format) {
                formats.push(format);
            }
        }
        formats.sort();
        Ok(formats)
    }
}

/// The output of `figure` in `format`, its SVG drawn first for SVG, PNG and PDF ([`draw`],
/// [`encode_drawn`]); `None` when the figure has none in it (a page of a figure without sliders).
pub fn encode(figure: &Figure, format: Format) -> Result<Option<Vec<u8>>> {
    let drawing = if format.from_drawing() {
        Some(draw(figure)?.0)
    } else {
        None
    };
    encode_drawn(figure, drawing.as_deref(), format)
}

/// The SVG drawing of `figure` that its SVG, PNG and PDF are converted from, with what the
/// figure lint finds in it and what the drawing chose ([`plot::Linted`]).
pub fn draw(figure: &Figure) -> Result<(Vec<u8>, plot::Linted)> {
    plot::svg_linted(figure).map_err(|e| drawing_failed(figure, &e))
}

/// The output of `figure` in `format`; `None` when the figure has none in it (a page of a figure
/// without sliders). SVG, PNG and PDF are converted from `drawing`, the figure's [`draw`], which
/// must be given for them.
pub fn encode_drawn(
    figure: &Figure,
    drawing: Option<&[u8]>,
    format: Format,
) -> Result<Option<Vec<u8>>> {
    let drawn = || drawing.expect("SVG, PNG and PDF are encoded from the drawing");
    Ok(match format {
        Format::Svg => Some(drawn().to_vec()),
        Format::Png => Some(plot::png(figure, drawn()).map_err(|e| drawing_failed(figure, &e))?),
        Format::Pdf => Some(
            pdf::from_svg(drawn(), &figure.title, &figure.provenance).map_err(|e| {
                Error::Numerics(format!("{}: PDF conversion failed: {e}", figure.id))
            })?,
        ),
        Format::Csv => Some(figure_csv(figure)),
        Format::Html => html::page(figure),
    })
}

/// The error of a drawing of `figure` that failed.
fn drawing_failed(figure: &Figure, e: &plot::PlotError) -> Error {
    Error::Numerics(format!("{}: drawing failed: {e}", figure.id))
}

/// What [`encode_drawn`] of `figure` in `format` is expected to cost, in units of one element of
/// the drawing rasterized (about 10 µs): a schedule runs the dearest encodings first, so that
/// no large one is left to a single core at the end. A PNG or PDF costs one unit per element of
/// `drawing` (the SVG) and 11 more per text (shaped, then filled glyph by glyph), and a PNG one
/// more per 2 800 of its pixels; a CSV or page one per 50 points; an SVG, a copy of the drawing,
/// nothing. Measured over the catalogue, the estimate is within 5 ms of the time taken for most
/// figures; it decides only the order of the work, never its result.
pub fn encoding_cost(figure: &Figure, drawing: Option<&[u8]>, format: Format) -> f64 {
    const EXTRA_PER_TEXT: f64 = 11.0;
    const PIXELS_PER_UNIT: f64 = 2800.0;
    const POINTS_PER_UNIT: f64 = 50.0;
    match format {
        Format::Png | Format::Pdf => {
            let drawing = drawing.unwrap_or_default();
            let (mut elements, mut texts) = (0usize, 0usize);
            for (i, _) in drawing.iter().enumerate().filter(|(_, b)| **b == b'<') {
                elements += 1;
                texts += usize::from(drawing[i + 1..].starts_with(b"text"));
            }
            let (width, height) = figure.canvas.png_size();
            let pixels = if format == Format::Png {
                width * height
            } else {
                0.0
            };
            elements as f64 + EXTRA_PER_TEXT * texts as f64 + pixels / PIXELS_PER_UNIT
        }
        Format::Csv | Format::Html => figure.point_count() as f64 / POINTS_PER_UNIT,
        Format::Svg => 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The estimate follows its stated formula: a text costs 12 units (itself and 11 more), the
    /// PNG's pixels one unit per 2 800, a CSV one per 50 points, the SVG nothing.
    #[test]
    fn the_encoding_cost_is_what_its_formula_says() {
        let figure = plot::fixtures::sample();
        let (drawing, _) = draw(&figure).unwrap();
        let pdf = encoding_cost(&figure, Some(&drawing), Format::Pdf);
        let png = encoding_cost(&figure, Some(&drawing), Format::Png);
        let (width, height) = figure.canvas.png_size();
        assert!(
            (png - pdf - width * height / 2800.0).abs() < 1e-9,
            "{png} − {pdf}"
        );
        let with_text = [&drawing[..], b"<text>x</text>"].concat();
        assert_eq!(
            encoding_cost(&figure, Some(&with_text), Format::Pdf) - pdf,
            13.0,
            "the text and its closing tag"
        );
        assert!(figure.point_count() > 0);
        assert_eq!(
            encoding_cost(&figure, None, Format::Csv),
            figure.point_count() as f64 / 50.0
        );
        assert_eq!(encoding_cost(&figure, Some(&drawing), Format::Svg), 0.0);
    }
}
