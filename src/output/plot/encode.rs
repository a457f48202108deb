//! Bytes out: the device size of a canvas, the finishing touches of the SVG document, its
//! rasterization and the PNG encoding, each carrying the figure's provenance record. Nothing here draws, and nothing
//! here computes the record: it only embeds it.

use super::PlotError;
use super::device_size;
use super::style::{EM_PER_SIZE, family};
use crate::model::math::elementary::{Block, widest};
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

/// A drawn raster: premultiplied 8-bit RGBA pixels, row by row, and whether the PNG keeps alpha
/// (a transparent canvas) or is RGB (an opaque one, where premultiplied and straight colour agree).
pub(super) struct Raster<'a> {
    /// The premultiplied RGBA pixels, row by row.
    pub(super) rgba: &'a [u8],
    /// Width and height in pixels.
    pub(super) size: (u32, u32),
    /// Whether the PNG has an alpha channel (straight, not premultiplied).
    pub(super) alpha: bool,
}

impl Raster<'_> {
    /// The PNG's colour type: RGBA with alpha, else RGB.
    fn color_type(&self) -> png::ColorType {
        if self.alpha {
            png::ColorType::Rgba
        } else {
            png::ColorType::Rgb
        }
    }

    /// Bytes of a pixel in the PNG's rows: 4 with alpha, else 3.
    fn png_bytes_per_pixel(&self) -> usize {
        if self.alpha { 4 } else { 3 }
    }
}

/// The memory a raster is drawn in: the premultiplied RGBA canvas. Each thread keeps its own from
/// figure to figure ([`with_scratch`]), so that a raster of several megabytes is not faulted in
/// afresh — every page zeroed by the kernel, then overwritten — for each figure; it grows to the
/// largest raster the thread has drawn, backed by memory in one call ([`back_with_memory`]).
#[derive(Default)]
pub(super) struct Scratch {
    canvas: Vec<u8>,
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
/// `canvas.png_scale` pixels per CSS pixel by resvg, anti-aliased with sub-pixel positions: on an
/// opaque canvas, whose drawing begins with its background over the whole canvas, or, on a
/// transparent canvas, on nothing. The pixels live in `scratch`, whatever it held before: an
/// opaque drawing's background covers every pixel with full coverage (the canvas spans whole
/// pixels), so only a transparent canvas is cleared first.
pub(super) fn rasterize<'s>(
    svg: &[u8],
    canvas: &Canvas,
    scratch: &'s mut Scratch,
) -> Result<Raster<'s>, PlotError> {
    let (width, height) = png_size(canvas)?;
    let tree = crate::output::svg_tree::parse(svg)
        .map_err(|e| PlotError::Draw(format!("the drawn SVG could not be read back: {e}")))?;
    let pixels = width as usize * height as usize;
    if scratch.canvas.len() < pixels * 4 {
        // The smaller canvas is freed first, and the larger one comes zeroed from the system
        // (no copy of the old pixels, no pass clearing it), its pages made present at once.
        scratch.canvas = Vec::new();
        scratch.canvas = vec![0; pixels * 4];
        back_with_memory(&mut scratch.canvas);
    }
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
    Ok(Raster {
        rgba: &scratch.canvas[..pixels * 4],
        size: (width, height),
        alpha: canvas.transparent,
    })
}

