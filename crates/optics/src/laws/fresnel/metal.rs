//! Metals by name, for `optics fresnel --metal`: the course's gold as its
//! shader writes it, and four measured metals read at one wavelength per
//! RGB channel.
//!
//! The measured indices are those `validation/reference/metals.json` holds
//! (Mitsuba's tabulated `n + iκ`, written by `python-checks/metals.py`),
//! compiled in and read at [`RGB_WAVELENGTHS_NM`]; a test holds them to the
//! harness's own reading of the same file.

use std::sync::OnceLock;

use radiometry::course::{GOLD_000_KAPPA, GOLD_000_N};
use radiometry::spectrum::{interpolate_linear, RGB_WAVELENGTHS_NM};
use record::{say, Lang};
use serde::{Deserialize, Serialize};

/// A metal `optics fresnel --metal` knows by name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum, Deserialize, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum MetalName {
    /// The course's gold, `n = (0.17, 0.35, 1.5)`, `κ = (3.1, 2.7, 1.9)` (seed `000`).
    CourseGold,
    /// Gold, measured.
    Gold,
    /// Silver, measured.
    Silver,
    /// Copper, measured.
    Copper,
    /// Aluminium, measured.
    Aluminium,
}

/// A metal's complex index per RGB channel, red first.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Channels {
    /// Real part, per channel.
    pub n: [f64; 3],
    /// Extinction coefficient, per channel.
    pub kappa: [f64; 3],
}

impl MetalName {
    /// The name in the measured table (`metals.json`); `None` for the
    /// course's gold, which the course gives per channel.
    pub fn measured_name(self) -> Option<&'static str> {
        match self {
            MetalName::CourseGold => None,
            MetalName::Gold => Some("gold"),
            MetalName::Silver => Some("silver"),
            MetalName::Copper => Some("copper"),
            MetalName::Aluminium => Some("aluminium"),
        }
    }

    /// The index per channel.
    pub fn channels(self) -> Channels {
        let Some(name) = self.measured_name() else {
            return Channels {
                n: GOLD_000_N,
                kappa: GOLD_000_KAPPA,
            };
        };
        let metal = measured()
            .iter()
            .find(|m| m.name == name)
            .expect("every measured metal is in metals.json (tested)");
        let at = |values: &[f64], nm: f64| {
            interpolate_linear(&metal.wavelengths_nm, values, nm)
                .expect("metals.json covers the RGB wavelengths (tested)")
        };
        Channels {
            n: RGB_WAVELENGTHS_NM.map(|nm| at(&metal.n, nm)),
            kappa: RGB_WAVELENGTHS_NM.map(|nm| at(&metal.kappa, nm)),
        }
    }

    /// The metal's name in words.
    pub fn word(self, lang: Lang) -> &'static str {
        match self {
            MetalName::CourseGold => lang.pick("the course's gold", "a kurzus aranya"),
            MetalName::Gold => lang.pick("gold", "arany"),
            MetalName::Silver => lang.pick("silver", "ezüst"),
            MetalName::Copper => lang.pick("copper", "réz"),
            MetalName::Aluminium => lang.pick("aluminium", "alumínium"),
        }
    }

    /// Where the index comes from, in words.
    pub fn source(self, lang: Lang) -> String {
        let [r, g, b] = RGB_WAVELENGTHS_NM;
        match self {
            MetalName::CourseGold => lang
                .pick(
                    "the course's gold, as its shader gives it (000, lines 1385–1386)",
                    "a kurzus aranya, ahogy a shadere megadja (000, 1385–1386. sor)",
                )
                .to_owned(),
            _ => say!(
                lang,
                "measured (Mitsuba's table), read at {r}, {g} and {b} nm",
                "mért érték (a Mitsuba táblázata), {r}, {g} és {b} nm-en"
            ),
        }
    }
}

/// One measured metal, as `metals.json` tabulates it.
#[derive(Deserialize)]
struct Measured {
    name: String,
    wavelengths_nm: Vec<f64>,
    n: Vec<f64>,
    kappa: Vec<f64>,
}

#[derive(Deserialize)]
struct Table {
    metals: Vec<Measured>,
}

/// The measured metals, read once.
fn measured() -> &'static [Measured] {
    static TABLE: OnceLock<Vec<Measured>> = OnceLock::new();
    TABLE.get_or_init(|| {
        let text = include_str!("../../../../../validation/reference/metals.json");
        serde_json::from_str::<Table>(text)
            .expect("metals.json parses (tested)")
            .metals
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::ValueEnum;

    /// Every named metal has an index per channel, finite, `κ > 0`: a
    /// conductor.
    #[test]
    fn every_named_metal_is_a_conductor_in_each_channel() {
        for metal in MetalName::value_variants() {
            let c = metal.channels();
            for i in 0..3 {
                assert!(c.n[i] > 0.0 && c.n[i].is_finite(), "{metal:?} n");
                assert!(c.kappa[i] > 0.0 && c.kappa[i].is_finite(), "{metal:?} κ");
            }
        }
    }

    /// The measured channels are the harness's own reading of the same
    /// table at the same wavelengths, to the bit.
    #[cfg(feature = "harness")]
    #[test]
    fn measured_channels_are_the_references_index_at_the_rgb_wavelengths() {
        let dir =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../validation/reference");
        let reference = validation::metals::MetalsReference::load(&dir).expect("metals.json");
        for metal in MetalName::value_variants() {
            let Some(name) = metal.measured_name() else {
                continue;
            };
            let m = reference.metals.iter().find(|m| m.name == name).unwrap();
            let c = metal.channels();
            for (i, nm) in RGB_WAVELENGTHS_NM.into_iter().enumerate() {
                assert_eq!(
                    m.index_at(nm),
                    Some((c.n[i], c.kappa[i])),
                    "{name} at {nm} nm"
                );
            }
        }
    }
}
