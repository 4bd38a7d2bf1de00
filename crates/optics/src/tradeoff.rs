//! `optics tradeoff`: what each shortcut a scene allows costs in accuracy
//! and buys in time, measured on whole renders against a converged ground
//! truth with all the light, by fixed error measures ([`measure`]).
//!
//! The sweep ([`sweep::plan`]) varies each setting that applies to the
//! scene alone from the scene's own and walks `003`'s ladder of
//! integrators; each point is rendered `--repeats` times (Monte Carlo
//! points with a new seed each time, so that variance and bias separate),
//! timed by the median, and held against the truth. The Pareto front per
//! measure ([`pareto::front`]) says which settings are worth their time.
//!
//! A sweep renders here, in one run, or as independent jobs that a
//! scheduler spreads over machines: `--plan` writes them ([`jobs`]),
//! `optics tradeoff-job` runs one, `--collect` merges their results; both
//! end in the same measures and the same record.

pub(crate) mod distribute;
pub use validation::tradeoff::jobs;
mod metals;
mod mitsuba;
mod report;
pub(crate) mod setup;
pub use validation::tradeoff::{sweep, truth};
mod timing;
mod worker;

pub use worker::{run_job, TradeoffJobArgs};

pub use validation::tradeoff::checks::UNCONVERGED;
pub use validation::tradeoff::{measure, pareto, prose, Verdict, MEASURES, SCHEMA, SCHEMA_VERSION};

use std::path::{Path, PathBuf};

use serde::Serialize;
use tracer::scene::{MAX_IMAGE_SIDE, MAX_SPP};

use crate::error::{self, ErrorKind};
use crate::ui::Ui;
use measure::Errors;
use setup::Files;
pub(crate) use setup::Setup;
pub(crate) use timing::{renders_wanted, Timed, MAX_RENDERS};
use validation::tradeoff::findings::{Findings, MetalRgb};
pub(crate) use validation::tradeoff::render::render;

#[derive(clap::Args, Debug, Serialize)]
#[command(after_help = "Examples:
  optics tradeoff crates/tracer/scenes/kaleidoscope_lit.json --width 160 --height 120
  optics --json tradeoff crates/tracer/scenes/gold_spheres.json --repeats 5 --out /tmp/gold
  optics tradeoff crates/tracer/scenes/shadow.json --lambert --plan jobs.jsonl
  optics tradeoff crates/tracer/scenes/shadow.json --lambert --collect results

