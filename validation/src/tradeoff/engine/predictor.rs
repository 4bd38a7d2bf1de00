//! The budget's prediction in its metric: the relative RMSE from the
//! pilot's sums ([`crate::tradeoff::budget`]), or a measure of the
//! displayed image from simulated renders
//! ([`crate::tradeoff::budget::displayed`]); one choice for both.

use crate::tradeoff::budget::displayed::{self, Reference, Shown, Simulation};
use crate::tradeoff::budget::{self, Bound, Choice, Need, Pilot, Prediction};
use crate::tradeoff::measure::Mask;
use serde::Serialize;
use tracer::render::Image;

use tracer::scene::Settings;

/// The most samples per pixel the budget gives a candidate: 2^16.
pub const MAX_BUDGET_SPP: u32 = 1 << 16;

/// A candidate's prediction in the budget's metric.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Predicted {
    /// The relative RMSE's bound, its bias and noise.
    RelRmse(Prediction),
    /// A displayed measure's bound, simulated.
    Shown(displayed::Prediction),
}

impl Bound for Predicted {
    fn bound(&self) -> f64 {
        match self {
            Predicted::RelRmse(p) => p.bound(),
            Predicted::Shown(p) => p.bound(),
        }
    }

    fn rays(&self) -> f64 {
        match self {
            Predicted::RelRmse(p) => p.rays,
            Predicted::Shown(p) => p.rays,
        }
    }
}

impl Predicted {
    /// Samples per pixel (`None`: a deterministic candidate's own).
    pub fn spp(&self) -> Option<u32> {
        match self {
            Predicted::RelRmse(p) => p.spp,
            Predicted::Shown(p) => p.spp,
        }
    }
}

/// What predicts every candidate in one metric.
pub enum Predictor {
    /// The relative RMSE, from each candidate's sums and the truth's
    /// energy.
    RelRmse {
        /// One per candidate.
        pilots: Vec<Pilot>,
        /// `Σ t²`, at K deviations down.
        energy: f64,
    },
    /// A displayed measure, from simulated renders.
    Shown {
        /// The measure.
        measure: Shown,
        /// The truth's settings' pilot.
        reference: Reference,
        /// One per candidate.
        simulations: Vec<Simulation>,
    },
}

impl Predictor {
    /// The relative RMSE's predictor.
    pub fn rel_rmse(pilots: Vec<Pilot>, energy: f64) -> Self {
        Predictor::RelRmse { pilots, energy }
    }

    /// `measure`'s predictor, from the pilot's halves of `half_spp`
    /// samples (the reference's and each candidate's, with its pilot), at
    /// a ground truth of `truth_spp`.
    pub fn shown(
        measure: Shown,
        (reference, candidates): (&[Image; 2], &[[Image; 2]]),
        pilots: &[Pilot],
        (half_spp, mask, truth_spp): (u32, &Mask, u32),
    ) -> Self {
        let [a, b] = reference;
        let reference = Reference::new([a, b], half_spp, mask, truth_spp);
        let simulations = candidates
            .iter()
            .zip(pilots)
            .map(|([a, b], pilot)| Simulation::new([a, b], &reference, half_spp, *pilot))
            .collect();
        Predictor::Shown {
            measure,
            reference,
            simulations,
        }
    }

    /// How many candidates it predicts.
    pub fn len(&self) -> usize {
        match self {
            Predictor::RelRmse { pilots, .. } => pilots.len(),
            Predictor::Shown { simulations, .. } => simulations.len(),
        }
    }

    /// Whether it predicts none.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Candidate `index`'s pilot.
    fn pilot(&self, index: usize) -> &Pilot {
        match self {
            Predictor::RelRmse { pilots, .. } => &pilots[index],
            Predictor::Shown { simulations, .. } => simulations[index].pilot(),
        }
    }

    /// Candidate `index`'s prediction at `spp` samples per pixel.
    pub fn at(&self, index: usize, spp: u32) -> Predicted {
        match self {
            Predictor::RelRmse { pilots, energy } => {
                Predicted::RelRmse(budget::predict(&pilots[index], *energy, spp))
            }
            Predictor::Shown {
                measure,
                reference,
                simulations,
            } => Predicted::Shown(simulations[index].predict(reference, *measure, spp)),
        }
    }

