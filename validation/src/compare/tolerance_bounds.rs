//! The per-pixel tolerance of deterministic comparisons.

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
