//! The cheap refraction against Snell's law: exact at normal incidence,
//! worse with the angle, the closed-form values of the plane of incidence,
//! and total internal reflection as the law's outcome.

use radiometry::snell::{critical_angle, transmitted_angle};

use super::*;

const WATER: f64 = 1.33;
const GLASS: f64 = 1.5;

/// Every 0.1° from 0° up to `below` (radians), excluded.
fn angles_below(below: f64) -> impl Iterator<Item = f64> {
    (0..=900)
        .map(|k| f64::to_radians(k as f64 / 10.0))
        .take_while(move |&a| a < below)
}

/// Head-on, every form of `c` goes straight through, as the law does:
/// `−c n + i` is along `n`, and the angle between parallel vectors is 0 to
/// the bit (their cross product is exactly zero).
#[test]
fn cheap_refraction_is_exact_at_normal_incidence() {
    for eta in [WATER, GLASS, 2.42] {
        for side in [Side::Outside, Side::Inside] {
            for constant in [SLIDES_WATER, Constant::FirstOrder, Constant::Fixed(0.3)] {
                let error = compare_at(0.0, side, eta, constant).unwrap().error();
                assert_eq!(error, Some(0.0), "{eta} {side:?} {constant:?}");
            }
        }
    }
}

/// With the first-order `c` the error grows strictly with the incidence
/// angle, on a 0.1° grid: to grazing incidence entering the medium, to the
/// critical angle leaving it. With the slides' `c = 1` entering, it grows
/// up to its worst angle, `cos²α = (η² − 1)/3` (the erratum's test measures
/// that maximum), and falls beyond it. Strictly: neighbouring errors differ
/// by more than 1e-10 rad on this grid, their rounding by about 1e-16.
#[test]
fn cheap_refraction_error_grows_with_incidence_angle() {
    let grows = |eta: f64, side: Side, constant: Constant, below: f64| {
        let errors: Vec<f64> = angles_below(below)
            .map(|a| compare_at(a, side, eta, constant).unwrap().error().unwrap())
            .collect();
        assert!(errors.len() > 100, "{eta} {side:?}");
        for pair in errors.windows(2) {
            assert!(pair[1] > pair[0], "{eta} {side:?} {constant:?}: {pair:?}");
        }
    };
    let grazing = std::f64::consts::FRAC_PI_2 + 1e-9;
    for eta in [WATER, GLASS] {
        grows(eta, Side::Outside, Constant::FirstOrder, grazing);
        grows(
            eta,
            Side::Inside,
            Constant::FirstOrder,
            critical_angle(1.0 / eta).unwrap(),
        );
        let worst = ((eta * eta - 1.0) / 3.0).sqrt().acos();
        grows(eta, Side::Outside, SLIDES_WATER, worst);
        let past = compare_at(worst + 0.1, Side::Outside, eta, SLIDES_WATER).unwrap();
        let at = compare_at(worst, Side::Outside, eta, SLIDES_WATER).unwrap();
        assert!(past.error() < at.error(), "{eta}");
    }
}

