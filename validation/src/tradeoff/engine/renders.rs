//! What a sweep's renders are, however they were rendered (here, or as
//! jobs collected): each point's images and times, and where and when
//! they were taken.

use serde::Serialize;
use tracer::render::Image;

use crate::tradeoff::{measure, truth};

/// One point's renders: the images measured, the times.
pub struct Timed {
    /// One image for a deterministic setting; the first
    /// [`crate::tradeoff::jobs::MAX_KEPT`] seeds' for a Monte Carlo one.
    pub images: Vec<Image>,
    /// Every render's time, s.
    pub seconds: Vec<f64>,
    /// Rays over all the renders.
    pub rays: f64,
}

/// How a collected sweep was run: the record's `collected` (absent from
/// a sweep rendered in one run).
#[derive(Clone, Debug, Serialize)]
pub struct Collected {
    /// The plan's id.
    pub plan: String,
    /// How many jobs it ran as.
    pub jobs: usize,
    /// The machines the jobs ran on, each once, in the jobs' order.
    pub machines: Vec<String>,
}

/// Where and when the renders were timed.
pub struct Provenance {
    /// The machine (or machines) the times are of.
    pub machine: String,
    /// The day (or days) they were taken.
    pub date: String,
    /// The load average as the renders ended.
    pub load: Option<String>,
    /// The jobs, when the renders were run as jobs.
    pub collected: Option<Collected>,
}

/// What the measures read, however it was rendered: the truth, each
/// point's renders, and where and when they were taken.
pub type Renders = (measure::Truth, truth::TruthRecord, Vec<Timed>, Provenance);
