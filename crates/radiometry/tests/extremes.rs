//! Numerical stability at the extremes of every input: each named test is
//! one extreme. No valid input may give NaN or infinity; invalid input gives
//! what the crate conventions document (NaN, or `None` for a direction).
//!
//! Exact values at these extremes, to the last bit, are checked against
//! 50-digit references in the workspace test `fresnel_reference`; here the
//! checks are the limits the laws must reach. Where a limit has a closed
//! form, the tolerance is 4ε to 8ε relative (ε = `f64::EPSILON`): the handful
//! of roundings between the law and that closed form, each at most ε/2, with
//! room for the closed form's own. Tolerances of another kind say why beside
//! them.

use glam::{DVec3, Vec3};
use num_traits::{Float, FloatConst, One, Zero};
use proptest::prelude::*;
use radiometry::brdf::{BlinnPhong, BlinnPhongReciprocal, Brdf, Lambert};
use radiometry::fresnel::{
    conductor, conductor_polarized, dielectric, dielectric_polarized, f0, schlick,
};
use radiometry::radiance::across_interface;
use radiometry::snell::{
    brewster_angle, cos_transmitted, critical_angle, transmitted_angle, Incidence,
};
use radiometry::specular::refract;
use radiometry::{domain, Vector3};

const EPS: f64 = f64::EPSILON;
const GLASS: f64 = 1.5;

/// At normal incidence, from either side, both polarisations reflect
/// F0 = ((η − 1)/(η + 1))² and transmit T0 = 4η/(η + 1)², and the light
/// goes straight on (cos θ_t = 1), over the whole documented range of
/// indices, its ends included: from the denser side beyond η ≈ 1.27e16
/// (η² ≈ 2^107) the two-part sums of 1 − η² and Brewster's factor lose
/// their 1, which once gave cos θ_t = 0, R_p = 0 and T = 0 there. T0 is
/// 4e-50 at the ends, so it is compared relatively: 8ε, the closed form's
/// three roundings and the law's few.
#[test]
fn normal_incidence_cos_1_gives_f0_from_both_sides() {
    let (lo, hi) = domain::INDEX_RANGE.range.into_inner();
    let beyond_two_parts = [1.3e16, 1e20, 1e30];
    let indices = [GLASS, 1.333, 2.42, 1e-3, 1e3, 2f64.powi(53), lo, hi];
    for eta in indices
        .into_iter()
        .chain(beyond_two_parts)
        .chain(beyond_two_parts.map(|eta| 1.0 / eta))
    {
        let f0 = f0(eta, 0.0);
        let t0 = 4.0 * eta / ((eta + 1.0) * (eta + 1.0));
        for cos_i in [1.0, -1.0] {
            let f = dielectric_polarized(cos_i, eta);
            for r in [f.r_s, f.r_p] {
                assert!(
                    (r - f0).abs() <= 4.0 * EPS * f0,
                    "eta {eta}, cos {cos_i}: {f:?} vs F0 {f0}"
                );
            }
            for t in [f.t_s, f.t_p] {
                assert!(
                    (t - t0).abs() <= 8.0 * EPS * t0,
                    "eta {eta}, cos {cos_i}: {f:?} vs T0 {t0}"
                );
            }
            assert_eq!(f.cos_t, Some(1.0), "eta {eta}, cos {cos_i}");
            assert_eq!(cos_transmitted(cos_i, eta), Some(1.0), "eta {eta}");
        }
    }
}

#[test]
fn grazing_incidence_cos_0_reflects_everything() {
    for eta in [GLASS, 1.0 / GLASS, 1.0 + 1e-12, 1.0 - 1e-12, 1e-3, 1e3] {
        for cos_i in [0.0, -0.0] {
            let f = dielectric_polarized(cos_i, eta);
            assert_eq!(
                (f.r_s, f.r_p, f.t_s, f.t_p),
                (1.0, 1.0, 0.0, 0.0),
                "eta {eta}: {f:?}"
            );
        }
        assert_eq!(conductor(0.0, eta, 0.0), 1.0);
        assert_eq!(conductor(0.0, 0.17, 3.1), 1.0);
    }
    // The f32 tier too, whose quotients take a few more f64 roundings.
    for eta in [1.5f32, 1.0 / 1.5, 1.0 + 1e-6, 1.0 - 1e-6, 1e-3, 1e3] {
        for cos_i in [0.0f32, -0.0] {
            let f = dielectric_polarized(cos_i, eta);
            assert_eq!(
                (f.r_s, f.r_p, f.t_s, f.t_p),
                (1.0, 1.0, 0.0, 0.0),
                "f32 eta {eta}: {f:?}"
            );
        }
    }
}

