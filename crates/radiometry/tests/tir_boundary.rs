//! Total internal reflection happens exactly when Snell's law would need
//! `sin θ_t > 1`, decided to the last bit of the inputs.
//!
//! For light going from index `n_i` into `n_t` (one of them 1, the other
//! `eta`) with `c = |cos θ_i|`, Snell's law has a real solution exactly when
//! `n_t² − n_i² (1 − c²) ≥ 0`. Every input is a binary floating-point number,
//! so this polynomial's sign can be computed exactly, in integers: the
//! reference below does so with arbitrary-precision arithmetic, independent
//! of the crate's compensated sums. The tests then walk the inputs ulp by ulp
//! across the critical angle, in both tiers and from both sides, and require
//! `snell::cos_transmitted` and the Fresnel law to switch at the same double
//! (or float) as the exact sign does, and `refract` too, against the exact
//! sign of `n_t² − n_i² sin²θ_i` where it decides from the direction's
//! measured sine. No tolerance: the crate
//! sums the discriminant as if in twice the working precision (`f32` in
//! `f64`, where its products are exact), so its sign can only be wrong where
//! the exact value is below about ε² of its terms, which no input within
//! these thousands of ulps of the boundary comes near.

use std::cmp::Ordering;

use glam::{DVec3, Vec3};
use num_bigint::BigInt;
use num_traits::{Float, FloatConst, One, ToPrimitive, Zero};
use proptest::prelude::*;
use radiometry::fresnel::dielectric_polarized;
use radiometry::snell::cos_transmitted;
use radiometry::specular::{incidence, refract};
use radiometry::Vector3;

mod common;
use common::strategies::relative_index_with_extremes;

/// `x = m · 2^e` exactly, for a finite `x`.
fn dyadic(x: f64) -> (BigInt, i32) {
    let bits = x.to_bits();
    let sign = if bits >> 63 == 1 { -1 } else { 1 };
    let exponent = ((bits >> 52) & 0x7ff) as i32;
    let fraction = (bits & ((1 << 52) - 1)) as i64;
    let (m, e) = if exponent == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1 << 52), exponent - 1075)
    };
    (BigInt::from(sign * m), e)
}

/// The exact sign of `Σ ∏ factors` over the given products of doubles.
fn exact_sign(products: &[(i32, &[f64])]) -> Ordering {
    let terms: Vec<(BigInt, i32)> = products
        .iter()
        .map(|&(sign, factors)| {
            factors.iter().fold((BigInt::from(sign), 0), |(m, e), &x| {
                let (mx, ex) = dyadic(x);
                (m * mx, e + ex)
            })
        })
        .collect();
    let lowest = terms.iter().map(|t| t.1).min().unwrap_or(0);
    let sum: BigInt = terms
        .into_iter()
        .map(|(m, e)| m << ((e - lowest) as usize))
        .sum();
    sum.sign().cmp_zero()
}

trait SignCmp {
    fn cmp_zero(self) -> Ordering;
}

impl SignCmp for num_bigint::Sign {
    fn cmp_zero(self) -> Ordering {
        match self {
            num_bigint::Sign::Minus => Ordering::Less,
            num_bigint::Sign::NoSign => Ordering::Equal,
            num_bigint::Sign::Plus => Ordering::Greater,
        }
    }
}

/// Whether Snell's law has no real solution for the signed cosine `cos_i`
/// at an interface of `eta = n_inside / n_outside`, exactly:
/// `n_t² − n_i² + n_i² c² < 0`.
fn exactly_tir(cos_i: f64, eta: f64) -> bool {
    let c = cos_i.abs();
    let (n_i, n_t) = if cos_i < 0.0 { (eta, 1.0) } else { (1.0, eta) };
    exact_sign(&[(1, &[n_t, n_t]), (-1, &[n_i, n_i]), (1, &[n_i, n_i, c, c])]) == Ordering::Less
}

/// Whether Snell's law has no real solution for a direction whose
/// `sin θ_i` is the double `sin_i`, on the side `cos_i` gives: exactly,
/// `n_t² − n_i² sin_i² < 0`. `refract` decides from this sine near normal
/// incidence, where the direction says more than its rounded cosine.
fn exactly_tir_by_sine(cos_i: f64, sin_i: f64, eta: f64) -> bool {
    let (n_i, n_t) = if cos_i < 0.0 { (eta, 1.0) } else { (1.0, eta) };
    exact_sign(&[(1, &[n_t, n_t]), (-1, &[n_i, n_i, sin_i, sin_i])]) == Ordering::Less
}

