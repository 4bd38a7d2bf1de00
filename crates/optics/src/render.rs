//! `optics render`: a scene file to a PNG for people and a PFM for
//! comparison, with a one-line summary of what it cost.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};

use serde::Serialize;
use tracer::integrator::Machinery;
use tracer::job::{Overrides, RenderJob};
use tracer::needs::{Needs, WARN_RAYS};
use tracer::output::Destination;
use tracer::render::Rendered;
use tracer::scene::{FresnelName, IntegratorKind, PixelFilter, Precision, RenderSpec, Settings};
use tracer::scene::{MAX_DEPTH, MAX_PHOTONS, MAX_PHOTON_PASSES, MAX_SPP};

use crate::error::{self, ErrorKind};
use crate::image_size::ImageSize;
use crate::lang::needs;
use crate::ui::Ui;
use record::{say, Lang};
use record::{Answer, Record};

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:
  optics render crates/tracer/scenes/kaleidoscope.json -o kaleidoscope.png
  optics render crates/tracer/scenes/gold_spheres.json -o gold.png --integrator course
  optics --json render scene.json -o out.png --integrator path --spp 64 --seed 7 --threads 2
  optics render crates/tracer/scenes/glass_spheres.json -o caustics.png --integrator photon --spp 64
  optics render crates/tracer/scenes/kaleidoscope_lit.json -o k.png --tolerance 0.05 --metric rel_rmse --verify

Writes the PNG (sRGB, radiance clamped to [0, 1]: see docs/scene-schema.md)
and, beside it, the linear radiance as a PFM with the same name.")]
#[derive(Serialize)]
pub struct RenderArgs {
    /// The scene file (JSON, see docs/scene-schema.md).
    pub scene: PathBuf,
    /// The PNG to write; the PFM goes beside it with the extension .pfm.
    #[arg(short, long)]
    pub output: PathBuf,
    #[command(flatten)]
    #[serde(flatten)]
    pub job: JobArgs,
    /// Worker threads (default: all cores). The image does not depend on it.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub threads: Option<u32>,
    /// The accuracy budget: `--tolerance`, `--metric`, `--verify`.
    #[cfg(feature = "harness")]
    #[command(flatten)]
    #[serde(flatten)]
    pub budget: crate::budget::BudgetArgs,
}

/// The settings `render` and `inspect` take over the scene's own; as
/// JSON, those given.
#[derive(clap::Args, Clone, Debug, Serialize)]
pub struct JobArgs {
    /// Light transport (default: the scene's).
    #[arg(long, value_enum)]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub integrator: Option<IntegratorKind>,
    /// Samples per pixel (the path tracer's; the others are deterministic).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=MAX_SPP as i64))]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spp: Option<u32>,
    /// Bounces allowed after the primary hit.
    #[arg(long, value_parser = clap::value_parser!(u32).range(0..=MAX_DEPTH as i64))]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_depth: Option<u32>,
    /// Fresnel law of mirrors and glass (the bare `schlick` is refused:
    /// name the form).
    #[arg(long, value_enum)]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fresnel: Option<FresnelName>,
    /// Where primary rays pass through their pixel (default: the scene's,
    /// else box for path and center for the others).
    #[arg(long, value_enum)]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pixel_filter: Option<PixelFilter>,
    /// Seed of the path tracer's random numbers.
    #[arg(long)]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// The precision tier the tracer computes in (default: the scene's,
    /// else f32); f64 for local and whitted only.
    #[arg(long, value_enum)]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub precision: Option<Precision>,
    /// Photons per pass of the photon integrator's caustic map.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=MAX_PHOTONS as i64))]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub photons: Option<u32>,
    /// Passes of the caustic map, each with its own photons and a smaller
    /// radius (photons × passes at most 2^22).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=MAX_PHOTON_PASSES as i64))]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub photon_passes: Option<u32>,
    /// The caustic map's gather radius in the first pass, m.
    #[arg(long)]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub photon_radius: Option<f64>,
    /// The image's size, where it overrides the scene's.
    #[command(flatten)]
    #[serde(flatten)]
    pub size: ImageSize,
    /// Render even when the estimate of the rays cast is past 10¹² (hours);
    /// past 10¹⁰ the estimate is shown before the render starts.
    #[arg(long)]
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub allow_expensive: bool,
}

