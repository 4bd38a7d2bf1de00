//! The identities of the bent normal, each a property over random planes
//! (unit normals from random vectors, points within ±10 m) and random
//! points of spheres (radii 0.1 to 10 m), and the slides' Cg sample
//! replayed. Tolerances are stated where used, each with its reason.

use glam::DVec3;
use proptest::prelude::*;

use super::*;

fn vector() -> impl Strategy<Value = DVec3> {
    (-10.0..10.0f64, -10.0..10.0f64, -10.0..10.0f64).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn unit_vector() -> impl Strategy<Value = DVec3> {
    vector()
        .prop_filter("a vector with a direction", |v| v.length() > 1e-3)
        .prop_map(DVec3::normalize)
}

/// A point of a random plane through a random origin.
fn plane_point() -> impl Strategy<Value = SurfacePoint> {
    (vector(), unit_vector(), vector()).prop_map(|(origin, n, p)| {
        let on = p - n * n.dot(p - origin);
        on_plane(origin, n, on)
    })
}

/// A point of a random sphere, away from the poles of its parameters
/// (`sin θ > 0.01`), where the parametrisation is regular.
fn sphere_point() -> impl Strategy<Value = SurfacePoint> {
    (vector(), 0.1..10.0f64, unit_vector())
        .prop_filter("off the poles", |(_, _, d)| d.y.abs() < 0.9999)
        .prop_map(|(c, r, d)| on_sphere(c, r, c + d * r).unwrap())
}

fn surface_point() -> impl Strategy<Value = SurfacePoint> {
    prop_oneof![plane_point(), sphere_point()]
}

/// Sine fields of every period accepted up to 1 and amplitudes up to 1 m.
fn sine_field() -> impl Strategy<Value = HeightField> {
    (-1.0..1.0f64, MIN_PERIOD..1.0f64).prop_map(|(a, p)| HeightField::sine(a, p).unwrap())
}

/// The normal of `normalize(n − b_u P_u / |P_u|² − b_v P_v / |P_v|²)`:
/// Blinn's normal written out for orthogonal tangents (both the plane's
/// and the sphere's are), where `n × P_v = −|P_v|/|P_u| P_u` and
/// `n × P_u = |P_u|/|P_v| P_v`.
fn analytic(at: &SurfacePoint, b_u: f64, b_v: f64) -> DVec3 {
    let Tangents { p_u, p_v } = at.tangents;
    (at.normal - p_u * (b_u / p_u.length_squared()) - p_v * (b_v / p_v.length_squared()))
        .normalize()
}

/// The angle between unit vectors, radians, as `atan2(|a × b|, a · b)`:
/// glam's `angle_between` takes an `acos`, whose digits run out below
/// about 1e-8 rad.
fn angle(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b))
}

