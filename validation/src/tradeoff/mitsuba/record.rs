//! The record's field of Mitsuba's truth (`mitsuba` in an
//! `optics.tradeoff` record), what the findings read of it, and what
//! `optics validate` holds it to.

use serde::{Deserialize, Serialize};

/// What a sweep's record says of Mitsuba's truth: measured, or why not.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MitsubaTruth {
    /// Why there is no reference for this sweep, in words.
    NoReference(String),
    /// Every setting against Mitsuba's estimate.
    Measured(AgainstMitsuba),
}

/// The settings measured against Mitsuba's estimate of all the light.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct AgainstMitsuba {
    /// The reference scene's name.
    pub scene: String,
    /// The estimate ([`super::ESTIMATE`]'s name).
    pub estimate: String,
    /// The region ([`super::REGION`]'s name).
    pub region: String,
    /// The reference's width, pixels.
    pub width: u32,
    /// The reference's height, pixels.
    pub height: u32,
    /// Each reference pixel is the mean of `factor × factor` of the sweep's.
    pub factor: u32,
    /// The region's pixels at the reference's size.
    pub pixels: u32,
    /// Mitsuba's independent passes, and its samples per pixel in each.
    pub passes: u32,
    /// Samples per pixel of each pass.
    pub spp: u32,
    /// Mitsuba's bounce limit (the suite's count).
    pub max_depth: u32,
    /// The sweep's own truth against Mitsuba's: the floor.
    pub floor: Against,
    /// Each setting, in the record's order of points.
    pub points: Vec<Against>,
    /// The ranking by relative RMSE under both truths.
    pub ranking: Ranking,
}

/// One image (or one setting's renders) against Mitsuba's estimate.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Against {
    /// The setting's label (`truth` for the floor).
    pub label: String,
    /// `Σx / ΣM` over the region's pixel-channels.
    pub light: f64,
    /// Its standard error from Mitsuba's passes.
    pub light_se: f64,
    /// Relative RMSE against Mitsuba's per-pixel mean.
    pub rel_rmse: f64,
    /// Relative RMSE against the sweep's truth, on the same pixels at the
    /// same size: the ranking's other side (0 for the floor).
    pub rel_rmse_truth: f64,
}

/// The settings ranked by relative RMSE against each truth, compared
/// pair by pair.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Ranking {
    /// Pairs ordered alike under both truths.
    pub concordant: usize,
    /// Pairs ordered the other way, by label; a tie under either truth is
    /// neither.
    pub discordant: Vec<[String; 2]>,
}

impl Ranking {
    /// The pairs of `points` compared by `rel_rmse_truth` and `rel_rmse`.
    pub fn of(points: &[Against]) -> Self {
        let mut concordant = 0;
        let mut discordant = Vec::new();
        for (i, a) in points.iter().enumerate() {
            for b in &points[i + 1..] {
                let ours = (a.rel_rmse_truth - b.rel_rmse_truth).signum();
                let theirs = (a.rel_rmse - b.rel_rmse).signum();
                if a.rel_rmse_truth == b.rel_rmse_truth || a.rel_rmse == b.rel_rmse {
                    continue;
                }
                if ours == theirs {
                    concordant += 1;
                } else {
                    discordant.push([a.label.clone(), b.label.clone()]);
                }
            }
        }
        Ranking {
            concordant,
            discordant,
        }
    }

    /// Whether no pair is ordered the other way.
    pub fn agrees(&self) -> bool {
        self.discordant.is_empty()
    }
}

/// What the findings say of Mitsuba's truth: how much of its light the
/// sweep's truth and the scene's own settings carry, whether the truth's
/// share is 1 within [`crate::tradeoff::findings::NOISE_SIGMAS`] standard errors,
/// and whether the two truths rank the settings alike.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SecondTruth {
    /// The reference's size, pixels.
    pub size: [u32; 2],
    /// The region's pixels.
    pub pixels: u32,
    /// The sweep's truth's light share and its standard error.
    pub truth: [f64; 2],
    /// The scene's own settings' light share and its standard error.
    pub own: [f64; 2],
    /// Whether the truth's share is 1 within the noise.
    pub within_noise: bool,
    /// Pairs of settings ranked, alike or not.
    pub pairs: usize,
    /// Pairs ranked the other way under Mitsuba's truth.
    pub discordant: usize,
}

impl SecondTruth {
    /// From a record's field; `None` where nothing was measured.
    pub fn of(truth: Option<&MitsubaTruth>) -> Option<Self> {
        let Some(MitsubaTruth::Measured(m)) = truth else {
            return None;
        };
        let own = m.points.first()?;
        let floor = &m.floor;
        Some(SecondTruth {
            size: [m.width, m.height],
            pixels: m.pixels,
            truth: [floor.light, floor.light_se],
            own: [own.light, own.light_se],
            within_noise: (floor.light - 1.0).abs()
                <= crate::tradeoff::findings::NOISE_SIGMAS * floor.light_se,
            pairs: m.ranking.concordant + m.ranking.discordant.len(),
            discordant: m.ranking.discordant.len(),
        })
    }
}

/// What `optics validate` holds a record's Mitsuba truth to, given its
/// points' labels in order: each setting's numbers a value the measure
/// can take, in the record's order, and the ranking the one its numbers
/// give. Each failure in words; none for a record without the field.
pub fn hold(truth: Option<&MitsubaTruth>, labels: &[&str]) -> Vec<String> {
    let measured = match truth {
        None => return Vec::new(),
        Some(MitsubaTruth::NoReference(why)) if why.trim().is_empty() => {
            return vec!["no Mitsuba reference, and no reason given".to_owned()]
        }
        Some(MitsubaTruth::NoReference(_)) => return Vec::new(),
        Some(MitsubaTruth::Measured(m)) => m,
    };
    let mut failures = Vec::new();
    let recorded: Vec<&str> = measured.points.iter().map(|p| p.label.as_str()).collect();
    if recorded != labels {
        failures.push(format!(
            "against Mitsuba: the settings {recorded:?} are not the record's {labels:?}"
        ));
    }
    for p in std::iter::once(&measured.floor).chain(&measured.points) {
        let values = [p.light, p.light_se, p.rel_rmse, p.rel_rmse_truth];
        if !values.iter().all(|v| v.is_finite() && *v >= 0.0) {
            failures.push(format!(
                "against Mitsuba: `{}` has light {} ± {}, relative RMSE {} and {}: each must be finite and ≥ 0",
                p.label, p.light, p.light_se, p.rel_rmse, p.rel_rmse_truth
            ));
        }
    }
    if Ranking::of(&measured.points) != measured.ranking {
        failures.push(
            "against Mitsuba: the ranking recorded is not the one its numbers give".to_owned(),
        );
    }
    failures
}
