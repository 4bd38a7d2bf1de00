//! Writing images: PNG for people, PFM for comparison, both atomically.
//!
//! **Tone mapping, stated**: none beyond the display's range. Each channel's
//! radiance is taken as the display-referred linear value (1 W/(sr·m²) is
//! full white), clamped to `[0, 1]` as the course's OpenGL framebuffer does,
//! encoded with the sRGB transfer function (IEC 61966-2-1) and rounded to 8
//! bits. The PFM holds the unclamped linear radiance as 32-bit floats.
//!
//! A file is written to a temporary file in the destination's directory and
//! renamed over the destination only once complete, so an interrupted or
//! failed write never leaves a partial image; the PNG and its PFM are
//! renamed as one set, so they are never of two renders
//! (`safe_io::write_all_atomically`, and `safe_io::interrupt` for
//! signals). The destination is checked before the render
//! ([`Destination::new`], `safe_io::check_destination`).

use image::ImageEncoder;
use safe_io::{check_destination, write_all_atomically, write_atomically, WriteError};
use std::path::{Path, PathBuf};

use crate::render::Image;

/// Why an image could not be written.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// The file could not be written (`safe_io`'s kinds, texts unchanged).
    #[error(transparent)]
    Write(#[from] WriteError),
    /// A PNG's name whose PFM would be itself (it ends in `.pfm`).
    #[error("{path}: give the PNG's name (the PFM is written beside it)")]
    PfmIsPng {
        /// The name given.
        path: String,
    },
    /// A name whose extension says another format than the PNG written.
    #[error(
        "{path}: the image is written as PNG (and a PFM beside it): give a name ending in .png"
    )]
    NotPng {
        /// The name given.
        path: String,
    },
    /// The PNG encoder failed.
    #[error("cannot encode {path} as PNG: {source}")]
    Png {
        /// The destination.
        path: String,
        /// The reason.
        source: image::ImageError,
    },
}

/// One channel of a pixel as an 8-bit sRGB value (NaN shows as black).
pub fn to_srgb8(radiance: f32) -> u8 {
    let clamped = if radiance.is_nan() {
        0.0
    } else {
        radiance.clamp(0.0, 1.0)
    };
    (radiometry::colour::srgb_encode(f64::from(clamped)) * 255.0).round() as u8
}

/// The image as 8-bit sRGB bytes, rows top to bottom.
pub fn srgb8(image: &Image) -> Vec<u8> {
    // A pixel bit for bit the one before it (an enlarged figure repeats each
    // pixel) takes that one's bytes: the encoding's powers are the cost.
    let mut out = Vec::with_capacity(3 * image.pixels.len());
    let mut last: Option<([u32; 3], [u8; 3])> = None;
    for pixel in &image.pixels {
        let bits = pixel.to_array().map(f32::to_bits);
        let bytes = match last {
            Some((before, bytes)) if before == bits => bytes,
            _ => pixel.to_array().map(to_srgb8),
        };
        last = Some((bits, bytes));
        out.extend_from_slice(&bytes);
    }
    out
}

/// The image as a PFM file: `PF`, size, `-1` (little-endian), then rows
/// from the bottom up, three `f32` per pixel.
pub fn pfm_bytes(image: &Image) -> Vec<u8> {
    let mut out = format!("PF\n{} {}\n-1.0\n", image.width, image.height).into_bytes();
    for y in (0..image.height).rev() {
        for x in 0..image.width {
            for c in image.get(x, y).to_array() {
                out.extend_from_slice(&c.to_le_bytes());
            }
        }
    }
    out
}

/// Where a render is written: a PNG and, beside it, the PFM of the same
/// name. Checked when made ([`check_destination`], for each), so that a
/// destination that cannot or must not be written is refused before the
/// render is spent on it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Destination {
    png: PathBuf,
    pfm: PathBuf,
}

