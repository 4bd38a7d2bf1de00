//! The suite's colorimetry against colour-science.
//!
//! Reference: `validation/reference/colorimetry.json` (schema
//! `colorimetry/1`), written by `python-checks/colorimetry.py`, which also
//! writes the radiometry crate's compiled-in CIE tables.
//!
//! # Tolerances
//!
//! Both sides evaluate the same formulas in `f64`; they differ only in the
//! order of summation (85 terms) and in library `cbrt`/`pow`/`atan2`.
//! - XYZ and linear sRGB, absolute [`XYZ_ABS`] = 1e-12: a sum of 85 positive
//!   terms in another order differs by at most about 85 ε ≈ 2e-14 relative.
//! - Encoded sRGB, absolute [`SRGB_ABS`] = 1e-12: the transfer function's
//!   slope is below 13 except near 0, where it is linear.
//! - CIELAB, absolute [`LAB_ABS`] = 1e-9: `a*` multiplies a difference of
//!   cube roots by 500.
//! - CIEDE2000, absolute [`DELTA_E_ABS`] = 1e-9 from colour-science, and
//!   5e-5 from the four decimals Sharma et al. print.

use radiometry::colour::{self, Lab, Xyz};
use radiometry::spectrum::{self, SAMPLES};
use serde::Deserialize;

use crate::check::Check;

/// XYZ and linear sRGB against colour-science, absolute.
pub const XYZ_ABS: f64 = 1e-12;
/// Encoded sRGB against colour-science, absolute.
pub const SRGB_ABS: f64 = 1e-12;
/// CIELAB against colour-science, absolute.
pub const LAB_ABS: f64 = 1e-9;
/// CIEDE2000 against colour-science, absolute.
pub const DELTA_E_ABS: f64 = 1e-9;
/// CIEDE2000 against the four printed decimals of Sharma et al. (2005).
pub const PRINTED_ABS: f64 = 5e-5;

/// The file name of the reference.
pub const FILE: &str = "colorimetry.json";
/// Its schema.
pub const SCHEMA: &str = "colorimetry/1";

/// The colorimetry under test: the radiometry crate's by default, or broken
/// versions in the fault-injection tests.
#[derive(Clone, Copy)]
pub struct ColourLaws {
    /// Reflectance on the CIE grid to XYZ under D65.
    pub reflectance_to_xyz: fn(&[f64; SAMPLES]) -> Xyz,
    /// XYZ to linear sRGB.
    pub xyz_to_linear_srgb: fn(Xyz) -> [f64; 3],
    /// The sRGB transfer function.
    pub srgb_encode: fn(f64) -> f64,
    /// XYZ to CIELAB relative to a white.
    pub xyz_to_lab: fn(Xyz, Xyz) -> Lab,
    /// CIEDE2000.
    pub delta_e_2000: fn(Lab, Lab) -> f64,
}

impl ColourLaws {
    /// The radiometry crate's colorimetry.
    pub fn radiometry() -> Self {
        Self {
            reflectance_to_xyz: spectrum::reflectance_to_xyz,
            xyz_to_linear_srgb: colour::xyz_to_linear_srgb,
            srgb_encode: colour::srgb_encode,
            xyz_to_lab: colour::xyz_to_lab,
            delta_e_2000: colour::delta_e_2000,
        }
    }
}

/// `colorimetry.json`.
#[derive(Clone, Debug, Deserialize)]
pub struct Colorimetry {
    /// colour-science's version.
    pub colour_science_version: String,
    /// The colour-matching functions on the grid.
    pub cmf_xyz: Vec<[f64; 3]>,
    /// D65 on the grid.
    pub d65: Vec<f64>,
    /// Test spectra and their colours.
    pub spectra: Vec<SpectrumCase>,
    /// CIEDE2000 test pairs.
    pub delta_e_2000: Vec<DeltaECase>,
}

/// A reflectance spectrum and colour-science's colour of it.
#[derive(Clone, Debug, Deserialize)]
pub struct SpectrumCase {
    /// What it is.
    pub label: String,
    /// Reflectance on the CIE grid.
    pub reflectance: Vec<f64>,
    /// Its colour.
    #[serde(flatten)]
    pub colour: ColourValues,
}

