//! The laws against Mitsuba 3 and the exact values, in float32.
//!
//! Reference: `validation/reference/mitsuba_laws.json` (schema
//! `mitsuba-laws/1`), written by `python-checks/mitsuba_laws.py`. Each case
//! holds Mitsuba's float32 result and the exact value (mpmath, 50 digits) at
//! the same float32 input. The laws under test are a parameter ([`Laws`]) so
//! that a deliberately broken law can be checked to be caught.
//!
//! # Tolerances, and who is wrong
//!
//! - **Ours against the exact value**: [`OURS_ULPS`] f32 ulps for reflectances
//!   (the radiometry crate's f32 tier is measured within 6 ulps of 50-digit
//!   references, see `tests/fresnel_reference.rs`), and [`DIRECTION_ABS`] per
//!   component for unit directions. Beyond that is a **failure**.
//! - **Mitsuba against the exact value**: Mitsuba evaluates the textbook
//!   formulas in float32. Each of its roughly ten roundings is at most half an
//!   ulp of an intermediate of order one, so away from cancellations its
//!   error is a few `f32::EPSILON` in absolute terms; [`MITSUBA_ABS`]
//!   (16 ε₃₂ ≈ 1.9e-6) bounds that. A larger deviation, with ours within its
//!   own bound, is a **finding** about Mitsuba: it happens where the textbook
//!   form cancels (near the critical angle, `1 − sin²θ_t`; near `η = 1`).
//! - **Ours against Mitsuba, grossly**: even through that cancellation,
//!   float32 rounding moves a reflectance by at most about `√ε₃₂ ≈ 3.5e-4`
//!   (the square root of an absolute error of ε₃₂ in `cos²θ_t`). A difference
//!   beyond [`GROSS_ABS`] (1e-3) is a convention or a law that differs, not
//!   rounding, and is a **failure** even if our mpmath reference agrees with
//!   us: Mitsuba is the check on the reference itself.

use glam::Vec3;
use radiometry::fresnel::{self, ConductorFresnel, DielectricFresnel};
use radiometry::snell;
use radiometry::specular::{self, Refraction};
use serde::Deserialize;

use crate::check::{ulps_f32, Check};

/// Our reflectances against the exact value: f32 ulps of the exact value.
pub const OURS_ULPS: f64 = 8.0;
/// Our unit directions against the exact ones, per component: 8 ulps of 1.
pub const DIRECTION_ABS: f64 = 8.0 * f32::EPSILON as f64;
/// The extra allowance for a refracted direction near the critical angle,
/// per component.
///
/// A law that takes `wi` and `n` computes `cos θ_i = n·wi` itself, in float32,
/// off by up to about 2 ε₃₂; the transmitted direction
/// `t = −wi/η + (cos θ_i/η − cos θ_t) n` moves with it at the rate
/// `|1/η − cos θ_i / (η² cos θ_t)|`, which grows without bound as
/// `cos θ_t → 0`. There the square root caps it instead: the discriminant
/// `η²cos²θ_t = η² − sin²θ_i` moves by at most `2 cos θ_i · 2ε₃₂ ≤ 4ε₃₂`, so
/// `cos θ_t` moves by at most `2√ε₃₂ / η`, and the other terms by `2ε₃₂ / η`.
/// The allowance is the smaller of the two bounds. `cos_i = |n·wi|`,
/// `eta_path` the effective `n_t / n_i` (written η above), `cos_t` the exact
/// transmitted cosine.
pub fn refraction_allowance(cos_i: f64, eta_path: f64, cos_t: f64) -> f64 {
    let eps = f64::from(f32::EPSILON);
    let eta = eta_path;
    let linear = 2.0 * eps * (1.0 / eta - cos_i / (eta * eta * cos_t)).abs();
    let root = (2.0 * eps.sqrt() + 2.0 * eps) / eta;
    linear.min(root)
}

/// [`refraction_allowance`] from the input and the exact refracted direction.
pub fn refraction_allowance_at(wi: [f64; 3], n: [f64; 3], eta: f64, refracted: [f64; 3]) -> f64 {
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let cos_i = dot(wi, n);
    let eta_path =
        radiometry::snell::Incidence::resolve(cos_i, eta).map_or(f64::NAN, |i| i.eta_path());
    refraction_allowance(cos_i.abs(), eta_path, dot(refracted, n).abs())
}

