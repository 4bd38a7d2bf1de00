//! The schema of `mitsuba_renders.json` and its decoding: the base64 images
//! as `f64` per channel, the scene as Mitsuba rendered it, every size
//! checked before anything is allocated.

use std::path::Path;

use base64::Engine as _;
use serde::Deserialize;
use tracer::scene::{PixelFilter, Scene};

use crate::reference::ReferenceError;

/// The reference file.
pub const FILE: &str = "mitsuba_renders.json";
/// Its schema.
pub const SCHEMA: &str = "mitsuba-renders/2";

/// `mitsuba_renders.json`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MitsubaRenders {
    /// [`SCHEMA`].
    pub schema: String,
    /// The script that wrote it.
    pub generator: String,
    /// The command that regenerates it.
    pub regenerate: String,
    /// What it holds.
    pub description: String,
    /// Mitsuba's version and variant.
    pub mitsuba: Tool,
    /// Scenes not compared, and why.
    pub excluded: std::collections::BTreeMap<String, String>,
    /// The scenes rendered.
    pub scenes: Vec<SceneRenders>,
}

/// A tool's version.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Tool {
    /// Version.
    pub version: String,
    /// Mitsuba's variant.
    pub variant: String,
}

/// One scene's Mitsuba renders.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneRenders {
    /// The scene's name (its file stem).
    pub name: String,
    /// Its file, relative to the repository root.
    pub scene_file: String,
    /// The scene file's text as Mitsuba rendered it.
    pub scene_text: String,
    /// Image width, pixels.
    pub width: u32,
    /// Image height, pixels.
    pub height: u32,
    /// The Whitted render.
    pub whitted: WhittedRender,
    /// Edge mask, one byte per pixel (1: masked), base64.
    pub edges_u8: String,
    /// Mitsuba's path tracer, when compared.
    #[serde(default)]
    pub path: Option<PathRender>,
    /// Why the path tracer is not compared.
    #[serde(default)]
    pub path_skipped: Option<String>,
}

/// A Whitted render.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WhittedRender {
    /// Bounces after the primary hit.
    pub max_depth: u32,
    /// The throughput below which a branch is cut.
    pub throughput_cutoff: f64,
    /// Radiance, float32 little-endian RGB, rows top to bottom, base64.
    pub radiance_f32le: String,
}

/// Mitsuba's path tracer through its own renderer (`mi.render`), box
/// filtered, at its own size.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PathRender {
    /// Image width, pixels.
    pub width: u32,
    /// Image height, pixels.
    pub height: u32,
    /// The film's reconstruction filter: `box`, the tracer's
    /// `pixel_filter` of the same name.
    pub pixel_filter: PixelFilter,
    /// Bounces after the primary hit, the suite's count.
    pub max_depth: u32,
    /// The same as Mitsuba counts it (path segments): `max_depth + 2`.
    pub mitsuba_max_depth: u32,
    /// Samples per pixel: independent passes of one sample each.
    pub samples: u32,
    /// The passes' seeds, in words.
    pub seeds: String,
    /// Per-pixel mean, float16 RGB, zlib, base64.
    pub mean_f16le_zlib: String,
    /// Per-pixel standard deviation of one sample (unbiased variance's
    /// square root), bfloat16 RGB, zlib, base64.
    pub std_bf16le_zlib: String,
    /// How far Mitsuba's own ray offsets move each pixel: its Whitted render
    /// with `si.spawn_ray` against the one the Whitted check uses, at the
    /// Whitted size, taken at this size as the largest over each pixel's
    /// Whitted pixel and its neighbours; float16 RGB, zlib, base64.
    pub offset_sensitivity_f16le_zlib: String,
}

impl MitsubaRenders {
    /// Reads [`FILE`] from `dir`.
    pub fn load(dir: &std::path::Path) -> Result<Self, ReferenceError> {
        crate::reference::load(dir, FILE, SCHEMA)
    }
}

/// A scene's reference decoded: images as `f64` per channel.
#[derive(Clone, Debug)]
pub struct Decoded {
    /// The scene as Mitsuba saw it, at the reference's size.
    pub scene: Scene,
    /// Mitsuba's Whitted radiance, `3 · width · height`.
    pub whitted: Vec<f64>,
    /// Masked pixels, `width · height`.
    pub edges: Vec<bool>,
    /// Mitsuba's path mean and variance, and how far its ray offsets move
    /// each pixel, `3 · width · height` each.
    pub path: Option<PathImages>,
}

