//! The pixel filter: where in its pixel each sample's primary ray passes.
//!
//! Under [`PixelFilter::Box`] a pixel's `spp` samples are stratified over
//! the pixel ([`Strata`]) and each is jittered uniformly within its
//! stratum, from the pixel's own random stream (`crate::rng`), so the image
//! still depends on the seed alone. The pixel is the unweighted mean of its
//! samples: the integral of the radiance over the pixel with a box of one
//! pixel, Mitsuba's `box` filter (radius ½ pixel, each sample in its own
//! pixel only). Under [`PixelFilter::Center`] every ray passes through the
//! pixel's centre and no random number is drawn, so the deterministic
//! integrators' images are what they were before there was a filter.

use crate::camera::PIXEL_CENTRE;
use crate::rng::Pcg32;
use crate::scene::PixelFilter;

/// A grid of `columns × rows` equal strata covering the pixel, one sample
/// in each.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Strata {
    /// Strata across the pixel.
    pub columns: u32,
    /// Strata down the pixel.
    pub rows: u32,
}

impl Strata {
    /// The most nearly square grid of exactly `spp` strata: `rows` the
    /// largest divisor of `spp` not above `√spp`. A square `spp` gets its
    /// `n × n` grid (64: 8 × 8); others the closest factor pair (8: 4 × 2);
    /// a prime a one-dimensional stratification across the pixel (7: 7 × 1).
    /// `spp` 0 is taken as 1.
    pub fn for_samples(spp: u32) -> Self {
        let spp = spp.max(1);
        let mut rows = (spp as f64).sqrt() as u32;
        // The float square root can round up past an exact root's neighbour.
        while rows * rows > spp {
            rows -= 1;
        }
        while !spp.is_multiple_of(rows) {
            rows -= 1;
        }
        Strata {
            columns: spp / rows,
            rows,
        }
    }

    /// The point of sample `k` (0-based) within the pixel, each coordinate in
    /// `[0, 1)` from the top-left corner: its stratum, left to right then top
    /// to bottom, jittered by two numbers from `rng`.
    pub fn point(&self, k: u32, rng: &mut Pcg32) -> (f64, f64) {
        let (column, row) = (k % self.columns, (k / self.columns) % self.rows);
        let (u, v) = (rng.next_f32() as f64, rng.next_f32() as f64);
        (
            (column as f64 + u) / self.columns as f64,
            (row as f64 + v) / self.rows as f64,
        )
    }
}

/// Where sample `k` of a pixel passes under `filter`: a jittered point of
/// its stratum (drawing two numbers from `rng`), or the centre (drawing
/// none).
pub fn sample_point(filter: PixelFilter, strata: &Strata, k: u32, rng: &mut Pcg32) -> (f64, f64) {
    match filter {
        PixelFilter::Box => strata.point(k, rng),
        PixelFilter::Center => PIXEL_CENTRE,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strata_are_the_most_square_grid_of_exactly_spp_cells() {
        let cases = [
            (1, (1, 1)),
            (2, (2, 1)),
            (4, (2, 2)),
            (7, (7, 1)),
            (8, (4, 2)),
            (12, (4, 3)),
            (64, (8, 8)),
            (1 << 20, (1024, 1024)),
            ((1 << 20) - 1, (1025, 1023)),
        ];
        for (spp, (columns, rows)) in cases {
            let strata = Strata::for_samples(spp);
            assert_eq!((strata.columns, strata.rows), (columns, rows), "spp {spp}");
            assert_eq!(strata.columns * strata.rows, spp);
        }
    }

    /// Stratification: sample k lies in its own cell, so every cell of the
    /// grid holds exactly one of the spp samples.
    #[test]
    fn each_stratum_holds_exactly_one_sample() {
        for spp in [1, 3, 6, 16, 30] {
            let strata = Strata::for_samples(spp);
            let mut rng = Pcg32::for_pixel(3, 5);
            let mut seen = vec![0; spp as usize];
            for k in 0..spp {
                let (x, y) = strata.point(k, &mut rng);
                assert!((0.0..1.0).contains(&x) && (0.0..1.0).contains(&y));
                let cell = (y * strata.rows as f64) as u32 * strata.columns
                    + (x * strata.columns as f64) as u32;
                seen[cell as usize] += 1;
            }
            assert!(seen.iter().all(|&n| n == 1), "spp {spp}: {seen:?}");
        }
    }

    /// The jitter is uniform over the pixel: with one stratum the mean
    /// point of 10⁵ samples is the centre within 5 standard deviations,
    /// 5/√(12 · 10⁵) ≈ 0.0046 per coordinate.
    #[test]
    fn box_jitter_is_uniform_over_the_pixel() {
        let strata = Strata::for_samples(1);
        let mut rng = Pcg32::for_pixel(11, 0);
        let n = 100_000;
        let (mut sx, mut sy) = (0.0, 0.0);
        for _ in 0..n {
            let (x, y) = sample_point(PixelFilter::Box, &strata, 0, &mut rng);
            sx += x;
            sy += y;
        }
        assert!((sx / n as f64 - 0.5).abs() < 0.0046);
        assert!((sy / n as f64 - 0.5).abs() < 0.0046);
    }

    #[test]
    fn the_centre_filter_draws_no_random_number() {
        let strata = Strata::for_samples(16);
        let (mut a, b) = (Pcg32::for_pixel(1, 2), Pcg32::for_pixel(1, 2));
        assert_eq!(
            sample_point(PixelFilter::Center, &strata, 5, &mut a),
            PIXEL_CENTRE
        );
        assert_eq!(a.clone().next_u32(), b.clone().next_u32());
    }
}