/// The error at 30°, 60° and 80°, against values computed independently of
/// the vector code: the angles in the plane of incidence,
/// `atan2(sin α, cos α + c) − asin(sin α / η)` (η along the path), in
/// mpmath at 30 digits with η = 133/100, 3/2 and their inverses, printed to
/// 15 significant digits (so rounded by up to 5e-14°). Tolerance 1e-12°
/// (2e-14 rad): the vector forms round to a few ulps, about 1e-16 rad, and
/// the largest difference measured is 4.3e-14°; a wrong formula or
/// constant is off by 1e-3° or more. `None`: total internal reflection.
#[test]
fn cheap_refraction_error_matches_the_plane_of_incidence_values() {
    use Side::{Inside, Outside};
    #[rustfmt::skip]
    let table = [
        ("water, c = 1", WATER, Outside, SLIDES_WATER, 30.0_f64, Some(7.08241319447225)),
        ("water, c = 1", WATER, Outside, SLIDES_WATER, 60.0, Some(10.6281306514821)),
        ("water, c = 1", WATER, Outside, SLIDES_WATER, 80.0, Some(7.77035586616183)),
        ("water, c = η − 1", WATER, Outside, Constant::FirstOrder, 30.0, Some(0.605017432253901)),
        ("water, c = η − 1", WATER, Outside, Constant::FirstOrder, 60.0, Some(5.58871034737495)),
        ("water, c = η − 1", WATER, Outside, Constant::FirstOrder, 80.0, Some(15.1436349607889)),
        ("glass, c = 1", GLASS, Outside, SLIDES_WATER, 30.0, Some(4.47122063449069)),
        ("glass, c = 1", GLASS, Outside, SLIDES_WATER, 60.0, Some(5.26438968275465)),
        ("glass, c = 1", GLASS, Outside, SLIDES_WATER, 80.0, Some(1.03641052520335)),
        ("glass, c = η − 1", GLASS, Outside, Constant::FirstOrder, 30.0, Some(0.632688726526408)),
        ("glass, c = η − 1", GLASS, Outside, Constant::FirstOrder, 60.0, Some(5.62900496637625)),
        ("glass, c = η − 1", GLASS, Outside, Constant::FirstOrder, 80.0, Some(14.589889050058)),
        ("out of water, c = 1/η − 1", WATER, Inside, Constant::FirstOrder, 30.0, Some(2.7030347528853)),
        ("out of glass, c = 1/η − 1", GLASS, Inside, Constant::FirstOrder, 30.0, Some(5.40359245871562)),
        ("out of glass, c = 1/η − 1", GLASS, Inside, Constant::FirstOrder, 60.0, None),
        ("out of glass, c = 1: bends the wrong way", GLASS, Inside, SLIDES_WATER, 30.0, Some(33.5903778907291)),
    ];
    for (case, eta, side, constant, degrees, want) in table {
        let got = compare_at(degrees.to_radians(), side, eta, constant)
            .unwrap()
            .error()
            .map(f64::to_degrees);
        match (got, want) {
            (Some(got), Some(want)) => {
                assert!(
                    (got - want).abs() <= 1e-12,
                    "{case} at {degrees}°: {got}° vs {want}°"
                )
            }
            _ => assert_eq!(got, want, "{case} at {degrees}°"),
        }
    }
}

/// With `c = η − 1` entering, the cheap ray stays within 1° of Snell's up
/// to 35.25° in water and 34.80° in glass (where mpmath's root of the
/// plane-of-incidence error puts 1°: 35.254°, 34.796°). Checked 0.01° either
/// side, where the error differs from 1° by 8e-4° (its slope there is
/// about 0.09° per degree), its rounding by about 1e-14°.
#[test]
fn first_order_cheap_refraction_is_within_a_degree_to_35_degrees() {
    for (eta, one_degree_at) in [(WATER, 35.254), (GLASS, 34.796)] {
        let error = |degrees: f64| {
            compare_at(
                degrees.to_radians(),
                Side::Outside,
                eta,
                Constant::FirstOrder,
            )
            .unwrap()
            .error()
            .unwrap()
            .to_degrees()
        };
        assert!(error(one_degree_at - 0.01) < 1.0, "{eta}");
        assert!(error(one_degree_at + 0.01) > 1.0, "{eta}");
    }
}

