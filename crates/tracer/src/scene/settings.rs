//! Render settings: as given ([`RenderSpec`], from a scene file's `render`
//! or from a caller's overrides) and as settled ([`Settings`], validated
//! once, over the defaults). Nothing after [`Settings::settle`] re-checks or
//! re-maps a setting.

use radiometry::domain;
use serde::{Deserialize, Serialize};

use super::error::{ErrorKind, SceneError};
use super::values::{count, positive};
use crate::kinds::{
    FresnelModel, FresnelName, GlassShortcut, IntegratorKind, PixelFilter, Precision, RayOffset,
    MAX_DEPTH, MAX_PHOTONS, MAX_PHOTON_PASSES, MAX_SPP,
};

/// Render settings as given, all optional: a scene file's `render`, or a
/// caller's overrides. Counts are `f64` so that a bad value is reported
/// exactly as it was given.
#[derive(Clone, Copy, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RenderSpec {
    /// The integrator.
    pub integrator: Option<IntegratorKind>,
    /// Samples per pixel (path tracer), 1 to [`MAX_SPP`].
    pub spp: Option<f64>,
    /// Maximum number of bounces after the primary hit, 0 to [`MAX_DEPTH`].
    pub max_depth: Option<f64>,
    /// Fresnel model, as named: the bare `schlick` is refused when settled.
    pub fresnel: Option<FresnelName>,
    /// Throughput below which a path is cut (whitted) or rouletted (path).
    pub throughput_cutoff: Option<f64>,
    /// Seed of the path tracer's random numbers.
    pub seed: Option<u64>,
    /// How secondary rays leave a surface.
    pub ray_offset: Option<RayOffset>,
    /// Where primary rays pass through their pixel.
    pub pixel_filter: Option<PixelFilter>,
    /// Photons emitted per pass (`photon`), 1 to [`MAX_PHOTONS`].
    pub photons: Option<f64>,
    /// Photon passes (`photon`), 1 to [`MAX_PHOTON_PASSES`], with
    /// `photons × photon_passes` at most [`MAX_PHOTONS`].
    pub photon_passes: Option<f64>,
    /// The first pass's gather radius (`photon`), m, positive.
    pub photon_radius: Option<f64>,
    /// The precision tier (`f64` for `local` and `whitted` only).
    pub precision: Option<Precision>,
}

/// The caustic photon map's settings (the `photon` integrator).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PhotonSettings {
    /// Photons emitted per pass, over all lights.
    pub photons: u32,
    /// Passes, each with its own photons and its own, smaller, radius.
    pub passes: u32,
    /// The first pass's gather radius, m.
    #[serde(serialize_with = "as_written")]
    pub radius: f32,
}

impl Default for PhotonSettings {
    fn default() -> Self {
        PhotonSettings {
            photons: 100_000,
            passes: 16,
            radius: 0.05,
        }
    }
}

/// Settled render settings.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Settings {
    /// The light transport.
    pub integrator: IntegratorKind,
    /// Samples per pixel; only the path tracer is random, the others use 1.
    pub spp: u32,
    /// Bounces allowed after the primary hit (the course's `maxBounces`
    /// counts the primary hit too: its 12 is `max_depth` 11).
    pub max_depth: u32,
    /// Fresnel law of smooth materials.
    pub fresnel: FresnelModel,
    /// A branch whose throughput (largest channel) falls below this is cut
    /// (`whitted`) or continued with Russian roulette (`path`). 0 never cuts.
    #[serde(serialize_with = "as_written")]
    pub throughput_cutoff: f32,
    /// Seed of the path tracer.
    pub seed: u64,
    /// How secondary rays leave a surface.
    pub ray_offset: RayOffset,
    /// Where primary rays pass through their pixel. Decided here and
    /// nowhere else: as given, else [`PixelFilter::default_for`] the
    /// integrator given beside it (see [`Settings::settle`]).
    pub pixel_filter: PixelFilter,
    /// The caustic photon map (`photon` only).
    pub photon: PhotonSettings,
    /// The precision tier the tracer computes in; settled only where it
    /// serves the integrator ([`Precision::serves`]).
    pub precision: Precision,
    /// A slide's shortcut at glass, measured against the laws; never
    /// written out, as no input sets it.
    #[serde(skip)]
    pub glass_shortcut: GlassShortcut,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            integrator: IntegratorKind::Whitted,
            spp: 1,
            max_depth: 11,
            fresnel: FresnelModel::Exact,
            throughput_cutoff: 1e-3,
            seed: 0,
            ray_offset: RayOffset::Robust,
            pixel_filter: PixelFilter::default_for(IntegratorKind::Whitted),
            photon: PhotonSettings::default(),
            precision: Precision::F32,
            glass_shortcut: GlassShortcut::None,
        }
    }
}

