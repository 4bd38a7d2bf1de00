//! What every mode of a sweep settles before it renders: the scene at its
//! size, the surface pixels, the sweep's points, the plan's key, and where
//! the results go.

use std::path::{Path, PathBuf};

use tracer::integrator::Tracer;
use tracer::job::{Overrides, RenderJob};

use super::request::SweepRequest;
use crate::tradeoff::error::TradeoffError;
use crate::tradeoff::findings::GRAZING_COS;
use crate::tradeoff::jobs::{self, Input, JobError};
use crate::tradeoff::measure::Mask;
use crate::tradeoff::{sweep, truth};

/// The scene as the sweep and the budget measure it: with `lambert`, its
/// course_rough materials made the suite's Lambert stand-in.
pub fn measured_scene(scene: tracer::scene::Scene, lambert: bool) -> tracer::scene::Scene {
    if lambert {
        scene.course_rough_as_lambert()
    } else {
        scene
    }
}

/// What every mode knows before it renders: the scene, settled at its
/// size, the surface pixels, the sweep's points and the plan's key.
pub struct Setup {
    /// The scene with the size given, at its own settings.
    pub job: RenderJob,
    /// The course material's diffuse albedo where above 1, and its name.
    pub gain: Option<(f32, String)>,
    /// The files' stem (`shadow-lambert`).
    pub stem: String,
    /// Where the results go.
    pub files: Files,
    /// The surface pixels.
    pub mask: Mask,
    /// The grazing pixels: those whose centre first meets a mirror or
    /// glass at a cosine below [`GRAZING_COS`].
    pub grazing: Mask,
    /// The sweep's points.
    pub plan: sweep::Plan,
    /// What the plan is made of.
    pub key: jobs::PlanKey,
}

impl Setup {
    /// Loads the scene `args` names and plans its sweep.
    pub fn new(args: &SweepRequest) -> Result<Self, TradeoffError> {
        let overrides = Overrides {
            width: args.width,
            height: args.height,
            allow_expensive: true,
            ..Overrides::default()
        };
        let scene_error = |error| TradeoffError::Scene {
            file: args.scene.clone(),
            error,
        };
        let scene = measured_scene(
            tracer::scene::load(&args.scene).map_err(scene_error)?,
            args.lambert,
        );
        let gain = scene.diffuse_gain().map(|(g, name)| (g, name.to_owned()));
        let job = RenderJob::new(scene, &overrides).map_err(scene_error)?;
        let stem = args
            .scene
            .file_stem()
            .map_or_else(|| "scene".to_owned(), |s| s.to_string_lossy().into_owned());
        let stem = if args.lambert {
            format!("{stem}-lambert")
        } else {
            stem
        };
        let bytes = std::fs::read(&args.scene).unwrap_or_default();
        let key = jobs::PlanKey {
            scene: args.scene.display().to_string(),
            scene_fnv1a: jobs::scene_fnv1a(&bytes),
            lambert: args.lambert,
            width: job.scene().width,
            height: job.scene().height,
            spp: args.spp,
            truth_spp: args.truth_spp,
            repeats: args.repeats,
            min_seconds: args.min_seconds,
        };
        Ok(Setup {
            files: Files::new(&args.out, &stem),
            mask: Mask::from_hits(&job.first_hits()),
            grazing: grazing(&job),
            plan: sweep::plan(&job, args.spp),
            gain,
            stem,
            job,
            key,
        })
    }

    /// The truth's cache as `args` asks for it.
    pub fn truth_request<'a>(
        &'a self,
        args: &'a SweepRequest,
        dir: &'a Path,
    ) -> truth::Request<'a> {
        truth::Request {
            scene_file: &args.scene,
            spp: args.truth_spp,
            lambert: args.lambert,
            dir,
            fresh: args.fresh,
        }
    }
}

/// The pixels whose centre's ray first meets a mirror or glass at a
/// cosine below [`GRAZING_COS`] to its shading normal: where Schlick's
/// law is read apart. One intersection a pixel, as the surface mask.
fn grazing(job: &RenderJob) -> Mask {
    let scene = job.scene();
    let tracer = Tracer::new(scene, *job.settings(), job.machinery().clone());
    let hits: Vec<Option<u32>> = (0..scene.height)
        .flat_map(|y| (0..scene.width).map(move |x| (x, y)))
        .map(|(x, y)| {
            let ray = scene.camera.ray(x, y);
            let hit = tracer.intersect(&ray)?;
            let specular = scene.materials[hit.material as usize].is_specular();
            let cos = f64::from(hit.shading.dot(ray.direction).abs());
            (specular && cos < GRAZING_COS).then_some(hit.object)
        })
        .collect();
    Mask::from_hits(&hits)
}

/// Where a sweep writes.
#[derive(Debug)]
pub struct Files {
    /// The directory of all three, and of the truth's cache.
    dir: PathBuf,
    /// The record, `STEM.json`.
    pub json: PathBuf,
    /// The table, `STEM.md`.
    pub markdown: PathBuf,
    /// The Pareto plot, `STEM-pareto.png`.
    pub plot: PathBuf,
}

impl Files {
    /// The files of stem `stem` in `dir`.
    pub fn new(dir: &Path, stem: &str) -> Self {
        Files {
            dir: dir.to_owned(),
            json: dir.join(format!("{stem}.json")),
            markdown: dir.join(format!("{stem}.md")),
            plot: dir.join(format!("{stem}-pareto.png")),
        }
    }

    /// The truth's cache.
    pub fn truth_dir(&self) -> PathBuf {
        self.dir.join("truth")
    }

    /// Creates the directories and checks the files as `render` checks
    /// its own, before any render is spent: none may be the `scene` being
    /// read (the output directory the scene's own would write the record
    /// over it) or anything a rename must not replace.
    pub fn prepare(&self, scene: &Path) -> Result<(), TradeoffError> {
        let create = |dir: &Path| {
            std::fs::create_dir_all(dir).map_err(|source| {
                TradeoffError::Output(
                    safe_io::WriteError::Io {
                        path: dir.display().to_string(),
                        source,
                    }
                    .into(),
                )
            })
        };
        create(&self.dir)?;
        for file in [&self.json, &self.markdown, &self.plot] {
            safe_io::check_destination(file, &[scene]).map_err(|error| {
                TradeoffError::Jobs(JobError::Write {
                    input: Input::Out,
                    error: error.into(),
                })
            })?;
        }
        create(&self.truth_dir())?;
        Ok(())
    }
}