/// Mitsuba's float32 textbook evaluation against the exact value, absolute.
pub const MITSUBA_ABS: f64 = 16.0 * f32::EPSILON as f64;
/// A disagreement with Mitsuba no float32 rounding explains, absolute.
pub const GROSS_ABS: f64 = 1e-3;

/// The file name of the reference.
pub const FILE: &str = "mitsuba_laws.json";
/// Its schema.
pub const SCHEMA: &str = "mitsuba-laws/1";

/// The laws under test, in float32: the radiometry crate's by default
/// ([`Laws::radiometry`]), or deliberately broken ones in the fault-injection
/// tests.
#[derive(Clone, Copy)]
pub struct Laws {
    /// Exact dielectric Fresnel, `(cos_i, eta)`, either side.
    pub dielectric: fn(f32, f32) -> DielectricFresnel<f32>,
    /// Exact conductor Fresnel, `(cos_i, n, kappa)`.
    pub conductor: fn(f32, f32, f32) -> ConductorFresnel<f32>,
    /// Mirror direction, `(w, n)`.
    pub reflect: fn(Vec3, Vec3) -> Vec3,
    /// Refracted direction, `(wi, n, eta)`; `None` under TIR.
    pub refract: fn(Vec3, Vec3, f32) -> Option<Refraction<Vec3>>,
    /// Schlick's approximation, `(cos_i, f0)`.
    pub schlick: fn(f32, f32) -> f32,
    /// Snell's law for angles, `(theta_i, eta_path)`; `None` under TIR.
    pub transmitted_angle: fn(f32, f32) -> Option<f32>,
    /// The critical angle, `eta_path`.
    pub critical_angle: fn(f32) -> Option<f32>,
    /// Brewster's angle, `eta_path`.
    pub brewster_angle: fn(f32) -> Option<f32>,
}

impl Laws {
    /// The radiometry crate's laws.
    pub fn radiometry() -> Self {
        Self {
            dielectric: fresnel::dielectric_polarized,
            conductor: fresnel::conductor_polarized,
            reflect: specular::reflect,
            refract: specular::refract,
            schlick: fresnel::schlick,
            transmitted_angle: snell::transmitted_angle,
            critical_angle: snell::critical_angle,
            brewster_angle: snell::brewster_angle,
        }
    }
}

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
    pub fn load(dir: &std::path::Path) -> Result<Self, crate::ReferenceError> {
        crate::reference::load(dir, FILE, SCHEMA)
    }

    fn version(&self) -> String {
        format!(
            "Mitsuba {} ({}, float32) and mpmath exact values",
            self.mitsuba_version, self.mitsuba_variant
        )
    }
}

fn power(amplitude: [f64; 2]) -> f64 {
    amplitude[0] * amplitude[0] + amplitude[1] * amplitude[1]
}

fn vec3(v: [f64; 3]) -> Vec3 {
    Vec3::new(v[0] as f32, v[1] as f32, v[2] as f32)
}

/// Compares one scalar quantity three ways (see the module docs) and records
/// the outcome in `check`.
fn compare_scalar(
    check: &mut Check,
    quantity: &str,
    label: &str,
    ours: f64,
    mitsuba: f64,
    exact: f64,
) {
    let ours_ulps = ulps_f32(ours, exact);
    let mitsuba_err = (mitsuba - exact).abs();
    let disagreement = (ours - mitsuba).abs();
    check.measure(
        &format!("{quantity}: |ours − exact| (f32 ulps)"),
        ours_ulps,
        label,
    );
    check.measure(
        &format!("{quantity}: |Mitsuba − exact|"),
        mitsuba_err,
        label,
    );
    check.measure(
        &format!("{quantity}: |ours − Mitsuba|"),
        disagreement,
        label,
    );
    if !(ours_ulps <= OURS_ULPS) {
        check.fail(format!(
            "{quantity} at {label}: ours {ours:e}, exact {exact:e} ({ours_ulps:.1} ulps > {OURS_ULPS})"
        ));
    }
    if !(disagreement <= GROSS_ABS) {
        check.fail(format!(
            "{quantity} at {label}: ours {ours:e}, Mitsuba {mitsuba:e} differ by {disagreement:.2e} > {GROSS_ABS:e}"
        ));
    } else if mitsuba_err > MITSUBA_ABS && ours_ulps <= OURS_ULPS {
        check.find(format!(
            "Mitsuba {quantity} at {label}: {mitsuba:e}, exact {exact:e} (off by {mitsuba_err:.2e}, {:.0} f32 ulps)",
            ulps_f32(mitsuba, exact)
        ));
    }
}

