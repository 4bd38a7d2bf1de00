//! What a scene's sweep says of each shortcut, read from its record once:
//! which are worth their time and which are seen, the light each
//! integrator leaves out, what the last bounces buy, what Schlick's law
//! costs (over the whole image and at grazing angles), whether the local
//! model can be told from Whitted's, and what three channels cost the
//! scene's metals. The command writes these into the record and words
//! them; nothing here measures, it only reads the measured rows.

mod field;
mod read;
mod rows;
mod thresholds;

pub use field::{
    Accuracy, BounceStep, Bounces, Findings, GrazingCost, LeftOut, LightLeftOut,
    LocalAgainstWhitted, MetalRgb, RgbOutcome, Schlick, Shortcut, TimingNoise, Upgrade,
};
pub use thresholds::{GRAZING_COS, NEARER, NOISE_SIGMAS};

#[cfg(test)]
mod tests;
