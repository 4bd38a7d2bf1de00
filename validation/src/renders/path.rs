//! Path against path: Monte Carlo renders compared per pixel and channel by
//! Welch's t-test, Bonferroni-corrected, a rejection explained by Mitsuba's
//! own ray offsets recorded as a finding about the reference.

use super::figure::triptych;
use super::{
    pixel_label, summarise_failures, tolerance, Compared, Decoded, PathImages, ALPHA,
    TOLERANCE_ABSOLUTE, TOLERANCE_RELATIVE,
};
use crate::check::Check;
use crate::statistics::{self, Sample, Welch};

/// Both sides of a path comparison, per pixel-channel: the means, the
/// per-sample variances and the sample counts.
struct Sides<'a> {
    ours: (&'a [f64], &'a [f64]),
    our_samples: u32,
    mitsuba: &'a PathImages,
    mitsuba_samples: u32,
    width: u32,
}

/// What the t-tests found, for the check's metrics.
struct Verdicts {
    threshold: f64,
    rejected: usize,
    offset_findings: usize,
    offset_example: Option<String>,
}

/// Path against path: Welch's t per pixel and channel, Bonferroni-corrected.
pub fn compare_path(
    name: &str,
    reference: &Decoded,
    mitsuba_samples: u32,
    ours: (&[f64], &[f64]),
    our_samples: u32,
) -> Option<Compared> {
    let mitsuba = reference.path.as_ref()?;
    let scene = &reference.scene;
    let sides = Sides {
        ours,
        our_samples,
        mitsuba,
        mitsuba_samples,
        width: scene.width,
    };
    let mut check = new_check(name);
    let mut tests = Vec::new();
    let mut deterministic = Vec::new();
    let (mut sum, mut compared) = (0.0, 0usize);
    for i in 0..mitsuba.mean.len() {
        if reference.edges[i / 3] {
            continue;
        }
        compared += 1;
        let (a, b) = (ours.0[i], mitsuba.mean[i]);
        sum += (a - b).abs();
        check.measure(
            "|mean ours − mean Mitsuba|, W/(sr m²)",
            (a - b).abs(),
            &pixel_label(scene.width, i),
        );
        let side = |mean, variance, count: u32| Sample {
            mean,
            variance,
            count: count as f64,
        };
        match statistics::welch(
            side(a, ours.1[i], our_samples),
            side(b, mitsuba.variance[i], mitsuba_samples),
        ) {
            Some(w) => tests.push((i, w)),
            None => deterministic.push(i),
        }
    }
    let mut heat = vec![f64::NAN; mitsuba.mean.len()];
    let verdicts = judge_tests(&mut check, &sides, &tests, &mut heat);
    judge_deterministic(&mut check, &sides, &deterministic, &mut heat);
    check.cases = compared / 3;
    record_metrics(&mut check, &sides, &tests, &verdicts, deterministic.len());
    check.measure(
        "masked edge pixels",
        reference.edges.iter().filter(|&&e| e).count() as f64,
        "",
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
    summarise_failures(&mut check);
    let figure = triptych(name, "path", scene, ours.0, &mitsuba.mean, &heat);
    Some(Compared { check, figure })
}

fn new_check(name: &str) -> Check {
    Check::new(
        &format!("renders.mitsuba.{name}.path"),
        &format!("{name}: the tracer's path against Mitsuba's path integrator, per-pixel Welch t-test"),
        "Mitsuba 3 path integrator (scalar_rgb), pixel centres (mitsuba_renders.json)",
        &format!(
            "a pixel-channel fails when p < α/m, α = {ALPHA} over the m t-tests (Bonferroni: one correct \
             render in {:.0} fails by chance), and its means differ by more than the Whitted tolerance \
             {TOLERANCE_ABSOLUTE:e} + {TOLERANCE_RELATIVE:e} · |Mitsuba| (float32 differences, which no \
             number of samples removes); edges masked",
            1.0 / ALPHA
        ),
    )
}

/// Judges every t-test at the Bonferroni threshold: a rejection is a
/// failure, or a finding when Mitsuba's ray offsets explain it. Fills `heat`
/// in units of the threshold's −log (1 at the threshold).
fn judge_tests(
    check: &mut Check,
    sides: &Sides,
    tests: &[(usize, Welch)],
    heat: &mut [f64],
) -> Verdicts {
    let (ours, m_mean) = (sides.ours.0, &sides.mitsuba.mean);
    let offset_sensitivity = &sides.mitsuba.offset_sensitivity;
    let threshold = ALPHA / tests.len().max(1) as f64;
    let mut verdicts = Verdicts {
        threshold,
        rejected: 0,
        offset_findings: 0,
        offset_example: None,
    };
    for &(i, w) in tests {
        heat[i] = w.p.max(1e-300).ln() / threshold.ln();
        check.measure("|t|", w.t.abs(), &pixel_label(sides.width, i));
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
            if verdicts.offset_example.is_none() {
                verdicts.offset_example = Some(format!(
                    "{message}, within the {:.2e} that Mitsuba's ray offsets move this pixel",
                    offset_sensitivity[i]
                ));
            }
        } else {
            verdicts.rejected += 1;
            check.fail(message);
        }
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
        "pixel-channels where neither side varies",
        deterministic as f64,
        "",
    );
}
