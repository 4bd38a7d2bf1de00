//! A region's mean from independent passes, the missing share with its
//! standard error, and the smallest difference a Welch test would detect.

use crate::statistics::{self, Sample, Welch};

/// A region's mean radiance (W/(sr·m²)) as one side of a Welch test: the
/// mean of `count` independent estimates and the unbiased variance of one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RegionMean(pub Sample);

impl RegionMean {
    /// From per-pass values (at least two).
    pub fn from_passes(values: impl IntoIterator<Item = f64>) -> Self {
        let values: Vec<f64> = values.into_iter().collect();
        let count = values.len() as f64;
        let mean = values.iter().sum::<f64>() / count;
        let variance = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (count - 1.0);
        Self(Sample {
            mean,
            variance,
            count,
        })
    }

    /// From a render's per-pixel means and variances of one sample, over
    /// the pixels of `mask`, at `samples` samples per pixel: the pixels'
    /// sample streams are independent, so the variance of one sample of the
    /// region's mean is the sum of theirs over the pixel count squared.
    pub fn from_pixels(
        mean: &[f64],
        variance: &[f64],
        mask: &[bool],
        channel: usize,
        samples: u32,
    ) -> Self {
        let inside: Vec<usize> = (0..mask.len()).filter(|&p| mask[p]).collect();
        let n = inside.len() as f64;
        let at = |image: &[f64], p: usize| image[3 * p + channel];
        Self(Sample {
            mean: inside.iter().map(|&p| at(mean, p)).sum::<f64>() / n,
            variance: inside.iter().map(|&p| at(variance, p)).sum::<f64>() / (n * n),
            count: f64::from(samples),
        })
    }

    /// The standard error of the mean.
    pub fn standard_error(self) -> f64 {
        (self.0.variance / self.0.count).sqrt()
    }

    /// Welch's test of equal means, `None` when neither side varies.
    pub fn welch(self, other: RegionMean) -> Option<Welch> {
        statistics::welch(self.0, other.0)
    }

    /// The smallest difference of means that a two-sided Welch test at
    /// level `alpha` detects with probability `power`:
    /// `(t_{α} + t_{2(1 − power)}) · se`, the usual normal-approximation
    /// formula with Student's quantiles at the Welch degrees of freedom.
    pub fn detectable_difference(self, other: RegionMean, alpha: f64, power: f64) -> f64 {
        let Some(w) = statistics::welch(
            self.0,
            Sample {
                mean: other.0.mean + 1.0,
                ..other.0
            },
        ) else {
            return 0.0;
        };
        let se = 1.0 / w.t.abs();
        // A p-value of 1 or more is |t| = 0: no shift needed for it.
        let quantile = |p: f64| statistics::student_t_critical(p, w.dof).unwrap_or(0.0);
        (quantile(alpha) + quantile(2.0 * (1.0 - power))) * se
    }
}

/// The share of the light an estimate misses, `1 − found / full`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Share {
    /// The share.
    pub share: f64,
    /// Its standard error (delta method, the two sides independent).
    pub standard_error: f64,
}

/// `1 − found / full`, with `se = (found / full) · √((se_f / found)² + (se_F / full)²)`.
pub fn share(found: RegionMean, full: RegionMean) -> Share {
    let ratio = found.0.mean / full.0.mean;
    let relative = |m: RegionMean| m.standard_error() / m.0.mean;
    Share {
        share: 1.0 - ratio,
        standard_error: ratio.abs() * relative(found).hypot(relative(full)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_region_mean_from_passes_is_their_mean_and_sample_variance() {
        let m = RegionMean::from_passes([1.0, 2.0, 3.0, 4.0]);
        assert_eq!(m.0.mean, 2.5);
        // Σ (x − 2.5)² / 3 = 5 / 3, exactly representable to the last bit here.
        assert!((m.0.variance - 5.0 / 3.0).abs() < 1e-15);
        assert!((m.standard_error() - (5.0f64 / 12.0).sqrt()).abs() < 1e-15);
    }

    #[test]
    fn the_detectable_difference_is_about_2_8_standard_errors_for_many_samples() {
        // z_{0.005} + z_{0.2} = 2.576 + 0.842 = 3.418 at α = 0.01, power 0.8 (normal limit).
        let side = RegionMean(Sample {
            mean: 0.0,
            variance: 1.0,
            count: 1e6,
        });
        let d = side.detectable_difference(side, 0.01, 0.8);
        let se = (2.0f64 / 1e6).sqrt();
        assert!((d / se - 3.418).abs() < 2e-3, "{}", d / se);
    }

    #[test]
    fn a_share_of_half_the_light_is_one_half() {
        let found = RegionMean(Sample {
            mean: 1.0,
            variance: 0.0,
            count: 4.0,
        });
        let full = RegionMean(Sample {
            mean: 2.0,
            variance: 4.0,
            count: 4.0,
        });
        let s = share(found, full);
        assert_eq!(s.share, 0.5);
        // (1/2) · (1 / 2): full's relative error is √(4/4) / 2.
        assert!((s.standard_error - 0.25).abs() < 1e-15);
    }
}