/// Backs `bytes` with memory before the rasterizer first writes it: asks for transparent huge
/// pages where the system offers them on request (`MADV_HUGEPAGE`: one 2 MiB page where there
/// would be 512 of 4 KiB), then makes every page present and writable in one call
/// (`MADV_POPULATE_WRITE`) instead of one page fault at each page's first write (measured in
/// docs/performance.md, "The raster's memory made present at once"). Both are hints: where a
/// call is not available (kernels before 5.14, huge pages off, other systems) the pages fault in
/// as before, and the bytes are the same either way.
fn back_with_memory(bytes: &mut [u8]) {
    #[cfg(target_os = "linux")]
    {
        // SAFETY: sysconf reads a constant of the system.
        let page = usize::try_from(unsafe { libc::sysconf(libc::_SC_PAGESIZE) }).unwrap_or(0);
        if page == 0 {
            return;
        }
        let start = bytes.as_mut_ptr() as usize;
        let (first, end) = (
            start.next_multiple_of(page),
            (start + bytes.len()) / page * page,
        );
        if end > first {
            let (at, length) = (first as *mut libc::c_void, end - first);
            // SAFETY: the range lies inside `bytes`, memory this process owns and may write;
            // neither advice changes a byte of it. A refusal leaves it as it was.
            unsafe {
                libc::madvise(at, length, libc::MADV_HUGEPAGE);
                libc::madvise(at, length, libc::MADV_POPULATE_WRITE);
            }
        }
    }
    #[cfg(not(target_os = "linux"))]
    let _ = bytes;
}

/// Encodes a raster as a PNG (8-bit RGB, or straight RGBA on a transparent canvas) with fixed
/// settings: fast deflate and the Paeth filter on every row, the rows packed, filtered and
/// deflated one at a time ([`deflated_rows`]). Over the catalogue's 50 PNGs that is 4 % larger than choosing the filter
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
    let mut out = Vec::with_capacity(raster.rgba.len() / 16);
    let mut encoder = png::Encoder::new(&mut out, width, height);
    encoder.set_color(raster.color_type());
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_compression(png::Compression::Fast);
    encoder.set_filter(png::Filter::Paeth);
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
    let data = deflated_rows(raster).map_err(png::EncodingError::from)?;
    writer.write_chunk(png::chunk::IDAT, &data)?;
    writer.finish()?;
    Ok(out)
}

/// The PNG image data of `raster`: its rows packed (RGB, or straight RGBA on a transparent canvas),
/// each Paeth-filtered against the packed row above (zeros above the first; an opaque row straight
/// from the RGBA rows, [`paeth_filter_opaque`]) and deflated by fdeflate as it is made, so no
/// packed copy of the whole raster is kept — byte for byte what png's `Writer::write_image_data`
/// writes with `Compression::Fast` and `Filter::Paeth`, including its stored blocks where
/// deflating would not shrink the rows.
fn deflated_rows(raster: &Raster) -> std::io::Result<Vec<u8>> {
    let (width, height) = (raster.size.0 as usize, raster.size.1 as usize);
    let bpp = raster.png_bytes_per_pixel();
    let row_len = width * bpp;
    let mut row = vec![0; row_len];
    let mut filtered = vec![PNG_PAETH; row_len + 1];
    let mut compressor = fdeflate::Compressor::new(std::io::Cursor::new(Vec::new()))?;
    if raster.alpha {
        let mut above = vec![0; row_len];
        for source in raster.rgba.chunks_exact(width * 4) {
            pack_row(source, true, &mut row);
            paeth_filter(&row, &above, bpp, &mut filtered[1..]);
            compressor.write_data(&filtered)?;
            std::mem::swap(&mut above, &mut row);
        }
    } else {
        let zeros = vec![0; width * 4];
        let mut above = &zeros[..];
        for source in raster.rgba.chunks_exact(width * 4) {
            filter_opaque_row(source, above, &mut filtered[1..]);
            compressor.write_data(&filtered)?;
            above = source;
        }
    }
    let compressed = compressor.finish()?.into_inner();
    let stored_size = fdeflate::StoredOnlyCompressor::<()>::compressed_size((row_len + 1) * height);
    if compressed.len() <= stored_size {
        return Ok(compressed);
    }
    let mut stored = fdeflate::StoredOnlyCompressor::new(std::io::Cursor::new(Vec::new()))?;
    for source in raster.rgba.chunks_exact(width * 4) {
        pack_row(source, raster.alpha, &mut row);
        stored.write_data(&[PNG_NO_FILTER])?;
        stored.write_data(&row)?;
    }
    Ok(stored.finish()?.into_inner())
}

