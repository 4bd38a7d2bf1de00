//! The fixed error measures of a render against the ground truth, the same
//! for every setting so that none can look good by choosing its own; and
//! the same measures against the scene's own settings' render, which say
//! what a shortcut itself changes.
//!
//! All are taken over the *surface pixels*, those whose centre sees an
//! object ([`tracer::job::RenderJob::first_hits`]); the background is
//! whatever the scene says it is for every setting alike.
//!
//! - **Relative RMSE** of linear radiance: `√(Σ (x − t)² / Σ t²)` over the
//!   surface pixels' channels, the error's energy against the image's.
//! - **ΔE2000 of the displayed image**: each pixel as `optics render`'s PNG
//!   shows it (clamped to [0, 1], 8-bit sRGB) in CIELAB under D65, against
//!   the truth shown the same way; the mean and the 99th percentile.
//! - **ꟻLIP** of the displayed image ([`crate::flip`], LDR, at 67
//!   pixels per degree), the rendering field's perceptual difference:
//!   the error map of the whole frame (its filters see across the edge of
//!   the surface), averaged over the surface pixels.
//! - For a Monte Carlo setting, rendered with `r ≥ 2` seeds, the error
//!   splits into **variance** (the per-pixel sample variance across seeds,
//!   of one render) and **bias** (what remains of the mean squared error
//!   once the variance and the truth's own noise are taken out), both
//!   relative to `Σ t²` like the RMSE; **efficiency** is
//!   1 / (relative variance × seconds).

mod mask;
mod setting;
mod shown;
mod truth;

pub use mask::Mask;
pub use setting::{errors, Errors, Split};
pub use shown::percentile;
pub use truth::Truth;

#[cfg(test)]
mod tests;
