//! `optics validate`'s checks of the slides' techniques: they pass with
//! the suite's N-BK7, and a glass a hair off Schott's coefficients fails
//! the data-sheet check.

use techniques::dispersion::SELLMEIER_N_BK7;
use validation::techniques::{check_all, check_sellmeier};

#[test]
fn every_technique_check_passes() {
    let (checks, curves) = check_all(&SELLMEIER_N_BK7);
    assert_eq!(curves.refraction.len(), 4);
    assert_eq!(curves.fresnel_fits.len(), 3);
    assert_eq!(checks.len(), 6);
    for check in &checks {
        assert!(check.passed(), "{}: {:?}", check.id, check.failures);
    }
    // The slides' c = 1 into water: 10.6° from Snell's law at its worst (59°).
    let cheap = checks
        .iter()
        .find(|c| c.id == "techniques.refraction.cheap")
        .unwrap();
    let worst = cheap
        .worst("into water, c = 1: angle from Snell's law (°)")
        .unwrap();
    assert!((worst.worst - 10.63).abs() < 0.01, "{worst:?}");
}

#[test]
fn a_glass_off_schotts_coefficients_fails_the_data_sheet() {
    let mut glass = SELLMEIER_N_BK7;
    // B1 off by 2e-5 of itself moves n_d by 7e-6, past the printed digits
    // at the e, d and C lines (n_F moves by less).
    glass.b[0] *= 1.0 + 2e-5;
    let check = check_sellmeier(&glass);
    assert!(!check.passed());
    assert_eq!(check.failures.len(), 3, "{:?}", check.failures);
}
