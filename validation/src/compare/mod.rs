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

pub mod map;
pub mod regions;
pub mod tolerance;
pub mod welch;

use serde::Serialize;

/// Absolute part of the per-pixel tolerance of deterministic pixels,
/// W/(sr·m²): a dark pixel's few float32 roundings of order-one terms.
pub const TOLERANCE_ABSOLUTE: f64 = 1e-5;

/// Relative part of the per-pixel tolerance of deterministic pixels. Both
/// sides compute in float32 with different intersection routines and start
/// secondary rays at different offsets (ours: twice the hit's error bound;
/// the reference: 4 ulps of the hit's largest coordinate), so hit points
/// differ by micrometres after a chain of mirrors. The course's Blinn-Phong
/// lobe `cos^s δ` with `s = 100` multiplies a cosine's relative error by `s`:
/// on the kaleidoscope's five-mirror chains that is up to 2 × 10⁻⁴ (ours is
/// that far from an exact float64 trace there; the reference 3 × 10⁻⁶).
/// 10⁻³ covers it with a margin; a wrong law, light unit or camera is
/// percent-level, ten times beyond.
pub const TOLERANCE_RELATIVE: f64 = 1e-3;

/// The per-pixel tolerance of a deterministic comparison: `absolute +
/// relative · |reference|`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Tolerance {
    /// W/(sr·m²).
    pub absolute: f64,
    /// Dimensionless.
    pub relative: f64,
}

impl Tolerance {
    /// The renders' comparison with Mitsuba: [`TOLERANCE_ABSOLUTE`] and
    /// [`TOLERANCE_RELATIVE`], whose documentation says why.
    pub const RENDERS: Tolerance = Tolerance {
        absolute: TOLERANCE_ABSOLUTE,
        relative: TOLERANCE_RELATIVE,
    };

    /// What it allows at a reference value.
    pub fn at(&self, reference: f64) -> f64 {
        self.absolute + self.relative * reference.abs()
    }
}

/// Monte Carlo estimates per pixel-channel: the mean of `samples`
/// independent samples and the unbiased variance of one sample.
#[derive(Clone, Copy, Debug)]
pub struct Estimate<'a> {
    /// Means.
    pub mean: &'a [f64],
    /// Per-sample variances (divided by `samples − 1`).
    pub variance: &'a [f64],
    /// Samples per pixel, at least 2.
    pub samples: u32,
}

impl Estimate<'_> {
    /// The standard error of the mean at pixel-channel `i`.
    pub fn standard_error(&self, i: usize) -> f64 {
        (self.variance[i] / f64::from(self.samples)).sqrt()
    }
}

/// A test's outcome per pixel-channel; masked pixels have a NaN score and
/// difference and are neither compared nor counted.
#[derive(Clone, Debug, PartialEq)]
pub struct Verdicts {
    /// Image − reference, in [`Verdicts::unit`].
    pub difference: Vec<f64>,
    /// The difference in units of what the test allows there (> 1:
    /// disagrees; NaN where a value is not a number, which disagrees).
    pub score: Vec<f64>,
    /// Whether each pixel-channel was compared (not masked).
    pub compared: Vec<bool>,
    /// The unit of the differences: `"W/(sr m²)"` or `"8-bit codes"`.
    pub unit: &'static str,
    /// The test, in words, with its tolerance.
    pub test: String,
}

impl Verdicts {
    fn new(n: usize, unit: &'static str, test: String) -> Self {
        Verdicts {
            difference: vec![f64::NAN; n],
            score: vec![f64::NAN; n],
            compared: vec![false; n],
            unit,
            test,
        }
    }

    /// Whether pixel-channel `i` was compared and disagrees.
    pub fn disagrees(&self, i: usize) -> bool {
        self.compared[i] && !(self.score[i] <= 1.0)
    }

    /// Pixel-channels compared.
    pub fn compared_count(&self) -> usize {
        self.compared.iter().filter(|&&c| c).count()
    }

    /// Pixel-channels that disagree.
    pub fn disagreeing_count(&self) -> usize {
        (0..self.score.len()).filter(|&i| self.disagrees(i)).count()
    }
}

/// Whether pixel `i / 3` of a flat RGB image is masked.
fn masked(mask: Option<&[bool]>, i: usize) -> bool {
    mask.is_some_and(|m| m[i / 3])
}
