//! Path against path: Monte Carlo renders compared per pixel and channel by
//! Welch's t-test, Bonferroni-corrected, a rejection explained by Mitsuba's
//! own ray offsets recorded as a finding about the reference.

use super::figure::triptych;
use super::image_mean;
use super::{pixel_label, summarise_failures, tolerance, Compared, Decoded, PathImages, ALPHA};
use crate::check::Check;
use crate::compare::welch::{guarded_variance, pixel_tests_guarded};
use crate::compare::{Estimate, TOLERANCE_ABSOLUTE, TOLERANCE_RELATIVE};
use crate::statistics::{self, Sample, Welch};

/// Both sides of a path comparison, per pixel-channel: the means, the
/// per-sample variances and the sample counts.
struct Sides<'a> {
    ours: (&'a [f64], &'a [f64]),
    our_samples: u32,
    mitsuba: &'a PathImages,
    mitsuba_samples: u32,
    width: u32,
    /// Each side's per-sample variance as the tests use it
    /// ([`guarded_variance`]): ours, Mitsuba's.
    variance: (Vec<f64>, Vec<f64>),
}

/// What the t-tests found, for the check's metrics.
struct Verdicts {
    threshold: f64,
    rejected: usize,
    offset_findings: usize,
    offset_example: Option<String>,
    rule_findings: usize,
    rule_example: Option<String>,
    /// Per pixel-channel: a rejection attributed to Mitsuba's offsets.
    explained: Vec<bool>,
}

/// The render under Mitsuba's offset rule, made once when first asked for.
type Moved = std::cell::OnceCell<Result<(Vec<f64>, Vec<f64>), String>>;

/// The tracer's per-pixel mean and per-sample variance with its secondary
/// rays started by Mitsuba's rule ([`super::MITSUBA_RAY_EPSILON`]); asked
/// for only when a rejection is left that the measured offset sensitivity
/// does not explain.
pub type UnderMitsubaOffsets<'a> = &'a dyn Fn() -> Result<(Vec<f64>, Vec<f64>), String>;

/// Path against path: Welch's t per pixel and channel, Bonferroni-corrected,
/// over every pixel of Mitsuba's box-filtered render (no edge is masked:
/// both sides integrate the same pixel).
pub fn compare_path(
    name: &str,
    reference: &Decoded,
    mitsuba_samples: u32,
    ours: (&[f64], &[f64]),
    our_samples: u32,
    under_mitsuba_offsets: UnderMitsubaOffsets,
) -> Option<Compared> {
    let mitsuba = reference.path.as_ref()?;
    let scene = &mitsuba.scene;
    let sides = Sides {
        ours,
        our_samples,
        mitsuba,
        mitsuba_samples,
        width: scene.width,
        variance: (
            guarded_variance(ours.1, scene.width),
            guarded_variance(&mitsuba.variance, scene.width),
        ),
    };
    let mut check = new_check(name);
    if ours.0.len() != mitsuba.mean.len() {
        check.fail(format!(
            "the render has {} values, the reference {}",
            ours.0.len(),
            mitsuba.mean.len()
        ));
    }
    let Split {
        tests,
        deterministic,
        sum,
        compared,
    } = split(&mut check, &sides);
    let mut heat = vec![f64::NAN; mitsuba.mean.len()];
    let moved = Moved::new();
    let moved_render = || moved.get_or_init(under_mitsuba_offsets);
    let verdicts = judge_tests(&mut check, &sides, &tests, &mut heat, &moved_render);
    let kept: Vec<bool> = verdicts.explained.iter().map(|&e| !e).collect();
    let image = image_mean::judge(
        &mut check,
        image_mean::Side {
            mean: ours.0,
            variance: ours.1,
            samples: our_samples,
        },
        image_mean::Side {
            mean: &mitsuba.mean,
            variance: &mitsuba.variance,
            samples: mitsuba_samples,
        },
        &kept,
        verdicts.threshold,
        &|| moved_render().as_ref().ok().cloned(),
    );
    judge_deterministic(&mut check, &sides, &deterministic, &mut heat);
    check.cases = compared / 3;
    record_metrics(&mut check, &sides, &tests, &verdicts, deterministic.len());
    let pixels = (scene.width * scene.height) as f64;
    check.measure(
        "compared pixel fraction",
        compared as f64 / 3.0 / pixels,
        "",
    );
    record_power(
        &mut check,
        &sides,
        (&tests, &deterministic),
        verdicts.threshold,
        image.least_shift,
    );
    check.measure(
        "mean |mean ours − mean Mitsuba|, W/(sr m²)",
        sum / compared.max(1) as f64,
        "",
    );
    if let Some(example) = verdicts.offset_example {
        check.find(format!(
            "{} pixel-channels differ significantly from Mitsuba's path integrator, each by \
             less than Mitsuba's own ray offsets (RayEpsilon ≈ 8.9e-5 relative) move it; e.g. {example}",
            verdicts.offset_findings
        ));
    }
    if let Some(example) = verdicts.rule_example {
        check.find(format!(
            "{} pixel-channels differ significantly from Mitsuba's path integrator, and agree with it \
             when the tracer starts its secondary rays as Mitsuba does, {:.3e} (1 + max |p_i|) off the \
             surface: Mitsuba's offsets move this light; e.g. {example}",
            verdicts.rule_findings,
            super::MITSUBA_RAY_EPSILON
        ));
    }
    check.sum_up(|c| {
        format!(
            "In {name}, Mitsuba's path render departs from ours only where its own ray offsets \
             move light: {} pixel-channels and {} of the image's mean channels, each explained \
             by those offsets.",
            verdicts.offset_findings + verdicts.rule_findings,
            c.findings
                .iter()
                .filter(|f| f.starts_with("the image's mean"))
                .count()
        )
    });
    summarise_failures(&mut check);
    let figure = triptych(name, "path", scene, ours.0, &mitsuba.mean, &heat);
    Some(Compared { check, figure })
}

