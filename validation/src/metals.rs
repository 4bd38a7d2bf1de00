//! Metals in colour: the exact spectral reflectance of gold, silver, copper
//! and aluminium against colour-science, and the colour error (CIEDE2000) of
//! the shortcuts renderers take instead of a spectrum.
//!
//! Reference: `validation/reference/metals.json` (schema `metals/1`), written
//! by `python-checks/metals.py`: the measured `n + iκ` that Mitsuba ships in
//! `data/ior`, and colour-science's colour of the exact reflectance spectra.
//!
//! The spectral colour is the reference for the shortcuts: the reflectance at
//! every 5 nm from 360 to 780 nm, integrated against the CIE 1931 observer
//! under D65 ([`radiometry::spectrum`]). Each shortcut gives linear sRGB (or a
//! spectrum) whose CIELAB is compared with it:
//!
//! | shortcut | what it does |
//! |---|---|
//! | course RGB | the course's gold `n = (0.17, 0.35, 1.5)`, `κ = (3.1, 2.7, 1.9)` per channel (seed `000`), gold only |
//! | `n, κ` at 650/550/450 nm | the measured index at one wavelength per channel, Fresnel per channel |
//! | `n, κ` at 700/546.1/435.8 nm | likewise at the CIE 1931 RGB primaries |
//! | Schlick, spectral F0 | Schlick's approximation per wavelength, from `F0(λ)` |
//! | Schlick, RGB F0 | Schlick per channel from the linear sRGB of the spectral F0 colour (the "F0 colour" of real-time renderers) |
//!
//! The RGB shortcuts treat their three reflectances as linear sRGB directly,
//! as a three-wavelength renderer does.

use radiometry::colour;
use radiometry::course::{GOLD_000_KAPPA, GOLD_000_N};
use radiometry::fresnel;
use radiometry::spectrum::{self, SAMPLES};
use serde::{Deserialize, Serialize};

use crate::check::Check;
use crate::colorimetry::{self, lab, ColourLaws, ColourValues};

/// Our reflectance spectrum against the exact one, absolute: the conductor
/// law is within 14 ulps of 50-digit values in `f64` (`tests/fresnel_reference.rs`),
/// and the linear interpolation of `n, κ` rounds differently by an ulp.
pub const REFLECTANCE_ABS: f64 = 1e-13;

/// The file name of the reference.
pub const FILE: &str = "metals.json";
/// Its schema.
pub const SCHEMA: &str = "metals/1";

/// Wavelength choices for the per-channel shortcut: a label and `[R, G, B]` in nm.
pub const WAVELENGTH_CHOICES: [(&str, [f64; 3]); 2] = [
    ("n, κ at 650/550/450 nm", spectrum::RGB_WAVELENGTHS_NM),
    (
        "n, κ at 700/546.1/435.8 nm (CIE RGB primaries)",
        [700.0, 546.1, 435.8],
    ),
];

/// `metals.json`.
#[derive(Clone, Debug, Deserialize)]
pub struct MetalsReference {
    /// Mitsuba's version (the source of the indices).
    pub mitsuba_version: String,
    /// colour-science's version.
    pub colour_science_version: String,
    /// The metals.
    pub metals: Vec<Metal>,
}

/// One metal's measured index and reference colours.
#[derive(Clone, Debug, Deserialize)]
pub struct Metal {
    /// English name.
    pub name: String,
    /// Tabulated wavelengths, increasing, nm.
    pub wavelengths_nm: Vec<f64>,
    /// Real part of the index at each.
    pub n: Vec<f64>,
    /// Extinction coefficient at each.
    pub kappa: Vec<f64>,
    /// Reference colours at several angles.
    pub angles: Vec<MetalAngle>,
}

/// The exact reflectance spectrum and its colour at one angle.
#[derive(Clone, Debug, Deserialize)]
pub struct MetalAngle {
    /// Angle of incidence, degrees.
    pub angle_deg: f64,
    /// Its cosine.
    pub cos_i: f64,
    /// Exact reflectance on the CIE grid.
    pub reflectance: Vec<f64>,
    /// colour-science's colour of it.
    #[serde(flatten)]
    pub colour: ColourValues,
}

impl MetalsReference {
    /// Loads the reference from `dir`.
    pub fn load(dir: &std::path::Path) -> Result<Self, crate::reference::ReferenceError> {
        crate::reference::load(dir, FILE, SCHEMA)
    }
}

impl Metal {
    /// `(n, κ)` at `wavelength_nm`, interpolated linearly; `None` outside the table.
    pub fn index_at(&self, wavelength_nm: f64) -> Option<(f64, f64)> {
        let n = spectrum::interpolate_linear(&self.wavelengths_nm, &self.n, wavelength_nm)?;
        let k = spectrum::interpolate_linear(&self.wavelengths_nm, &self.kappa, wavelength_nm)?;
        Some((n, k))
    }

