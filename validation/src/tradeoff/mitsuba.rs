//! Mitsuba's renders as a second truth: each setting of a sweep held
//! against Mitsuba 3's estimate of all the light
//! (`mitsuba_full_light.json`, [`crate::full_light`]) where the sweep's
//! scene is the one Mitsuba measured and the sweep's size maps onto the
//! reference's exactly.
//!
//! **The size.** The reference is box-filtered at `w × h`; a sweep at
//! `k w × k h` maps onto it by the mean of each `k × k` block
//! ([`box_downsample`]). That mean *is* the box-filtered pixel at `w × h`,
//! exactly: a box-filtered pixel is the mean radiance over its footprint,
//! the camera maps the image plane to pixels linearly at any size
//! (`tracer::camera::Camera::ndc`), so the block's `k²` footprints tile the
//! reference pixel's in equal areas, and the mean of means over equal areas
//! is the mean over their union.
//!
//! **The region.** The harness's `diffuse` region ([`Region::Diffuse`]):
//! the pixels whose centre and eight neighbours' centres see a diffuse
//! surface at `w × h`. There Mitsuba's light tracer (`ptracer`) is all the
//! light with the delta lights as they are, while its area-light estimate
//! moves the light by its stand-in spheres and disks; over the `surface`
//! region no estimate holds all the light (the pixels that see a mirror or
//! glass hold the delta lights' own images, which no path tracer draws).
//!
//! **The measures**, per setting, over the region's pixel-channels at
//! `w × h`: the light share `Σx / ΣM` with its standard error from
//! Mitsuba's passes ([`light_share`]), and the relative RMSE
//! `√(Σ (x − M)² / Σ M²)` ([`relative_rmse`]), each render's own squared
//! error averaged over the setting's renders as the sweep's measure does.
//! Mitsuba's per-pixel noise is not in the reference, so nothing is
//! subtracted; instead the sweep's own truth is measured against `M` alike,
//! and that is the floor under every setting's numbers. The ranking of
//! the settings by relative RMSE against the sweep's truth and against
//! Mitsuba's, on the same pixels, is compared pair by pair ([`Ranking`]).

use std::path::Path;

use base64::Engine as _;
use glam::DVec3;
use tracer::render::Image;
use tracer::scene::{Material, Scene};

use crate::full_light::{decode, Estimate, FullLight, Region, RegionMean};

mod record;
pub use record::{hold, Against, AgainstMitsuba, MitsubaTruth, Ranking, SecondTruth};

/// Mitsuba's estimate of all the light the sweep is held against.
pub const ESTIMATE: Estimate = Estimate::Ptracer;

/// The region it is held against on.
pub const REGION: Region = Region::Diffuse;

/// Why a sweep has no Mitsuba reference.
#[derive(Clone, Debug, PartialEq)]
pub enum NoReference {
    /// The reference could not be read.
    Unreadable(String),
    /// The reference leaves this course scene out, for this reason.
    Excluded {
        /// The scene's name.
        scene: String,
        /// The reference's reason.
        why: String,
    },
    /// The reference has no scene of this name.
    NotMeasured {
        /// The scene's name.
        scene: String,
    },
    /// The sweep's size is no whole multiple of the reference's.
    SizeDoesNotMap {
        /// The sweep's width, pixels.
        width: u32,
        /// The sweep's height, pixels.
        height: u32,
        /// The reference's width and height, pixels.
        reference: (u32, u32),
    },
    /// The scene still has the course's rough material, which Mitsuba
    /// measured as Lambert.
    NotLambert,
    /// The sweep's scene differs from the one Mitsuba measured.
    SceneDiffers {
        /// The first part that differs (`camera`, `background`, ...).
        part: &'static str,
        /// Where that is the background: ours and Mitsuba's.
        backgrounds: Option<([f32; 3], [f32; 3])>,
    },
    /// The camera sees no diffuse surface where the light tracer applies.
    NoRegion,
}

impl std::fmt::Display for NoReference {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            NoReference::Unreadable(detail) => write!(f, "{} unreadable: {detail}", crate::full_light::FILE),
            NoReference::Excluded { scene, why } => write!(f, "{} leaves {scene} out: {why}", crate::full_light::FILE),
            NoReference::NotMeasured { scene } => write!(f, "{} has no scene {scene}", crate::full_light::FILE),
            NoReference::SizeDoesNotMap { width, height, reference: (w, h) } => write!(
                f,
                "{width}×{height} is no whole multiple k·{w} × k·{h} of the reference's size"
            ),
            NoReference::NotLambert => write!(
                f,
                "Mitsuba measured course_rough as Lambert, and the scene's course_rough is not \
                 the Lambert stand-in"
            ),
            NoReference::SceneDiffers {
                backgrounds: Some((ours, theirs)),
                ..
            } => write!(
                f,
                "the scene is not the one Mitsuba measured: its background {ours:?} lights it, \
                 where Mitsuba's was {theirs:?}"
            ),
            NoReference::SceneDiffers { part, .. } => write!(
                f,
                "the scene is not the one Mitsuba measured: its {part} differ"
            ),
            NoReference::NoRegion => write!(
                f,
                "the camera sees no diffuse surface, where Mitsuba's light tracer holds all the light"
            ),
        }
    }
}