/// The filter-type bytes that begin a PNG row: none, and Paeth.
const PNG_NO_FILTER: u8 = 0;
const PNG_PAETH: u8 = 4;

/// One row of premultiplied RGBA `source` packed into `row`: RGB as it is (opaque), or straight
/// RGBA (each colour divided by alpha as tiny-skia's `demultiply` does).
fn pack_row(source: &[u8], alpha: bool, row: &mut [u8]) {
    if alpha {
        for (out, pixel) in row.chunks_exact_mut(4).zip(source.chunks_exact(4)) {
            let straight = resvg::tiny_skia::PremultipliedColorU8::from_rgba(
                pixel[0], pixel[1], pixel[2], pixel[3],
            )
            .map_or(resvg::tiny_skia::ColorU8::from_rgba(0, 0, 0, 0), |p| {
                p.demultiply()
            });
            out.copy_from_slice(&[
                straight.red(),
                straight.green(),
                straight.blue(),
                straight.alpha(),
            ]);
        }
    } else {
        for (out, pixel) in row.chunks_exact_mut(3).zip(source.chunks_exact(4)) {
            out.copy_from_slice(&pixel[..3]);
        }
    }
}

/// PNG's Paeth filter of `row` against `above` (`bpp` bytes a pixel): each byte minus the Paeth
/// prediction from its left, upper and upper-left neighbours (zero beyond the left edge).
fn paeth_filter(row: &[u8], above: &[u8], bpp: usize, out: &mut [u8]) {
    for i in 0..bpp.min(row.len()) {
        out[i] = row[i].wrapping_sub(paeth_predictor(0, above[i], 0));
    }
    if row.len() <= bpp {
        return;
    }
    let len = row.len();
    for ((((out, &x), &a), &b), &c) in out[bpp..]
        .iter_mut()
        .zip(&row[bpp..])
        .zip(&row[..len - bpp])
        .zip(&above[bpp..])
        .zip(&above[..len - bpp])
    {
        *out = x.wrapping_sub(paeth_predictor(a, b, c));
    }
}

/// [`paeth_filter_opaque`] in the widest byte instructions the processor has: sixteen pixels
/// (64 bytes) at a time where it has AVX-512BW, else eight through [`widest`] (AVX2 or the
/// baseline). The bytes are the same on every path.
fn filter_opaque_row(source: &[u8], above: &[u8], out: &mut [u8]) {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx512bw")
        && std::arch::is_x86_feature_detected!("avx512vl")
    {
        // SAFETY: the processor has AVX-512BW and AVX-512VL, checked just above.
        return unsafe { paeth_filter_opaque_avx512bw(source, above, out) };
    }
    widest(&mut OpaqueRow { source, above, out });
}

/// [`paeth_filter_opaque`] sixteen pixels at a time, compiled for AVX-512BW.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512bw,avx512vl")]
fn paeth_filter_opaque_avx512bw(source: &[u8], above: &[u8], out: &mut [u8]) {
    paeth_filter_opaque::<64, 48>(source, above, out);
}

/// One opaque row for [`paeth_filter_opaque`] eight pixels at a time, run by [`widest`].
struct OpaqueRow<'a> {
    source: &'a [u8],
    above: &'a [u8],
    out: &'a mut [u8],
}

impl Block for OpaqueRow<'_> {
    #[inline(always)]
    fn run(&mut self) {
        paeth_filter_opaque::<32, 24>(self.source, self.above, self.out);
    }
}

