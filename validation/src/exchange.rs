//! Cases the Rust side exports for a reference tool to evaluate, and the
//! results it hands back: the laws at random inputs against Mitsuba 3.
//!
//! The committed references cover chosen grids; this adds inputs nobody
//! chose. `optics validate` draws [`random_cases`] from a seeded generator,
//! writes them as `cases.json` (schema `law-cases/1`), runs
//! `python-checks/mitsuba_eval.py` on them, reads back `results.json`
//! (schema `law-results/1`: Mitsuba's outputs, one per case, in order) and
//! compares with [`check_random`].
//!
//! The radiometry crate's `f64` laws stand in for the exact values here:
//! they are within 8 `f64` ulps of 50-digit references (check
//! `laws.mpmath.*`), eight orders of magnitude below the `f32` tolerances.
//! The tolerances and the rule separating failures from findings are those
//! of [`crate::laws`].

use glam::{DVec3, Vec3};
use serde::{Deserialize, Serialize};

use crate::check::{ulps_f32, Check};
use crate::laws::{
    refraction_allowance_at, Laws, Laws64, DIRECTION_ABS, GROSS_ABS, MITSUBA_ABS, OURS_ULPS,
};


/// The schema of the exported cases.
pub const CASES_SCHEMA: &str = "law-cases/1";
/// The schema of the results.
pub const RESULTS_SCHEMA: &str = "law-results/1";

/// One input to one law. Every number is a float32 value (stored exactly as
/// a double), so both sides evaluate at the same point.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "law", rename_all = "snake_case")]
pub enum LawCase {
    /// `mi.fresnel(cos_i, eta)`.
    Fresnel {
        /// Signed cosine.
        cos_i: f64,
        /// `n_inside / n_outside`.
        eta: f64,
    },
    /// `mi.fresnel_conductor(cos_i, n + iκ)`.
    FresnelConductor {
        /// Cosine, light from outside.
        cos_i: f64,
        /// Real index.
        n: f64,
        /// Extinction coefficient.
        kappa: f64,
    },
    /// `mi.reflect(wi, n)` and `mi.refract(wi, n, cos_t, eta_ti)` with the
    /// last two from `mi.fresnel(dot(wi, n), eta)`.
    Directions {
        /// Incident direction, away from the surface.
        wi: [f64; 3],
        /// Normal, outside.
        n: [f64; 3],
        /// `n_inside / n_outside`.
        eta: f64,
    },
}

/// `cases.json`.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct CasesFile {
    /// [`CASES_SCHEMA`].
    pub schema: String,
    /// The seed the cases were drawn with.
    pub seed: u64,
    /// The cases.
    pub cases: Vec<LawCase>,
}

/// Mitsuba's outputs for one case (the fields its law returns).
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct LawResult {
    /// Reflectance (`fresnel`, `fresnel_conductor`).
    #[serde(default)]
    pub f: Option<f64>,
    /// Signed transmitted cosine (`fresnel`, `directions`), 0 under TIR.
    #[serde(default)]
    pub cos_t: Option<f64>,
    /// Mirror direction (`directions`).
    #[serde(default)]
    pub reflect: Option<[f64; 3]>,
    /// Refracted direction (`directions`).
    #[serde(default)]
    pub refract: Option<[f64; 3]>,
}

/// `results.json`.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ResultsFile {
    /// [`RESULTS_SCHEMA`].
    pub schema: String,
    /// The tool and its version.
    pub evaluator: String,
    /// One result per case, in the order of the cases.
    pub results: Vec<LawResult>,
}

/// SplitMix64 (Steele, Lea & Flood, OOPSLA 2014): a small, well-mixed,
/// reproducible generator; the cases depend only on the seed.
struct SplitMix64(u64);

impl SplitMix64 {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in `[lo, hi)`.
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        let unit = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * unit
    }

    /// A uniformly distributed unit vector (Marsaglia's method via z and φ).
    fn unit_vector(&mut self) -> DVec3 {
        let z = self.uniform(-1.0, 1.0);
        let phi = self.uniform(0.0, std::f64::consts::TAU);
        let r = (1.0 - z * z).sqrt();
        DVec3::new(r * phi.cos(), r * phi.sin(), z)
    }
}

fn f32_exact(x: f64) -> f64 {
    f64::from(x as f32)
}

fn f32_vector(v: DVec3) -> [f64; 3] {
    v.to_array().map(f32_exact)
}