/// A colour in every representation the suite computes.
#[derive(Clone, Debug, Deserialize)]
pub struct ColourValues {
    /// XYZ, `Y = 1` white.
    pub xyz: [f64; 3],
    /// Linear sRGB.
    pub linear_srgb: [f64; 3],
    /// Encoded sRGB of the linear value clipped into `[0, 1]`.
    pub srgb: [f64; 3],
    /// CIELAB relative to the D65 white.
    pub lab: [f64; 3],
}

/// A CIEDE2000 test pair.
#[derive(Clone, Debug, Deserialize)]
pub struct DeltaECase {
    /// Which pair.
    pub label: String,
    /// First colour.
    pub lab1: [f64; 3],
    /// Second colour.
    pub lab2: [f64; 3],
    /// colour-science's ΔE00.
    pub delta_e_2000: f64,
    /// The value printed in the paper (four decimals).
    pub printed: f64,
}

impl Colorimetry {
    /// Loads the reference from `dir`.
    pub fn load(dir: &std::path::Path) -> Result<Self, crate::reference::ReferenceError> {
        crate::reference::load(dir, FILE, SCHEMA)
    }
}

/// The Lab triple as a [`Lab`].
pub fn lab(v: [f64; 3]) -> Lab {
    Lab::new(v[0], v[1], v[2])
}

/// Our colour of a reflectance spectrum, every representation.
pub fn colour_of(laws: &ColourLaws, reflectance: &[f64; SAMPLES]) -> ColourValues {
    let xyz = (laws.reflectance_to_xyz)(reflectance);
    let linear = (laws.xyz_to_linear_srgb)(xyz);
    let lab = (laws.xyz_to_lab)(xyz, colour::d65_white());
    ColourValues {
        xyz: [xyz.x, xyz.y, xyz.z],
        linear_srgb: linear,
        srgb: linear.map(|c| (laws.srgb_encode)(c.clamp(0.0, 1.0))),
        lab: [lab.l, lab.a, lab.b],
    }
}

fn max_abs(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|i| (a[i] - b[i]).abs()).fold(
        0.0,
        |m, d| if d.is_nan() { f64::INFINITY } else { m.max(d) },
    )
}

/// Compares every representation of a colour with colour-science's, recording into `check`.
pub fn compare_colour(check: &mut Check, label: &str, ours: &ColourValues, theirs: &ColourValues) {
    let rows = [
        (["XYZ", "XYZ"], ours.xyz, theirs.xyz, XYZ_ABS),
        (
            ["linear sRGB", "lineáris sRGB"],
            ours.linear_srgb,
            theirs.linear_srgb,
            XYZ_ABS,
        ),
        (["sRGB", "sRGB"], ours.srgb, theirs.srgb, SRGB_ABS),
        (["CIELAB", "CIELAB"], ours.lab, theirs.lab, LAB_ABS),
    ];
    for ([name, name_hu], a, b, tolerance) in rows {
        let d = max_abs(a, b);
        check.measure_in_both(
            [
                &format!("{name}: max |ours − colour-science|"),
                &format!("{name_hu}: max |miénk − colour-science|"),
            ],
            d,
            label,
        );
        if !(d <= tolerance) {
            check.fail(format!("{name} of {label}: ours {a:?}, colour-science {b:?} (off by {d:.2e} > {tolerance:e})"));
        }
    }
}

/// The compiled-in CIE tables are colour-science's, bit for bit.
pub fn check_tables(reference: &Colorimetry) -> Check {
    let mut check = Check::new(
        "colour.colour-science.tables",
        [
            "CIE 1931 2° colour-matching functions and D65, compiled into the radiometry crate",
            "A CIE 1931 2°-os színillesztő függvények és a D65, a radiometriai könyvtárba fordítva",
        ],
        [
            &format!("colour-science {}", reference.colour_science_version),
            &format!("colour-science {}", reference.colour_science_version),
        ],
        [
            "bit-identical: the tables are copied, not computed",
            "bitre azonos: a táblázatok másolatok, nem számítottak",
        ],
    );
    if reference.cmf_xyz.len() != SAMPLES || reference.d65.len() != SAMPLES {
        check.fail(format!(
            "the reference tables do not have {SAMPLES} samples"
        ));
        return check;
    }
    for i in 0..SAMPLES {
        let label = format!("{} nm", spectrum::wavelength_nm(i));
        check.cases += 1;
        if spectrum::CMF_XYZ[i] != reference.cmf_xyz[i] || spectrum::D65[i] != reference.d65[i] {
            check.fail(format!("tables differ at {label}"));
        }
    }
    check
}