/// cos θ = 1e-300: the light skims the surface. R is 1 to within 1e-299 and
/// T is a tiny positive number, not zero, NaN or a negative rounding residue.
#[test]
fn cos_1e_minus_300_is_finite_and_just_below_total_reflection() {
    for eta in [GLASS, 1.333, 1e3] {
        let f = dielectric_polarized(1e-300, eta);
        assert_eq!(f.reflectance(), 1.0);
        let t = f.transmittance();
        assert!(t > 0.0 && t < 1e-290, "eta {eta}: T = {t}");
        // T_s = 4 c s / (c + s)² → 4c / s for c → 0, with s = √(η² − 1).
        let expected = 4.0 * 1e-300 / (eta * eta - 1.0).sqrt();
        assert!(
            (f.t_s - expected).abs() <= 4.0 * EPS * expected,
            "{} vs {expected}",
            f.t_s
        );
    }
    assert!((1.0 - conductor(1e-300_f64, 0.17, 3.1)).abs() < 1e-290);
    // From the dense side a grazing ray is beyond the critical angle.
    assert_eq!(dielectric(-1e-300, GLASS), 1.0);
}

/// eta exactly 1: no interface, nothing reflects, at every angle, grazing
/// included, and the ray goes straight through.
#[test]
fn index_matched_interface_reflects_exactly_nothing() {
    for cos_i in [1.0, 0.5, 1e-300, 0.0, -0.0, -0.5, -1.0] {
        let f = dielectric_polarized(cos_i, 1.0);
        assert_eq!(
            (f.r_s, f.r_p, f.t_s, f.t_p),
            (0.0, 0.0, 1.0, 1.0),
            "cos {cos_i}"
        );
        assert_eq!(conductor(cos_i, 1.0, 0.0), 0.0);
    }
    let wi = DVec3::new(0.6, 0.0, 0.8);
    assert_eq!(refract(wi, DVec3::Z, 1.0).unwrap().direction, -wi);
}

/// eta = 1 ± 1e-12: R at normal incidence is ((η−1)/(η+1))² ≈ 2.5e-25, and
/// must come out with full relative precision. η − 1 is exact in floating
/// point here, so the closed form is a reference.
#[test]
fn eta_within_1e_minus_12_of_one_keeps_relative_precision() {
    for eta in [1.0 + 1e-12, 1.0 - 1e-12_f64] {
        let expected = ((eta - 1.0) / (eta + 1.0)).powi(2);
        for cos_i in [1.0, -1.0] {
            let r = dielectric(cos_i, eta);
            assert!(
                (r - expected).abs() <= 8.0 * EPS * expected,
                "eta {eta}: {r} vs {expected}"
            );
        }
        // At 60° the reflectance is still ~1e-25, smooth in the angle.
        let r60 = dielectric(0.5, eta);
        assert!(r60 > 0.0 && r60 < 1e-23, "{r60}");
    }
}

#[test]
fn extreme_indices_1e_minus_3_and_1e3_stay_in_range() {
    for eta in [1e-3, 1e3] {
        for k in 0..=1000 {
            let cos_i = -1.0 + 2.0 * k as f64 / 1000.0;
            let f = dielectric_polarized(cos_i, eta);
            for v in [f.r_s, f.r_p, f.t_s, f.t_p] {
                assert!((0.0..=1.0).contains(&v), "eta {eta}, cos {cos_i}: {f:?}");
            }
            let c = conductor_polarized(cos_i, eta, 0.0);
            assert!(c.r_s.is_finite() && c.r_p.is_finite());
        }
        // Nearly everything reflects at normal incidence, from both sides.
        let f0 = ((eta - 1.0) / (eta + 1.0)).powi(2);
        for cos_i in [1.0, -1.0] {
            assert!((dielectric(cos_i, eta) - f0).abs() <= 4.0 * EPS, "{f0}");
        }
    }
}

