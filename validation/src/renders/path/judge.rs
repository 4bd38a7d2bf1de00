//! The verdicts of a path comparison: every t-test at the Bonferroni
//! threshold, a rejection explained by Mitsuba's ray offsets kept as a
//! finding; and the pixel-channels where neither side varies.

use super::sides::{Sides, Verdicts};
use crate::case_words;
use crate::check::Check;
use crate::compare::welch::guarded_variance;
use crate::renders::common::{pixel_label, tolerance, ALPHA};
use crate::statistics::{self, Sample, Welch};

/// Judges every t-test at the Bonferroni threshold: a rejection is a
/// failure, or a finding when Mitsuba's ray offsets explain it, by the
/// sensitivity the generator measured or by the tracer's own render under
/// Mitsuba's offset rule. Fills `heat` in units of the threshold's −log (1
/// at the threshold).
pub(super) fn judge_tests<'a>(
    check: &mut Check,
    sides: &Sides,
    tests: &[(usize, Welch)],
    heat: &mut [f64],
    moved_render: &dyn Fn() -> &'a Result<(Vec<f64>, Vec<f64>), String>,
) -> Verdicts {
    // The family: the per-pixel tests and the image's mean in each channel.
    let threshold = ALPHA / (tests.len() + 3) as f64;
    let mut verdicts = Verdicts {
        threshold,
        rejected: 0,
        offset_findings: 0,
        offset_example: None,
        rule_findings: 0,
        rule_example: None,
        explained: vec![false; sides.mitsuba.mean.len()],
    };
    let unexplained = judge_by_sensitivity(check, sides, tests, heat, &mut verdicts);
    if unexplained.is_empty() {
        return verdicts;
    }
    judge_under_offset_rule(check, sides, unexplained, &mut verdicts, moved_render);
    verdicts
}

/// The first pass of [`judge_tests`]: each t-test at the threshold, a
/// rejection within what Mitsuba's own ray offsets move its pixel (the
/// generator's measured sensitivity) kept as a finding. Returns the
/// rejections left unexplained, with their messages `[English, Hungarian]`.
fn judge_by_sensitivity(
    check: &mut Check,
    sides: &Sides,
    tests: &[(usize, Welch)],
    heat: &mut [f64],
    verdicts: &mut Verdicts,
) -> Vec<(usize, [String; 2])> {
    let (ours, m_mean) = (sides.ours.0, &sides.mitsuba.mean);
    let offset_sensitivity = &sides.mitsuba.offset_sensitivity;
    let threshold = verdicts.threshold;
    let mut unexplained = Vec::new();
    for &(i, w) in tests {
        heat[i] = w.p.max(1e-300).ln() / threshold.ln();
        check.measure_at_in_both(["|t|", "|t|"], w.t.abs(), || pixel_label(sides.width, i));
        let difference = (ours[i] - m_mean[i]).abs();
        if w.p >= threshold || difference <= tolerance(m_mean[i]) {
            continue;
        }
        // The same test of |difference| ≤ what Mitsuba's own ray offsets
        // move this pixel by: passing it, the disagreement is the reference's.
        let allowance = tolerance(m_mean[i]) + offset_sensitivity[i];
        let standard_error = difference / w.t.abs();
        let shifted = (difference - allowance).max(0.0) / standard_error;
        let p_shifted = statistics::student_t_two_sided(shifted.abs(), w.dof);
        let label = pixel_label(sides.width, i);
        let figures = |[mine, theirs]: [&str; 2]| {
            format!(
                "{mine} {:.6} (n = {}), {theirs} {:.6} (n = {}), t = {:.2}, p = {:.2e} < {threshold:.2e}",
                ours[i], sides.our_samples, m_mean[i], sides.mitsuba_samples, w.t, w.p
            )
        };
        let message = [
            format!("{label}: {}", figures(["ours", "Mitsuba"])),
            format!(
                "{}: {}",
                case_words::in_hungarian(&label),
                figures(["a miénk", "a Mitsubáé"])
            ),
        ];
        if p_shifted >= threshold {
            verdicts.offset_findings += 1;
            verdicts.explained[i] = true;
            if verdicts.offset_example.is_none() {
                let [en, hu] = message;
                let moved = offset_sensitivity[i];
                verdicts.offset_example = Some([
                    format!("{en}, within the {moved:.2e} that Mitsuba's ray offsets move this pixel"),
                    format!("{hu}, azon a {moved:.2e}-n belül, amennyivel a Mitsuba sugáreltolásai ezt a képpontot elmozdítják"),
                ]);
            }
        } else {
            unexplained.push((i, message));
        }
    }
    unexplained
}

/// The second pass of [`judge_tests`]: each rejection left is judged again
/// by the same test against the tracer's render under Mitsuba's offset
/// rule; agreeing there, it is a finding, else a failure.
fn judge_under_offset_rule<'a>(
    check: &mut Check,
    sides: &Sides,
    unexplained: Vec<(usize, [String; 2])>,
    verdicts: &mut Verdicts,
    moved_render: &dyn Fn() -> &'a Result<(Vec<f64>, Vec<f64>), String>,
) {
    let m_mean = &sides.mitsuba.mean;
    let threshold = verdicts.threshold;
    let moved = moved_render().as_ref().map(|(mean, variance)| {
        let guarded = guarded_variance(variance, sides.width);
        (mean, guarded)
    });
    for (i, message) in unexplained {
        let agrees = moved.as_ref().ok().and_then(|(mean, variance)| {
            let side = |mean, variance, count: u32| Sample {
                mean,
                variance,
                count: count as f64,
            };
            let difference = (mean[i] - m_mean[i]).abs();
            let w = statistics::welch(
                side(mean[i], variance[i], sides.our_samples),
                side(m_mean[i], sides.variance.1[i], sides.mitsuba_samples),
            );
            let agrees = difference <= tolerance(m_mean[i]) || w.is_some_and(|w| w.p >= threshold);
            agrees.then_some(mean[i])
        });
        match agrees {
            Some(moved_mean) => {
                verdicts.rule_findings += 1;
                verdicts.explained[i] = true;
                if verdicts.rule_example.is_none() {
                    let [en, hu] = message;
                    verdicts.rule_example = Some([
                        format!("{en}; under Mitsuba's offsets ours {moved_mean:.6}"),
                        format!("{hu}; a Mitsuba sugáreltolásaival a miénk {moved_mean:.6}"),
                    ]);
                }
            }
            None => {
                verdicts.rejected += 1;
                check.fail_in_both(message);
            }
        }
    }
    if let Err(e) = moved_render() {
        check.fail(format!(
            "the render under Mitsuba's offset rule failed: {e}"
        ));
    }
}

/// Pixel-channels where neither side varies, compared as the Whitted ones are.
pub(super) fn judge_deterministic(
    check: &mut Check,
    sides: &Sides,
    pixels: &[usize],
    heat: &mut [f64],
) {
    let (ours, m_mean) = (sides.ours.0, &sides.mitsuba.mean);
    for &i in pixels {
        let d = (ours[i] - m_mean[i]).abs();
        heat[i] = d / tolerance(m_mean[i]);
        if !(d <= tolerance(m_mean[i])) {
            check.fail(format!(
                "{}: neither side varies; ours {:.7}, Mitsuba {:.7}",
                pixel_label(sides.width, i),
                ours[i],
                m_mean[i]
            ));
        }
    }
}
