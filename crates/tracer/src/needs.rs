//! What a scene needs: which effects can occur in it, so the renderer runs
//! only that machinery (`optics inspect` reports it, and measures what the
//! rest would have cost).
//!
//! Each rule switches a part off only where the laws say it cannot change
//! the image, and the test `skipping_unused_machinery_leaves_the_image_unchanged`
//! renders every course scene both ways and requires identical pixels. One
//! rule also removes rounding artefacts: a light outside the closed mirror
//! tube around the camera lights nothing, but with it on, a shadow ray that
//! starts within rounding of where a sphere or the far wall meets a mirror
//! can slip out (1 pixel of 76 800 in the course kaleidoscope, path traced
//! at 320 × 240 with 16 samples); skipping the light leaves that pixel dark,
//! as the law has it.

use serde::Serialize;

use crate::geometry::{Object, Tube};
use crate::integrator::Machinery;
use crate::scene::{IntegratorKind, Light, Material, PixelFilter, Scene, Settings};
use crate::trap::Trap;

pub use crate::kinds::{MAX_RAYS, WARN_RAYS};

/// How deep specular recursion can go in a scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ReflectionDepth {
    /// No mirror or glass is visible to the integrator.
    None,
    /// One bounce at most: a single convex mirror cannot see itself.
    One,
    /// Bounded only by `max_depth`: mirrors that see each other or
    /// themselves (the tube), or glass (light bounces inside it).
    UpToMaxDepth(u32),
}

/// One light and whether it matters.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LightUse {
    /// Its index in `lights`.
    pub index: usize,
    /// What kind of light it is.
    pub kind: LightKind,
    /// Whether it can light anything.
    pub used: bool,
    /// Why not, when it is not.
    pub reason: Option<Unused>,
}

/// The kinds of light a scene can hold.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LightKind {
    /// A directional light (parallel rays, irradiance).
    Directional,
    /// A point light (radiant intensity).
    Point,
}

/// Why a light can light nothing in a scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Unused {
    /// Its power is zero in every channel.
    EmitsNothing,
    /// No surface is shaded from lights (only mirrors, glass, flat colours).
    NothingShaded,
    /// A closed mirror tube around the camera keeps its light out.
    OutsideClosedTube,
}

impl std::fmt::Display for LightKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            LightKind::Directional => "directional",
            LightKind::Point => "point",
        })
    }
}

impl std::fmt::Display for Unused {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Unused::EmitsNothing => "it emits nothing",
            Unused::NothingShaded => "no surface is shaded from lights",
            Unused::OutsideClosedTube => {
                "the closed mirror tube around the camera keeps its light out"
            }
        })
    }
}

/// The effects a scene needs under given settings.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Needs {
    /// How deep reflections and refractions can go.
    pub reflection_depth: ReflectionDepth,
    /// Whether a dielectric refracts.
    pub refraction: bool,
    /// Whether a conductor's complex-index Fresnel is evaluated.
    pub conductors: bool,
    /// Whether surfaces are shaded from lights.
    pub rough_surfaces: bool,
    /// Whether an object can block a light (else no shadow ray is needed).
    pub shadows: bool,
    /// Each light.
    pub lights: Vec<LightUse>,
    /// Whether the path tracer's paths are all deterministic, so one sample
    /// per pixel is the converged image.
    pub deterministic: bool,
    /// The mirror tube that holds the rays moving away from everything
    /// else, whose camera paths end there (`path` and `photon` only).
    pub trap: Option<Trap>,
}

