//! `optics reflect`: the mirror direction, by the law of reflection.

use super::normalized::note_normalized;
use crate::error::Result;
use crate::input::{Vec3Arg, Via};
use radiometry::specular::reflect;
use record::{number, vector, Answer, Record, Steps};
use record::{say, Lang};
use serde::Deserialize;

/// The mirror direction (law of reflection).
#[derive(clap::Args, Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[command(
    allow_negative_numbers = true,
    after_help = "Directions point away from the surface.

Example:
  optics reflect --wi 0,0.6,0.8 --normal 0,0,1"
)]
pub struct ReflectArgs {
    /// Direction towards the incident light, away from the surface (any length).
    #[arg(long, allow_hyphen_values = true)]
    pub wi: Vec3Arg,
    /// Surface normal (any length).
    #[arg(long, allow_hyphen_values = true)]
    pub normal: Vec3Arg,
}

impl ReflectArgs {
    /// Evaluates the law: its inputs checked (named as `via` gives them), the working in `lang`.
    pub fn solve(&self, via: Via, lang: Lang, steps: Steps) -> Result<Record> {
        let wi = via.direction("wi", self.wi)?;
        let n = via.direction("normal", self.normal)?;
        let title = say!(lang, "Mirror direction", "Tükörirány");
        let mut record = Record::new(Self::LAW, title, "1").with_steps(steps);
        record.input("wi", self.wi.0).input("normal", self.normal.0);
        note_normalized(&mut record, lang, "wi", &wi);
        note_normalized(&mut record, lang, "normal", &n);
        let r = reflect(wi.unit, n.unit);
        record.step(|| format!("cos θi = n · ωi = {}", number(wi.unit.dot(n.unit))));
        record.step(|| format!("ωr = 2 (n · ωi) n − ωi = {}", vector(r.to_array())));
        record.answer = Answer::Vector(r.to_array());
        Ok(record)
    }
}
