//! The tracer's renders against Mitsuba 3's: each physically based course
//! scene, by a Whitted integrator written on Mitsuba's own primitives and by
//! Mitsuba's `path` integrator (`python-checks/mitsuba_render.py`, reference
//! `mitsuba_renders.json`), against the tracer's `whitted` and `path`.
//!
//! - **Whitted** renders are deterministic: compared per pixel, away from
//!   edges. A pixel is an edge when a neighbour's Whitted path meets another
//!   object or another shadow (the reference's mask): there a float32
//!   difference in one intersection moves a whole object.
//! - **Path** renders are Monte Carlo: per pixel and channel, Welch's t-test
//!   of the tracer's mean over `n₁` samples against Mitsuba's over `n₂`,
//!   with the per-sample variances of both; the render fails when any p-value
//!   falls below `α / m` for `m` tests (Bonferroni; Holm's step-down rejects
//!   something exactly when this does) and the means differ by more than the
//!   Whitted tolerance, which no number of samples removes. Pixels where
//!   neither side varies are compared as the Whitted ones are. A rejection
//!   that the same test no longer makes once the difference is reduced by
//!   what Mitsuba's own ray offsets move that pixel (measured by the
//!   generator) is a finding about the reference, not a failure; so is one
//!   that the tracer itself makes too when it starts its secondary rays by
//!   Mitsuba's rule ([`MITSUBA_RAY_EPSILON`]): rendered only when some
//!   rejection is left unexplained, and judged by the same test against
//!   Mitsuba. Inside a dielectric sphere, Mitsuba's offset moves each
//!   reflected chord inwards, shortening its distance from the centre, so
//!   chords trapped by total internal reflection (exactly trapped: a
//!   sphere keeps a chord's angle) escape after a dozen bounces, and each
//!   further bounce frees more: that render therefore lets light escape
//!   after as many scatterings as Mitsuba's `path` does, one more than the
//!   suite's `max_depth` (`python-checks/test_bench_vs_mitsuba.py`).
//!
//! The renderer is a parameter ([`Renderer`]), so a deliberately broken render
//! can be shown to be caught. Radiance is in W/(sr·m²) per channel.

mod checks;
mod figure;
mod image_mean;
mod path;
mod reference;
mod runner;
mod whitted;

pub use checks::RenderChecks;
pub use figure::{RenderFigure, TRIPTYCH_GAP};
pub use path::compare_path;
pub use reference::{
    decode, Decoded, MitsubaRenders, PathImages, PathRender, SceneRenders, Tool, WhittedRender,
};
pub use runner::{
    path_statistics, path_statistics_with, sample_statistics, tracer_render, Renderer,
};
pub use whitted::compare_whitted;

use tracer::render::Image;

use crate::check::Check;

/// The reference file.
pub const FILE: &str = "mitsuba_renders.json";
/// Its schema.
pub const SCHEMA: &str = "mitsuba-renders/2";

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

fn tolerance(mitsuba: f64) -> f64 {
    crate::compare::Tolerance::RENDERS.at(mitsuba)
}

fn pixel_label(width: u32, i: usize) -> String {
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
fn summarise_failures(check: &mut Check) {
    const SHOWN: usize = 10;
    if check.failures.len() > SHOWN {
        let rest = check.failures.len() - SHOWN;
        check.failures.truncate(SHOWN);
        check.failures.push(format!("… and {rest} more"));
    }
}

fn flatten(image: &Image) -> Vec<f64> {
    image
        .pixels
        .iter()
        .flat_map(|p| p.to_array())
        .map(f64::from)
        .collect()
}