impl JobArgs {
    /// The scene at `path` with these flags settled over its settings.
    pub(crate) fn job(&self, path: &Path) -> error::Result<RenderJob> {
        self.job_of(path, |scene| scene)
    }

    /// The job of `path`'s scene made `scene` by `make` before the
    /// overrides are settled over it.
    pub(crate) fn job_of(
        &self,
        path: &Path,
        make: impl FnOnce(tracer::scene::Scene) -> tracer::scene::Scene,
    ) -> error::Result<RenderJob> {
        let overrides = Overrides {
            render: RenderSpec {
                integrator: self.integrator,
                spp: self.spp.map(f64::from),
                max_depth: self.max_depth.map(f64::from),
                fresnel: self.fresnel,
                seed: self.seed,
                pixel_filter: self.pixel_filter,
                photons: self.photons.map(f64::from),
                photon_passes: self.photon_passes.map(f64::from),
                photon_radius: self.photon_radius,
                precision: self.precision,
                ..RenderSpec::default()
            },
            width: self.size.width,
            height: self.size.height,
            allow_expensive: self.allow_expensive,
        };
        let scene_error = |error| -> error::Error {
            ErrorKind::Scene {
                file: path.to_owned(),
                error,
            }
            .into()
        };
        let scene = tracer::scene::load(path).map_err(scene_error)?;
        RenderJob::new(make(scene), &overrides).map_err(scene_error)
    }
}

pub fn run(args: &RenderArgs, ui: &Ui) -> error::Result<()> {
    #[cfg(feature = "harness")]
    if let Some(budget) = args.budget.settle() {
        let lambert = args.budget.lambert;
        let job = args.job.job_of(&args.scene, |scene| {
            validation::tradeoff::engine::measured_scene(scene, lambert)
        })?;
        let asked = crate::budget::Asked {
            inputs: args,
            scene: &args.scene,
            job: &job,
            output: &args.output,
            flags: &args.budget,
            threads: args.threads.map(|t| t as usize),
        };
        return crate::budget::run(&asked, budget, ui);
    }
    let job = args.job.job(&args.scene)?;
    // Refuse an unwritable destination before spending the render on it.
    let destination = Destination::new(&args.output, &[&args.scene]).map_err(ErrorKind::Output)?;
    warn_if_long(&job, ui.lang);
    let bar = progress_bar(job.scene().height as u64);
    let progress = |rows: usize| {
        if let Some(bar) = &bar {
            bar.set_position(rows as u64);
        }
    };
    let rendered = job.render_to(&destination, args.threads.map(|t| t as usize), &progress);
    if let Some(bar) = &bar {
        bar.finish_and_clear();
    }
    ui.show_steps_and_notes(&record(args, &job, &destination, &rendered?, ui.lang))
}

/// Past [`WARN_RAYS`], the estimate on stderr before the work starts.
pub(crate) fn warn_if_long(job: &RenderJob, lang: Lang) {
    if job.rays() > WARN_RAYS {
        crate::ui::print_err(&say!(
            lang,
            "warning: this may cast up to {:.2e} rays (more than {:e}): it may take long\n",
            "figyelem: ez legfeljebb {:.2e} sugarat indíthat (több, mint {:e}): sokáig tarthat\n",
            job.rays(),
            WARN_RAYS
        ));
    }
}