/// The reference of one scene, decoded for the measures.
#[derive(Clone, Debug)]
pub struct Reference {
    /// The scene's name.
    pub scene: String,
    /// The reference's size, pixels.
    pub width: u32,
    /// The reference's size, pixels.
    pub height: u32,
    /// The sweep's pixels per reference pixel, per side.
    pub factor: u32,
    /// The region, at the reference's size.
    pub mask: Vec<bool>,
    /// Per pass, the region's mean of the channels' sum.
    pub passes: Vec<f64>,
    /// The estimate's per-pixel mean over the passes.
    pub mean: Vec<DVec3>,
    /// Samples per pixel of each pass.
    pub spp: u32,
    /// Mitsuba's bounce limit.
    pub max_depth: u32,
}

/// The reference for a sweep of `scene` (named `name`, its file's stem),
/// or why there is none.
pub fn reference_for(
    scene: &Scene,
    name: &str,
    full: &FullLight,
    file: &Path,
) -> Result<Reference, NoReference> {
    if let Some(why) = full.excluded.get(name) {
        return Err(NoReference::Excluded {
            scene: name.to_owned(),
            why: why.clone(),
        });
    }
    let Some((index, s)) = full.scenes.iter().enumerate().find(|(_, s)| s.name == name) else {
        return Err(NoReference::NotMeasured {
            scene: name.to_owned(),
        });
    };
    let factor = scene.width / s.width;
    if factor == 0 || scene.width != factor * s.width || scene.height != factor * s.height {
        return Err(NoReference::SizeDoesNotMap {
            width: scene.width,
            height: scene.height,
            reference: (s.width, s.height),
        });
    }
    let decoded = decode(file, index, s).map_err(|e| NoReference::Unreadable(e.to_string()))?;
    if scene
        .materials
        .iter()
        .any(|m| matches!(m, Material::CourseRough { .. }))
    {
        return Err(NoReference::NotLambert);
    }
    let ours = scene.resized(s.width, s.height);
    if let Some(part) = difference(&ours, &decoded.scene) {
        let backgrounds = (part == "background").then(|| {
            (
                ours.background.to_array(),
                decoded.scene.background.to_array(),
            )
        });
        return Err(NoReference::SceneDiffers { part, backgrounds });
    }
    let Some(passes) = decoded.passes.get(&(ESTIMATE, REGION)) else {
        return Err(NoReference::NoRegion);
    };
    let mean = pixels_f32le(&s.ptracer.mean_f32le, s.width as usize * s.height as usize)
        .map_err(|m| NoReference::Unreadable(format!("scenes[{index}].ptracer.mean_f32le: {m}")))?;
    Ok(Reference {
        scene: s.name.clone(),
        width: s.width,
        height: s.height,
        factor,
        mask: decoded.masks[&REGION].clone(),
        passes: passes.iter().map(|p| p.iter().sum()).collect(),
        mean,
        spp: full.spp,
        max_depth: full.max_depth,
    })
}

/// The first part in which `ours` (at the reference's size) differs from
/// the scene Mitsuba measured; the render settings are the sweep's to vary
/// and are not compared.
fn difference(ours: &Scene, theirs: &Scene) -> Option<&'static str> {
    let parts = [
        ("camera", ours.camera == theirs.camera),
        ("background", ours.background == theirs.background),
        (
            "environment",
            ours.environment.is_none() && theirs.environment.is_none(),
        ),
        ("ambient", ours.ambient == theirs.ambient),
        (
            "materials",
            ours.materials == theirs.materials && ours.material_names == theirs.material_names,
        ),
        ("objects", ours.objects == theirs.objects),
        (
            "bump maps",
            ours.bumps.iter().chain(&theirs.bumps).all(Option::is_none),
        ),
        ("lights", ours.lights == theirs.lights),
    ];
    parts.iter().find(|(_, same)| !same).map(|(part, _)| *part)
}

