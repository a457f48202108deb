//! Bytes out: the device size of a canvas, the finishing touches of the SVG document, its
//! rasterization and the PNG encoding, each carrying the figure's provenance record. Nothing here draws, and nothing
//! here computes the record: it only embeds it.

use super::PlotError;
use super::device_size;
use super::style::{EM_PER_SIZE, family};
use crate::pipeline::provenance::Provenance;
use crate::spec::look::Canvas;

/// The PNG's size in pixels ([`Canvas::png_size`]), after checking it as [`device_size`] does
/// and against [`Canvas::MAX_PNG_PIXELS`], the cap that validation enforces.
pub(super) fn png_size(canvas: &Canvas) -> Result<(u32, u32), PlotError> {
    device_size(canvas, canvas.png_scale)?;
    let (width, height) = canvas.png_size();
    let (width, height) = (width.max(1.0) as u32, height.max(1.0) as u32);
    if u64::from(width) * u64::from(height) > Canvas::MAX_PNG_PIXELS {
        return Err(PlotError::Canvas {
            width_px: canvas.width_px,
            height_px: canvas.height_px,
            scale: canvas.png_scale,
            font_px: canvas.font_px,
            reason: "the raster would exceed 2^26 pixels",
        });
    }
    Ok((width, height))
}

/// Gives the SVG its CSS size, font family and font sizes, and puts the provenance record in a
/// `<metadata>` element right after the opening tag, as `key=value` words
/// (`<metadata>ndfplot-version=0.1.0 spec-sha256=…</metadata>`).
///
/// The drawing was made at `SVG_UNITS_PER_PX` units per pixel, so the `viewBox` keeps those
/// units. plotters' SVG backend writes `font-family="<registered name>" font-size="size / 1.24"`;
/// the family gets its generic fallback, and the size becomes the em size that the raster
/// backend uses for the same text style, so that SVG and PNG text have the same extent.
pub(super) fn finish_svg(
    document: &str,
    canvas: &Canvas,
    (width, height): (u32, u32),
    provenance: &Provenance,
) -> String {
    /// plotters-svg 0.3.7 divides the style size by this to get `font-size`.
    const PLOTTERS_SVG_DIVISOR: f64 = 1.24;
    let drawn = format!(r#"<svg width="{width}" height="{height}" "#);
    let sized = match canvas.print {
        Some(print) => format!(
            r#"<svg width="{}{unit}" height="{}{unit}" "#,
            crate::spec::numbers::pretty(print.width),
            crate::spec::numbers::pretty(print.height),
            unit = print.unit.symbol()
        ),
        None => format!(
            r#"<svg width="{}" height="{}" "#,
            canvas.width_px, canvas.height_px
        ),
    };
    let document = paint_opacity(&document.replacen(&drawn, &sized, 1));
    // The opening tag ends at the first `>`: plotters writes no `>` inside its attributes.
    let document = match document.split_once('>') {
        Some((open, rest)) => format!(
            "{open}>\n<metadata>{}</metadata>{rest}",
            provenance.words().join(" ")
        ),
        None => document,
    };
    // The embedded face, then its generic family as the fallback.
    let (name, generic) = family(canvas.face);
    let marker = format!(r#"font-family="{name}" font-size=""#);
    let mut parts = document.split(marker.as_str());
    let mut out = String::with_capacity(document.len() + document.len() / 16);
    out.push_str(parts.next().unwrap_or_default());
    for part in parts {
        let (size, rest) = part.split_once('"').unwrap_or(("", part));
        let em = size.parse::<f64>().unwrap_or(0.0) * PLOTTERS_SVG_DIVISOR * EM_PER_SIZE;
        out.push_str(&format!(
            r#"font-family="{name}, {generic}" font-size="{em:.2}""#
        ));
        out.push_str(&preserve_spaces(rest));
    }
    out
}

/// `document` with each element's `opacity` moved onto its one paint: plotters draws every
/// element either filled or stroked, never both, so `opacity="a" fill="…"` is
/// `fill-opacity="a" fill="…"` and `opacity="a" stroke="…"` is `stroke-opacity="a" stroke="…"`,
/// and `opacity="1"` says nothing. The picture is the same, but a renderer need not paint a
/// translucent element into a layer of its own first (a legend's background, a surface's facets).
fn paint_opacity(document: &str) -> String {
    const OPACITY: &str = r#" opacity=""#;
    let mut out = String::with_capacity(document.len());
    let mut rest = document;
    while let Some(at) = rest.find(OPACITY) {
        out.push_str(&rest[..at]);
        let after = &rest[at + OPACITY.len()..];
        let (value, tail) = after.split_once('"').unwrap_or((after, ""));
        if value != "1" {
            let paint = if tail.starts_with(r#" stroke=""#) {
                "stroke"
            } else {
                "fill"
            };
            out.push_str(&format!(r#" {paint}-opacity="{value}""#));
        }
        rest = tail;
    }
    out.push_str(rest);
    out
}

/// The rest of a `<text>` element as plotters writes it (`… fill="#222222">\n = 0.2\n</text>…`)
/// with its content's spaces kept: `xml:space="preserve"` on the element and the line breaks
/// plotters puts around the content removed. Text is drawn in runs placed one after another, so
/// a run such as `" = 0.2"` after a subscript must keep its leading space in every renderer.
fn preserve_spaces(rest: &str) -> String {
    let Some((attributes, after)) = rest.split_once(">\n") else {
        return rest.to_owned();
    };
    let Some((content, tail)) = after.split_once("\n</text>") else {
        return rest.to_owned();
    };
    format!(r#"{attributes} xml:space="preserve">{content}</text>{tail}"#)
}

/// Packed 8-bit pixels of a raster: RGB, or straight (not premultiplied) RGBA.
pub(super) struct Raster<'a> {
    /// The pixels, row by row.
    pub(super) pixels: &'a [u8],
    /// Width and height in pixels.
    pub(super) size: (u32, u32),
    /// Whether each pixel has an alpha byte.
    pub(super) alpha: bool,
}

/// The memory a raster is drawn and packed in: the premultiplied RGBA canvas and the packed
/// pixels. Each thread keeps its own from figure to figure ([`with_scratch`]), so that a raster
/// of several megabytes is not faulted in afresh — every page zeroed by the kernel, then
/// overwritten — for each figure.
#[derive(Default)]
pub(super) struct Scratch {
    canvas: Vec<u8>,
    packed: Vec<u8>,
}

thread_local! {
    static SCRATCH: std::cell::RefCell<Scratch> = std::cell::RefCell::default();
}

/// Runs `f` with this thread's [`Scratch`] (a fresh one if it is already in use further up the
/// stack).
pub(super) fn with_scratch<T>(f: impl FnOnce(&mut Scratch) -> T) -> T {
    SCRATCH.with(|cell| match cell.try_borrow_mut() {
        Ok(mut scratch) => f(&mut scratch),
        Err(_) => f(&mut Scratch::default()),
    })
}

/// The SVG `svg` of a figure on `canvas` (as [`super::svg`] draws it) rasterized at
/// `canvas.png_scale` pixels per CSS pixel by resvg, anti-aliased with sub-pixel positions: as RGB
/// on an opaque canvas, whose drawing begins with its background over the whole canvas, or, on a
/// transparent canvas, on nothing as straight RGBA. The pixels live in `scratch`, whatever it held
/// before: an opaque drawing's background covers every pixel with full coverage (the canvas spans
/// whole pixels), so only a transparent canvas is cleared first.
pub(super) fn rasterize<'s>(
    svg: &[u8],
    canvas: &Canvas,
    scratch: &'s mut Scratch,
) -> Result<Raster<'s>, PlotError> {
    let (width, height) = png_size(canvas)?;
    let tree = crate::output::svg_tree::parse(svg)
        .map_err(|e| PlotError::Draw(format!("the drawn SVG could not be read back: {e}")))?;
    let pixels = width as usize * height as usize;
    scratch.canvas.resize(pixels * 4, 0);
    let mut pixmap =
        resvg::tiny_skia::PixmapMut::from_bytes(&mut scratch.canvas[..pixels * 4], width, height)
            .ok_or_else(|| PlotError::Draw("the raster could not be allocated".to_owned()))?;
    if canvas.transparent {
        pixmap.fill(resvg::tiny_skia::Color::TRANSPARENT);
    }
    let size = tree.size();
    let transform = resvg::tiny_skia::Transform::from_scale(
        width as f32 / size.width(),
        height as f32 / size.height(),
    );
    resvg::render(&tree, transform, &mut pixmap);
    let packed = &mut scratch.packed;
    if canvas.transparent {
        packed.clear();
        packed.reserve(pixels * 4);
        for p in pixmap.as_ref().pixels() {
            let c = p.demultiply();
            packed.extend_from_slice(&[c.red(), c.green(), c.blue(), c.alpha()]);
        }
    } else {
        // Opaque ground: premultiplied and straight colour agree, so alpha is dropped as it is.
        // Every byte is written: only memory beyond what the last raster used is cleared first.
        packed.resize(pixels * 3, 0);
        for (rgb, rgba) in packed
            .chunks_exact_mut(3)
            .zip(pixmap.as_ref().data().chunks_exact(4))
        {
            rgb.copy_from_slice(&rgba[..3]);
        }
    }
    Ok(Raster {
        pixels: &scratch.packed,
        size: (width, height),
        alpha: canvas.transparent,
    })
}

/// Encodes a raster (8-bit RGB or RGBA) as a PNG with fixed settings: fast deflate and the Paeth
/// filter on every row. Over the catalogue's 50 PNGs that is 4 % larger than choosing the filter
/// row by row (adaptive, which filters each row five times) for 0.1 s less CPU, and 1.5× smaller
/// than the Sub filter; zlib's default level would be 3.3× smaller for 9× the time. Lossless
/// either way: fast deflate keeps a render's time in drawing, not in compression.
/// The resolution `dpi` goes into a `pHYs` chunk. The provenance record goes into `tEXt` chunks before the image data: `Software` =
/// `ndfplot <version>`, then one chunk per field, keyed as [`Provenance::fields`] names them.
pub(super) fn encode_png(
    raster: &Raster,
    dpi: f64,
    provenance: &Provenance,
) -> Result<Vec<u8>, PlotError> {
    let (width, height) = raster.size;
    let mut out = Vec::with_capacity(raster.pixels.len() / 16);
    let mut encoder = png::Encoder::new(&mut out, width, height);
    encoder.set_color(if raster.alpha {
        png::ColorType::Rgba
    } else {
        png::ColorType::Rgb
    });
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_compression(png::Compression::Fast);
    encoder.set_filter(png::FilterType::Paeth);
    encoder.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
    // pHYs: the resolution in pixels per metre, so that the image opens at its printed size.
    let per_metre = (dpi / 0.0254).round() as u32;
    encoder.set_pixel_dims(Some(png::PixelDimensions {
        xppu: per_metre,
        yppu: per_metre,
        unit: png::Unit::Meter,
    }));
    encoder.add_text_chunk("Software".to_owned(), provenance.software())?;
    for (key, value) in provenance.fields() {
        encoder.add_text_chunk(key.to_owned(), value)?;
    }
    let mut writer = encoder.write_header()?;
    writer.write_image_data(raster.pixels)?;
    writer.finish()?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::super::fixtures::{fresnel_sample, sample};
    use super::*;
    use crate::spec::look::Theme;

    /// An opaque canvas is not cleared before drawing: its background must cover every pixel
    /// fully, at any size and scale, or the raster would show what the memory held before.
    #[test]
    fn an_opaque_raster_does_not_depend_on_what_its_memory_held() {
        for (mut figure, theme) in [(sample(), Theme::Notebook), (fresnel_sample(), Theme::Dark)] {
            figure.theme = theme;
            for (width_px, height_px, png_scale) in
                [(400, 250, 2.0), (333, 217, 1.37), (301, 199, 3.3)]
            {
                figure.canvas.width_px = width_px;
                figure.canvas.height_px = height_px;
                figure.canvas.png_scale = png_scale;
                let svg = super::super::svg(&figure).unwrap();
                let raster = |scratch: &mut Scratch| {
                    rasterize(&svg, &figure.canvas, scratch)
                        .unwrap()
                        .pixels
                        .to_vec()
                };
                let fresh = raster(&mut Scratch::default());
                for held in [0x00, 0x5A, 0xFF] {
                    let mut dirty = Scratch {
                        canvas: vec![held; fresh.len() / 3 * 4],
                        packed: vec![held; 16],
                    };
                    let reused = raster(&mut dirty);
                    assert!(
                        reused == fresh,
                        "{theme:?} {width_px}×{height_px} at {png_scale}: memory holding {held:#x}"
                    );
                }
            }
        }
    }
}
