//! The drawn SVG read back as a usvg tree, for the outputs converted from it (PNG and PDF).
//!
//! Owns the font database of those conversions: the embedded DejaVu Sans and DejaVu Serif faces
//! only (upright, and oblique or italic for variables), also answering for the generic families,
//! so text is laid out the same on a machine with no fonts.

use std::sync::{Arc, OnceLock};

use usvg::fontdb;

/// Family of the default face, which every generic family but `serif` resolves to.
const FAMILY: &str = "DejaVu Sans";
/// Family of the serif face, which `serif` resolves to.
const SERIF_FAMILY: &str = "DejaVu Serif";

/// The usvg tree of `svg` (a document as [`super::plot::svg`] writes it), its text set in the
/// embedded face.
pub fn parse(svg: &[u8]) -> Result<usvg::Tree, usvg::Error> {
    let options = usvg::Options {
        font_family: FAMILY.to_owned(),
        fontdb: Arc::clone(font_database()),
        ..usvg::Options::default()
    };
    usvg::Tree::from_data(svg, &options)
}

/// The font database of every conversion: the four embedded DejaVu faces only, read where they
/// are embedded (not copied), built once per process.
fn font_database() -> &'static Arc<fontdb::Database> {
    static DATABASE: OnceLock<Arc<fontdb::Database>> = OnceLock::new();
    DATABASE.get_or_init(|| {
        let mut database = fontdb::Database::new();
        for face in [
            dejavu::sans::regular(),
            dejavu::sans::oblique(),
            dejavu::serif::regular(),
            dejavu::serif::italic(),
        ] {
            // The embedded bytes as they are, not a copy of them.
            database.load_font_source(fontdb::Source::Binary(Arc::new(face)));
        }
        database.set_sans_serif_family(FAMILY);
        database.set_serif_family(SERIF_FAMILY);
        database.set_monospace_family(FAMILY);
        database.set_cursive_family(FAMILY);
        database.set_fantasy_family(FAMILY);
        Arc::new(database)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fonts_come_from_the_embedded_faces_only() {
        let faces: Vec<_> = font_database().faces().collect();
        assert_eq!(faces.len(), 4, "no system font is ever loaded");
        for family in [FAMILY, SERIF_FAMILY] {
            let of: Vec<_> = faces.iter().filter(|f| f.families[0].0 == family).collect();
            assert_eq!(of.len(), 2, "{family}");
            assert!(of.iter().any(|f| f.style != fontdb::Style::Normal));
        }
    }
}
