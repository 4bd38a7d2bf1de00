//! The course's formulas, formula for formula, against the laws: each test
//! names the source (`000`, `001`, `003` in `shared/seeds/`) and says whether
//! the formula is right, and if not, how it is wrong, by measurement.
//!
//! The course formulas take `v`, the ray's direction of travel (towards the
//! surface), with the normal on the side the ray comes from; the crate's
//! laws take `wi = −v`.

use glam::DVec3;
use proptest::prelude::*;
use radiometry::course;
use radiometry::fresnel::{dielectric, f0, schlick};
use radiometry::snell::critical_angle;
use radiometry::specular::refract;

const EPS: f64 = f64::EPSILON;

/// A direction of travel towards the surface z = 0 from above, at least
/// 0.1° off grazing.
fn incoming() -> impl Strategy<Value = DVec3> {
    (0.0018..=1.0f64, 0.0..std::f64::consts::TAU).prop_map(|(cos, phi): (f64, f64)| {
        let sin = (1.0 - cos * cos).sqrt();
        DVec3::new(sin * phi.cos(), sin * phi.sin(), -cos)
    })
}

fn relative_index() -> impl Strategy<Value = f64> {
    0.25..=4.0f64
}

/// How far a textbook refraction formula may sit from the law and still be
/// called right. Every textbook form takes `cos_t = √(1 − r²(1 − cos²θᵢ))`
/// of a discriminant it computes with an absolute rounding error of a few
/// ε·(1 + r²), and the square root multiplies that by `1/(2 cos_t)`: near
/// the critical angle the formula is correct but ill-conditioned. So the
/// tolerance is 32ε for two differently ordered evaluations, plus
/// `4ε(1 + r²)/cos_t` for that conditioning (`r = 1/eta`, the sources' ratio).
fn textbook_tolerance(cos_t: f64, eta: f64) -> f64 {
    let r = 1.0 / eta;
    32.0 * EPS + 4.0 * EPS * (1.0 + r * r) / cos_t
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// `001`, slide: `t = r i + (w − k) n`, `r = n₁/n₂`, `w = −(i·n) r`,
    /// `k = √(1 + (w − r)(w + r))`. Correct: it equals the law wherever light
    /// refracts (within [`textbook_tolerance`]), and is NaN under total
    /// internal reflection.
    #[test]
    fn course_001_slide_refraction_is_snells_law(v in incoming(), eta in relative_index()) {
        let n = DVec3::Z;
        let slide = course::refract_001_slide(v, n, 1.0 / eta);
        match refract(-v, n, eta) {
            Some(t) => prop_assert!(
                (slide - t.direction).length() <= textbook_tolerance(t.cos_t, eta),
                "{slide} vs {}", t.direction
            ),
            None => prop_assert!(slide.is_nan()),
        }
    }

    /// `001`, Cg `refract(I, N, etaRatio)`: correct where light refracts
    /// (within [`textbook_tolerance`]), and the zero vector under total internal reflection.
    #[test]
    fn course_001_cg_refract_is_snells_law_with_zero_vector_for_tir(v in incoming(), eta in relative_index()) {
        let n = DVec3::Z;
        let cg = course::refract_001_cg(v, n, 1.0 / eta);
        match refract(-v, n, eta) {
            Some(t) => prop_assert!((cg - t.direction).length() <= textbook_tolerance(t.cos_t, eta)),
            None => prop_assert_eq!(cg, DVec3::ZERO),
        }
    }

    /// `003`, code: `V / ns + N (cosa / ns − √disc)` with `ns = n_t / n_i`.
    /// Correct where light refracts (within [`textbook_tolerance`]); the zero vector under total internal
    /// reflection.
    #[test]
    fn course_003_code_refract_is_snells_law_with_zero_vector_for_tir(v in incoming(), eta in relative_index()) {
        let n = DVec3::Z;
        let code = course::refract_003_code(v, n, eta);
        match refract(-v, n, eta) {
            Some(t) => prop_assert!((code - t.direction).length() <= textbook_tolerance(t.cos_t, eta)),
            None => prop_assert_eq!(code, DVec3::ZERO),
        }
    }
}

/// `003`, boxed formula: `v/n + N (cos(α/n) − √(1 − (1 − cos²α)/n²))`.
/// Wrong: `cos(α/n)` where the chapter's own code has `cos(α)/n`. Into glass
/// at 45° the boxed vector is 0.678 long instead of 1 and points 15.9° off
/// the refracted direction; even head-on it is 1/1.5 long.
#[test]
fn course_003_boxed_refraction_formula_is_wrong() {
    let n = DVec3::Z;
    let v = DVec3::new(1.0, 0.0, -1.0).normalize(); // 45°
    let boxed = course::refract_003_boxed(v, n, 1.5);
    let law = refract(-v, n, 1.5).unwrap().direction;
    let angle_off = boxed.normalize().dot(law).acos().to_degrees();
    assert!(
        (boxed.length() - 0.6780).abs() < 1e-4,
        "length {}",
        boxed.length()
    );
    assert!((angle_off - 15.92).abs() < 0.01, "{angle_off}°");
    // Even head-on it is wrong: cos(0/n) = 1 where cos(0)/n = 1/n, so the
    // boxed vector is −N/1.5 instead of −N.
    let straight = course::refract_003_boxed(-n, n, 1.5);
    assert!((straight - (-n / 1.5)).length() < 1e-15, "{straight}");
    // The code's version of the same formula is right (see the property test above).
    let code = course::refract_003_code(v, n, 1.5);
    assert!((code - law).length() < 1e-15);
}

