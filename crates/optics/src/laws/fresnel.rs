//! `optics fresnel`: Fresnel reflectance, exact or by Schlick's
//! approximation, of a dielectric or a conductor.
//!
//! The incidence is resolved once, here, and every law is evaluated once at
//! it; the working is narrated from what the laws returned: the side and
//! indices of the [`Incidence`], the exact law's `cos θt`, and the cosine
//! Schlick took ([`SchlickDielectric::cosine`]).

use crate::input::Via;
use crate::lang::{say, Lang};
use crate::record::{number, Answer, Record};
use anyhow::{bail, Result};
use radiometry::fresnel::{
    conductor_polarized, dielectric_resolved, f0, schlick, schlick_dielectric_resolved,
    DielectricFresnel, SchlickCosine, SchlickDielectric,
};
use radiometry::snell::Incidence;
use serde::Deserialize;

/// Which Fresnel law to evaluate.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum FresnelModel {
    /// The exact Fresnel equations.
    #[default]
    Exact,
    /// Schlick's approximation, F0 + (1 − F0)(1 − cos θ)⁵.
    Schlick,
}

impl FresnelModel {
    fn name(self) -> &'static str {
        match self {
            FresnelModel::Exact => "exact",
            FresnelModel::Schlick => "schlick",
        }
    }
}

/// Fresnel reflectance of a smooth interface.
#[derive(clap::Args, Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[command(
    allow_negative_numbers = true,
    after_help = "Examples:
  optics fresnel --eta 1.5 --theta-i-deg 60
  optics fresnel --eta 1.5 --cos-i -0.5           (from inside the glass: total internal reflection)
  optics fresnel --eta 0.17 --kappa 3.1 --cos-i 1 (gold, red channel, at normal incidence)
  optics fresnel --eta 1.5 --cos-i 0.3 --model schlick --json"
)]
pub struct FresnelArgs {
    /// Relative index n_inside / n_outside (= n_t / n_i for light from outside).
    #[arg(long)]
    pub eta: f64,
    /// Extinction coefficient of the inside; > 0 makes it a conductor (complex index eta + i·kappa).
    #[arg(long, default_value_t = 0.0)]
    #[serde(default)]
    pub kappa: f64,
    /// Signed cosine of incidence, n·wi: > 0 from outside, < 0 from inside.
    #[arg(
        long,
        required_unless_present = "theta_i_deg",
        conflicts_with = "theta_i_deg"
    )]
    #[serde(default)]
    pub cos_i: Option<f64>,
    /// Angle of incidence from the outward normal in degrees, 0..180 (over 90: from inside).
    #[arg(long)]
    #[serde(default)]
    pub theta_i_deg: Option<f64>,
    /// The law: exact, or Schlick's approximation.
    #[arg(long, value_enum, default_value_t)]
    #[serde(default)]
    pub model: FresnelModel,
}

