//! N-BK7's Sellmeier index against Schott's data sheet, the three-eta
//! table, the slides' erratum on which colour bends more, and the prism:
//! the traced deviation is the analytic minimum at the symmetric incidence
//! and larger at any other.

use proptest::prelude::*;
use radiometry::snell::transmitted_angle;

use super::prism::{Passage, Prism};
use super::*;

const BK7: Sellmeier = SELLMEIER_N_BK7;

fn n_bk7(nm: f64) -> f64 {
    BK7.index_at(nm).unwrap()
}

/// Schott's data sheet prints N-BK7's indices to five decimals:
/// n_d = 1.51680, n_F = 1.52238, n_C = 1.51432, n_e = 1.51872, and the
/// Abbe number ν_d = 64.17. The formula with the sheet's coefficients must
/// round to them: tolerance half a unit in the last printed place (5e-6 for
/// an index, 0.005 for ν_d). Measured: 1.5168000, 1.5223763, 1.5143223,
/// 1.5187220 and 64.167.
#[test]
fn sellmeier_n_bk7_gives_the_data_sheets_indices() {
    use fraunhofer_nm::{C, D, E, F};
    for (line, nm, sheet) in [
        ("d", D, 1.51680),
        ("F", F, 1.52238),
        ("C", C, 1.51432),
        ("e", E, 1.51872),
    ] {
        let n = n_bk7(nm);
        println!("n_{line} ({nm} nm) = {n:.7}");
        assert!((n - sheet).abs() <= 5e-6, "n_{line} = {n}, sheet {sheet}");
    }
    let abbe = abbe_number(&BK7).unwrap();
    assert!((abbe - 64.17).abs() <= 0.005, "ν_d = {abbe}");
}

/// Normal dispersion: over the visible (380–780 nm, every nm) N-BK7's index
/// falls strictly with wavelength. Neighbouring indices differ by more
/// than 1e-6, their rounding by about 1e-16.
#[test]
fn sellmeier_index_falls_with_wavelength_in_the_visible() {
    let indices: Vec<f64> = (380..=780).map(|nm| n_bk7(f64::from(nm))).collect();
    assert!(indices.windows(2).all(|p| p[1] < p[0]));
    assert_eq!(BK7.index_at(299.0), None);
    assert_eq!(BK7.index_at(2501.0), None);
    assert_eq!(BK7.index_at(f64::NAN), None);
}

/// The three-eta table of `docs/techniques.md`: N-BK7's index and the
/// slides' `etaRatio = 1/n` entering it from air at the CIE 1931 RGB
/// primaries, and the refracted angles at 45° incidence by Snell's law
/// (printed with `cargo test -p techniques three_eta -- --nocapture`).
/// The same formulas in mpmath at 30 digits give the same digits.
#[test]
fn three_eta_ratios_at_the_cie_rgb_primaries() {
    let ratios = eta_ratios(&BK7, CIE_RGB_PRIMARIES_NM).unwrap();
    let mut rows = Vec::new();
    for ((channel, nm), ratio) in ["R", "G", "B"]
        .into_iter()
        .zip(CIE_RGB_PRIMARIES_NM)
        .zip(ratios)
    {
        let n = n_bk7(nm);
        assert_eq!(ratio, 1.0 / n);
        let theta_t = transmitted_angle(45f64.to_radians(), n)
            .unwrap()
            .to_degrees();
        rows.push(format!(
            "{channel} | {nm} | {n:.5} | {ratio:.5} | {theta_t:.3}"
        ));
    }
    println!("{}", rows.join("\n"));
    assert_eq!(
        rows,
        [
            "R | 700 | 1.51306 | 0.66091 | 27.861",
            "G | 546.1 | 1.51872 | 0.65845 | 27.749",
            "B | 435.8 | 1.52669 | 0.65501 | 27.591",
        ]
    );
}

/// `001` line 474: "a vörös fény jobban elhajlik, mint a kék" (red light
/// bends more than blue). Wrong for glass: N-BK7 bends blue (435.8 nm)
/// more than red (700 nm) at every incidence from 1° to 89°, into the
/// glass (a smaller refracted angle) and through a 60° prism (a larger
/// minimum deviation, 39.52° against 38.32°). The margins are 1e-4 rad or
/// more, the rounding about 1e-16.
#[test]
fn course_001_blue_bends_more_than_red_in_glass() {
    let (red, blue) = (n_bk7(700.0), n_bk7(435.8));
    for degrees in 1..=89 {
        let alpha = f64::from(degrees).to_radians();
        let bend = |n| alpha - transmitted_angle(alpha, n).unwrap();
        assert!(bend(blue) > bend(red), "{degrees}°");
    }
    let prism = Prism::new(60f64.to_radians()).unwrap();
    let deviation = |n| prism.minimum_deviation(n).unwrap().to_degrees();
    assert!(deviation(blue) > deviation(red) + 0.5);
    assert_eq!(
        format!("{:.2}° {:.2}°", deviation(blue), deviation(red)),
        "39.52° 38.32°"
    );
}

