//! The render settings' vocabulary: which integrator, which Fresnel law,
//! which glass shortcut, which pixel filter, how secondary rays are
//! offset, which precision tier, and the limits of the counts. The
//! ground floor of the crate: it imports nothing of the tracer, and the
//! scene, the settings, the sampling and the integrators all name these.

use std::fmt;

use serde::{Deserialize, Serialize};

mod fresnel;

pub use fresnel::{FresnelModel, FresnelName};

/// The most samples per pixel accepted: 2^20. Beyond this the `f32` image
/// cannot resolve the difference a further sample makes.
pub const MAX_SPP: u32 = 1 << 20;

/// The deepest recursion accepted. The course's shaders use 12 and 64.
pub const MAX_DEPTH: u32 = 1024;

/// The most photons a render emits, over all its passes: 2^22. Each lands
/// at most once, so the maps hold at most this many (44 bytes each, 185
/// MB, twice that while a pass's grid is sorted), and the photon pass
/// casts at most this many times `max_depth + 3` rays
/// (`needs::Needs::rays`).
pub const MAX_PHOTONS: u32 = 1 << 22;

/// The most photon passes, each with its own map and radius: 2^16.
pub const MAX_PHOTON_PASSES: u32 = 1 << 16;

/// The light transport algorithm: the speed/accuracy ladder of `003`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "snake_case")]
pub enum IntegratorKind {
    /// Direct light only; mirrors and glass show the background.
    Local,
    /// Recursive specular reflection and refraction, shadow rays.
    Whitted,
    /// Monte Carlo global illumination.
    Path,
    /// The path tracer plus a caustic photon map: also the delta lights'
    /// light through mirrors and glass onto rough surfaces.
    Photon,
    /// What the course's final GLSL shader computes, bugs included.
    Course,
}

impl IntegratorKind {
    /// Whether it samples (takes `spp` random paths per pixel).
    pub fn samples(self) -> bool {
        matches!(self, IntegratorKind::Path | IntegratorKind::Photon)
    }
}

impl fmt::Display for IntegratorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            IntegratorKind::Local => "local",
            IntegratorKind::Whitted => "whitted",
            IntegratorKind::Path => "path",
            IntegratorKind::Photon => "photon",
            IntegratorKind::Course => "course",
        })
    }
}

/// A slide's rasteriser-side shortcut in place of a law at glass, for
/// measuring it against the traced truth (none by default). Set only by a
/// caller that measures it (the harness's technique checks), never read
/// from a scene file or a flag, so no input reaches it.
///
/// Either applies only where Snell's law transmits: total internal
/// reflection stays the law's decision, made once by
/// [`radiometry::specular::incidence`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum GlassShortcut {
    /// The laws alone.
    #[default]
    None,
    /// `001`'s cheap refraction, `t = normalize(−c n + i)`
    /// ([`radiometry::course::refract_001_approx`]), in place of Snell's
    /// direction, from either side, with `c` from the index along the path
    /// the law resolved ([`techniques::refraction::Constant::value`]).
    CheapRefraction(techniques::refraction::Constant),
    /// `001`'s empirical Fresnel form, clamped
    /// ([`techniques::empirical_fresnel::reflectance`]), in place of the
    /// chosen law's reflectance where light arrives from outside the glass
    /// (the one surface a rasteriser shades; inside, the chosen law): the
    /// form fitted to the scene's glass by its caller.
    EmpiricalFresnel(radiometry::course::EmpiricalFresnel<f64>),
}

/// Where in a pixel its primary rays pass: the pixel filter.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "snake_case")]
pub enum PixelFilter {
    /// A box over the pixel: each sample's ray through a point uniform over
    /// the pixel, the pixel's samples stratified (`crate::filter`), the
    /// pixel the samples' unweighted mean. Mitsuba's `box` filter of
    /// radius ½ pixel. The `path` integrator's default.
    #[cfg_attr(
        feature = "clap",
        value(help = "Stratified rays over the pixel, averaged (path's default)")
    )]
    Box,
    /// Every ray through the pixel's centre, as the course's fragment
    /// shaders cast them (`gl_FragCoord`): no anti-aliasing. The default of
    /// `local`, `whitted` and `course`, which compare pixel centres.
    #[cfg_attr(
        feature = "clap",
        value(
            help = "Rays through the pixel centre, as the course's shaders (the others' default)"
        )
    )]
    Center,
}

impl PixelFilter {
    /// The filter an integrator renders with when none is given: `box` for
    /// the Monte Carlo `path` and `photon`, `center` for the deterministic
    /// ones.
    pub fn default_for(integrator: IntegratorKind) -> Self {
        if integrator.samples() {
            PixelFilter::Box
        } else {
            PixelFilter::Center
        }
    }
}

impl fmt::Display for PixelFilter {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            PixelFilter::Box => "box",
            PixelFilter::Center => "center",
        })
    }
}

/// How a secondary ray's origin is moved off the surface it leaves.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum RayOffset {
    /// Along the normal by the bound on the hit point's rounding error.
    Robust,
    /// Along the normal by a fixed distance in metres (the course: 0.001).
    Fixed(f64),
    /// Along the normal by `ε (1 + max |p_i|)` m, a relative epsilon that
    /// grows with the hit point's coordinates: Mitsuba 3's rule, with its
    /// `RayEpsilon` ε = 1500 · 2⁻²⁴ ≈ 8.94e-5 in `float32`.
    Scaled(f64),
}

/// The precision tier a render computes in: a render setting
/// (`render.precision`, `--precision`), `f32` by default.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize, Serialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Precision {
    /// Single precision, `glam::Vec3`: the course's shaders' and every
    /// integrator's.
    #[serde(rename = "f32")]
    #[cfg_attr(
        feature = "clap",
        value(name = "f32", help = "Single precision (every integrator)")
    )]
    #[default]
    F32,
    /// Double precision, `glam::DVec3`: `local` and `whitted` only.
    #[serde(rename = "f64")]
    #[cfg_attr(
        feature = "clap",
        value(name = "f64", help = "Double precision (local and whitted only)")
    )]
    F64,
}

impl Precision {
    /// Whether `integrator` computes at this tier: every one in `f32`;
    /// in `f64` the deterministic `local` and `whitted`, whose steps are
    /// written over [`radiometry::Vector3`] (`path`, `photon` and the
    /// course's shader stay `f32`).
    pub fn serves(self, integrator: IntegratorKind) -> bool {
        match self {
            Precision::F32 => true,
            Precision::F64 => matches!(integrator, IntegratorKind::Local | IntegratorKind::Whitted),
        }
    }
}

impl fmt::Display for Precision {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Precision::F32 => "f32",
            Precision::F64 => "f64",
        })
    }
}

/// The only schema version this crate reads.
pub const SCHEMA_VERSION: u32 = 1;

/// The largest image side accepted, in pixels. 16384 is the largest texture
/// side common GPUs allow and four times a 4K display; a larger image is
/// almost certainly a typo, and 16384² RGB floats are already 3 GiB.
pub const MAX_IMAGE_SIDE: u32 = 16_384;

/// The most pixels accepted: 8192², a 64-megapixel image (768 MiB of
/// `f32` radiance).
pub const MAX_PIXELS: u64 = 8192 * 8192;

/// The most rays a render may cast without the caller allowing more
/// (`Overrides::allow_expensive`): 10¹², hours at the tracer's
/// 10⁷–10⁸ rays per second.
pub const MAX_RAYS: f64 = 1e12;

/// Past this many rays a render is announced as long before it starts:
/// 10¹⁰, minutes.
pub const WARN_RAYS: f64 = 1e10;