/// [`paeth_filter`] of an opaque row packed to RGB against the packed row above, read straight
/// from the RGBA rows `source` and `above` (zeros above the first row) into `out` (3 bytes a
/// pixel): a byte's left and upper-left neighbours are the same channel of the pixel before, which
/// packing does not change, so filtering before dropping alpha gives the same bytes. `BYTES / 4`
/// pixels (`BYTES` RGBA bytes, `PACKED` = 3 · `BYTES / 4` RGB bytes) are filtered at a time,
/// alpha included and then dropped, by code the compiler vectorizes in the instruction set of its
/// caller ([`filter_opaque_row`]).
#[inline(always)]
fn paeth_filter_opaque<const BYTES: usize, const PACKED: usize>(
    source: &[u8],
    above: &[u8],
    out: &mut [u8],
) {
    let block = BYTES / 4;
    debug_assert_eq!(PACKED, 3 * block);
    let pixels = source.len() / 4;
    let filter = |i: usize, out: &mut [u8]| {
        for k in 0..3 {
            let (left, upper_left) = match i {
                0 => (0, 0),
                _ => (source[4 * i - 4 + k], above[4 * i - 4 + k]),
            };
            out[3 * i + k] =
                source[4 * i + k].wrapping_sub(paeth_predictor(left, above[4 * i + k], upper_left));
        }
    };
    filter(0, out);
    let mut i = 1;
    while i + block <= pixels {
        let range = 4 * i..4 * (i + block);
        let before = 4 * i - 4..4 * (i + block) - 4;
        let x: &[u8; BYTES] = source[range.clone()].try_into().expect("a block");
        let a: &[u8; BYTES] = source[before.clone()].try_into().expect("a block");
        let b: &[u8; BYTES] = above[range].try_into().expect("a block");
        let c: &[u8; BYTES] = above[before].try_into().expect("a block");
        let mut filtered = [0u8; BYTES];
        for k in 0..BYTES {
            filtered[k] = x[k].wrapping_sub(paeth_predictor(a[k], b[k], c[k]));
        }
        let packed: [u8; PACKED] = std::array::from_fn(|j| filtered[j / 3 * 4 + j % 3]);
        out[3 * i..3 * (i + block)].copy_from_slice(&packed);
        i += block;
    }
    for i in i..pixels {
        filter(i, out);
    }
}

/// The Paeth predictor of PNG: of the left `a`, upper `b` and upper-left `c` bytes, the one nearest
/// p = a + b − c (ties to a, then b), computed on bytes alone: |p − a| = |b − c|, |p − b| = |a − c|,
/// and |p − c| = ||b − c| − |a − c|| where c lies between a and b, more than both otherwise.
#[inline(always)]
fn paeth_predictor(a: u8, b: u8, c: u8) -> u8 {
    let pa = b.max(c) - b.min(c);
    let pb = a.max(c) - a.min(c);
    let pc = if (a < c) == (c < b) {
        pa.max(pb) - pa.min(pb)
    } else {
        u8::MAX
    };
    if pa <= pb && pa <= pc {
        a
    } else if pb <= pc {
        b
    } else {
        c
    }
}

#[cfg(test)]
mod tests {
    use super::super::fixtures::{fresnel_sample, sample};
    use super::*;
    use crate::spec::look::Theme;

    /// The image data as png itself writes it from the packed raster (`Compression::Fast`,
    /// `Filter::Paeth`), for comparison with [`deflated_rows`].
    fn png_image_data(raster: &Raster) -> Vec<u8> {
        let packed: Vec<u8> = raster
            .rgba
            .chunks_exact(4)
            .flat_map(|pixel| {
                let mut row = [0; 4];
                pack_row(
                    pixel,
                    raster.alpha,
                    &mut row[..if raster.alpha { 4 } else { 3 }],
                );
                row.into_iter().take(if raster.alpha { 4 } else { 3 })
            })
            .collect();
        let mut out = Vec::new();
        let mut encoder = png::Encoder::new(&mut out, raster.size.0, raster.size.1);
        encoder.set_color(raster.color_type());
        encoder.set_compression(png::Compression::Fast);
        encoder.set_filter(png::Filter::Paeth);
        let mut writer = encoder.write_header().unwrap();
        writer.write_image_data(&packed).unwrap();
        writer.finish().unwrap();
        // The IDAT chunk's data: after the signature, IHDR (25 bytes) and the IDAT length and type.
        let length = u32::from_be_bytes(out[33..37].try_into().unwrap()) as usize;
        assert_eq!(&out[37..41], b"IDAT");
        out[41..41 + length].to_vec()
    }