/// At the symmetric incidence `asin(n sin(A/2))` the ray traced through the
/// prism with radiometry's refraction runs parallel to the base inside and
/// is deviated by exactly `2 asin(n sin(A/2)) − A`: to 4e-15 rad, a few
/// ulps of the two refractions and the angle between unit vectors (6.7e-16
/// at most, measured); the inside ray's `y` to 4e-16 (1.1e-16 measured).
#[test]
fn symmetric_passage_deviates_by_the_minimum_deviation() {
    for apex_degrees in [30.0, 45.0, 60.0, 75.0] {
        let prism = Prism::new(f64::to_radians(apex_degrees)).unwrap();
        for n in [1.33, n_bk7(fraunhofer_nm::D), 1.6, 1.9] {
            let Some(theta) = prism.symmetric_incidence(n) else {
                // No ray crosses symmetrically: n sin(A/2) > 1 (75°, 1.9).
                assert!(n * (prism.apex() / 2.0).sin() > 1.0);
                continue;
            };
            let Some(Passage::Emerges {
                deviation, inside, ..
            }) = prism.trace(n, theta)
            else {
                panic!("{apex_degrees}° {n}");
            };
            let analytic = prism.minimum_deviation(n).unwrap();
            assert!(
                (deviation - analytic).abs() <= 4e-15,
                "{apex_degrees}° {n}: {deviation} vs {analytic}"
            );
            assert!(inside.y.abs() <= 4e-16, "{apex_degrees}° {n}: {inside}");
        }
    }
}

/// The angular spread of N-BK7 between the F (486.13 nm) and C (656.27 nm)
/// lines through a 60° prism: each at its own minimum deviation, and both
/// traced at the incidence of the d line's minimum deviation (what a
/// spectroscope set up for d shows). Printed with `cargo test -p
/// techniques spread -- --nocapture`, pinned to the digits quoted; the
/// closed forms in mpmath at 30 digits (`θ₁ + θ₄ − A` for the traced
/// pair) give the same digits.
#[test]
fn n_bk7_prism_spreads_f_and_c_by_0_71_degrees() {
    use fraunhofer_nm::{C, D, F};
    let prism = Prism::new(60f64.to_radians()).unwrap();
    let minimum = |nm| prism.minimum_deviation(n_bk7(nm)).unwrap().to_degrees();
    let theta_d = prism.symmetric_incidence(n_bk7(D)).unwrap();
    let traced = |nm| match prism.trace(n_bk7(nm), theta_d) {
        Some(Passage::Emerges { deviation, .. }) => deviation.to_degrees(),
        other => panic!("{nm}: {other:?}"),
    };
    let report = format!(
        "δ_min d {:.4}°, F {:.4}°, C {:.4}°; spread at minimum {:.4}°, at d's incidence {:.4}°",
        minimum(D),
        minimum(F),
        minimum(C),
        minimum(F) - minimum(C),
        traced(F) - traced(C)
    );
    println!("{report}");
    assert_eq!(
        report,
        "δ_min d 38.6467°, F 39.1381°, C 38.4291°; spread at minimum 0.7090°, at d's incidence 0.7097°"
    );
}

fn index_of_glass() -> impl Strategy<Value = f64> {
    1.3..1.9f64
}

fn incidence_angle() -> impl Strategy<Value = f64> {
    -1.5..1.5f64
}

proptest! {
    /// Minimum deviation: any incidence whose ray leaves the 60° prism is
    /// deviated at least `δ_min` (within 4e-15 rad of rounding), and more
    /// than `δ_min + 1e-9` when it is 1e-3 rad or more from the symmetric
    /// one (near the minimum `δ − δ_min ≈ δ''/2 Δθ²`, with `δ''/2` from
    /// 0.47 at n = 1.3 to 2.9 at n = 1.9, by mpmath: 4.7e-7 at least).
    #[test]
    fn minimum_deviation_is_the_least(n in index_of_glass(), theta in incidence_angle()) {
        let prism = Prism::new(60f64.to_radians()).unwrap();
        let least = prism.minimum_deviation(n).unwrap();
        if let Some(Passage::Emerges { deviation, .. }) = prism.trace(n, theta) {
            prop_assert!(deviation >= least - 4e-15, "{deviation} < {least}");
            if (theta - prism.symmetric_incidence(n).unwrap()).abs() >= 1e-3 {
                prop_assert!(deviation > least + 1e-9, "{deviation} vs {least}");
            }
        }
    }
}

/// Past the critical angle at the second face the ray is reflected back
/// inside, and a ray arriving from far above the normal turns away from
/// the second face: both are outcomes, not deviations.
#[test]
fn prism_names_the_rays_that_do_not_emerge() {
    let prism = Prism::new(60f64.to_radians()).unwrap();
    let n = n_bk7(fraunhofer_nm::D);
    // θ₁ = −10°: inside θ₂ = −6.6°, so the second face is met at
    // A − θ₂ = 66.6°, past N-BK7's critical angle of 41.2°. θ₁ = −80°:
    // θ₂ = −40.5°, the second face would be met at 100.5°, from behind.
    assert_eq!(
        prism.trace(n, f64::to_radians(-10.0)),
        Some(Passage::TotalInternalReflection)
    );
    assert_eq!(
        prism.trace(n, f64::to_radians(-80.0)),
        Some(Passage::MissesSecondFace)
    );
    assert_eq!(prism.trace(n, 2.0), None);
    assert_eq!(Prism::new(0.0), None);
}
