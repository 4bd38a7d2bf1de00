//! The sphere map.
//!
//! Tolerances. The normal reflects the view into the direction to 8 ε:
//! `n` is one scaled normalisation of `r + e` (2 ε a component), the
//! reflection two products and a difference (3 ε), the comparison's own
//! rounding 1 ε; doubled for margin. Through the texel `(u, v)` the way
//! back takes `n_z = √(1 − n_x² − n_y²)`, whose rounding is amplified by
//! `1 / n_z` towards the rim: the round trip holds to `16 ε / n_z`
//! (`n_z = m / 2` is the normal's cosine to the view), and within
//! `√ε ≈ 1.5e-8` rad of `(0, 0, −1)`, where `(u, v)` rounds onto the rim,
//! to `4 √ε`: the resolution of the map there, not an error of the
//! formulas.

use glam::DVec3;
use proptest::prelude::*;
use proptest::test_runner::{Config, TestCaseError, TestRunner};

use super::{any_direction, chord, direction, near_an_axis};
use crate::envmap::sphere::{SphereTexel, TOWARDS_VIEWER};
use crate::envmap::{Direction, TexelError};

const EPS: f64 = f64::EPSILON;

/// The law of reflection, written out here rather than called, so that
/// the test does not trust the function the map uses: `n` reflects the
/// view `e` into `r`, to 8 ε.
fn reflects_view_into(n: DVec3, r: Direction) -> Result<(), TestCaseError> {
    let e = TOWARDS_VIEWER;
    let reflected = 2.0 * n.dot(e) * n - e;
    let error = (reflected - r.get()).length();
    prop_assert!(
        error <= 8.0 * EPS,
        "{n:?} reflects e into {reflected:?}, not {:?}",
        r.get()
    );
    Ok(())
}

fn round_trip(r: Direction) -> Result<(), TestCaseError> {
    let texel = SphereTexel::from_direction(r);
    let (back, n_z) = match texel {
        SphereTexel::Disc(t) => {
            let back = SphereTexel::from_uv(t.u(), t.v())
                .map_err(|e| TestCaseError::fail(format!("{t:?} is no texel: {e:?}")))?;
            (back.direction(), t.normal().z)
        }
        SphereTexel::Rim => (texel.direction(), 0.0),
    };
    let tolerance = (16.0 * EPS / n_z).min(4.0 * EPS.sqrt());
    let error = chord(r, back);
    prop_assert!(
        error <= tolerance,
        "{:?} went to {texel:?} and back to {:?}, {error:e} rad off (n_z = {n_z:e})",
        r.get(),
        back.get()
    );
    Ok(())
}

proptest! {
    #[test]
    fn sphere_map_round_trip_returns_the_direction(r in any_direction()) {
        round_trip(r)?;
    }

    #[test]
    fn sphere_map_round_trip_holds_beside_the_rim_direction(r in near_an_axis()) {
        round_trip(r)?;
    }

    #[test]
    fn sphere_map_normal_reflects_view_into_direction(r in any_direction()) {
        let SphereTexel::Disc(texel) = SphereTexel::from_direction(r) else {
            prop_assert_eq!(r.get(), -TOWARDS_VIEWER);
            return Ok(());
        };
        let n = texel.normal();
        prop_assert!((n.length() - 1.0).abs() <= 4.0 * EPS, "|n| = {}", n.length());
        reflects_view_into(n, r)?;
    }

    #[test]
    fn sphere_map_m_is_the_slides_length_of_r_plus_e(r in any_direction()) {
        // m = √(r_x² + r_y² + (r_z + 1)²) as the slides write it, to 4 ε
        // relative, where its squares do not underflow (m > 1e-150); and
        // m = 2 n_z everywhere.
        let SphereTexel::Disc(texel) = SphereTexel::from_direction(r) else {
            return Ok(());
        };
        let v = r.get();
        if texel.m() > 1e-150 {
            let slides = (v.x * v.x + v.y * v.y + (v.z + 1.0) * (v.z + 1.0)).sqrt();
            prop_assert!((texel.m() - slides).abs() <= 4.0 * EPS * slides, "{} against {slides}", texel.m());
        }
        prop_assert!((texel.m() - 2.0 * texel.normal().z).abs() <= 4.0 * EPS * texel.m(), "{texel:?}");
    }
}

#[test]
fn sphere_map_rim_is_the_direction_straight_away_from_the_viewer() {
    let away = direction(DVec3::new(0.0, 0.0, -3.0));
    assert_eq!(SphereTexel::from_direction(away), SphereTexel::Rim);
    assert_eq!(
        SphereTexel::Rim.direction().get(),
        DVec3::new(0.0, 0.0, -1.0)
    );
    // Every point of the rim stores it.
    for (u, v) in [(1.0, 0.5), (0.0, 0.5), (0.5, 1.0), (0.5, 0.0)] {
        let texel = SphereTexel::from_uv(u, v).unwrap();
        assert_eq!(texel, SphereTexel::Rim, "({u}, {v})");
    }
    // A direction 1e-300 from it still has a texel of its own, at the rim.
    let beside = direction(DVec3::new(1e-300, 0.0, -1.0));
    let SphereTexel::Disc(texel) = SphereTexel::from_direction(beside) else {
        panic!("(1e-300, 0, −1) fell on the rim");
    };
    assert_eq!((texel.u(), texel.v()), (1.0, 0.5));
    assert!(texel.m() > 0.0 && texel.m().is_finite());
}

#[test]
fn sphere_map_centre_is_the_direction_towards_the_viewer() {
    let SphereTexel::Disc(texel) = SphereTexel::from_direction(direction(TOWARDS_VIEWER)) else {
        panic!("e has no texel");
    };
    assert_eq!((texel.u(), texel.v(), texel.m()), (0.5, 0.5, 2.0));
}

#[test]
fn sphere_map_texels_outside_the_disc_are_refused() {
    assert_eq!(
        SphereTexel::from_uv(0.0, 0.0),
        Err(TexelError::OutsideDisc { u: 0.0, v: 0.0 })
    );
    assert_eq!(SphereTexel::from_uv(0.5, 1.5), Err(TexelError::V(1.5)));
}

/// The normal identity catches a wrong normal: `r_z − 1` for `r_z + 1`
/// (half way to `−e`, the view's direction of travel, instead of to the
/// viewer), a sign fault the slides' reader could make.
#[test]
fn sphere_map_normal_identity_catches_the_half_way_vector_to_minus_e() {
    let wrong_normal = |r: DVec3| DVec3::new(r.x, r.y, r.z - 1.0).normalize();
    let mut runner = TestRunner::new(Config::with_cases(64));
    let outcome = runner.run(&any_direction(), |r| {
        prop_assume!(r.get().z < 1.0 - 1e-6);
        reflects_view_into(wrong_normal(r.get()), r)
    });
    assert!(
        outcome.is_err(),
        "the identity missed the wrong half-way vector"
    );
}