/// The crate's decisions, in either tier, for light with signed cosine
/// `cos_i`, each against its exact reference: the laws of a cosine
/// (`snell::cos_transmitted`, the Fresnel law, which must agree) against
/// [`exactly_tir`], and `refract` of the direction `(s, 0, cos_i)`,
/// `s = √(1 − c²)` rounded, whose dot product with +z is exactly `cos_i`:
/// against [`exactly_tir`] where the cosine decides, and where the law
/// measures the sine (`|cos θ_i| ≥ 1/√2`; its sine is then exactly `s`,
/// the tangential part being `(−s, 0, 0)`) against [`exactly_tir_by_sine`].
/// Returns the cosine laws' decision.
fn crate_tir<V: Vector3>(cos_i: V::Scalar, eta: V::Scalar) -> bool {
    let wide = |x: V::Scalar| x.to_f64().expect("a finite float");
    let one = V::Scalar::one();
    let sin_i = (one - cos_i * cos_i).max(V::Scalar::zero()).sqrt();
    let (wi, n) = (
        V::new(sin_i, V::Scalar::zero(), cos_i),
        V::new(V::Scalar::zero(), V::Scalar::zero(), one),
    );
    let by_snell = cos_transmitted(cos_i, eta).is_none();
    let by_fresnel = dielectric_polarized(cos_i, eta).is_total_internal_reflection();
    assert_eq!(by_snell, by_fresnel, "cos {cos_i:?}, eta {eta}");
    assert_eq!(
        by_fresnel,
        exactly_tir(wide(cos_i), wide(eta)),
        "cos {cos_i:?}, eta {eta}"
    );
    let measured = cos_i.abs() >= V::Scalar::FRAC_1_SQRT_2();
    let at = incidence(wi, n, eta).expect("a valid interface");
    assert_eq!(at.sin_i, measured.then_some(sin_i), "the measured sine");
    let by_refract = refract(wi, n, eta).is_none();
    let expected = if measured {
        exactly_tir_by_sine(wide(cos_i), wide(sin_i), wide(eta))
    } else {
        by_fresnel
    };
    assert_eq!(by_refract, expected, "refract at cos {cos_i:?}, eta {eta}");
    by_fresnel
}

fn crate_tir_f64(cos_i: f64, eta: f64) -> bool {
    crate_tir::<DVec3>(cos_i, eta)
}

fn crate_tir_f32(cos_i: f32, eta: f32) -> bool {
    crate_tir::<Vec3>(cos_i, eta)
}

/// `x` moved by `k` steps of its own type (away from zero for k > 0).
fn step_f64(x: f64, k: i64) -> f64 {
    f64::from_bits((x.to_bits() as i64 + k) as u64)
}

fn step_f32(x: f32, k: i32) -> f32 {
    f32::from_bits((x.to_bits() as i32 + k) as u32)
}

