//! `optics inspect`: what a scene needs, what the renderer skips, and what
//! each skipped part would have cost, measured by rendering with it on.

use std::path::PathBuf;
use std::sync::atomic::{AtomicU64, Ordering};

use serde_json::{json, Value};
use tracer::integrator::Machinery;
use tracer::job::RenderJob;
use tracer::needs::{Needs, ReflectionDepth};
use tracer::render::Rendered;

use crate::error;
use crate::lang::needs;
use crate::render::JobArgs;
use crate::ui::Ui;
use record::{say, Lang};
use record::{Answer, Record};

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:
  optics inspect crates/tracer/scenes/shadow.json
  optics --json inspect crates/tracer/scenes/kaleidoscope.json --integrator path --spp 16
  optics inspect crates/tracer/scenes/gold_spheres.json --integrator path --spp 16 --measure

The costs are measured by rendering the scene twice or more at its own size
(or --width/--height): with only the machinery it needs, and with each
skipped part switched back on. The images are compared: skipping must not
change a pixel.")]
#[derive(serde::Serialize)]
pub struct InspectArgs {
    /// The scene file (JSON).
    pub scene: PathBuf,
    // The settings to inspect for, over the scene's; --width and --height
    // size the measuring renders.
    #[command(flatten)]
    #[serde(flatten)]
    pub job: JobArgs,
    /// Measure the share of the light the path integrator misses on this
    /// scene, by rendering it with path and photon (four times each, at
    /// its settings): where the scene has light that path cannot find.
    #[arg(long)]
    pub measure: bool,
}

pub fn run(args: &InspectArgs, ui: &Ui) -> error::Result<()> {
    let job = args.job.job(&args.scene)?;
    let (scene, settings, needs) = (job.scene(), job.settings(), job.needs());
    let lang = ui.lang;
    crate::render::warn_if_long(&job, lang);
    let parts = skipped_parts(&job);
    // Every measuring render's rows on one bar, shown from the start.
    let rows = scene.height as u64;
    let bar = crate::render::progress_bar(rows * RUNS * (1 + parts.len() as u64));
    let runs = AtomicU64::new(0);
    let progress = |done: usize| {
        if let Some(bar) = &bar {
            let before = runs.load(Ordering::Relaxed);
            bar.set_position(before * rows + done as u64);
        }
    };
    let measure = |machinery: &Machinery| measure(&job, machinery, &runs, &progress);
    let base = measure(job.machinery());
    let full: error::Result<Vec<(Part, Rendered)>> = match &base {
        Ok(_) => parts
            .iter()
            .map(|(part, machinery)| Ok((*part, measure(machinery)?)))
            .collect(),
        Err(_) => Ok(Vec::new()),
    };
    if let Some(bar) = &bar {
        bar.finish_and_clear();
    }
    let base = base?;
    let mut costs = Vec::new();
    let mut lines = Vec::new();
    for (part, full) in full? {
        let (cost, line) = cost_of(part, &full, &base, lang);
        costs.push(cost);
        lines.push(line);
    }
    let mut record = Record::new("inspect", String::new(), "");
    record.inputs_from(args);
    if let Value::Object(needs) = serde_json::to_value(needs).unwrap_or(Value::Null) {
        record.set_answer(Answer::Object(needs), None);
    }
    for line in needs_steps(needs, base.rays.deepest, lang) {
        record.step(|| line);
    }
    record.step(|| {
        say!(
            lang,
            "{}×{} {}: {} rays with only what the scene needs",
            "{}×{} {}: {} sugár csak a szükséges részekkel",
            scene.width,
            scene.height,
            settings.integrator,
            base.rays.total()
        )
    });
    let (missing, missing_detail) =
        crate::missing_light::report(&job, &args.scene, lang, args.measure)?;
    for line in crate::render::steps(needs, job.machinery(), settings, lang)
        .into_iter()
        .chain(lines)
        .chain(missing)
    {
        record.step(|| line);
    }
    record
        .detail("width", scene.width)
        .detail("height", scene.height)
        .detail("settings", settings)
        .detail("skipped", costs)
        .detail("missing_light", missing_detail)
        .detail("rays", base.rays);
    ui.show_steps(&record)
}

/// How many times each machinery is rendered.
const RUNS: u64 = 3;

/// The best of [`RUNS`] renders with `machinery`, so that the time
/// differences are not scheduling noise; `runs` counts the renders done,
/// for `progress`.
fn measure(
    job: &RenderJob,
    machinery: &Machinery,
    runs: &AtomicU64,
    progress: &(dyn Fn(usize) + Sync),
) -> error::Result<Rendered> {
    let render = || {
        let rendered = job.render_with(machinery, None, progress);
        runs.fetch_add(1, Ordering::Relaxed);
        rendered
    };
    let mut best = render()?;
    for _ in 1..RUNS {
        let again = render()?;
        if again.elapsed < best.elapsed {
            best = again;
        }
    }
    Ok(best)
}

/// A part of the machinery the job skips because the scene does not need
/// it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Part {
    /// The shadow rays.
    ShadowRays,
    /// The lights that light nothing.
    UnusedLights,
    /// The samples after the first, where every path is deterministic.
    ExtraSamples,
    /// The rest of the paths the closed mirror tube holds.
    HeldPaths,
    /// All of them together.
    All,
}

