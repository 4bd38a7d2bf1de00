//! The radiometry crate's colorimetry against colour-science, from the
//! committed `validation/reference/colorimetry.json` (regenerate with
//! `.venv/bin/python python-checks/colorimetry.py`). Tolerances are stated in
//! `validation::colorimetry`. Run with `--nocapture` for the table.

mod caught;
mod tables;

use caught::{caught_at, caught_only};
use radiometry::colour::{self, Lab};
use radiometry::spectrum;
use validation::colorimetry::{self, Colorimetry, ColourLaws};
use validation::reference::committed_dir;

fn reference() -> Colorimetry {
    Colorimetry::load(&committed_dir()).expect("committed colorimetry reference")
}

#[test]
fn colorimetry_agrees_with_colour_science() {
    tables::assert_passed_and_settled(
        "colour-vs-colour-science",
        "cargo test -p validation --test colorimetry_vs_colour_science",
        &colorimetry::check_all(&ColourLaws::radiometry(), &reference()),
    );
}

/// The CIE 1976 difference, the Euclidean distance in CIELAB, in place of
/// CIEDE2000: a common substitution, and a different law.
fn delta_e_1976(lab1: Lab, lab2: Lab) -> f64 {
    let (dl, da, db) = (lab1.l - lab2.l, lab1.a - lab2.a, lab1.b - lab2.b);
    (dl * dl + da * da + db * db).sqrt()
}

#[test]
fn delta_e_1976_in_place_of_2000_is_caught() {
    let broken = ColourLaws {
        delta_e_2000: delta_e_1976,
        ..ColourLaws::radiometry()
    };
    let check = colorimetry::check_delta_e(&broken, &reference());
    // Pair 1 is a blue pair where the two differ by half (2.04 against 4.00).
    caught_at(&check, |f| f.starts_with("Sharma 2005 pair 1:"));
}

/// Lab against the white of the spectral integration, chromaticity
/// (0.31271, 0.32901), instead of the D65 chromaticity (0.3127, 0.3290)
/// that sRGB and colour-science use: the smallest change of white there is
/// to make, which moves the perfect reflector's a*, b* by 0.0016 and
/// 0.0054 (`radiometry::colour::D65_WHITE_XY`), far beyond `LAB_ABS`.
fn xyz_to_lab_with_integrated_white(xyz: colour::Xyz, _white: colour::Xyz) -> Lab {
    colour::xyz_to_lab(xyz, spectrum::reflectance_to_xyz(&[1.0; spectrum::SAMPLES]))
}

#[test]
fn cielab_against_the_wrong_white_is_caught() {
    let broken = ColourLaws {
        xyz_to_lab: xyz_to_lab_with_integrated_white,
        ..ColourLaws::radiometry()
    };
    let check = colorimetry::check_spectra(&broken, &reference());
    caught_only(&check, |f| f.starts_with("CIELAB"));
}
