//! Every point of a sweep measured against the truth and against the
//! scene's own settings, its Pareto fronts and verdicts marked: the
//! sweep's record, as `optics tradeoff` writes it and `optics validate`
//! reads it back ([`crate::tradeoff::record`]).

use serde::Serialize;

use super::renders::{Collected, Provenance, Renders, Timed};
use super::request::SweepRequest;
use super::setup::{Files, Setup};
use super::{metals, second};
use crate::tradeoff::error::TradeoffError;
use crate::tradeoff::findings::Findings;
use crate::tradeoff::findings::MetalRgb;
use crate::tradeoff::measure::{self, Errors};
use crate::tradeoff::mitsuba::{MitsubaTruth, NoReference};
use crate::tradeoff::schema::{MEASURES, SCHEMA, SCHEMA_VERSION};
use crate::tradeoff::verdict::Verdict;
use crate::tradeoff::{pareto, sweep, truth};

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
/// ([`crate::tradeoff::findings::GRAZING_COS`]).
#[derive(Clone, Debug, Serialize)]
pub struct Grazing {
    /// How many pixels graze.
    pub pixels: usize,
    /// The measures against the truth over them.
    pub errors: Errors,
    /// The measures against the scene's own render over them.
    pub against_scene: Errors,
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
    pub files: Files,
    /// Its files' stem (not in the JSON).
    #[serde(skip)]
    pub stem: String,
    /// The course material that multiplies light, and its name (the
    /// JSON's `diffuse_gain`).
    #[serde(skip)]
    pub gain: Option<(f32, String)>,
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
    pub collected: Option<Collected>,
    /// Every setting against Mitsuba's estimate of all the light, or why
    /// there is no such reference for this sweep
    /// ([`crate::tradeoff::mitsuba`]).
    pub mitsuba: MitsubaTruth,
    /// Why there is no reference, typed, for the table's words (not in
    /// the JSON, which has them in `mitsuba`).
    #[serde(skip)]
    pub mitsuba_missing: Option<NoReference>,
}

/// What `sweep`'s record says, read as `optics validate` reads it: the
/// record written, read back ([`crate::tradeoff::record::Record`]), so
/// the findings are those of the numbers the JSON carries.
fn findings(sweep: &Sweep) -> Result<Findings, TradeoffError> {
    let value = serde_json::to_value(sweep).map_err(TradeoffError::Encode)?;
    let record: crate::tradeoff::record::Record =
        serde_json::from_value(value).map_err(TradeoffError::Encode)?;
    Ok(Findings::of(&record))
}

/// Every point measured against the truth and against the scene's own
/// settings, its fronts and its verdict marked, and what the numbers say
/// of each shortcut ([`Findings::of`]): the sweep's record. A truth that
/// is black (known only now where the jobs rendered it) is refused.
pub fn measure_points(
    setup: Setup,
    args: &SweepRequest,
    renders: Renders,
) -> Result<Sweep, TradeoffError> {
    let (truth, truth_record, timed, provenance) = renders;
    if truth.is_black() {
        return Err(TradeoffError::TruthIsBlack {
            file: args.scene.clone(),
        });
    }
    let truth = &truth;
    let mut sweep = measure(setup, args, (truth, truth_record), timed, provenance);
    sweep.findings = Some(findings(&sweep)?);
    Ok(sweep)
}

/// [`measure_points`] before its findings.
fn measure(
    setup: Setup,
    args: &SweepRequest,
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
    // Found once, for Mitsuba's renders and the metals' spectra alike.
    let checkout = args.checkout.find().map_err(|e| e.to_string());
    let checkout = checkout.as_ref().map_err(String::as_str);
    let mut second = second::Second::new(job.scene(), &args.scene, checkout);
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
        points.push(measured(point, timed, (errors, against_scene), grazing));
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
        command: args.command_line(),
        truth: truth_record,
        points,
        skipped: plan.skipped,
        rgb_against_spectrum: metals::rgb_against_spectrum(job.scene(), checkout),
        findings: None,
        collected: provenance.collected,
        mitsuba,
        mitsuba_missing,
    }
}

/// A point's time and measures, before its fronts and its verdict.
fn measured(
    point: sweep::Point,
    timed: Timed,
    (errors, against_scene): (Errors, Errors),
    grazing: Option<Grazing>,
) -> Measured {
    let seconds_median = median(&timed.seconds);
    let efficiency = errors
        .split
        .filter(|_| point.settings.integrator.samples())
        .map(|split| 1.0 / (split.variance * seconds_median));
    Measured {
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
pub fn median(values: &[f64]) -> f64 {
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    let n = sorted.len();
    match n {
        0 => f64::NAN,
        _ if n % 2 == 1 => sorted[n / 2],
        _ => 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]),
    }
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
