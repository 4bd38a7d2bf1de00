//! A computed value measured against the exact one, in ulps of the tier
//! and relative, and judged against a bound.

use super::bounds::BOUND_ULPS;
use super::reference::Exact;
use crate::check::Check;

/// Records `got` against `exact` in ulps of the tier and relative to the
/// exact value (0 when both are 0, infinite when only the exact value is),
/// and returns the ulps.
pub(super) fn measure(
    check: &mut Check,
    tier: &str,
    quantity: &str,
    label: &str,
    got: f64,
    exact: Exact,
) -> f64 {
    let err = exact.error(got);
    let ulps = exact.ulps(got, tier);
    let relative = if err == 0.0 {
        0.0
    } else {
        err / (exact.0 + exact.1).abs()
    };
    let ulps_name = format!("{tier} {quantity} (ulps)");
    check.measure_in_both([&ulps_name, &ulps_name], ulps, label);
    check.measure_in_both(
        [
            &format!("{tier} {quantity} (relative)"),
            &format!("{tier} {quantity} (relatív)"),
        ],
        relative,
        label,
    );
    ulps
}

/// [`measure`], failing above [`BOUND_ULPS`].
pub(super) fn compare(
    check: &mut Check,
    tier: &str,
    quantity: &str,
    label: &str,
    got: f64,
    exact: Exact,
) {
    compare_within(check, BOUND_ULPS, (tier, quantity, label), got, exact)
}

/// [`measure`], failing above `bound` ulps.
pub(super) fn compare_within(
    check: &mut Check,
    bound: f64,
    (tier, quantity, label): (&str, &str, &str),
    got: f64,
    exact: Exact,
) {
    let ulps = measure(check, tier, quantity, label, got, exact);
    if !(ulps <= bound) {
        check.fail(format!(
            "{tier} {quantity} at {label}: got {got:e}, exact {:e} ({ulps:.1} ulps)",
            exact.0
        ));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An exact value just below a power of two is measured in the spacing
    /// of the binade it lies in, not in the coarser one of its rounded `hi`.
    #[test]
    fn ulps_are_those_of_the_exact_value_at_a_power_of_two() {
        let just_below = Exact(1.0, -f64::EPSILON / 8.0);
        assert_eq!(just_below.ulp("f64"), f64::EPSILON / 2.0);
        assert_eq!(just_below.ulp("f32"), f32::EPSILON as f64 / 2.0);
        assert_eq!(Exact(1.0, f64::EPSILON / 8.0).ulp("f64"), f64::EPSILON);
        assert_eq!(Exact(0.75, -1e-20).ulp("f64"), f64::EPSILON / 2.0);
        assert_eq!(
            Exact(-1.0, f64::EPSILON / 8.0).ulp("f64"),
            f64::EPSILON / 2.0
        );
        assert_eq!(Exact(-1.0, -f64::EPSILON / 8.0).ulp("f64"), f64::EPSILON);
        let mut check = Check::new("t", ["t", "t"], ["t", "t"], ["t", "t"]);
        compare(
            &mut check,
            "f64",
            "R",
            "one below",
            1.0,
            Exact(1.0, -f64::EPSILON / 4.0),
        );
        assert_eq!(check.worst("f64 R (ulps)").unwrap().worst, 0.5);
        let relative = check.worst("f64 R (relative)").unwrap().worst;
        assert!(
            (relative - f64::EPSILON / 4.0).abs() < 1e-30,
            "{relative:e}"
        );
    }
}
