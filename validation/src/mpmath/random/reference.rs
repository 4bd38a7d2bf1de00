//! The schema of `fresnel_random.json` and its decoding: per law, tier and
//! sampling, base64 columns of little-endian IEEE 754 numbers of the tier,
//! the inputs as drawn and the correctly rounded values.

use std::collections::BTreeMap;
use std::path::Path;

use base64::Engine as _;
use serde::Deserialize;

use crate::reference::ReferenceError;

/// The file name of the reference.
pub const FILE: &str = "fresnel_random.json";
/// Its schema.
pub const SCHEMA: &str = "fresnel-random/1";

/// A law of the random cases, with the columns of its inputs (in the order
/// the law takes them) and of its values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Law {
    /// Dielectric Fresnel `(cos_i, eta)`: R_s, R_p, R, T and the decision on
    /// total internal reflection.
    Dielectric,
    /// Conductor Fresnel `(cos_i, n, kappa)`: R_s, R_p, R.
    Conductor,
    /// Snell's law for angles `(theta_i, eta_path)`, with the condition
    /// number of `θ_t` over `θ_i`.
    TransmittedAngle,
    /// The critical angle `(eta_path)`.
    CriticalAngle,
    /// Brewster's angle `(eta_path)`.
    BrewsterAngle,
    /// Schlick's approximation `(cos_i, f0)`.
    Schlick,
}

impl Law {
    /// The input columns, in the order the law takes them.
    pub fn inputs(self) -> &'static [&'static str] {
        match self {
            Law::Dielectric => &["cos_i", "eta"],
            Law::Conductor => &["cos_i", "n", "kappa"],
            Law::TransmittedAngle => &["theta_i", "eta_path"],
            Law::CriticalAngle | Law::BrewsterAngle => &["eta_path"],
            Law::Schlick => &["cos_i", "f0"],
        }
    }

    /// The value columns the law is compared on, each with its name in the
    /// report.
    pub fn values(self) -> &'static [(&'static str, &'static str)] {
        match self {
            Law::Dielectric => &[("r_s", "R_s"), ("r_p", "R_p"), ("r", "R"), ("t", "T")],
            Law::Conductor => &[("r_s", "R_s"), ("r_p", "R_p"), ("r", "R")],
            Law::TransmittedAngle => &[("theta_t", "θ_t")],
            Law::CriticalAngle => &[("theta_c", "θ_c")],
            Law::BrewsterAngle => &[("theta_b", "θ_B")],
            Law::Schlick => &[("f", "F")],
        }
    }

    /// Its name in check ids and the report.
    pub fn name(self) -> &'static str {
        match self {
            Law::Dielectric => "fresnel_dielectric",
            Law::Conductor => "fresnel_conductor",
            Law::TransmittedAngle => "transmitted_angle",
            Law::CriticalAngle => "critical_angle",
            Law::BrewsterAngle => "brewster_angle",
            Law::Schlick => "schlick",
        }
    }
}

/// How the inputs were drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Sampling {
    /// Uniform over the real numbers of each argument's range.
    Reals,
    /// Uniform over the tier's floating-point numbers in the range (their
    /// bit patterns), as Herbie samples.
    Floats,
    /// Uniform over the real numbers of a small targeted region of the
    /// range, where a law's roundings add up most: a set that a law need
    /// not have.
    Near,
}

impl Sampling {
    /// Its name in the report.
    pub fn name(self) -> &'static str {
        self.names()[0]
    }

    /// Its name in the report in English and in Hungarian.
    pub fn names(self) -> [&'static str; 2] {
        match self {
            Sampling::Reals => ["reals", "valós"],
            Sampling::Floats => ["floats", "lebegőpontos"],
            Sampling::Near => ["near", "közeli"],
        }
    }
}

/// The precision tier of a set: its inputs are numbers of the tier, and its
/// values are rounded to it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
pub enum Tier {
    /// binary64.
    #[serde(rename = "f64")]
    F64,
    /// binary32.
    #[serde(rename = "f32")]
    F32,
}

impl Tier {
    /// `"f64"` or `"f32"`.
    pub fn name(self) -> &'static str {
        match self {
            Tier::F64 => "f64",
            Tier::F32 => "f32",
        }
    }

    fn width(self) -> usize {
        match self {
            Tier::F64 => 8,
            Tier::F32 => 4,
        }
    }
}

/// `fresnel_random.json` as written.
#[derive(Clone, Debug, Deserialize)]
pub struct FresnelRandom {
    /// mpmath's version.
    pub mpmath_version: String,
    /// The seed of the draws.
    pub seed: u64,
    /// One set per law, tier and sampling.
    pub sets: Vec<RawSet>,
}

/// One set as written: its columns still base64.
#[derive(Clone, Debug, Deserialize)]
pub struct RawSet {
    /// The law.
    pub law: Law,
    /// The tier.
    pub tier: Tier,
    /// How the inputs were drawn.
    pub sampling: Sampling,
    /// The number of cases.
    pub count: usize,
    /// Each column, base64 of little-endian numbers of the tier.
    pub columns: BTreeMap<String, String>,
    /// One byte per case, 1 under total internal reflection (dielectric).
    #[serde(default)]
    pub tir_u8: Option<String>,
}

