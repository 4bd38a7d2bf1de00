//! The slides' own numbers and claims (`001`, "Környezet leképezés"),
//! and the errata of that part (`docs/errata.md`), each proven here.

use std::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_4, PI};

use glam::{DMat3, DVec3};

use super::{chord, direction};
use crate::envmap::cube::{CubeTexel, Face};
use crate::envmap::lat_long::LatLong;
use crate::envmap::sphere::SphereTexel;

const EPS: f64 = f64::EPSILON;

/// "Például a (−3.2, 5.1, −8.4) a −Z oldalt jelöli ki": on that face
/// (Table 8.19: `s_c = −r_x`, `t_c = −r_y`, `|m_a| = 8.4`),
/// `u = (3.2/8.4 + 1)/2 = 29/42` and `v = (−5.1/8.4 + 1)/2 = 11/56`, to
/// the 4 ε of normalising first.
#[test]
fn the_slides_example_selects_minus_z_at_29_42_11_56() {
    let r = direction(DVec3::new(-3.2, 5.1, -8.4));
    let texel = CubeTexel::from_direction(r);
    assert_eq!(texel.face(), Face::NegativeZ);
    assert!(
        (texel.u() - 29.0 / 42.0).abs() <= 4.0 * EPS,
        "{}",
        texel.u()
    );
    assert!(
        (texel.v() - 11.0 / 56.0).abs() <= 4.0 * EPS,
        "{}",
        texel.v()
    );
    assert!(chord(texel.direction(), r) <= 8.0 * EPS);
}

/// The slides' longitude, `φ = arctan(r_y / r_x)`, "ha r_x ≠ 0" (line 34).
fn slides_phi(r: DVec3) -> f64 {
    (r.y / r.x).atan()
}

/// Erratum: `arctan(r_y / r_x)` lies in `(−π/2, π/2)`, not the slides'
/// `[0, 2π]`, and gives a direction and its half turn about `z` the same
/// longitude: the lat-long map's left and right halves fold onto one.
/// `atan2(r_y, r_x)` tells them apart.
#[test]
fn course_001_lat_long_arctan_covers_half_the_circle() {
    let r = DVec3::new(1.0, 1.0, 0.0);
    let turned = DVec3::new(-1.0, -1.0, 0.0);
    assert_eq!(slides_phi(r), FRAC_PI_4);
    assert_eq!(
        slides_phi(turned),
        FRAC_PI_4,
        "the half turn reads the same"
    );
    // Negative for the fourth quadrant, outside [0, 2π].
    assert!(slides_phi(DVec3::new(1.0, -1.0, 0.0)) < 0.0);
    // None where r_x = 0 ("ha r_x ≠ 0"), though (0, 1, 0) has φ = π/2.
    let up = LatLong::from_direction(direction(DVec3::Y));
    assert!((up.phi() - PI / 2.0).abs() <= 2.0 * EPS);
    // The map tells them apart: π apart in φ, u half a map apart.
    let (a, b) = (
        LatLong::from_direction(direction(r)),
        LatLong::from_direction(direction(turned)),
    );
    assert!((b.phi() - a.phi() - PI).abs() <= 4.0 * EPS);
    assert!(chord(a.direction(), b.direction()) > 1.9);
}

/// Erratum: "a gömbtérkép nem tartalmazza a teljes környezetet" (line 185):
/// it holds every direction but one. The half of the surroundings behind
/// the sphere (`r_z < 0`) fills the ring `1/√2 < ρ < 1` of the picture,
/// half its area, and reads back; only `(0, 0, −1)` has no point of its
/// own (it is the whole rim). What the map lacks away from the view is
/// resolution, which is why it is redrawn when the view turns.
#[test]
fn course_001_sphere_map_holds_every_direction_but_one() {
    let steps = 64;
    for i in 1..steps {
        // Polar angle from −z over (0, π/2]: the half behind the sphere.
        let from_behind = (f64::from(i) / f64::from(steps)) * PI / 2.0;
        for k in 0..steps {
            let azimuth = f64::from(k) / f64::from(steps) * 2.0 * PI;
            let (s, c) = from_behind.sin_cos();
            let r = direction(DVec3::new(s * azimuth.cos(), s * azimuth.sin(), -c));
            let SphereTexel::Disc(texel) = SphereTexel::from_direction(r) else {
                panic!("{:?} has no texel", r.get());
            };
            let radius = (2.0 * texel.u() - 1.0).hypot(2.0 * texel.v() - 1.0);
            assert!(
                (FRAC_1_SQRT_2 - 4.0 * EPS..1.0).contains(&radius),
                "{:?} at radius {radius}",
                r.get()
            );
            let back = SphereTexel::from_uv(texel.u(), texel.v()).unwrap();
            assert!(chord(back.direction(), r) <= 1e-13, "{:?}", r.get());
        }
    }
    assert_eq!(
        SphereTexel::from_direction(direction(DVec3::NEG_Z)),
        SphereTexel::Rim
    );
}

