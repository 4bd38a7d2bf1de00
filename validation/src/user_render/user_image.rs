//! The user's image, decoded: a PNG as its 8-bit sRGB codes, a PFM as its
//! linear values, each value checked where it enters.
//!
//! PFM is read as its writers write it (Debevec's format, as pbrt, the
//! suite and most renderers do): `PF` (RGB) or `Pf` (grey, shown as three
//! equal channels), the width, the height and the scale separated by white
//! space, one white-space byte, then rows from the bottom up, the byte
//! order little-endian for a negative scale and big-endian for a positive
//! one. The scale's magnitude is not applied (the suite writes 1).

use std::path::Path;

use image::ImageDecoder;

use super::error::{CompareError, PfmProblem};

/// A decoded image: rows top to bottom, three channels a pixel.
#[derive(Clone, Debug, PartialEq)]
pub enum UserImage {
    /// A PNG's 8-bit sRGB codes.
    Codes {
        /// Width, pixels.
        width: u32,
        /// Height, pixels.
        height: u32,
        /// `[R, G, B, …]`.
        codes: Vec<u8>,
    },
    /// A PFM's linear values.
    Linear {
        /// Width, pixels.
        width: u32,
        /// Height, pixels.
        height: u32,
        /// `[R, G, B, …]`.
        values: Vec<f64>,
    },
}

impl UserImage {
    /// Width and height, pixels.
    pub fn size(&self) -> (u32, u32) {
        match self {
            UserImage::Codes { width, height, .. } | UserImage::Linear { width, height, .. } => {
                (*width, *height)
            }
        }
    }
}

/// The bytes of the file at `path`, given as `field`.
pub fn read_bytes(field: &'static str, path: &Path) -> Result<Vec<u8>, CompareError> {
    std::fs::read(path).map_err(|source| CompareError::Read {
        field,
        path: path.to_owned(),
        source,
    })
}

/// Reads and decodes the file at `path`, given as `field`.
pub fn read(field: &'static str, path: &Path) -> Result<UserImage, CompareError> {
    decode(field, path, &read_bytes(field, path)?)
}

/// Decodes `bytes` by their first bytes: the PNG signature, or `P` and
/// `F`/`f`.
pub fn decode(field: &'static str, path: &Path, bytes: &[u8]) -> Result<UserImage, CompareError> {
    if bytes.starts_with(b"\x89PNG\r\n\x1a\n") {
        decode_png(field, path, bytes)
    } else if bytes.starts_with(b"PF") || bytes.starts_with(b"Pf") {
        decode_pfm(bytes).map_err(|problem| CompareError::Pfm {
            field,
            path: path.to_owned(),
            problem,
        })
    } else {
        Err(CompareError::UnknownFormat {
            field,
            path: path.to_owned(),
        })
    }
}

fn decode_png(field: &'static str, path: &Path, bytes: &[u8]) -> Result<UserImage, CompareError> {
    let refused = |e: image::ImageError| CompareError::Png {
        field,
        path: path.to_owned(),
        message: e.to_string(),
    };
    // The decoder's default limits bound what a header can make it allocate.
    let decoder =
        image::codecs::png::PngDecoder::new(std::io::Cursor::new(bytes)).map_err(refused)?;
    let (width, height) = decoder.dimensions();
    let colour = decoder.color_type();
    let channels = match colour {
        image::ColorType::Rgb8 => 3,
        image::ColorType::Rgba8 => 4,
        other => {
            return Err(CompareError::PngPixels {
                field,
                path: path.to_owned(),
                format: format!("{other:?}"),
            })
        }
    };
    let mut data = vec![0; decoder.total_bytes() as usize];
    decoder.read_image(&mut data).map_err(refused)?;
    // Alpha is not part of the render: a screenshot's is opaque.
    let codes = data
        .chunks_exact(channels)
        .flat_map(|p| [p[0], p[1], p[2]])
        .collect();
    Ok(UserImage::Codes {
        width,
        height,
        codes,
    })
}

fn decode_pfm(bytes: &[u8]) -> Result<UserImage, PfmProblem> {
    // Four white-space separated fields, then one white-space byte.
    let mut fields = Vec::new();
    let mut at = 0;
    while fields.len() < 4 {
        while bytes.get(at).is_some_and(u8::is_ascii_whitespace) {
            at += 1;
        }
        let start = at;
        while bytes.get(at).is_some_and(|b| !b.is_ascii_whitespace()) {
            at += 1;
        }
        if start == at || at - start > 32 {
            return Err(PfmProblem::Header);
        }
        fields.push(std::str::from_utf8(&bytes[start..at]).map_err(|_| PfmProblem::Header)?);
    }
    if !bytes.get(at).is_some_and(u8::is_ascii_whitespace) {
        return Err(PfmProblem::Header);
    }
    let data = &bytes[at + 1..];
    let channels: usize = match fields[0] {
        "PF" => 3,
        "Pf" => 1,
        _ => return Err(PfmProblem::Header),
    };
    let size = |s: &str| s.parse::<u32>().map_err(|_| PfmProblem::Header);
    let (width, height) = (size(fields[1])?, size(fields[2])?);
    let scale: f64 = fields[3].parse().map_err(|_| PfmProblem::Header)?;
    if !(scale.is_finite() && scale != 0.0) {
        return Err(PfmProblem::Scale);
    }
    let expected = u64::from(width) * u64::from(height) * channels as u64 * 4;
    if data.len() as u64 != expected && !length_unchecked() {
        return Err(PfmProblem::Length {
            expected,
            got: data.len() as u64,
        });
    }
    let float = |i: usize| {
        let b = [
            data[4 * i],
            data[4 * i + 1],
            data[4 * i + 2],
            data[4 * i + 3],
        ];
        f64::from(if scale < 0.0 {
            f32::from_le_bytes(b)
        } else {
            f32::from_be_bytes(b)
        })
    };
    let (w, h) = (width as usize, height as usize);
    let mut values = Vec::with_capacity(3 * w * h);
    for y in 0..h {
        let row = h - 1 - y;
        for x in 0..w {
            let first = (row * w + x) * channels;
            values.extend((0..3).map(|c| float(first + c % channels)));
        }
    }
    Ok(UserImage::Linear {
        width,
        height,
        values,
    })
}