proptest! {
    /// A flat field hands back the surface's normal to the bit: both
    /// slopes are exactly zero, and no normalisation round trip is made.
    #[test]
    fn flat_field_leaves_the_normal_unchanged(at in surface_point()) {
        let n = shading_normal(&HeightField::Flat, &at);
        prop_assert_eq!(n, at.normal);
        // A slope of zero and a sine of amplitude zero are flat too.
        for field in [HeightField::slope(0.0, 0.0).unwrap(), HeightField::sine(0.0, 0.25).unwrap()] {
            prop_assert_eq!(shading_normal(&field, &at), at.normal);
        }
    }

    /// On a plane, `h = du u + dv v` is the plane `P + h n` tilted: its
    /// normal is `normalize(n − du P_u − dv P_v)` exactly, so the only
    /// error is the central difference's rounding: each height (at most
    /// 10 · 2 · 35 m over this box) rounds by `ε |h| ≈ 8e-14` m, two of
    /// them over `2 STEP = 1/2048` give 3.2e-10 in the slope, and the unit
    /// normal moves by no more. Tolerance 1e-9.
    #[test]
    fn constant_slope_gives_the_analytic_tilted_normal(
        at in plane_point(),
        du in -10.0..10.0f64,
        dv in -10.0..10.0f64,
    ) {
        let field = HeightField::slope(du, dv).unwrap();
        let n = shading_normal(&field, &at);
        let exact = (at.normal - at.tangents.p_u * du - at.tangents.p_v * dv).normalize();
        prop_assert!((n - exact).length() < 1e-9, "{n} against {exact}");
    }

    /// On a sphere, a slope in `u` tilts the normal by `atan(du / |P_u|)`
    /// towards `−P_u`: metres of height per metre of arc. Heights here
    /// are at most 10 m, the speeds `|P_u| ≥ 2π · 0.1 · 0.014` m: the
    /// rounding bound of the plane's case grows to 1e-9 over the slowest
    /// tangent. Tolerance 1e-8.
    #[test]
    fn constant_slope_on_a_sphere_tilts_by_slope_over_speed(
        at in sphere_point(),
        du in -5.0..5.0f64,
        dv in -5.0..5.0f64,
    ) {
        let field = HeightField::slope(du, dv).unwrap();
        let n = shading_normal(&field, &at);
        let exact = analytic(&at, du, dv);
        prop_assert!((n - exact).length() < 1e-8, "{n} against {exact}");
    }

    /// The bent normal is a unit vector: off by at most a few rounding
    /// units of one normalisation, tolerance 4 ε.
    #[test]
    fn the_bent_normal_stays_unit(at in surface_point(), field in sine_field()) {
        let n = shading_normal(&field, &at);
        prop_assert!((n.length() - 1.0).abs() <= 4.0 * f64::EPSILON, "{}", n.length());
    }

    /// The bent normal leans towards the side the outward normal is on:
    /// `n' · n > 0`, whatever the slopes (the bend lies in the tangent
    /// plane, so `n' · n = 1 / |n + bend| > 0`).
    #[test]
    fn the_bent_normal_stays_on_the_outer_side(at in surface_point(), field in sine_field()) {
        prop_assert!(shading_normal(&field, &at).dot(at.normal) > 0.0);
    }

    /// As the bumps flatten the normal returns to the surface's: on a
    /// plane (unit-speed tangents) its angle from `n` is `atan |∇h|`, at
    /// most `atan(√2 · 2π |a| / p)`, and so it falls in proportion to the
    /// amplitude. Tolerance: the bound times 1.03, the central
    /// difference's worst relative error at the shortest period (2.6 %),
    /// plus 1e-15 rad of rounding.
    #[test]
    fn small_bump_scale_leaves_the_normal_unperturbed(
        at in plane_point(),
        period in MIN_PERIOD..1.0f64,
        k in 1..12i32,
    ) {
        let amplitude = 10f64.powi(-k);
        let field = HeightField::sine(amplitude, period).unwrap();
        let angle = angle(shading_normal(&field, &at), at.normal);
        let bound = (2f64.sqrt() * TAU * amplitude / period).atan();
        prop_assert!(angle <= bound * 1.03 + 1e-15, "{angle} > {bound}");
    }

    /// The bent normal of a sine field is Blinn's normal of the slopes
    /// worked out by hand, `∂h/∂u = a (2π/p) cos(2πu/p) sin(2πv/p)`, to
    /// within the central difference's error (relative `(2π STEP / p)² / 6`,
    /// 2.6 % of the slope at the shortest period; the normal moves by at
    /// most that times the slope, over `1 + slope²`). Tolerance: 0.026 ×
    /// half the steepest slope, which bounds that.
    #[test]
    fn sine_field_bends_by_its_analytic_slopes(at in plane_point(), field in sine_field()) {
        let HeightField::Sine { amplitude: a, period: p } = field else { unreachable!() };
        let w = TAU / p;
        let b_u = a * w * (w * at.u).cos() * (w * at.v).sin();
        let b_v = a * w * (w * at.u).sin() * (w * at.v).cos();
        let n = shading_normal(&field, &at);
        let exact = analytic(&at, b_u, b_v);
        let tolerance = 0.026 * (a.abs() * w).max(1e-12);
        prop_assert!((n - exact).length() <= tolerance, "{n} against {exact}");
    }

    /// The sphere's tangents are the derivatives of its parametrisation:
    /// against a central difference of `P(u, v)` with step 1e-6, whose
    /// error is about 1e-12 r relative; tolerance 1e-7 of `2π r`. And
    /// `P_u × P_v` points outwards.
    #[test]
    fn sphere_tangents_are_the_derivatives_of_its_parametrisation(at in sphere_point()) {
        let (u, v, h) = (at.u, at.v, 1e-6);
        let point = |u: f64, v: f64| {
            let (phi, theta) = (TAU * u, PI * v);
            DVec3::new(theta.sin() * phi.cos(), theta.cos(), theta.sin() * phi.sin())
        };
        let radius = at.tangents.p_v.length() / PI;
        let p_u = (point(u + h, v) - point(u - h, v)) * (radius / (2.0 * h));
        let p_v = (point(u, v + h) - point(u, v - h)) * (radius / (2.0 * h));
        let tolerance = 1e-7 * TAU * radius;
        prop_assert!((p_u - at.tangents.p_u).length() < tolerance);
        prop_assert!((p_v - at.tangents.p_v).length() < tolerance);
        prop_assert!(at.tangents.p_u.cross(at.tangents.p_v).dot(at.normal) > 0.0);
    }
}