/// Mitsuba's path render, decoded.
#[derive(Clone, Debug)]
pub struct PathImages {
    /// The scene at the path render's size.
    pub scene: Scene,
    /// Per-pixel mean.
    pub mean: Vec<f64>,
    /// Per-pixel variance of one sample.
    pub variance: Vec<f64>,
    /// Per-pixel sensitivity to Mitsuba's ray offsets.
    pub offset_sensitivity: Vec<f64>,
}

/// Decodes one scene of the reference; errors name the field.
pub fn decode(file: &Path, index: usize, s: &SceneRenders) -> Result<Decoded, ReferenceError> {
    let malformed = |field: &str, message: String| ReferenceError::Malformed {
        path: file.to_owned(),
        field: format!("scenes[{index}].{field}"),
        message,
    };
    check_sizes(s).map_err(|(field, message)| malformed(field, message))?;
    let scene = tracer::scene::parse(&s.scene_text)
        .map_err(|e| malformed("scene_text", e.to_string()))?
        .resized(s.width, s.height);
    let pixels = s.width as usize * s.height as usize;
    let floats = |field: &str, text: &str| rgb_f32le(text, pixels).map_err(|m| malformed(field, m));
    let whitted = floats("whitted.radiance_f32le", &s.whitted.radiance_f32le)?;
    let edges = base64_bytes(&s.edges_u8).map_err(|m| malformed("edges_u8", m))?;
    if edges.len() != pixels {
        return Err(malformed(
            "edges_u8",
            format!("expected {pixels} bytes, got {}", edges.len()),
        ));
    }
    let path = match &s.path {
        Some(p) => {
            let pixels = p.width as usize * p.height as usize;
            let halves = |field: &str, text: &str, format| {
                rgb_16_zlib(text, pixels, format).map_err(|m| malformed(field, m))
            };
            let std = halves("path.std_bf16le_zlib", &p.std_bf16le_zlib, Half::Brain)?;
            Some(PathImages {
                scene: scene.resized(p.width, p.height),
                mean: halves("path.mean_f16le_zlib", &p.mean_f16le_zlib, Half::Ieee)?,
                variance: std.iter().map(|s| s * s).collect(),
                offset_sensitivity: halves(
                    "path.offset_sensitivity_f16le_zlib",
                    &p.offset_sensitivity_f16le_zlib,
                    Half::Ieee,
                )?,
            })
        }
        None => None,
    };
    Ok(Decoded {
        scene,
        whitted,
        edges: edges.iter().map(|&b| b != 0).collect(),
        path,
    })
}

/// The sizes that decide what [`decode`] allocates, and the path's depths,
/// checked first: the field at fault and what is wrong with it.
fn check_sizes(s: &SceneRenders) -> Result<(), (&'static str, String)> {
    // The reference images are small (64 × 48, the path's 320 × 240);
    // anything beyond the tracer's own cap is a malformed file, refused
    // before any allocation.
    let side = 1..=tracer::scene::MAX_IMAGE_SIDE;
    if !side.contains(&s.width) || !side.contains(&s.height) {
        return Err((
            "width",
            format!(
                "image {} × {} outside 1..={} per side",
                s.width,
                s.height,
                tracer::scene::MAX_IMAGE_SIDE
            ),
        ));
    }
    if let Some(p) = &s.path {
        if !side.contains(&p.width) || !side.contains(&p.height) {
            return Err((
                "path.width",
                format!(
                    "image {} × {} outside 1..={} per side",
                    p.width,
                    p.height,
                    side.end()
                ),
            ));
        }
        if p.pixel_filter != PixelFilter::Box {
            return Err((
                "path.pixel_filter",
                format!(
                    "the path comparison is of box-filtered renders, not {}",
                    p.pixel_filter
                ),
            ));
        }
        if p.samples < 2 {
            return Err((
                "path.samples",
                format!("a variance needs at least 2 samples, got {}", p.samples),
            ));
        }
        // The translation of the depth, which the comparison under
        // Mitsuba's offset rule counts escapes by (`checks.rs`).
        if p.max_depth.checked_add(2) != Some(p.mitsuba_max_depth) {
            return Err((
                "path.mitsuba_max_depth",
                format!(
                    "Mitsuba counts the suite's {} bounces as {} path segments, not {}",
                    p.max_depth,
                    u64::from(p.max_depth) + 2,
                    p.mitsuba_max_depth
                ),
            ));
        }
    }
    Ok(())
}

/// A base64 image of `pixels` float32 little-endian RGB pixels, widened.
fn rgb_f32le(text: &str, pixels: usize) -> Result<Vec<f64>, String> {
    let bytes = base64_bytes(text)?;
    if bytes.len() != 12 * pixels {
        return Err(format!(
            "expected {} float32 RGB pixels ({} bytes), got {} bytes",
            pixels,
            12 * pixels,
            bytes.len()
        ));
    }
    Ok(bytes
        .chunks_exact(4)
        .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64)
        .collect())
}

