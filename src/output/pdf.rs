//! SVG → PDF: the drawn figure as a one-page vector PDF with the embedded DejaVu Sans face.
//!
//! Owns the conversion of the SVG that [`super::plot::svg`] draws (parsed by usvg, written by
//! krilla): text stays text in a subset of the embedded face, and the document information
//! dictionary carries the figure's title and provenance record. The SVG is read by
//! [`super::svg_tree`], which never loads a system font. Nothing in the document varies between runs: no date is written, and the file
//! identifiers are hashes of the content.
//!
//! It must not draw (the SVG is the drawing), compute provenance, or touch the file system.

use krilla::geom::Size;
use krilla::metadata::Metadata;
use krilla::page::PageSettings;
use krilla::{Document, SerializeSettings};
use krilla_svg::{SurfaceExt, SvgSettings};

use crate::pipeline::provenance::Provenance;

/// PDF points per CSS pixel: 72 points and 96 CSS pixels to the inch.
pub const POINTS_PER_PX: f32 = 0.75;

/// Why an SVG could not be turned into a PDF.
#[derive(Debug, thiserror::Error)]
pub enum PdfError {
    /// usvg could not read the SVG.
    #[error("the SVG could not be read: {0}")]
    Svg(#[from] usvg::Error),
    /// The page would have no area.
    #[error("the page of {width}×{height} px has no area")]
    Page {
        /// SVG width in CSS pixels.
        width: f32,
        /// SVG height in CSS pixels.
        height: f32,
    },
    /// krilla could not draw the SVG onto the page.
    #[error("the SVG could not be drawn onto the page")]
    Draw,
    /// krilla could not write the document (a font or image it could not embed).
    #[error("the PDF could not be written: {0}")]
    Write(String),
}

/// The one-page PDF of `svg` (a document as [`super::plot::svg`] writes it), its page
/// [`POINTS_PER_PX`] points per CSS pixel of the SVG's size.
///
/// The information dictionary holds `Title` = `title` (when not empty), `Creator` and `Producer`
/// = `ndfplot <version>`, and `Keywords` = the provenance record as comma-separated `key=value`
/// words (`ndfplot-version=0.1.0, spec-sha256=…`); the XMP metadata repeats them. No creation
/// date; identical input gives identical bytes.
pub fn from_svg(svg: &[u8], title: &str, provenance: &Provenance) -> Result<Vec<u8>, PdfError> {
    let tree = super::svg_tree::parse(svg)?;
    let (width, height) = (tree.size().width(), tree.size().height());
    let page = Size::from_wh(width * POINTS_PER_PX, height * POINTS_PER_PX)
        .ok_or(PdfError::Page { width, height })?;

    let mut document = Document::new_with(SerializeSettings {
        // A figure is not a structured text: no tag tree to write.
        enable_tagging: false,
        ..SerializeSettings::default()
    });
    let mut metadata = Metadata::new()
        .creator(provenance.software())
        .producer(provenance.software())
        .keywords(provenance.words());
    if !title.is_empty() {
        metadata = metadata.title(title.to_owned());
    }
    document.set_metadata(metadata);
    {
        let mut page_builder = document.start_page_with(PageSettings::new(page));
        let mut surface = page_builder.surface();
        let drawn = surface.draw_svg(&tree, page, SvgSettings::default());
        surface.finish();
        page_builder.finish();
        drawn.ok_or(PdfError::Draw)?;
    }
    document
        .finish()
        .map_err(|e| PdfError::Write(format!("{e:?}")))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A small SVG with the glyphs the figures use: Greek, subscripts, superscripts.
    const SVG: &str = r##"<svg width="200" height="100" viewBox="0 0 200 100" xmlns="http://www.w3.org/2000/svg">
<rect x="0" y="0" width="200" height="100" fill="#FFFFFF"/>
<rect x="10" y="10" width="50" height="50" fill="#2689D1" fill-opacity="0.8"/>
<rect x="30" y="30" width="50" height="50" fill="#DB2E2E" fill-opacity="0.5"/>
<polyline fill="none" stroke="#000000" stroke-width="2" points="0,90 100,10 200,90"/>
<text x="100" y="50" font-family="DejaVu Sans, sans-serif" font-size="12">θ α₂₂ 10⁴</text>
</svg>"##;

    fn pdf() -> Vec<u8> {
        from_svg(SVG.as_bytes(), "A title", &Provenance::of_spec(b"{}")).unwrap()
    }

    fn contains(haystack: &[u8], needle: &str) -> bool {
        haystack
            .windows(needle.len())
            .any(|w| w == needle.as_bytes())
    }

    #[test]
    fn the_pdf_embeds_the_face_and_the_provenance() {
        let bytes = pdf();
        assert!(bytes.starts_with(b"%PDF-"));
        assert!(contains(&bytes, "/FontFile2"), "an embedded TrueType face");
        assert!(contains(&bytes, "DejaVuSans"));
        assert!(contains(&bytes, "/Title(A title)"));
        let record = Provenance::of_spec(b"{}");
        assert!(contains(
            &bytes,
            &format!("/Producer(ndfplot {})", record.version)
        ));
        assert!(contains(
            &bytes,
            &format!("/Keywords({})", record.words().join(", "))
        ));
        assert!(!contains(&bytes, "/CreationDate"));
    }

    #[test]
    fn the_page_is_the_svg_size_in_points() {
        let bytes = pdf();
        assert!(contains(&bytes, "/MediaBox[0 0 150 75]"));
    }

    #[test]
    fn conversions_are_byte_identical_across_runs_and_threads() {
        let first = pdf();
        std::thread::scope(|scope| {
            let runs: Vec<_> = (0..3).map(|_| scope.spawn(pdf)).collect();
            for run in runs {
                assert!(run.join().unwrap() == first);
            }
        });
    }

    #[test]
    fn unreadable_svgs_are_errors() {
        let record = Provenance::without_spec();
        assert!(matches!(
            from_svg(b"<svg", "", &record),
            Err(PdfError::Svg(_))
        ));
    }
}
