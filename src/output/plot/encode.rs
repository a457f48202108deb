//! Bytes out: the device size of a canvas, the finishing touches of the SVG document and the
//! PNG encoding, each carrying the figure's provenance record. Nothing here draws, and nothing
//! here computes the record: it only embeds it.

use super::PlotError;
use super::style::{EM_PER_SIZE, FONT_NAME};
use crate::look::Canvas;
use crate::provenance::Provenance;

/// Largest raster accepted: 2²⁶ pixels (64 Mpx, a 192 MB RGB buffer).
pub(super) const MAX_DEVICE_PIXELS: u64 = 1 << 26;

/// `font-family` written into the SVG: the embedded face, then the generic fallback.
pub(super) const SVG_FONT_FAMILY: &str = "DejaVu Sans, sans-serif";

/// Device size of `canvas` at `scale`, after checking that it can be drawn.
pub(super) fn device_size(canvas: &Canvas, scale: f64) -> Result<(u32, u32), PlotError> {
    let fail = |reason| PlotError::Canvas {
        width_px: canvas.width_px,
        height_px: canvas.height_px,
        scale,
        font_px: canvas.font_px,
        reason,
    };
    if !(scale.is_finite() && scale > 0.0) {
        return Err(fail("the scale must be a positive number"));
    }
    if !(canvas.font_px.is_finite() && canvas.font_px > 0.0) {
        return Err(fail("the font size must be a positive number"));
    }
    let width = (f64::from(canvas.width_px) * scale).round();
    let height = (f64::from(canvas.height_px) * scale).round();
    if width < 1.0 || height < 1.0 {
        return Err(fail("the raster would be empty"));
    }
    if width * height > MAX_DEVICE_PIXELS as f64 {
        return Err(fail("the raster would exceed 2^26 pixels"));
    }
    Ok((width as u32, height as u32))
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
    let sized = format!(
        r#"<svg width="{}" height="{}" "#,
        canvas.width_px, canvas.height_px
    );
    let document = document.replacen(&drawn, &sized, 1);
    // The opening tag ends at the first `>`: plotters writes no `>` inside its attributes.
    let document = match document.split_once('>') {
        Some((open, rest)) => format!(
            "{open}>\n<metadata>{}</metadata>{rest}",
            provenance.words().join(" ")
        ),
        None => document,
    };
    let marker = format!(r#"font-family="{FONT_NAME}" font-size=""#);
    let mut parts = document.split(marker.as_str());
    let mut out = String::with_capacity(document.len() + document.len() / 16);
    out.push_str(parts.next().unwrap_or_default());
    for part in parts {
        let (size, rest) = part.split_once('"').unwrap_or(("", part));
        let em = size.parse::<f64>().unwrap_or(0.0) * PLOTTERS_SVG_DIVISOR * EM_PER_SIZE;
        out.push_str(&format!(
            r#"font-family="{SVG_FONT_FAMILY}" font-size="{em:.2}"{rest}"#
        ));
    }
    out
}

/// The packed 8-bit RGB raster `rgb` of `(width, height)` pixels shrunk `factor` times on each
/// side: each output pixel is the mean of its `factor` × `factor` block, rounded (a box filter,
/// which turns a supersampled drawing into anti-aliased pixels). `factor` 1 returns `rgb`.
pub(super) fn downsample(rgb: Vec<u8>, (width, height): (u32, u32), factor: u32) -> Vec<u8> {
    if factor <= 1 {
        return rgb;
    }
    let (f, row) = (factor as usize, width as usize * 3);
    let out_row = row / f;
    let block = (f * f) as u32;
    let mut out = Vec::with_capacity(out_row * height as usize / f);
    let mut sums = vec![0u32; out_row];
    for rows in rgb.chunks_exact(row * f) {
        sums.fill(0);
        for line in rows.chunks_exact(row) {
            for (sum, pixels) in sums.chunks_exact_mut(3).zip(line.chunks_exact(3 * f)) {
                for pixel in pixels.chunks_exact(3) {
                    for (s, &c) in sum.iter_mut().zip(pixel) {
                        *s += u32::from(c);
                    }
                }
            }
        }
        out.extend(sums.iter().map(|&s| ((s + block / 2) / block) as u8));
    }
    out
}

/// Encodes packed 8-bit RGB pixels as a PNG with fixed settings: fast deflate and the Sub
/// filter, ~6× faster than adaptive filtering for files ~1.6× larger (plots are mostly flat).
/// The provenance record goes into `tEXt` chunks before the image data: `Software` =
/// `ndfplot <version>`, then one chunk per field, keyed as [`Provenance::fields`] names them.
pub(super) fn encode_png(
    rgb: &[u8],
    (width, height): (u32, u32),
    provenance: &Provenance,
) -> Result<Vec<u8>, PlotError> {
    let mut out = Vec::with_capacity(rgb.len() / 16);
    let mut encoder = png::Encoder::new(&mut out, width, height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_compression(png::Compression::Fast);
    encoder.set_filter(png::FilterType::Sub);
    encoder.set_adaptive_filter(png::AdaptiveFilterType::NonAdaptive);
    encoder.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
    encoder.add_text_chunk("Software".to_owned(), provenance.software())?;
    for (key, value) in provenance.fields() {
        encoder.add_text_chunk(key.to_owned(), value)?;
    }
    let mut writer = encoder.write_header()?;
    writer.write_image_data(rgb)?;
    writer.finish()?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn downsampling_averages_each_block_per_channel() {
        // A 4×2 raster, factor 2: two output pixels, each the rounded mean of a 2×2 block.
        let rgb = vec![
            0, 10, 255, 2, 10, 255, /**/ 9, 9, 9, 9, 9, 9, //
            0, 10, 255, 3, 11, 0, /**/ 9, 9, 9, 9, 9, 10,
        ];
        assert_eq!(downsample(rgb.clone(), (4, 2), 2), [1, 10, 191, 9, 9, 9]);
        assert_eq!(downsample(rgb.clone(), (4, 2), 1), rgb);
    }
}
