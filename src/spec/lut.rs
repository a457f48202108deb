//! An engine's albedo table as `ndfplot albedo --against FILE --layout KEY=VALUE,…` reads it: the
//! layout that says what its numbers are (which axis runs along rows, where the grid points sit,
//! how the axis maps to α, which value, how it is encoded, under which G2 and Fresnel), and the
//! decoding of the file's bytes into values (docs/contracts.md "Auditing an engine's table").
//!
//! Owns the parsing of the layout and of the three file kinds — a CSV matrix, a C/C++ header
//! holding one array, raw little-endian binary — and the decoding of the five encodings. The file
//! is read by [`crate::spec::datafile::read_regular`] (regular files only, bounded); the exact
//! table and the comparison are the model's.

use crate::model::albedo::RoughnessMap;
pub use crate::model::engine_table::{LutAxis, LutGrid, LutValue};
use crate::model::masking::G2Model;
use crate::model::names::named;
use crate::problem::{Problem, Problems};
use crate::spec::lut_image::Samples;

named! {
    /// How each number is stored.
    pub enum Encoding {
        /// Little-endian IEEE binary32 (raw), or a decimal number (text).
        F32 = "f32",
        /// Little-endian IEEE binary16 (raw), or a decimal number (text).
        F16 = "f16",
        /// One byte k, the value k/255 (raw), or the integer k (text).
        Unorm8 = "unorm8",
        /// A little-endian 16-bit k, the value k/65535 (raw), or the integer k (text).
        Unorm16 = "unorm16",
        /// A decimal number (text files only).
        Text = "text",
    }
}

named! {
    /// The kind of file holding the table.
    pub enum LutFile {
        /// Numbers separated by commas or white space, `#` comment lines skipped; rows are lines.
        Csv = "csv",
        /// A C/C++ source holding one array: the numbers between its first `{` and last `}`
        /// (comments skipped, literal suffixes f/u/l and 0x hex integers accepted).
        Header = "header",
        /// Raw little-endian binary, row-major, no header.
        Raw = "raw",
        /// A grayscale, grey–alpha, RGB or RGBA PNG image of 8 or 16 bits per sample (unorm8,
        /// unorm16); image rows are table rows.
        Png = "png",
        /// An OpenEXR image (its first layer, at full resolution) of half or float channels (f16,
        /// f32); image rows are table rows.
        Exr = "exr",
    }
}

/// The first bytes of a PNG file.
const PNG_MAGIC: [u8; 8] = [0x89, b'P', b'N', b'G', b'\r', b'\n', 0x1a, b'\n'];
/// The first bytes of an OpenEXR file (its magic number 20000630, little-endian).
const EXR_MAGIC: [u8; 4] = [0x76, 0x2f, 0x31, 0x01];

/// The kind of image the bytes start with, if any.
fn image_kind(bytes: &[u8]) -> Option<LutFile> {
    if bytes.starts_with(&PNG_MAGIC) {
        Some(LutFile::Png)
    } else if bytes.starts_with(&EXR_MAGIC) {
        Some(LutFile::Exr)
    } else {
        None
    }
}

named! {
    /// The Fresnel factor the engine's table integrates.
    pub enum LutFresnel {
        /// F = 1.
        None = "none",
        /// The curve given with `--fresnel`.
        Given = "given",
    }
}

/// Layout keys, in the order `--layout` documents them.
pub const LAYOUT_KEYS: [&str; 12] = [
    "rows", "cols", "grid", "map", "value", "encoding", "g2", "fresnel", "file", "clamp",
    "channels", "channel",
];

/// Most channels per cell (`channels=`): RGBA.
pub const MAX_CHANNELS: usize = 4;
/// The names `channel=` takes besides an index: R, G, B, A are 0 to 3 (an image's channel
/// order), Y (a grey image's one channel) is 0.
pub const CHANNEL_NAMES: [(&str, usize); 5] = [("R", 0), ("G", 1), ("B", 2), ("A", 3), ("Y", 0)];