/// The plane's tangents are orthonormal and right-handed about its
/// normal, for the normals glam's basis treats apart (near `±z`).
#[test]
fn plane_tangents_are_a_right_handed_frame() {
    for n in [
        DVec3::Z,
        -DVec3::Z,
        DVec3::X,
        DVec3::new(1.0, 2.0, -3.0).normalize(),
    ] {
        let Tangents { p_u, p_v } = on_plane(DVec3::ZERO, n, DVec3::ZERO).tangents;
        assert!((p_u.length() - 1.0).abs() < 1e-15 && (p_v.length() - 1.0).abs() < 1e-15);
        assert!(p_u.dot(p_v).abs() < 1e-15);
        assert!((p_u.cross(p_v) - n).length() < 1e-15, "{n}");
    }
}

/// The central difference is second order: halving the step quarters
/// its error on a sine (ratio within 4 ± 0.05 while the error is well
/// above rounding: steps from p/64 down to p/1024, at a point where the
/// third derivative is far from zero).
#[test]
fn central_differences_converge_at_second_order() {
    let (a, p) = (0.1, 0.25);
    let field = HeightField::sine(a, p).unwrap();
    let (u, v) = (0.03, 0.07);
    let w = TAU / p;
    let exact = a * w * (w * u).cos() * (w * v).sin();
    let error = |step: f64| (slopes(&field, u, v, step).b_u - exact).abs();
    for k in 6..10 {
        let step = p / 2f64.powi(k);
        let ratio = error(step) / error(step / 2.0);
        assert!((ratio - 4.0).abs() < 0.05, "step {step}: ratio {ratio}");
    }
}

/// At a pole of the sphere's parameters `P_u = 0`: the bend is
/// undefined, said by `None`, and the shading keeps the sphere's normal.
#[test]
fn the_spheres_poles_are_degenerate_and_keep_the_normal() {
    let at = on_sphere(DVec3::ZERO, 1.0, DVec3::Y).unwrap();
    assert_eq!(at.tangents.p_u, DVec3::ZERO);
    let tilt = Slopes { b_u: 0.5, b_v: 0.0 };
    assert_eq!(perturbed_normal(at.normal, &at.tangents, tilt), None);
    let field = HeightField::slope(0.5, 0.0).unwrap();
    assert_eq!(shading_normal(&field, &at), at.normal);
}