/// Erratum (the Cg vertex programs, lines 106, 430, 500): `N = mul((float3x3)
/// modelToWorld, normal)` transforms the normal as a tangent. That is
/// right for rotations, translations and uniform scales only; under a
/// non-uniform scale the normal must go through the inverse transpose, or
/// it leaves the surface's perpendicular and `reflect` looks up the wrong
/// texel. Here the plane `x + y = 0` stretched by 2 along `x`.
#[test]
fn course_001_cg_normal_transform_needs_the_inverse_transpose() {
    let model_to_world = DMat3::from_diagonal(DVec3::new(2.0, 1.0, 1.0));
    let normal = DVec3::new(1.0, 1.0, 0.0).normalize();
    let tangent = DVec3::new(1.0, -1.0, 0.0);
    let world_tangent = model_to_world * tangent;
    let cg = (model_to_world * normal).normalize();
    let right = (model_to_world.inverse().transpose() * normal).normalize();
    // The Cg normal is 36.9° off the perpendicular, the inverse transpose's on it.
    let off = cg.dot(world_tangent.normalize()).asin().to_degrees();
    assert!((off - 36.87).abs() < 0.01, "{off}°");
    assert!(right.dot(world_tangent).abs() <= 4.0 * EPS);
    // And the eye ray straight down −x reflects elsewhere: the looked-up
    // direction turns by twice the normal's error.
    let eye_ray = DVec3::NEG_X;
    let reflect = |n: DVec3| eye_ray - 2.0 * n.dot(eye_ray) * n;
    let turned = reflect(cg).angle_between(reflect(right)).to_degrees();
    assert!((turned - 2.0 * off).abs() < 1e-9, "{turned}°");
}

/// Erratum (lines 153–174): the sphere map's basis has rows `h`, `u`, `f`
/// ("we look at the picture along `f`"), the eye vector `e` runs from the
/// eye to the vertex (lines 40–42, 159–163), and the normal lies half way
/// between `r` and the eye's direction `(0, 0, 1)` (line 174). That last
/// one points towards the viewer, so `f` must too (then `h`, `u`, `f` is
/// right-handed): with `f` along the view, as "along `f`" reads and as `e`
/// runs, the sphere's centre, which reflects the view straight back, maps
/// to the rim, and no normal comes back.
#[test]
fn course_001_sphere_map_basis_needs_f_towards_the_viewer() {
    // A camera looking along world +x, up +y: right is view × up.
    let view = DVec3::X;
    let up = DVec3::Y;
    let right = view.cross(up);
    let basis = |f: DVec3| DMat3::from_cols(right, up, f).transpose();
    let (towards, along) = (basis(-view), basis(view));
    assert!((towards.determinant() - 1.0).abs() <= 4.0 * EPS);
    assert!((along.determinant() + 1.0).abs() <= 4.0 * EPS);
    // Normals of the sphere's visible half, the centre first.
    let normals = [
        -view,
        (-view + 0.5 * up).normalize(),
        (-view - 0.3 * right + 0.2 * up).normalize(),
    ];
    for n in normals {
        // The slides' reflection in the map's space, r = e' − 2 (n'·e') n'.
        let r = radiometry::course::reflect_001(towards * view, towards * n);
        let SphereTexel::Disc(texel) = SphereTexel::from_direction(direction(r)) else {
            panic!("{n}: no texel with f towards the viewer");
        };
        // 1e-13: a few roundings of the normalisation and the reflection.
        assert!((texel.normal() - towards * n).length() <= 1e-13, "{n}");
        let r = radiometry::course::reflect_001(along * view, along * n);
        match SphereTexel::from_direction(direction(r)) {
            SphereTexel::Rim => assert_eq!(n, -view),
            SphereTexel::Disc(texel) => {
                assert!((texel.normal() - along * n).length() > 0.5, "{n}");
            }
        }
    }
}