impl FresnelArgs {
    pub fn solve(&self, via: Via, lang: Lang) -> Result<Record> {
        let eta = via.index("eta", self.eta)?;
        let kappa = via.extinction("kappa", self.kappa)?;
        let cos_i = self.signed_cosine(via, kappa)?;
        let mut record = self.record(eta, kappa, cos_i, lang);
        // The one place the side is decided; each law below takes it.
        let incidence = Incidence::resolve(cos_i, eta)
            .expect("cos_i and eta were validated by radiometry::domain above");
        narrate_incidence(&mut record, lang, &incidence, eta, kappa);
        let reflectance = match (self.model, kappa > 0.0) {
            (FresnelModel::Exact, false) => {
                exact_dielectric(&mut record, lang, &dielectric_resolved(&incidence))
            }
            (FresnelModel::Exact, true) => exact_conductor(&mut record, &incidence, eta, kappa),
            (FresnelModel::Schlick, false) => {
                let working = schlick_dielectric_resolved(&incidence);
                let exact = dielectric_resolved(&incidence).reflectance();
                schlick_for_dielectric(&mut record, lang, &working, exact)
            }
            (FresnelModel::Schlick, true) => {
                schlick_for_conductor(&mut record, lang, &incidence, eta, kappa)
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
                    bail!(
                        "{} must be an angle in [0, 180] degrees, got {deg}",
                        via.name("theta_i_deg")
                    );
                }
                deg.to_radians().cos()
            }
            _ => bail!(
                "give exactly one of {} and {}",
                via.name("cos_i"),
                via.name("theta_i_deg")
            ),
        };
        if kappa > 0.0 && cos_i < 0.0 {
            bail!(
                "{} must be ≥ 0 for a conductor (kappa > 0): light cannot arrive from inside a metal, got {cos_i}",
                via.name(if self.cos_i.is_some() { "cos_i" } else { "theta_i_deg" })
            );
        }
        Ok(cos_i)
    }

    /// The record with its title and inputs, before any working.
    fn record(&self, eta: f64, kappa: f64, cos_i: f64, lang: Lang) -> Record {
        let kind = if kappa > 0.0 {
            lang.pick("conductor", "vezető")
        } else {
            lang.pick("dielectric", "dielektrikum")
        };
        let model = match (self.model, lang) {
            (FresnelModel::Exact, Lang::En) => "exact",
            (FresnelModel::Exact, Lang::Hu) => "pontos",
            (FresnelModel::Schlick, _) => "Schlick",
        };
        let mut record = Record::new(
            "fresnel",
            say!(
                lang,
                "Fresnel reflectance, {model}, {kind}",
                "Fresnel-függvény, {model}, {kind}"
            ),
            "1",
        );
        record.input("eta", eta).input("kappa", kappa);
        match self.theta_i_deg {
            Some(deg) => record.input("theta_i_deg", deg),
            None => record.input("cos_i", cos_i),
        };
        record.input("model", self.model.name());
        record
    }
}

/// The side and angle of incidence, as resolved.
fn narrate_incidence(
    record: &mut Record,
    lang: Lang,
    incidence: &Incidence<f64>,
    eta: f64,
    kappa: f64,
) {
    if kappa > 0.0 {
        record.step(say!(
            lang,
            "light arrives from outside onto a conductor of complex index ñ = η + iκ = {} + {}i",
            "a fény kívülről érkezik egy ñ = η + iκ = {} + {}i komplex törésmutatójú vezetőre",
            number(eta),
            number(kappa)
        ));
    } else if incidence.from_inside {
        record.step(say!(
            lang,
            "cos θi < 0: light arrives from inside, n_i = η = {}, n_t = 1",
            "cos θi < 0: a fény belülről érkezik, n_i = η = {}, n_t = 1",
            number(eta)
        ));
    } else {
        record.step(say!(
            lang,
            "cos θi ≥ 0: light arrives from outside, n_i = 1, n_t = η = {}",
            "cos θi ≥ 0: a fény kívülről érkezik, n_i = 1, n_t = η = {}",
            number(eta)
        ));
    }
    record.step(format!(
        "|cos θi| = {}, θi = {}°",
        number(incidence.abs_cos_i),
        number(incidence.abs_cos_i.acos().to_degrees())
    ));
}

/// The exact dielectric law's working, from what it returned; its `R`.
fn exact_dielectric(record: &mut Record, lang: Lang, fresnel: &DielectricFresnel<f64>) -> f64 {
    match fresnel.cos_t {
        Some(cos_t) => record.step(say!(
            lang,
            "Snell: cos θt = √(n_t² − n_i² sin²θi) / n_t = {} (θt = {}°)",
            "Snellius–Descartes: cos θt = √(n_t² − n_i² sin²θi) / n_t = {} (θt = {}°)",
            number(cos_t),
            number(cos_t.acos().to_degrees())
        )),
        None => record.step(say!(
            lang,
            "Snell: sin θt = n_i sin θi / n_t = {} > 1: total internal reflection",
            "Snellius–Descartes: sin θt = n_i sin θi / n_t = {} > 1: teljes visszaverődés",
            number(fresnel.incidence.sin_transmitted())
        )),
    };
    if fresnel.is_total_internal_reflection() {
        record.step(format!(
            "R_s = {}, R_p = {}",
            number(fresnel.r_s),
            number(fresnel.r_p)
        ));
    } else {
        record.step(format!(
            "R_s = ((n_i cos θi − n_t cos θt) / (n_i cos θi + n_t cos θt))² = {}",
            number(fresnel.r_s)
        ));
        record.step(format!(
            "R_p = ((n_t cos θi − n_i cos θt) / (n_t cos θi + n_i cos θt))² = {}",
            number(fresnel.r_p)
        ));
    }
    let r = fresnel.reflectance();
    record.step(format!("R = (R_s + R_p) / 2 = {}", number(r)));
    record.step(format!("T = 1 − R = {}", number(fresnel.transmittance())));
    record
        .detail("r_s", fresnel.r_s)
        .detail("r_p", fresnel.r_p)
        .detail("transmittance", fresnel.transmittance())
        .detail("cos_t", fresnel.cos_t)
        .detail(
            "total_internal_reflection",
            fresnel.is_total_internal_reflection(),
        );
    r
}

