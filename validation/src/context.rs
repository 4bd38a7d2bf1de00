//! What a run of the checks is against and how much of it: the suite's
//! vocabulary, shared by the harness ([`crate::suite`]) and the checks it
//! runs, which take it as a plain value.

use std::path::PathBuf;

/// What the checks run against, and how much of them.
#[derive(Clone, Debug)]
pub struct Context {
    /// The directory holding the reference JSON files.
    pub reference_dir: PathBuf,
    /// The suite's checkout, where the scene files that the references name
    /// are read (to tell a reference made from an older scene).
    pub checkout: PathBuf,
    /// The reduced set: fewer timing iterations and fewer samples.
    pub quick: bool,
}

/// A count of samples (or renders) for the full run and for `--quick`.
#[derive(Clone, Copy, Debug)]
pub struct Samples {
    /// With `--quick`.
    pub quick: u32,
    /// Without.
    pub full: u32,
}

impl Context {
    /// The count of `samples` for this run.
    pub fn samples(&self, samples: Samples) -> u32 {
        if self.quick {
            samples.quick
        } else {
            samples.full
        }
    }
}