impl Destination {
    /// The PNG at `png`, the PFM beside it, neither one of `inputs` (the
    /// scene read).
    pub fn new(png: &Path, inputs: &[&Path]) -> Result<Self, OutputError> {
        let pfm = png.with_extension("pfm");
        if pfm == png {
            return Err(OutputError::PfmIsPng {
                path: png.display().to_string(),
            });
        }
        check_destination(png, inputs)?;
        check_destination(&pfm, inputs)?;
        // PNG bytes under another format's name (`x.jpg`) would mislead;
        // a name without an extension says nothing wrong. Checked after
        // the destinations, so that the scene itself given as the output
        // is refused as such.
        if png
            .extension()
            .is_some_and(|e| !e.eq_ignore_ascii_case("png"))
        {
            return Err(OutputError::NotPng {
                path: png.display().to_string(),
            });
        }
        Ok(Destination {
            png: png.to_owned(),
            pfm,
        })
    }

    /// The PNG.
    pub fn png(&self) -> &Path {
        &self.png
    }

    /// The PFM.
    pub fn pfm(&self) -> &Path {
        &self.pfm
    }

    /// Writes `image` to both, atomically as a pair: after a write error
    /// or SIGINT/SIGTERM both are the previous render's (or absent), never
    /// one of each.
    pub fn write(&self, image: &Image) -> Result<(), OutputError> {
        let png = png_bytes(&self.png, image)?;
        Ok(write_all_atomically(&[
            (&self.png, &png),
            (&self.pfm, &pfm_bytes(image)),
        ])?)
    }
}

/// Writes the image as an sRGB PNG, atomically.
pub fn write_png(path: &Path, image: &Image) -> Result<(), OutputError> {
    Ok(write_atomically(path, &png_bytes(path, image)?)?)
}

/// The image encoded as an sRGB PNG (`path` names it in an error).
fn png_bytes(path: &Path, image: &Image) -> Result<Vec<u8>, OutputError> {
    let mut encoded = Vec::new();
    image::codecs::png::PngEncoder::new(&mut encoded)
        .write_image(
            &srgb8(image),
            image.width,
            image.height,
            image::ExtendedColorType::Rgb8,
        )
        .map_err(|source| OutputError::Png {
            path: path.display().to_string(),
            source,
        })?;
    Ok(encoded)
}

/// Writes the image as a PFM, atomically: the file `optics compare` reads,
/// for an image rendered or changed through the library rather than by
/// `optics render`.
pub fn write_pfm(path: &Path, image: &Image) -> Result<(), OutputError> {
    Ok(write_atomically(path, &pfm_bytes(image))?)
}