/// Analyses `scene` for `settings`.
pub fn analyse(scene: &Scene, settings: &Settings) -> Needs {
    let material = |o: &Object| scene.materials[o.material() as usize];
    let rough = scene.objects.iter().any(|o| material(o).is_rough());
    let specular: Vec<&Object> = scene
        .objects
        .iter()
        .filter(|o| material(o).is_specular())
        .collect();
    let refraction = specular
        .iter()
        .any(|o| matches!(material(o), Material::Dielectric { .. }));
    let conductors = specular
        .iter()
        .any(|o| matches!(material(o), Material::Conductor { .. }));
    let recursive = matches!(
        settings.integrator,
        IntegratorKind::Whitted
            | IntegratorKind::Path
            | IntegratorKind::Photon
            | IntegratorKind::Course
    );
    let reflection_depth = if !recursive || specular.is_empty() || settings.max_depth == 0 {
        ReflectionDepth::None
    } else if specular.len() == 1 && specular[0].is_convex() && !refraction {
        ReflectionDepth::One
    } else {
        ReflectionDepth::UpToMaxDepth(settings.max_depth)
    };
    let lights = light_uses(scene, rough);
    let lit = lights.iter().any(|l| l.used);
    // A single convex object cannot block the light to its own lit side:
    // cos θ > 0 there, and the segment towards the light leaves it.
    let shadows = lit && (scene.objects.len() > 1 || scene.objects.iter().any(|o| !o.is_convex()));
    // The path tracer draws random numbers only at rough surfaces (when it
    // may bounce on) and at glass; the photon integrator's photons and the
    // pass a camera path looks up are random wherever a surface is rough.
    let random_at_rough = rough
        && match settings.integrator {
            IntegratorKind::Path => settings.max_depth > 0,
            IntegratorKind::Photon => true,
            _ => false,
        };
    let deterministic = !(refraction || random_at_rough);
    let trap = match settings.integrator {
        IntegratorKind::Path | IntegratorKind::Photon => Trap::of(scene),
        _ => None,
    };
    Needs {
        reflection_depth,
        refraction,
        conductors,
        rough_surfaces: rough,
        shadows,
        lights,
        deterministic,
        trap,
    }
}

/// What each of `scene`'s lights delivers, and why it is left out where
/// it delivers nothing (`rough`: whether any surface is shaded from lights).
fn light_uses(scene: &Scene, rough: bool) -> Vec<LightUse> {
    let enclosing = enclosing_tube(scene);
    scene
        .lights
        .iter()
        .enumerate()
        .map(|(index, light)| {
            let (kind, power) = match *light {
                Light::Directional { irradiance, .. } => (LightKind::Directional, irradiance),
                Light::Point { intensity, .. } => (LightKind::Point, intensity),
            };
            let reason = if power.max_element() <= 0.0 {
                Some(Unused::EmitsNothing)
            } else if !rough {
                Some(Unused::NothingShaded)
            } else if enclosing.is_some_and(|tube| !reaches_inside(tube, light)) {
                Some(Unused::OutsideClosedTube)
            } else {
                None
            };
            LightUse {
                index,
                kind,
                used: reason.is_none(),
                reason,
            }
        })
        .collect()
}

/// A mirror tube that contains every primary ray's origin. Infinite along
/// its axis and closed around it, it keeps every ray that starts inside
/// inside: the camera sees only what is in the tube, and light from outside
/// reaches none of it (the course's "everything is always in shadow").
fn enclosing_tube(scene: &Scene) -> Option<&Tube> {
    let (w, h) = (scene.width - 1, scene.height - 1);
    let origins = [(0, 0), (w, 0), (0, h), (w, h), (w / 2, h / 2)]
        .map(|(x, y)| scene.camera.ray(x, y).origin);
    scene.objects.iter().find_map(|o| match o {
        // Strictly inside every side, by more than the rounding of the
        // origins: a camera on a mirror is not enclosed.
        Object::Tube(tube)
            if origins.iter().all(|p| {
                tube.faces
                    .iter()
                    .all(|f| (*p - f.point).dot(f.normal) < -1e-4 * (1.0 + p.abs().max_element()))
            }) =>
        {
            Some(tube)
        }
        _ => None,
    })
}

/// Whether a light can shine into a tube: a point light inside it, or a
/// directional light along its axis (a ray parallel to the sides never
/// meets them).
fn reaches_inside(tube: &Tube, light: &Light) -> bool {
    match *light {
        Light::Point { position, .. } => tube
            .faces
            .iter()
            .all(|f| (position - f.point).dot(f.normal) < 0.0),
        Light::Directional { towards, .. } => towards.cross(tube.axis).length() == 0.0,
    }
}

