//! An engine's table stored as an image (`ndfplot albedo --against table.png|table.exr`): the
//! decoding of a PNG (8 or 16 bits per sample: unorm8, unorm16) or an OpenEXR file (half or
//! float channels: f16, f32) into its samples, row-major with the channels of a pixel
//! interleaved, and what the image says about them (size, encoding, channels).
//!
//! Owns the use of the `png` decoder and the `exr` crate, and the bounds that keep a hostile image
//! from taking memory: the size in the header is checked against the caller's largest side before
//! any pixel is decoded. What the numbers mean is [`super::lut`]'s layout.

use std::io::Cursor;

/// How an image stores its samples.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Samples {
    /// 8-bit integers k, the value k/255.
    Unorm8,
    /// 16-bit integers k, the value k/65535.
    Unorm16,
    /// IEEE binary16.
    F16,
    /// IEEE binary32.
    F32,
}

/// An image's samples and what it says about them.
#[derive(Debug, Clone, PartialEq)]
pub struct Image {
    /// Every sample, row by row from the top, the channels of a pixel interleaved.
    pub values: Vec<f64>,
    /// Pixels per row.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// How the samples are stored.
    pub samples: Samples,
    /// Samples per pixel.
    pub channels: usize,
    /// The channels' names in their order (`Y`, `R, G, B, A`), for messages.
    pub names: String,
}

/// Refuses an image whose side exceeds `max_side` or is below 2 (a table axis has 2 to
/// `max_side` points).
fn check_size(width: usize, height: usize, max_side: usize) -> Result<(), String> {
    if (2..=max_side).contains(&width) && (2..=max_side).contains(&height) {
        Ok(())
    } else {
        Err(format!(
            "image size out of range (got {width} x {height} pixels, expected each side 2 to {max_side})"
        ))
    }
}

/// A PNG image of 8 or 16 bits per sample (grey, grey–alpha, RGB or RGBA; no palette), its
/// samples k read as k/255 or k/65535.
pub fn png(bytes: &[u8], max_side: usize) -> Result<Image, String> {
    let failed = |e: png::DecodingError| format!("not a readable PNG image ({e})");
    let mut decoder = png::Decoder::new(Cursor::new(bytes));
    decoder.set_transformations(png::Transformations::IDENTITY);
    // Room for the largest table: max_side² pixels of four 16-bit samples.
    decoder.set_limits(png::Limits {
        bytes: max_side * max_side * 8,
    });
    let mut reader = decoder.read_info().map_err(failed)?;
    let info = reader.info();
    let (width, height) = (info.width as usize, info.height as usize);
    check_size(width, height, max_side)?;
    let (colour, depth) = reader.output_color_type();
    let (channels, names) = match colour {
        png::ColorType::Grayscale => (1, "Y"),
        png::ColorType::GrayscaleAlpha => (2, "Y, A"),
        png::ColorType::Rgb => (3, "R, G, B"),
        png::ColorType::Rgba => (4, "R, G, B, A"),
        png::ColorType::Indexed => {
            return Err(
                "a palette PNG (expected grey, grey-alpha, RGB or RGBA samples, 8 or 16 bits)"
                    .into(),
            );
        }
    };
    let samples = match depth {
        png::BitDepth::Eight => Samples::Unorm8,
        png::BitDepth::Sixteen => Samples::Unorm16,
        other => {
            return Err(format!(
                "{} bits per sample (expected 8 or 16)",
                other as u8
            ));
        }
    };
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| format!("image too large to decode (got {width} x {height} pixels)"))?;
    let mut buffer = vec![0; size];
    let frame = reader.next_frame(&mut buffer).map_err(failed)?;
    let data = &buffer[..frame.buffer_size()];
    let values = match samples {
        Samples::Unorm8 => data.iter().map(|&k| f64::from(k) / 255.0).collect(),
        // PNG stores 16-bit samples big-endian.
        _ => data
            .chunks_exact(2)
            .map(|b| f64::from(u16::from_be_bytes([b[0], b[1]])) / 65535.0)
            .collect(),
    };
    Ok(Image {
        values,
        width,
        height,
        samples,
        channels,
        names: names.into(),
    })
}

/// The first layer of an OpenEXR image at full resolution, of half or float channels (all of
/// one type): one channel as it is, several in the order R, G, B, A when those are their names,
/// else in the file's (alphabetical) order; at most `max_channels` of them.
pub fn exr(bytes: &[u8], max_side: usize, max_channels: usize) -> Result<Image, String> {
    use exr::prelude::{ReadChannels, ReadLayers, read};
    let failed = |e: exr::error::Error| format!("not a readable OpenEXR image ({e})");
    // The header first: its size is checked before any pixel is decoded.
    let meta =
        exr::meta::MetaData::read_from_buffered(Cursor::new(bytes), false).map_err(failed)?;
    let header = meta
        .headers
        .first()
        .ok_or("an OpenEXR file without a layer")?;
    let size = header.layer_size;
    check_size(size.0, size.1, max_side)?;
    if header.channels.list.len() > max_channels {
        return Err(format!(
            "{} channels (expected 1 to {max_channels})",
            header.channels.list.len()
        ));
    }
    let image = read()
        .no_deep_data()
        .largest_resolution_level()
        .all_channels()
        .first_valid_layer()
        .all_attributes()
        .non_parallel()
        .from_buffered(Cursor::new(bytes))
        .map_err(failed)?;
    let layer = &image.layer_data;
    let (width, height) = (layer.size.0, layer.size.1);
    check_size(width, height, max_side)?;
    let list = &layer.channel_data.list;
    let mut order: Vec<usize> = (0..list.len()).collect();
    let rank = |name: &str| ["R", "G", "B", "A"].iter().position(|n| *n == name);
    if list.iter().all(|c| rank(&c.name.to_string()).is_some()) {
        order.sort_by_key(|&k| rank(&list[k].name.to_string()));
    }
    // Channel names come from the file: messages quote an excerpt of each.
    let name = |k: usize| crate::problem::excerpt(&list[k].name.to_string());
    let names: Vec<String> = order.iter().map(|&k| name(k)).collect();
    let mut kind = None;
    let mut columns: Vec<Vec<f64>> = Vec::with_capacity(order.len());
    for &k in &order {
        let (this, values): (Samples, Vec<f64>) = match &list[k].sample_data {
            exr::image::FlatSamples::F16(v) => {
                (Samples::F16, v.iter().map(|h| h.to_f64()).collect())
            }
            exr::image::FlatSamples::F32(v) => {
                (Samples::F32, v.iter().map(|&f| f64::from(f)).collect())
            }
            exr::image::FlatSamples::U32(_) => {
                return Err(format!(
                    "channel {} holds 32-bit integers (expected half or float samples)",
                    name(k)
                ));
            }
        };
        if *kind.get_or_insert(this) != this {
            return Err("channels of mixed half and float samples (expected one type)".into());
        }
        if values.len() != width * height {
            return Err(format!(
                "channel {} is subsampled (got {} samples, expected {width} x {height})",
                name(k),
                values.len()
            ));
        }
        columns.push(values);
    }
    let samples = kind.ok_or("an OpenEXR layer without channels")?;
    let values = (0..width * height)
        .flat_map(|p| columns.iter().map(move |c| c[p]))
        .collect();
    Ok(Image {
        values,
        width,
        height,
        samples,
        channels: order.len(),
        names: names.join(", "),
    })
}