/// Reads a PFM written by [`pfm_bytes`] (three channels, little-endian).
pub fn read_pfm(bytes: &[u8]) -> Option<Image> {
    let mut fields = Vec::new();
    let mut start = 0;
    for (i, b) in bytes.iter().enumerate() {
        if *b == b'\n' {
            fields.push(std::str::from_utf8(&bytes[start..i]).ok()?);
            start = i + 1;
            if fields.len() == 3 {
                break;
            }
        }
    }
    if fields.len() != 3 || fields[0] != "PF" || fields[2] != "-1.0" {
        return None;
    }
    let mut size = fields[1].split(' ').map(|s| s.parse::<u32>());
    let (width, height) = (size.next()?.ok()?, size.next()?.ok()?);
    let data = &bytes[start..];
    // A header's size is trusted only as far as the bytes that follow it:
    // its product is checked, not wrapped.
    let (w, h) = (width as usize, height as usize);
    let count = w.checked_mul(h)?;
    if Some(data.len()) != count.checked_mul(12) {
        return None;
    }
    let float =
        |i: usize| f32::from_le_bytes(data[4 * i..4 * i + 4].try_into().unwrap_or_default());
    let mut pixels = vec![glam::Vec3::ZERO; count];
    for row in 0..h {
        let y = h - 1 - row;
        for x in 0..w {
            let i = (row * w + x) * 3;
            pixels[y * w + x] = glam::Vec3::new(float(i), float(i + 1), float(i + 2));
        }
    }
    Some(Image {
        width,
        height,
        pixels,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A header whose size's byte count passes `usize` is refused, not
    /// wrapped (the truth cache's fuzz target found the overflow).
    #[test]
    fn a_pfm_whose_size_overflows_is_refused() {
        for header in [
            "PF\n4294967295 4294967295\n-1.0\n",
            "PF\n65536 65536\n-1.0\n",
        ] {
            let mut bytes = header.as_bytes().to_vec();
            bytes.extend_from_slice(&[0; 12]);
            assert!(read_pfm(&bytes).is_none(), "{header}");
        }
    }
    use glam::Vec3;

    /// Runs of equal pixels take the first one's bytes: the result is each
    /// pixel encoded alone, also where a pixel differs from the one before
    /// in one channel only, or in the sign of a zero, or is NaN.
    #[test]
    fn srgb_bytes_are_each_pixel_encoded_alone() {
        let pixels = [
            Vec3::new(0.2, 0.5, 0.9),
            Vec3::new(0.2, 0.5, 0.9),
            Vec3::new(0.2, 0.6, 0.9),
            Vec3::new(0.2, 0.6, 0.91),
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(-0.0, 0.0, 0.0),
            Vec3::splat(f32::NAN),
            Vec3::splat(f32::NAN),
            Vec3::new(1.5, 0.5, 0.0),
        ];
        let image = Image {
            width: pixels.len() as u32,
            height: 1,
            pixels: pixels.to_vec(),
        };
        let alone: Vec<u8> = pixels
            .iter()
            .flat_map(|p| p.to_array().map(to_srgb8))
            .collect();
        assert_eq!(srgb8(&image), alone);
    }

    #[test]
    fn srgb_encoding_matches_iec_61966_2_1() {
        // Known values (the transfer function itself is tested in
        // radiometry::colour): 0.5 linear is 0.7354 encoded (188 of 255),
        // 0.2140 linear is 0.5 encoded (128: 127.5 rounds up).
        assert_eq!(to_srgb8(0.0), 0);
        assert_eq!(to_srgb8(1.0), 255);
        assert_eq!(to_srgb8(0.5), 188);
        assert_eq!(to_srgb8(0.214_1), 128);
    }

    #[test]
    fn tone_mapping_clamps_to_the_display_range() {
        assert_eq!(to_srgb8(7.5), 255);
        assert_eq!(to_srgb8(-0.1), 0);
        assert_eq!(to_srgb8(f32::NAN), 0);
    }

    #[test]
    fn pfm_round_trips_exactly_with_rows_bottom_up() {
        let image = Image {
            width: 3,
            height: 2,
            pixels: (0..6)
                .map(|i| Vec3::new(i as f32, 0.5, -1e-7 * i as f32))
                .collect(),
        };
        let bytes = pfm_bytes(&image);
        assert!(bytes.starts_with(b"PF\n3 2\n-1.0\n"));
        // The first stored pixel is the bottom-left one: (0, 1), value 3.
        let first = f32::from_le_bytes(bytes[12..16].try_into().unwrap());
        assert_eq!(first, 3.0);
        assert_eq!(read_pfm(&bytes), Some(image));
    }

    /// What [`write_pfm`] leaves on disk reads back bit for bit, negative
    /// zero, subnormals and infinities included.
    #[test]
    fn written_pfm_reads_back_exactly() {
        let pixels = vec![
            Vec3::new(-0.0, f32::from_bits(1), f32::INFINITY),
            Vec3::new(0.1, 0.2, 0.3),
            Vec3::new(1e30, -1e-30, f32::MAX),
            Vec3::new(2.0, 0.5, 7.25),
        ];
        let image = Image {
            width: 2,
            height: 2,
            pixels,
        };
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("image.pfm");
        write_pfm(&path, &image).unwrap();
        let back = read_pfm(&std::fs::read(&path).unwrap()).unwrap();
        let bits = |image: &Image| -> Vec<[u32; 3]> {
            image
                .pixels
                .iter()
                .map(|p| p.to_array().map(f32::to_bits))
                .collect()
        };
        assert_eq!((back.width, back.height), (2, 2));
        assert_eq!(bits(&back), bits(&image));
    }
}