    /// Bytes of xorshift64 noise from `state` (not zero).
    fn noise(mut state: u64) -> impl FnMut() -> u8 {
        move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 32) as u8
        }
    }

    /// Rows packed, filtered and deflated one at a time give png's bytes: opaque and transparent,
    /// one to many pixels wide, smooth rows (deflated) and noise (kept in stored blocks).
    #[test]
    fn rows_deflated_one_at_a_time_are_what_png_writes() {
        let mut noise = noise(0x2545_F491_4F6C_DD1D);
        for (width, height) in [
            (1, 1),
            (1, 5),
            (2, 3),
            (5, 2),
            (7, 4),
            (9, 3),
            (64, 33),
            (67, 5),
        ] {
            for alpha in [false, true] {
                for smooth in [true, false] {
                    let rgba: Vec<u8> = (0..width * height)
                        .flat_map(|i| {
                            let a = if alpha { (i * 37 % 256) as u8 } else { 255 };
                            let mut colour = |k: usize| {
                                let v = if smooth { (i * k % 200) as u8 } else { noise() };
                                // Premultiplied: no channel above alpha.
                                ((u16::from(v) * u16::from(a)) / 255) as u8
                            };
                            [colour(3), colour(5), colour(7), a]
                        })
                        .collect();
                    let raster = Raster {
                        rgba: &rgba,
                        size: (width as u32, height as u32),
                        alpha,
                    };
                    let data = deflated_rows(&raster).unwrap();
                    assert_eq!(
                        data,
                        png_image_data(&raster),
                        "{width}×{height}, alpha {alpha}, smooth {smooth}"
                    );
                    // After the 2-byte zlib header, a deflate block of type 0 is stored: the
                    // widest noise takes that route, the widest smooth rows are deflated.
                    if width == 64 {
                        assert_eq!(data[2] & 0b110 == 0, !smooth, "{width}×{height}, {smooth}");
                    }
                }
            }
        }
    }

    /// Every path of the opaque filter — sixteen pixels at a time (AVX-512BW), eight (AVX2 or
    /// the baseline, through `widest`), one at a time — gives the same bytes, at every width
    /// from 1 to 70 pixels.
    #[test]
    fn the_opaque_filter_is_the_same_on_every_path() {
        let mut noise = noise(0x9E37_79B9_7F4A_7C15);
        for width in 1..=70 {
            let (source, above): (Vec<u8>, Vec<u8>) = (0..4 * width)
                .map(|i| {
                    if i % 4 == 3 {
                        (255, 255)
                    } else {
                        (noise(), noise())
                    }
                })
                .unzip();
            let one_at_a_time = {
                let mut row = vec![0; 3 * width];
                let mut packed_above = vec![0; 3 * width];
                pack_row(&source, false, &mut row);
                pack_row(&above, false, &mut packed_above);
                let mut out = vec![0; 3 * width];
                paeth_filter(&row, &packed_above, 3, &mut out);
                out
            };
            let mut widest_path = vec![0; 3 * width];
            widest(&mut OpaqueRow {
                source: &source,
                above: &above,
                out: &mut widest_path,
            });
            let mut dispatched = vec![0; 3 * width];
            filter_opaque_row(&source, &above, &mut dispatched);
            assert_eq!(
                widest_path, one_at_a_time,
                "{width} pixels, eight at a time"
            );
            assert_eq!(dispatched, one_at_a_time, "{width} pixels, widest path");
        }
    }

    /// An opaque canvas is not cleared before drawing: its background must cover every pixel
    /// fully, at any size and scale, or the raster would show what the memory held before,
    /// whatever it held and however much of it there is.
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
                        .rgba
                        .to_vec()
                };
                let fresh = raster(&mut Scratch::default());
                for held in [0x00, 0x5A, 0xFF] {
                    // Left larger by an earlier, larger figure: only the front is drawn in.
                    let mut dirty = Scratch {
                        canvas: vec![held; fresh.len() + 4096],
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