/// `count` cases of each law at random inputs: cosines uniform over both
/// sides, `eta` log-uniform in `[1/3, 3]`, `n` in `[0.05, 3]`, `κ` in
/// `[0, 10]`, directions and normals uniform on the sphere.
pub fn random_cases(seed: u64, count: usize) -> CasesFile {
    let mut rng = SplitMix64(seed);
    let mut cases = Vec::with_capacity(3 * count);
    let eta = |rng: &mut SplitMix64| f32_exact(3f64.powf(rng.uniform(-1.0, 1.0)));
    for _ in 0..count {
        let e = eta(&mut rng);
        cases.push(LawCase::Fresnel {
            cos_i: f32_exact(rng.uniform(-1.0, 1.0)),
            eta: e,
        });
        cases.push(LawCase::FresnelConductor {
            cos_i: f32_exact(rng.uniform(0.0, 1.0)),
            n: f32_exact(rng.uniform(0.05, 3.0)),
            kappa: f32_exact(rng.uniform(0.0, 10.0)),
        });
        let e = eta(&mut rng);
        cases.push(LawCase::Directions {
            wi: f32_vector(rng.unit_vector()),
            n: f32_vector(rng.unit_vector()),
            eta: e,
        });
    }
    CasesFile {
        schema: CASES_SCHEMA.to_owned(),
        seed,
        cases,
    }
}

fn vec3(v: [f64; 3]) -> Vec3 {
    Vec3::new(v[0] as f32, v[1] as f32, v[2] as f32)
}

fn max_abs(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|i| (a[i] - b[i]).abs()).fold(
        0.0,
        |m, d| if d.is_nan() { f64::INFINITY } else { m.max(d) },
    )
}

/// Compares our `f32` laws with Mitsuba and with our `f64` laws at every
/// exported case.
pub fn check_random(
    laws: &Laws,
    laws64: &Laws64,
    cases: &CasesFile,
    results: &ResultsFile,
) -> Check {
    let mut check = Check::new(
        "laws.mitsuba.random",
        "Fresnel (dielectric, conductor), reflection and refraction at random inputs exported by the harness",
        &format!("{} on cases.json (seed {})", results.evaluator, cases.seed),
        &format!(
            "ours (f32) within {OURS_ULPS} f32 ulps of our f64 law (itself within 8 f64 ulps of exact), directions within {DIRECTION_ABS:.1e} plus the refraction allowance near the critical angle; Mitsuba beyond {MITSUBA_ABS:.1e} is a finding; ours and Mitsuba within {GROSS_ABS:e}"
        ),
    );
    if cases.cases.len() != results.results.len() {
        check.fail(format!(
            "{} cases but {} results",
            cases.cases.len(),
            results.results.len()
        ));
        return check;
    }
    for (i, (case, result)) in cases.cases.iter().zip(&results.results).enumerate() {
        check.cases += 1;
        let label = format!(
            "case {i}: {}",
            serde_json::to_string(case).unwrap_or_default()
        );
        compare_case(&mut check, laws, laws64, &label, case, result);
    }
    check
}

/// One exported case: ours (`f32`) against Mitsuba and our `f64` law.
fn compare_case(
    check: &mut Check,
    laws: &Laws,
    laws64: &Laws64,
    label: &str,
    case: &LawCase,
    result: &LawResult,
) {
    match *case {
        LawCase::Fresnel { cos_i, eta } => {
            let ours = (laws.dielectric)(cos_i as f32, eta as f32);
            let exact = (laws64.dielectric)(cos_i, eta);
            if ours.is_total_internal_reflection() != exact.is_total_internal_reflection() {
                check.fail(format!(
                    "{label}: total internal reflection differs between f32 and f64"
                ));
            }
            scalar(
                check,
                "fresnel R",
                label,
                ours.reflectance().into(),
                result.f,
                exact.reflectance(),
            );
        }
        LawCase::FresnelConductor { cos_i, n, kappa } => {
            let ours = (laws.conductor)(cos_i as f32, n as f32, kappa as f32);
            let exact = (laws64.conductor)(cos_i, n, kappa);
            scalar(
                check,
                "fresnel_conductor R",
                label,
                ours.reflectance().into(),
                result.f,
                exact.reflectance(),
            );
        }
        LawCase::Directions { wi, n, eta } => {
            compare_directions(check, laws, laws64, label, (wi, n, eta), result)
        }
    }
}

