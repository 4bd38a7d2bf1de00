//! The exported cases and the results read back: their schemas, their
//! file formats and the seeded generator that draws them.

use glam::DVec3;
use serde::{Deserialize, Serialize};

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