/// `mi.fresnel` and `mi.fresnel_polarized` (real index) against ours and the exact law.
pub fn check_dielectric(laws: &Laws, reference: &MitsubaLaws) -> Check {
    let mut check = Check::new(
        "laws.mitsuba.fresnel_dielectric",
        "Dielectric Fresnel R, R_s, R_p, both sides, normal to grazing, TIR",
        &reference.version(),
        &format!(
            "ours within {OURS_ULPS} f32 ulps of exact; Mitsuba beyond {MITSUBA_ABS:.1e} of exact is a finding; ours and Mitsuba within {GROSS_ABS:e}"
        ),
    );
    for case in &reference.dielectric {
        let ours = (laws.dielectric)(case.cos_i as f32, case.eta as f32);
        let label = &case.label;
        check.cases += 1;
        if ours.is_total_internal_reflection() != case.exact.tir {
            check.fail(format!(
                "{label}: total internal reflection {} but exactly {}",
                ours.is_total_internal_reflection(),
                case.exact.tir
            ));
        }
        // Mitsuba signals TIR by cos_t = 0, which index-matched grazing light also gives.
        let mitsuba_tir = case.mitsuba.cos_t == 0.0 && case.eta != 1.0;
        if mitsuba_tir != case.exact.tir {
            check.find(format!(
                "Mitsuba at {label}: total internal reflection {mitsuba_tir} but exactly {}",
                case.exact.tir
            ));
        }
        let m = &case.mitsuba;
        compare_scalar(
            &mut check,
            "R",
            label,
            ours.reflectance().into(),
            m.f,
            case.exact.r,
        );
        compare_scalar(
            &mut check,
            "R_s",
            label,
            ours.r_s.into(),
            power(m.a_s),
            case.exact.r_s,
        );
        compare_scalar(
            &mut check,
            "R_p",
            label,
            ours.r_p.into(),
            power(m.a_p),
            case.exact.r_p,
        );
        // The effective index along the path is a convention, not a rounding.
        if (f64::from(ours.eta_path()) - m.eta_it).abs() > 1e-6 * m.eta_it {
            check.fail(format!(
                "{label}: eta along the path {} but Mitsuba's eta_it is {}",
                ours.eta_path(),
                m.eta_it
            ));
        }
    }
    check
}

/// `mi.fresnel_conductor` and complex `mi.fresnel_polarized` against ours and the exact law.
pub fn check_conductor(laws: &Laws, reference: &MitsubaLaws) -> Check {
    let mut check = Check::new(
        "laws.mitsuba.fresnel_conductor",
        "Conductor Fresnel R, R_s, R_p (n + iκ), normal to grazing",
        &reference.version(),
        &format!(
            "ours within {OURS_ULPS} f32 ulps of exact; Mitsuba beyond {MITSUBA_ABS:.1e} of exact is a finding; ours and Mitsuba within {GROSS_ABS:e}"
        ),
    );
    for case in &reference.conductor {
        let ours = (laws.conductor)(case.cos_i as f32, case.n as f32, case.kappa as f32);
        let (label, m, e) = (&case.label, &case.mitsuba, &case.exact);
        check.cases += 1;
        compare_scalar(&mut check, "R", label, ours.reflectance().into(), m.f, e.r);
        compare_scalar(
            &mut check,
            "R_s",
            label,
            ours.r_s.into(),
            power(m.a_s),
            e.r_s,
        );
        compare_scalar(
            &mut check,
            "R_p",
            label,
            ours.r_p.into(),
            power(m.a_p),
            e.r_p,
        );
    }
    check
}