/// `003`, derivation: `N⊥ = (v + N)/sin α`, "since |v + N| = sin α". Wrong:
/// the tangential part of `v` is `v + N cos α`. At 45° the stated `N⊥` has
/// length 1.082 instead of 1 and makes 67.5° with `N` instead of 90°.
#[test]
fn course_003_tangent_is_neither_unit_nor_perpendicular() {
    let n = DVec3::Z;
    let v = DVec3::new(1.0, 0.0, -1.0).normalize();
    let t = course::tangent_003(v, n);
    assert!((t.length() - 1.0824).abs() < 1e-4, "{}", t.length());
    assert!((t.normalize().dot(n).acos().to_degrees() - 67.5).abs() < 1e-9);
    // At grazing incidence (α = 90°) the claim happens to hold.
    let grazing = course::tangent_003(DVec3::X, n);
    assert!(
        (grazing.length() - 2f64.sqrt()).abs() < 1e-15,
        "and even there |v + N| = √2, not sin α = 1"
    );
}

/// `000`, GLSL `Fresnel(F0, cosTheta) = F0 + (1 − F0) cosθ⁵`. Wrong: the
/// term is `(1 − cos θ)⁵`. For the course's gold the mirror reflects 100 %
/// head-on instead of F0 = (0.938, 0.846, 0.391), and only F0 at grazing
/// angles instead of 100 %: the Fresnel effect backwards.
#[test]
fn course_000_glsl_fresnel_is_backwards() {
    for f0 in radiometry::fresnel::f0_rgb([0.17, 0.35, 1.5], [3.1, 2.7, 1.9]) {
        assert_eq!(course::fresnel_000_glsl(f0, 1.0), 1.0);
        assert_eq!(course::fresnel_000_glsl(f0, 0.0), f0);
        assert_eq!(schlick(1.0, f0), f0);
        assert_eq!(schlick(0.0, f0), 1.0);
    }
}

/// `003`, `Fresnel(V, N)`: Schlick with `F0 = ((n−1)² + κ²)/((n+1)² + κ²)`
/// and `cosa = −V·N`. Correct as Schlick's approximation; for glass the
/// textbook example's 4 % is exact at normal incidence.
#[test]
fn course_003_f0_formula_and_glass_example_are_right() {
    assert!((f0(1.5_f64, 0.0) - 0.04).abs() < 1e-17);
    assert!((dielectric(1.0_f64, 1.5) - 0.04).abs() < 1e-17);
}

/// `001`, slide: `max(0, min(1, bias + scale (0 + I·N)^power))`. Wrong: with
/// `I` towards the surface `I·N < 0`, and a negative base to a fractional
/// power is NaN, which the clamps then turn into whatever the hardware's
/// min/max make of NaN (IEEE minNum, as here: 1, a perfect mirror); an odd
/// integer power gives `bias − scale cos^power θ`, which never rises above
/// the bias: no Fresnel effect at all. The vertex program's
/// `1 + dot(I, N)` is Schlick's curve for `bias = F0, scale = 1 − F0,
/// power = 5`, and exceeds 1 when `bias + scale > 1` because, unlike the
/// slide, it does not clamp.
#[test]
fn course_001_empirical_fresnel_slide_is_wrong_code_is_schlick() {
    let n = DVec3::Z;
    let v = DVec3::new(0.6, 0.0, -0.8);
    assert_eq!(
        course::EmpiricalFresnel {
            bias: 0.04,
            scale: 0.96,
            power: 5.5
        }
        .slide(v, n),
        1.0
    );
    let schlick_like = course::EmpiricalFresnel {
        bias: 0.04,
        scale: 0.96,
        power: 5.0,
    };
    for k in 0..=100 {
        let cos = k as f64 / 100.0;
        let v = DVec3::new((1.0 - cos * cos).sqrt(), 0.0, -cos);
        // With an odd power the slide gives max(0, bias − scale cos⁵θ): never
        // above the bias, so no rise towards grazing incidence at all.
        let slide = schlick_like.slide(v, n);
        assert!((slide - (0.04 - 0.96 * cos.powi(5)).max(0.0)).abs() <= 4.0 * EPS && slide <= 0.04);
        let code = schlick_like.vertex_program(v, n);
        assert!(
            (code - schlick(cos, 0.04)).abs() <= 4.0 * EPS,
            "cos {cos}: {code}"
        );
    }
    let grazing = DVec3::X;
    assert!(
        course::EmpiricalFresnel {
            bias: 0.5,
            scale: 0.9,
            power: 5.0
        }
        .vertex_program(grazing, n)
            > 1.0
    );
}

/// `003`, quiz 2: a dielectric of index 1.4 reflects F0 = 0.16/5.76 =
/// 2.777…% at normal incidence. The printed answer "≈ 2.77 %" truncates
/// instead of rounding: to two decimals it is 2.78 %.
#[test]
fn course_003_quiz_2_f0_of_1_4_is_2_78_percent() {
    let percent = 100.0 * f0(1.4_f64, 0.0);
    assert!((percent - 25.0 / 9.0).abs() < 1e-13, "{percent}");
    assert_eq!(format!("{percent:.2}"), "2.78");
}

/// `003`, quiz 4: leaving a medium of index 1/0.1 = 10 into air, total
/// internal reflection starts at asin(1/10) = 5.74°. The printed answer is
/// right, though its working swaps θ and θ_in.
#[test]
fn course_003_quiz_4_critical_angle_of_index_10_is_5_74_degrees() {
    let theta = critical_angle(0.1_f64).unwrap().to_degrees();
    assert_eq!(format!("{theta:.2}"), "5.74");
    // Just past it nothing leaves the medium (eta = 10 seen from inside).
    let past = (theta + 1e-6).to_radians();
    assert!(refract(DVec3::new(past.sin(), 0.0, -past.cos()), DVec3::Z, 10.0).is_none());
}