    /// `(n, κ)` on the CIE grid; `None` if the table does not cover it.
    pub fn index_on_grid(&self) -> Option<[(f64, f64); SAMPLES]> {
        let mut out = [(0.0, 0.0); SAMPLES];
        for (i, slot) in out.iter_mut().enumerate() {
            *slot = self.index_at(spectrum::wavelength_nm(i))?;
        }
        Some(out)
    }
}

/// The laws the metal study is computed with: a conductor Fresnel law and
/// the colorimetry (parameters, so that broken ones can be injected).
#[derive(Clone, Copy)]
pub struct MetalLaws {
    /// Unpolarised conductor reflectance `(cos_i, n, kappa)`.
    pub conductor: fn(f64, f64, f64) -> f64,
    /// Schlick's approximation `(cos_i, f0)`.
    pub schlick: fn(f64, f64) -> f64,
    /// Normal-incidence reflectance `(n, kappa)`.
    pub f0: fn(f64, f64) -> f64,
    /// The colorimetry.
    pub colour: ColourLaws,
}

impl MetalLaws {
    /// The radiometry crate's.
    pub fn radiometry() -> Self {
        Self {
            conductor: fresnel::conductor,
            schlick: fresnel::schlick,
            f0: fresnel::f0,
            colour: ColourLaws::radiometry(),
        }
    }

    /// The exact reflectance spectrum at `cos_i`.
    pub fn spectrum(&self, index: &[(f64, f64); SAMPLES], cos_i: f64) -> [f64; SAMPLES] {
        index.map(|(n, k)| (self.conductor)(cos_i, n, k))
    }

    /// The colour of three reflectances taken as linear sRGB.
    pub fn rgb_colour(&self, rgb: [f64; 3]) -> ColourValues {
        let xyz = colour::linear_srgb_to_xyz(rgb);
        let lab = (self.colour.xyz_to_lab)(xyz, colour::d65_white());
        ColourValues {
            xyz: [xyz.x, xyz.y, xyz.z],
            linear_srgb: rgb,
            srgb: rgb.map(|c| (self.colour.srgb_encode)(c.clamp(0.0, 1.0))),
            lab: [lab.l, lab.a, lab.b],
        }
    }
}

/// One colour of one metal at one angle, by one method, and its error.
#[derive(Clone, Debug, Serialize)]
pub struct MetalColour {
    /// The metal.
    pub metal: String,
    /// Angle of incidence, degrees.
    pub angle_deg: f64,
    /// `spectral (exact)` or the shortcut's name.
    pub method: String,
    /// Encoded sRGB of the colour (clipped into the gamut), for swatches.
    pub srgb: [f64; 3],
    /// CIELAB.
    pub lab: [f64; 3],
    /// CIEDE2000 from the spectral colour (0 for the spectral colour itself).
    pub delta_e_2000: f64,
}

/// The exact spectral colour of each metal and angle against colour-science.
pub fn check_spectral_colours(laws: &MetalLaws, reference: &MetalsReference) -> Check {
    let mut check = Check::new(
        "colour.colour-science.metals",
        [
            "Exact reflectance spectra of gold, silver, copper, aluminium (Mitsuba's measured n, κ) and their colour",
            "Az arany, az ezüst, a réz és az alumínium pontos visszaverődési spektruma (a Mitsuba mért n, κ értékeivel) és színük",
        ],
        [
            &format!(
                "colour-science {} on mpmath reflectances; indices from Mitsuba {}",
                reference.colour_science_version, reference.mitsuba_version
            ),
            &format!(
                "colour-science {} az mpmath visszaverődési tényezőin; a törésmutatók a Mitsuba {} adatai",
                reference.colour_science_version, reference.mitsuba_version
            ),
        ],
        [&format!(
            "reflectance within {REFLECTANCE_ABS:e}; colour as in the colorimetry check ({:e} XYZ, {:e} CIELAB)",
            colorimetry::XYZ_ABS,
            colorimetry::LAB_ABS
        ), &format!("visszaverődési tényező legfeljebb {REFLECTANCE_ABS:e} eltéréssel; a szín úgy, mint a színmérés ellenőrzésében ({:e} XYZ, {:e} CIELAB)", colorimetry::XYZ_ABS, colorimetry::LAB_ABS)],
    );
    for metal in &reference.metals {
        let Some(index) = metal.index_on_grid() else {
            check.fail(format!(
                "{}: the table does not cover 360–780 nm",
                metal.name
            ));
            continue;
        };
        for angle in &metal.angles {
            let label = format!("{} at {}°", metal.name, angle.angle_deg);
            check.cases += 1;
            let ours = laws.spectrum(&index, angle.cos_i);
            if angle.reflectance.len() != SAMPLES {
                check.fail(format!(
                    "{label}: {} reflectance samples",
                    angle.reflectance.len()
                ));
                continue;
            }
            let worst = ours
                .iter()
                .zip(&angle.reflectance)
                .map(|(a, b)| (a - b).abs())
                .fold(
                    0.0,
                    |m: f64, d| if d.is_nan() { f64::INFINITY } else { m.max(d) },
                );
            check.measure_in_both(
                [
                    "reflectance: max |ours − exact|",
                    "visszaverődési tényező: max |miénk − pontos|",
                ],
                worst,
                &label,
            );
            if !(worst <= REFLECTANCE_ABS) {
                check.fail(format!(
                    "reflectance of {label}: off by {worst:.2e} > {REFLECTANCE_ABS:e}"
                ));
            }
            let colour = colorimetry::colour_of(&laws.colour, &ours);
            colorimetry::compare_colour(&mut check, &label, &colour, &angle.colour);
        }
    }
    check
}