/// XYZ, sRGB and CIELAB of the test spectra against colour-science.
pub fn check_spectra(laws: &ColourLaws, reference: &Colorimetry) -> Check {
    let mut check = Check::new(
        "colour.colour-science.spectra",
        [
            "Reflectance spectra to XYZ (D65), linear sRGB, sRGB and CIELAB: flat, smooth and the 24 ColorChecker patches",
            "Visszaverődési spektrumok XYZ-be (D65), lineáris sRGB-be, sRGB-be és CIELAB-ba: egyenletes, sima és a 24 ColorChecker-mező",
        ],
        [
            &format!("colour-science {}", reference.colour_science_version),
            &format!("colour-science {}", reference.colour_science_version),
        ],
        [&format!("XYZ and linear sRGB within {XYZ_ABS:e}, sRGB within {SRGB_ABS:e}, CIELAB within {LAB_ABS:e} (summation order)"), &format!("XYZ és lineáris sRGB legfeljebb {XYZ_ABS:e}, sRGB legfeljebb {SRGB_ABS:e}, CIELAB legfeljebb {LAB_ABS:e} eltéréssel (az összegzés sorrendje)")],
    );
    for case in &reference.spectra {
        check.cases += 1;
        let Ok(reflectance) = <[f64; SAMPLES]>::try_from(case.reflectance.as_slice()) else {
            check.fail(format!(
                "{}: {} samples, expected {SAMPLES}",
                case.label,
                case.reflectance.len()
            ));
            continue;
        };
        compare_colour(
            &mut check,
            &case.label,
            &colour_of(laws, &reflectance),
            &case.colour,
        );
    }
    check
}

/// CIEDE2000 of the Sharma et al. (2005) pairs against colour-science and the paper.
pub fn check_delta_e(laws: &ColourLaws, reference: &Colorimetry) -> Check {
    let mut check = Check::new(
        "colour.colour-science.ciede2000",
        [
            "CIEDE2000 of the 34 test pairs of Sharma, Wu & Dalal (2005)",
            "Sharma, Wu és Dalal (2005) 34 tesztpárjának CIEDE2000-értéke",
        ],
        [
            &format!("colour-science {} and the paper's printed values", reference.colour_science_version),
            &format!("colour-science {} és a cikkben nyomtatott értékek", reference.colour_science_version),
        ],
        [&format!("within {DELTA_E_ABS:e} of colour-science, {PRINTED_ABS:e} of the printed four decimals"), &format!("legfeljebb {DELTA_E_ABS:e} eltérés a colour-science értékétől, {PRINTED_ABS:e} a nyomtatott négy tizedestől")],
    );
    for case in &reference.delta_e_2000 {
        check.cases += 1;
        let ours = (laws.delta_e_2000)(lab(case.lab1), lab(case.lab2));
        let (d, p) = (
            (ours - case.delta_e_2000).abs(),
            (ours - case.printed).abs(),
        );
        check.measure_in_both(
            ["|ours − colour-science|", "|miénk − colour-science|"],
            d,
            &case.label,
        );
        check.measure_in_both(["|ours − printed|", "|miénk − nyomtatott|"], p, &case.label);
        if !(d <= DELTA_E_ABS && p <= PRINTED_ABS) {
            check.fail(format!(
                "{}: ours {ours:.6}, colour-science {:.6}, printed {:.4}",
                case.label, case.delta_e_2000, case.printed
            ));
        }
    }
    check
}

/// Every colorimetry check.
pub fn check_all(laws: &ColourLaws, reference: &Colorimetry) -> Vec<Check> {
    vec![
        check_tables(reference),
        check_spectra(laws, reference),
        check_delta_e(laws, reference),
    ]
}
