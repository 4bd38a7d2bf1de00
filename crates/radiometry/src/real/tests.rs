//! The tiers' spacings and rounding bounds against their definitions.

use super::*;

#[test]
fn ulp_at_is_the_float32_spacing() {
    assert_eq!(f32::ulp_at(1.0), f32::EPSILON as f64);
    assert_eq!(f32::ulp_at(0.75), f32::EPSILON as f64 / 2.0);
    assert_eq!(f32::ulp_at(0.0), 2f64.powi(-149));
    assert_eq!(f32::ulp_at(-1.0), f32::EPSILON as f64);
    for x in [1e-40f32, f32::MIN_POSITIVE, 0.04, 3.0, 1e30] {
        let spacing = f64::from(x.next_up()) - f64::from(x);
        assert_eq!(f32::ulp_at(x.into()), spacing, "{x:e}");
    }
    // An exact value just below 1 is in the binade below, even though
    // it rounds to 1 in f32.
    assert_eq!(f32::ulp_at(1.0 - 1e-12), f32::EPSILON as f64 / 2.0);
}

#[test]
fn ulp_at_is_the_double_spacing() {
    assert_eq!(f64::ulp_at(1.0), f64::EPSILON);
    assert_eq!(f64::ulp_at(0.75), f64::EPSILON / 2.0);
    assert_eq!(f64::ulp_at(0.0), f64::from_bits(1));
    assert_eq!(f64::ulp_at(f64::MIN_POSITIVE), f64::from_bits(1));
    assert_eq!(f64::ulp_at(1e-300), 1e-300f64.next_up() - 1e-300);
    for x in [
        f64::from_bits(1 << 52),
        f64::from_bits(60 << 52),
        5.8e-300,
        0.04,
    ] {
        assert_eq!(f64::ulp_at(x), x.next_up() - x, "{x:e}");
    }
}

/// `γ(n) = n u / (1 − n u)` with each tier's unit roundoff, `u = 2⁻²⁴`
/// for `f32` and `2⁻⁵³` for `f64` (Higham §3.1), within one ulp of the
/// tier (the formula evaluated in the tier against it in `f64`, for
/// `f32`, and against `n u` plus its square, the next term, for `f64`).
#[test]
fn gamma_is_the_bound_of_n_roundings_at_each_tier() {
    for n in [1_u32, 6, 8, 100] {
        let u = 2f64.powi(-24) * f64::from(n);
        let exact = u / (1.0 - u);
        let single = f64::from(<f32 as Real>::gamma(n));
        assert!(
            (single - exact).abs() <= f32::ulp_at(exact),
            "f32 γ({n}) = {single:e}"
        );
        let u = 2f64.powi(-53) * f64::from(n);
        let double = <f64 as Real>::gamma(n);
        assert!(
            (double - (u + u * u)).abs() <= f64::ulp_at(u),
            "f64 γ({n}) = {double:e}"
        );
    }
}