/// Every metal's colour at every reference angle: spectral, then each
/// shortcut with its CIEDE2000 from the spectral colour.
pub fn shortcut_colours(laws: &MetalLaws, reference: &MetalsReference) -> Vec<MetalColour> {
    let mut rows = Vec::new();
    for metal in &reference.metals {
        let Some(index) = metal.index_on_grid() else {
            continue;
        };
        let f0_spectrum = index.map(|(n, k)| (laws.f0)(n, k));
        let f0_rgb = colorimetry::colour_of(&laws.colour, &f0_spectrum)
            .linear_srgb
            .map(|c| c.clamp(0.0, 1.0));
        for angle in &metal.angles {
            let cos_i = angle.cos_i;
            let exact = colorimetry::colour_of(&laws.colour, &laws.spectrum(&index, cos_i));
            let reference_lab = lab(exact.lab);
            let mut push = |method: &str, c: ColourValues| {
                rows.push(MetalColour {
                    metal: metal.name.clone(),
                    angle_deg: angle.angle_deg,
                    method: method.to_owned(),
                    srgb: c.srgb,
                    lab: c.lab,
                    delta_e_2000: (laws.colour.delta_e_2000)(reference_lab, lab(c.lab)),
                });
            };
            push("spectral (exact)", exact.clone());
            if metal.name == "gold" {
                push(
                    "course RGB n, κ (seed 000)",
                    three_channel(laws, cos_i, GOLD_000_N, GOLD_000_KAPPA),
                );
            }
            for (name, nm) in WAVELENGTH_CHOICES {
                let rgb = nm.map(|w| {
                    metal
                        .index_at(w)
                        .map_or(f64::NAN, |(n, k)| (laws.conductor)(cos_i, n, k))
                });
                push(name, laws.rgb_colour(rgb));
            }
            let schlick = f0_spectrum.map(|f0| (laws.schlick)(cos_i, f0));
            push(
                "Schlick, spectral F0",
                colorimetry::colour_of(&laws.colour, &schlick),
            );
            push(
                "Schlick, RGB F0",
                laws.rgb_colour(f0_rgb.map(|f0| (laws.schlick)(cos_i, f0))),
            );
        }
    }
    rows
}

/// The colour of a conductor given as `n, κ` per channel at `cos_i`, as a
/// three-wavelength renderer shows it: the exact law per channel, the
/// three reflectances taken as linear sRGB.
pub fn three_channel(laws: &MetalLaws, cos_i: f64, n: [f64; 3], kappa: [f64; 3]) -> ColourValues {
    laws.rgb_colour(core::array::from_fn(|ch| {
        (laws.conductor)(cos_i, n[ch], kappa[ch])
    }))
}

/// CIEDE2000 of a conductor given as `n, κ` per channel (a scene's metal)
/// against the exact spectral colour of `metal`, at each of the
/// reference's angles: `(angle_deg, ΔE)`, as [`shortcut_colours`] measures
/// the course's gold. `None` where the metal's table does not cover the
/// CIE grid.
pub fn three_channel_delta_e(
    laws: &MetalLaws,
    metal: &Metal,
    n: [f64; 3],
    kappa: [f64; 3],
) -> Option<Vec<(f64, f64)>> {
    let index = metal.index_on_grid()?;
    Some(
        metal
            .angles
            .iter()
            .map(|angle| {
                let exact =
                    colorimetry::colour_of(&laws.colour, &laws.spectrum(&index, angle.cos_i));
                let rgb = three_channel(laws, angle.cos_i, n, kappa);
                let delta_e = (laws.colour.delta_e_2000)(lab(exact.lab), lab(rgb.lab));
                (angle.angle_deg, delta_e)
            })
            .collect(),
    )
}

/// The worst CIEDE2000 of each method over the angles, per metal: the
/// headline table.
pub fn worst_delta_e(rows: &[MetalColour]) -> Vec<(String, String, f64, f64)> {
    let mut out: Vec<(String, String, f64, f64)> = Vec::new();
    for row in rows.iter().filter(|r| r.method != "spectral (exact)") {
        match out
            .iter_mut()
            .find(|(m, s, _, _)| *m == row.metal && *s == row.method)
        {
            Some(entry) if row.delta_e_2000 > entry.2 => {
                entry.2 = row.delta_e_2000;
                entry.3 = row.angle_deg;
            }
            Some(_) => {}
            None => out.push((
                row.metal.clone(),
                row.method.clone(),
                row.delta_e_2000,
                row.angle_deg,
            )),
        }
    }
    out
}
