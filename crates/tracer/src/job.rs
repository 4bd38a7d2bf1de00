//! The one way to render: a [`RenderJob`] is a validated scene with its
//! settings settled once, the scene's own under a caller's [`Overrides`],
//! checked against what the integrator can render, with the machinery the
//! scene needs; it renders and writes.
//!
//! Settings pass two stages, as a command line's raw flags become its
//! settled arguments: as given ([`RenderSpec`], from the file's `render` or
//! from the overrides, `f64` counts reported as written) and as settled
//! ([`Settings`]), each value checked in [`Settings::settle`], the only
//! place it is checked. Nothing after [`RenderJob::new`] re-checks or
//! re-maps a setting.

use std::path::Path;

use glam::DVec3;

use crate::integrator::{Machinery, Tracer};
use crate::needs::{self, Needs};
use crate::output::{Destination, OutputError};
use crate::render::{self, Rendered};
use crate::scene::values::image_size;
use crate::scene::{
    self, ErrorKind, IntegratorKind, Material, Precision, RenderSpec, Scene, SceneError, Settings,
};

/// Settings given beside a scene (a command line's flags, a test's case),
/// each over the scene's own. Refusals name them `overrides.<field>`
/// (`overrides.spp`, `overrides.width`).
#[derive(Clone, Copy, Debug, Default)]
pub struct Overrides {
    /// Render settings, as given.
    pub render: RenderSpec,
    /// Image width, pixels (the camera keeps its view).
    pub width: Option<u32>,
    /// Image height, pixels.
    pub height: Option<u32>,
    /// Render even past [`needs::MAX_RAYS`] (`--allow-expensive`).
    pub allow_expensive: bool,
}

/// A scene ready to render: settings settled, integrator checked, needs
/// analysed.
#[derive(Clone, Debug)]
pub struct RenderJob {
    scene: Scene,
    settings: Settings,
    needs: Needs,
    machinery: Machinery,
    rays: f64,
}

/// Why a render did not complete.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    /// The worker threads could not be started.
    #[error("cannot start the render's threads: {0}")]
    Threads(#[from] rayon::ThreadPoolBuildError),
    /// An image could not be written.
    #[error(transparent)]
    Output(#[from] OutputError),
    /// A pixel's radiance left `f32` (infinite, or NaN from infinities),
    /// though the scene's numbers are bounded (a path's gain beyond the
    /// bound of `scene::bound`); nothing is written.
    #[error(
        "the radiance at pixel ({x}, {y}) is not finite in f32: the paths' gain \
         exceeds f32 there; nothing was written"
    )]
    NotFinite {
        /// Column, from 0 at the left.
        x: u32,
        /// Row, from 0 at the top.
        y: u32,
    },
}

impl RenderJob {
    /// Reads the scene file at `path` and settles `overrides` over it.
    pub fn load(path: &Path, overrides: &Overrides) -> Result<Self, SceneError> {
        RenderJob::new(scene::load(path)?, overrides)
    }

    /// `scene` with `overrides` settled over its own settings.
    pub fn new(scene: Scene, overrides: &Overrides) -> Result<Self, SceneError> {
        let scene = match (overrides.width, overrides.height) {
            (None, None) => scene,
            (w, h) => {
                let (w, h) = (w.unwrap_or(scene.width), h.unwrap_or(scene.height));
                let (w, h) = image_size("overrides", w.into(), h.into())?;
                scene.resized(w, h)
            }
        };
        let settings = scene.settings.settle("overrides", &overrides.render)?;
        let job = RenderJob::with_settings(scene, settings)?;
        if job.rays > needs::MAX_RAYS && !overrides.allow_expensive {
            let rays = job.rays;
            return Err(SceneError::new(".", ErrorKind::TooExpensive { rays }));
        }
        Ok(job)
    }

    /// `scene` with settings already settled (a variation of a settled
    /// job's, or of [`Scene::settings`]), at whatever cost: a caller that
    /// chose the settings itself is not refused by [`RenderJob::rays`].
    pub fn with_settings(scene: Scene, settings: Settings) -> Result<Self, SceneError> {
        renderable(&scene, &settings)?;
        let needs = needs::analyse(&scene, &settings);
        let machinery = needs.machinery(&settings);
        let rays = needs.rays(&scene, &machinery, &settings);
        Ok(RenderJob {
            scene,
            settings,
            needs,
            machinery,
            rays,
        })
    }

    /// The scene, at the size it is rendered.
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// The settled settings.
    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// What the scene needs under these settings.
    pub fn needs(&self) -> &Needs {
        &self.needs
    }

    /// The machinery a render runs: only what the scene needs.
    pub fn machinery(&self) -> &Machinery {
        &self.machinery
    }

