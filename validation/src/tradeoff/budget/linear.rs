//! The bound on the relative RMSE of linear radiance at given samples, the
//! samples it needs to reach a tolerance, and the cheapest samples that
//! reach it; the budget's module docs ([`super`]) derive the bound.

use serde::Serialize;

use super::need::Need;
use super::pilot::{ladder, Pilot, K};

/// The predicted error of one candidate at its samples.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Prediction {
    /// Samples per pixel (`None`: a deterministic candidate's own).
    pub spp: Option<u32>,
    /// The bias part, relative: `√(B_up / E)`.
    pub bias: f64,
    /// The noise part at `spp` with the cross term, relative.
    pub noise: f64,
    /// The bound on the relative RMSE: `√(bias² + noise²)`.
    pub rel_rmse: f64,
    /// Rays one render casts.
    pub rays: f64,
}

/// `pilot`'s predicted error at `spp` samples per pixel (ignored for a
/// deterministic candidate) against a truth of energy `energy`.
pub fn predict(pilot: &Pilot, energy: f64, spp: u32) -> Prediction {
    let bias_squared = pilot.bias.upper();
    let (spp, noise_squared) = if pilot.samples {
        (Some(spp), noise_squared(pilot, f64::from(spp)))
    } else {
        (None, 0.0)
    };
    let bias = (bias_squared / energy).sqrt();
    let noise = (noise_squared / energy).sqrt();
    Prediction {
        spp,
        bias,
        noise,
        rel_rmse: bias.hypot(noise),
        rays: pilot.rays.at(spp.unwrap_or(0)),
    }
}

/// The squared noise bound of a sampling `pilot` at `n` samples per
/// pixel, with the bias–noise cross term.
fn noise_squared(pilot: &Pilot, n: f64) -> f64 {
    let noise = pilot.noise.sum + 2.0 * K * (2.0 * pilot.noise.squares).sqrt();
    let cross = 2.0 * K * (pilot.cross / n).sqrt();
    noise / n + cross
}

/// The fewest samples per pixel, a power of two with no cap, at which
/// `pilot` is predicted within `tolerance`; or why none is.
pub fn need(pilot: &Pilot, energy: f64, tolerance: f64) -> Need {
    let bias_squared = pilot.bias.upper() / energy;
    let room = tolerance * tolerance - bias_squared;
    if !pilot.samples || room <= 0.0 {
        return Need::Never;
    }
    if pilot.most_spp < u32::MAX {
        return Need::Capped {
            spp: pilot.most_spp,
        };
    }
    (0..64)
        .map(|k| 1u64 << k)
        .filter(|&n| n >= u64::from(pilot.fewest_spp))
        .find(|&n| noise_squared(pilot, n as f64) / energy <= room)
        .map_or(Need::Never, |spp| Need::Samples { spp })
}

/// The fewest samples per pixel, a power of two up to `max_spp` (and the
/// pilot's `most_spp`), at which
/// `pilot` is predicted within `tolerance`; a deterministic candidate
/// within it as it is; `None` where neither is.
pub fn cheapest(pilot: &Pilot, energy: f64, tolerance: f64, max_spp: u32) -> Option<Prediction> {
    ladder(pilot, max_spp)
        .into_iter()
        .map(|n| predict(pilot, energy, n))
        .find(|p| p.rel_rmse <= tolerance)
}