/// What an engine's table holds and how (`--layout`); every key has a default.
#[derive(Debug, Clone, PartialEq)]
pub struct Layout {
    /// The axis along each row of the file (`rows=mu`: one row per μ, the default).
    pub rows: LutAxis,
    /// The axis along the columns (`cols=r` by default); differs from `rows`.
    pub cols: LutAxis,
    /// Where the grid points sit (`endpoints`).
    pub grid: LutGrid,
    /// How r maps to α (`map=r2` α = r², `alpha` the axis is α, `sqrt` α = √r; `r2`).
    pub map: RoughnessMap,
    /// What the numbers are (`e`).
    pub value: LutValue,
    /// How they are stored (`text` for CSV and headers, `f32` for raw files).
    pub encoding: Encoding,
    /// The G2 model (`--g2`'s unless given).
    pub g2: G2Model,
    /// The Fresnel factor (`none`).
    pub fresnel: LutFresnel,
    /// The kind of file (from its extension: `.csv`/`.txt` CSV, `.h`/`.hpp`/`.c`/`.cpp`/`.inc`
    /// header, anything else raw).
    pub file: LutFile,
    /// The engine evaluates its grid at max(coordinate, clamp) (Cycles: 1e-4); 0 by default.
    pub clamp: f64,
    /// Numbers per cell, interleaved (an RG or RGBA texture); 1 by default.
    pub channels: usize,
    /// Which of them is audited, from 0.
    pub channel: usize,
    /// The keys `--layout` gave (the others hold their defaults).
    pub given: Vec<&'static str>,
}

