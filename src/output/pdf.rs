//! SVG → PDF: the drawn figure as a one-page vector PDF with the embedded DejaVu Sans face.
//!
//! Owns the conversion of the SVG that [`super::plot::svg`] draws (parsed by usvg, written by
//! krilla): text stays text in a subset of the embedded face, and the document information
//! dictionary carries the figure's title and provenance record. The font database holds only the
//! embedded face; system fonts are never loaded, so the output is the same on a machine with no
//! fonts at all. Nothing in the document varies between runs: no date is written, and the file
//! identifiers are hashes of the content.
//!
//! It must not draw (the SVG is the drawing), compute provenance, or touch the file system.

use std::sync::{Arc, OnceLock};

use krilla::geom::Size;
use krilla::metadata::Metadata;
use krilla::page::PageSettings;
use krilla::{Document, SerializeSettings};
use krilla_svg::{SurfaceExt, SvgSettings};
use usvg::fontdb;

use crate::provenance::Provenance;

/// PDF points per CSS pixel: 72 points and 96 CSS pixels to the inch.
pub const POINTS_PER_PX: f32 = 0.75;

/// Family that the SVG names first and that every generic family resolves to.
const FAMILY: &str = "DejaVu Sans";

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
    let options = usvg::Options {
        font_family: FAMILY.to_owned(),
        fontdb: Arc::clone(font_database()),
        ..usvg::Options::default()
    };
    let tree = usvg::Tree::from_data(svg, &options)?;
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

/// The font database of every conversion: the embedded DejaVu Sans face only, also answering
/// for the generic families, built once per process.
fn font_database() -> &'static Arc<fontdb::Database> {
    static DATABASE: OnceLock<Arc<fontdb::Database>> = OnceLock::new();
    DATABASE.get_or_init(|| {
        let mut database = fontdb::Database::new();
        database.load_font_data(dejavu::sans::regular().to_vec());
        database.set_sans_serif_family(FAMILY);
        database.set_serif_family(FAMILY);
        database.set_monospace_family(FAMILY);
        database.set_cursive_family(FAMILY);
        database.set_fantasy_family(FAMILY);
        Arc::new(database)
    })
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
        assert!(contains(&bytes, "/Title (A title)"));
        let record = Provenance::of_spec(b"{}");
        assert!(contains(
            &bytes,
            &format!("/Producer (ndfplot {})", record.version)
        ));
        assert!(contains(
            &bytes,
            &format!("/Keywords ({})", record.words().join(", "))
        ));
        assert!(!contains(&bytes, "/CreationDate"));
    }

    #[test]
    fn fonts_come_from_the_embedded_face_only() {
        let faces: Vec<_> = font_database().faces().collect();
        assert_eq!(faces.len(), 1, "no system font is ever loaded");
        assert_eq!(faces[0].families[0].0, FAMILY);
    }

    #[test]
    fn the_page_is_the_svg_size_in_points() {
        let bytes = pdf();
        assert!(contains(&bytes, "/MediaBox [0 0 150 75]"));
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
