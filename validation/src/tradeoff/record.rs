//! An `optics tradeoff` record as the report reads it: the fields it
//! shows and checks (the command writes more; unknown fields are ignored,
//! so a record stays readable as fields are added within a version).

use std::borrow::Cow;

use serde::{Deserialize, Serialize};
use serde_json::Value;
use tracer::scene::FresnelName;

use super::findings::{Findings, MetalRgb};
use super::mitsuba::MitsubaTruth;
use super::schema::{SCHEMA_VERSION, SCHLICK_UNNAMED_VERSION};
use super::sweep::SCHLICK_SWEPT;
use super::verdict::Verdict;

/// One scene's sweep.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Record {
    /// [`super::SCHEMA`].
    pub schema: String,
    /// [`super::SCHEMA_VERSION`] when written.
    pub version: u32,
    /// The scene file, relative to the checkout.
    pub scene: String,
    /// Whether the course's rough material was measured as Lambert.
    #[serde(default)]
    pub lambert: bool,
    /// Image width, pixels.
    pub width: u32,
    /// Image height, pixels.
    pub height: u32,
    /// The machine the times are of.
    pub machine: String,
    /// The day they were taken.
    pub date: String,
    /// The machine's load then.
    #[serde(default)]
    pub load: String,
    /// The command that wrote the record.
    pub command: String,
    /// The ground truth.
    pub truth: Truth,
    /// Every setting measured, the scene's own first.
    pub points: Vec<Point>,
    /// The colour error of three channels against a spectrum for each of
    /// the scene's metals, by the harness's code (`metals.*`).
    #[serde(default)]
    pub rgb_against_spectrum: Vec<MetalRgb>,
    /// What the numbers say of each shortcut ([`Findings::of`]), as the
    /// command wrote it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub findings: Option<Findings>,
    /// Every setting against Mitsuba's estimate of all the light, or why
    /// there is none (absent from records written before it was measured).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mitsuba: Option<MitsubaTruth>,
}

/// The ground truth a record measures against.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Truth {
    /// Its samples per pixel.
    pub spp: u32,
    /// Its own noise relative to the image (from its two halves).
    pub noise_relative: f64,
    /// The standard deviation of its light `Σ t` over the surface
    /// pixel-channels, relative: the floor under each share of the light.
    #[serde(default)]
    pub light_noise_relative: Option<f64>,
}

/// One setting, measured.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Point {
    /// What was varied.
    pub axis: String,
    /// The setting in words.
    pub label: String,
    /// The settings rendered (the fields the findings read).
    pub settings: Settings,
    /// The median render time, s.
    pub seconds_median: f64,
    /// Every timed render, s (absent from records written before they
    /// were kept): the spread around the median.
    #[serde(default)]
    pub seconds: Vec<f64>,
    /// Rays cast by one render.
    pub rays: f64,
    /// The fixed measures against the truth.
    pub errors: Errors,
    /// The same measures against the scene's own settings' render.
    pub against_scene: Errors,
    /// 1 / (relative variance × median seconds), Monte Carlo points only.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub efficiency: Option<f64>,
    /// The measures on whose Pareto front the point lies.
    pub pareto: Vec<String>,
    /// The verdict against the scene's own settings (none for them).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub verdict: Option<Verdict>,
    /// The measures over the grazing pixels alone, for the points of the
    /// Fresnel law.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub grazing: Option<Grazing>,
}

/// A point's settings, as far as the findings read them.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Settings {
    /// The integrator (`whitted`, `path`, ...).
    pub integrator: String,
    /// The bounce limit.
    pub max_depth: u32,
    /// The Fresnel law (`exact`, `schlick-incident`, `schlick-rarer`, `course`).
    pub fresnel: String,
}

/// The measures over the pixels whose centre first meets a mirror or
/// glass at a cosine below [`super::findings::GRAZING_COS`].
#[derive(Clone, Copy, Debug, Serialize, Deserialize)]
pub struct Grazing {
    /// How many pixels.
    pub pixels: usize,
    /// The measures against the truth over them.
    pub errors: Errors,
    /// The measures against the scene's own render over them.
    pub against_scene: Errors,
}

/// The fixed measures ([`super::MEASURES`]).
#[derive(Clone, Copy, Debug, Serialize, Deserialize)]
pub struct Errors {
    /// Relative RMSE of linear radiance.
    pub rel_rmse: f64,
    /// Mean ΔE2000 of the displayed image.
    pub delta_e_mean: f64,
    /// 99th percentile of ΔE2000.
    pub delta_e_p99: f64,
    /// Mean LDR ꟻLIP over the surface pixels.
    pub flip_mean: f64,
    /// The light carried as a share of the reference's, `Σ x / Σ t`
    /// (absent from records written before it was measured).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub light: Option<f64>,
    /// The standard error of `light` from the setting's own renders,
    /// where it was rendered with several seeds.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub light_noise: Option<f64>,
}

impl Errors {
    /// The measure named `name` (one of [`super::MEASURES`]); NaN for
    /// another name.
    pub fn get(&self, name: &str) -> f64 {
        match name {
            "rel_rmse" => self.rel_rmse,
            "delta_e_mean" => self.delta_e_mean,
            "delta_e_p99" => self.delta_e_p99,
            "flip_mean" => self.flip_mean,
            _ => f64::NAN,
        }
    }
}

impl Record {
    /// The file stem the command gives the record (`gold_spheres-lambert`).
    pub fn stem(&self) -> String {
        let name = std::path::Path::new(&self.scene)
            .file_stem()
            .map_or_else(|| self.scene.clone(), |s| s.to_string_lossy().into_owned());
        if self.lambert {
            format!("{name}-lambert")
        } else {
            name
        }
    }
}

/// The record `text` as this version reads it: a record of
/// [`SCHLICK_UNNAMED_VERSION`] has its every `schlick` (the `fresnel`
/// setting) and `fresnel schlick` (a label) renamed for the form they
/// meant, Schlick's rarer-medium ([`SCHLICK_SWEPT`]), and is read as
/// [`SCHEMA_VERSION`]; any other text is read as it is. Mapped, not
/// rewritten: the committed records are measurements, and the names are
/// all that changed.
pub fn upgrade(text: &str) -> Cow<'_, str> {
    let Ok(mut value) = serde_json::from_str::<Value>(text) else {
        return Cow::Borrowed(text);
    };
    if value["version"] != SCHLICK_UNNAMED_VERSION {
        return Cow::Borrowed(text);
    }
    let (old, new) = (FresnelName::UNNAMED_SCHLICK, SCHLICK_SWEPT.to_string());
    let (old_label, new_label) = (format!("fresnel {old}"), format!("fresnel {new}"));
    rename(&mut value, &|s| {
        if s == old {
            Some(new.clone())
        } else if s == old_label {
            Some(new_label.clone())
        } else {
            None
        }
    });
    value["version"] = SCHEMA_VERSION.into();
    Cow::Owned(value.to_string())
}

/// Every string in `value` that `new` maps, replaced.
fn rename(value: &mut Value, new: &dyn Fn(&str) -> Option<String>) {
    match value {
        Value::String(s) => {
            if let Some(renamed) = new(s) {
                *s = renamed;
            }
        }
        Value::Array(items) => items.iter_mut().for_each(|v| rename(v, new)),
        Value::Object(map) => map.values_mut().for_each(|v| rename(v, new)),
        _ => {}
    }
}