/// One set decoded: every column of its law, `count` numbers each, widened
/// to `f64` exactly (NaN where the law has no value).
#[derive(Clone, Debug)]
pub struct CaseSet {
    /// The law.
    pub law: Law,
    /// The tier.
    pub tier: Tier,
    /// How the inputs were drawn.
    pub sampling: Sampling,
    /// The number of cases.
    pub count: usize,
    /// The columns by name.
    pub columns: BTreeMap<String, Vec<f64>>,
    /// Total internal reflection per case (dielectric only).
    pub tir: Option<Vec<bool>>,
}

impl CaseSet {
    /// The column `name` (every column of the law is there: [`decode`]).
    pub fn column(&self, name: &str) -> &[f64] {
        &self.columns[name]
    }

    /// The inputs of case `i`, in the order the law takes them.
    pub fn inputs(&self, i: usize) -> Vec<f64> {
        self.law
            .inputs()
            .iter()
            .map(|c| self.column(c)[i])
            .collect()
    }
}

impl FresnelRandom {
    /// Loads the reference from `dir` and decodes every set.
    pub fn load(dir: &Path) -> Result<(Self, Vec<CaseSet>), ReferenceError> {
        let raw: Self = crate::reference::load(dir, FILE, SCHEMA)?;
        let sets = decode(&dir.join(FILE), &raw)?;
        Ok((raw, sets))
    }
}

/// Decodes every set, refusing a missing column or one of the wrong length
/// with the field that is at fault.
pub fn decode(file: &Path, raw: &FresnelRandom) -> Result<Vec<CaseSet>, ReferenceError> {
    raw.sets
        .iter()
        .enumerate()
        .map(|(index, set)| {
            decode_set(set).map_err(|(field, message)| ReferenceError::Malformed {
                path: file.to_owned(),
                field: format!("sets[{index}].{field}"),
                message,
            })
        })
        .collect()
}

fn decode_set(set: &RawSet) -> Result<CaseSet, (String, String)> {
    let mut columns = BTreeMap::new();
    let names = set.law.inputs().iter().copied();
    let names = names.chain(set.law.values().iter().map(|(c, _)| *c));
    let names = names.chain((set.law == Law::TransmittedAngle).then_some("cond_theta"));
    for name in names {
        let field = format!("columns.{name}");
        let text = set
            .columns
            .get(name)
            .ok_or_else(|| (field.clone(), "missing".to_owned()))?;
        let values = numbers(text, set.tier, set.count).map_err(|m| (field, m))?;
        columns.insert(name.to_owned(), values);
    }
    let tir = match (&set.tir_u8, set.law) {
        (Some(text), Law::Dielectric) => {
            let bytes = base64_bytes(text).map_err(|m| ("tir_u8".to_owned(), m))?;
            if bytes.len() != set.count {
                let message = format!("expected {} bytes, got {}", set.count, bytes.len());
                return Err(("tir_u8".to_owned(), message));
            }
            Some(bytes.iter().map(|&b| b != 0).collect())
        }
        (None, Law::Dielectric) => return Err(("tir_u8".to_owned(), "missing".to_owned())),
        _ => None,
    };
    Ok(CaseSet {
        law: set.law,
        tier: set.tier,
        sampling: set.sampling,
        count: set.count,
        columns,
        tir,
    })
}

/// `count` little-endian numbers of the tier, widened exactly.
fn numbers(text: &str, tier: Tier, count: usize) -> Result<Vec<f64>, String> {
    let bytes = base64_bytes(text)?;
    if bytes.len() != count * tier.width() {
        return Err(format!(
            "expected {count} {} numbers ({} bytes), got {} bytes",
            tier.name(),
            count * tier.width(),
            bytes.len()
        ));
    }
    Ok(match tier {
        Tier::F64 => bytes
            .chunks_exact(8)
            .map(|b| f64::from_le_bytes(b.try_into().expect("8 bytes")))
            .collect(),
        Tier::F32 => bytes
            .chunks_exact(4)
            .map(|b| f64::from(f32::from_le_bytes(b.try_into().expect("4 bytes"))))
            .collect(),
    })
}

/// Standard base64 (RFC 4648, with padding), as Python's `base64.b64encode`
/// writes it.
fn base64_bytes(text: &str) -> Result<Vec<u8>, String> {
    base64::engine::general_purpose::STANDARD
        .decode(text)
        .map_err(|e| format!("not base64: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn encode(values: &[f32]) -> String {
        let bytes: Vec<u8> = values.iter().flat_map(|v| v.to_le_bytes()).collect();
        base64::engine::general_purpose::STANDARD.encode(bytes)
    }

    #[test]
    fn a_column_of_the_wrong_length_is_refused_naming_it() {
        let raw = FresnelRandom {
            mpmath_version: "x".into(),
            seed: 1,
            sets: vec![RawSet {
                law: Law::BrewsterAngle,
                tier: Tier::F32,
                sampling: Sampling::Reals,
                count: 2,
                columns: [
                    ("eta_path".to_owned(), encode(&[1.5, 2.0])),
                    ("theta_b".to_owned(), encode(&[0.9])),
                ]
                .into(),
                tir_u8: None,
            }],
        };
        let message = decode(Path::new("f.json"), &raw).unwrap_err().to_string();
        assert!(message.contains("sets[0].columns.theta_b"), "{message}");
        assert!(message.contains("expected 2 f32 numbers"), "{message}");
    }

    #[test]
    fn f32_columns_widen_exactly() {
        let values = numbers(&encode(&[0.1, f32::MIN_POSITIVE / 8.0]), Tier::F32, 2).unwrap();
        assert_eq!(
            values,
            [f64::from(0.1f32), f64::from(f32::MIN_POSITIVE / 8.0)]
        );
    }
}