#[cfg(any(test, feature = "faults"))]
thread_local! {
    /// A test-only switch that reverts the PFM length check on this
    /// thread, for the compare-images fuzz target (in the command line's
    /// tests) to find; compiled only with the `faults` feature.
    pub static LENGTH_UNCHECKED: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

#[cfg(any(test, feature = "faults"))]
fn length_unchecked() -> bool {
    LENGTH_UNCHECKED.get()
}

#[cfg(not(any(test, feature = "faults")))]
fn length_unchecked() -> bool {
    false
}

/// The first value of a linear image that is not finite (or negative,
/// for a variance): the error naming it.
pub fn check_values(
    field: &'static str,
    width: u32,
    values: &[f64],
    non_negative: bool,
) -> Result<(), CompareError> {
    let bad = |v: &f64| !v.is_finite() || (non_negative && *v < 0.0);
    match values.iter().position(bad) {
        None => Ok(()),
        Some(i) => Err(CompareError::BadValue {
            field,
            x: (i / 3) as u32 % width,
            y: (i / 3) as u32 / width,
            channel: ['R', 'G', 'B'][i % 3],
            value: values[i] as f32,
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_suites_pfm_reads_back_with_rows_top_to_bottom() {
        let image = tracer::render::Image {
            width: 2,
            height: 2,
            pixels: (0..4)
                .map(|i| glam::Vec3::new(i as f32, 0.5, -0.25))
                .collect(),
        };
        let bytes = tracer::output::pfm_bytes(&image);
        let decoded = decode("IMAGE", Path::new("a.pfm"), &bytes).unwrap();
        let expected: Vec<f64> = (0..4).flat_map(|i| [i as f64, 0.5, -0.25]).collect();
        assert_eq!(
            decoded,
            UserImage::Linear {
                width: 2,
                height: 2,
                values: expected
            }
        );
    }

    #[test]
    fn a_big_endian_grey_pfm_is_three_equal_channels() {
        let mut bytes = b"Pf 2 1\n1\n".to_vec();
        for v in [1.5f32, 2.0] {
            bytes.extend_from_slice(&v.to_be_bytes());
        }
        let decoded = decode("IMAGE", Path::new("g.pfm"), &bytes).unwrap();
        let expected = vec![1.5, 1.5, 1.5, 2.0, 2.0, 2.0];
        assert_eq!(
            decoded,
            UserImage::Linear {
                width: 2,
                height: 1,
                values: expected
            }
        );
    }

    fn png(colour: image::ExtendedColorType, bytes: &[u8]) -> Vec<u8> {
        use image::ImageEncoder;
        let mut out = Vec::new();
        image::codecs::png::PngEncoder::new(&mut out)
            .write_image(bytes, 2, 1, colour)
            .unwrap();
        out
    }

    #[test]
    fn an_rgba_png_is_its_colour_and_a_16_bit_one_is_refused() {
        let rgba = png(image::ExtendedColorType::Rgba8, &[1, 2, 3, 0, 4, 5, 6, 255]);
        let decoded = decode("IMAGE", Path::new("a.png"), &rgba).unwrap();
        let codes = vec![1, 2, 3, 4, 5, 6];
        assert_eq!(
            decoded,
            UserImage::Codes {
                width: 2,
                height: 1,
                codes
            }
        );
        let deep = png(image::ExtendedColorType::Rgb16, &[0; 12]);
        match decode("IMAGE", Path::new("b.png"), &deep) {
            Err(CompareError::PngPixels { format, .. }) => assert_eq!(format, "Rgb16"),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn malformed_pfms_say_what_is_wrong() {
        let path = Path::new("bad.pfm");
        let problem = |bytes: &[u8]| match decode("IMAGE", path, bytes) {
            Err(CompareError::Pfm { problem, .. }) => problem,
            other => panic!("{other:?}"),
        };
        assert_eq!(problem(b"PF 1 1\n"), PfmProblem::Header);
        assert_eq!(problem(b"PF 1 x\n-1\n"), PfmProblem::Header);
        assert_eq!(problem(b"PF 1 1\n0\n............"), PfmProblem::Scale);
        assert_eq!(problem(b"PF 1 1\nnan\n............"), PfmProblem::Scale);
        assert_eq!(
            problem(b"PF 2 1\n-1\n............"),
            PfmProblem::Length {
                expected: 24,
                got: 12
            }
        );
    }
}
