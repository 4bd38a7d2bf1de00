//! Monte Carlo against Monte Carlo: Welch's t per pixel-channel with both
//! sides' per-sample variances, each guarded by its neighbourhood's
//! ([`guarded_variance`]; [`crate::statistics::welch`]),
//! Bonferroni-corrected over the `m` tests: a pixel-channel disagrees when
//! `p < α/m` **and** the means differ by more than the deterministic
//! tolerance, which no number of samples removes (float32 differences
//! between renderers). Where neither side varies, the deterministic test
//! alone decides.
//!
//! The score is `min(ln p / ln(α/m), |Δ| / tolerance)`: above 1 exactly
//! when both conditions hold.

use super::estimate::Estimate;
use super::tolerance_bounds::Tolerance;
use super::verdicts::{masked, Verdicts};
use crate::statistics::{self, Sample};

/// The t-tests made: how many, and the per-test threshold `α/m`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tests {
    /// `m`, the pixel-channels where some side varies.
    pub count: usize,
    /// `α/m`.
    pub threshold: f64,
}

/// Per pixel-channel, the larger of its own sample variance and the mean of
/// its 3 × 3 neighbourhood's (clipped at the image's border). Light that
/// only a rare path finds (through glass, after a Russian roulette) has a
/// heavy-tailed distribution: a pixel whose few samples all missed the rare
/// large value shows too small a variance as well as too small a mean, and
/// a t-test on it rejects a correct render. Its neighbours integrate nearly
/// the same light, each with its own chances of the rare value; where they
/// vary more, the test takes their variance. This only widens a standard
/// error (a conservative test); the power stated is computed with it.
pub fn guarded_variance(variance: &[f64], width: u32) -> Vec<f64> {
    let width = width as usize;
    let height = variance.len() / (3 * width).max(1);
    let mut guarded = variance.to_vec();
    for y in 0..height {
        for x in 0..width {
            for c in 0..3 {
                let (mut sum, mut count) = (0.0, 0.0);
                for ny in y.saturating_sub(1)..(y + 2).min(height) {
                    for nx in x.saturating_sub(1)..(x + 2).min(width) {
                        sum += variance[3 * (ny * width + nx) + c];
                        count += 1.0;
                    }
                }
                let i = 3 * (y * width + x) + c;
                guarded[i] = variance[i].max(sum / count);
            }
        }
    }
    guarded
}

/// Per pixel-channel of `image` against `reference` (both `width` pixels
/// wide): `None` where `mask` hides it, `Some(None)` where neither side's
/// own samples vary (the deterministic test alone decides), else Welch's t
/// on each side's [`guarded_variance`]. The one per-pixel test of `optics
/// compare` and of the path renders against Mitsuba's.
pub fn pixel_tests(
    image: &Estimate,
    reference: &Estimate,
    width: u32,
    mask: Option<&[bool]>,
) -> Vec<Option<Option<statistics::Welch>>> {
    let guarded = (
        guarded_variance(image.variance, width),
        guarded_variance(reference.variance, width),
    );
    pixel_tests_guarded(image, reference, (&guarded.0, &guarded.1), mask)
}

/// [`pixel_tests`] with each side's [`guarded_variance`] already taken
/// (image's, reference's), for a caller that keeps them.
pub fn pixel_tests_guarded(
    image: &Estimate,
    reference: &Estimate,
    guarded: (&[f64], &[f64]),
    mask: Option<&[bool]>,
) -> Vec<Option<Option<statistics::Welch>>> {
    let side = |e: &Estimate, variance: &[f64], i: usize| Sample {
        mean: e.mean[i],
        variance: variance[i],
        count: f64::from(e.samples),
    };
    let test = |i: usize| {
        let varies = image.variance[i] > 0.0 || reference.variance[i] > 0.0;
        let w = statistics::welch(side(image, guarded.0, i), side(reference, guarded.1, i));
        w.filter(|_| varies)
    };
    (0..reference.mean.len())
        .map(|i| (!masked(mask, i)).then(|| test(i)))
        .collect()
}

