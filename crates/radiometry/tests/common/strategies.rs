//! Proptest strategies for the law tests, named after what they produce and
//! built from bounded ranges so that shrinking stays meaningful. A test that
//! needs another distribution gets another strategy with another name, never
//! a redefinition of one of these.

// Each test file uses the strategies it needs; the rest are unused there.
#![allow(dead_code)]

use glam::DVec3;
use proptest::prelude::*;
use std::f64::consts::TAU;

/// The unit vector at polar cosine `z` and azimuth `phi` about +z.
fn at_polar(z: f64, phi: f64) -> DVec3 {
    // |z| ≤ 1, so z·z ≤ 1 in floating point too and the root is real.
    let r = (1.0 - z * z).sqrt();
    DVec3::new(r * phi.cos(), r * phi.sin(), z)
}

/// A unit direction, uniform in (cos θ, φ) over the whole sphere: uniform
/// over the sphere's area.
pub fn unit_direction() -> impl Strategy<Value = DVec3> {
    (-1.0..=1.0f64, 0.0..TAU).prop_map(|(z, phi)| at_polar(z, phi))
}

/// A unit direction strictly above the surface z = 0 (cos θ ≥ 1e-3),
/// uniform in (cos θ, φ).
pub fn unit_direction_above() -> impl Strategy<Value = DVec3> {
    (1e-3..=1.0f64, 0.0..TAU).prop_map(|(z, phi)| at_polar(z, phi))
}

/// A direction of travel towards the surface z = 0 from above, at least
/// 0.1° off grazing (cos θ ≥ 0.0018), uniform in (cos θ, φ).
pub fn travel_direction_down() -> impl Strategy<Value = DVec3> {
    (0.0018..=1.0f64, 0.0..TAU).prop_map(|(cos, phi)| travelling_down(cos, phi))
}

/// A direction of travel towards the surface z = 0 from above, oblique:
/// between 0.1° off grazing and 0.5° off the normal (cos θ in
/// [0.0018, 0.99996]), where a tangent `(…)/sin θ` is defined.
pub fn travel_direction_down_oblique() -> impl Strategy<Value = DVec3> {
    (0.0018..=0.99996f64, 0.0..TAU).prop_map(|(cos, phi)| travelling_down(cos, phi))
}

fn travelling_down(cos: f64, phi: f64) -> DVec3 {
    let up = at_polar(cos, phi);
    DVec3::new(up.x, up.y, -up.z)
}

/// A relative index of refraction between 1/4 and 4, log-uniform, as both
/// sides of everyday interfaces (air, water, glass, diamond) span: as many
/// indices below 1 as above.
pub fn relative_index_log_uniform() -> impl Strategy<Value = f64> {
    (-4f64.ln()..=4f64.ln()).prop_map(f64::exp)
}

/// A relative index of refraction between 1/4 and 4, uniform: mostly above
/// 1 (light entering a denser medium), as the course's sources write their
/// formulas.
pub fn relative_index_uniform() -> impl Strategy<Value = f64> {
    0.25..=4.0f64
}

/// A relative index to the ends of the documented `f64` range (crate
/// conventions, `domain::INDEX_RANGE`): three cases in four from 1/4 to 4
/// log-uniformly, as [`relative_index_log_uniform`], the fourth from 1e-50
/// to 1e50 log-uniformly, where the sums of `η² ± 1` outgrow two doubles.
pub fn relative_index_to_the_documented_ends() -> impl Strategy<Value = f64> {
    prop_oneof![
        3 => relative_index_log_uniform(),
        1 => (-50.0..=50.0f64).prop_map(|e| 10f64.powf(e)),
    ]
}

/// A cosine of either sign, with the extremes a uniform draw misses: the
/// normal, grazing, and cosines whose square underflows.
pub fn signed_cosine() -> impl Strategy<Value = f64> {
    prop_oneof![
        8 => -1.0..=1.0f64,
        1 => prop_oneof![Just(1.0), Just(-1.0), Just(0.0), Just(-0.0), Just(1e-160), Just(-1e-160)],
    ]
}

/// A relative index with a critical angle on one side or the other: from
/// 1/4 to 4 log-uniformly, and one case in nine from the extremes near 1
/// (`1 ± 1e-12`) and far from it (`1e3`, `1e-3`).
pub fn relative_index_with_extremes() -> impl Strategy<Value = f64> {
    prop_oneof![
        8 => relative_index_log_uniform(),
        1 => prop_oneof![Just(1.0 + 1e-12), Just(1.0 - 1e-12), Just(1e3), Just(1e-3)],
    ]
}

/// A unit normal of any orientation and a unit direction within a small
/// angle of it, on either side: the angle log-uniform from 1e-12 rad to
/// 1 rad, where near normal incidence a direction refracts into a rarer
/// medium of up to 1e-8 times the index.
pub fn near_normal_incidence() -> impl Strategy<Value = (DVec3, DVec3)> {
    (
        unit_direction(),
        unit_direction(),
        -12.0..=0.0f64,
        any::<bool>(),
    )
        .prop_map(|(n, other, log_angle, below)| {
            let tangent = n
                .cross(other)
                .try_normalize()
                .unwrap_or_else(|| n.any_orthonormal_vector());
            let angle = 10f64.powf(log_angle);
            let normal_part = if below { -angle.cos() } else { angle.cos() };
            let wi = (n * normal_part + tangent * angle.sin()).normalize();
            (wi, n)
        })
}

/// A relative index of refraction from 1e-8 to 1e8, log-uniform: the
/// extremes where refraction magnifies the tangential part the most.
pub fn relative_index_wide() -> impl Strategy<Value = f64> {
    (-8.0 * 10f64.ln()..=8.0 * 10f64.ln()).prop_map(f64::exp)
}

/// A fraction in [0, 1], uniform: a reflectance coefficient.
pub fn fraction() -> impl Strategy<Value = f64> {
    0.0..=1.0f64
}
