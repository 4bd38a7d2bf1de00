//! The budget's choice among candidates, of any metric: the cheapest in
//! rays within the tolerance, or else the best with what it would need.

use serde::Serialize;

use super::displayed;
use super::linear::{cheapest, need, predict, Prediction};
use super::need::Need;
use super::pilot::{top_spp, Pilot};

/// A prediction of one candidate at its samples, whatever its metric:
/// the bound it puts on the metric and what the render costs.
pub trait Bound: Copy {
    /// The bound on the metric.
    fn bound(&self) -> f64;
    /// Rays one render casts.
    fn rays(&self) -> f64;
}

impl Bound for Prediction {
    fn bound(&self) -> f64 {
        self.rel_rmse
    }

    fn rays(&self) -> f64 {
        self.rays
    }
}

impl Bound for displayed::Prediction {
    fn bound(&self) -> f64 {
        self.bound
    }

    fn rays(&self) -> f64 {
        self.rays
    }
}

/// What the budget decides among candidates.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(tag = "outcome", rename_all = "snake_case")]
pub enum Choice<P = Prediction> {
    /// The candidate (its index) that costs the fewest rays within the
    /// tolerance, at its samples.
    Chosen {
        /// Its index among the candidates.
        index: usize,
        /// Its prediction.
        prediction: P,
    },
    /// No candidate is predicted within the tolerance: the one with the
    /// smallest prediction, at the most samples the budget would render
    /// it at (a power of two).
    Unreachable {
        /// Its index among the candidates.
        index: usize,
        /// Its prediction.
        prediction: P,
        /// What it would need to reach the tolerance.
        need: Need,
    },
}

/// The cheapest of `pilots` within `tolerance` (ties: the smaller
/// prediction, then the earlier candidate), or the best of them when none
/// is; `None` only for no candidates.
pub fn choose(pilots: &[Pilot], energy: f64, tolerance: f64, max_spp: u32) -> Option<Choice> {
    choose_among(
        pilots.len(),
        |i| cheapest(&pilots[i], energy, tolerance, max_spp),
        |i| predict(&pilots[i], energy, top_spp(&pilots[i], max_spp)),
        |i| need(&pilots[i], energy, tolerance),
    )
}

/// The choice among `count` candidates, of any metric: the cheapest in
/// rays of those `cheapest` finds within the tolerance (ties: the smaller
/// bound, then the earlier candidate), or else the smallest `best` (each
/// at the most samples the budget renders it at) with its `need`; `None`
/// only for no candidates.
pub fn choose_among<P: Bound>(
    count: usize,
    cheapest: impl Fn(usize) -> Option<P>,
    best: impl Fn(usize) -> P,
    need: impl Fn(usize) -> Need,
) -> Option<Choice<P>> {
    let within = (0..count)
        .filter_map(|i| cheapest(i).map(|q| (i, q)))
        .min_by(|(_, a), (_, b)| {
            a.rays()
                .total_cmp(&b.rays())
                .then(a.bound().total_cmp(&b.bound()))
        });
    if let Some((index, prediction)) = within {
        return Some(Choice::Chosen { index, prediction });
    }
    (0..count)
        .map(|i| (i, best(i)))
        .min_by(|(_, a), (_, b)| a.bound().total_cmp(&b.bound()))
        .map(|(index, prediction)| Choice::Unreachable {
            index,
            prediction,
            need: need(index),
        })
}