/// The cosine of the critical angle on the side that has one, with the sign
/// that puts the light there: from inside for `eta > 1`, from outside for
/// `eta < 1`. Within a few ulps (`eta − 1` and `1 − eta` are exact, so
/// nothing cancels); the tests walk around it.
fn critical_cosine(eta: f64) -> f64 {
    if eta > 1.0 {
        -((eta - 1.0) * (eta + 1.0)).sqrt() / eta
    } else {
        ((1.0 - eta) * (1.0 + eta)).sqrt()
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// f64: each of the 4001 doubles within 2000 ulps of the critical cosine
    /// is decided as the exact sign decides it, and the boundary is crossed
    /// (so the walk really straddles it).
    #[test]
    fn total_internal_reflection_switches_at_the_exact_double(eta in relative_index_with_extremes()) {
        let start = critical_cosine(eta);
        let (mut seen_tir, mut seen_refraction) = (false, false);
        for k in -2000..=2000 {
            let cos_i = step_f64(start, k);
            if !(-1.0..=1.0).contains(&cos_i) || cos_i == 0.0 {
                continue;
            }
            let exact = exactly_tir(cos_i, eta);
            prop_assert_eq!(crate_tir_f64(cos_i, eta), exact, "cos {:e} ({} ulps from the rounded critical cosine), eta {}", cos_i, k, eta);
            seen_tir |= exact;
            seen_refraction |= !exact;
        }
        prop_assert!(seen_tir && seen_refraction, "the walk did not cross the critical angle for eta {}", eta);
    }

    /// f32: the same for every float within 200 f32 ulps of the critical
    /// cosine, with the f32 inputs' exact values.
    #[test]
    fn total_internal_reflection_switches_at_the_exact_float(eta in relative_index_with_extremes()) {
        let eta = eta as f32;
        prop_assume!(eta != 1.0);
        let start = critical_cosine(f64::from(eta)) as f32;
        let (mut seen_tir, mut seen_refraction) = (false, false);
        for k in -200..=200 {
            let cos_i = step_f32(start, k);
            if !(-1.0..=1.0).contains(&cos_i) || cos_i == 0.0 {
                continue;
            }
            let exact = exactly_tir(f64::from(cos_i), f64::from(eta));
            prop_assert_eq!(crate_tir_f32(cos_i, eta), exact, "cos {:e} ({} ulps), eta {}", cos_i, k, eta);
            seen_tir |= exact;
            seen_refraction |= !exact;
        }
        prop_assert!(seen_tir && seen_refraction, "the walk did not cross the critical angle for eta {}", eta);
    }

    /// Away from the boundary too: any cosine, either side, any index.
    #[test]
    fn total_internal_reflection_is_decided_exactly_everywhere(cos_i in -1.0..=1.0f64, eta in relative_index_with_extremes()) {
        prop_assume!(cos_i != 0.0);
        prop_assert_eq!(crate_tir_f64(cos_i, eta), exactly_tir(cos_i, eta));
        let (c32, e32) = (cos_i as f32, eta as f32);
        prop_assert_eq!(crate_tir_f32(c32, e32), exactly_tir(f64::from(c32), f64::from(e32)));
    }
}

/// The exact reference itself, on cases decided by hand.
#[test]
fn the_exact_reference_knows_the_textbook_cases() {
    // Inside glass: 60° is beyond the 41.8° critical angle, 30° is not.
    assert!(exactly_tir(-0.5, 1.5));
    assert!(!exactly_tir(-(0.75f64.sqrt()), 1.5));
    // Into glass, never; out of an index-matched medium, never.
    assert!(!exactly_tir(1e-300, 1.5) && !exactly_tir(-1e-300, 1.0));
    // Grazing from inside a denser medium: always.
    assert!(exactly_tir(-1e-300, 1.0 + 1e-12));
    // Inside a medium of index 2 the critical cosine is √0.75, irrational:
    // the doubles on either side of it fall on either side of the boundary.
    let c = 0.75f64.sqrt();
    assert!(exactly_tir(-step_f64(c, -1), 2.0) && !exactly_tir(-step_f64(c, 1), 2.0));
    // sin θ_t = 1 exactly is not total reflection: the discriminant is 0.
    assert_eq!(
        exact_sign(&[(1, &[0.5, 0.5]), (-1, &[0.25])]),
        Ordering::Equal
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// The angle form, `snell::transmitted_angle(θ_i, eta_path)`: walking θ_i
    /// double by double across the critical angle `asin(eta_path)` (from
    /// `snell::critical_angle`, within an ulp or two), it refracts below and
    /// reflects totally above. The few doubles around the critical angle
    /// itself are skipped: there the answer depends on how `sin`, `cos` and
    /// `critical_angle` round, not on the law. Near grazing (eta_path → 1)
    /// one ulp of `sin θ` spans thousands of ulps of θ, which is why the law
    /// reads the cosine there.
    #[test]
    fn transmitted_angle_refracts_below_and_reflects_above_the_critical_angle(eta in relative_index_with_extremes()) {
        use radiometry::snell::{critical_angle, transmitted_angle};
        let eta_path = if eta < 1.0 { eta } else { 1.0 / eta };
        let theta_c = critical_angle(eta_path).expect("eta_path < 1 has a critical angle");
        for k in (-2000..=2000_i64).filter(|k| k.abs() > 4) {
            let theta = step_f64(theta_c, k);
            if theta > std::f64::consts::FRAC_PI_2 {
                continue;
            }
            let refracts = transmitted_angle(theta, eta_path).is_some();
            prop_assert_eq!(refracts, k < 0, "θ {:e} ({} ulps from θ_c), eta_path {}", theta, k, eta_path);
        }
    }
}