/// Pixels of three little-endian `f32`, base64, `count` of them.
fn pixels_f32le(text: &str, count: usize) -> Result<Vec<DVec3>, String> {
    let bytes = base64::engine::general_purpose::STANDARD
        .decode(text)
        .map_err(|e| format!("not base64: {e}"))?;
    if bytes.len() != 12 * count {
        return Err(format!("{} bytes, expected {}", bytes.len(), 12 * count));
    }
    let values: Vec<f64> = bytes
        .chunks_exact(4)
        .map(|b| f64::from(f32::from_le_bytes([b[0], b[1], b[2], b[3]])))
        .collect();
    if let Some(k) = values.iter().position(|v| !v.is_finite()) {
        return Err(format!("value {k} is not finite"));
    }
    Ok(values
        .chunks_exact(3)
        .map(|c| DVec3::new(c[0], c[1], c[2]))
        .collect())
}

/// The mean of each `factor × factor` block of `image`, row by row: the
/// box-filtered image at `1/factor` of the size (see the module's doc).
///
/// # Panics
///
/// If `factor` is 0 or does not divide the image's sides: the sweep
/// settles the factor once, from the sizes, in [`reference_for`].
pub fn box_downsample(image: &Image, factor: u32) -> Vec<DVec3> {
    assert!(
        factor > 0 && image.width.is_multiple_of(factor) && image.height.is_multiple_of(factor),
        "{factor} divides {}×{}",
        image.width,
        image.height
    );
    let (w, h) = (image.width / factor, image.height / factor);
    let area = f64::from(factor * factor);
    (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| {
            let block = (0..factor).flat_map(|j| (0..factor).map(move |i| (i, j)));
            block
                .map(|(i, j)| image.get(factor * x + i, factor * y + j).as_dvec3())
                .sum::<DVec3>()
                / area
        })
        .collect()
}

/// The light share `Σx / ΣM`: `ours` is the region's mean of the channels'
/// sum in the image measured, `passes` Mitsuba's per pass (at least two).
/// The standard error is Mitsuba's alone, from the spread of its passes
/// ([`RegionMean::from_passes`]): `(Σx / ΣM) · se(M) / M`.
pub fn light_share(ours: f64, passes: &[f64]) -> (f64, f64) {
    let theirs = RegionMean::from_passes(passes.iter().copied());
    let light = ours / theirs.0.mean;
    (light, light.abs() * theirs.standard_error() / theirs.0.mean)
}

/// The region's mean of the channels' sum.
pub fn region_light(image: &[DVec3], mask: &[bool]) -> f64 {
    let (sum, n) = image
        .iter()
        .zip(mask)
        .filter(|(_, &inside)| inside)
        .fold((0.0, 0usize), |(s, n), (p, _)| (s + p.element_sum(), n + 1));
    sum / n.max(1) as f64
}

/// `√(mean over images of Σ (x − M)² / Σ M²)` over the region's
/// pixel-channels.
pub fn relative_rmse(images: &[Vec<DVec3>], reference: &[DVec3], mask: &[bool]) -> f64 {
    let inside = || (0..mask.len()).filter(|&p| mask[p]);
    let energy: f64 = inside().map(|p| reference[p].length_squared()).sum();
    let squared: f64 = images
        .iter()
        .map(|x| {
            inside()
                .map(|p| (x[p] - reference[p]).length_squared())
                .sum::<f64>()
        })
        .sum::<f64>()
        / images.len().max(1) as f64;
    (squared / energy.max(f64::MIN_POSITIVE)).sqrt()
}

/// One setting's renders (each already at the reference's size) against
/// the reference and the sweep's truth (at the reference's size too).
pub fn against(
    label: &str,
    images: &[Vec<DVec3>],
    truth: &[DVec3],
    reference: &Reference,
) -> Against {
    let mask = &reference.mask;
    let shares: Vec<(f64, f64)> = images
        .iter()
        .map(|x| light_share(region_light(x, mask), &reference.passes))
        .collect();
    let n = shares.len().max(1) as f64;
    Against {
        label: label.to_owned(),
        light: shares.iter().map(|s| s.0).sum::<f64>() / n,
        light_se: shares.iter().map(|s| s.1).sum::<f64>() / n,
        rel_rmse: relative_rmse(images, &reference.mean, mask),
        rel_rmse_truth: relative_rmse(images, truth, mask),
    }
}

/// The whole record: the floor and every setting, in order.
pub fn measure(reference: &Reference, truth: &[DVec3], points: Vec<Against>) -> AgainstMitsuba {
    AgainstMitsuba {
        scene: reference.scene.clone(),
        estimate: ESTIMATE.name().to_owned(),
        region: REGION.name().to_owned(),
        width: reference.width,
        height: reference.height,
        factor: reference.factor,
        pixels: reference.mask.iter().filter(|&&m| m).count() as u32,
        passes: reference.passes.len() as u32,
        spp: reference.spp,
        max_depth: reference.max_depth,
        floor: against("truth", &[truth.to_vec()], truth, reference),
        ranking: Ranking::of(&points),
        points,
    }
}

#[cfg(test)]
mod tests;
