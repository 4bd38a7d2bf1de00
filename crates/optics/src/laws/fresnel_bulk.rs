//! `optics fresnel-bulk`: the exact Fresnel reflectance of one material at
//! many cosines at once, by the slice laws (`radiometry::fresnel::slice`),
//! which give the scalar law's bits on the widest instructions the CPU
//! has. The route for a table of reflectances, or an array from Python,
//! in one request rather than one line each.

use crate::error::{Error, ErrorKind, Result};
use crate::input::Via;
use radiometry::fresnel::{conductor_slice, dielectric_slice, Lanes};
use record::{number, Answer, Record, Steps};
use record::{say, Lang};
use serde::Deserialize;
use serde_json::Value;

/// The exact reflectance of one material at many cosines.
#[derive(clap::Args, Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[command(
    allow_negative_numbers = true,
    after_help = "The answer is the list of reflectances, in the order of the cosines, each the
same bits as `optics fresnel --model exact` gives for that cosine. A conductor
(--kappa > 0) is lit only from outside: every cosine ≥ 0.

Example:
  optics fresnel-bulk --eta 1.5 --cos-i 1,0.5,0,-0.5,-0.9
  printf '%s\\n' '{\"law\": \"fresnel_bulk\", \"eta\": 0.17, \"kappa\": 3.1, \"cos_i\": [1, 0.5, 0]}' | optics batch"
)]
pub struct FresnelBulkArgs {
    /// Relative index n_inside / n_outside (a conductor's n).
    #[arg(long, allow_hyphen_values = true)]
    pub eta: f64,
    /// Extinction coefficient κ (0 for a dielectric).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    #[serde(default)]
    pub kappa: f64,
    /// The cosines of incidence, comma-separated (an array in a request); > 0 from outside.
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        required = true
    )]
    pub cos_i: Vec<f64>,
}

impl FresnelBulkArgs {
    /// Evaluates the law: its inputs checked (named as `via` gives them), the working in `lang`.
    pub fn solve(&self, via: Via, lang: Lang, steps: Steps) -> Result<Record> {
        let eta = via.index("eta", self.eta)?;
        let kappa = via.extinction("kappa", self.kappa)?;
        if self.cos_i.is_empty() {
            let name = via.name("cos_i");
            return Err(Error::from(ErrorKind::EmptyList { name }));
        }
        for (k, &c) in self.cos_i.iter().enumerate() {
            let field = format!("cos_i[{k}]");
            let c = via.cosine(&field, c)?;
            if kappa > 0.0 && c < 0.0 {
                let name = via.name(&field);
                let (cos_i, degrees) = (c, None);
                return Err(Error::from(ErrorKind::ConductorFromInside {
                    name,
                    cos_i,
                    degrees,
                }));
            }
        }
        let title = say!(
            lang,
            "Fresnel reflectance at {} cosines, exact",
            "Fresnel-visszaverődés {} koszinuszra, pontos",
            self.cos_i.len()
        );
        let mut record = Record::new(Self::LAW, title, "1").with_steps(steps);
        record.input("eta", eta).input("kappa", kappa);
        record.input("cos_i", &self.cos_i);
        let mut out = vec![0.0; self.cos_i.len()];
        if kappa > 0.0 {
            conductor_slice(&self.cos_i, eta, kappa, &mut out);
        } else {
            dielectric_slice(&self.cos_i, eta, &mut out);
        }
        let lanes = Lanes::widest();
        record.step(|| {
            say!(
                lang,
                "the exact {} law over the slice, on {lanes:?} instructions: each the scalar law's bits",
                "a pontos {} törvény a szeleten, {lanes:?} utasításokkal: mindegyik a skalár törvény bitjei",
                if kappa > 0.0 {
                    lang.pick("conductor", "vezető")
                } else {
                    lang.pick("dielectric", "dielektrikum")
                }
            )
        });
        if let (Some(first), Some(last)) = (out.first(), out.last()) {
            record.step(|| format!("R = {} … {}", number(*first), number(*last)));
        }
        record.answer = Answer::List(out.into_iter().map(Value::from).collect());
        Ok(record)
    }
}

#[cfg(test)]
mod tests {
    use super::FresnelBulkArgs;
    use crate::input::Via;
    use crate::laws::{FresnelArgs, FresnelModel};
    use record::{Answer, Lang, Steps};

    /// The bulk answers of 10⁵ cosines per material are the scalar
    /// `fresnel` law's, bit for bit (tolerance zero).
    #[test]
    fn bulk_reflectance_is_the_scalar_fresnel_law_bit_for_bit() {
        let count = 100_000;
        let spread = |from: f64| -> Vec<f64> {
            (0..count)
                .map(|k| from + (1.0 - from) * k as f64 / (count - 1) as f64)
                .collect()
        };
        let materials = [
            (1.5, 0.0, -1.0),
            (1.0 / 1.5, 0.0, -1.0),
            (1.333, 0.0, -1.0),
            (0.17, 3.1, 0.0),
        ];
        for (eta, kappa, from) in materials {
            let cos_i = spread(from);
            let bulk = FresnelBulkArgs {
                eta,
                kappa,
                cos_i: cos_i.clone(),
            };
            let record = bulk
                .solve(Via::Json, Lang::En, Steps::from_wanted(false))
                .unwrap();
            let Answer::List(answers) = record.answer else {
                panic!("a list")
            };
            assert_eq!(answers.len(), count);
            for (&c, r) in cos_i.iter().zip(&answers) {
                let scalar = FresnelArgs {
                    eta: Some(eta),
                    kappa,
                    metal: None,
                    cos_i: Some(c),
                    theta_i_deg: None,
                    model: FresnelModel::Exact.into(),
                };
                let scalar = scalar
                    .solve(Via::Json, Lang::En, Steps::from_wanted(false))
                    .unwrap();
                let Answer::Number(scalar) = scalar.answer else {
                    panic!("a number")
                };
                let r = r.as_f64().unwrap();
                assert_eq!(
                    r.to_bits(),
                    scalar.to_bits(),
                    "eta {eta}, κ {kappa}, cos {c}: {r} against {scalar}"
                );
            }
        }
    }

    /// No cosine is not an empty answer: the list is refused, naming it.
    #[test]
    fn an_empty_list_of_cosines_is_refused_naming_it() {
        let bulk = FresnelBulkArgs {
            eta: 1.5,
            kappa: 0.0,
            cos_i: Vec::new(),
        };
        let error = bulk.solve(Via::Json, Lang::En, Steps::Wanted).unwrap_err();
        assert!(
            matches!(error.kind(), crate::error::ErrorKind::EmptyList { name } if name == "cos_i"),
            "{error:?}"
        );
    }
}