impl Part {
    /// Its name in the record (`part`).
    fn name(self) -> &'static str {
        match self {
            Part::ShadowRays => "shadow_rays",
            Part::UnusedLights => "unused_lights",
            Part::ExtraSamples => "extra_samples",
            Part::HeldPaths => "held_paths",
            Part::All => "all",
        }
    }

    /// Its name in words, as a sentence starts.
    fn words(self, lang: Lang) -> &'static str {
        match self {
            Part::ShadowRays => lang.pick("the shadow rays", "az árnyéksugarak"),
            Part::UnusedLights => lang.pick("the unused lights", "a nem használt fények"),
            Part::ExtraSamples => lang.pick("the samples after the first", "az első utáni minták"),
            Part::HeldPaths => lang.pick(
                "the rest of the paths the mirror tube holds",
                "a tükörcsőben tartott utak folytatása",
            ),
            Part::All => lang.pick("all of them", "mindez együtt"),
        }
    }
}

/// Each part the job skips switched back on alone, then all together.
fn skipped_parts(job: &RenderJob) -> Vec<(Part, Machinery)> {
    let (lean, everything) = (job.machinery(), job.everything());
    let mut parts: Vec<(Part, Machinery)> = Vec::new();
    if !lean.shadow_rays && job.needs().lights.iter().any(|l| l.used) {
        parts.push((
            Part::ShadowRays,
            Machinery {
                shadow_rays: true,
                ..lean.clone()
            },
        ));
    }
    if lean.lights != everything.lights {
        parts.push((
            Part::UnusedLights,
            // With their shadow rays: what blocks a light is part of its cost.
            Machinery {
                lights: everything.lights.clone(),
                shadow_rays: true,
                ..lean.clone()
            },
        ));
    }
    if lean.spp != everything.spp {
        parts.push((
            Part::ExtraSamples,
            Machinery {
                spp: everything.spp,
                ..lean.clone()
            },
        ));
    }
    if lean.trap.is_some() {
        parts.push((
            Part::HeldPaths,
            Machinery {
                trap: None,
                ..lean.clone()
            },
        ));
    }
    if parts.len() > 1 {
        parts.push((Part::All, everything));
    }
    parts
}

fn yes_no(lang: Lang, b: bool) -> String {
    lang.pick(if b { "yes" } else { "no" }, if b { "igen" } else { "nem" })
        .to_owned()
}

/// What switching `part` back on cost against `base`: the record and its line.
fn cost_of(part: Part, full: &Rendered, base: &Rendered, lang: Lang) -> (Value, String) {
    let extra_rays = full.rays.total() as i64 - base.rays.total() as i64;
    let extra_seconds = full.elapsed.as_secs_f64() - base.elapsed.as_secs_f64();
    let identical = full.image == base.image;
    let changed = full
        .image
        .pixels
        .iter()
        .zip(&base.image.pixels)
        .filter(|(p, q)| p != q)
        .count();
    let (_, max_difference) = full.image.difference(&base.image);
    let line = say!(
        lang,
        "{}: would cost {} more rays ({:+.1} %), {:+.4} s; image identical: {}",
        "{}: {} további sugár ({:+.1} %), {:+.4} s; a kép azonos: {}",
        part.words(lang),
        extra_rays,
        100.0 * extra_rays as f64 / base.rays.total().max(1) as f64,
        extra_seconds,
        if identical {
            yes_no(lang, true)
        } else {
            say!(
                lang,
                "no, {} pixels differ by up to {:.3}",
                "nem, {} képpont tér el, legfeljebb {:.3}-mal",
                changed,
                max_difference
            )
        }
    );
    let cost = json!({
        "part": part.name(),
        "extra_rays": extra_rays,
        "extra_seconds": extra_seconds,
        "image_identical": identical,
        "pixels_changed": changed,
        "max_difference": max_difference,
    });
    (cost, line)
}

/// What the scene needs, one line each, and the deepest bounce a render
/// with only that took.
fn needs_steps(needs: &Needs, deepest: u32, lang: Lang) -> Vec<String> {
    let depth = match needs.reflection_depth {
        ReflectionDepth::None => "0".to_string(),
        ReflectionDepth::One => "1".to_string(),
        ReflectionDepth::UpToMaxDepth(d) => {
            say!(lang, "up to {} (max_depth)", "legfeljebb {} (max_depth)", d)
        }
    };
    let lights: Vec<String> = needs
        .lights
        .iter()
        .map(|l| {
            let kind = needs::light_kind(l.kind, lang);
            match l.reason {
                None => say!(
                    lang,
                    "light {} ({}) used",
                    "{}. fény ({}): használt",
                    l.index,
                    kind
                ),
                Some(r) => say!(
                    lang,
                    "light {} ({}) not used: {}",
                    "{}. fény ({}): nem használt: {}",
                    l.index,
                    kind,
                    needs::unused(r, lang)
                ),
            }
        })
        .collect();
    let lights = if lights.is_empty() {
        lang.pick("none", "nincs").to_owned()
    } else {
        lights.join("; ")
    };
    vec![
        say!(
            lang,
            "reflection depth reachable: {}",
            "elérhető tükrözési mélység: {}",
            depth
        ),
        say!(
            lang,
            "deepest bounce taken in this render: {}",
            "a legmélyebb visszaverődés ebben a képben: {}",
            deepest
        ),
        say!(
            lang,
            "refraction: {}",
            "fénytörés: {}",
            yes_no(lang, needs.refraction)
        ),
        say!(
            lang,
            "conductors (complex Fresnel): {}",
            "fémek (komplex Fresnel): {}",
            yes_no(lang, needs.conductors)
        ),
        say!(
            lang,
            "surfaces shaded from lights: {}",
            "fényforrásokkal árnyalt felületek: {}",
            yes_no(lang, needs.rough_surfaces)
        ),
        say!(
            lang,
            "shadows possible: {}",
            "lehet árnyék: {}",
            yes_no(lang, needs.shadows)
        ),
        say!(lang, "lights: {}", "fények: {}", lights),
    ]
}
