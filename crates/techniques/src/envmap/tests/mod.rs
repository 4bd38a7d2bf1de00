//! The identities of the environment maps, as properties over directions
//! drawn where the maps are hard as often as where they are easy: the
//! seams, cube edges and corners, the poles, the sphere map's rim.
//!
//! Errors are measured as the chord `|a − b|` between unit vectors, which
//! is the angle between them in radians to within its cube. `ε` is
//! `f64::EPSILON` (2.2e-16); each test states its tolerance and why.

mod cube;
mod lat_long;
mod slides;
mod sphere;

use glam::DVec3;
use proptest::prelude::*;

use super::Direction;

const EPS: f64 = f64::EPSILON;

/// The chord between two directions, radians to within its cube.
fn chord(a: Direction, b: Direction) -> f64 {
    (a.get() - b.get()).length()
}

fn direction(v: DVec3) -> Direction {
    Direction::new(v).expect("the strategies draw directions")
}

/// A component in `[−1, 1]`.
fn component() -> impl Strategy<Value = f64> {
    -1.0..=1.0f64
}

/// Any direction of the box `[−1, 1]³` but those within 1e-6 of zero.
fn box_direction() -> impl Strategy<Value = Direction> {
    (component(), component(), component())
        .prop_filter("a vector with a direction", |&(x, y, z)| {
            DVec3::new(x, y, z).length() > 1e-6
        })
        .prop_map(|(x, y, z)| direction(DVec3::new(x, y, z)))
}

/// A sign, ±1.
fn sign() -> impl Strategy<Value = f64> {
    prop::sample::select(vec![1.0, -1.0])
}

/// A direction on a cube edge (two components of equal magnitude, the
/// third smaller) or corner (all three equal), on either side of each
/// axis, in any order of the axes.
fn cube_edge_or_corner() -> impl Strategy<Value = Direction> {
    (
        0.01..=1.0f64,
        0.0..=1.0f64,
        any::<bool>(),
        [sign(), sign(), sign()],
        0..3usize,
    )
        .prop_map(|(big, fraction, corner, signs, rotate)| {
            let small = if corner { big } else { big * fraction };
            let mut c = [signs[0] * big, signs[1] * big, signs[2] * small];
            c.rotate_left(rotate);
            direction(DVec3::from_array(c))
        })
}

/// A direction within 1e-300 to 1e-1 of an axis (a pole, a face's
/// centre, the sphere map's rim direction `−z`), either side.
fn near_an_axis() -> impl Strategy<Value = Direction> {
    (
        0..3usize,
        sign(),
        -300.0..-1.0f64,
        component(),
        component(),
        any::<bool>(),
    )
        .prop_map(|(axis, side, log_off, a, b, exact)| {
            let off = if exact { 0.0 } else { 10f64.powf(log_off) };
            let mut c = [off * a, off * b, off * a * b];
            c[axis] = side;
            direction(DVec3::from_array(c))
        })
}

/// A direction on or just beside the lat-long seam `φ = 0` (`y = ±0` or
/// within 1e-300 to 1e-3 of it, `x > 0`).
fn near_the_seam() -> impl Strategy<Value = Direction> {
    (
        1e-3..=1.0f64,
        -300.0..-3.0f64,
        sign(),
        any::<bool>(),
        component(),
    )
        .prop_map(|(x, log_y, side, exact, z)| {
            let y = if exact {
                side * 0.0
            } else {
                side * 10f64.powf(log_y)
            };
            direction(DVec3::new(x, y, z))
        })
}

/// Any direction: the box, the edges and corners, the axes, the seam.
fn any_direction() -> impl Strategy<Value = Direction> {
    prop_oneof![
        4 => box_direction(),
        2 => cube_edge_or_corner(),
        2 => near_an_axis(),
        1 => near_the_seam(),
    ]
}

#[test]
fn a_direction_needs_a_finite_nonzero_vector() {
    use super::DirectionError;
    assert_eq!(Direction::new(DVec3::ZERO), Err(DirectionError::Zero));
    assert_eq!(
        Direction::new(DVec3::new(f64::NAN, 0.0, 1.0)),
        Err(DirectionError::NotFinite)
    );
    assert_eq!(
        Direction::new(DVec3::new(0.0, f64::INFINITY, 1.0)),
        Err(DirectionError::NotFinite)
    );
    // Scaled before normalising: tiny and huge vectors have directions.
    let tiny = Direction::new(DVec3::new(1e-300, 0.0, 0.0)).unwrap();
    assert_eq!(tiny.get(), DVec3::X);
    let huge = Direction::new(DVec3::new(3e300, 4e300, 0.0)).unwrap();
    assert!((huge.get() - DVec3::new(0.6, 0.8, 0.0)).length() <= 2.0 * EPS);
}
