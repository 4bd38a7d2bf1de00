//! Monte Carlo estimates per pixel-channel.

/// Monte Carlo estimates per pixel-channel: the mean of `samples`
/// independent samples and the unbiased variance of one sample.
#[derive(Clone, Copy, Debug)]
pub struct Estimate<'a> {
    /// Means.
    pub mean: &'a [f64],
    /// Per-sample variances (divided by `samples − 1`).
    pub variance: &'a [f64],
    /// Samples per pixel, at least 2.
    pub samples: u32,
}

impl Estimate<'_> {
    /// The standard error of the mean at pixel-channel `i`.
    pub fn standard_error(&self, i: usize) -> f64 {
        (self.variance[i] / f64::from(self.samples)).sqrt()
    }
}
