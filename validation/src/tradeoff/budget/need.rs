//! What would bring a candidate within a tolerance it misses.

use serde::Serialize;

/// What would bring a candidate within a tolerance it misses at the
/// samples the budget allows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(tag = "need", rename_all = "snake_case")]
pub enum Need {
    /// More samples: the fewest per pixel, a power of two as the budget
    /// renders them, at which its prediction is within the tolerance.
    Samples {
        /// That power of two.
        spp: u64,
    },
    /// No samples: its bias alone is predicted above the tolerance (or it
    /// is deterministic).
    Never,
    /// No samples: the floor of a displayed measure, simulated with no
    /// noise of the candidate's own (its bias, the pilot's noise and the
    /// ground truth's), is predicted above the tolerance.
    Floor,
    /// None it can take: its noise stops falling past these samples per
    /// pixel (a caustic map at its most photons).
    Capped {
        /// The pilot's `most_spp`.
        spp: u32,
    },
}