/// κ = 1e3: an almost perfect mirror. F0 = (0 + 1e6)/(4 + 1e6) leaves 4e-6
/// unreflected; the exact law must agree at normal incidence and stay in
/// [0.999, 1] at every angle: R dips to its minimum, 0.999001 (mpmath, at
/// cos θ = 1e-3 = 1/κ, where R_p is 0.998002 and R_s 0.999999996),
/// before rising to 1 at grazing incidence.
#[test]
fn kappa_1e3_is_an_almost_perfect_mirror() {
    let f0 = f0(1.0_f64, 1e3);
    assert!((1.0 - f0 - 4.0 / (4.0 + 1e6)).abs() < 1e-15);
    assert!((conductor(1.0, 1.0, 1e3) - f0).abs() <= 4.0 * EPS);
    for k in 0..=1000 {
        let r = conductor(k as f64 / 1000.0, 1.0, 1e3);
        assert!(
            r.is_finite() && (0.999..=1.0).contains(&r),
            "cos {}: {r}",
            k as f64 / 1000.0
        );
    }
}

/// Within 1e-12 rad of the critical angle, on both code paths that have
/// one: from inside glass (`n_i = eta`, `n_t = 1`) and from the outside of an
/// interface with `eta < 1` (an air bubble in glass: `n_i = 1`, `n_t = eta`).
/// Just below the angle the light still refracts, barely: R < 1 and
/// T = 1 − R > 0 follows its leading order in the small `cos θ_t`,
/// `T ≈ 2 (cos θ_t / cos θ_i)(n_t/n_i + n_i/n_t)` (from `T_s = 4as/(a + s)²`
/// and `T_p = 4as n_t²/(n_t² c + n_i s)²` with `s = n_t cos θ_t ≪ a = n_i c`),
/// within 1e-3 relative: the next order is `cos θ_t ≈ 1.4e-6` relative, and
/// `cos θ_t` from the plain `√(1 − (n_i/n_t)² sin²θ_i)` in f64 is good to
/// about 1e-4 here, where `1 − …` cancels to 2e-12. Just above the angle
/// nothing refracts and R = 1 exactly. `refract`, `cos_transmitted`
/// and the Fresnel law agree on which side each input lies.
#[test]
fn within_1e_minus_12_rad_of_the_critical_angle_from_both_sides() {
    // (eta, the sign of cos θ_i): inside glass, and outside a bubble.
    for (eta, sign) in [(GLASS, -1.0), (1.0 / GLASS, 1.0)] {
        let theta_c = critical_angle(1.0 / GLASS).unwrap();
        let at = |theta: f64| {
            let cos_i = sign * theta.cos();
            let wi = DVec3::new(theta.sin(), 0.0, cos_i);
            (cos_i, refract(wi, DVec3::Z, eta))
        };
        let (below, refracted) = at(theta_c - 1e-12);
        let (above, reflected) = at(theta_c + 1e-12);
        assert!(
            refracted.is_some() && cos_transmitted(below, eta).is_some(),
            "eta {eta}"
        );
        assert!(
            reflected.is_none() && cos_transmitted(above, eta).is_none(),
            "eta {eta}"
        );
        let f = dielectric_polarized(below, eta);
        let (r, t) = (f.reflectance(), f.transmittance());
        let (n_i, n_t) = if sign < 0.0 { (eta, 1.0) } else { (1.0, eta) };
        let c = below.abs();
        let cos_t = (1.0 - (n_i / n_t) * (n_i / n_t) * (1.0 - c * c)).sqrt();
        let leading = 2.0 * (cos_t / c) * (n_t / n_i + n_i / n_t);
        assert!(
            r < 1.0 && (t - leading).abs() <= 1e-3 * leading,
            "eta {eta}: R {r}, T {t}, leading order {leading}"
        );
        assert!(
            (r + t - 1.0).abs() <= 2.0 * EPS,
            "eta {eta}: R + T = {}",
            r + t
        );
        assert_eq!(dielectric(above, eta), 1.0);
        assert_eq!(dielectric_polarized(above, eta).transmittance(), 0.0);
    }
}

