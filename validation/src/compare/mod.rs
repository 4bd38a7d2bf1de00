//! One image against a reference render, per pixel and channel: the
//! machinery of the renders' comparison with Mitsuba
//! ([`crate::renders`]) and of `optics compare`, which holds a user's own
//! render against the tracer's.
//!
//! Three tests, each giving per pixel-channel the signed difference and a
//! **score**, the difference in units of what the test allows (a
//! pixel-channel disagrees exactly when its score exceeds 1):
//!
//! - [`tolerance::radiance`]: deterministic radiance, `|image − reference|
//!   ≤ a + r · |reference|` ([`Tolerance::RENDERS`], the Whitted
//!   comparison's), widened by the reference's own noise where it has any;
//! - [`tolerance::codes`]: 8-bit sRGB codes against the codes of that
//!   interval, widened by one code for another renderer's rounding;
//! - [`welch::welch`]: Welch's t per pixel-channel with both sides'
//!   per-sample variances, each guarded by its neighbourhood's
//!   ([`welch::guarded_variance`]), Bonferroni-corrected over the tests; its
//!   per-pixel test ([`welch::pixel_tests`]) is also the path renders'
//!   against Mitsuba's (`crate::renders`).
//!
//! [`regions`] then says where the disagreements are: per region of the
//! image (what the camera sees at each pixel), the pixels compared and
//! disagreeing, the mean and worst difference; [`map`] draws the scores.
//! Radiance is in W/(sr·m²) per channel; images are flat `[R, G, B, …]`
//! rows top to bottom, as [`crate::renders`] flattens them.

mod estimate;
pub mod map;
pub mod regions;
pub mod tolerance;
mod tolerance_bounds;
mod verdicts;
pub mod welch;

pub use estimate::Estimate;
pub use tolerance_bounds::{Tolerance, TOLERANCE_ABSOLUTE, TOLERANCE_RELATIVE};
pub use verdicts::Verdicts;
