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

use glam::Vec3;
use radiometry::colour::{d65_white, delta_e_2000, linear_srgb_to_xyz, srgb_decode, xyz_to_lab};
use serde::Serialize;
use tracer::output::{srgb8, to_srgb8};
use tracer::render::Image;

/// The surface pixels: `true` where the pixel's centre sees an object.
#[derive(Clone, Debug, PartialEq)]
pub struct Mask(Vec<bool>);

impl Mask {
    /// From the first hits of the pixel centres (`None`: background).
    pub fn from_hits(hits: &[Option<u32>]) -> Self {
        Mask(hits.iter().map(Option::is_some).collect())
    }

    /// Every pixel of a `count`-pixel image.
    pub fn all(count: usize) -> Self {
        Mask(vec![true; count])
    }

    /// How many pixels it keeps.
    pub fn count(&self) -> usize {
        self.0.iter().filter(|&&keep| keep).count()
    }

    /// The kept pixels' indices.
    pub(crate) fn kept(&self) -> impl Iterator<Item = usize> + '_ {
        self.0
            .iter()
            .enumerate()
            .filter_map(|(i, &keep)| keep.then_some(i))
    }
}

/// The ground truth: its image, and the variance of its pixel-channels
/// (the mean of two half renders: a quarter of their squared difference).
#[derive(Clone, Debug)]
pub struct Truth {
    /// The converged image.
    pub image: Image,
    /// Mean over the surface pixel-channels of the image's own variance.
    pub noise: f64,
    /// `Σ t²` over the surface pixel-channels.
    energy: f64,
    /// `Σ t` over the surface pixel-channels: the light the measures of
    /// what a render leaves out are shares of.
    light: f64,
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
    /// against it ([`Errors::light`]).
    pub fn light_noise_relative(&self, mask: &Mask) -> f64 {
        (self.noise * 3.0 * mask.count() as f64).sqrt() / self.light.max(f64::MIN_POSITIVE)
    }
}

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
    let displayed_truth = displayed(&truth.image, mask);
    let shown_truth = srgb8(&truth.image);
    let mut delta_e_mean = 0.0;
    let mut delta_e_p99 = 0.0;
    let mut flip_mean = 0.0;
    for image in images {
        let map = crate::flip::error_map(&shown_truth, &srgb8(image), image.width, image.height);
        flip_mean += crate::flip::mean(&map, Some(&mask.0)) / n;
        let mut de: Vec<f64> = displayed(image, mask)
            .iter()
            .zip(&displayed_truth)
            .map(|(&a, &b)| delta_e_2000(a, b))
            .collect();
        delta_e_mean += de.iter().sum::<f64>() / de.len().max(1) as f64 / n;
        delta_e_p99 += percentile(&mut de, 0.99) / n;
    }
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

/// The `q`-quantile (0 to 1) of `values`, the nearest rank; 0 for none.
pub fn percentile(values: &mut [f64], q: f64) -> f64 {
    if values.is_empty() {
        return 0.0;
    }
    values.sort_by(f64::total_cmp);
    let rank = (q * values.len() as f64).ceil() as usize;
    values[rank.clamp(1, values.len()) - 1]
}

/// The kept pixels as the PNG displays them, in CIELAB (D65).
fn displayed(image: &Image, mask: &Mask) -> Vec<radiometry::colour::Lab> {
    let white = d65_white();
    mask.kept()
        .map(|i| {
            let shown = image.pixels[i]
                .to_array()
                .map(|c| srgb_decode(f64::from(to_srgb8(c)) / 255.0));
            xyz_to_lab(linear_srgb_to_xyz(shown), white)
        })
        .collect()
}

fn squared(v: Vec3) -> f64 {
    v.as_dvec3().length_squared()
}