#[test]
fn nan_input_gives_nan_and_no_direction() {
    let nan = f64::NAN;
    assert!(dielectric(nan, GLASS).is_nan());
    assert!(dielectric(0.5, nan).is_nan());
    assert!(conductor(nan, 0.17, 3.1).is_nan());
    assert!(conductor(0.5, nan, 3.1).is_nan());
    assert!(conductor(0.5, 0.17, nan).is_nan());
    assert!(f0(nan, 0.0).is_nan() && f0(1.5, nan).is_nan());
    assert!(schlick(nan, 0.04).is_nan());
    assert!(cos_transmitted(nan, GLASS).is_none());
    assert!(refract(DVec3::new(nan, 0.0, 1.0), DVec3::Z, GLASS).is_none());
    assert!(refract(DVec3::Z, DVec3::Z, nan).is_none());
    let nan_dir = DVec3::new(nan, 0.0, 1.0);
    let brdfs: [&dyn Fn(DVec3, DVec3) -> f64; 3] = [
        &|wi, wo| Lambert { albedo: 0.5 }.eval(DVec3::Z, wi, wo),
        &|wi, wo| {
            BlinnPhong {
                kd: 0.1,
                ks: 0.5,
                shine: 8.0,
            }
            .eval(DVec3::Z, wi, wo)
        },
        &|wi, wo| {
            BlinnPhongReciprocal {
                kd: 0.1,
                ks: 0.5,
                shine: 8.0,
            }
            .eval(DVec3::Z, wi, wo)
        },
    ];
    for brdf in brdfs {
        assert!(brdf(nan_dir, DVec3::Z).is_nan() && brdf(DVec3::Z, nan_dir).is_nan());
        assert_eq!(
            brdf(-DVec3::Z, DVec3::Z),
            0.0,
            "light from below reflects nothing"
        );
    }
}

#[test]
fn non_physical_indices_give_nan_or_no_outcome() {
    for bad in [0.0, -1.5, f64::INFINITY, -f64::INFINITY, f64::NAN] {
        assert!(dielectric(0.5, bad).is_nan(), "eta {bad}");
        assert!(conductor(0.5, bad, 1.0).is_nan(), "n {bad}");
        assert!(refract(DVec3::Z, DVec3::Z, bad).is_none());
        for cos_i in [0.5, -0.5, 1.0] {
            assert_eq!(cos_transmitted(cos_i, bad), None, "eta {bad}, cos {cos_i}");
        }
        assert_eq!(transmitted_angle(0.3, bad), None, "eta_path {bad}");
        assert_eq!(critical_angle(bad), None, "eta_path {bad}");
        assert_eq!(brewster_angle(bad), None, "eta_path {bad}");
        assert_eq!(Incidence::resolve(0.5, bad), None, "eta {bad}");
    }
    // Angles of incidence outside [0, π/2] describe no incidence.
    for theta in [-0.1, 1.6, f64::NAN] {
        assert_eq!(transmitted_angle(theta, GLASS), None, "θ {theta}");
    }
    assert!(conductor(0.5_f64, 0.17, -3.1).is_nan());
    assert!(f0(0.0_f64, 1.0).is_nan() && f0(1.5_f64, -1.0).is_nan());
}

/// A cosine a rounding step outside [-1, 1], as a dot product of unit
/// vectors can give, is clamped: it is normal incidence, not NaN.
#[test]
fn cosines_rounded_past_one_are_clamped() {
    let just_over = 1.0 + 2.0 * EPS;
    assert_eq!(dielectric(just_over, GLASS), dielectric(1.0, GLASS));
    assert_eq!(dielectric(-just_over, GLASS), dielectric(-1.0, GLASS));
    assert_eq!(conductor(just_over, 0.17, 3.1), conductor(1.0, 0.17, 3.1));
}

/// The f32 tier at its own extremes: subnormal and tiny cosines, indices
/// 1e-3 and 1e3, κ = 1e3.
#[test]
fn f32_extremes_stay_finite_and_in_range() {
    let tiny = [f32::MIN_POSITIVE, 1e-38, 1e-45, 0.0];
    for cos_i in tiny.into_iter().chain(tiny.map(|c| -c)) {
        for eta in [1.5f32, 1e-3, 1e3, 1.0 + f32::EPSILON] {
            let f = dielectric_polarized(cos_i, eta);
            for v in [f.r_s, f.r_p, f.t_s, f.t_p] {
                assert!((0.0..=1.0).contains(&v), "cos {cos_i}, eta {eta}: {f:?}");
            }
            assert!((0.0..=1.0).contains(&conductor(cos_i, eta, 1e3)));
        }
    }
    assert_eq!(dielectric(0.3f32, 1.0), 0.0);
    let t = refract(Vec3::new(0.6, 0.0, 0.8), Vec3::Z, 1.5f32).unwrap();
    assert!((t.direction.length() - 1.0).abs() < 4.0 * f32::EPSILON);
}