/// Every pixel-channel, as a t-test or, where neither side varies, a
/// deterministic comparison; with the sum of the differences of the means.
struct Split {
    tests: Vec<(usize, Welch)>,
    deterministic: Vec<usize>,
    sum: f64,
    compared: usize,
}

fn split(check: &mut Check, sides: &Sides) -> Split {
    let mut split = Split {
        tests: Vec::new(),
        deterministic: Vec::new(),
        sum: 0.0,
        compared: 0,
    };
    if sides.ours.0.len() != sides.mitsuba.mean.len() {
        return split; // failed by the caller: nothing to compare
    }
    let ours = Estimate {
        mean: sides.ours.0,
        variance: sides.ours.1,
        samples: sides.our_samples,
    };
    let mitsuba = Estimate {
        mean: &sides.mitsuba.mean,
        variance: &sides.mitsuba.variance,
        samples: sides.mitsuba_samples,
    };
    let guarded = (&sides.variance.0[..], &sides.variance.1[..]);
    let outcomes = pixel_tests_guarded(&ours, &mitsuba, guarded, None);
    for (i, outcome) in outcomes.into_iter().enumerate() {
        split.compared += 1;
        let difference = (ours.mean[i] - mitsuba.mean[i]).abs();
        split.sum += difference;
        check.measure_at(
            "|mean ours − mean Mitsuba|, W/(sr m²)",
            difference,
            || pixel_label(sides.width, i),
        );
        match outcome {
            Some(Some(w)) => split.tests.push((i, w)),
            _ => split.deterministic.push(i),
        }
    }
    split
}

