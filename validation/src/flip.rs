//! ꟻLIP, the rendering field's measure of how different two images look
//! (Andersson et al., "FLIP: A Difference Evaluator for Alternating
//! Images", 2020), in its LDR form: per pixel, a value in [0, 1] from
//! colour differences filtered by the eye's contrast sensitivity at a
//! viewing distance, and edges and points that appear or vanish.
//!
//! The suite's ꟻLIP is the `nv-flip` crate's binding of an older copy of
//! NVIDIA's C++; [`check_against_nvidia`] holds it against NVIDIA's own
//! evaluator (`flip-evaluator` on PyPI, `validation/reference/flip.json`
//! from `python-checks/flip_reference.py`) on image pairs of known
//! character. Both sides use [`PIXELS_PER_DEGREE`], stated, not defaulted.

use serde::Deserialize;

use crate::check::Check;
use crate::reference::ReferenceError;

/// The reference file in the reference directory.
pub const FILE: &str = "flip.json";
/// Its schema.
pub const SCHEMA: &str = "flip/1";

/// Pixels per degree of visual angle: ꟻLIP's observer, 0.7 m from a 0.7 m
/// wide monitor of 3840 pixels (67.02, rounded as both tools' defaults are).
pub const PIXELS_PER_DEGREE: f32 = 67.0;

/// An implementation of the LDR ꟻLIP error map: `(reference, test, width,
/// height)`, both 8-bit sRGB row-major RGB of `3 · width · height` bytes, to
/// one value in [0, 1] per pixel. A parameter, so that a broken one can be
/// shown to be caught.
pub type ErrorMap = fn(&[u8], &[u8], u32, u32) -> Vec<f32>;

/// The suite's ꟻLIP error map of `test` against `reference` (see
/// [`ErrorMap`] for the layout).
///
/// # Panics
///
/// If either image is not `3 · width · height` bytes.
pub fn error_map(reference: &[u8], test: &[u8], width: u32, height: u32) -> Vec<f32> {
    let bytes = 3 * width as usize * height as usize;
    assert_eq!(
        reference.len(),
        bytes,
        "the reference is not {width} × {height} RGB"
    );
    assert_eq!(
        test.len(),
        bytes,
        "the test image is not {width} × {height} RGB"
    );
    let reference = nv_flip::FlipImageRgb8::with_data(width, height, reference);
    let test = nv_flip::FlipImageRgb8::with_data(width, height, test);
    nv_flip::flip(reference, test, PIXELS_PER_DEGREE).to_vec()
}

/// The colour of ꟻLIP value `value` (clamped into [0, 1]) on the magma
/// scale ꟻLIP's authors draw error maps with (`nv_flip::magma_lut`, 256
/// entries), as linear RGB for an image that is sRGB-encoded when written.
pub fn magma(value: f32) -> glam::Vec3 {
    static LUT: std::sync::OnceLock<Vec<u8>> = std::sync::OnceLock::new();
    let lut = LUT.get_or_init(|| nv_flip::magma_lut().to_vec());
    let entries = lut.len() / 3;
    let t = if value.is_nan() {
        0.0
    } else {
        value.clamp(0.0, 1.0)
    };
    let i = 3 * ((t * (entries - 1) as f32).round() as usize);
    let linear = |byte: u8| radiometry::colour::srgb_decode(f64::from(byte) / 255.0) as f32;
    glam::Vec3::new(linear(lut[i]), linear(lut[i + 1]), linear(lut[i + 2]))
}

/// The mean of an error map over the pixels `keep` says (all where `None`);
/// 0 for none. ꟻLIP's authors name the mean as its one-number summary.
pub fn mean(map: &[f32], keep: Option<&[bool]>) -> f64 {
    let (sum, count) = map
        .iter()
        .enumerate()
        .filter(|&(i, _)| keep.is_none_or(|k| k[i]))
        .fold((0.0, 0usize), |(s, n), (_, &v)| (s + f64::from(v), n + 1));
    if count == 0 {
        0.0
    } else {
        sum / count as f64
    }
}

/// NVIDIA's evaluator on the pairs of `python-checks/flip_reference.py`.
#[derive(Clone, Debug, Deserialize)]
pub struct FlipReference {
    /// flip-evaluator's version.
    pub flip_evaluator_version: String,
    /// Its `ppd` parameter.
    pub pixels_per_degree: f32,
    /// Every image's width, pixels.
    pub width: u32,
    /// Every image's height, pixels.
    pub height: u32,
    /// The pairs.
    pub pairs: Vec<FlipPair>,
}

/// One pair and NVIDIA's summary of its error map.
#[derive(Clone, Debug, Deserialize)]
pub struct FlipPair {
    /// What the pair differs by.
    pub name: String,
    /// The reference image, 8-bit sRGB RGB row-major, base64.
    pub reference_rgb8_base64: String,
    /// The test image, the same way.
    pub test_rgb8_base64: String,
    /// The error map's mean.
    pub mean: f64,
    /// Its maximum.
    pub max: f64,
}

impl FlipReference {
    /// Loads the reference from `dir`.
    pub fn load(dir: &std::path::Path) -> Result<Self, ReferenceError> {
        crate::reference::load(dir, FILE, SCHEMA)
    }
}

/// How far the suite's mean ꟻLIP may lie from NVIDIA's, absolute: three
/// times the largest difference measured on the reference pairs, 3.3e-6
/// (red against orange, where every pixel's value is 0.609502 and
/// NVIDIA's single-precision sum of them reads 0.6094987).
pub const MEAN_ABS: f64 = 1e-5;