/// `mi.reflect` and `mi.refract` against ours and the exact directions.
pub fn check_directions(laws: &Laws, reference: &MitsubaLaws) -> Check {
    let mut check = Check::new(
        "laws.mitsuba.directions",
        "Mirror and refracted directions, both sides, tilted normals, TIR",
        &reference.version(),
        &format!(
            "ours within {DIRECTION_ABS:.1e} of exact per component, plus the refraction_allowance for the conditioning near the critical angle; Mitsuba beyond {MITSUBA_ABS:.1e} is a finding; ours and Mitsuba within {GROSS_ABS:e}"
        ),
    );
    for case in &reference.directions {
        let (wi, n, label) = (vec3(case.wi), vec3(case.n), &case.label);
        check.cases += 1;
        let reflected = (laws.reflect)(wi, n);
        compare_direction(
            &mut check,
            "reflect",
            label,
            reflected,
            case.mitsuba.reflect,
            case.exact.reflect,
            0.0,
        );
        let refracted = (laws.refract)(wi, n, case.eta as f32);
        match (refracted, case.exact.refract) {
            (Some(ours), Some(exact)) => {
                let allowance = laws_allowance(case, exact);
                compare_direction(
                    &mut check,
                    "refract",
                    label,
                    ours.direction,
                    case.mitsuba.refract,
                    exact,
                    allowance,
                )
            }
            (None, None) => {
                if case.mitsuba.cos_t != 0.0 {
                    check.find(format!(
                        "Mitsuba at {label}: refracts under total internal reflection"
                    ));
                }
            }
            (ours, exact) => check.fail(format!(
                "{label}: refraction {} but exactly {}",
                if ours.is_some() { "exists" } else { "is TIR" },
                if exact.is_some() { "exists" } else { "is TIR" }
            )),
        }
    }
    check
}

fn laws_allowance(case: &DirectionCase, exact: [f64; 3]) -> f64 {
    refraction_allowance_at(case.wi, case.n, case.eta, exact)
}

fn compare_direction(
    check: &mut Check,
    law: &str,
    label: &str,
    ours: Vec3,
    mitsuba: [f64; 3],
    exact: [f64; 3],
    allowance: f64,
) {
    let ours = ours.to_array().map(f64::from);
    let err = |v: [f64; 3]| (0..3).map(|i| (v[i] - exact[i]).abs()).fold(0.0, f64::max);
    let (ours_err, mitsuba_err) = (err(ours), err(mitsuba));
    let disagreement = (0..3)
        .map(|i| (ours[i] - mitsuba[i]).abs())
        .fold(0.0, f64::max);
    check.measure(
        &format!("{law}: max |ours − exact| per component"),
        ours_err,
        label,
    );
    check.measure(
        &format!("{law}: max |Mitsuba − exact| per component"),
        mitsuba_err,
        label,
    );
    check.measure(
        &format!("{law}: max |ours − Mitsuba| per component"),
        disagreement,
        label,
    );
    let bound = DIRECTION_ABS + allowance;
    if !(ours_err <= bound) {
        check.fail(format!(
            "{law} at {label}: ours {ours:?}, exact {exact:?} (off by {ours_err:.2e} > {bound:.1e})"
        ));
    }
    if !(disagreement <= GROSS_ABS) {
        check.fail(format!(
            "{law} at {label}: ours {ours:?}, Mitsuba {mitsuba:?} differ by {disagreement:.2e}"
        ));
    } else if mitsuba_err > MITSUBA_ABS + allowance && ours_err <= bound {
        check.find(format!(
            "Mitsuba {law} at {label}: off the exact direction by {mitsuba_err:.2e}"
        ));
    }
}

/// Schlick's approximation against its exact definition (Mitsuba has no
/// binding for it, so this is a check of the formula, not of a renderer).
pub fn check_schlick(laws: &Laws, reference: &MitsubaLaws) -> Check {
    let mut check = Check::new(
        "laws.mpmath.schlick",
        "Schlick's approximation F0 + (1 − F0)(1 − cos)⁵ against its definition",
        "mpmath, 50 digits",
        &format!("within {OURS_ULPS} f32 ulps: five products and a sum, each rounded once"),
    );
    for case in &reference.schlick {
        let ours: f64 = (laws.schlick)(case.cos_i as f32, case.f0 as f32).into();
        let ulps = ulps_f32(ours, case.exact);
        check.cases += 1;
        check.measure("|ours − exact| (f32 ulps)", ulps, &case.label);
        if !(ulps <= OURS_ULPS) {
            check.fail(format!(
                "{}: ours {ours:e}, exact {:e} ({ulps:.1} ulps)",
                case.label, case.exact
            ));
        }
    }
    check
}

/// Every law check against `mitsuba_laws.json`.
pub fn check_all(laws: &Laws, reference: &MitsubaLaws) -> Vec<Check> {
    vec![
        check_dielectric(laws, reference),
        check_conductor(laws, reference),
        check_directions(laws, reference),
        check_schlick(laws, reference),
    ]
}
