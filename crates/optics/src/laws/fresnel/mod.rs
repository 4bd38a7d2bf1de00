//! `optics fresnel`: Fresnel reflectance, exact or by either form of
//! Schlick's approximation, of a dielectric or a conductor.
//!
//! The incidence is resolved once, here, and every law is evaluated once at
//! it; the working is narrated from what the laws returned: the side and
//! indices of the [`Incidence`], the exact law's `cos θt`, and the cosine
//! each Schlick form took (`SchlickDielectric::cosine`); [`working`]
//! narrates them.

use crate::error::Result;
use crate::error::{Error, ErrorKind};
use crate::input::Via;
use radiometry::fresnel::{
    conductor_polarized, dielectric_resolved, f0, schlick_dielectric_incident_resolved,
    schlick_dielectric_resolved,
};
use radiometry::snell::Incidence;
use record::{say, Lang};
use record::{Answer, Record, Steps};
use serde::Deserialize;
pub use tracer::scene::{FresnelModel, FresnelName};
use working::{
    course_form, exact_conductor, exact_dielectric, narrate_incidence, schlick_for_conductor,
    schlick_for_dielectric,
};

pub use metal::MetalName;

mod metal;
#[cfg(test)]
mod tests;
mod working;

/// Fresnel reflectance of a smooth interface.
#[derive(clap::Args, Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[command(
    allow_negative_numbers = true,
    group = clap::ArgGroup::new("incidence").required(true).args(["cos_i", "theta_i_deg"]),
    group = clap::ArgGroup::new("material").required(true).args(["eta", "metal"]),
    group = clap::ArgGroup::new("extinction").args(["kappa", "metal"]),
    after_help = "Examples:
  optics fresnel --eta 1.5 --theta-i-deg 60
  optics fresnel --eta 1.5 --cos-i -0.5           (from inside the glass: total internal reflection)
  optics fresnel --eta 0.17 --kappa 3.1 --cos-i 1 (gold, red channel, at normal incidence)
  optics fresnel --metal course-gold --theta-i-deg 60 (all three channels: R, G, B)
  optics fresnel --eta 1.5 --theta-i-deg 120 --model schlick-incident (misses total internal reflection)
  optics fresnel --eta 1.5 --cos-i 0.3 --model schlick-rarer --json"
)]
pub struct FresnelArgs {
    /// Relative index n_inside / n_outside (= n_t / n_i for light from outside).
    #[arg(long, allow_hyphen_values = true)]
    #[serde(default)]
    pub eta: Option<f64>,
    /// Extinction coefficient of the inside; > 0 makes it a conductor (complex index eta + i·kappa).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    #[serde(default)]
    pub kappa: f64,
    /// A metal by name, instead of --eta and --kappa: answered per RGB channel.
    #[arg(long, value_enum)]
    #[serde(default)]
    pub metal: Option<MetalName>,
    /// Signed cosine of incidence, n·wi: > 0 from outside, < 0 from inside.
    #[arg(long, allow_hyphen_values = true)]
    #[serde(default)]
    pub cos_i: Option<f64>,
    /// Angle of incidence from the outward normal in degrees, 0..180 (over 90: from inside).
    #[arg(long, allow_hyphen_values = true)]
    #[serde(default)]
    pub theta_i_deg: Option<f64>,
    /// The law: exact, Schlick's approximation in either form, or the course shader's reversed form.
    #[arg(long, value_enum, default_value_t)]
    #[serde(default)]
    pub model: FresnelName,
}

impl FresnelArgs {
    /// Evaluates the law: its inputs checked (named as `via` gives them), the working in `lang`.
    pub fn solve(&self, via: Via, lang: Lang, steps: Steps) -> Result<Record> {
        match (self.eta, self.metal) {
            (Some(eta), None) => self.solve_at(eta, via, lang, steps),
            (None, Some(metal)) if self.kappa == 0.0 => self.solve_metal(metal, via, lang, steps),
            _ => Err(Error::from(ErrorKind::IndexOrMetal {
                eta: via.name("eta"),
                kappa: via.name("kappa"),
                metal: via.name("metal"),
            })),
        }
    }

    /// The law per RGB channel of a metal named, each channel's working
    /// beneath its index; the answer `[R, G, B]`.
    fn solve_metal(&self, metal: MetalName, via: Via, lang: Lang, steps: Steps) -> Result<Record> {
        let channels = metal.channels();
        let mut solved = Vec::with_capacity(3);
        for (&n, &kappa) in channels.n.iter().zip(&channels.kappa) {
            let one = FresnelArgs {
                eta: Some(n),
                kappa,
                metal: None,
                ..self.clone()
            };
            solved.push(one.solve_at(n, via, lang, steps)?);
        }
        let mut record = Record::new(
            Self::LAW,
            say!(
                lang,
                "{}: {}, per RGB channel",
                "{}: {}, RGB-csatornánként",
                solved[0].title,
                metal.word(lang)
            ),
            "1",
        )
        .with_steps(steps);
        record
            .input("metal", metal)
            .input("eta", channels.n)
            .input("kappa", channels.kappa);
        for name in ["theta_i_deg", "cos_i", "model"] {
            if let Some(value) = solved[0].inputs.get(name) {
                record.input(name, value.clone());
            }
        }
        record.step(|| metal.source(lang));
        let mut rgb = [0.0; 3];
        for ((channel, one), slot) in ["R", "G", "B"].iter().zip(&solved).zip(&mut rgb) {
            record.step(|| say!(lang, "{channel} channel:", "{channel} csatorna:"));
            for line in &one.steps {
                record.step(|| format!("  {line}"));
            }
            if let Answer::Number(r) = one.answer {
                *slot = r;
            }
        }
        record.answer = Answer::Vector(rgb);
        Ok(record)
    }

