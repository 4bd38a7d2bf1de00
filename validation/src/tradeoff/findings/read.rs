//! The findings of one sweep, read from its record's measured rows.

use super::field::{Accuracy, Findings, Shortcut, TimingNoise, Upgrade};
use super::rows::{bounces, light_left_out, local_against_whitted, same_work, schlick};
use super::thresholds::NEARER;
use crate::tradeoff::mitsuba::SecondTruth;
use crate::tradeoff::record::{Point, Record};
use crate::tradeoff::verdict::{Verdict, JUST_NOTICEABLE, WORTH_IT};

impl Findings {
    /// What `record`'s rows say; the scene's own settings are its first
    /// point.
    pub fn of(record: &Record) -> Self {
        let points = &record.points;
        let Some((base, rest)) = points.split_first() else {
            return Findings::empty(record);
        };
        let ratio = |p: &Point| p.seconds_median / base.seconds_median.max(f64::MIN_POSITIVE);
        let shortcut = |p: &Point| Shortcut {
            label: p.label.clone(),
            time_ratio: ratio(p),
            delta_e_p99: p.against_scene.delta_e_p99,
        };
        let same: Vec<&Point> = rest.iter().filter(|p| same_work(base, p)).collect();
        let timing_noise = (!same.is_empty()).then(|| TimingNoise {
            labels: same.iter().map(|p| p.label.clone()).collect(),
            ratios: [
                same.iter().map(|p| ratio(p)).fold(f64::INFINITY, f64::min),
                same.iter().map(|p| ratio(p)).fold(0.0, f64::max),
            ],
        });
        let [least, most] = timing_noise.as_ref().map_or([1.0, 1.0], |t| t.ratios);
        let with = |verdict: Verdict| {
            let mut list: Vec<Shortcut> = rest
                .iter()
                .filter(|p| p.verdict == Some(verdict) && !same_work(base, p))
                .map(shortcut)
                .collect();
            list.sort_by(|a, b| a.time_ratio.total_cmp(&b.time_ratio));
            list
        };
        let mut worth_it = with(Verdict::WorthIt);
        worth_it.retain(|s| s.time_ratio < least);
        let mut no_gain = with(Verdict::Unseen);
        no_gain.retain(|s| s.time_ratio > most.max(1.0 / WORTH_IT));
        let mut upgrades: Vec<Upgrade> = rest
            .iter()
            .filter(|p| {
                p.pareto.iter().any(|m| m == "rel_rmse")
                    && p.errors.rel_rmse <= NEARER * base.errors.rel_rmse
                    && p.against_scene.delta_e_p99 > JUST_NOTICEABLE
            })
            .map(|p| Upgrade {
                label: p.label.clone(),
                time_ratio: ratio(p),
                rel_rmse: p.errors.rel_rmse,
                delta_e_p99: p.errors.delta_e_p99,
            })
            .collect();
        upgrades.sort_by(|a, b| a.time_ratio.total_cmp(&b.time_ratio));
        Findings {
            own: Accuracy {
                rel_rmse: base.errors.rel_rmse,
                delta_e_p99: base.errors.delta_e_p99,
            },
            timing_noise,
            worth_it,
            seen: with(Verdict::Trade),
            no_gain,
            upgrades,
            light_left_out: light_left_out(record, base, rest),
            bounces: bounces(base, rest),
            schlick: schlick(base, rest, ratio),
            local_against_whitted: local_against_whitted(base, rest),
            metals: record.rgb_against_spectrum.clone(),
            mitsuba: SecondTruth::of(record.mitsuba.as_ref()),
        }
    }

    fn empty(record: &Record) -> Self {
        Findings {
            own: Accuracy {
                rel_rmse: f64::NAN,
                delta_e_p99: f64::NAN,
            },
            timing_noise: None,
            worth_it: Vec::new(),
            seen: Vec::new(),
            no_gain: Vec::new(),
            upgrades: Vec::new(),
            light_left_out: None,
            bounces: None,
            schlick: None,
            local_against_whitted: None,
            metals: record.rgb_against_spectrum.clone(),
            mitsuba: SecondTruth::of(record.mitsuba.as_ref()),
        }
    }
}
