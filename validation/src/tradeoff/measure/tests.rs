//! The fixed measures on small images whose errors are known by
//! construction.

use glam::Vec3;
use tracer::render::Image;

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
                    .map(|_| Vec3::new(uniform(), uniform(), uniform()) * a + Vec3::splat(t + b))
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
