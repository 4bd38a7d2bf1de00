//! The record's field of findings (`findings` in an `optics.tradeoff`
//! record): what each finding holds, as the command writes it and the
//! report reads it back.

use serde::{Deserialize, Serialize};

use crate::tradeoff::mitsuba::SecondTruth;
use crate::tradeoff::verdict::Verdict;

/// The findings of one sweep.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Findings {
    /// The scene's own settings against the truth.
    pub own: Accuracy,
    /// The points that do the scene's own work (as many rays, the same
    /// image): their times measure only the machine.
    pub timing_noise: Option<TimingNoise>,
    /// Not seen, at most [`WORTH_IT`](crate::tradeoff::WORTH_IT) of the time and faster than
    /// the timing noise, fastest first.
    pub worth_it: Vec<Shortcut>,
    /// Faster but seen, fastest first: trades, not savings.
    pub seen: Vec<Shortcut>,
    /// Dearer by more than a tenth and than the timing noise, and not
    /// seen: time that buys nothing.
    pub no_gain: Vec<Shortcut>,
    /// On the relative RMSE front, nearer the truth than the scene's own
    /// settings by [`NEARER`](super::NEARER) and seen against their render, cheapest
    /// first: the accuracy there is to buy.
    pub upgrades: Vec<Upgrade>,
    /// The light the scene's settings and each integrator leave out.
    pub light_left_out: Option<LightLeftOut>,
    /// What each bounce adds, where the bounce limit is swept.
    pub bounces: Option<Bounces>,
    /// What Schlick's law costs, where the Fresnel law is swept.
    pub schlick: Option<Schlick>,
    /// The local model against Whitted's, where both were rendered and
    /// one of them is the scene's own.
    pub local_against_whitted: Option<LocalAgainstWhitted>,
    /// The scene's metals in three channels against their spectra.
    pub metals: Vec<MetalRgb>,
    /// Against Mitsuba's truth, where the record measured it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mitsuba: Option<SecondTruth>,
}

/// What renders of the scene's own work took against its time: a saving
/// or a cost inside this band is the run's timing noise, not the setting's.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TimingNoise {
    /// The points that do the scene's own work.
    pub labels: Vec<String>,
    /// The least and the most of their time ratios.
    pub ratios: [f64; 2],
}

/// A shortcut read against the scene's own settings.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Shortcut {
    /// The point's label.
    pub label: String,
    /// Its median time over the scene's own.
    pub time_ratio: f64,
    /// ΔE2000 p99 of its render against the scene's own.
    pub delta_e_p99: f64,
}

/// How far a render is from the truth.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Accuracy {
    /// Relative RMSE.
    pub rel_rmse: f64,
    /// ΔE2000 p99.
    pub delta_e_p99: f64,
}

/// A setting nearer the truth than the scene's own.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Upgrade {
    /// The point's label.
    pub label: String,
    /// Its median time over the scene's own.
    pub time_ratio: f64,
    /// Its relative RMSE from the truth.
    pub rel_rmse: f64,
    /// Its ΔE2000 p99 from the truth.
    pub delta_e_p99: f64,
}

/// `1 − Σx/Σt` of each integrator's render.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LightLeftOut {
    /// The bounce limit they share, the scene's own.
    pub max_depth: u32,
    /// The standard deviation of the truth's `Σ t`, relative: a share
    /// left out below it is the truth's noise.
    pub truth_noise: f64,
    /// The scene's own settings first, then the integrators in the order
    /// swept.
    pub integrators: Vec<LeftOut>,
}

/// One render's share of the light left out.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LeftOut {
    /// The point's label.
    pub label: String,
    /// Its integrator.
    pub integrator: String,
    /// `1 − Σx/Σt`: below 0 where it renders more light than the truth.
    pub left_out: f64,
    /// Its standard deviation: the truth's noise and the render's own,
    /// in quadrature.
    pub noise: f64,
    /// Whether `|left_out|` is within [`NOISE_SIGMAS`](super::NOISE_SIGMAS) of `noise`.
    pub within_noise: bool,
}