/// The layout of `text` (`KEY=VALUE,…`, empty for all defaults) for the file `path` under the
/// command's G2 model `g2`: an unknown or repeated key, a value outside its choices, rows equal
/// to cols, or an encoding the file kind cannot hold is a problem naming `--layout` and the key.
pub fn parse_layout(text: &str, path: &str, g2: G2Model) -> Result<Layout, Problems> {
    let problem = |key: &str, message: String| Problems {
        source: "--layout".into(),
        list: vec![Problem::new(key, message)],
    };
    let extension = std::path::Path::new(path)
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase();
    let file = match extension.as_str() {
        "csv" | "txt" => LutFile::Csv,
        "h" | "hh" | "hpp" | "c" | "cc" | "cpp" | "inc" => LutFile::Header,
        "png" => LutFile::Png,
        "exr" => LutFile::Exr,
        _ => LutFile::Raw,
    };
    let mut layout = Layout {
        rows: LutAxis::Mu,
        cols: LutAxis::R,
        grid: LutGrid::Endpoints,
        map: RoughnessMap::Squared,
        value: LutValue::E,
        encoding: Encoding::Text,
        g2,
        fresnel: LutFresnel::None,
        file,
        clamp: 0.0,
        channels: 1,
        channel: 0,
        given: Vec::new(),
    };
    let mut seen: Vec<&str> = Vec::new();
    let mut encoding = None;
    for pair in text.split(',').filter(|p| !p.trim().is_empty()) {
        let Some((key, value)) = pair.split_once('=') else {
            return Err(problem(
                "",
                format!(
                    "not KEY=VALUE (got {:?}, expected e.g. rows=mu)",
                    crate::problem::excerpt(pair)
                ),
            ));
        };
        let (key, value) = (key.trim(), value.trim());
        let Some(&key) = LAYOUT_KEYS.iter().find(|k| **k == key) else {
            return Err(problem(
                "",
                format!(
                    "unknown key (got {:?}, expected one of: {}){}",
                    crate::problem::excerpt(key),
                    LAYOUT_KEYS.join(", "),
                    crate::problem::suggestion(key, LAYOUT_KEYS)
                ),
            ));
        };
        if seen.contains(&key) {
            return Err(problem(
                key,
                format!("given twice (got {key}={})", crate::problem::excerpt(value)),
            ));
        }
        seen.push(key);
        let bad = |choices: &[&str]| {
            problem(
                key,
                format!(
                    "unknown value (got {:?}, expected one of: {})",
                    crate::problem::excerpt(value),
                    choices.join(", ")
                ),
            )
        };
        macro_rules! choice {
            ($ty:ty) => {
                <$ty>::from_name(value).ok_or_else(|| bad(&<$ty>::NAMES.map(|(n, _)| n)))?
            };
        }
        let count = |min: usize, max: usize| {
            value
                .parse::<usize>()
                .ok()
                .filter(|n| (min..=max).contains(n))
                .ok_or_else(|| {
                    problem(
                        key,
                        format!(
                            "not a whole number in range (got {:?}, expected {min} to {max})",
                            crate::problem::excerpt(value)
                        ),
                    )
                })
        };
        match key {
            "rows" => layout.rows = choice!(LutAxis),
            "cols" => layout.cols = choice!(LutAxis),
            "grid" => layout.grid = choice!(LutGrid),
            "map" => {
                layout.map = match value {
                    "r2" => RoughnessMap::Squared,
                    "alpha" | "r" => RoughnessMap::Linear,
                    "sqrt" => RoughnessMap::Root,
                    _ => return Err(bad(&["r2", "alpha", "sqrt"])),
                }
            }
            "value" => layout.value = choice!(LutValue),
            "encoding" => encoding = Some(choice!(Encoding)),
            "g2" => layout.g2 = choice!(G2Model),
            "fresnel" => layout.fresnel = choice!(LutFresnel),
            "file" => layout.file = choice!(LutFile),
            "clamp" => {
                layout.clamp = value
                    .parse::<f64>()
                    .ok()
                    .filter(|c| (0.0..1.0).contains(c))
                    .ok_or_else(|| {
                        problem(
                            key,
                            format!(
                                "not a clamp (got {:?}, expected a number in [0, 1))",
                                crate::problem::excerpt(value)
                            ),
                        )
                    })?
            }
            "channels" => layout.channels = count(1, MAX_CHANNELS)?,
            _ => {
                layout.channel = match CHANNEL_NAMES
                    .iter()
                    .find(|(name, _)| name.eq_ignore_ascii_case(value))
                {
                    Some(&(_, index)) => index,
                    None => count(0, MAX_CHANNELS - 1)?,
                }
            }
        }
    }
    layout.given = seen.clone();
    // Without `channels=` the count may come from an image: decode checks the channel then.
    if let Some(message) = missing_channel(&layout).filter(|_| seen.contains(&"channels")) {
        return Err(problem("channel", message));
    }
    if layout.rows == layout.cols {
        return Err(problem(
            "cols",
            format!(
                "rows and cols name the same axis (got rows={} and cols={}, expected one mu and one r)",
                layout.rows.name(),
                layout.cols.name()
            ),
        ));
    }
    layout.encoding = match (encoding, layout.file) {
        (None, LutFile::Raw | LutFile::Exr) => Encoding::F32,
        (None, LutFile::Png) => Encoding::Unorm16,
        (None, _) => Encoding::Text,
        (Some(Encoding::Text), LutFile::Raw | LutFile::Png | LutFile::Exr) => {
            return Err(problem(
                "encoding",
                format!(
                    "text in a binary file (got encoding=text with file={}, expected f32, f16, unorm8 or unorm16)",
                    layout.file.name()
                ),
            ));
        }
        (Some(encoding), _) => encoding,
    };
    Ok(layout)
}

/// (rows, numbers per row) of a table file.
type Shape = (usize, usize);

/// Why `channel=` names no channel of `channels=`, if it does not.
fn missing_channel(layout: &Layout) -> Option<String> {
    (layout.channel >= layout.channels).then(|| {
        format!(
            "no such channel (got {}, expected 0 to {} with channels={})",
            layout.channel,
            layout.channels - 1,
            layout.channels
        )
    })
}

/// The numbers of a table file with the shape its text gives, before any channel is picked.
#[derive(Debug, Clone, PartialEq)]
pub struct Decoded {
    /// The values, row-major, decoded by the encoding (unorm k/255, k/65535).
    pub values: Vec<f64>,
    /// (rows, numbers per row) when a CSV file has several lines of equal length, or an image's
    /// (height, width).
    pub shape: Option<Shape>,
    /// The layout with what the file itself says: an image's kind, encoding and channel count.
    pub layout: Layout,
}

