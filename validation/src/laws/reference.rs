//! The schema of `mitsuba_laws.json`: each case's input, Mitsuba's float32
//! results and the exact values (mpmath, 50 digits).

use serde::Deserialize;

/// The file name of the reference.
pub const FILE: &str = "mitsuba_laws.json";
/// Its schema.
pub const SCHEMA: &str = "mitsuba-laws/1";

/// `mitsuba_laws.json`.
#[derive(Clone, Debug, Deserialize)]
pub struct MitsubaLaws {
    /// Mitsuba's version.
    pub mitsuba_version: String,
    /// Mitsuba's variant (`scalar_rgb`: float32).
    pub mitsuba_variant: String,
    /// Dielectric Fresnel cases.
    pub dielectric: Vec<DielectricCase>,
    /// Conductor Fresnel cases.
    pub conductor: Vec<ConductorCase>,
    /// Reflection and refraction directions.
    pub directions: Vec<DirectionCase>,
    /// Schlick's approximation, tabulated exactly.
    pub schlick: Vec<SchlickCase>,
    /// Mitsuba's reflectance every degree, per material, for the figures.
    pub curves: Vec<Curve>,
}

/// One dielectric Fresnel case.
#[derive(Clone, Debug, Deserialize)]
pub struct DielectricCase {
    /// Where on the grid.
    pub label: String,
    /// Signed cosine (float32 value).
    pub cos_i: f64,
    /// `n_inside / n_outside` (float32 value).
    pub eta: f64,
    /// Mitsuba's results.
    pub mitsuba: MitsubaDielectric,
    /// The exact values.
    pub exact: ExactDielectric,
}

/// `mi.fresnel` and `mi.fresnel_polarized` at one input.
#[derive(Clone, Debug, Deserialize)]
pub struct MitsubaDielectric {
    /// Unpolarised reflectance.
    pub f: f64,
    /// Signed transmitted cosine (0 under TIR).
    pub cos_t: f64,
    /// Relative index along the path.
    pub eta_it: f64,
    /// Its reciprocal.
    pub eta_ti: f64,
    /// Complex s amplitude `[re, im]`.
    pub a_s: [f64; 2],
    /// Complex p amplitude `[re, im]` (Fresnel's 1823 sign).
    pub a_p: [f64; 2],
}

/// The exact dielectric reflectances.
#[derive(Clone, Debug, Deserialize)]
pub struct ExactDielectric {
    /// s-polarised reflectance.
    pub r_s: f64,
    /// p-polarised reflectance.
    pub r_p: f64,
    /// Unpolarised reflectance.
    pub r: f64,
    /// Total internal reflection.
    pub tir: bool,
}

/// One conductor Fresnel case.
#[derive(Clone, Debug, Deserialize)]
pub struct ConductorCase {
    /// Where on the grid.
    pub label: String,
    /// Cosine (float32 value), light from outside.
    pub cos_i: f64,
    /// Real part of the index.
    pub n: f64,
    /// Extinction coefficient.
    pub kappa: f64,
    /// Mitsuba's results.
    pub mitsuba: MitsubaConductor,
    /// The exact values.
    pub exact: ExactConductor,
}

/// `mi.fresnel_conductor` and complex `mi.fresnel_polarized` at one input.
#[derive(Clone, Debug, Deserialize)]
pub struct MitsubaConductor {
    /// Unpolarised reflectance.
    pub f: f64,
    /// Complex s amplitude.
    pub a_s: [f64; 2],
    /// Complex p amplitude.
    pub a_p: [f64; 2],
}

/// The exact conductor reflectances.
#[derive(Clone, Debug, Deserialize)]
pub struct ExactConductor {
    /// s-polarised.
    pub r_s: f64,
    /// p-polarised.
    pub r_p: f64,
    /// Unpolarised.
    pub r: f64,
}

/// One reflection/refraction case.
#[derive(Clone, Debug, Deserialize)]
pub struct DirectionCase {
    /// Where on the grid.
    pub label: String,
    /// Incident direction, pointing away from the surface (float32 values).
    pub wi: [f64; 3],
    /// Normal, pointing outside.
    pub n: [f64; 3],
    /// `n_inside / n_outside`.
    pub eta: f64,
    /// Mitsuba's directions.
    pub mitsuba: MitsubaDirections,
    /// The exact directions.
    pub exact: ExactDirections,
}

/// `mi.reflect` and `mi.refract`.
#[derive(Clone, Debug, Deserialize)]
pub struct MitsubaDirections {
    /// Mirror direction.
    pub reflect: [f64; 3],
    /// Refracted direction (meaningless under TIR, where `cos_t = 0`).
    pub refract: [f64; 3],
    /// Signed transmitted cosine from `mi.fresnel`.
    pub cos_t: f64,
}

/// The exact directions.
#[derive(Clone, Debug, Deserialize)]
pub struct ExactDirections {
    /// Mirror direction.
    pub reflect: [f64; 3],
    /// Refracted direction, `None` under TIR.
    pub refract: Option<[f64; 3]>,
}

/// One tabulated value of Schlick's approximation.
#[derive(Clone, Debug, Deserialize)]
pub struct SchlickCase {
    /// Where on the grid.
    pub label: String,
    /// Cosine.
    pub cos_i: f64,
    /// Normal-incidence reflectance.
    pub f0: f64,
    /// `F0 + (1 − F0)(1 − cos)⁵`, exactly.
    pub exact: f64,
}

/// Mitsuba's reflectance of one material at every degree.
#[derive(Clone, Debug, Deserialize)]
pub struct Curve {
    /// The material and side.
    pub label: String,
    /// Real index (relative).
    pub n: f64,
    /// Extinction coefficient (0 for dielectrics).
    pub kappa: f64,
    /// Signed cosines, one per degree from 0° to 90°.
    pub cos_i: Vec<f64>,
    /// Mitsuba's unpolarised reflectance there.
    pub mitsuba_f: Vec<f64>,
}

impl MitsubaLaws {
    /// Loads the reference from `dir`.
    pub fn load(dir: &std::path::Path) -> Result<Self, crate::reference::ReferenceError> {
        crate::reference::load(dir, FILE, SCHEMA)
    }

    /// The reference and its version, `[English, Hungarian]`.
    pub(super) fn version(&self) -> [String; 2] {
        let (version, variant) = (&self.mitsuba_version, &self.mitsuba_variant);
        [
            format!("Mitsuba {version} ({variant}, float32) and mpmath exact values"),
            format!("Mitsuba {version} ({variant}, float32) és az mpmath pontos értékei"),
        ]
    }
}
