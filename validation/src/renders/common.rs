//! What the renders' comparisons share: Mitsuba's ray offset, the
//! false-alarm rate, a scene's outcome and the helpers that word and
//! flatten pixels.

use tracer::render::Image;

use super::figure::RenderFigure;
use crate::check::Check;

/// Mitsuba 3's `RayEpsilon` in `float32`, `1500 · 2⁻²⁴`: its secondary rays
/// start `RayEpsilon (1 + max |p_i|)` off the surface along the normal
/// (`Interaction::spawn_ray`), which the tracer reproduces as
/// `RayOffset::Scaled(MITSUBA_RAY_EPSILON)`.
pub const MITSUBA_RAY_EPSILON: f64 = 1500.0 / 16_777_216.0;

/// Family-wise false-alarm rate of a path comparison: one correct render in
/// a hundred may fail by chance.
pub const ALPHA: f64 = 0.01;

/// Outcome of one scene's comparison.
pub struct Compared {
    /// The check.
    pub check: Check,
    /// Its figure.
    pub figure: RenderFigure,
}

pub(super) fn tolerance(mitsuba: f64) -> f64 {
    crate::compare::Tolerance::RENDERS.at(mitsuba)
}

pub(super) fn pixel_label(width: u32, i: usize) -> String {
    const CHANNEL: [&str; 3] = ["R", "G", "B"];
    let pixel = i / 3;
    format!(
        "pixel ({}, {}) {}",
        pixel as u32 % width,
        pixel as u32 / width,
        CHANNEL[i % 3]
    )
}

/// Keeps the first failures and counts the rest.
pub(super) fn summarise_failures(check: &mut Check) {
    const SHOWN: usize = 10;
    if check.failures.len() > SHOWN {
        let rest = check.failures.len() - SHOWN;
        check.keep_failures(
            SHOWN,
            [format!("… and {rest} more"), format!("… és még {rest}")],
        );
    }
}

pub(super) fn flatten(image: &Image) -> Vec<f64> {
    image
        .pixels
        .iter()
        .flat_map(|p| p.to_array())
        .map(f64::from)
        .collect()
}