/// A bar of `rows` on a terminal's stderr, drawn at once and redrawn
/// while a slow first row is traced.
pub(crate) fn progress_bar(rows: u64) -> Option<indicatif::ProgressBar> {
    std::io::stderr().is_terminal().then(|| {
        let bar = indicatif::ProgressBar::new(rows);
        bar.set_style(
            indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} rows, {eta} left")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        bar.enable_steady_tick(std::time::Duration::from_millis(250));
        bar
    })
}

/// The render's record: the files written as the answer, the summary line
/// as its one step, what was skipped as notes, the cost as details.
fn record(
    args: &RenderArgs,
    job: &RenderJob,
    destination: &Destination,
    rendered: &Rendered,
    lang: Lang,
) -> Record {
    let (scene, settings, machinery) = (job.scene(), job.settings(), job.machinery());
    let (png, pfm) = (destination.png(), destination.pfm());
    let seconds = rendered.elapsed.as_secs_f64();
    let rays = rendered.rays.total();
    let rate = rays as f64 / seconds.max(1e-9);
    let mut record = Record::new("render", String::new(), "");
    record
        .inputs_from(args)
        .set_answer(
            Answer::List(vec![
                png.display().to_string().into(),
                pfm.display().to_string().into(),
            ]),
            None,
        )
        .step(|| {
            say!(
                lang,
                "{}×{} {} in {:.3} s: {} rays, {:.2} M rays/s → {}, {}",
                "{}×{} {} {:.3} s alatt: {} sugár, {:.2} M sugár/s → {}, {}",
                scene.width,
                scene.height,
                settings.integrator,
                seconds,
                rays,
                rate / 1e6,
                png.display(),
                pfm.display()
            )
        })
        .detail("width", scene.width)
        .detail("height", scene.height)
        .detail("settings", settings)
        .detail("png", png.display().to_string())
        .detail("pfm", pfm.display().to_string())
        .detail("seconds", seconds)
        .detail("rays", rendered.rays)
        .detail("rays_total", rays)
        .detail("rays_estimated_at_most", job.rays())
        .detail("rays_per_second", rate)
        .detail("samples_per_pixel_taken", machinery.spp)
        .detail("shadow_rays", machinery.shadow_rays);
    for line in steps(job.needs(), machinery, settings, lang) {
        record.note(line);
    }
    record
}

/// What the renderer switched off and why, one line each.
pub(crate) fn steps(
    needs: &Needs,
    machinery: &Machinery,
    settings: &Settings,
    lang: Lang,
) -> Vec<String> {
    let mut steps = Vec::new();
    if !machinery.shadow_rays {
        steps.push(if needs.lights.iter().any(|l| l.used) {
            say!(
                lang,
                "shadow rays skipped: no object can block a light",
                "árnyéksugarak kihagyva: semmi sem takarhatja el a fényt"
            )
        } else {
            say!(
                lang,
                "shadow rays skipped: no light is used",
                "árnyéksugarak kihagyva: nincs használt fény"
            )
        });
    }
    for light in needs.lights.iter().filter(|l| !l.used) {
        steps.push(say!(
            lang,
            "light {} ({}) skipped: {}",
            "{}. fény ({}) kihagyva: {}",
            light.index,
            needs::light_kind(light.kind, lang),
            light.reason.map_or("", |r| needs::unused(r, lang))
        ));
    }
    if machinery.spp < settings.spp {
        steps.push(if settings.integrator.samples() {
            say!(
                lang,
                "{} samples per pixel reduced to 1: every path is deterministic and passes through the pixel centre",
                "{} minta képpontonként 1-re csökkentve: minden út determinisztikus, és a képpont közepén halad át",
                settings.spp
            )
        } else {
            say!(
                lang,
                "{} samples per pixel reduced to 1: the {} integrator is deterministic and its rays pass through the pixel centre (--pixel-filter box takes them all)",
                "{} minta képpontonként 1-re csökkentve: a(z) {} integrátor determinisztikus, sugarai a képpont közepén haladnak át (a --pixel-filter box mindet felhasználja)",
                settings.spp,
                settings.integrator
            )
        });
    }
    steps
}