/// Why a table file could not be decoded.
#[derive(Debug, Clone, PartialEq)]
pub enum DecodeError {
    /// The file's bytes (the message names no file; the caller does).
    File(String),
    /// A `--layout` key that contradicts the file: the key and the message.
    Layout(&'static str, String),
}

/// Decodes the bytes of a table file by `layout` (its file kind and encoding): a PNG or OpenEXR
/// file is recognised by its first bytes whatever its name, its encoding and channel count come
/// from the image (an explicit `file=`, `encoding=` or `channels=` that says otherwise is a
/// [`DecodeError::Layout`]), and an image wider or taller than `max_side` is refused before its
/// pixels are read. Messages quote no more than an excerpt of the file.
pub fn decode(bytes: &[u8], layout: &Layout, max_side: usize) -> Result<Decoded, DecodeError> {
    let file = DecodeError::File;
    let mut layout = layout.clone();
    let given = |key: &str| layout.given.contains(&key);
    if let Some(kind) = image_kind(bytes) {
        if given("file") && layout.file != kind {
            return Err(DecodeError::Layout(
                "file",
                format!(
                    "the file is {} image (got file={}, expected file={} or no file key)",
                    if kind == LutFile::Png {
                        "a PNG"
                    } else {
                        "an OpenEXR"
                    },
                    layout.file.name(),
                    kind.name()
                ),
            ));
        }
        layout.file = kind;
    } else if matches!(layout.file, LutFile::Png | LutFile::Exr) {
        return Err(file(format!(
            "not {} file (its first bytes are not the format's signature; give file=… for another kind)",
            if layout.file == LutFile::Png {
                "a PNG"
            } else {
                "an OpenEXR"
            }
        )));
    }
    let fixed_channels = |layout: &Layout| match missing_channel(layout) {
        Some(message) => Err(DecodeError::Layout("channel", message)),
        None => Ok(()),
    };
    let image = match layout.file {
        LutFile::Raw => {
            fixed_channels(&layout)?;
            let values = decode_raw(bytes, layout.encoding).map_err(file)?;
            return Ok(Decoded {
                values,
                shape: None,
                layout,
            });
        }
        LutFile::Csv | LutFile::Header => {
            fixed_channels(&layout)?;
            let text = std::str::from_utf8(bytes).map_err(|e| {
                file(format!(
                    "not UTF-8 text at byte {} (expected a {} file; a binary table takes file=raw)",
                    e.valid_up_to(),
                    layout.file.name()
                ))
            })?;
            let (values, shape) = if layout.file == LutFile::Csv {
                decode_csv(text, layout.encoding).map_err(file)?
            } else {
                (decode_header(text, layout.encoding).map_err(file)?, None)
            };
            return Ok(Decoded {
                values,
                shape,
                layout,
            });
        }
        LutFile::Png => super::lut_image::png(bytes, max_side).map_err(file)?,
        LutFile::Exr => super::lut_image::exr(bytes, max_side, MAX_CHANNELS).map_err(file)?,
    };
    let encoding = match image.samples {
        Samples::Unorm8 => Encoding::Unorm8,
        Samples::Unorm16 => Encoding::Unorm16,
        Samples::F16 => Encoding::F16,
        Samples::F32 => Encoding::F32,
    };
    if given("encoding") && layout.encoding != encoding {
        return Err(DecodeError::Layout(
            "encoding",
            format!(
                "the image stores {} (got encoding={}, expected encoding={} or no encoding key)",
                encoding.name(),
                layout.encoding.name(),
                encoding.name()
            ),
        ));
    }
    if given("channels") && layout.channels != image.channels {
        return Err(DecodeError::Layout(
            "channels",
            format!(
                "the image has {} channels (got channels={}, expected channels={} or no channels key)",
                image.channels, layout.channels, image.channels
            ),
        ));
    }
    if layout.channel >= image.channels {
        return Err(DecodeError::Layout(
            "channel",
            format!(
                "no such channel in the image (got channel={}, expected 0 to {}: the image has {})",
                layout.channel,
                image.channels - 1,
                image.names
            ),
        ));
    }
    layout.encoding = encoding;
    layout.channels = image.channels;
    Ok(Decoded {
        values: image.values,
        shape: Some((image.height, image.width)),
        layout,
    })
}

/// Raw little-endian numbers of `encoding`.
fn decode_raw(bytes: &[u8], encoding: Encoding) -> Result<Vec<f64>, String> {
    let width = match encoding {
        Encoding::F32 => 4,
        Encoding::F16 | Encoding::Unorm16 => 2,
        Encoding::Unorm8 => 1,
        Encoding::Text => unreachable!("parse_layout refuses text in binary files"),
    };
    if bytes.len() % width != 0 {
        return Err(format!(
            "not a whole number of {} values (got {} bytes, expected a multiple of {width})",
            encoding.name(),
            bytes.len()
        ));
    }
    Ok(bytes
        .chunks_exact(width)
        .map(|b| match encoding {
            Encoding::F32 => f64::from(f32::from_le_bytes([b[0], b[1], b[2], b[3]])),
            Encoding::F16 => half_to_f64(u16::from_le_bytes([b[0], b[1]])),
            Encoding::Unorm16 => f64::from(u16::from_le_bytes([b[0], b[1]])) / 65535.0,
            _ => f64::from(b[0]) / 255.0,
        })
        .collect())
}

/// The IEEE binary16 number with bits `h`, exactly (every half is a double).
pub fn half_to_f64(h: u16) -> f64 {
    let sign = if h & 0x8000 != 0 { -1.0 } else { 1.0 };
    let exponent = i32::from((h >> 10) & 0x1f);
    let mantissa = f64::from(h & 0x3ff);
    sign * match exponent {
        0 => mantissa * 2f64.powi(-24),
        31 if mantissa == 0.0 => f64::INFINITY,
        31 => f64::NAN,
        e => (1.0 + mantissa / 1024.0) * 2f64.powi(e - 15),
    }
}

/// One number of a text file under `encoding`: a decimal (or a 0x hex integer), suffixes f/u/l
/// dropped; unorm values are integers in range, divided by 255 or 65535.
fn text_number(token: &str, encoding: Encoding) -> Result<f64, String> {
    let quoted = || crate::problem::excerpt(token);
    let bare = token.trim_end_matches(['f', 'F', 'u', 'U', 'l', 'L']);
    let value = match bare.strip_prefix("0x").or_else(|| bare.strip_prefix("0X")) {
        Some(hex) => u64::from_str_radix(hex, 16).ok().map(|v| v as f64),
        None => bare.parse::<f64>().ok().filter(|v| v.is_finite()),
    }
    .ok_or_else(|| format!("not a number (got {:?})", quoted()))?;
    let unorm = |max: f64| {
        if value.fract() == 0.0 && (0.0..=max).contains(&value) {
            Ok(value / max)
        } else {
            Err(format!(
                "not a {} integer (got {:?}, expected 0 to {max})",
                encoding.name(),
                quoted()
            ))
        }
    };
    match encoding {
        Encoding::Unorm8 => unorm(255.0),
        Encoding::Unorm16 => unorm(65535.0),
        _ => Ok(value),
    }
}

/// A CSV matrix: numbers separated by commas or white space, one table row per line, `#` lines
/// and blank lines skipped.
fn decode_csv(text: &str, encoding: Encoding) -> Result<(Vec<f64>, Option<Shape>), String> {
    let mut values = Vec::new();
    let mut widths = Vec::new();
    for (number, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let before = values.len();
        for token in line
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|t| !t.is_empty())
        {
            values.push(
                text_number(token, encoding).map_err(|e| format!("line {}: {e}", number + 1))?,
            );
        }
        widths.push(values.len() - before);
    }
    let shape = (widths.len() > 1 && widths.iter().all(|&w| w == widths[0]))
        .then(|| (widths.len(), widths[0]));
    Ok((values, shape))
}

