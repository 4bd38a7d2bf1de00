//! The schema of `mitsuba_full_light.json` and its decoding: the measured
//! scene, each region's mask, and each estimate's per-pass region means,
//! every size checked before it is used.

use std::collections::BTreeMap;
use std::path::Path;

use base64::Engine as _;
use serde::Deserialize;
use tracer::scene::Scene;

use super::estimates::{Estimate, Region};
use crate::reference::ReferenceError;
use crate::renders::Tool;

/// The reference file.
pub const FILE: &str = "mitsuba_full_light.json";
/// Its schema.
pub const SCHEMA: &str = "mitsuba-full-light/1";

/// `mitsuba_full_light.json`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FullLight {
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
    /// Independent passes per estimate.
    pub passes: u32,
    /// Samples per pixel of each pass.
    pub spp: u32,
    /// Samples per pixel of each pass of `path_centres`.
    pub centre_spp: u32,
    /// Bounces after the primary hit, the suite's count.
    pub max_depth: u32,
    /// The area lights' angular radius, radians.
    pub angular_radius: f64,
    /// Course scenes not measured, and why.
    pub excluded: BTreeMap<String, String>,
    /// The scenes measured.
    pub scenes: Vec<SceneLight>,
}

/// One scene's three estimates.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneLight {
    /// The scene's name (its file stem).
    pub name: String,
    /// The course scene it was made from, relative to the repository root.
    pub scene_file: String,
    /// The scene as measured (course_rough as Lambert, black background).
    pub scene_text: String,
    /// Image width, pixels.
    pub width: u32,
    /// Image height, pixels.
    pub height: u32,
    /// The area lights that replace the delta lights in `area`.
    pub area_lights: Vec<serde_json::Value>,
    /// Each region's mask.
    pub regions: BTreeMap<String, RegionMask>,
    /// Mitsuba's `path` with the delta lights.
    pub path: EstimateRender,
    /// Mitsuba's light tracer.
    pub ptracer: EstimateRender,
    /// Mitsuba's `path` with area lights of equal power.
    pub area: EstimateRender,
    /// Mitsuba's `path` with the delta lights, through the pixel centres.
    pub path_centres: EstimateRender,
}

/// A region of the image.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RegionMask {
    /// How many pixels it has.
    pub pixels: u32,
    /// One byte per pixel (1: in the region), base64.
    pub mask_u8: String,
}

/// One estimate's renders.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EstimateRender {
    /// Per-pixel mean over the passes, float32 RGB, base64.
    pub mean_f32le: String,
    /// Per region, per pass, the region's mean radiance per channel (empty
    /// where the region has no pixel).
    pub passes_region_mean: BTreeMap<String, Vec<Vec<f64>>>,
}

impl FullLight {
    /// Reads [`FILE`] from `dir`.
    pub fn load(dir: &Path) -> Result<Self, ReferenceError> {
        crate::reference::load(dir, FILE, SCHEMA)
    }
}

/// One scene decoded.
#[derive(Clone, Debug)]
pub struct DecodedLight {
    /// The scene as Mitsuba measured it, at the reference's size.
    pub scene: Scene,
    /// Per region, its mask (`width · height`).
    pub masks: BTreeMap<Region, Vec<bool>>,
    /// Per estimate and region, per pass, the region's mean per channel;
    /// absent where the region is empty.
    pub passes: BTreeMap<(Estimate, Region), Vec<[f64; 3]>>,
}

/// Decodes one scene of the reference; errors name the field.
pub fn decode(file: &Path, index: usize, s: &SceneLight) -> Result<DecodedLight, ReferenceError> {
    let malformed = |field: String, message: String| ReferenceError::Malformed {
        path: file.to_owned(),
        field: format!("scenes[{index}].{field}"),
        message,
    };
    let scene = tracer::scene::parse(&s.scene_text)
        .map_err(|e| malformed("scene_text".into(), e.to_string()))?;
    if (scene.width, scene.height) != (s.width, s.height) {
        return Err(malformed(
            "width".into(),
            format!(
                "{} × {} against the scene's {} × {}",
                s.width, s.height, scene.width, scene.height
            ),
        ));
    }
    let pixels = s.width as usize * s.height as usize;
    let mut masks = BTreeMap::new();
    for region in Region::ALL {
        let field = format!("regions.{}", region.name());
        let entry = s
            .regions
            .get(region.name())
            .ok_or_else(|| malformed(field.clone(), "missing".into()))?;
        let mask = base64::engine::general_purpose::STANDARD
            .decode(&entry.mask_u8)
            .map_err(|e| malformed(format!("{field}.mask_u8"), format!("not base64: {e}")))?;
        let inside = mask.iter().filter(|&&b| b != 0).count();
        if mask.len() != pixels || inside != entry.pixels as usize {
            return Err(malformed(
                format!("{field}.mask_u8"),
                format!(
                    "{} bytes with {inside} set, expected {pixels} with {}",
                    mask.len(),
                    entry.pixels
                ),
            ));
        }
        masks.insert(region, mask.iter().map(|&b| b != 0).collect());
    }
    let mut passes = BTreeMap::new();
    for estimate in Estimate::ALL {
        let render = match estimate {
            Estimate::Path => &s.path,
            Estimate::Ptracer => &s.ptracer,
            Estimate::Area => &s.area,
            Estimate::PathCentres => &s.path_centres,
        };
        for region in Region::ALL {
            let field = format!("{}.passes_region_mean.{}", estimate.name(), region.name());
            let rows = render
                .passes_region_mean
                .get(region.name())
                .ok_or_else(|| malformed(field.clone(), "missing".into()))?;
            if let Some(rows) = region_passes(rows).map_err(|m| malformed(field, m))? {
                passes.insert((estimate, region), rows);
            }
        }
    }
    Ok(DecodedLight {
        scene,
        masks,
        passes,
    })
}

/// The passes of one region: `None` when every pass is empty (no pixel),
/// else at least two passes of three finite channels each.
fn region_passes(rows: &[Vec<f64>]) -> Result<Option<Vec<[f64; 3]>>, String> {
    if rows.iter().all(Vec::is_empty) {
        return Ok(None);
    }
    if rows.len() < 2 {
        return Err(format!(
            "a variance needs at least 2 passes, got {}",
            rows.len()
        ));
    }
    rows.iter()
        .enumerate()
        .map(|(k, row)| match row.as_slice() {
            [r, g, b] if row.iter().all(|v| v.is_finite()) => Ok([*r, *g, *b]),
            _ => Err(format!(
                "pass {k}: expected three finite channels, got {row:?}"
            )),
        })
        .collect::<Result<Vec<_>, _>>()
        .map(Some)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_region_with_one_pass_or_a_missing_channel_is_refused() {
        assert_eq!(region_passes(&[vec![], vec![]]).unwrap(), None);
        assert!(region_passes(&[vec![1.0, 2.0, 3.0]]).is_err());
        let short = region_passes(&[vec![1.0, 2.0, 3.0], vec![1.0, 2.0]]).unwrap_err();
        assert!(short.contains("pass 1"), "{short}");
        assert!(region_passes(&[vec![1.0, 2.0, f64::NAN], vec![1.0, 2.0, 3.0]]).is_err());
        assert_eq!(
            region_passes(&[vec![1.0, 2.0, 3.0], vec![4.0, 5.0, 6.0]]).unwrap(),
            Some(vec![[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]])
        );
    }
}
