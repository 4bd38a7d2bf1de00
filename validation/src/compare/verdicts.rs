//! A test's outcome per pixel-channel, and the mask that excludes pixels.

/// A test's outcome per pixel-channel; masked pixels have a NaN score and
/// difference and are neither compared nor counted.
#[derive(Clone, Debug, PartialEq)]
pub struct Verdicts {
    /// Image − reference, in [`Verdicts::unit`].
    pub difference: Vec<f64>,
    /// The difference in units of what the test allows there (> 1:
    /// disagrees; NaN where a value is not a number, which disagrees).
    pub score: Vec<f64>,
    /// Whether each pixel-channel was compared (not masked).
    pub compared: Vec<bool>,
    /// The unit of the differences: `"W/(sr m²)"` or `"8-bit codes"`.
    pub unit: &'static str,
    /// The test, in words, with its tolerance.
    pub test: String,
}

impl Verdicts {
    pub(super) fn new(n: usize, unit: &'static str, test: String) -> Self {
        Verdicts {
            difference: vec![f64::NAN; n],
            score: vec![f64::NAN; n],
            compared: vec![false; n],
            unit,
            test,
        }
    }

    /// Whether pixel-channel `i` was compared and disagrees.
    pub fn disagrees(&self, i: usize) -> bool {
        self.compared[i] && !(self.score[i] <= 1.0)
    }

    /// Pixel-channels compared.
    pub fn compared_count(&self) -> usize {
        self.compared.iter().filter(|&&c| c).count()
    }

    /// Pixel-channels that disagree.
    pub fn disagreeing_count(&self) -> usize {
        (0..self.score.len()).filter(|&i| self.disagrees(i)).count()
    }
}

/// Whether pixel `i / 3` of a flat RGB image is masked.
pub(super) fn masked(mask: Option<&[bool]>, i: usize) -> bool {
    mask.is_some_and(|m| m[i / 3])
}