    /// The law at the relative index `eta` (with `self.kappa`).
    fn solve_at(&self, eta: f64, via: Via, lang: Lang, steps: Steps) -> Result<Record> {
        let eta = via.index("eta", eta)?;
        let kappa = via.extinction("kappa", self.kappa)?;
        let cos_i = self.signed_cosine(via, kappa)?;
        let model = self.model.model().ok_or_else(|| {
            let name = via.name("model");
            Error::from(ErrorKind::SchlickFormUnnamed { name })
        })?;
        let mut record = self
            .record(model, eta, kappa, cos_i, lang)
            .with_steps(steps);
        // The one place the side is decided; each law below takes it.
        let incidence = Incidence::resolve(cos_i, eta)
            .expect("cos_i and eta were validated by radiometry::domain above");
        narrate_incidence(&mut record, lang, &incidence, eta, kappa);
        let reflectance = match (model, kappa > 0.0) {
            (FresnelModel::Exact, false) => {
                exact_dielectric(&mut record, lang, &dielectric_resolved(&incidence))
            }
            (FresnelModel::Exact, true) => exact_conductor(&mut record, &incidence, eta, kappa),
            (FresnelModel::SchlickIncident | FresnelModel::SchlickRarer, false) => {
                let forms = [
                    schlick_dielectric_incident_resolved(&incidence),
                    schlick_dielectric_resolved(&incidence),
                ];
                let exact = dielectric_resolved(&incidence);
                schlick_for_dielectric(&mut record, lang, model, &forms, &exact)
            }
            (FresnelModel::SchlickIncident | FresnelModel::SchlickRarer, true) => {
                schlick_for_conductor(&mut record, lang, &incidence, eta, kappa)
            }
            (FresnelModel::Course, conductor) => {
                let exact = if conductor {
                    conductor_polarized(incidence.abs_cos_i, eta, kappa).reflectance()
                } else {
                    dielectric_resolved(&incidence).reflectance()
                };
                course_form(&mut record, lang, &incidence, f0(eta, kappa), exact)
            }
        };
        record.answer = Answer::Number(reflectance);
        Ok(record)
    }

    /// The signed cosine of incidence, from `cos_i` or `theta_i_deg`,
    /// checked; a conductor is lit only from outside.
    fn signed_cosine(&self, via: Via, kappa: f64) -> Result<f64> {
        let cos_i = match (self.cos_i, self.theta_i_deg) {
            (Some(c), None) => via.cosine("cos_i", c)?,
            (None, Some(deg)) => {
                let deg = via.finite("theta_i_deg", deg)?;
                if !(0.0..=180.0).contains(&deg) {
                    let name = via.name("theta_i_deg");
                    return Err(Error::from(ErrorKind::AngleDegrees { name, value: deg }));
                }
                // Grazing incidence exactly: the rounding of 90° in
                // radians would leave a cosine of 6.1e-17.
                if deg == 90.0 {
                    0.0
                } else {
                    deg.to_radians().cos()
                }
            }
            _ => {
                let (cosine, angle) = (via.name("cos_i"), via.name("theta_i_deg"));
                return Err(Error::from(ErrorKind::CosineOrAngle { cosine, angle }));
            }
        };
        if kappa > 0.0 && cos_i < 0.0 {
            let name = via.name(if self.cos_i.is_some() {
                "cos_i"
            } else {
                "theta_i_deg"
            });
            let degrees = self.theta_i_deg.filter(|_| self.cos_i.is_none());
            return Err(Error::from(ErrorKind::ConductorFromInside {
                name,
                cos_i,
                degrees,
            }));
        }
        Ok(cos_i)
    }

    /// The record with its title and inputs, before any working.
    fn record(&self, model: FresnelModel, eta: f64, kappa: f64, cos_i: f64, lang: Lang) -> Record {
        let kind = if kappa > 0.0 {
            lang.pick("conductor", "vezető")
        } else {
            lang.pick("dielectric", "dielektrikum")
        };
        let label = match (model, lang) {
            (FresnelModel::Exact, Lang::En) => "exact",
            (FresnelModel::Exact, Lang::Hu) => "pontos",
            (FresnelModel::SchlickIncident, Lang::En) => "Schlick at cos θi",
            (FresnelModel::SchlickIncident, Lang::Hu) => "Schlick a beesési cos θi-vel",
            (FresnelModel::SchlickRarer, Lang::En) => "Schlick at the rarer medium's cosine",
            (FresnelModel::SchlickRarer, Lang::Hu) => "Schlick a ritkább közegbeli koszinusszal",
            (FresnelModel::Course, Lang::En) => "the course shader's form",
            (FresnelModel::Course, Lang::Hu) => "a kurzus shaderének alakja",
        };
        let mut record = Record::new(
            Self::LAW,
            say!(
                lang,
                "Fresnel reflectance, {label}, {kind}",
                "Fresnel-függvény, {label}, {kind}"
            ),
            "1",
        );
        record.input("eta", eta).input("kappa", kappa);
        match self.theta_i_deg {
            Some(deg) => record.input("theta_i_deg", deg),
            None => record.input("cos_i", cos_i),
        };
        record.input("model", model);
        record
    }
}