/// Which 16-bit float.
#[derive(Clone, Copy, Debug)]
enum Half {
    /// IEEE 754 binary16.
    Ieee,
    /// bfloat16: the top 16 bits of a float32.
    Brain,
}

/// A base64 image of `pixels` 16-bit float little-endian RGB pixels, zlib
/// compressed, widened; inflated no further than the image's size.
fn rgb_16_zlib(text: &str, pixels: usize, format: Half) -> Result<Vec<f64>, String> {
    let compressed = base64_bytes(text)?;
    let expected = 6 * pixels;
    let bytes = miniz_oxide::inflate::decompress_to_vec_zlib_with_limit(&compressed, expected)
        .map_err(|e| format!("not a zlib stream of {expected} bytes: {e:?}"))?;
    if bytes.len() != expected {
        return Err(format!(
            "expected {pixels} float16 RGB pixels ({expected} bytes), got {} bytes",
            bytes.len()
        ));
    }
    Ok(bytes
        .chunks_exact(2)
        .map(|b| match format {
            Half::Ieee => half::f16::from_le_bytes([b[0], b[1]]).to_f64(),
            Half::Brain => half::bf16::from_le_bytes([b[0], b[1]]).to_f64(),
        })
        .collect())
}

/// Standard base64 (RFC 4648, with padding), as Python's `base64.b64encode`
/// writes it.
fn base64_bytes(text: &str) -> Result<Vec<u8>, String> {
    base64::engine::general_purpose::STANDARD
        .decode(text)
        .map_err(|e| format!("not base64: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_decodes_rfc4648_test_vectors() {
        // RFC 4648 §10.
        for (text, bytes) in [
            ("", ""),
            ("Zg==", "f"),
            ("Zm8=", "fo"),
            ("Zm9v", "foo"),
            ("Zm9vYg==", "foob"),
            ("Zm9vYmE=", "fooba"),
            ("Zm9vYmFy", "foobar"),
        ] {
            assert_eq!(base64_bytes(text).unwrap(), bytes.as_bytes(), "{text}");
        }
        assert!(base64_bytes("Zm9").is_err());
        assert!(base64_bytes("Zm9*").is_err());
    }

    #[test]
    fn an_image_of_the_wrong_size_is_refused() {
        // Two float32 pixels' worth of bytes for one pixel.
        let text = base64::engine::general_purpose::STANDARD.encode([0u8; 24]);
        let message = rgb_f32le(&text, 1).unwrap_err();
        assert!(message.contains("12 bytes"), "{message}");
        assert_eq!(rgb_f32le(&text, 2).unwrap().len(), 6);
    }

    /// IEEE float16 1.0 is 0x3C00, 0.5 0x3800, 65504 0x7BFF (IEEE 754 binary16).
    #[test]
    fn sixteen_bit_zlib_images_decode_and_refuse_the_wrong_size() {
        let halves: [u16; 6] = [0x3C00, 0x3800, 0x7BFF, 0x0000, 0x8000, 0x3C00];
        let raw: Vec<u8> = halves.iter().flat_map(|h| h.to_le_bytes()).collect();
        let text = base64::engine::general_purpose::STANDARD
            .encode(miniz_oxide::deflate::compress_to_vec_zlib(&raw, 9));
        assert_eq!(
            rgb_16_zlib(&text, 2, Half::Ieee).unwrap(),
            [1.0, 0.5, 65504.0, 0.0, -0.0, 1.0]
        );
        // bfloat16 1.0 is 0x3F80, 2^100 0x7180.
        let brain: Vec<u8> = [0x3F80u16, 0x7180, 0, 0x3F80, 0x3F80, 0x3F80]
            .iter()
            .flat_map(|h| h.to_le_bytes())
            .collect();
        let text_bf = base64::engine::general_purpose::STANDARD
            .encode(miniz_oxide::deflate::compress_to_vec_zlib(&brain, 9));
        assert_eq!(
            rgb_16_zlib(&text_bf, 2, Half::Brain).unwrap()[..2],
            [1.0, 2f64.powi(100)]
        );
        let message = rgb_16_zlib(&text, 1, Half::Ieee).unwrap_err();
        assert!(message.contains("6 bytes"), "{message}");
        assert!(rgb_16_zlib(&text, 3, Half::Ieee)
            .unwrap_err()
            .contains("18 bytes"));
    }
}