/// Welch's t per pixel-channel of `image` against `reference` (both
/// `width` pixels wide), away from `mask` ([`pixel_tests`]), judged at the
/// Bonferroni threshold.
pub fn welch(
    image: &Estimate,
    reference: &Estimate,
    width: u32,
    tolerance: Tolerance,
    alpha: f64,
    mask: Option<&[bool]>,
) -> (Verdicts, Tests) {
    let n = reference.mean.len();
    let outcomes = pixel_tests(image, reference, width, mask);
    let count = outcomes
        .iter()
        .filter(|o| matches!(o, Some(Some(_))))
        .count();
    let threshold = alpha / count.max(1) as f64;
    let test = format!(
        "Welch's t per pixel-channel ({count} tests): disagrees when p < α/m = {threshold:.3e} \
         (α = {alpha}, Bonferroni) and |image − reference| > {:e} + {:e} · |reference|",
        tolerance.absolute, tolerance.relative
    );
    let mut verdicts = Verdicts::new(n, "W/(sr m²)", test);
    for (i, outcome) in outcomes.into_iter().enumerate() {
        let Some(outcome) = outcome else { continue };
        let d = image.mean[i] - reference.mean[i];
        let beyond = d.abs() / tolerance.at(reference.mean[i]);
        verdicts.compared[i] = true;
        verdicts.difference[i] = d;
        verdicts.score[i] = match outcome {
            // ln p / ln(α/m): 1 at the threshold; p underflowing to 0 is 1e-300.
            Some(w) => (w.p.max(1e-300).ln() / threshold.ln()).min(beyond),
            None => beyond,
        };
    }
    (verdicts, Tests { count, threshold })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn estimate<'a>(mean: &'a [f64], variance: &'a [f64], samples: u32) -> Estimate<'a> {
        Estimate {
            mean,
            variance,
            samples,
        }
    }

    #[test]
    fn means_several_standard_errors_apart_disagree() {
        // Standard error of the difference: √(1/100 + 1/100) = 0.1414. One
        // test: threshold 0.01, |t| ≈ 2.63 at 100+ dof. Δ = 0.2 is t = 1.41
        // (agrees), Δ = 0.6 is t = 4.24 (disagrees); both beyond the
        // deterministic tolerance.
        let reference = estimate(&[1.0, 1.0, 1.0], &[1.0, 0.0, 0.0], 100);
        for (shift, disagrees) in [(0.2, false), (0.6, true)] {
            let mean = [1.0 + shift, 1.0, 1.0];
            let image = estimate(&mean, &[1.0, 0.0, 0.0], 100);
            let (v, tests) = welch(&image, &reference, 1, Tolerance::RENDERS, 0.01, None);
            assert_eq!(tests.count, 1);
            assert_eq!(v.disagrees(0), disagrees, "Δ = {shift}: {v:?}");
            assert_eq!(v.disagreeing_count(), usize::from(disagrees));
        }
    }

    #[test]
    fn a_significant_difference_within_the_tolerance_agrees() {
        // Millions of samples resolve a 1e-4 difference, which the float32
        // tolerance (1e-3 relative) allows.
        let reference = estimate(&[1.0, 1.0, 1.0], &[1e-6; 3], 1_000_000);
        let image = estimate(&[1.0001, 1.0, 1.0], &[1e-6; 3], 1_000_000);
        let (v, _) = welch(&image, &reference, 1, Tolerance::RENDERS, 0.01, None);
        assert!(v.score[0] < 1.0 && !v.disagrees(0), "{v:?}");
    }

    #[test]
    fn the_bonferroni_threshold_divides_alpha_by_the_tests() {
        let variance = [1.0; 12];
        let reference = estimate(&[0.5; 12], &variance, 64);
        let (_, tests) = welch(
            &reference,
            &reference,
            4,
            Tolerance::RENDERS,
            0.01,
            Some(&[false, true, false, false]),
        );
        assert_eq!(
            tests,
            Tests {
                count: 9,
                threshold: 0.01 / 9.0
            }
        );
    }
}