/// The test's power: the relative shift of a pixel-channel's mean at which
/// it would fail half the time, `(t_c · SE + tolerance + offset) / |mean|`:
/// `SE` the two sides' standard error, `t_c` Student's `|t|` at the
/// Bonferroni threshold with the test's Welch degrees of freedom rounded
/// down (which only raises `t_c`: the shift is, if anything, overstated),
/// and the Whitted tolerance and Mitsuba's offset sensitivity the allowance
/// a failure must clear ([`judge_tests`]); where neither side varies, the
/// Whitted tolerance. Recorded: the median
/// over the pixel-channels of nonzero mean, and the least, which is the
/// smallest uniform relative shift of the whole image (a light's power, a
/// BRDF's scale) that the comparison detects.
fn record_power(
    check: &mut Check,
    sides: &Sides,
    (tests, deterministic): (&[(usize, Welch)], &[usize]),
    threshold: f64,
    image_least: Option<(f64, &'static str)>,
) {
    let mut critical = std::collections::BTreeMap::new();
    let mut critical_at = |dof: f64| {
        *critical
            .entry(dof.floor().max(1.0) as u64)
            .or_insert_with_key(|&d| {
                statistics::student_t_critical(threshold, d as f64).unwrap_or(f64::INFINITY)
            })
    };
    let m = &sides.mitsuba.mean;
    let standard_error = |i: usize| {
        (sides.variance.0[i] / sides.our_samples as f64
            + sides.variance.1[i] / sides.mitsuba_samples as f64)
            .sqrt()
    };
    let mut shifts: Vec<(f64, usize)> = tests
        .iter()
        .map(|&(i, w)| {
            let allowance = tolerance(m[i]) + sides.mitsuba.offset_sensitivity[i];
            (critical_at(w.dof) * standard_error(i) + allowance, i)
        })
        .chain(deterministic.iter().map(|&i| (tolerance(m[i]), i)))
        .filter(|&(_, i)| m[i].abs() > 0.0)
        .map(|(shift, i)| (shift / m[i].abs(), i))
        .collect();
    if shifts.is_empty() {
        return;
    }
    shifts.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (pixel_least, at) = shifts[0];
    let (least, at) = match image_least {
        Some((shift, channel)) if shift < pixel_least => {
            (shift, format!("the image's mean, {channel}"))
        }
        _ => (pixel_least, pixel_label(sides.width, at)),
    };
    if let Some((shift, _)) = image_least {
        check.measure(
            "power: image mean, least relative shift detected",
            shift,
            "",
        );
    }
    check.measure(
        "power: least relative shift detected (a uniform shift of the image)",
        least,
        &at,
    );
    check.measure(
        "power: median relative shift detected per pixel-channel",
        shifts[shifts.len() / 2].0,
        "",
    );
}

fn new_check(name: &str) -> Check {
    Check::new(
        &format!("renders.mitsuba.{name}.path"),
        &format!("{name}: the tracer's path against Mitsuba's path integrator, per-pixel Welch t-test"),
        "Mitsuba 3 path integrator through mi.render (scalar_rgb), box filter (mitsuba_renders.json)",
        &format!(
            "a pixel-channel fails when p < α/m, α = {ALPHA} over the m t-tests (Bonferroni: one correct \
             render in {:.0} fails by chance), and its means differ by more than the Whitted tolerance \
             {TOLERANCE_ABSOLUTE:e} + {TOLERANCE_RELATIVE:e} · |Mitsuba| (float32 differences, which no \
             number of samples removes); every pixel, both sides box filtered",
            1.0 / ALPHA
        ),
    )
}

/// Judges every t-test at the Bonferroni threshold: a rejection is a
/// failure, or a finding when Mitsuba's ray offsets explain it, by the
/// sensitivity the generator measured or by the tracer's own render under
/// Mitsuba's offset rule. Fills `heat` in units of the threshold's −log (1
/// at the threshold).
fn judge_tests<'a>(
    check: &mut Check,
    sides: &Sides,
    tests: &[(usize, Welch)],
    heat: &mut [f64],
    moved_render: &dyn Fn() -> &'a Result<(Vec<f64>, Vec<f64>), String>,
) -> Verdicts {
    let (ours, m_mean) = (sides.ours.0, &sides.mitsuba.mean);
    let offset_sensitivity = &sides.mitsuba.offset_sensitivity;
    // The family: the per-pixel tests and the image's mean in each channel.
    let threshold = ALPHA / (tests.len() + 3) as f64;
    let mut verdicts = Verdicts {
        threshold,
        rejected: 0,
        offset_findings: 0,
        offset_example: None,
        rule_findings: 0,
        rule_example: None,
        explained: vec![false; m_mean.len()],
    };
    let mut unexplained = Vec::new();
    for &(i, w) in tests {
        heat[i] = w.p.max(1e-300).ln() / threshold.ln();
        check.measure_at("|t|", w.t.abs(), || pixel_label(sides.width, i));
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
        let message = format!(
            "{}: ours {:.6} (n = {}), Mitsuba {:.6} (n = {}), t = {:.2}, p = {:.2e} < {threshold:.2e}",
            pixel_label(sides.width, i),
            ours[i],
            sides.our_samples,
            m_mean[i],
            sides.mitsuba_samples,
            w.t,
            w.p
        );
        if p_shifted >= threshold {
            verdicts.offset_findings += 1;
            verdicts.explained[i] = true;
            if verdicts.offset_example.is_none() {
                verdicts.offset_example = Some(format!(
                    "{message}, within the {:.2e} that Mitsuba's ray offsets move this pixel",
                    offset_sensitivity[i]
                ));
            }
        } else {
            unexplained.push((i, message));
        }
    }
    if unexplained.is_empty() {
        return verdicts;
    }
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
                    verdicts.rule_example = Some(format!(
                        "{message}; under Mitsuba's offsets ours {moved_mean:.6}"
                    ));
                }
            }
            None => {
                verdicts.rejected += 1;
                check.fail(message);
            }
        }
    }
    if let Err(e) = moved_render() {
        check.fail(format!(
            "the render under Mitsuba's offset rule failed: {e}"
        ));
    }
    verdicts
}

/// Pixel-channels where neither side varies, compared as the Whitted ones are.
fn judge_deterministic(check: &mut Check, sides: &Sides, pixels: &[usize], heat: &mut [f64]) {
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

/// The t-tests' metrics: the smallest p against the threshold, the counts.
fn record_metrics(
    check: &mut Check,
    sides: &Sides,
    tests: &[(usize, Welch)],
    verdicts: &Verdicts,
    deterministic: usize,
) {
    let smallest = tests.iter().map(|(_, w)| w.p).fold(1.0, f64::min);
    let p_at = tests
        .iter()
        .find(|(_, w)| w.p == smallest)
        .map_or(String::new(), |(i, _)| pixel_label(sides.width, *i));
    // Smaller p is worse: recorded as −log10 p beside the threshold's.
    // A p-value that underflows to 0 is shown as 10⁻³⁰⁰.
    check.measure(
        "−log10 smallest p",
        0.0 - smallest.max(1e-300).log10(),
        &p_at,
    );
    check.measure(
        "−log10 (α/m), the threshold",
        -verdicts.threshold.log10(),
        "",
    );
    check.measure("pixel-channel t-tests m", tests.len() as f64, "");
    check.measure("tests rejected", verdicts.rejected as f64, "");
    check.measure(
        "rejected within Mitsuba's ray-offset sensitivity (findings)",
        verdicts.offset_findings as f64,
        "",
    );
    check.measure(
        "rejected, agreeing under Mitsuba's offset rule (findings)",
        verdicts.rule_findings as f64,
        "",
    );
    check.measure(
        "pixel-channels where neither side varies",
        deterministic as f64,
        "",
    );
}
