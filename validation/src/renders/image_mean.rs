//! The image's mean against Mitsuba's, per channel: the test that sees a
//! uniform shift of a noisy image (a light's power, a BRDF's scale), which
//! no single pixel's test can. The pixels are independent (each has its own
//! random stream on both sides), so the variance of the image's mean is the
//! sum of the pixels' variances of their means over the pixel count squared;
//! with tens of thousands of pixels the estimate is unbiased and its heavy
//! tails average out, so each side's own per-sample variances are used, not
//! the guarded ones of the per-pixel tests.
//!
//! Pixel-channels the per-pixel tests attributed to Mitsuba's ray offsets
//! are left out of both means; where the mean still differs, the tracer's
//! render under Mitsuba's offset rule is held to the same test, and passing
//! it the difference is a finding about the reference.

use super::common::tolerance;
use crate::check::Check;
use crate::statistics::{self, Sample, Welch};

const CHANNELS: [&str; 3] = ["R", "G", "B"];

/// One side of the test: per pixel-channel means and per-sample variances,
/// and the samples behind each pixel's mean.
#[derive(Clone, Copy)]
pub(super) struct Side<'a> {
    pub mean: &'a [f64],
    pub variance: &'a [f64],
    pub samples: u32,
}

impl Side<'_> {
    /// Channel `c`'s image mean over the pixel-channels `kept`, as a sample
    /// whose standard error is the image mean's: the mean per-sample
    /// variance over `pixels × samples` samples.
    fn channel(&self, c: usize, kept: &[bool]) -> Sample {
        let (mut sum, mut variance, mut pixels) = (0.0, 0.0, 0.0);
        for i in (c..self.mean.len()).step_by(3).filter(|&i| kept[i]) {
            sum += self.mean[i];
            variance += self.variance[i];
            pixels += 1.0;
        }
        Sample {
            mean: sum / pixels,
            variance: variance / pixels,
            count: pixels * f64::from(self.samples),
        }
    }
}

/// What the image-mean tests found.
pub(super) struct ImageMeans {
    /// The least relative shift of a channel's image mean that the test
    /// detects half the time, and its channel.
    pub least_shift: Option<(f64, &'static str)>,
}

/// Judges each channel's image mean at `threshold` (a share of the
/// comparison's Bonferroni family), failing `check` where the means differ
/// beyond the float32 tolerance and the tracer under Mitsuba's offsets
/// (`moved`, asked for only then) does not agree either.
pub(super) fn judge(
    check: &mut Check,
    ours: Side,
    mitsuba: Side,
    kept: &[bool],
    threshold: f64,
    moved: &dyn Fn() -> Option<(Vec<f64>, Vec<f64>)>,
) -> ImageMeans {
    let mut least_shift: Option<(f64, &'static str)> = None;
    for (c, channel) in CHANNELS.iter().enumerate() {
        let (a, b) = (ours.channel(c, kept), mitsuba.channel(c, kept));
        let Some(w) = statistics::welch(a, b) else {
            continue;
        };
        check.measure_in_both(["image mean |t|", "képátlag |t|"], w.t.abs(), channel);
        let standard_error = ((a.variance / a.count) + (b.variance / b.count)).sqrt();
        let critical = statistics::student_t_critical(threshold, w.dof.floor().max(1.0))
            .unwrap_or(f64::INFINITY);
        if b.mean.abs() > 0.0 {
            let shift = (critical * standard_error + tolerance(b.mean)) / b.mean.abs();
            if least_shift.is_none_or(|(s, _)| shift < s) {
                least_shift = Some((shift, channel));
            }
        }
        if !differs(a.mean, b.mean, w, threshold) {
            continue;
        }
        let numbers = |[mine, theirs]: [&str; 2]| {
            format!(
                "{mine} {:.6} (n = {}), {theirs} {:.6} (n = {}), t = {:.2}, p = {:.2e} < {threshold:.2e}",
                a.mean, ours.samples, b.mean, mitsuba.samples, w.t, w.p
            )
        };
        let message = format!(
            "the image's mean, {channel}: {}",
            numbers(["ours", "Mitsuba"])
        );
        let agrees_moved = moved().is_some_and(|(mean, variance)| {
            let moved = Side {
                mean: &mean,
                variance: &variance,
                samples: ours.samples,
            }
            .channel(c, kept);
            statistics::welch(moved, b).is_none_or(|w| !differs(moved.mean, b.mean, w, threshold))
        });
        if agrees_moved {
            check.find([
                format!(
                    "{message}; the tracer under Mitsuba's offset rule agrees: Mitsuba's offsets move this light"
                ),
                format!(
                    "a kép átlaga, {channel}: {}; a sugárkövető a Mitsuba eltolási szabályával egyezik: \
                     ezt a fényt a Mitsuba sugáreltolásai mozdítják el",
                    numbers(["a miénk", "a Mitsubáé"])
                ),
            ]);
        } else {
            check.fail(message);
        }
    }
    ImageMeans { least_shift }
}

/// Whether two means differ significantly and beyond the float32 tolerance.
fn differs(ours: f64, mitsuba: f64, w: Welch, threshold: f64) -> bool {
    w.p < threshold && (ours - mitsuba).abs() > tolerance(mitsuba)
}
