//! The latitude–longitude map.
//!
//! Tolerance of the round trip: 1e-14 rad. The way there and back is
//! `hypot`, two `atan2`, a division and a multiplication by `π` and `2π`,
//! two `sin_cos` and a normalisation: about ten roundings of 1.1e-16
//! each, amplified at most by `2π` (the scale of `φ`), so 1e-14 leaves a
//! margin of ten. The slides' `arccos(−r_z)` loses 1e-8 rad at the poles
//! (the test `the_slides_arccos_loses_the_angle_near_the_poles`) and
//! could not meet it.

use std::f64::consts::{FRAC_PI_4, PI};

use glam::DVec3;
use proptest::prelude::*;
use proptest::test_runner::{Config, TestCaseError, TestRunner};

use super::{any_direction, chord, direction};
use crate::envmap::lat_long::LatLong;
use crate::envmap::Direction;

const ROUND_TRIP: f64 = 1e-14;

/// The round trip of one direction through a map given as its two halves.
pub(super) fn round_trip(
    r: Direction,
    there: impl Fn(Direction) -> LatLong,
) -> Result<(), TestCaseError> {
    let texel = there(r);
    let back = LatLong::from_uv(texel.u(), texel.v())
        .map_err(|e| TestCaseError::fail(format!("{texel:?} is no texel: {e:?}")))?
        .direction();
    let error = chord(r, back);
    prop_assert!(
        error <= ROUND_TRIP,
        "{:?} went to {texel:?} and back to {:?}, {error:e} rad off",
        r.get(),
        back.get()
    );
    Ok(())
}

proptest! {
    #[test]
    fn lat_long_round_trip_returns_the_direction(r in any_direction()) {
        round_trip(r, LatLong::from_direction)?;
    }

    #[test]
    fn lat_long_u_is_in_0_1_open_and_v_in_0_1_closed(r in any_direction()) {
        let texel = LatLong::from_direction(r);
        prop_assert!((0.0..1.0).contains(&texel.u()), "{texel:?}");
        prop_assert!((0.0..=1.0).contains(&texel.v()), "{texel:?}");
        prop_assert!(texel.u().is_sign_positive(), "{texel:?} has u = −0");
    }

    #[test]
    fn lat_long_rho_is_the_angle_from_minus_z(r in any_direction()) {
        // cos ρ = −r_z, to the rounding of cos near ρ (ε) and of ρ (πε).
        let rho = LatLong::from_direction(r).rho();
        prop_assert!((rho.cos() + r.get().z).abs() <= 8.0 * f64::EPSILON, "{rho}");
    }
}

#[test]
fn lat_long_seam_and_poles_are_decided_once() {
    let at = |x, y, z| LatLong::from_direction(direction(DVec3::new(x, y, z)));
    // The seam φ = 0 belongs to u = 0, −0 and the side just below it too
    // (φ = 2π − 1e-300 rounds to 2π); just above it u is just above 0.
    for y in [0.0, -0.0, -1e-300] {
        assert_eq!(at(1.0, y, 0.0).u(), 0.0, "y = {y}");
        assert!(at(1.0, y, 0.0).u().is_sign_positive(), "y = {y}");
    }
    assert!((0.0..1e-300).contains(&at(1.0, 1e-300, 0.0).u()));
    // The poles: u = 0 by decision, v = 0 at −z and 1 at +z; said so.
    assert_eq!((at(0.0, 0.0, -1.0).u(), at(0.0, 0.0, -1.0).v()), (0.0, 0.0));
    assert_eq!((at(-0.0, 0.0, 1.0).u(), at(-0.0, 0.0, 1.0).v()), (0.0, 1.0));
    assert!(at(0.0, 0.0, -1.0).is_pole() && at(-0.0, 0.0, 1.0).is_pole());
    assert!(!at(1e-300, 0.0, -1.0).is_pole());
    // The quadrants: φ over the whole circle (the slides' "[0, 2π]").
    assert_eq!(at(1.0, 1.0, 0.0).phi(), FRAC_PI_4);
    assert!((at(-1.0, -1.0, 0.0).phi() - 5.0 * FRAC_PI_4).abs() <= 4.0 * f64::EPSILON);
    assert!((at(1.0, -1.0, 0.0).phi() - 7.0 * FRAC_PI_4).abs() <= 8.0 * f64::EPSILON);
    assert_eq!(at(-1.0, 0.0, 0.0).phi(), PI);
}

#[test]
fn lat_long_texels_outside_the_square_are_refused_by_coordinate() {
    use crate::envmap::TexelError;
    assert_eq!(LatLong::from_uv(1.5, 0.5), Err(TexelError::U(1.5)));
    assert_eq!(LatLong::from_uv(0.5, -0.1), Err(TexelError::V(-0.1)));
    assert!(matches!(LatLong::from_uv(f64::NAN, 0.5), Err(TexelError::U(u)) if u.is_nan()));
    // u = 1 is the seam again: the same meridian as u = 0.
    let (one, zero) = (
        LatLong::from_uv(1.0, 0.5).unwrap(),
        LatLong::from_uv(0.0, 0.5).unwrap(),
    );
    assert!(chord(one.direction(), zero.direction()) <= 4.0 * f64::EPSILON);
}

#[test]
fn the_slides_arccos_loses_the_angle_near_the_poles() {
    // r 1e-9 rad from −z: arccos(−r_z) rounds to 0, atan2 keeps it.
    let r = direction(DVec3::new(1e-9, 0.0, -1.0));
    assert_eq!((-r.get().z).acos(), 0.0);
    let rho = LatLong::from_direction(r).rho();
    assert!((rho - 1e-9).abs() <= 1e-9 * 4.0 * f64::EPSILON, "{rho}");
}

/// The round trip catches a wrong map: here `φ` measured from `+y`
/// instead of `+x` on the way there, a fault each texel shows.
#[test]
fn lat_long_round_trip_catches_a_quarter_turn_of_phi() {
    let quarter_turned = |r: Direction| {
        let v = r.get();
        LatLong::from_direction(direction(DVec3::new(-v.y, v.x, v.z)))
    };
    let mut runner = TestRunner::new(Config::with_cases(64));
    let outcome = runner.run(&any_direction(), |r| round_trip(r, quarter_turned));
    assert!(
        outcome.is_err(),
        "the round trip missed a quarter turn of φ"
    );
}
