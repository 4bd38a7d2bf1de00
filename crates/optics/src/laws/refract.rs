//! `optics refract`: the refracted direction, by Snell's law in vector form.

use super::normalized::note_normalized;
use crate::error::Result;
use crate::input::{Vec3Arg, Via};
use glam::DVec3;
use radiometry::snell::Incidence;
use radiometry::specular::{incidence, reflect, refract_resolved};
use record::{number, vector, Answer, Record, Steps};
use record::{say, Lang};
use serde::Deserialize;

/// The refracted direction (Snell's law in vector form).
#[derive(clap::Args, Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[command(
    allow_negative_numbers = true,
    after_help = "Directions point away from the surface: --wi points back towards where the light comes from,
and the ray travels along −wi. The normal points outside (into the medium of index 1).

Examples:
  optics refract --wi 0,0.6,0.8 --normal 0,0,1 --eta 1.5
  optics refract --wi 0,0.8,-0.6 --normal 0,0,1 --eta 1.5   (from inside, beyond the critical angle)"
)]
pub struct RefractArgs {
    /// Direction towards the incident light, away from the surface (any length).
    #[arg(long, allow_hyphen_values = true)]
    pub wi: Vec3Arg,
    /// Outward surface normal (any length).
    #[arg(long, allow_hyphen_values = true)]
    pub normal: Vec3Arg,
    /// Relative index n_inside / n_outside.
    #[arg(long, allow_hyphen_values = true)]
    pub eta: f64,
}

impl RefractArgs {
    /// Evaluates the law: its inputs checked (named as `via` gives them), the working in `lang`.
    pub fn solve(&self, via: Via, lang: Lang, steps: Steps) -> Result<Record> {
        let wi = via.direction("wi", self.wi)?;
        let n = via.direction("normal", self.normal)?;
        let eta = via.index("eta", self.eta)?;
        let mut record = Record::new(
            Self::LAW,
            say!(lang, "Refracted direction", "Törési irány"),
            "1",
        )
        .with_steps(steps);
        record
            .input("wi", self.wi.0)
            .input("normal", self.normal.0)
            .input("eta", eta);
        note_normalized(&mut record, lang, "wi", &wi);
        note_normalized(&mut record, lang, "normal", &n);
        let (wi, n) = (wi.unit, n.unit);
        let cos_i = wi.dot(n);
        // The side and Snell's law are decided here, once; the direction is
        // built from that decision (`refract` would decide them again).
        let incidence = resolve(wi, n, eta)
            .expect("wi, normal and eta were validated by radiometry::domain above");
        record.step(|| format!("cos θi = n · ωi = {}", number(cos_i)));
        narrate_side(&mut record, lang, &incidence);
        match incidence.cos_transmitted() {
            Some(cos_t) => refracted(
                &mut record,
                lang,
                refract_resolved(wi, n, &incidence, cos_t),
            ),
            None => totally_reflected(&mut record, lang, &incidence, reflect(wi, n)),
        }
        Ok(record)
    }
}

/// The incidence, from the directions.
#[cfg(not(test))]
fn resolve(wi: DVec3, n: DVec3, eta: f64) -> Option<Incidence<f64>> {
    incidence(wi, n, eta)
}

#[cfg(test)]
thread_local! {
    /// A test-only switch that reverts the fix for unit directions: the
    /// incidence from the rounded cosine alone, as before it, for the
    /// flag-values fuzz target to find.
    pub(crate) static FROM_THE_COSINE_ALONE: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

#[cfg(test)]
fn resolve(wi: DVec3, n: DVec3, eta: f64) -> Option<Incidence<f64>> {
    if FROM_THE_COSINE_ALONE.get() {
        Incidence::resolve(n.dot(wi), eta)
    } else {
        incidence(wi, n, eta)
    }
}

fn narrate_side(record: &mut Record, lang: Lang, incidence: &Incidence<f64>) {
    record.step(|| {
        if incidence.from_inside {
            say!(
                lang,
                "from inside: the normal is flipped to the incident side and η' = 1/η = {}",
                "belülről: a normálist a beesés oldalára fordítjuk, η' = 1/η = {}",
                number(incidence.eta_path())
            )
        } else {
            say!(
                lang,
                "from outside: η' = η = {}",
                "kívülről: η' = η = {}",
                number(incidence.eta_path())
            )
        }
    });
}

fn refracted(record: &mut Record, lang: Lang, t: radiometry::specular::Refraction<DVec3>) {
    record.step(|| {
        say!(
            lang,
            "Snell: cos θt = {} (θt = {}°)",
            "Snellius–Descartes: cos θt = {} (θt = {}°)",
            number(t.cos_t),
            number(t.cos_t.acos().to_degrees())
        )
    });
    record.step(|| {
        format!(
            "ωt = −ωi/η' + (cos θi/η' − cos θt) n' = {}",
            vector(t.direction.to_array())
        )
    });
    record.answer = Answer::Vector(t.direction.to_array());
    record
        .detail("outcome", "refracted")
        .detail("eta_path", t.eta_path)
        .detail("cos_t", t.cos_t);
}

fn totally_reflected(record: &mut Record, lang: Lang, incidence: &Incidence<f64>, mirror: DVec3) {
    record.step(|| say!(
        lang,
        "sin θt = sin θi / η' > 1: total internal reflection, no refracted ray (all light goes to the mirror direction {})",
        "sin θt = sin θi / η' > 1: teljes visszaverődés, nincs megtört sugár (minden fény a tükörirányba megy: {})",
        vector(mirror.to_array())
    ));
    record.answer = Answer::None;
    record
        .detail("outcome", "total_internal_reflection")
        .detail("eta_path", incidence.eta_path())
        .detail("reflected", mirror.to_array());
}
