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

/// The output of `figure` in `format` (see [`encode_all`]); `None` when the figure has none in
/// it (a page of a figure without sliders).
pub fn encode(figure: &Figure, format: Format) -> Result<Option<Vec<u8>>> {
    Ok(encode_all(figure, &[format])?.pop().map(|(_, bytes)| bytes))
}

/// The outputs of a figure in each of `formats`, as (format, bytes) in order; a format with no
/// output for this figure (a page of a figure without sliders) is left out. The PNG and the PDF
/// are converted from the figure's SVG, which is drawn once however many of the three are asked
/// for.
pub fn encode_all(figure: &Figure, formats: &[Format]) -> Result<Vec<(Format, Vec<u8>)>> {
    Ok(encode_all_linted(figure, formats)?.0)
}

/// [`encode_all`], with what the figure lint finds in the drawing and what the drawing chose
/// ([`plot::Linted`]) when one of `formats` draws it (SVG, PNG or PDF; nothing otherwise), from
/// the same drawing.
pub fn encode_all_linted(
    figure: &Figure,
    formats: &[Format],
) -> Result<(Vec<(Format, Vec<u8>)>, plot::Linted)> {
    let plot_error =
        |e: plot::PlotError| Error::Numerics(format!("{}: drawing failed: {e}", figure.id));
    let mut svg: Option<Vec<u8>> = None;
    let mut linted = plot::Linted::default();
    let mut encoded = Vec::with_capacity(formats.len());
    for &format in formats {
        if matches!(format, Format::Svg | Format::Png | Format::Pdf) && svg.is_none() {
            let (drawn, found) = plot::svg_linted(figure).map_err(plot_error)?;
            svg = Some(drawn);
            linted = found;
        }
        let drawn = || svg.as_ref().expect("the SVG is drawn first");
        let bytes = match format {
            Format::Svg => Some(drawn().clone()),
            Format::Png => Some(plot::png(figure, drawn()).map_err(plot_error)?),
            Format::Pdf => Some(
                pdf::from_svg(drawn(), &figure.title, &figure.provenance).map_err(|e| {
                    Error::Numerics(format!("{}: PDF conversion failed: {e}", figure.id))
                })?,
            ),
            Format::Csv => Some(figure_csv(figure)),
            Format::Html => html::page(figure),
        };
        encoded.extend(bytes.map(|b| (format, b)));
    }
    Ok((encoded, linted))
}