/// The exact conductor law's working, lit from outside at `incidence`; its `R`.
fn exact_conductor(record: &mut Record, incidence: &Incidence<f64>, eta: f64, kappa: f64) -> f64 {
    let fresnel = conductor_polarized(incidence.abs_cos_i, eta, kappa);
    record.step(format!(
        "R_s = |(cos θi − √(ñ² − sin²θi)) / (cos θi + √(ñ² − sin²θi))|² = {}",
        number(fresnel.r_s)
    ));
    record.step(format!(
        "R_p = |(ñ² cos θi − √(ñ² − sin²θi)) / (ñ² cos θi + √(ñ² − sin²θi))|² = {}",
        number(fresnel.r_p)
    ));
    let r = fresnel.reflectance();
    record.step(format!("R = (R_s + R_p) / 2 = {}", number(r)));
    record.detail("r_s", fresnel.r_s).detail("r_p", fresnel.r_p);
    r
}

/// Schlick's working at a dielectric, from the cosine it says it took,
/// compared with the exact law's `exact`; its `R`.
fn schlick_for_dielectric(
    record: &mut Record,
    lang: Lang,
    working: &SchlickDielectric<f64>,
    exact: f64,
) -> f64 {
    step_f0(record, working.f0);
    match (working.cosine, working.cosine_used()) {
        (SchlickCosine::Transmitted, Some(cos_t)) => {
            record.step(say!(
                lang,
                "from the denser side Schlick takes the angle in the rarer medium: cos θt = {}",
                "a sűrűbb oldalról Schlick a ritkább közegbeli szöget használja: cos θt = {}",
                number(cos_t)
            ));
        }
        (SchlickCosine::TotalInternalReflection, _) => {
            record.step(say!(
                lang,
                "beyond the critical angle: total internal reflection, R = 1",
                "a határszögön túl: teljes visszaverődés, R = 1"
            ));
        }
        _ => {}
    }
    if let Some(cos) = working.cosine_used() {
        step_schlick(record, working.f0, cos, working.reflectance);
    }
    compare_with_exact(record, lang, working.f0, working.reflectance, exact)
}

/// Schlick's approximation at a conductor, with the incident cosine,
/// compared with the exact law; its `R`.
fn schlick_for_conductor(
    record: &mut Record,
    lang: Lang,
    incidence: &Incidence<f64>,
    eta: f64,
    kappa: f64,
) -> f64 {
    let f_0 = f0(eta, kappa);
    step_f0(record, f_0);
    let r = schlick(incidence.abs_cos_i, f_0);
    step_schlick(record, f_0, incidence.abs_cos_i, r);
    let exact = conductor_polarized(incidence.abs_cos_i, eta, kappa).reflectance();
    compare_with_exact(record, lang, f_0, r, exact)
}

fn step_f0(record: &mut Record, f_0: f64) {
    record.step(format!(
        "F0 = ((η − 1)² + κ²) / ((η + 1)² + κ²) = {}",
        number(f_0)
    ));
}

fn step_schlick(record: &mut Record, f_0: f64, cos: f64, r: f64) {
    record.step(format!(
        "R ≈ F0 + (1 − F0)(1 − cos θ)⁵ = {} + {}·{}⁵ = {}",
        number(f_0),
        number(1.0 - f_0),
        number(1.0 - cos),
        number(r)
    ));
}

fn compare_with_exact(record: &mut Record, lang: Lang, f_0: f64, r: f64, exact: f64) -> f64 {
    record.step(say!(
        lang,
        "for comparison, the exact law gives R = {}: Schlick − exact = {}",
        "összevetésül a pontos képlet: R = {}, Schlick − pontos = {}",
        number(exact),
        number(r - exact)
    ));
    record
        .detail("f0", f_0)
        .detail("exact", exact)
        .detail("error", r - exact);
    r
}