impl Needs {
    /// The machinery to run.
    pub fn machinery(&self, settings: &Settings) -> Machinery {
        Machinery {
            shadow_rays: self.shadows,
            lights: self.lights.iter().map(|l| l.used).collect(),
            // A box filter's rays vary within the pixel whatever the
            // integrator; through the centre, only a sampling integrator's
            // vary, and not when every path is deterministic.
            spp: if settings.pixel_filter == PixelFilter::Box
                || (settings.integrator.samples() && !self.deterministic)
            {
                settings.spp
            } else {
                1
            },
            trap: self.trap.clone(),
        }
    }
}

impl Needs {
    /// An upper estimate of the rays a render casts, before it starts, from
    /// the branching the scene allows (and the photon pass's rays): a primary ray per sample, each
    /// followed to the reachable depth `D` (the reflection depth, or under
    /// the path tracer `max_depth` where rough surfaces bounce light; one
    /// branch per bounce, or at
    /// glass under Whitted two, so up to `2^k` at depth `k`, capped by the
    /// throughput cutoff at `g / cutoff` branches, `g` the largest radiance
    /// gain `η²` a crossing gives), and each ray that ends at a rough
    /// surface followed by a shadow ray per used light.
    pub fn rays(&self, scene: &Scene, machinery: &Machinery, settings: &Settings) -> f64 {
        let depth = match self.reflection_depth {
            // The path tracer bounces off rough surfaces too.
            _ if settings.integrator.samples() && self.rough_surfaces => settings.max_depth,
            ReflectionDepth::None => 0,
            ReflectionDepth::One => 1,
            ReflectionDepth::UpToMaxDepth(d) => d,
        };
        let lights = machinery.lights.iter().filter(|on| **on).count();
        let shadow = if machinery.shadow_rays { lights } else { 0 } as f64;
        let per_sample = match settings.integrator {
            IntegratorKind::Local => 1.0 + shadow,
            IntegratorKind::Course => 1.0 + depth as f64,
            IntegratorKind::Path | IntegratorKind::Photon => (1.0 + depth as f64) * (1.0 + shadow),
            IntegratorKind::Whitted => {
                let branches = if self.refraction {
                    whitted_branches(depth, scene, settings.throughput_cutoff)
                } else {
                    depth as f64
                };
                (1.0 + branches) * (1.0 + shadow)
            }
        };
        let pixels = scene.width as f64 * scene.height as f64;
        (pixels * machinery.spp as f64 * per_sample + photon_rays(settings)).min(f64::MAX)
    }
}

/// The photon pass's rays at most: each photon an escape test (directional
/// lights) and up to `max_depth + 2` segments (`max_depth + 1` smooth
/// bounces, then the rough surface it lands on).
fn photon_rays(settings: &Settings) -> f64 {
    if settings.integrator != IntegratorKind::Photon {
        return 0.0;
    }
    let photon = settings.photon;
    photon.photons as f64 * photon.passes as f64 * (settings.max_depth as f64 + 3.0)
}

/// `Σ_{k=1..depth} min(2^k, cap)`: the rays a primary ray's tree through
/// glass can hold, `cap` the branches a cutoff lets live at one depth.
fn whitted_branches(depth: u32, scene: &Scene, cutoff: f32) -> f64 {
    let gain = scene
        .materials
        .iter()
        .filter_map(|m| match *m {
            Material::Dielectric { eta } => {
                let e2 = (eta as f64).powi(2);
                Some(e2.max(1.0 / e2))
            }
            _ => None,
        })
        .fold(1.0, f64::max);
    let cap = if cutoff > 0.0 {
        gain / cutoff as f64
    } else {
        f64::INFINITY
    };
    (1..=depth).map(|k| 2f64.powi(k as i32).min(cap)).sum()
}
