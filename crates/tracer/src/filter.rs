//! The pixel filter: where in its pixel each sample's primary ray passes.
//!
//! Under [`PixelFilter::Box`] each sample's point is the first pair its
//! [`Sample`] draws: uniform over the pixel, and over a pixel's first `2^m`
//! samples one point in every elementary interval of area `2^-m` of the
//! pixel (`crate::sampler`), so the pixel is stratified in every grid of
//! `2^a × 2^b` cells at once (16 × 16 at 256 samples, and 256 × 1). The
//! pixel is the unweighted mean of its samples: the integral of the
//! radiance over the pixel with a box of one pixel, Mitsuba's `box` filter
//! (radius ½ pixel, each sample in its own pixel only). Under
//! [`PixelFilter::Center`] every ray passes through the pixel's centre and
//! no number is drawn, so the deterministic integrators' images are what
//! they were before there was a filter.

use crate::camera::PIXEL_CENTRE;
use crate::kinds::PixelFilter;
use crate::sampler::Sample;

/// Where `sample`'s primary ray passes under `filter`, each coordinate in
/// `[0, 1)` from the pixel's top-left corner: the sample's next pair, or
/// the centre (drawing nothing).
#[inline]
pub fn sample_point(filter: PixelFilter, sample: &mut Sample) -> (f64, f64) {
    match filter {
        PixelFilter::Box => {
            let [x, y] = sample.next_2d();
            (x as f64, y as f64)
        }
        PixelFilter::Center => PIXEL_CENTRE,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampler::Sampler;

    /// The box filter's point is uniform over the pixel: the mean point of
    /// one sample in each of 10⁵ pixels is the centre within 5 standard
    /// deviations, 5/√(12 · 10⁵) ≈ 0.0046 per coordinate, and every point
    /// lies inside the pixel.
    #[test]
    fn box_points_are_uniform_over_the_pixel() {
        let n = 100_000;
        let (mut sx, mut sy) = (0.0, 0.0);
        for pixel in 0..n {
            let mut sample = Sampler::for_pixel(11, pixel).sample(0);
            let (x, y) = sample_point(PixelFilter::Box, &mut sample);
            assert!((0.0..1.0).contains(&x) && (0.0..1.0).contains(&y));
            sx += x;
            sy += y;
        }
        assert!((sx / n as f64 - 0.5).abs() < 0.0046);
        assert!((sy / n as f64 - 0.5).abs() < 0.0046);
    }

    /// Stratification: at `spp = 4^k` the `2^k × 2^k` grid of the pixel holds
    /// exactly one sample per cell, as a jittered grid would.
    #[test]
    fn each_square_stratum_holds_exactly_one_sample() {
        for k in 0..5 {
            let (side, spp) = (1_u32 << k, 1_u32 << (2 * k));
            let pixel = Sampler::for_pixel(3, 5);
            let mut seen = vec![0; spp as usize];
            for i in 0..spp {
                let (x, y) = sample_point(PixelFilter::Box, &mut pixel.sample(i));
                let cell = (y * side as f64) as u32 * side + (x * side as f64) as u32;
                seen[cell as usize] += 1;
            }
            assert!(seen.iter().all(|&n| n == 1), "spp {spp}: {seen:?}");
        }
    }

    #[test]
    fn the_centre_filter_draws_no_number() {
        let mut sample = Sampler::for_pixel(1, 2).sample(5);
        assert_eq!(sample_point(PixelFilter::Center, &mut sample), PIXEL_CENTRE);
        assert_eq!(sample.slots_drawn(), 0);
    }
}