/// The bounce limit, step by step: the scene's own depth and the swept
/// ones, in order.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Bounces {
    /// The scene's own bounce limit.
    pub own: u32,
    /// The light each depth carries, a share of the truth's, shallowest
    /// first.
    pub light: Vec<(u32, f64)>,
    /// Each step from one swept depth to the next.
    pub steps: Vec<BounceStep>,
    /// The least depth from which every deeper one is within ΔE p99
    /// [`JUST_NOTICEABLE`](crate::tradeoff::JUST_NOTICEABLE) of the scene's own render.
    pub enough: Option<u32>,
}

/// What going from `from` bounces to `to` adds.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct BounceStep {
    /// The lower limit.
    pub from: u32,
    /// The higher limit.
    pub to: u32,
    /// The light added, as a share of the truth's.
    pub light_added: f64,
    /// Relative RMSE from the truth at `from`.
    pub rel_rmse_from: f64,
    /// Relative RMSE from the truth at `to`.
    pub rel_rmse_to: f64,
    /// ΔE2000 p99 between the two renders, where one is the scene's own
    /// (the other's measure against it); `None` otherwise.
    pub delta_e_p99: Option<f64>,
}

/// Schlick's law against the exact one.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Schlick {
    /// The Schlick point, read against the scene's own (exact) render.
    pub shortcut: Shortcut,
    /// Its verdict.
    pub verdict: Verdict,
    /// Relative RMSE from the truth with the exact law and with Schlick's.
    pub rel_rmse: [f64; 2],
    /// Over the grazing pixels, where the scene has any.
    pub grazing: Option<GrazingCost>,
}

/// Schlick's error over the grazing pixels, against the exact law's render.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct GrazingCost {
    /// How many pixels graze.
    pub pixels: usize,
    /// ΔE2000 mean over them.
    pub delta_e_mean: f64,
    /// ΔE2000 p99 over them.
    pub delta_e_p99: f64,
    /// Relative RMSE over them.
    pub rel_rmse: f64,
}

/// The local model's render against Whitted's.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LocalAgainstWhitted {
    /// ΔE2000 p99 between them.
    pub delta_e_p99: f64,
    /// Whether that is within [`JUST_NOTICEABLE`](crate::tradeoff::JUST_NOTICEABLE).
    pub indistinguishable: bool,
}

/// A metal of the scene in three channels against its spectrum, by the
/// harness's code ([`crate::metals::three_channel_delta_e`]).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MetalRgb {
    /// The scene's material.
    pub material: String,
    /// What was found.
    #[serde(flatten)]
    pub outcome: RgbOutcome,
}

/// Whether a metal's three-channel colour could be held to a spectrum.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "outcome", rename_all = "snake_case")]
pub enum RgbOutcome {
    /// Its ΔE2000 against the spectrum of the measured metal of its name
    /// at each of the reference's angles of incidence.
    Measured {
        /// The angles, degrees.
        angles_deg: Vec<f64>,
        /// ΔE2000 at each.
        delta_e: Vec<f64>,
    },
    /// The harness's reference (`validation/reference/metals.json`)
    /// could not be read.
    NoReference {
        /// What reading it said.
        detail: String,
    },
    /// The reference has no measured spectrum of this name over the CIE
    /// grid (360–780 nm).
    NoSpectrum,
}

impl RgbOutcome {
    /// The largest ΔE over the angles and its angle, when measured.
    pub fn worst(&self) -> Option<(f64, f64)> {
        match self {
            RgbOutcome::Measured {
                angles_deg,
                delta_e,
            } => angles_deg
                .iter()
                .zip(delta_e)
                .map(|(&a, &e)| (e, a))
                .max_by(|x, y| x.0.total_cmp(&y.0)),
            RgbOutcome::NoReference { .. } | RgbOutcome::NoSpectrum => None,
        }
    }
}