/// The numbers of the one array of a C/C++ source: the text between its first `{` and last `}`,
/// comments removed, split at commas, braces and white space; a source with no brace at all is an
/// initializer list `#include`d between an array's braces elsewhere (Adobe's openpbr-bsdf tables),
/// all of whose text is the numbers.
fn decode_header(text: &str, encoding: Encoding) -> Result<Vec<f64>, String> {
    let mut code = String::with_capacity(text.len());
    let mut rest = text;
    while !rest.is_empty() {
        if let Some(after) = rest.strip_prefix("//") {
            rest = after.find('\n').map_or("", |i| &after[i..]);
        } else if let Some(after) = rest.strip_prefix("/*") {
            rest = after.find("*/").map_or("", |i| &after[i + 2..]);
            code.push(' ');
        } else {
            let c = rest.chars().next().expect("not empty");
            code.push(c);
            rest = &rest[c.len_utf8()..];
        }
    }
    let numbers = match (code.find('{'), code.rfind('}')) {
        (None, None) => &code[..],
        (Some(open), Some(close)) if open < close => &code[open + 1..close],
        _ => {
            return Err(
                "no array (expected one { … } holding the numbers, or numbers and no brace)".into(),
            );
        }
    };
    numbers
        .split(|c: char| c == ',' || c == '{' || c == '}' || c.is_whitespace())
        .filter(|t| !t.is_empty())
        .map(|t| text_number(t, encoding))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn halves_decode_exactly() {
        // IEEE 754 binary16: 0x3C00 = 1, 0x3555 = 0.333251953125, 0x0001 = 2^-24, 0xC000 = -2.
        assert_eq!(half_to_f64(0x3C00), 1.0);
        assert_eq!(half_to_f64(0x3555), 0.333251953125);
        assert_eq!(half_to_f64(0x0001), 2f64.powi(-24));
        assert_eq!(half_to_f64(0xC000), -2.0);
        assert_eq!(half_to_f64(0x7C00), f64::INFINITY);
    }

    #[test]
    fn headers_and_csv_matrices_decode() {
        let header = "// table\nstatic const float t[4] = { 0.5f, /* x */ 1.0f,\n 0x0, 2e-1 };\n";
        let layout = parse_layout("", "t.h", G2Model::HeightCorrelated).unwrap();
        assert_eq!(layout.file, LutFile::Header);
        assert_eq!(
            decode(header.as_bytes(), &layout, 1024).unwrap().values,
            [0.5, 1.0, 0.0, 0.2]
        );
        // An initializer list meant to be #included between braces; one brace alone is no array.
        let included = "// clang-format off\n0, 65535, 0x8000\n    // clang-format on\n";
        let layout = parse_layout("encoding=unorm16", "t.h", G2Model::Separable).unwrap();
        assert_eq!(
            decode(included.as_bytes(), &layout, 1024).unwrap().values,
            [0.0, 1.0, 32768.0 / 65535.0]
        );
        assert!(decode(b"0, 1 }", &layout, 1024).is_err());
        let layout = parse_layout("encoding=unorm8", "t.csv", G2Model::Separable).unwrap();
        let decoded = decode(b"# c\n0,255\n51 102\n", &layout, 1024).unwrap();
        assert_eq!(decoded.values, [0.0, 1.0, 0.2, 0.4]);
        assert_eq!(decoded.shape, Some((2, 2)));
    }

    #[test]
    fn layouts_refuse_what_they_cannot_mean() {
        let g2 = G2Model::HeightCorrelated;
        for bad in [
            "rows=r",
            "rows=mu,rows=mu",
            "colour=red",
            "map=r3",
            "encoding=text",
            "channels=2,channel=2",
            "clamp=1",
        ] {
            assert!(parse_layout(bad, "t.bin", g2).is_err(), "{bad}");
        }
        let layout = parse_layout(
            "rows=r,cols=mu,grid=centers,map=sqrt,value=1-e,encoding=unorm16,g2=separable,channels=2,channel=1",
            "t.bin",
            g2,
        )
        .unwrap();
        assert_eq!(layout.rows, LutAxis::R);
        assert_eq!(layout.map, RoughnessMap::Root);
        assert_eq!(layout.g2, G2Model::Separable);
        assert_eq!((layout.channels, layout.channel), (2, 1));
    }
}
