//! The measures a path comparison records: the tests' power (the least
//! shift of the image it detects) and the t-tests' counts and extremes.

use super::sides::{Sides, Verdicts};
use crate::check::Check;
use crate::renders::common::{pixel_label, tolerance};
use crate::statistics::{self, Welch};

/// The test's power: the relative shift of a pixel-channel's mean at which
/// it would fail half the time, `(t_c · SE + tolerance + offset) / |mean|`:
/// `SE` the two sides' standard error, `t_c` Student's `|t|` at the
/// Bonferroni threshold with the test's Welch degrees of freedom rounded
/// down (which only raises `t_c`: the shift is, if anything, overstated),
/// and the Whitted tolerance and Mitsuba's offset sensitivity the allowance
/// a failure must clear ([`judge_tests`](super::judge::judge_tests)); where neither side varies, the
/// Whitted tolerance. Recorded: the median
/// over the pixel-channels of nonzero mean, and the least, which is the
/// smallest uniform relative shift of the whole image (a light's power, a
/// BRDF's scale) that the comparison detects.
pub(super) fn record_power(
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
        check.measure_in_both(
            [
                "power: image mean, least relative shift detected",
                "próbaerő: képátlag, a legkisebb kimutatott relatív eltolódás",
            ],
            shift,
            "",
        );
    }
    check.measure_in_both(
        [
            "power: least relative shift detected (a uniform shift of the image)",
            "próbaerő: a legkisebb kimutatott relatív eltolódás (a kép egyenletes eltolódása)",
        ],
        least,
        &at,
    );
    check.measure_in_both(
        [
            "power: median relative shift detected per pixel-channel",
            "próbaerő: a képpont-csatornánként kimutatott relatív eltolódás mediánja",
        ],
        shifts[shifts.len() / 2].0,
        "",
    );
}

/// The t-tests' metrics: the smallest p against the threshold, the counts.
pub(super) fn record_metrics(
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
    check.measure_in_both(
        ["−log10 smallest p", "−log10 legkisebb p"],
        0.0 - smallest.max(1e-300).log10(),
        &p_at,
    );
    check.measure_in_both(
        ["−log10 (α/m), the threshold", "−log10 (α/m), a küszöb"],
        -verdicts.threshold.log10(),
        "",
    );
    check.measure_in_both(
        [
            "pixel-channel t-tests m",
            "képpont-csatornánkénti t-próbák m",
        ],
        tests.len() as f64,
        "",
    );
    check.measure_in_both(
        ["tests rejected", "elutasított próbák"],
        verdicts.rejected as f64,
        "",
    );
    check.measure_in_both(
        [
            "rejected within Mitsuba's ray-offset sensitivity (findings)",
            "elutasítva a Mitsuba sugáreltolási érzékenységén belül (megállapítások)",
        ],
        verdicts.offset_findings as f64,
        "",
    );
    check.measure_in_both(
        [
            "rejected, agreeing under Mitsuba's offset rule (findings)",
            "elutasítva, a Mitsuba eltolási szabályával egyezve (megállapítások)",
        ],
        verdicts.rule_findings as f64,
        "",
    );
    check.measure_in_both(
        [
            "pixel-channels where neither side varies",
            "képpont-csatornák, ahol egyik oldal sem változik",
        ],
        deterministic as f64,
        "",
    );
}