    /// Candidate `index`'s fewest samples within `tolerance`, if any.
    pub fn cheapest(&self, index: usize, tolerance: f64) -> Option<Predicted> {
        match self {
            Predictor::RelRmse { pilots, energy } => {
                budget::cheapest(&pilots[index], *energy, tolerance, MAX_BUDGET_SPP)
                    .map(Predicted::RelRmse)
            }
            Predictor::Shown {
                measure,
                reference,
                simulations,
            } => simulations[index]
                .cheapest(reference, *measure, tolerance, MAX_BUDGET_SPP)
                .map(Predicted::Shown),
        }
    }

    /// What candidate `index` would need to reach `tolerance`.
    fn need(&self, index: usize, tolerance: f64) -> Need {
        match self {
            Predictor::RelRmse { pilots, energy } => {
                budget::need(&pilots[index], *energy, tolerance)
            }
            Predictor::Shown {
                measure,
                reference,
                simulations,
            } => simulations[index].need(reference, *measure, tolerance),
        }
    }

    /// The cheapest candidate within `tolerance`, or the best (`None`
    /// only for no candidates), and each candidate's fewest samples
    /// within it.
    pub fn choose(&self, tolerance: f64) -> (Option<Choice<Predicted>>, Vec<Option<Predicted>>) {
        let within: Vec<Option<Predicted>> = (0..self.len())
            .map(|i| self.cheapest(i, tolerance))
            .collect();
        let choice = budget::choose_among(
            self.len(),
            |i| within[i],
            |i| self.at(i, budget::top_spp(self.pilot(i), MAX_BUDGET_SPP)),
            |i| self.need(i, tolerance),
        );
        (choice, within)
    }

    /// Candidate `index`'s error without noise of its own: the relative
    /// bias, or the displayed measure with no samples' noise.
    pub fn bias(&self, index: usize) -> f64 {
        match self {
            Predictor::RelRmse { pilots, energy } => {
                budget::predict(&pilots[index], *energy, 1).bias
            }
            Predictor::Shown {
                measure,
                reference,
                simulations,
            } => simulations[index].floor(reference, *measure),
        }
    }
}

/// The bias of each shortcut of the chosen candidate measured alone, from
/// the candidates that take it alone, in the budget's metric.
pub fn terms(
    candidates: &[crate::tradeoff::pilot::Candidate],
    predictor: &Predictor,
    index: usize,
) -> Vec<(&'static str, f64)> {
    use crate::tradeoff::pilot::Shortcut;
    let chosen = &candidates[index];
    let alone = |shortcut: Shortcut, keep: &dyn Fn(&Settings) -> bool| {
        candidates
            .iter()
            .position(|c| c.shortcut == shortcut && keep(&c.settings))
            .map(|i| predictor.bias(i))
    };
    let s = chosen.settings;
    let mut terms = Vec::new();
    let depth = || alone(Shortcut::MaxDepth, &|c| c.max_depth == s.max_depth);
    let schlick = || alone(Shortcut::Schlick, &|_| true);
    match chosen.shortcut {
        Shortcut::MaxDepth => terms.extend(depth().map(|d| ("max_depth", d))),
        Shortcut::Schlick => terms.extend(schlick().map(|d| ("fresnel", d))),
        Shortcut::MaxDepthAndSchlick => {
            terms.extend(depth().map(|d| ("max_depth", d)));
            terms.extend(schlick().map(|d| ("fresnel", d)));
        }
        Shortcut::Cutoff => terms.push(("throughput_cutoff", predictor.bias(index))),
        Shortcut::Integrator | Shortcut::Scene => {
            let name = if chosen.shortcut == Shortcut::Scene {
                "scene_settings"
            } else {
                "integrator"
            };
            terms.push((name, predictor.bias(index)));
        }
        Shortcut::None => {}
    }
    terms
}