/// The sum of the three channels, in `f64`.
fn summed(v: Vec3) -> f64 {
    v.as_dvec3().element_sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn image(pixels: Vec<Vec3>) -> Image {
        Image {
            width: pixels.len() as u32,
            height: 1,
            pixels,
        }
    }

    fn grey(values: &[f32]) -> Image {
        image(values.iter().map(|&v| Vec3::splat(v)).collect())
    }

    #[test]
    fn a_render_equal_to_the_truth_has_no_error() {
        let truth = grey(&[0.2, 0.5, 0.9]);
        let mask = Mask::all(3);
        let errors = errors(
            std::slice::from_ref(&truth),
            &Truth::new(truth.clone(), 0.0, &mask),
            &mask,
        );
        assert_eq!(errors.rel_rmse, 0.0);
        assert_eq!(errors.delta_e_mean, 0.0);
        assert_eq!(errors.delta_e_p99, 0.0);
        assert_eq!(errors.flip_mean, 0.0);
    }

    /// Truth (1, 1), render (1, 0.5): Σ(x − t)² = 3·0.25, Σt² = 6, so the
    /// relative RMSE is √(1/8), to 1e-12.
    #[test]
    fn relative_rmse_is_the_error_energy_over_the_image_energy() {
        let mask = Mask::all(2);
        let truth = Truth::new(grey(&[1.0, 1.0]), 0.0, &mask);
        let e = errors(&[grey(&[1.0, 0.5])], &truth, &mask);
        assert!((e.rel_rmse - (1.0_f64 / 8.0).sqrt()).abs() < 1e-12);
    }

    #[test]
    fn masked_pixels_do_not_count() {
        let mask = Mask::from_hits(&[Some(0), None]);
        let truth = Truth::new(grey(&[0.5, 0.5]), 0.0, &mask);
        let e = errors(&[grey(&[0.5, 0.0])], &truth, &mask);
        assert_eq!(e.rel_rmse, 0.0);
        assert_eq!(e.delta_e_p99, 0.0);
    }

    /// Two seeds at t + b ± d on every channel: the sample variance of
    /// one render is 2d² per channel; the squared bias is the squared
    /// error of the renders' mean less that mean's expected noise s²/n,
    /// b² − d² here; with b = 0 it is below 0 and reads 0 (both to 1e-4
    /// relative: the pixels are `f32`, and 0.5 ± 0.01 rounds at 3e-8).
    #[test]
    fn variance_and_bias_separate() {
        let (t, d, b) = (0.5_f32, 0.01_f32, 0.05_f32);
        let mask = Mask::all(4);
        let truth = Truth::new(grey(&[t; 4]), 0.0, &mask);
        let energy = 4.0 * 3.0 * f64::from(t * t);
        let unbiased = errors(&[grey(&[t + d; 4]), grey(&[t - d; 4])], &truth, &mask);
        let split = unbiased.split.unwrap();
        let want_variance = 4.0 * 3.0 * 2.0 * f64::from(d * d) / energy;
        assert!((split.variance - want_variance).abs() < 1e-4 * want_variance);
        assert_eq!(split.bias_squared, 0.0);
        let biased = errors(
            &[grey(&[t + b + d; 4]), grey(&[t + b - d; 4])],
            &truth,
            &mask,
        );
        let split = biased.split.unwrap();
        let want_bias = 4.0 * 3.0 * f64::from(b * b - d * d) / energy;
        assert!((split.variance - want_variance).abs() < 1e-4 * want_variance);
        assert!((split.bias_squared - want_bias).abs() < 1e-4 * want_bias);
    }

    /// On random renders (uniform noise of half-width a, so variance a²/3,
    /// and an offset b, over 3000 pixel-channels and 4 seeds) the split
    /// recovers both: the variance within 5 %, the squared bias within
    /// 10 % (a fixed generator: the test is deterministic).
    #[test]
    fn the_split_recovers_variance_and_bias_of_random_renders() {
        let (t, a, b) = (0.5_f32, 0.2_f32, 0.05_f32);
        let pixels = 1000;
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut uniform = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f32 / (1u64 << 53) as f32 * 2.0 - 1.0
        };
        let mask = Mask::all(pixels);
        let truth = Truth::new(grey(&vec![t; pixels]), 0.0, &mask);
        let renders: Vec<Image> = (0..4)
            .map(|_| {
                image(
                    (0..pixels)
                        .map(|_| {
                            Vec3::new(uniform(), uniform(), uniform()) * a + Vec3::splat(t + b)
                        })
                        .collect(),
                )
            })
            .collect();
        let split = errors(&renders, &truth, &mask).split.unwrap();
        let energy = f64::from(t * t);
        let want_variance = f64::from(a * a) / 3.0 / energy;
        let want_bias = f64::from(b * b) / energy;
        assert!(
            (split.variance / want_variance - 1.0).abs() < 0.05,
            "{split:?}"
        );
        assert!(
            (split.bias_squared / want_bias - 1.0).abs() < 0.10,
            "{split:?}"
        );
    }

    /// The truth's own noise is taken out of the RMSE: a render that
    /// differs from the truth by exactly that noise measures 0.
    #[test]
    fn the_truths_noise_is_not_the_renders_error() {
        let mask = Mask::all(2);
        let (a, b) = (grey(&[0.6, 0.4]), grey(&[0.4, 0.6]));
        let truth = Truth::from_renders(&[a, b], &mask);
        assert!((truth.noise - 0.01).abs() < 1e-8, "{}", truth.noise);
        // Against the truth's mean (0.5): squared error 0.01 per channel,
        // all of it the truth's noise; what is left is f32 rounding of the
        // pixels (≈ 1e-8 of the energy) under a square root. The same
        // render against a noiseless truth is 0.2 off.
        let e = errors(&[grey(&[0.6, 0.6])], &truth, &mask);
        assert!(e.rel_rmse < 1e-3, "{}", e.rel_rmse);
        let noiseless = Truth::new(truth.image.clone(), 0.0, &mask);
        let e = errors(&[grey(&[0.6, 0.6])], &noiseless, &mask);
        assert!((e.rel_rmse - 0.2).abs() < 1e-6, "{}", e.rel_rmse);
    }

    /// The light a render carries is `Σ x / Σ t` over the kept channels,
    /// the mean over its renders, with their standard error: renders at
    /// 0.5 and 0.7 of a truth of 2 carry 0.6 ± 0.1 (to 1e-6: `f32`
    /// pixels). The truth's Σt (12) is not its Σt² (24).
    #[test]
    fn the_light_carried_is_the_share_of_the_truths_sum() {
        let mask = Mask::from_hits(&[Some(0), Some(0), None]);
        let truth = Truth::new(grey(&[2.0, 2.0, 9.0]), 0.0, &mask);
        let one = errors(&[grey(&[0.5, 1.5, 0.0])], &truth, &mask);
        assert!((one.light - 0.5).abs() < 1e-6, "{}", one.light);
        assert_eq!(one.light_noise, None);
        let two = errors(
            &[grey(&[1.0, 1.0, 0.0]), grey(&[1.4, 1.4, 0.0])],
            &truth,
            &mask,
        );
        assert!((two.light - 0.6).abs() < 1e-6, "{}", two.light);
        assert!(
            (two.light_noise.unwrap() - 0.1).abs() < 1e-6,
            "{:?}",
            two.light_noise
        );
    }

    /// sRGB (255, 0, 0) against black: colour-science 0.4 gives ΔE2000
    /// 50.407 (`delta_E(XYZ_to_Lab(sRGB_to_XYZ([1, 0, 0])), [0, 0, 0],
    /// method='CIE 2000')`), so both statistics of a one-pixel image are
    /// that, to 0.01.
    #[test]
    fn delta_e_is_taken_on_the_displayed_colours() {
        let mask = Mask::all(1);
        let truth = Truth::new(image(vec![Vec3::ZERO]), 0.0, &mask);
        let red = errors(&[image(vec![Vec3::new(1.0, 0.0, 0.0)])], &truth, &mask);
        assert!(
            (red.delta_e_mean - 50.407).abs() < 0.01,
            "{}",
            red.delta_e_mean
        );
        assert_eq!(red.delta_e_mean, red.delta_e_p99);
        // Radiance past 1 displays as 1: no further error.
        let hot = errors(&[image(vec![Vec3::new(7.0, 0.0, 0.0)])], &truth, &mask);
        assert_eq!(hot.delta_e_mean, red.delta_e_mean);
    }

    /// ꟻLIP orders renders by how far they look from the truth: grey 0.5
    /// shown against 0.52 and 0.6 (8-bit 188 against 190 and 203).
    #[test]
    fn flip_grows_with_the_difference_seen() {
        let square = |v: f32| Image {
            width: 16,
            height: 16,
            pixels: vec![Vec3::splat(v); 256],
        };
        let mask = Mask::all(256);
        let truth = Truth::new(square(0.5), 0.0, &mask);
        let near = errors(&[square(0.52)], &truth, &mask).flip_mean;
        let far = errors(&[square(0.6)], &truth, &mask).flip_mean;
        assert!(0.0 < near && near < far && far <= 1.0, "{near} {far}");
    }

    #[test]
    fn the_percentile_is_the_nearest_rank() {
        let mut values: Vec<f64> = (1..=200).map(f64::from).collect();
        assert_eq!(percentile(&mut values, 0.99), 198.0);
        assert_eq!(percentile(&mut [3.0], 0.99), 3.0);
        assert_eq!(percentile(&mut [], 0.99), 0.0);
    }
}
