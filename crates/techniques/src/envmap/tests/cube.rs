//! The cube map.
//!
//! Tolerance of the round trip: 8 ε (1.8e-15 rad). There and back is a
//! division by `|m_a|`, `(s + 1) / 2` and `2u − 1` (each coordinate off by
//! at most 2 ε in `[−1, 1]`) and a normalisation (1 ε per component):
//! about 4 ε, doubled for margin. The face is decided by comparisons
//! alone, so it is checked exactly.

use glam::DVec3;
use proptest::prelude::*;
use proptest::test_runner::{Config, TestCaseError, TestRunner};

use super::{any_direction, chord, cube_edge_or_corner, direction};
use crate::envmap::cube::{CubeTexel, Face};
use crate::envmap::{Direction, TexelError};

const ROUND_TRIP: f64 = 8.0 * f64::EPSILON;

fn round_trip(r: Direction, there: impl Fn(Direction) -> CubeTexel) -> Result<(), TestCaseError> {
    let texel = there(r);
    let back = CubeTexel::from_uv(texel.face(), texel.u(), texel.v())
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
    fn cube_round_trip_returns_the_direction(r in any_direction()) {
        round_trip(r, CubeTexel::from_direction)?;
    }

    #[test]
    fn cube_round_trip_holds_on_edges_and_corners(r in cube_edge_or_corner()) {
        round_trip(r, CubeTexel::from_direction)?;
    }

    #[test]
    fn cube_face_is_the_major_axis(r in any_direction()) {
        let face = Face::of(r);
        let frame = face.frame();
        let v = r.get();
        let major = v[frame.axis];
        prop_assert!(major * frame.sign > 0.0, "{v:?} on {face:?}");
        for other in 0..3 {
            prop_assert!(v[other].abs() <= major.abs(), "{v:?} on {face:?}");
        }
    }

    #[test]
    fn cube_ties_go_to_z_then_y(r in cube_edge_or_corner()) {
        let a = r.get().abs();
        let axis = Face::of(r).frame().axis;
        let largest = a.max_element();
        let first_largest = (0..3).rev().find(|&k| a[k] == largest);
        prop_assert_eq!(Some(axis), first_largest, "{:?}", r.get());
    }

    #[test]
    fn cube_uv_lies_on_the_face(r in any_direction()) {
        let texel = CubeTexel::from_direction(r);
        prop_assert!((0.0..=1.0).contains(&texel.u()) && (0.0..=1.0).contains(&texel.v()), "{texel:?}");
    }
}

/// Each face's centre, its `u` and `v` axes as Table 8.19 orients them:
/// the centre is the axis, and `u`, `v` grow along `s_c`, `t_c`.
#[test]
fn cube_faces_are_oriented_as_table_8_19() {
    // (face, direction at u = 1, v = 1/2, direction at u = 1/2, v = 1)
    let table: [(Face, [f64; 3], [f64; 3]); 6] = [
        (Face::PositiveX, [1.0, 0.0, -1.0], [1.0, -1.0, 0.0]),
        (Face::NegativeX, [-1.0, 0.0, 1.0], [-1.0, -1.0, 0.0]),
        (Face::PositiveY, [1.0, 1.0, 0.0], [0.0, 1.0, 1.0]),
        (Face::NegativeY, [1.0, -1.0, 0.0], [0.0, -1.0, -1.0]),
        (Face::PositiveZ, [1.0, 0.0, 1.0], [0.0, -1.0, 1.0]),
        (Face::NegativeZ, [-1.0, 0.0, -1.0], [0.0, -1.0, -1.0]),
    ];
    for (face, u_edge, v_edge) in table {
        let at = |u, v| CubeTexel::from_uv(face, u, v).unwrap().direction();
        let centre = direction(DVec3::from_array(face_axis(face)));
        assert!(chord(at(0.5, 0.5), centre) <= ROUND_TRIP, "{face:?} centre");
        let u_edge = direction(DVec3::from_array(u_edge));
        assert!(chord(at(1.0, 0.5), u_edge) <= ROUND_TRIP, "{face:?} u");
        let v_edge = direction(DVec3::from_array(v_edge));
        assert!(chord(at(0.5, 1.0), v_edge) <= ROUND_TRIP, "{face:?} v");
    }
}

fn face_axis(face: Face) -> [f64; 3] {
    let frame = face.frame();
    let mut axis = [0.0; 3];
    axis[frame.axis] = frame.sign;
    axis
}

#[test]
fn cube_corners_belong_to_the_z_faces() {
    for x in [1.0, -1.0] {
        for y in [1.0, -1.0] {
            for (z, face) in [(1.0, Face::PositiveZ), (-1.0, Face::NegativeZ)] {
                let r = direction(DVec3::new(x, y, z));
                assert_eq!(Face::of(r), face, "({x}, {y}, {z})");
            }
        }
    }
    assert_eq!(
        Face::of(direction(DVec3::new(-1.0, 1.0, 0.5))),
        Face::PositiveY
    );
}

#[test]
fn cube_texels_outside_the_square_are_refused_by_coordinate() {
    assert_eq!(
        CubeTexel::from_uv(Face::PositiveX, -0.5, 0.5),
        Err(TexelError::U(-0.5))
    );
    assert!(matches!(
        CubeTexel::from_uv(Face::PositiveX, 0.5, f64::INFINITY),
        Err(TexelError::V(_))
    ));
}

/// The round trip and the table catch a wrong map: `u` and `v` swapped on
/// the `+Y` face alone (a fault on one face in six, as a misread table
/// would make). The round trip finds it: the swapped texel reads back a
/// direction mirrored across the face's diagonal.
#[test]
fn cube_round_trip_catches_u_and_v_swapped_on_one_face() {
    let swapped_on_plus_y = |r: Direction| {
        let texel = CubeTexel::from_direction(r);
        match texel.face() {
            Face::PositiveY => CubeTexel::from_uv(Face::PositiveY, texel.v(), texel.u()).unwrap(),
            _ => texel,
        }
    };
    let mut runner = TestRunner::new(Config::with_cases(256));
    let outcome = runner.run(&any_direction(), |r| round_trip(r, swapped_on_plus_y));
    assert!(
        outcome.is_err(),
        "the round trip missed u and v swapped on +Y"
    );
}