/// The same for the error map's maximum: the reference keeps seven
/// digits, and the largest difference measured is 4.9e-8.
pub const MAX_ABS: f64 = 1e-6;

/// `flip` against NVIDIA's evaluator on every reference pair: the mean and
/// maximum of the error map within [`MEAN_ABS`] and [`MAX_ABS`].
pub fn check_against_nvidia(flip: ErrorMap, reference: &FlipReference) -> Check {
    use base64::Engine as _;
    let mut check = Check::new(
        "images.flip.nvidia",
        [
            "LDR ꟻLIP error maps (nv-flip) of image pairs of known character",
            "Ismert jellegű képpárok LDR ꟻLIP-hibatérképei (nv-flip)",
        ],
        [
            &format!(
                "NVIDIA's flip-evaluator {} at {} pixels per degree",
                reference.flip_evaluator_version, reference.pixels_per_degree
            ),
            &format!(
                "az NVIDIA flip-evaluator {} programja, fokonként {} képponttal",
                reference.flip_evaluator_version, reference.pixels_per_degree
            ),
        ],
        [&format!("mean within {MEAN_ABS:e}, maximum within {MAX_ABS:e} (NVIDIA sums the mean in single precision; the reference keeps seven digits)"), &format!("átlag legfeljebb {MEAN_ABS:e}, a legnagyobb legfeljebb {MAX_ABS:e} eltéréssel (az NVIDIA egyszeres pontossággal összegzi az átlagot; a referencia hét jegyet őriz)")],
    );
    if reference.pixels_per_degree != PIXELS_PER_DEGREE {
        check.fail(format!(
            "the reference was evaluated at {} pixels per degree, the suite at {PIXELS_PER_DEGREE}",
            reference.pixels_per_degree
        ));
    }
    let decode = |text: &str| base64::engine::general_purpose::STANDARD.decode(text).ok();
    let bytes = 3 * reference.width as usize * reference.height as usize;
    for pair in &reference.pairs {
        check.cases += 1;
        let (Some(a), Some(b)) = (
            decode(&pair.reference_rgb8_base64),
            decode(&pair.test_rgb8_base64),
        ) else {
            check.fail(format!("{}: an image is not base64", pair.name));
            continue;
        };
        if a.len() != bytes || b.len() != bytes {
            check.fail(format!(
                "{}: an image is not {} × {} RGB",
                pair.name, reference.width, reference.height
            ));
            continue;
        }
        let map = flip(&a, &b, reference.width, reference.height);
        let ours_mean = mean(&map, None);
        let ours_max = map.iter().copied().fold(0.0_f32, f32::max);
        let mean_off = (ours_mean - pair.mean).abs();
        let max_off = (f64::from(ours_max) - pair.max).abs();
        check.measure_in_both(
            ["mean: |ours − NVIDIA|", "átlag: |miénk − NVIDIA|"],
            mean_off,
            &pair.name,
        );
        check.measure_in_both(
            ["maximum: |ours − NVIDIA|", "legnagyobb: |miénk − NVIDIA|"],
            max_off,
            &pair.name,
        );
        if !(mean_off <= MEAN_ABS) || map.iter().any(|v| !(0.0..=1.0).contains(v)) {
            check.fail(format!(
                "{}: mean {ours_mean:.6} against NVIDIA's {:.6}",
                pair.name, pair.mean
            ));
        }
        if !(max_off <= MAX_ABS) {
            check.fail(format!(
                "{}: maximum {ours_max:.6} against NVIDIA's {:.6}",
                pair.name, pair.max
            ));
        }
    }
    check
}

#[cfg(test)]
mod tests {
    use super::*;

    fn committed() -> FlipReference {
        FlipReference::load(&crate::reference::committed_dir()).unwrap()
    }

    #[test]
    fn the_suites_flip_agrees_with_nvidias_evaluator() {
        let check = check_against_nvidia(error_map, &committed());
        assert!(check.passed(), "{check:#?}");
        assert_eq!(check.cases, 8);
    }

    /// A ꟻLIP that forgets the eye's filtering (the plain colour difference
    /// of each pixel, scaled to [0, 1]) is caught.
    #[test]
    fn a_flip_without_the_contrast_filter_is_caught() {
        fn unfiltered(a: &[u8], b: &[u8], _: u32, _: u32) -> Vec<f32> {
            a.chunks(3)
                .zip(b.chunks(3))
                .map(|(p, q)| {
                    let d: f32 = p
                        .iter()
                        .zip(q)
                        .map(|(&x, &y)| (f32::from(x) - f32::from(y)).powi(2))
                        .sum();
                    (d.sqrt() / (255.0 * 3f32.sqrt())).min(1.0)
                })
                .collect()
        }
        let check = check_against_nvidia(unfiltered, &committed());
        assert!(!check.passed());
    }

    #[test]
    fn identical_images_do_not_differ_and_the_mean_keeps_the_mask() {
        let image = vec![90u8; 3 * 4 * 3];
        assert!(error_map(&image, &image, 4, 3).iter().all(|&v| v == 0.0));
        let map = [0.5, 0.1, 0.9];
        assert!((mean(&map, Some(&[true, false, true])) - 0.7).abs() < 1e-7);
        assert_eq!(mean(&map, Some(&[false; 3])), 0.0);
    }
}