/// One exported direction case: the mirror and the refracted direction.
fn compare_directions(
    check: &mut Check,
    laws: &Laws,
    laws64: &Laws64,
    label: &str,
    (wi, n, eta): ([f64; 3], [f64; 3], f64),
    result: &LawResult,
) {
    let (wi64, n64) = (DVec3::from_array(wi), DVec3::from_array(n));
    let ours = (laws.reflect)(vec3(wi), vec3(n)).to_array().map(f64::from);
    let exact = (laws64.reflect)(wi64, n64).to_array();
    direction(check, "reflect", label, ours, result.reflect, exact, 0.0);
    let ours = (laws.refract)(vec3(wi), vec3(n), eta as f32);
    let exact = (laws64.refract)(wi64, n64, eta);
    match (ours, exact) {
        (Some(o), Some(e)) => {
            let exact = e.direction.to_array();
            let allowance = refraction_allowance_at(wi, n, eta, exact);
            let ours = o.direction.to_array().map(f64::from);
            direction(
                check,
                "refract",
                label,
                ours,
                result.refract,
                exact,
                allowance,
            )
        }
        (None, None) => {
            if result.cos_t.is_some_and(|c| c != 0.0) {
                check.find(format!(
                    "Mitsuba at {label}: refracts under total internal reflection"
                ));
            }
        }
        _ => check.fail(format!(
            "{label}: total internal reflection differs between f32 and f64"
        )),
    }
}

fn scalar(check: &mut Check, law: &str, label: &str, ours: f64, mitsuba: Option<f64>, exact: f64) {
    let ulps = ulps_f32(ours, exact);
    check.measure(&format!("{law}: |ours − f64 law| (f32 ulps)"), ulps, label);
    if !(ulps <= OURS_ULPS) {
        check.fail(format!(
            "{law} at {label}: ours {ours:e}, f64 law {exact:e} ({ulps:.1} ulps)"
        ));
    }
    let Some(mitsuba) = mitsuba else {
        check.fail(format!("{law} at {label}: no result from Mitsuba"));
        return;
    };
    let (err, gap) = ((mitsuba - exact).abs(), (ours - mitsuba).abs());
    check.measure(&format!("{law}: |Mitsuba − f64 law|"), err, label);
    if !(gap <= GROSS_ABS) {
        check.fail(format!(
            "{law} at {label}: ours {ours:e}, Mitsuba {mitsuba:e}"
        ));
    } else if err > MITSUBA_ABS && ulps <= OURS_ULPS {
        check.find(format!(
            "Mitsuba {law} at {label}: {mitsuba:e}, exact {exact:e} (off by {err:.2e})"
        ));
    }
}

fn direction(
    check: &mut Check,
    law: &str,
    label: &str,
    ours: [f64; 3],
    mitsuba: Option<[f64; 3]>,
    exact: [f64; 3],
    allowance: f64,
) {
    let err = max_abs(ours, exact);
    check.measure(
        &format!("{law}: max |ours − f64 law| per component"),
        err,
        label,
    );
    let bound = DIRECTION_ABS + allowance;
    if !(err <= bound) {
        check.fail(format!(
            "{law} at {label}: ours {ours:?}, f64 law {exact:?} (off by {err:.2e} > {bound:.1e})"
        ));
    }
    let Some(mitsuba) = mitsuba else {
        check.fail(format!("{law} at {label}: no result from Mitsuba"));
        return;
    };
    let (m_err, gap) = (max_abs(mitsuba, exact), max_abs(ours, mitsuba));
    check.measure(
        &format!("{law}: max |Mitsuba − f64 law| per component"),
        m_err,
        label,
    );
    if !(gap <= GROSS_ABS) {
        check.fail(format!(
            "{law} at {label}: ours {ours:?}, Mitsuba {mitsuba:?}"
        ));
    } else if m_err > MITSUBA_ABS + allowance && err <= bound {
        check.find(format!(
            "Mitsuba {law} at {label}: off the exact direction by {m_err:.2e}"
        ));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cases_depend_only_on_the_seed() {
        assert_eq!(random_cases(7, 10).cases, random_cases(7, 10).cases);
        assert_ne!(random_cases(7, 10).cases, random_cases(8, 10).cases);
    }

    #[test]
    fn cases_are_float32_values() {
        for case in random_cases(1, 50).cases {
            let values = match case {
                LawCase::Fresnel { cos_i, eta } => vec![cos_i, eta],
                LawCase::FresnelConductor { cos_i, n, kappa } => vec![cos_i, n, kappa],
                LawCase::Directions { wi, n, eta } => [wi.to_vec(), n.to_vec(), vec![eta]].concat(),
            };
            assert!(
                values.iter().all(|&x| f64::from(x as f32) == x),
                "{values:?}"
            );
        }
    }

    #[test]
    fn the_case_format_is_tagged_by_law() {
        let text = serde_json::to_string(&LawCase::Fresnel {
            cos_i: 0.5,
            eta: 1.5,
        })
        .unwrap();
        assert_eq!(text, r#"{"law":"fresnel","cos_i":0.5,"eta":1.5}"#);
    }
}
