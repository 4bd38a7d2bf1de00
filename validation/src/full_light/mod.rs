//! All the light: the share of radiance that the integrators miss where a
//! delta light (point, directional) reaches a diffuse surface through delta
//! surfaces (mirrors, conductors, smooth glass), measured against Mitsuba 3
//! (`python-checks/mitsuba_full_light.py`, reference
//! `mitsuba_full_light.json`).
//!
//! Four Mitsuba estimates per course scene, each `passes` independent
//! renders: `path` (its path tracer with the delta lights: what is missed),
//! `path_centres` (the same through the pixel centres, as the tracer
//! samples them; the others average over the pixel), `ptracer` (its light tracer: all the light, where the camera sees a
//! diffuse surface) and `area` (its path tracer with each delta light an
//! area light of equal power: all the light, converged to by sampled
//! bounces). Two regions: `diffuse` (the camera sees a diffuse surface) and
//! `surface` (any surface). Per pass the reference keeps each region's mean
//! radiance per channel, so a region's standard error is the spread of its
//! passes (Student t, `passes − 1` degrees of freedom), correlations
//! between pixels and channels included.
//!
//! The missing share of a region is `1 − path / full`, the radiance summed
//! over the channels, with its standard error by the delta method. The
//! checks:
//!
//! - [`check_independent`]: the light tracer and the area lights agree on
//!   the `diffuse` region (Welch's t on the passes).
//! - [`check_missing_share`]: the share per region; where the scene has no
//!   delta surface it must be zero within its noise.
//! - [`check_all_the_light`]: a tracer render (mean, variance, samples per
//!   pixel) of an integrator that claims all the light, against `area` and
//!   `ptracer`; [`check_same_missing_light`]: one that claims only what
//!   Mitsuba's `path` finds, against `path`. Both per channel and region.
//!
//! Radiance is in W/(sr·m²) per channel.

mod checks;
mod estimates;
mod measure;
mod reference;
mod statistics;
mod thresholds;
mod tracer_checks;

pub use checks::{
    box_filter_shift, check_all_the_light, check_all_the_light_in, check_independent,
    check_missing_share, check_same_missing_light, TracerRender,
};
pub use estimates::{Estimate, Region};
pub use measure::{missing_share, MissingShare, PASSES};
pub use reference::{
    decode, DecodedLight, EstimateRender, FullLight, RegionMask, SceneLight, FILE, SCHEMA,
};
pub use statistics::{share, RegionMean, Share};
pub use thresholds::{ALPHA, FINDING_RELATIVE, POWER, TOLERANCE_RELATIVE};
pub use tracer_checks::FullLightChecks;
