//! The measures of one setting's renders against the truth: the relative
//! RMSE, its Monte Carlo split, the light carried, and the displayed
//! image's measures ([`super::shown`]).

use serde::Serialize;
use tracer::render::Image;

use super::mask::Mask;
use super::shown::shown;
use super::truth::{squared, summed, Truth};

/// The measures of one setting.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Errors {
    /// Relative RMSE of linear radiance, the truth's noise taken out.
    pub rel_rmse: f64,
    /// Mean ΔE2000 of the displayed image.
    pub delta_e_mean: f64,
    /// 99th percentile of ΔE2000 of the displayed image.
    pub delta_e_p99: f64,
    /// Mean LDR ꟻLIP of the displayed image over the surface pixels.
    pub flip_mean: f64,
    /// The light the render carries as a share of the truth's, `Σ x / Σ t`
    /// over the surface pixel-channels of linear radiance (the mean over
    /// its renders): `1 − light` is what it leaves out.
    pub light: f64,
    /// The standard error of `light` from the renders' own noise, where
    /// there are several (their sample deviation over `√n`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub light_noise: Option<f64>,
    /// The Monte Carlo split, for settings rendered with several seeds.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub split: Option<Split>,
}

/// A Monte Carlo setting's error in its two parts, relative to `Σ t²`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Split {
    /// The variance of one render, relative.
    pub variance: f64,
    /// The squared bias, relative; 0 where the noise hides it.
    pub bias_squared: f64,
}

/// The measures of the renders `images` of one setting (one image for a
/// deterministic setting; one per seed for a Monte Carlo one, split when
/// there are at least two) against `truth` over `mask`.
///
/// # Panics
///
/// If `images` is empty or an image's size differs from the truth's: the
/// sweep renders every image at the truth's size.
pub fn errors(images: &[Image], truth: &Truth, mask: &Mask) -> Errors {
    assert!(!images.is_empty(), "a setting has at least one render");
    let energy = truth.energy.max(f64::MIN_POSITIVE);
    let channels = 3.0 * mask.count().max(1) as f64;
    let n = images.len() as f64;
    // Mean over renders of Σ (x − t)².
    let squared_error = images
        .iter()
        .map(|image| {
            assert_eq!(image.pixels.len(), truth.image.pixels.len());
            mask.kept()
                .map(|i| squared(image.pixels[i] - truth.image.pixels[i]))
                .sum::<f64>()
        })
        .sum::<f64>()
        / n;
    let floor = truth.noise * channels;
    let shares: Vec<f64> = images
        .iter()
        .map(|image| {
            mask.kept().map(|i| summed(image.pixels[i])).sum::<f64>()
                / truth.light.max(f64::MIN_POSITIVE)
        })
        .collect();
    let light = shares.iter().sum::<f64>() / n;
    let light_noise = (images.len() >= 2).then(|| {
        let spread = shares.iter().map(|s| (s - light).powi(2)).sum::<f64>() / (n - 1.0);
        (spread / n).sqrt()
    });
    let split = (images.len() >= 2).then(|| {
        let variance = mask
            .kept()
            .map(|i| {
                let mean = images
                    .iter()
                    .map(|im| im.pixels[i].as_dvec3())
                    .sum::<glam::DVec3>()
                    / n;
                images
                    .iter()
                    .map(|im| (im.pixels[i].as_dvec3() - mean).length_squared())
                    .sum::<f64>()
                    / (n - 1.0)
            })
            .sum::<f64>();
        Split {
            variance: variance / energy,
            bias_squared: (squared_error - variance - floor).max(0.0) / energy,
        }
    });
    let (delta_e_mean, delta_e_p99, flip_mean) = shown(images, &truth.image, mask);
    Errors {
        rel_rmse: ((squared_error - floor).max(0.0) / energy).sqrt(),
        delta_e_mean,
        delta_e_p99,
        flip_mean,
        light,
        light_noise,
        split,
    }
}