/// Past the critical angle the law has no transmitted ray, and the outcome
/// says so; just before it, it has. The cheap form knows no critical angle
/// and still returns a unit vector; with the first-order `c = 1/η − 1`
/// past `cos α = −c` (70.5° in glass) that vector even turns back into the
/// medium. Tolerances: 1e-9 rad either side of the critical angle, far
/// above the rounding of `asin` and far below any grid; 1e-15 on the unit
/// length (a few ulps).
#[test]
fn total_internal_reflection_is_the_exact_laws_outcome() {
    for eta in [WATER, GLASS] {
        let critical = critical_angle(1.0 / eta).unwrap();
        for constant in [SLIDES_WATER, Constant::FirstOrder] {
            let before = compare_at(critical - 1e-9, Side::Inside, eta, constant).unwrap();
            assert!(matches!(before, Comparison::Refracts { .. }), "{eta}");
            let past = compare_at(critical + 1e-9, Side::Inside, eta, constant).unwrap();
            let Comparison::TotalInternalReflection { cheap } = past else {
                panic!("{eta} {constant:?}: {past:?}");
            };
            assert!((cheap.length() - 1.0).abs() <= 1e-15, "{cheap}");
            // Entering, nothing is reflected totally.
            let entering = compare_at(critical + 1e-9, Side::Outside, eta, constant).unwrap();
            assert!(entering.error().is_some());
        }
    }
    let back = compare_at(
        80f64.to_radians(),
        Side::Inside,
        GLASS,
        Constant::FirstOrder,
    )
    .unwrap();
    let Comparison::TotalInternalReflection { cheap } = back else {
        panic!("{back:?}");
    };
    // Travelling out of the medium is +z here; the cheap ray goes back in.
    assert!(cheap.z < 0.0, "{cheap}");
}

/// With `c = η − 1` the error is third order near the normal, from either
/// side: `|η − 1| α³ / (2 η³)` to leading order (η along the path). The
/// erratum's test checks the entering side; leaving, η < 1. At α = 0.01
/// the next term is `O(α²)` relative, 1e-4: tolerance 1e-3 relative.
#[test]
fn first_order_constant_errs_by_alpha_cubed_from_either_side() {
    let alpha: f64 = 0.01;
    for eta in [WATER, GLASS] {
        for (side, eta_path) in [(Side::Outside, eta), (Side::Inside, 1.0 / eta)] {
            let error = compare_at(alpha, side, eta, Constant::FirstOrder)
                .unwrap()
                .error()
                .unwrap();
            let leading = (eta_path - 1.0).abs() * alpha.powi(3) / (2.0 * eta_path.powi(3));
            assert!(
                (error / leading - 1.0).abs() <= 1e-3,
                "{eta} {side:?}: {error} vs {leading}"
            );
        }
    }
}

/// The slide's "the amount of refraction decreases near the horizon"
/// (`001` line 389), read two ways against Snell's law entering water and
/// glass on a 0.1° grid: the deviation `α − θ_t` grows all the way to
/// grazing incidence (41.2° for water at 90°), so read as the bend it is
/// wrong; the rate `dθ_t/dα = cos α / (η cos θ_t)` falls towards the
/// horizon, so read as how fast the refracted ray moves it is right.
/// Compared strictly: neighbouring values differ by more than 1e-7, their
/// rounding by about 1e-16.
#[test]
fn refraction_bends_more_but_moves_less_towards_the_horizon() {
    for eta in [WATER, GLASS] {
        let angles: Vec<f64> = angles_below(std::f64::consts::FRAC_PI_2 + 1e-9).collect();
        let theta_t: Vec<f64> = angles
            .iter()
            .map(|&a| transmitted_angle(a, eta).unwrap())
            .collect();
        let deviation: Vec<f64> = angles.iter().zip(&theta_t).map(|(a, t)| a - t).collect();
        let rate: Vec<f64> = angles
            .iter()
            .zip(&theta_t)
            .map(|(a, t)| a.cos() / (eta * t.cos()))
            .collect();
        assert!(deviation.windows(2).all(|p| p[1] > p[0]), "{eta}");
        assert!(rate.windows(2).all(|p| p[1] < p[0]), "{eta}");
        if eta == WATER {
            let at_grazing = deviation.last().unwrap().to_degrees();
            assert_eq!(format!("{at_grazing:.1}"), "41.2");
        }
    }
}
