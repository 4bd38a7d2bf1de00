//! The ground truth a setting is measured against: its image, its own
//! noise, and the sums of its surface pixel-channels.

use glam::Vec3;
use tracer::render::Image;

use super::mask::Mask;

/// The ground truth: its image, and the variance of its pixel-channels
/// (the mean of two half renders: a quarter of their squared difference).
#[derive(Clone, Debug)]
pub struct Truth {
    /// The converged image.
    pub image: Image,
    /// Mean over the surface pixel-channels of the image's own variance.
    pub noise: f64,
    /// `Σ t²` over the surface pixel-channels.
    pub(super) energy: f64,
    /// `Σ t` over the surface pixel-channels: the light the measures of
    /// what a render leaves out are shares of.
    pub(super) light: f64,
}

impl Truth {
    /// The mean of independent renders (two halves of the truth, or the
    /// seeds of a Monte Carlo setting), its noise the per-channel sample
    /// variance over their count; one render is taken as noiseless.
    ///
    /// # Panics
    ///
    /// If `renders` is empty.
    pub fn from_renders(renders: &[Image], mask: &Mask) -> Self {
        let n = renders.len() as f64;
        let first = &renders[0];
        let mean = |i: usize| {
            renders
                .iter()
                .map(|r| r.pixels[i].as_dvec3())
                .sum::<glam::DVec3>()
                / n
        };
        let image = Image {
            width: first.width,
            height: first.height,
            pixels: (0..first.pixels.len()).map(|i| mean(i).as_vec3()).collect(),
        };
        let noise = if renders.len() < 2 {
            0.0
        } else {
            let channels = 3.0 * mask.count().max(1) as f64;
            let variance: f64 = mask
                .kept()
                .map(|i| {
                    let m = mean(i);
                    renders
                        .iter()
                        .map(|r| (r.pixels[i].as_dvec3() - m).length_squared())
                        .sum::<f64>()
                        / (n - 1.0)
                })
                .sum();
            variance / channels / n
        };
        Truth::new(image, noise, mask)
    }

    /// `image` with a known mean variance per surface pixel-channel.
    pub fn new(image: Image, noise: f64, mask: &Mask) -> Self {
        let energy = mask.kept().map(|i| squared(image.pixels[i])).sum();
        let light = mask.kept().map(|i| summed(image.pixels[i])).sum();
        Truth {
            image,
            noise,
            energy,
            light,
        }
    }

    /// Whether no light reaches the surface pixels: every relative
    /// measure is then undefined.
    pub fn is_black(&self) -> bool {
        self.energy == 0.0
    }

    /// The truth's noise relative to its energy per channel: the floor
    /// under every relative squared error measured against it.
    pub fn noise_relative(&self, mask: &Mask) -> f64 {
        self.noise * 3.0 * mask.count() as f64 / self.energy.max(f64::MIN_POSITIVE)
    }

    /// The standard deviation of `Σ t` from the truth's own noise,
    /// relative to `Σ t`: `√(Σ σ²) / Σ t`, its pixels' noises taken as
    /// independent. The floor under every share of the light measured
    /// against it ([`Errors::light`](super::Errors::light)).
    pub fn light_noise_relative(&self, mask: &Mask) -> f64 {
        (self.noise * 3.0 * mask.count() as f64).sqrt() / self.light.max(f64::MIN_POSITIVE)
    }
}

/// The squared length of `v`, in `f64`.
pub(super) fn squared(v: Vec3) -> f64 {
    v.as_dvec3().length_squared()
}

/// The sum of the three channels, in `f64`.
pub(super) fn summed(v: Vec3) -> f64 {
    v.as_dvec3().element_sum()
}