/// Every law of a signed cosine and an index, in one tier, at one input: each
/// result a finite fraction, each refracted direction and carried radiance
/// finite, each angle in [0, π/2].
fn all_finite<V: Vector3>(
    cos_i: V::Scalar,
    eta: V::Scalar,
    kappa: V::Scalar,
) -> Result<(), String> {
    let fraction = |name: &str, v: V::Scalar| {
        let ok = v >= V::Scalar::zero() && v <= V::Scalar::one();
        ok.then_some(()).ok_or(format!("{name} = {v:?}"))
    };
    let f = dielectric_polarized(cos_i, eta);
    for (name, v) in [
        ("R_s", f.r_s),
        ("R_p", f.r_p),
        ("T_s", f.t_s),
        ("T_p", f.t_p),
    ] {
        fraction(name, v)?;
    }
    let c = conductor_polarized(cos_i, eta, kappa);
    fraction("conductor R_s", c.r_s)?;
    fraction("conductor R_p", c.r_p)?;
    fraction("Schlick", schlick(cos_i, f0(eta, kappa)))?;
    let one = V::Scalar::one();
    let sin_i = (one - cos_i * cos_i).max(V::Scalar::zero()).sqrt();
    let wi = V::new(sin_i, V::Scalar::zero(), cos_i);
    let n = V::new(V::Scalar::zero(), V::Scalar::zero(), one);
    if let Some(t) = refract(wi, n, eta) {
        let finite = t.direction.to_array().iter().all(|x| x.is_finite());
        finite.then_some(()).ok_or(format!("refracted {t:?}"))?;
        let carried = across_interface(one, t.eta_path);
        (carried.is_finite() && carried > V::Scalar::zero())
            .then_some(())
            .ok_or(format!("radiance across the interface {carried:?}"))?;
    }
    if let Some(c) = cos_transmitted(cos_i, eta) {
        fraction("cos θ_t", c)?;
    }
    // The angle laws, at the angle of this cosine and eta as the index along the path.
    let theta = cos_i.abs().min(one).acos();
    let angle = |name: &str, a: Option<V::Scalar>| match a {
        Some(a) if !(a >= V::Scalar::zero() && a <= V::Scalar::FRAC_PI_2()) => {
            Err(format!("{name} = {a:?}"))
        }
        _ => Ok(()),
    };
    angle("θ_t", transmitted_angle(theta, eta))?;
    angle("θ_c", critical_angle(eta))?;
    angle("θ_B", brewster_angle(eta))?;
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(5000))]

    /// No valid input gives NaN or infinity, over the whole documented range
    /// (crate conventions): in f64 η, n and κ from 1e-50 to 1e50 and κ = 0,
    /// in f32 from 1e-9 to 1e9, log-uniform, every cosine of both signs.
    #[test]
    fn valid_input_never_gives_nan_or_infinity(
        cos_i in -1.0..=1.0f64,
        log_eta in -50.0..=50.0f64,
        log_kappa in -50.0..=50.0f64,
        zero_kappa in any::<bool>(),
    ) {
        let kappa = if zero_kappa { 0.0 } else { 10f64.powf(log_kappa) };
        all_finite::<DVec3>(cos_i, 10f64.powf(log_eta), kappa).map_err(TestCaseError::fail)?;
        let scale = 9.0 / 50.0; // the f32 range
        let kappa = if zero_kappa { 0.0 } else { 10f32.powf((log_kappa * scale) as f32) };
        all_finite::<Vec3>(cos_i as f32, 10f32.powf((log_eta * scale) as f32), kappa)
            .map_err(TestCaseError::fail)?;
    }
}

/// The ends of the documented range of indices (crate conventions,
/// `domain::INDEX_RANGE` and `INDEX_RANGE_F32`), at the extreme cosines:
/// f64 from 1e-50 to 1e50, f32 from 1e-9 to 1e9.
#[test]
fn the_ends_of_the_documented_index_range_are_valid() {
    let cosines = [1.0, 0.5, 1e-30, 0.0, -0.0, -1e-30, -0.5, -1.0];
    let (lo, hi) = domain::INDEX_RANGE.range.into_inner();
    for eta in [lo, hi] {
        for kappa in [0.0, lo, hi] {
            for c in cosines {
                all_finite::<DVec3>(c, eta, kappa)
                    .unwrap_or_else(|e| panic!("{eta}, {kappa}, {c}: {e}"));
            }
        }
    }
    let (lo, hi) = domain::INDEX_RANGE_F32.range.into_inner();
    let (lo, hi) = (lo as f32, hi as f32);
    for eta in [lo, hi] {
        for kappa in [0.0, lo, hi] {
            for c in cosines.map(|c| c as f32) {
                all_finite::<Vec3>(c, eta, kappa)
                    .unwrap_or_else(|e| panic!("{eta}, {kappa}, {c}: {e}"));
            }
        }
    }
}