    /// The estimate, before rendering, of the rays the render casts at
    /// most ([`Needs::rays`]): past [`needs::WARN_RAYS`] a front end says
    /// so, past [`needs::MAX_RAYS`] [`RenderJob::new`] refuses unless
    /// allowed.
    pub fn rays(&self) -> f64 {
        self.rays
    }

    /// Everything switched on, the reference against which skipping is
    /// measured.
    pub fn everything(&self) -> Machinery {
        Machinery::everything(&self.scene, &self.settings)
    }

    /// Renders on `threads` threads (`None`: all cores); `progress` is
    /// called with the number of rows finished so far, from any thread.
    pub fn render(
        &self,
        threads: Option<usize>,
        progress: &(dyn Fn(usize) + Sync),
    ) -> Result<Rendered, RenderError> {
        self.render_with(&self.machinery, threads, progress)
    }

    /// Renders running `machinery` instead of what the scene needs (to
    /// measure what skipping saves; the image must not change).
    pub fn render_with(
        &self,
        machinery: &Machinery,
        threads: Option<usize>,
        progress: &(dyn Fn(usize) + Sync),
    ) -> Result<Rendered, RenderError> {
        let rendered = match self.settings.precision {
            Precision::F32 => {
                let tracer = Tracer::new(&self.scene, self.settings, machinery.clone());
                let (tracer, photon_time) = caustics(tracer, threads)?;
                let mut rendered = render::render(&tracer, threads, progress)?;
                if let Some(caustics) = &tracer.caustics {
                    rendered.rays.add(&caustics.rays);
                    rendered.elapsed += photon_time;
                }
                rendered
            }
            // Settled for local and whitted only, which build no maps.
            Precision::F64 => {
                let tracer = Tracer::<DVec3>::new(&self.scene, self.settings, machinery.clone());
                render::render(&tracer, threads, progress)?
            }
        };
        if let Some((x, y)) = rendered.image.first_not_finite() {
            return Err(RenderError::NotFinite { x, y });
        }
        Ok(rendered)
    }

    /// What the camera sees at each pixel, rows top to bottom: the index
    /// (into [`Scene::objects`]) of the object the primary ray through the
    /// pixel's centre meets first, by the physical integrators'
    /// intersection, or `None` where it escapes to the background.
    pub fn first_hits(&self) -> Vec<Option<u32>> {
        let tracer = Tracer::new(&self.scene, self.settings, self.machinery.clone());
        let (width, height) = (self.scene.width, self.scene.height);
        (0..height)
            .flat_map(|y| (0..width).map(move |x| (x, y)))
            .map(|(x, y)| {
                let ray = self.scene.camera.ray(x, y);
                tracer.intersect(&ray).map(|hit| hit.object)
            })
            .collect()
    }

    /// Renders and writes the PNG and the PFM of `destination`.
    pub fn render_to(
        &self,
        destination: &Destination,
        threads: Option<usize>,
        progress: &(dyn Fn(usize) + Sync),
    ) -> Result<Rendered, RenderError> {
        let rendered = self.render(threads, progress)?;
        destination.write(&rendered.image)?;
        Ok(rendered)
    }
}

/// `tracer` with its caustic maps built on `threads` threads, where its
/// integrator has them, and the time that took.
fn caustics(
    tracer: Tracer<'_>,
    threads: Option<usize>,
) -> Result<(Tracer<'_>, std::time::Duration), rayon::ThreadPoolBuildError> {
    let start = std::time::Instant::now();
    if tracer.settings.integrator != IntegratorKind::Photon {
        return Ok((tracer, start.elapsed()));
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads.unwrap_or(0))
        .build()?;
    let tracer = pool.install(|| tracer.with_caustics());
    Ok((tracer, start.elapsed()))
}

/// Refuses combinations an integrator cannot render: glass under the
/// course's shader, and a tier the integrator does not compute in (which
/// [`Settings::settle`] refuses too, for settings varied after it).
fn renderable(scene: &Scene, settings: &Settings) -> Result<(), SceneError> {
    if !settings.precision.serves(settings.integrator) {
        let kind = ErrorKind::PrecisionNotServed {
            precision: settings.precision,
            integrator: settings.integrator,
        };
        return Err(SceneError::new("render.precision", kind));
    }
    if settings.integrator == IntegratorKind::Course {
        if let Some((name, _)) = scene
            .material_names
            .iter()
            .zip(&scene.materials)
            .find(|(_, m)| matches!(m, Material::Dielectric { .. }))
        {
            return Err(SceneError::new(
                format!("materials.{name}"),
                ErrorKind::CourseHasNoRefraction,
            ));
        }
    }
    Ok(())
}
