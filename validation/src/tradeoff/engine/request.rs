//! A sweep as a front end asks for it: the scene, its size, the samples,
//! the repeats and where the results go, settled and range-checked by
//! the front end that took them.

use std::path::PathBuf;

use crate::checkout::Lookup;

/// What a sweep is to measure, and how.
#[derive(Clone, Debug, PartialEq)]
pub struct SweepRequest {
    /// The scene file.
    pub scene: PathBuf,
    /// Image width in pixels (the scene's when `None`).
    pub width: Option<u32>,
    /// Image height in pixels (the scene's when `None`).
    pub height: Option<u32>,
    /// Samples per pixel of the Monte Carlo integrators on the ladder
    /// when the scene's own integrator is deterministic.
    pub spp: u32,
    /// Samples per pixel of the ground truth (two halves of half as many).
    pub truth_spp: u32,
    /// Renders per setting, at least.
    pub repeats: u32,
    /// Seconds a setting's renders add up to, at least (at most
    /// [`super::MAX_RENDERS`] renders).
    pub min_seconds: f64,
    /// Directory of the results and the truth's cache.
    pub out: PathBuf,
    /// Whether course_rough is measured as the suite's Lambert stand-in.
    pub lambert: bool,
    /// Whether the truth is rendered again though a cached one matches.
    pub fresh: bool,
    /// Worker threads (all cores when `None`).
    pub threads: Option<usize>,
    /// Where the checkout is (its references: Mitsuba's renders and the
    /// metals' spectra; its plot script), as the front end was told.
    pub checkout: Lookup,
}

impl SweepRequest {
    /// The command line that reproduces the sweep (the record's
    /// `command`, and the plan's `planned_as`).
    pub fn command_line(&self) -> String {
        let mut words = vec![format!("optics tradeoff {}", self.scene.display())];
        if let Some(w) = self.width {
            words.push(format!("--width {w}"));
        }
        if let Some(h) = self.height {
            words.push(format!("--height {h}"));
        }
        if self.lambert {
            words.push("--lambert".to_owned());
        }
        words.push(format!(
            "--spp {} --truth-spp {} --repeats {} --min-seconds {}",
            self.spp, self.truth_spp, self.repeats, self.min_seconds
        ));
        words.join(" ")
    }
}