/// Each refusal names its parameter, table-driven.
#[test]
fn height_fields_refuse_bad_parameters_by_name() {
    use FieldError::*;
    let cases = [
        (HeightField::sine(f64::NAN, 0.5), Parameter::Amplitude),
        (HeightField::sine(0.1, f64::INFINITY), Parameter::Period),
        (HeightField::sine(0.1, 0.0), Parameter::Period),
        (HeightField::sine(0.1, -1.0), Parameter::Period),
        (HeightField::sine(0.1, MIN_PERIOD / 2.0), Parameter::Period),
        (HeightField::sine(1e6, 1.0), Parameter::Amplitude),
        (HeightField::slope(f64::NAN, 0.0), Parameter::Du),
        (HeightField::slope(0.0, -2e6), Parameter::Dv),
    ];
    for (result, parameter) in cases {
        let error = result.unwrap_err();
        assert_eq!(error.parameter(), parameter, "{error:?}");
        assert!(matches!(
            error,
            NotFinite { .. } | PeriodTooShort { .. } | TooSteep { .. }
        ));
    }
    assert!(HeightField::sine(0.1, MIN_PERIOD).is_ok());
    assert!(HeightField::slope(MAX_SLOPE, -MAX_SLOPE).is_ok());
}

/// The slides' Cg pair, `C8E1v_bumpWall` and `C8E2f_bumpSurf` (`001`),
/// replayed: `expand(v) = (v − 0.5) · 2`, and the colour is
/// `dot(expand(normalMap), normalize(lightDir))` with `lightDir` the
/// vertex program's `lightPosition − position`, in object space.
mod slides {
    use glam::DVec3;

    fn expand(v: DVec3) -> DVec3 {
        (v - 0.5) * 2.0
    }

    /// What `C8E2f_bumpSurf` writes, before the `COLOR` output's clamp.
    fn bump_surf(normal_texel: DVec3, light_position: DVec3, position: DVec3) -> f64 {
        let light = (light_position - position).normalize();
        expand(normal_texel).dot(light)
    }

    /// The texel of an unbent tangent-space normal `(0, 0, 1)`.
    const FLAT_TEXEL: DVec3 = DVec3::new(0.5, 0.5, 1.0);

    /// The fragment program dots a tangent-space normal (the map's) with
    /// an object-space light direction (the vertex program's): right for
    /// a wall in the object's `xy` plane facing `+z`, whose tangent frame
    /// is the object's frame, which the slides do not say. A wall facing
    /// `+x`, lit head-on by a light 2 m in front of it, is lit fully
    /// (`n · l = 1`); the sample computes `(0, 0, 1) · (1, 0, 0) = 0` and
    /// draws it black.
    #[test]
    fn course_001_cg_bump_sample_holds_only_for_a_wall_facing_z() {
        let point = DVec3::new(0.0, 0.3, -0.2);
        // The wall the sample was written for: normal +z.
        let front = bump_surf(FLAT_TEXEL, point + DVec3::Z * 2.0, point);
        assert!((front - 1.0).abs() < 1e-15, "{front}");
        // The same wall turned to face +x, the same light in front of it.
        let side = bump_surf(FLAT_TEXEL, point + DVec3::X * 2.0, point);
        assert_eq!(side, 0.0);
    }

    /// `tex2D` filters the normal map bilinearly and the sample does not
    /// normalise what comes back: half-way between texels of normals
    /// tilted ±45° about `y`, the filtered normal is `(0, 0, 0.707)`, and
    /// a head-on light gives 0.707 where the surface there faces it
    /// (29 % dark). Tolerance 1e-15 on the product.
    #[test]
    fn course_001_cg_bump_sample_does_not_renormalise_the_filtered_normal() {
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let texel = |n: DVec3| n * 0.5 + 0.5;
        let (left, right) = (texel(DVec3::new(-s, 0.0, s)), texel(DVec3::new(s, 0.0, s)));
        let filtered = (left + right) * 0.5;
        let shade = bump_surf(filtered, DVec3::Z * 3.0, DVec3::ZERO);
        assert!((shade - s).abs() < 1e-15, "{shade}");
        // Renormalised, the mid-point's normal (0, 0, 1) is lit fully.
        assert!((expand(filtered).normalize().dot(DVec3::Z) - 1.0).abs() < 1e-15);
    }
}