impl Settings {
    /// These settings with `spec`'s given values over them, each checked
    /// against its domain and named `{path}.{field}` when refused.
    ///
    /// The pixel filter is the one place a default follows another
    /// setting: a `spec` that gives an integrator without a filter gets
    /// that integrator's [`PixelFilter::default_for`]; one that gives a
    /// filter gets it, whatever the integrator; one that gives neither
    /// keeps the filter settled before.
    pub fn settle(&self, path: &str, spec: &RenderSpec) -> Result<Settings, SceneError> {
        let field = |name: &str| format!("{path}.{name}");
        let mut settled = *self;
        if let Some(integrator) = spec.integrator {
            settled.integrator = integrator;
            settled.pixel_filter = PixelFilter::default_for(integrator);
        }
        if let Some(filter) = spec.pixel_filter {
            settled.pixel_filter = filter;
        }
        if let Some(spp) = spec.spp {
            settled.spp = count(&field("spp"), spp, 1, MAX_SPP)?;
        }
        if let Some(depth) = spec.max_depth {
            settled.max_depth = count(&field("max_depth"), depth, 0, MAX_DEPTH)?;
        }
        if let Some(fresnel) = spec.fresnel {
            settled.fresnel = fresnel
                .model()
                .ok_or_else(|| SceneError::new(field("fresnel"), ErrorKind::SchlickFormUnnamed))?;
        }
        if let Some(cutoff) = spec.throughput_cutoff {
            settled.throughput_cutoff =
                domain::fraction(&field("throughput_cutoff"), cutoff)? as f32;
        }
        if let Some(seed) = spec.seed {
            settled.seed = seed;
        }
        if let Some(offset) = spec.ray_offset {
            match offset {
                RayOffset::Robust => {}
                RayOffset::Fixed(eps) => {
                    positive(&field("ray_offset.fixed"), eps)?;
                }
                RayOffset::Scaled(eps) => {
                    positive(&field("ray_offset.scaled"), eps)?;
                }
            }
            settled.ray_offset = offset;
        }
        settled.photon = settled.photon.settle(path, spec)?;
        if let Some(precision) = spec.precision {
            settled.precision = precision;
        }
        if !settled.precision.serves(settled.integrator) {
            // Named by the precision where it was given here, else by the
            // integrator that no longer takes the precision settled before.
            let name = if spec.precision.is_some() {
                "precision"
            } else {
                "integrator"
            };
            let kind = ErrorKind::PrecisionNotServed {
                precision: settled.precision,
                integrator: settled.integrator,
            };
            return Err(SceneError::new(field(name), kind));
        }
        Ok(settled)
    }
}

impl PhotonSettings {
    /// These with `spec`'s photon fields over them; the product of photons
    /// and passes is refused under the name of the field given last.
    fn settle(&self, path: &str, spec: &RenderSpec) -> Result<PhotonSettings, SceneError> {
        let field = |name: &str| format!("{path}.{name}");
        let mut settled = *self;
        if let Some(photons) = spec.photons {
            settled.photons = count(&field("photons"), photons, 1, MAX_PHOTONS)?;
        }
        if let Some(passes) = spec.photon_passes {
            settled.passes = count(&field("photon_passes"), passes, 1, MAX_PHOTON_PASSES)?;
        }
        if let Some(radius) = spec.photon_radius {
            settled.radius = positive(&field("photon_radius"), radius)?;
        }
        if settled.photons as u64 * settled.passes as u64 > MAX_PHOTONS as u64 {
            // Named by the passes unless only the photons were given here.
            let (name, value, other) = match (spec.photons, spec.photon_passes) {
                (Some(_), None) => ("photons", settled.photons, settled.passes),
                _ => ("photon_passes", settled.passes, settled.photons),
            };
            count(&field(name), value.into(), 1, MAX_PHOTONS / other)?;
        }
        Ok(settled)
    }
}

/// An `f32` as the shortest decimal that reads back as it, `1e-3` for the
/// float nearest 0.001: what the scene file said, not its widening to
/// `f64` (`0.0010000000474974513`), once the number passes through JSON
/// values of `f64`.
fn as_written<S: serde::Serializer>(x: &f32, serializer: S) -> Result<S::Ok, S::Error> {
    let shortest: f64 = x.to_string().parse().map_err(serde::ser::Error::custom)?;
    serializer.serialize_f64(shortest)
}

#[cfg(test)]
mod tests {
    use super::Settings;

    /// The settled cutoff is reported as the scene wrote it, through
    /// `serde_json::Value` (whose numbers are `f64`) as `optics --json` does.
    #[test]
    fn the_cutoff_is_reported_as_written_not_widened() {
        let value = serde_json::to_value(Settings::default()).unwrap();
        assert_eq!(value["throughput_cutoff"], serde_json::json!(0.001));
    }
}
