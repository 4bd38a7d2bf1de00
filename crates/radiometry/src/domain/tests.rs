//! Tests of the input checks: each refuses what lies outside a law's domain, by name.

use super::*;

#[test]
fn errors_name_the_input_and_the_expectation() {
    let cases: [(Result<f64, DomainError>, &str); 8] = [
        (cosine("cos_i", 1.5), "cos_i must be in [-1, 1], got 1.5"),
        (
            cosine("cos_i", f64::NAN),
            "cos_i must be a finite number, got NaN",
        ),
        (
            extinction("--kappa", -0.1),
            "--kappa must be a non-negative extinction coefficient, got -0.1",
        ),
        (
            refractive_index("eta", 0.0),
            "eta must be a positive refractive index, got 0",
        ),
        (fraction("kd", 1.2), "kd must be in [0, 1], got 1.2"),
        (
            refractive_index("--eta", 1e60),
            "--eta must be a refractive index from 1e-50 to 1e50, got 1e60",
        ),
        (
            extinction("--kappa", 1e-60),
            "--kappa must be an extinction coefficient of 0 or from 1e-50 to 1e50, got 1e-60",
        ),
        (
            finite("radiance", f64::INFINITY),
            "radiance must be a finite number, got inf",
        ),
    ];
    for (result, message) in cases {
        assert_eq!(result.unwrap_err().to_string(), message);
    }
}

#[test]
fn every_expectation_is_listed_once_in_order() {
    for (i, expected) in Expected::ALL.into_iter().enumerate() {
        assert_eq!(expected.ordinal(), i, "{expected:?}");
    }
}

#[test]
fn the_range_phrases_take_their_ends_from_the_ranges() {
    assert_eq!(
        Expected::IndexInRangeF32.to_string(),
        "a refractive index from 1e-9 to 1e9 (the range of the f32 laws)"
    );
    assert_eq!(
        INDEX_RANGE_F32.extinction("k", 1e20).unwrap_err().to_string(),
        "k must be an extinction coefficient of 0 or from 1e-9 to 1e9 (the range of the f32 laws), got 1e20"
    );
    assert_eq!(fraction("kd", 2.0).unwrap_err().name(), "kd");
}

#[test]
fn directions_are_normalized_and_zero_vectors_rejected() {
    let d = direction("--light-dir", DVec3::new(0.0, 3.0, 4.0)).unwrap();
    assert_eq!(d.unit, DVec3::new(0.0, 0.6, 0.8));
    assert!(d.was_normalized() && d.given_length == 5.0);
    assert!(!direction("n", DVec3::Z).unwrap().was_normalized());
    assert_eq!(
        direction("--normal", DVec3::ZERO).unwrap_err().to_string(),
        "--normal must be a non-zero direction, got (0, 0, 0)"
    );
    assert_eq!(
        direction("n", DVec3::new(0.0, f64::NAN, 1.0))
            .unwrap_err()
            .to_string(),
        "n.y must be a finite number, got NaN"
    );
    assert!(direction("-0", DVec3::splat(-0.0)).is_err());
}

/// Within 2 ulp of 1 (0.0 + three rounded squares summed and a rounded
/// square root), where the squared length itself under- or overflows.
fn assert_unit(d: &Direction) {
    let length = d.unit.length();
    assert!(
        (length - 1.0).abs() <= 2.0 * f64::EPSILON,
        "|{}| = {length}",
        d.unit
    );
}

#[test]
fn tiny_and_huge_directions_are_normalized_by_scaling() {
    let cases = [
        (DVec3::new(0.0, 3e-162, 4e-162), 5e-162),
        (DVec3::new(0.0, 3e200, 4e200), 5e200),
        (DVec3::new(0.0, -3e-320, 4e-320), 5e-320),
        (DVec3::splat(f64::MAX), f64::INFINITY),
    ];
    for (v, length) in cases {
        let d = direction("wi", v).unwrap();
        assert_unit(&d);
        // 1e-3 relative: the subnormal components carry a few digits only.
        assert!(
            (d.given_length - length).abs() <= 1e-3 * length || d.given_length == length,
            "{v}: {} is not {length}",
            d.given_length
        );
    }
    let d = direction("wi", DVec3::new(0.0, 3e-162, 4e-162)).unwrap();
    let off = (d.unit - DVec3::new(0.0, 0.6, 0.8)).abs().max_element();
    assert!(off <= 2.0 * f64::EPSILON, "{} is not (0, 0.6, 0.8)", d.unit);
}

#[test]
fn scaling_keeps_every_bit_of_an_ordinary_normalization() {
    // Dividing by the length, as the course does: a power-of-two scaling
    // changes no rounding where the squares were representable.
    let cases = [
        DVec3::new(1.0, 2.0, 3.0),
        DVec3::new(-0.3, 0.1, 7.25),
        DVec3::new(1e-100, 3e-101, -2e-100),
        DVec3::new(6e120, -1e119, 2.5e120),
    ];
    for v in cases {
        let length = v.length();
        assert_eq!(direction("v", v).unwrap().unit, v / length, "{v}");
        assert_eq!(direction("v", v).unwrap().given_length, length, "{v}");
    }
}
