//! A scene's `environment`, validated: its scale in its domain, its image
//! files read, decoded and sized for their map once, here, each refusal
//! naming the field that gave the file (`environment.image`,
//! `environment.faces[3]`). Nothing after this re-checks a map.

use std::path::Path;
use std::sync::Arc;

use glam::Vec3;
use image::ImageDecoder;
use radiometry::domain;

use super::error::{ErrorKind, SceneError};
use super::error::{ImageProblem, SizeRule};
use super::faults::{self, Fault};
use super::schema::EnvironmentSpec;
use crate::environment::{cut_cross, CubeMap, Environment, Texels};

/// The longest side of an environment image accepted, texels: a lat-long
/// map of 8192 × 4096 (0.4 GiB of `f32` radiance) resolves 0.044°, finer
/// than any render here needs; a longer side is almost certainly not a map.
pub const MAX_ENVIRONMENT_SIDE: u32 = 8192;

/// The environment of `spec`, its files named relative to `dir`.
pub(super) fn validate(spec: &EnvironmentSpec, dir: &Path) -> Result<Arc<Environment>, SceneError> {
    let environment = match spec {
        EnvironmentSpec::DirectionColour { scale } => Environment::DirectionColour {
            scale: scale_of(*scale)?,
        },
        EnvironmentSpec::LatLong { image, scale } => {
            let field = "environment.image";
            let texels = read_png(field, &dir.join(image))?;
            let (width, height) = (texels.width(), texels.height());
            if width != 2 * height && !faults::undone(Fault::EnvironmentSizeUnchecked) {
                return Err(size(
                    field,
                    image,
                    width,
                    height,
                    SizeRule::TwiceAsWideAsHigh,
                ));
            }
            Environment::LatLong {
                texels,
                scale: scale_of(*scale)?,
            }
        }
        EnvironmentSpec::CubeCross { image, scale } => {
            let field = "environment.image";
            let cross = read_png(field, &dir.join(image))?;
            let (width, height) = (cross.width(), cross.height());
            let side = width / 4;
            let fits = width % 4 == 0 && side > 0 && height == 3 * side;
            if !fits && !faults::undone(Fault::EnvironmentSizeUnchecked) {
                return Err(size(
                    field,
                    image,
                    width,
                    height,
                    SizeRule::FourByThreeFaces,
                ));
            }
            Environment::Cube {
                map: CubeMap::of_side(side, cut_cross(&cross, side)),
                scale: scale_of(*scale)?,
            }
        }
        EnvironmentSpec::Cube { faces, scale } => {
            let mut read: Vec<Texels> = Vec::with_capacity(6);
            for (k, file) in faces.iter().enumerate() {
                let field = format!("environment.faces[{k}]");
                let texels = read_png(&field, &dir.join(file))?;
                let (width, height) = (texels.width(), texels.height());
                let rule = match read.first() {
                    _ if width != height => Some(SizeRule::Square),
                    Some(first) if first.width() != width => {
                        Some(SizeRule::SideOfFirstFace(first.width()))
                    }
                    _ => None,
                };
                if let Some(rule) = rule {
                    if !faults::undone(Fault::EnvironmentSizeUnchecked) {
                        return Err(size(&field, file, width, height, rule));
                    }
                }
                read.push(texels);
            }
            Environment::Cube {
                map: CubeMap::of_side(read[0].width(), read),
                scale: scale_of(*scale)?,
            }
        }
    };
    Ok(Arc::new(environment))
}

/// The scale, default 1: finite, ≥ 0 and within `f32` (texels are at
/// most 1, so the environment's radiance is at most the scale).
fn scale_of(scale: Option<f64>) -> Result<f32, SceneError> {
    let Some(scale) = scale else {
        return Ok(1.0);
    };
    let field = "environment.scale";
    domain::non_negative(field, scale)?;
    if !(scale as f32).is_finite() {
        return Err(domain::DomainError::OutOfRange {
            name: field.to_owned(),
            value: scale,
            expected: domain::Expected::WithinF32,
        }
        .into());
    }
    Ok(scale as f32)
}

fn size(field: &str, file: &str, width: u32, height: u32, expected: SizeRule) -> SceneError {
    let problem = ImageProblem::Size {
        width,
        height,
        expected,
    };
    refusal(field, file, problem)
}

fn refusal(field: &str, file: &str, problem: ImageProblem) -> SceneError {
    let file = file.to_owned();
    SceneError::new(field, ErrorKind::EnvironmentImage { file, problem })
}

/// The PNG at `path`, given as `field`, as linear values: 8-bit RGB or
/// RGBA (alpha ignored), each code decoded by the sRGB transfer function
/// (`radiometry::colour::srgb_decode`), each side 1 to
/// [`MAX_ENVIRONMENT_SIDE`].
pub(super) fn read_png(field: &str, path: &Path) -> Result<Texels, SceneError> {
    let shown = path.display().to_string();
    let bytes =
        std::fs::read(path).map_err(|source| refusal(field, &shown, ImageProblem::Read(source)))?;
    decode_png(&bytes).map_err(|problem| refusal(field, &shown, problem))
}

/// The bytes of a PNG file as linear values: 8-bit RGB or RGBA (alpha
/// ignored), each code decoded by the sRGB transfer function, each side 1
/// to [`MAX_ENVIRONMENT_SIDE`]. The size is checked from the header before
/// any pixel is decoded, and the decoder's own limits bound what it
/// allocates.
pub fn decode_png(bytes: &[u8]) -> Result<Texels, ImageProblem> {
    let decode = |e: image::ImageError| ImageProblem::Decode(e.to_string());
    let decoder =
        image::codecs::png::PngDecoder::new(std::io::Cursor::new(bytes)).map_err(decode)?;
    let (width, height) = decoder.dimensions();
    if width > MAX_ENVIRONMENT_SIDE || height > MAX_ENVIRONMENT_SIDE {
        return Err(ImageProblem::Size {
            width,
            height,
            expected: SizeRule::AtMost(MAX_ENVIRONMENT_SIDE),
        });
    }
    let channels = match decoder.color_type() {
        image::ColorType::Rgb8 => 3,
        image::ColorType::Rgba8 => 4,
        other => return Err(ImageProblem::Pixels(format!("{other:?}"))),
    };
    let mut data = vec![0; decoder.total_bytes() as usize];
    decoder.read_image(&mut data).map_err(decode)?;
    let linear: [f32; 256] =
        std::array::from_fn(|code| radiometry::colour::srgb_decode(code as f64 / 255.0) as f32);
    let texels = data
        .chunks_exact(channels)
        .map(|p| {
            Vec3::new(
                linear[p[0] as usize],
                linear[p[1] as usize],
                linear[p[2] as usize],
            )
        })
        .collect();
    // The decoder filled exactly width × height pixels of `channels` bytes.
    Texels::new(width, height, texels).ok_or_else(|| {
        ImageProblem::Decode(format!("{width} × {height} pixels not decoded in full"))
    })
}
