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
use radiometry::fresnel::{dielectric, dielectric_transmittance, f0, schlick};
use radiometry::radiance::across_interface;
use radiometry::snell::{cos_transmitted, critical_angle, transmitted_angle};
use radiometry::specular::{reflect, refract};

mod common;
use common::strategies::{
    relative_index_uniform, travel_direction_down, travel_direction_down_oblique, unit_direction,
};

const EPS: f64 = f64::EPSILON;

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

/// What a course refraction formula gives under total internal reflection.
#[derive(Clone, Copy, Debug)]
enum UnderTir {
    /// NaN, from the square root of a negative discriminant.
    Nan,
    /// The zero vector, the formula's own signal.
    Zero,
}

/// `formula`, a course formula's refracted direction for travel `v` through
/// the surface z = 0 (normal +z) into relative index `eta`, is Snell's law
/// within [`textbook_tolerance`] where light refracts, and `under_tir` where
/// it does not.
fn is_snells_law(
    formula: DVec3,
    v: DVec3,
    eta: f64,
    under_tir: UnderTir,
) -> Result<(), TestCaseError> {
    match (refract(-v, DVec3::Z, eta), under_tir) {
        (Some(t), _) => prop_assert!(
            (formula - t.direction).length() <= textbook_tolerance(t.cos_t, eta),
            "{formula} vs {}",
            t.direction
        ),
        (None, UnderTir::Nan) => prop_assert!(formula.is_nan(), "{formula}"),
        (None, UnderTir::Zero) => prop_assert_eq!(formula, DVec3::ZERO),
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// `001`, slide: `t = r i + (w − k) n`, `r = n₁/n₂`, `w = −(i·n) r`,
    /// `k = √(1 + (w − r)(w + r))`. Correct: it equals the law wherever light
    /// refracts (within [`textbook_tolerance`]), and is NaN under total
    /// internal reflection.
    #[test]
    fn course_001_slide_refraction_is_snells_law(v in travel_direction_down(), eta in relative_index_uniform()) {
        let n = DVec3::Z;
        let slide = course::refract_001_slide(v, n, 1.0 / eta);
        is_snells_law(slide, v, eta, UnderTir::Nan)?;
    }

    /// `001`, Cg `refract(I, N, etaRatio)`: correct where light refracts
    /// (within [`textbook_tolerance`]), and the zero vector under total internal reflection.
    #[test]
    fn course_001_cg_refract_is_snells_law_with_zero_vector_for_tir(v in travel_direction_down(), eta in relative_index_uniform()) {
        let n = DVec3::Z;
        let cg = course::refract_001_cg(v, n, 1.0 / eta);
        is_snells_law(cg, v, eta, UnderTir::Zero)?;
    }

    /// `003`, code: `V / ns + N (cosa / ns − √disc)` with `ns = n_t / n_i`.
    /// Correct where light refracts (within [`textbook_tolerance`]); the zero vector under total internal
    /// reflection.
    #[test]
    fn course_003_code_refract_is_snells_law_with_zero_vector_for_tir(v in travel_direction_down(), eta in relative_index_uniform()) {
        let n = DVec3::Z;
        let code = course::refract_003_code(v, n, eta);
        is_snells_law(code, v, eta, UnderTir::Zero)?;
    }
}

/// The ray's direction of travel at incidence angle `alpha` in the xz-plane,
/// towards the surface z = 0 (normal +z) from above.
fn travelling_at(alpha: f64) -> DVec3 {
    DVec3::new(alpha.sin(), 0.0, -alpha.cos())
}

/// Incidence angles for the closed-form checks: near-normal to grazing.
const ALPHAS_DEG: [f64; 8] = [1.0, 10.0, 30.0, 45.0, 60.0, 75.0, 85.0, 90.0];

/// Relative indices for the closed-form checks: water, glass, diamond, and
/// two between, all entering a denser medium as the chapter's derivation does.
const INDICES: [f64; 5] = [1.2, 4.0 / 3.0, 1.5, 2.0, 2.42];

/// Splits `w` into its component along `n` and the length of the rest.
fn normal_and_tangential(w: DVec3, n: DVec3) -> (f64, f64) {
    let along = w.dot(n);
    (along, (w - n * along).length())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// `003` line 175 `R = v + 2N cos α` (`cos α = −v·N`) and line 184
    /// `V − N dot(N, V) 2`: the law of reflection, `specular::reflect(−v, N)`,
    /// for any unit `v` and `N` (both are even in `N`). Tolerance 16ε: the
    /// same products and sums in another order, on components of size
    /// `|v| + 2|v·N| ≤ 3`, each rounded a few times.
    #[test]
    fn course_003_boxed_and_code_reflection_are_the_law_of_reflection(v in unit_direction(), n in unit_direction()) {
        let law = reflect(-v, n);
        let boxed = course::reflect_003_boxed(v, n);
        let code = course::reflect_003_code(v, n);
        prop_assert!((boxed - law).length() <= 16.0 * EPS, "{boxed} vs {law}");
        prop_assert!((code - law).length() <= 16.0 * EPS, "{code} vs {law}");
    }

    /// `001` line 40 `r = e − 2(n·e)n`, line 73 `R = I − 2N(N·I)` and the Cg
    /// `reflect` (lines 76–79): the law of reflection, within 16ε as above.
    #[test]
    fn course_001_reflect_is_the_law_of_reflection(i in unit_direction(), n in unit_direction()) {
        let law = reflect(-i, n);
        let slide = course::reflect_001(i, n);
        prop_assert!((slide - law).length() <= 16.0 * EPS, "{slide} vs {law}");
    }

    /// `003` line 95 `θ = arcsin(sin θin / n)` (and `001` line 373,
    /// `n₁ sin θ₁ = n₂ sin θ₂`): Snell's law where light refracts, NaN
    /// where it is totally reflected (there is no guard). Tolerance
    /// `4ε + (1 + 1/n²) ε / cos θ_t` against `snell::transmitted_angle`:
    /// both are `atan2(x, c)` in effect, with `x = sin θin / n` and
    /// `c = cos θ_t`, and `√(c² + d)` moves by at most `|d|/(2c)`. The
    /// formula's `c² = 1 − x²` (inside `arcsin`) inherits at most 2ε from the
    /// rounded `x`; the crate's `c² = d / n²`, with the discriminant `d`
    /// summed exactly from one rounded `sin θin` or `cos θin` (whichever the
    /// angle determines better), inherits at most `2ε / n²` from it. 4ε
    /// covers the library calls. Near the
    /// critical angle both are right but ill-conditioned. `n sin θ = sin θin`
    /// within 4ε, three roundings of numbers ≤ 1. The two may disagree on
    /// whether light refracts only where `x` is within 2ε of 1.
    #[test]
    fn course_003_snell_angle_formula_is_snells_law_without_tir_guard(
        theta_in in 0.0..=std::f64::consts::FRAC_PI_2,
        eta in relative_index_uniform(),
    ) {
        let course = course::refraction_angle_003(theta_in, eta);
        let x = theta_in.sin() / eta;
        match (transmitted_angle(theta_in, eta), course.is_nan()) {
            (Some(law), false) => {
                let cos_t = cos_transmitted(theta_in.cos(), eta).unwrap();
                prop_assert!(
                    (course - law).abs() <= 4.0 * EPS + (1.0 + 1.0 / (eta * eta)) * EPS / cos_t,
                    "{course} vs {law}"
                );
                prop_assert!((eta * course.sin() - theta_in.sin()).abs() <= 4.0 * EPS);
            }
            (None, true) => {}
            (law, _) => prop_assert!(
                (x - 1.0).abs() <= 2.0 * EPS,
                "law {law:?}, course {course}, sin θin / n = {x}"
            ),
        }
    }

    /// `003` lines 217 and 240, `T = N⊥ sin β − N cos β`,
    /// `cos β = √(1 − sin²α/n²)`, with the true unit tangent
    /// `N⊥ = (v + N cos α)/sin α` from the chapter's reflection section
    /// (line 170): Snell's law, within [`textbook_tolerance`] (the same
    /// discriminant; the tangent's `sin α` cancels against `sin β`'s),
    /// and NaN under total internal reflection.
    #[test]
    fn course_003_derivation_with_the_true_tangent_is_snells_law(v in travel_direction_down_oblique(), eta in relative_index_uniform()) {
        let n = DVec3::Z;
        let cos_alpha = -v.dot(n);
        let sin_alpha = (1.0 - cos_alpha * cos_alpha).sqrt();
        let n_perp = course::perpendicular_003(v, n) * (1.0 / sin_alpha);
        let derived = course::refract_003_derivation(v, n, eta, n_perp);
        is_snells_law(derived, v, eta, UnderTir::Nan)?;
    }
}

/// `003` line 170: the perpendicular component `v + N cos α` is right: it
/// is perpendicular to `N` and `sin α` long. Tolerance 4ε: `v.z + cos α`
/// cancels exactly for `N = z`, and the length is one rounded square root.
#[test]
fn course_003_reflection_section_perpendicular_is_the_tangential_part() {
    let n = DVec3::Z;
    for alpha in ALPHAS_DEG.map(f64::to_radians) {
        let p = course::perpendicular_003(travelling_at(alpha), n);
        assert!(p.dot(n).abs() <= 4.0 * EPS, "{alpha}: {p}");
        assert!(
            (p.length() - alpha.sin()).abs() <= 4.0 * EPS,
            "{alpha}: {p}"
        );
    }
}

/// `003` line 223, `N⊥ = (v + N)/sin α`, "since |v + N| = sin α". Wrong at
/// every α in (0°, 90°]: the tangential part of `v` is `v + N cos α`, and
/// `v + N` has length `√(2 − 2 cos α) = 2 sin(α/2)` and `(v + N)·N =
/// 1 − cos α`. So the stated `N⊥` is `1/cos(α/2)` long, has `N⊥·N =
/// tan(α/2)`, and makes `90° − α/2` with `N` (grazing: √2 long, 45° off).
/// Tolerance `8ε + 2ε/sin²α`: the chapter's `sin α = √(1 − cos²α)` has a
/// relative error of `ε/(2 sin²α)` from the cancellation in `1 − cos²α`,
/// and a few roundings of numbers ≤ 2 come on top.
#[test]
fn course_003_tangent_is_neither_unit_nor_perpendicular() {
    let n = DVec3::Z;
    for alpha in ALPHAS_DEG.map(f64::to_radians) {
        let v = travelling_at(alpha);
        let tol = 8.0 * EPS + 2.0 * EPS / alpha.sin().powi(2);
        let sum = v + n;
        assert!((sum.length() - (2.0 - 2.0 * alpha.cos()).sqrt()).abs() <= tol);
        assert!((sum.dot(n) - (1.0 - alpha.cos())).abs() <= tol);
        let t = course::tangent_003(v, n);
        let half = alpha / 2.0;
        assert!(
            (t.length() - 1.0 / half.cos()).abs() <= tol,
            "{alpha}: |N⊥| = {}",
            t.length()
        );
        assert!(
            (t.dot(n) - half.tan()).abs() <= tol,
            "{alpha}: N⊥·N = {}",
            t.dot(n)
        );
        let angle = t.cross(n).length().atan2(t.dot(n));
        assert!(
            (angle - (std::f64::consts::FRAC_PI_2 - half)).abs() <= tol,
            "{alpha}: {angle}"
        );
        // It fails by more than rounding everywhere: sec x − 1 ≥ x²/2 and
        // tan x ≥ x, so it is off by at least α²/8 in length and α/2 in N⊥·N.
        assert!(t.length() - 1.0 >= alpha * alpha / 8.0 && alpha * alpha / 8.0 > 10.0 * tol);
        assert!(t.dot(n) >= half && half > 10.0 * tol);
    }
    // Grazing, exactly: |v + N| = √2 and (v + N)·N = 1, not sin α = 1 and 0.
    let grazing = course::tangent_003(DVec3::X, n);
    assert!((grazing.length() - 2f64.sqrt()).abs() <= 2.0 * EPS);
    assert_eq!(grazing.dot(n), 1.0);
}

/// `003` lines 217–240 with the chapter's own `N⊥ = (v + N)/sin α`: the
/// derivation then gives `v/n + N (1/n − cos β)`. The tangential part
/// `sin α / n` survives (the wrong `N⊥` has the right tangential part,
/// `sin α`, before the division); the component along `N` is off by
/// `(1 − cos α)/n` from Snell's `−cos β`. Tolerance 16ε: a dozen roundings
/// of numbers ≤ 2 (the two `sin α` evaluations are identical and cancel).
#[test]
fn course_003_derivation_with_its_own_tangent_is_off_by_1_minus_cos_over_n() {
    let n = DVec3::Z;
    for eta in INDICES {
        for alpha in ALPHAS_DEG.map(f64::to_radians) {
            let v = travelling_at(alpha);
            let derived = course::refract_003_derivation(v, n, eta, course::tangent_003(v, n));
            let law = refract(-v, n, eta).unwrap();
            let (normal, tangential) = normal_and_tangential(derived, n);
            assert!(
                (tangential - alpha.sin() / eta).abs() <= 16.0 * EPS,
                "{eta} {alpha}"
            );
            let error = (1.0 - alpha.cos()) / eta;
            assert!(
                (normal - (error - law.cos_t)).abs() <= 16.0 * EPS,
                "{eta} {alpha}: {normal} vs {}",
                error - law.cos_t
            );
            assert!(error > 100.0 * EPS, "wrong at {alpha} rad by {error}");
        }
    }
}

/// `003` line 246, boxed: `v/n + N (cos(α/n) − √(1 − (1 − cos²α)/n²))`.
/// Wrong: `cos(α/n)` where the chapter's code has `cos(α)/n`. Its
/// tangential part `sin α / n` is right; its component along `N` is
/// `−cos α/n + cos(α/n) − cos β` instead of `−cos β`, off by
/// `cos(α/n) − cos(α)/n > 0` for every `n > 1` (as `cos(α/n) ≥ cos α ≥
/// cos(α)/n`, one of them strictly). Head-on it is `−N/n` instead of `−N`. Tolerance 16ε: as for
/// the derivation, plus `acos` of a cosine rounded to ε/2, whose error
/// `ε/(2 sin α)` is damped by `sin(α/n)/n` in `cos(α/n)`.
#[test]
fn course_003_boxed_refraction_formula_is_wrong() {
    let n = DVec3::Z;
    for eta in INDICES {
        for alpha in ALPHAS_DEG.map(f64::to_radians) {
            let v = travelling_at(alpha);
            let boxed = course::refract_003_boxed(v, n, eta);
            let law = refract(-v, n, eta).unwrap();
            let (normal, tangential) = normal_and_tangential(boxed, n);
            assert!(
                (tangential - alpha.sin() / eta).abs() <= 16.0 * EPS,
                "{eta} {alpha}"
            );
            let error = (alpha / eta).cos() - alpha.cos() / eta;
            assert!(
                (normal - (error - law.cos_t)).abs() <= 16.0 * EPS,
                "{eta} {alpha}: {normal} vs {}",
                error - law.cos_t
            );
            assert!(error > 100.0 * EPS, "wrong at {alpha} rad by {error}");
            // The chapter's code has the right term, and is the law.
            let code = course::refract_003_code(v, n, eta);
            assert!((code - law.direction).length() <= textbook_tolerance(law.cos_t, eta));
        }
        // Head-on: cos(0/n) = 1 where cos(0)/n = 1/n.
        let straight = course::refract_003_boxed(-n, n, eta);
        assert!((straight - (-n / eta)).length() <= 4.0 * EPS, "{straight}");
    }
}

/// `003` line 95 has no guard for total internal reflection: leaving glass
/// (`n = 1/1.5`), just below the critical angle `asin(1/1.5)` it refracts
/// to just below 90°, and past it the arcsine of `sin θin / n > 1` is NaN,
/// where the crate reports `None`. The 1e-9 rad offsets are far above
/// rounding (ε) and far below the angles' scale.
#[test]
fn course_003_snell_angle_formula_is_nan_beyond_the_critical_angle() {
    let eta = 1.0 / 1.5;
    let critical = critical_angle(eta).unwrap();
    let below = course::refraction_angle_003(critical - 1e-9, eta);
    assert!(
        below < std::f64::consts::FRAC_PI_2 && below > 1.5,
        "{below}"
    );
    for theta_in in [
        critical + 1e-9,
        60f64.to_radians(),
        std::f64::consts::FRAC_PI_2,
    ] {
        assert!(course::refraction_angle_003(theta_in, eta).is_nan());
        assert_eq!(transmitted_angle(theta_in, eta), None);
    }
}

/// `dω_out / dω_in` of the map `w(θ, φ) ↦ f(w)` at `(θ, φ)`, measured:
/// the ratio of the areas that central differences with step `h` span on
/// the unit sphere, after and before the map.
fn solid_angle_ratio(
    f: impl Fn(DVec3) -> DVec3,
    w: impl Fn(f64, f64) -> DVec3,
    theta: f64,
    phi: f64,
    h: f64,
) -> f64 {
    let area = |g: &dyn Fn(f64, f64) -> DVec3| {
        let d_theta = g(theta + h, phi) - g(theta - h, phi);
        let d_phi = g(theta, phi + h) - g(theta, phi - h);
        d_theta.cross(d_phi).length()
    };
    area(&|t, p| f(w(t, p))) / area(&w)
}

/// `003` line 90: reflected radiance `L_in F`, refracted `L_in (1 − F)`.
/// The first is right; the second is the transmitted *power* fraction, not
/// a radiance. Measured without `radiance::across_interface`'s formula:
/// directions around `wi` are refracted with `specular::refract` (and
/// reflected with `specular::reflect`), the solid-angle ratio `dω_t/dω_i`
/// is measured by central differences, and power conservation
/// `L_t cos θ_t dω_t = T L_i cos θ_i dω_i` (`T` the exact Fresnel
/// transmittance) gives `L_t`. That `L_t` is `across_interface(T L_i, η_cam)`,
/// `η_cam` the `Refraction::eta_path` of the reversed (camera) path, and it is
/// the course's `L_in (1 − F)` times `η²`, `η = n_t/n_i` along the light:
/// the course's radiance is 2.25 times too small entering glass and 2.25
/// times too large leaving it. The reflected beam keeps its solid angle.
///
/// Tolerance 1e-8 relative: central differences with step `h = 1e-5` rad
/// err by `C h²`, `C = |f'''/(6 f')|`; `C` is largest leaving glass at 35°
/// (6.8° below the critical angle), where the error, measured at h = 1e-4
/// and 1e-5, scales as `h²` with `C ≈ 7`: 7e-10. Rounding adds about
/// `ε/h ≈ 2e-11`. 1e-8 leaves a factor of ten over both.
#[test]
fn course_003_refracted_radiance_misses_the_eta_squared_of_solid_angle_compression() {
    let n = DVec3::Z;
    let h = 1e-5;
    let l_in = 1.0; // W/(sr·m²); every relation below is linear in it
    let tol = 1e-8;
    // (interface eta = n_inside / n_outside, light from the inside?, θ_i in degrees)
    let mut cases = vec![];
    for eta in [1.5, 4.0 / 3.0] {
        for deg in [5.0, 20.0, 45.0, 70.0, 85.0] {
            cases.push((eta, false, deg));
        }
        for deg in [5.0, 20.0, 35.0] {
            cases.push((eta, true, deg));
        }
    }
    for (eta, from_inside, deg) in cases {
        let side = if from_inside { -1.0 } else { 1.0 };
        let w = |theta: f64, phi: f64| {
            DVec3::new(
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                side * theta.cos(),
            )
        };
        let (theta, phi) = (f64::to_radians(deg), 0.3);
        let wi = w(theta, phi);
        let refracted = refract(wi, n, eta).unwrap();
        let eta_light = refracted.eta_path;
        let d_omega_ratio =
            solid_angle_ratio(|w| refract(w, n, eta).unwrap().direction, w, theta, phi, h);
        let (cos_i, cos_t) = (wi.z.abs(), refracted.direction.z.abs());
        let t = dielectric_transmittance(wi.z, eta);
        let l_t = t * l_in * cos_i / (cos_t * d_omega_ratio);

        let camera = refract(refracted.direction, n, eta).unwrap();
        assert!(
            (camera.direction - wi).length() < 1e-14,
            "the camera path retraces the light"
        );
        let crate_law = across_interface(t * l_in, camera.eta_path);
        assert!(
            (l_t / crate_law - 1.0).abs() <= tol,
            "{eta} {from_inside} {deg}°: {l_t} vs {crate_law}"
        );

        let (reflected, refracted_course) = course::radiance_split_003(l_in, dielectric(wi.z, eta));
        let factor = l_t / refracted_course;
        assert!(
            (factor / (eta_light * eta_light) - 1.0).abs() <= tol,
            "{eta} {from_inside} {deg}°: L_t / (L_in (1 − F)) = {factor}, η² = {}",
            eta_light * eta_light
        );
        assert!(
            (factor - 1.0).abs() > 0.4,
            "the course is off by η² = {factor}"
        );

        // Reflection: the mirror keeps dω and cos θ, so L_r = F L_in is right.
        let d_omega_mirror = solid_angle_ratio(|w| reflect(w, n), w, theta, phi, h);
        assert!((d_omega_mirror - 1.0).abs() <= tol, "{d_omega_mirror}");
        let l_r = dielectric(wi.z, eta) * l_in * cos_i / (reflect(wi, n).z.abs() * d_omega_mirror);
        assert!((l_r / reflected - 1.0).abs() <= tol, "{l_r} vs {reflected}");
    }
}

/// `001` lines 390–395: `t = −c n + i`, normalised, `c ≈ 1` "for water".
/// An approximation: in the plane of incidence `t` makes
/// `atan2(sin α, cos α + c)` with `−n`, exactly `α/2` for `c = 1` whatever
/// the medium. Against Snell's `θ_t = asin(sin α / η)` the error
/// `α/2 − θ_t` is `(1/2 − 1/η) α + O(α³)` near the normal, and largest in
/// size where `dθ_t/dα = 1/2`, at `cos²α = (η² − 1)/3`: water (η = 4/3)
/// is off by 10.5° at 59.4°, glass by 5.7° at 49.8°. The first-order fit
/// `c = η − 1` leaves `(η − 1) α³/(2η³)`.
///
/// Tolerances: 8ε for angles from `atan2` of normalised vectors (a few
/// roundings, well conditioned); the grid maximum (step Δ = 0.01°) may fall
/// below the true one by `max|e''| (Δ/2)²/2 ≤ (Δ/2)²/(2√(η² − 1))`, under
/// 5e-9 rad; at α = 0.01 the Taylor forms' next terms are `O(α²) = 1e-4`
/// relative: twice the `α³` term for the first-order slope, and 1e-3
/// relative for the cubic coefficient.
#[test]
fn course_001_cheap_refraction_bends_by_half_the_incidence_angle() {
    let n = DVec3::Z;
    let angle_from_down = |t: DVec3| t.cross(-n).length().atan2(-t.dot(n));
    let exact = |alpha: f64, eta: f64| transmitted_angle(alpha, eta).unwrap();
    for eta in [4.0 / 3.0, 1.5] {
        // Every incidence angle: the approximation bends to exactly α/2.
        let step = 0.01f64.to_radians();
        let mut worst = 0.0f64;
        for k in 0..=9000 {
            let alpha = (k as f64 * step).min(std::f64::consts::FRAC_PI_2);
            let t = course::refract_001_approx(travelling_at(alpha), n, 1.0);
            assert!((t.length() - 1.0).abs() <= 4.0 * EPS);
            assert!(
                (angle_from_down(t) - alpha / 2.0).abs() <= 8.0 * EPS,
                "{alpha}"
            );
            let law = refract(-travelling_at(alpha), n, eta).unwrap().direction;
            let measured = t.cross(law).length().atan2(t.dot(law));
            assert!((measured - (alpha / 2.0 - exact(alpha, eta)).abs()).abs() <= 8.0 * EPS);
            worst = worst.max(measured);
        }
        let alpha_worst = ((eta * eta - 1.0) / 3.0).sqrt().acos();
        let closed_worst = exact(alpha_worst, eta) - alpha_worst / 2.0;
        let grid_slack = (step / 2.0).powi(2) / (2.0 * (eta * eta - 1.0).sqrt());
        assert!(
            worst <= closed_worst + 8.0 * EPS && worst >= closed_worst - grid_slack - 8.0 * EPS
        );
        // The doc's rounded figures come from this closed form.
        let quoted = format!(
            "{:.1}° at {:.1}°",
            closed_worst.to_degrees(),
            alpha_worst.to_degrees()
        );
        let expected = if eta == 1.5 {
            "5.7° at 49.8°"
        } else {
            "10.5° at 59.4°"
        };
        assert_eq!(quoted, expected);

        // Near the normal: the slope 1/2 − 1/η (water's bend is doubled).
        let alpha = 0.01;
        let error = alpha / 2.0 - exact(alpha, eta);
        let next = alpha * alpha * (eta * eta - 1.0) / (6.0 * eta.powi(3));
        assert!(
            (error / alpha - (0.5 - 1.0 / eta)).abs() <= 2.0 * next,
            "{eta}: {error}"
        );
        // With c = η − 1 the error is third order.
        let fitted = course::refract_001_approx(travelling_at(alpha), n, eta - 1.0);
        let cubic = (angle_from_down(fitted) - exact(alpha, eta)) / alpha.powi(3);
        let coefficient = (eta - 1.0) / (2.0 * eta.powi(3));
        assert!(
            (cubic / coefficient - 1.0).abs() <= 1e-3,
            "{eta}: {cubic} vs {coefficient}"
        );
    }
}

/// `003` lines 195–203, `Fresnel(V, N)` with `κ > 0`: per channel
/// `F0 + (1 − F0)(1 − cosa)⁵`, `F0 = ((n−1)² + κ²)/((n+1)² + κ²)`: it is
/// `fresnel::schlick(cos, fresnel::f0(n, κ))`, checked for the course's
/// gold (`000` lines 1385–1386) and for glass. With `N` on the far side
/// (against line 190's precondition) `cosa < 0` and the code exceeds 1,
/// `F0 + (1 − F0)(1 + cos θ)⁵`, where the crate's Schlick takes `|cos θ|`.
/// Tolerance 4ε: the same operations, a few roundings of numbers ≤ 1
/// (≤ 32 for the flipped normal, hence 128ε there).
#[test]
fn course_003_fresnel_code_is_schlick_with_the_conductor_f0() {
    let n = DVec3::Z;
    let materials = [([0.17, 0.35, 1.5], [3.1, 2.7, 1.9]), ([1.5; 3], [0.0; 3])];
    for (ior, kappa) in materials {
        for k in 0..=100 {
            let cos = k as f64 / 100.0;
            let v = DVec3::new((1.0 - cos * cos).sqrt(), 0.0, -cos);
            let code = course::fresnel_003_code(v, n, ior, kappa);
            let flipped = course::fresnel_003_code(v, -n, ior, kappa);
            for ch in 0..3 {
                let f0 = f0(ior[ch], kappa[ch]);
                assert!(
                    (code[ch] - schlick(cos, f0)).abs() <= 4.0 * EPS,
                    "{cos} {ch}: {}",
                    code[ch]
                );
                let above = f0 + (1.0 - f0) * (1.0 + cos).powi(5);
                assert!((flipped[ch] - above).abs() <= 128.0 * EPS);
                assert!(cos == 0.0 || flipped[ch] > 1.0);
                assert!(schlick(-cos, f0) <= 1.0);
            }
        }
    }
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

/// `001` line 467, slide: `max(0, min(1, bias + scale (0 + I·N)^power))`.
/// Wrong: with `I` towards the surface `I·N < 0`, and a negative base to a
/// fractional power is NaN, which the clamps then turn into whatever the
/// hardware's min/max make of NaN (IEEE minNum, as here: 1, a perfect
/// mirror); an odd integer power gives `bias − scale cos^power θ`, which
/// never rises above the bias: no Fresnel effect at all. The vertex
/// program's `1 + dot(I, N)` (line 508) is Schlick's curve for
/// `bias = F0, scale = 1 − F0, power = 5`. Its expression has no clamp, so
/// at grazing incidence its arithmetic gives `bias + scale`, above 1 when
/// `bias + scale > 1`; whether the fragment program sees that is not the
/// expression's doing: it is written to `out float reflectionFactor :
/// COLOR` (line 485), which Cg vertex profiles may clamp into `[0, 1]`.
/// Tolerances 4ε: a few roundings of numbers ≤ 1.
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
    let (bias, scale) = (0.5, 0.9);
    let grazing = course::EmpiricalFresnel {
        bias,
        scale,
        power: 5.0,
    }
    .vertex_program(DVec3::X, n);
    assert!(
        (grazing - (bias + scale)).abs() <= 4.0 * EPS && grazing > 1.0,
        "{grazing}"
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

/// `000` lines 1241–1247 (and 1402–1408, 1860–1866), `getMaterialF0`:
/// `pow(n − 1.0, 2.0)` for the course's gold, `n = (0.17, 0.35, 1.5)`,
/// `k = (3.1, 2.7, 1.9)`. Red and green have `n − 1 < 0`, where GLSL's `pow`
/// is undefined (GLSL ES 1.00 §8.2); lowered as `exp2(2 log2 x)` their F0 is
/// NaN, and so is every mirror weight `Fresnel(F0, cos θ)` makes of it. Blue
/// (`n − 1 = 0.5 > 0`) is the law's F0. Tolerance 64ε relative for blue:
/// each lowered `pow` is `exp2` of `2 log2 x` with `|log2 x| < 1.5`, whose
/// rounding `exp2` turns into a relative error of about `2 ln 2 · 1.5 ε + ε`,
/// and F0 is a ratio of two sums of two of them.
#[test]
fn course_000_f0_feeds_pow_a_negative_base_for_gold() {
    let (n, k): ([f64; 3], [f64; 3]) = ([0.17, 0.35, 1.5], [3.1, 2.7, 1.9]);
    for ch in 0..3 {
        let law = f0(n[ch], k[ch]);
        assert!(law > 0.0 && law < 1.0, "{ch}: {law}");
        let shader = course::f0_000_glsl(n[ch], k[ch]);
        if ch < 2 {
            assert!(n[ch] - 1.0 < 0.0, "the base of pow is negative");
            assert!(shader.is_nan(), "{ch}: {shader}");
            assert!(course::fresnel_000_glsl(shader, 0.5).is_nan());
        } else {
            assert!(
                (shader / law - 1.0).abs() <= 64.0 * EPS,
                "{shader} vs {law}"
            );
        }
    }
    // `pow(x, 2.0)` folded into `x * x` is defined for any x: the law.
    assert_eq!(
        ((0.17f64 - 1.0) * (0.17 - 1.0) + 3.1 * 3.1) / ((0.17 + 1.0) * (0.17 + 1.0) + 3.1 * 3.1),
        f0(0.17, 3.1)
    );
}

/// `003` line 257, looking up from the bottom of a pool: "if we *decrease*
/// the angle of incidence, that is look further away, total reflection
/// appears". Backwards: the angle is measured from the normal (line 146),
/// looking further away increases it, and total internal reflection needs
/// it *above* the critical angle, asin(1/1.333) = 48.6° for water. A viewer
/// at depth 2 m sees through the surface out to 2 tan 48.6° = 2.27 m and
/// the mirrored pool beyond. Exact: `transmitted_angle` decides refraction
/// on `sin θ / η > 1`, and the 1° grid stays 0.4° from the critical angle.
#[test]
fn course_003_pool_total_internal_reflection_needs_a_larger_angle_not_a_smaller_one() {
    let eta_path = 1.0_f64 / 1.333; // water to air, n_t / n_i
    let critical = critical_angle(eta_path).unwrap();
    assert_eq!(format!("{:.1}", critical.to_degrees()), "48.6");
    assert_eq!(format!("{:.2}", 2.0 * critical.tan()), "2.27");
    for deg in 0..90 {
        let theta = f64::from(deg).to_radians();
        let refracts = transmitted_angle(theta, eta_path).is_some();
        assert_eq!(refracts, theta < critical, "{deg}°");
    }
    // Decreasing the angle from 60° to 30° ends total reflection; it does
    // not start it.
    assert!(transmitted_angle(60f64.to_radians(), eta_path).is_none());
    assert!(transmitted_angle(30f64.to_radians(), eta_path).is_some());
}

/// `003` lines 415–426, `shade(N, V, L, inRad)`: Blinn-Phong as the boxed
/// formula (lines 388–389) has it, `L_in f_r cos θ` with `brdf::BlinnPhong`,
/// wherever light and viewer are above the surface, and it gives the quiz's
/// answers (quiz 3: 2.4, quiz 5: 2.5). But it never checks `N·V`: seen from
/// behind, with the light in front, it shades the surface as if seen from
/// the front, where the BRDF is 0, and seen from straight opposite the light
/// it normalises a zero half vector: NaN. Line 357 says the clamp `cos⁺θ`
/// hides a point seen from the other side; `θ` is the light's angle, so it
/// hides points lit from behind (the code's "self shadow"), nothing else.
///
/// Tolerance 1e-13 relative: a dozen roundings on each side, and the lobe's
/// `cos δ` from two normalisations an ulp or two apart, raised to
/// `shine ≤ 50`, moves by at most 50 · 4ε = 4.4e-14 relative.
#[test]
fn course_003_shade_code_is_blinn_phong_above_and_shades_surfaces_seen_from_behind() {
    use radiometry::brdf::{BlinnPhong, Brdf};
    let n = DVec3::Z;
    let at = |theta_deg: f64, phi_deg: f64| {
        let (t, p) = (theta_deg.to_radians(), phi_deg.to_radians());
        DVec3::new(t.sin() * p.cos(), t.sin() * p.sin(), t.cos())
    };
    for (kd, ks, shine) in [(0.6, 0.0, 1.0), (0.0, 2f64.sqrt(), 3.0), (0.1, 1.0, 50.0)] {
        let blinn = BlinnPhong { kd, ks, shine };
        for l in [
            at(0.0, 0.0),
            at(30.0, 10.0),
            at(60.0, 200.0),
            at(85.0, 90.0),
        ] {
            for v in [
                at(0.0, 0.0),
                at(20.0, 190.0),
                at(45.0, 30.0),
                at(80.0, 300.0),
            ] {
                let code = course::shade_003_code(n, v, l, 5.0, kd, ks, shine);
                let law = 5.0 * blinn.eval(n, l, v) * n.dot(l);
                assert!(
                    (code - law).abs() <= 1e-13 * law.abs().max(1.0),
                    "{kd} {ks} {shine} {l} {v}: {code} vs {law}"
                );
            }
        }
    }
    // The quiz: light from (0, 3, 4), L_in = 5; quiz 3 kd = 0.6 (2.4), quiz 5
    // ks = √2, shine 3, camera towards (0, 4, 3) (2.5).
    let (l, v) = (DVec3::new(0.0, 0.6, 0.8), DVec3::new(0.0, 0.8, 0.6));
    let quiz_3 = course::shade_003_code(n, v, l, 5.0, 0.6, 0.0, 1.0);
    let quiz_5 = course::shade_003_code(n, v, l, 5.0, 0.0, 2f64.sqrt(), 3.0);
    assert!((quiz_3 - 2.4).abs() <= 1e-14 && (quiz_5 - 2.5).abs() <= 1e-14);

    let blinn = BlinnPhong {
        kd: 0.6,
        ks: 2f64.sqrt(),
        shine: 3.0,
    };
    // Seen from behind (N·V = −0.6), lit from the front: shaded, where the
    // BRDF is 0.
    let behind = DVec3::new(0.0, 0.8, -0.6);
    let code = course::shade_003_code(n, behind, l, 5.0, blinn.kd, blinn.ks, blinn.shine);
    assert!(code >= 5.0 * 0.6 * 0.8, "{code}");
    assert_eq!(blinn.eval(n, l, behind), 0.0);
    // Seen from straight opposite the light: normalize(0) is NaN.
    assert!(course::shade_003_code(n, -l, l, 5.0, blinn.kd, blinn.ks, blinn.shine).is_nan());
    // Lit from behind: zero, the "self shadow" the code's comment names.
    let l_behind = DVec3::new(0.0, 0.6, -0.8);
    assert_eq!(
        course::shade_003_code(n, v, l_behind, 5.0, blinn.kd, blinn.ks, blinn.shine),
        0.0
    );
}

/// `003` lines 305 and 312: `L_in cos θ_in` is labelled "irradiance", and
/// the BRDF defined as `L / (L_in cos θ_in)`. Irradiance is power per area
/// (W/m²); a radiance times a cosine is still per steradian. The solid
/// angle `dω` the light arrives from is missing: by the chapter's own
/// radiance definition (line 26), light of radiance `L` from a patch of
/// sky `Δω` at `θ` delivers `E = L cos θ Δω`, and the BRDF is
/// `dL / (L_in cos θ dω)`, in 1/sr (which is why the course's `kd`, taken
/// as the BRDF, has albedo `π kd`). Measured: a source of 1 W/(sr·m²) at
/// 60° delivers 0.05 W/m² from 0.1 sr and half that from 0.05 sr, where
/// `L_in cos θ` stays 0.5 for both; a whole sky of it delivers π W/m².
/// Tolerances: 4ε relative for the definition (three roundings), 1e-12
/// for the sky (midpoint quadrature in `cos θ`, exact for the linear
/// integrand, leaves 80 000 rounded terms).
#[test]
fn course_003_radiance_times_cosine_is_not_irradiance() {
    use radiometry::brdf::{directional_albedo, CourseLambert};
    use radiometry::radiance::radiance_from_flux;
    let (l_in, cos) = (1.0_f64, 0.5);
    for solid_angle in [0.1, 0.05] {
        // The irradiance E = Φ / A for which the definition gives back l_in.
        let area = 1.0;
        let e = l_in * cos * solid_angle;
        let back = radiance_from_flux(e * area, area, cos, solid_angle);
        assert!((back / l_in - 1.0).abs() <= 4.0 * EPS, "{back}");
        assert!(
            (e - l_in * cos).abs() > 0.4,
            "the course's irradiance is {} W/(sr·m²), E is {e} W/m²",
            l_in * cos
        );
    }
    // A uniform sky: E = ∫ L cos θ dω = π L.
    let cosine_integral = directional_albedo(&CourseLambert { kd: 1.0 }, DVec3::Z, DVec3::Z, 100);
    let sky = l_in * cosine_integral.albedo;
    assert!((sky - std::f64::consts::PI).abs() <= 1e-12, "{sky}");
}

/// `000` lines 429–430 ("the diffuse colour, more correctly its absorbing
/// capacity") and 490 (`ambient`, "the material's ambient-light absorbing
/// capacity"): both factors multiply the light the surface sends back
/// (lines 449, 457), so they are reflectances; a surface absorbs what it
/// does not reflect. The green material, `kd = (0.1, 0.8, 0.3)` (line 534),
/// is green because it reflects green most and absorbs it least: as a
/// normalised Lambertian its albedo is `kd` and it absorbs `1 − kd =
/// (0.9, 0.2, 0.7)`. Tolerance 1e-12: the quadrature is exact for the
/// Lambertian's linear integrand, up to rounding of 80 000 terms.
#[test]
fn course_000_diffuse_factor_is_a_reflectance_not_an_absorptance() {
    use radiometry::brdf::{directional_albedo, Lambert};
    let kd = [0.1, 0.8, 0.3];
    let reflected =
        kd.map(|albedo| directional_albedo(&Lambert { albedo }, DVec3::Z, DVec3::Z, 100).albedo);
    let absorbed = reflected.map(|r| 1.0 - r);
    for ch in 0..3 {
        assert!((reflected[ch] - kd[ch]).abs() <= 1e-12, "{reflected:?}");
        assert!((absorbed[ch] - (1.0 - kd[ch])).abs() <= 1e-12);
    }
    // Green, the largest factor, is the most reflected and least absorbed.
    assert!(reflected[1] > reflected[0] && reflected[1] > reflected[2]);
    assert!(absorbed[1] < absorbed[0] && absorbed[1] < absorbed[2]);
}

/// Erratum (`001`, line 462): "Alacsony szög esetén nagy a tükröződés"
/// (at a low angle the reflection is strong, the water hides what is
/// under it). The slides measure angles from the normal (line 376); there
/// water (n = 1.33) reflects about its `F0` of 2 % and lets the rest
/// through. The reflection is strong at a high angle, near grazing.
#[test]
fn course_001_water_reflects_little_at_a_low_angle_from_the_normal() {
    let eta = 1.33;
    let at = |degrees: f64| dielectric(degrees.to_radians().cos(), eta);
    let (low, high) = (at(10.0), at(80.0));
    // 1e-4: the Fresnel curve's rise from 0° to 10° (about 1e-5), with room.
    assert!((low - f0(eta, 0.0)).abs() <= 1e-4, "10°: {low}");
    assert!(low < 0.03, "10°: {low}");
    // Above a third at 80°: more than fifteen times the 10° value.
    assert!(high > 15.0 * low && high > 0.33, "80°: {high}");
}

/// `003` line 56: of a point light "the intensity falls with the square of
/// the distance". Its radiant intensity `I` (W/sr) is the same at every
/// distance; what falls is the irradiance it delivers, `E = I cos θ / r²`
/// (`radiometry::radiance::point_irradiance`). Read back from the
/// irradiance at 1, 2 and 5 m, the intensity is 100 W/sr each time, where
/// the sentence has it a quarter at 2 m. Tolerance 8ε relative: a division
/// and a product by an exact square.
#[test]
fn course_003_point_light_intensity_is_constant_its_irradiance_falls_as_inverse_square() {
    use radiometry::radiance::point_irradiance;
    let intensity = 100.0_f64;
    for r in [1.0_f64, 2.0, 5.0] {
        let light = DVec3::new(0.0, 0.0, r);
        let e = point_irradiance(intensity, light, DVec3::ZERO, DVec3::Z).unwrap();
        let back = e.irradiance * r * r;
        assert!(
            (back / intensity - 1.0).abs() <= 8.0 * EPS,
            "r = {r}: {back}"
        );
        let written = intensity / (r * r);
        if r > 1.0 {
            assert!((back - written).abs() > 0.5 * intensity, "r = {r}");
        }
    }
}

/// `003` line 114: `κ` "shows how much the radiance falls in the material
/// over a distance of one wavelength". A plane wave in a medium of index
/// `n + iκ` goes as `exp(i 2π (n + iκ) z / λ)`, so its radiance falls by
/// `exp(−4π κ z / λ)` (Born & Wolf, §14.1): over one wavelength by the
/// factor `exp(−4πκ)`, not by `κ`. The course's own gold has `κ` of 3.1,
/// 2.7, 1.9 (`000` line 1386), which no fraction is, and keeps 1.2·10⁻¹⁷
/// of red light after one wavelength; a weak absorber of `κ = 0.01` loses
/// 11.8 %, not 1 %. Tolerances: 1e−3 relative on the printed figures.
#[test]
fn course_003_kappa_is_not_the_fraction_lost_per_wavelength() {
    use std::f64::consts::PI;
    let kept = |kappa: f64| (-4.0 * PI * kappa).exp();
    for kappa in [3.1, 2.7, 1.9] {
        assert!(kappa > 1.0, "gold's κ = {kappa} is no fraction");
    }
    let red = kept(3.1);
    assert!((red / 1.207e-17 - 1.0).abs() < 1e-3, "{red}");
    let lost = 1.0 - kept(0.01);
    assert!((lost / 0.1181 - 1.0).abs() < 1e-3, "{lost}");
    assert!((lost - 0.01).abs() > 0.1, "κ = 0.01 loses {lost}, not 1 %");
}

/// `003` line 309 (and line 488): `Ψ = cos(θ^in · f_r(L, r, V)`, the
/// bracket after `θ^in` never closed, reads as the cosine of the product.
/// With quiz 3's numbers (`L^in` = 5, `cos θ` = 0.8, the course's
/// `f_r = k_d = 0.6`) the meant `L^in cos θ f_r` is 2.4; as bracketed,
/// `L^in cos(θ · f_r)` is 4.63. Tolerance 1e−3 absolute on the printed
/// figures.
#[test]
fn course_003_psi_as_bracketed_is_the_cosine_of_a_product() {
    let (l_in, cos, f_r) = (5.0_f64, 0.8_f64, 0.6);
    let meant = l_in * cos * f_r;
    let bracketed = l_in * (cos.acos() * f_r).cos();
    assert!((meant - 2.4).abs() < 1e-3, "{meant}");
    assert!((bracketed - 4.632).abs() < 1e-3, "{bracketed}");
}

/// `003` line 375: `cos⁴(x)` drawn as the approximation of a Gaussian of
/// `s = 0.4`. Near the peak `cosⁿ x = 1 − n x²/2 + …` and
/// `exp(−x²/2s²) = 1 − x²/2s² + …`, so the matching power is `n = 1/s²`:
/// 6.25 for `s = 0.4`, while `cos⁴` is the Gaussian of `s = 0.5`. Over the
/// figure's `[−2, 2]` (with `cos⁺`) `cos⁴` strays 0.140 from the `s = 0.4`
/// curve, `cos^6.25` 0.031, and `cos⁴` from `s = 0.5` 0.050. Sampled at
/// 4001 points; tolerances 1e−3 on those maxima.
#[test]
fn course_003_cos4_matches_a_gauss_of_s_0_5_not_0_4() {
    let gap = |power: f64, s: f64| {
        (0..=4000)
            .map(|i| -2.0 + 4.0 * f64::from(i) / 4000.0)
            .map(|x: f64| (x.cos().max(0.0).powf(power) - (-x * x / (2.0 * s * s)).exp()).abs())
            .fold(0.0, f64::max)
    };
    let written = gap(4.0, 0.4);
    assert!((written - 0.1401).abs() < 1e-3, "{written}");
    assert!((gap(6.25, 0.4) - 0.0309).abs() < 1e-3);
    assert!((gap(4.0, 0.5) - 0.0502).abs() < 1e-3);
    assert!(written > 4.0 * gap(6.25, 0.4));
}