Writes SCENE.json (schema optics.tradeoff), SCENE.md (the table) and
SCENE-pareto.png (time against each error, log-log) into --out, and caches
the ground truth under --out/truth. See docs/tradeoffs.md for the measures.
--plan writes the sweep's render jobs instead (run each with `optics
tradeoff-job`), and --collect merges their results: docs/cli.md, \"Spread a
sweep over machines\".")]
pub struct TradeoffArgs {
    /// The scene file (JSON, see docs/scene-schema.md).
    pub scene: PathBuf,
    /// Image width in pixels (default: the scene's); the camera keeps its view.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=MAX_IMAGE_SIDE as i64))]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub width: Option<u32>,
    /// Image height in pixels (default: the scene's).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=MAX_IMAGE_SIDE as i64))]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub height: Option<u32>,
    /// Samples per pixel of the Monte Carlo integrators on the ladder when
    /// the scene's own integrator is deterministic.
    #[arg(long, default_value_t = 16, value_parser = clap::value_parser!(u32).range(1..=MAX_SPP as i64))]
    pub spp: u32,
    /// Samples per pixel of the ground truth (two halves of half as many).
    #[arg(long, default_value_t = 1024, value_parser = clap::value_parser!(u32).range(2..=MAX_SPP as i64))]
    pub truth_spp: u32,
    /// Renders per setting: the time is their median; Monte Carlo settings
    /// take a new seed each, and two or more split variance from bias.
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u32).range(1..=100))]
    pub repeats: u32,
    /// Render each setting until its renders add up to this many seconds
    /// (at most 64 renders), for a steadier median.
    #[arg(long, default_value_t = 0.5, value_parser = seconds_flag)]
    pub min_seconds: f64,
    /// Directory for the results and the truth's cache (created if missing).
    #[arg(long, short, default_value = "validation/out/tradeoff")]
    pub out: PathBuf,
    /// Measure the scene with its course_rough materials made Lambert of
    /// albedo kd, the suite's energy-conserving stand-in (the course's kd is
    /// in 1/sr: its diffuse albedo is π kd, up to 2.5 in the course scenes,
    /// and light multiplies between surfaces that see each other).
    #[arg(long)]
    pub lambert: bool,
    /// Render the ground truth again even when a cached one matches.
    #[arg(long)]
    pub fresh: bool,
    /// Do not draw the Pareto plot (it needs .venv's matplotlib).
    #[arg(long)]
    pub no_plot: bool,
    /// Worker threads (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub threads: Option<u32>,
    /// Render nothing: write the sweep as independent jobs, one JSON line
    /// each, to this file, for `optics tradeoff-job` to run anywhere.
    #[arg(long, value_name = "JOBS.jsonl", conflicts_with = "collect")]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plan: Option<PathBuf>,
    /// Render nothing: merge the results of the plan's jobs (directories
    /// of result files, or the files) into the sweep's record; give the
    /// scene and the flags given to --plan.
    #[arg(long, value_name = "RESULTS", num_args = 1..)]
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub collect: Vec<PathBuf>,
}

/// What `optics tradeoff` does, settled from its flags once.
#[derive(Debug, PartialEq)]
pub enum Mode<'a> {
    /// Render and measure the sweep here.
    Sweep,
    /// Write its jobs to this file (`--plan`).
    Plan(&'a Path),
    /// Measure the results of its jobs (`--collect`).
    Collect(&'a [PathBuf]),
}

impl TradeoffArgs {
    /// The mode the flags ask for (clap refuses `--plan` with `--collect`).
    pub fn mode(&self) -> Mode<'_> {
        match (&self.plan, self.collect.as_slice()) {
            (Some(jobs), _) => Mode::Plan(jobs),
            (None, []) => Mode::Sweep,
            (None, results) => Mode::Collect(results),
        }
    }
}

/// One point of the sweep, measured.
#[derive(Clone, Debug, Serialize)]
pub struct Measured {
    /// The point.
    #[serde(flatten)]
    pub point: sweep::Point,
    /// The render times, s, in the order taken.
    pub seconds: Vec<f64>,
    /// Their median, s.
    pub seconds_median: f64,
    /// Rays cast by one render (the mean over the repeats): the cost that
    /// does not depend on the machine.
    pub rays: f64,
    /// The fixed measures, against the truth.
    pub errors: Errors,
    /// The same measures against the scene's own settings' render (the
    /// mean of its seeds): what this setting itself changes.
    pub against_scene: Errors,
    /// 1 / (relative variance × median seconds), Monte Carlo points only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub efficiency: Option<f64>,
    /// The measures on whose Pareto front (time against that measure) the
    /// point lies.
    pub pareto: Vec<&'static str>,
    /// What the point is against the scene's own settings (none for them).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub verdict: Option<Verdict>,
    /// The measures over the grazing pixels alone (the scene's own
    /// settings and the Fresnel law's points, where any pixel grazes).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub grazing: Option<Grazing>,
}

/// A point's measures over the grazing pixels
/// ([`validation::tradeoff::findings::GRAZING_COS`]).
#[derive(Clone, Debug, Serialize)]
pub struct Grazing {
    /// How many pixels graze.
    pub pixels: usize,
    /// The measures against the truth over them.
    pub errors: Errors,
    /// The measures against the scene's own render over them.
    pub against_scene: Errors,
}

/// `--min-seconds`: a finite number of seconds, 0 to 60.
fn seconds_flag(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(s) if (0.0..=60.0).contains(&s) || seconds_unchecked() => Ok(s),
        Ok(s) => Err(format!("{s} is not between 0 and 60 seconds")),
        Err(e) => Err(e.to_string()),
    }
}

#[cfg(test)]
thread_local! {
    /// A test-only switch that reverts the range check of `--min-seconds`,
    /// for the tradeoff-flags fuzz target to find.
    pub(crate) static SECONDS_UNCHECKED: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

#[cfg(test)]
fn seconds_unchecked() -> bool {
    SECONDS_UNCHECKED.get()
}

#[cfg(not(test))]
fn seconds_unchecked() -> bool {
    false
}

impl Measured {
    /// The measure named `name` (one of [`MEASURES`]).
    pub fn measure(&self, name: &str) -> f64 {
        match name {
            "rel_rmse" => self.errors.rel_rmse,
            "delta_e_mean" => self.errors.delta_e_mean,
            "delta_e_p99" => self.errors.delta_e_p99,
            "flip_mean" => self.errors.flip_mean,
            _ => f64::NAN,
        }
    }
}

/// The whole sweep, as written to JSON.
#[derive(Debug, Serialize)]
pub struct Sweep {
    /// Where it is written (not in the JSON).
    #[serde(skip)]
    files: Files,
    /// Its files' stem (not in the JSON).
    #[serde(skip)]
    stem: String,
    /// The course material that multiplies light, and its name (the
    /// JSON's `diffuse_gain`).
    #[serde(skip)]
    gain: Option<(f32, String)>,
    /// [`SCHEMA`].
    pub schema: &'static str,
    /// [`SCHEMA_VERSION`].
    pub version: u32,
    /// The scene file, as given.
    pub scene: String,
    /// Whether course_rough was measured as Lambert (`--lambert`).
    pub lambert: bool,
    /// The course material's diffuse albedo `π kd` where it is above 1.
    pub diffuse_gain: Option<f32>,
    /// Image size, pixels.
    pub width: u32,
    /// Image size, pixels.
    pub height: u32,
    /// Pixels whose centre sees an object: those the measures cover.
    pub surface_pixels: usize,
    /// The machine and date the times were taken on.
    pub machine: String,
    /// `YYYY-MM-DD`, UTC.
    pub date: String,
    /// The load average as the sweep ended.
    pub load: Option<String>,
    /// The command that made it.
    pub command: String,
    /// The ground truth.
    pub truth: truth::TruthRecord,
    /// Every point, the scene's own settings first.
    pub points: Vec<Measured>,
    /// What was not swept, and why.
    pub skipped: Vec<sweep::Skipped>,
    /// The colour error of three channels against a spectrum for each of
    /// the scene's metals, by the harness's measure.
    pub rgb_against_spectrum: Vec<MetalRgb>,
    /// What the numbers say of each shortcut, read from the record
    /// ([`Findings::of`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub findings: Option<Findings>,
    /// Where the renders were run as jobs (`--plan`, `--collect`): absent
    /// for a sweep rendered in one run.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub collected: Option<distribute::Collected>,
    /// Every setting against Mitsuba's estimate of all the light, or why
    /// there is no such reference for this sweep
    /// ([`validation::tradeoff::mitsuba`]).
    pub mitsuba: validation::tradeoff::mitsuba::MitsubaTruth,
    /// Why there is no reference, typed, for the table's words (not in
    /// the JSON, which has them in `mitsuba`).
    #[serde(skip)]
    mitsuba_missing: Option<validation::tradeoff::mitsuba::NoReference>,
}

/// Where and when the renders were timed.
pub(crate) struct Provenance {
    /// The machine (or machines) the times are of.
    pub machine: String,
    /// The day (or days) they were taken.
    pub date: String,
    /// The load average as the renders ended.
    pub load: Option<String>,
    /// The jobs, when the renders were run as jobs.
    pub collected: Option<distribute::Collected>,
}

/// What the measures read, however it was rendered: the truth, each
/// point's renders, and where and when they were taken.
pub(crate) type Renders = (measure::Truth, truth::TruthRecord, Vec<Timed>, Provenance);

pub fn run(args: &TradeoffArgs, ui: &Ui) -> error::Result<()> {
    let setup = Setup::new(args)?;
    let mode = args.mode();
    if let Mode::Plan(jobs) = mode {
        return distribute::plan(&setup, args, jobs, ui);
    }
    setup.files.prepare(&args.scene)?;
    let truth_dir = setup.files.truth_dir();
    let request = setup.truth_request(args, &truth_dir);
    let (truth, truth_record, timed, provenance) = match mode {
        Mode::Collect(results) => distribute::collect(&setup, &request, results)?,
        _ => timing::render_here(&setup, args, &request)?,
    };
    // A truth rendered here is refused before the points are; one
    // collected is known only now.
    if truth.is_black() {
        return Err(ErrorKind::TruthIsBlack {
            file: args.scene.clone(),
        }
        .into());
    }
    let mut sweep = measure_points(setup, args, (&truth, truth_record), timed, provenance);
    sweep.findings = Some(findings(&sweep)?);
    report::write_and_show(&sweep, args, ui)
}

/// What `sweep`'s record says, read as `optics validate` reads it: the
/// record written, read back ([`validation::tradeoff::record::Record`]),
/// so the findings are those of the numbers the JSON carries.
fn findings(sweep: &Sweep) -> error::Result<Findings> {
    let value = serde_json::to_value(sweep).map_err(ErrorKind::Encode)?;
    let record: validation::tradeoff::record::Record =
        serde_json::from_value(value).map_err(ErrorKind::Encode)?;
    Ok(Findings::of(&record))
}

/// Every point measured against the truth and against the scene's own
/// settings, its fronts and its verdict marked: the sweep's record.
fn measure_points(
    setup: Setup,
    args: &TradeoffArgs,
    (truth, truth_record): (&measure::Truth, truth::TruthRecord),
    timed: Vec<Timed>,
    provenance: Provenance,
) -> Sweep {
    let Setup {
        job,
        gain,
        stem,
        files,
        mask,
        grazing,
        plan,
        ..
    } = setup;
    let mut truth_record = truth_record;
    truth_record.light_noise_relative = Some(truth.light_noise_relative(&mask));
    let mut points = Vec::with_capacity(plan.points.len());
    let mut scene_render: Option<measure::Truth> = None;
    // The truth's noise per pixel-channel is its mean over the surface,
    // taken for the grazing pixels too.
    let grazing_truth = (grazing.count() > 0)
        .then(|| measure::Truth::new(truth.image.clone(), truth.noise, &grazing));
    let mut scene_grazing: Option<measure::Truth> = None;
    let mut second = mitsuba::Second::new(job.scene(), &args.scene);
    for (point, timed) in plan.points.into_iter().zip(timed) {
        let errors = measure::errors(&timed.images, truth, &mask);
        second.add(&point.label, &timed.images);
        // The first point is the scene's own settings.
        let reference =
            scene_render.get_or_insert_with(|| measure::Truth::from_renders(&timed.images, &mask));
        let against_scene = measure::errors(&timed.images, reference, &mask);
        let grazing = match (&grazing_truth, point.axis) {
            (Some(truth), sweep::Axis::Scene | sweep::Axis::Fresnel) => {
                let own = scene_grazing
                    .get_or_insert_with(|| measure::Truth::from_renders(&timed.images, &grazing));
                Some(Grazing {
                    pixels: grazing.count(),
                    errors: measure::errors(&timed.images, truth, &grazing),
                    against_scene: measure::errors(&timed.images, own, &grazing),
                })
            }
            _ => None,
        };
        let seconds_median = median(&timed.seconds);
        let efficiency = errors
            .split
            .filter(|_| point.settings.integrator.samples())
            .map(|split| 1.0 / (split.variance * seconds_median));
        points.push(Measured {
            point,
            rays: timed.rays / timed.seconds.len() as f64,
            seconds: timed.seconds,
            seconds_median,
            errors,
            against_scene,
            efficiency,
            pareto: Vec::new(),
            verdict: None,
            grazing,
        });
    }
    mark_fronts(&mut points);
    mark_verdicts(&mut points);
    let (mitsuba, mitsuba_missing) = second.finish(&truth.image);
    Sweep {
        schema: SCHEMA,
        version: SCHEMA_VERSION,
        scene: args.scene.display().to_string(),
        lambert: args.lambert,
        diffuse_gain: gain.as_ref().map(|g| g.0),
        gain,
        stem,
        files,
        width: job.scene().width,
        height: job.scene().height,
        surface_pixels: mask.count(),
        machine: provenance.machine,
        date: provenance.date,
        load: provenance.load,
        command: command_line(args),
        truth: truth_record,
        points,
        skipped: plan.skipped,
        rgb_against_spectrum: metals::rgb_against_spectrum(job.scene()),
        findings: None,
        collected: provenance.collected,
        mitsuba,
        mitsuba_missing,
    }
}

/// Marks each point with the fronts it lies on.
fn mark_fronts(points: &mut [Measured]) {
    for name in MEASURES {
        let xy: Vec<(f64, f64)> = points
            .iter()
            .map(|p| (p.seconds_median, p.measure(name)))
            .collect();
        for i in pareto::front(&xy) {
            points[i].pareto.push(name);
        }
    }
}

/// Gives each point after the first, the scene's own settings, its verdict
/// against them.
fn mark_verdicts(points: &mut [Measured]) {
    let Some((base, shortcuts)) = points.split_first_mut() else {
        return;
    };
    for p in shortcuts {
        p.verdict = Some(Verdict::of(
            p.against_scene.delta_e_p99,
            p.seconds_median,
            base.seconds_median,
        ));
    }
}

/// The median of `values` (the mean of the middle two for an even count).
fn median(values: &[f64]) -> f64 {
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    let n = sorted.len();
    match n {
        0 => f64::NAN,
        _ if n % 2 == 1 => sorted[n / 2],
        _ => 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]),
    }
}

/// The command line that reproduces the sweep.
fn command_line(args: &TradeoffArgs) -> String {
    let mut words = vec![format!("optics tradeoff {}", args.scene.display())];
    if let Some(w) = args.width {
        words.push(format!("--width {w}"));
    }
    if let Some(h) = args.height {
        words.push(format!("--height {h}"));
    }
    if args.lambert {
        words.push("--lambert".to_owned());
    }
    words.push(format!(
        "--spp {} --truth-spp {} --repeats {} --min-seconds {}",
        args.spp, args.truth_spp, args.repeats, args.min_seconds
    ));
    words.join(" ")
}

#[cfg(test)]
mod tests {
    use super::median;

    #[test]
    fn the_median_of_odd_and_even_counts() {
        assert_eq!(median(&[3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&[4.0, 1.0, 2.0, 3.0]), 2.5);
        assert!(median(&[]).is_nan());
    }
}
