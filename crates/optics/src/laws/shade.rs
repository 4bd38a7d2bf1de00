//! `optics shade`: radiance reflected towards a viewer from a directional
//! light, by one of the course's BRDFs.

use super::lit_surface::lit_surface_args;
use super::normalized::note_normalized;
use crate::error::{ErrorKind, Result};
use crate::input::{Vec3Arg, Via};
use glam::DVec3;
use radiometry::brdf::{
    half_vector, hemisphere, BlinnPhong, BlinnPhongReciprocal, Brdf, CourseLambert, Hemisphere,
    Lambert, Phong,
};
use radiometry::radiance::{directional_irradiance, reflected_radiance};
use radiometry::specular::reflect;
use record::{number, vector, Answer, Record, Steps};
use record::{say, Lang};
use serde::Deserialize;

/// A BRDF model, by the course's names.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ShadeModel {
    /// Physically normalised Lambert, f = kd/π (kd is the albedo).
    Lambert,
    /// The course's Lambert, f = kd (no 1/π).
    CourseLambert,
    /// Phong: f = kd + ks (cos⁺α)^shine / cos θi.
    Phong,
    /// The course's Phong-Blinn: f = kd + ks (cos⁺δ)^shine / cos θi.
    #[default]
    BlinnPhong,
    /// The course's reciprocal fix: f = kd + ks (cos⁺δ)^shine / |L+V|².
    BlinnPhongReciprocal,
}

impl ShadeModel {
    fn name(self) -> &'static str {
        match self {
            ShadeModel::Lambert => "lambert",
            ShadeModel::CourseLambert => "course-lambert",
            ShadeModel::Phong => "phong",
            ShadeModel::BlinnPhong => "blinn-phong",
            ShadeModel::BlinnPhongReciprocal => "blinn-phong-reciprocal",
        }
    }
}

lit_surface_args! {
/// Radiance reflected towards a viewer from a directional light.
#[derive(clap::Args, Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[command(
    allow_negative_numbers = true,
    after_help = "The light is directional: --radiance is the course's L_in, the light's strength on a surface
facing it (W/m², which the course calls radiance). Directions point away from the surface.

Examples:
  optics shade --model course-lambert --normal 0,0,1 --light-dir 0,3,4 --view-dir 1,2,3 --radiance 5 --kd 0.6
  optics shade --model blinn-phong --normal 0,0,1 --light-dir 0,3,4 --view-dir 0,4,3 --radiance 5 --ks 1.41421356 --shine 3"
)]
pub struct ShadeArgs {
    /// Direction towards the viewer (any length).
    view_dir: Vec3Arg,
    /// The BRDF model.
    #[arg(long, value_enum, default_value_t)]
    #[serde(default)]
    pub model: ShadeModel,
    /// Diffuse coefficient (the albedo for `lambert`).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    #[serde(default)]
    pub kd: f64,
    /// Specular coefficient.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    #[serde(default)]
    pub ks: f64,
    /// Shininess exponent.
    #[arg(long, default_value_t = 1.0, allow_hyphen_values = true)]
    #[serde(default = "one")]
    pub shine: f64,
}
}

fn one() -> f64 {
    1.0
}

/// A shading evaluation's numbers, for the quiz solvers built on it.
pub struct Shading {
    /// The record, with the working.
    pub record: Record,
    /// The reflected radiance, W/(sr m²).
    pub radiance: f64,
}

impl ShadeArgs {
    /// Evaluates the law: its inputs checked (named as `via` gives them), the working in `lang`.
    pub fn solve(&self, via: Via, lang: Lang, steps: Steps) -> Result<Record> {
        Ok(self.shade(Self::LAW, via, lang, steps)?.record)
    }

    /// Shades and records the working under the name `law`.
    pub fn shade(&self, law: &'static str, via: Via, lang: Lang, steps: Steps) -> Result<Shading> {
        let n = via.direction("normal", self.normal)?;
        let l = via.direction("light_dir", self.light_dir)?;
        let v = via.direction("view_dir", self.view_dir)?;
        let l_in = via.non_negative("radiance", self.radiance)?;
        let kd = via.non_negative("kd", self.kd)?;
        let ks = via.non_negative("ks", self.ks)?;
        let shine = via.non_negative("shine", self.shine)?;
        let model = self.model;
        let mut record = Record::new(
            law,
            say!(
                lang,
                "Reflected radiance, {} BRDF, directional light",
                "Visszavert sugársűrűség, {} BRDF, irányfényforrás",
                model.name()
            ),
            "W/(sr m^2)",
        )
        .with_steps(steps);
        let coefficients = Coefficients { kd, ks, shine };
        self.record_inputs(&mut record, l_in, coefficients);
        note_normalized(&mut record, lang, "normal", &n);
        note_normalized(&mut record, lang, "light_dir", &l);
        note_normalized(&mut record, lang, "view_dir", &v);
        let (n, l, v) = (n.unit, l.unit, v.unit);
        record.step(|| format!("L = {}, V = {}", vector(l.to_array()), vector(v.to_array())));
        let cos_in = n.dot(l);
        record.step(|| format!("cos θin = N · L = {}", number(cos_in)));
        let side = hemisphere(n, l, v);
        let f = model.on_side(&mut record, lang, coefficients, side, (n, l, v));
        let f = model.finite("f_r", f, via, &[])?;
        let e = directional_irradiance(l_in, n, l);
        record.step(|| {
            format!(
                "E = L_in cos⁺θin = {} · {} = {} W/m²",
                number(l_in),
                number(cos_in.max(0.0)),
                number(e)
            )
        });
        let radiance = model.finite("L_ref", reflected_radiance(f, e), via, &["radiance"])?;
        record.step(|| {
            format!(
                "L_ref = f_r · E = {} · {} = {} W/(sr m²)",
                number(f),
                number(e),
                number(radiance)
            )
        });
        note_no_coefficients(&mut record, model, (kd, ks), via, lang);
        if side == Hemisphere::ViewerBelow {
            record.note(say!(
                lang,
                "the viewer is at or below the surface: nothing is reflected towards it",
                "a néző a felület síkjában vagy alatta van: felé semmi sem verődik vissza"
            ));
        }
        record.answer = Answer::Number(radiance);
        record.detail("brdf", f).detail("irradiance", e);
        Ok(Shading { record, radiance })
    }

    /// The inputs as the record lists them: the coefficients this model
    /// takes.
    fn record_inputs(&self, record: &mut Record, l_in: f64, c: Coefficients) {
        let Coefficients { kd, ks, shine } = c;
        record
            .input("model", self.model.name())
            .input("normal", self.normal.0)
            .input("light_dir", self.light_dir.0)
            .input("view_dir", self.view_dir.0)
            .input("radiance", l_in);
        match self.model {
            ShadeModel::Lambert | ShadeModel::CourseLambert => record.input("kd", kd),
            _ => record.input("kd", kd).input("ks", ks).input("shine", shine),
        };
    }
}

impl ShadeModel {
    /// `f_r` on the `side` [`hemisphere`] decided: the model's, narrated,
    /// where it has a lobe (or NaN), and 0 with the reason where the light
    /// or the viewer is at or below the surface.
    fn on_side(
        self,
        record: &mut Record,
        lang: Lang,
        c: Coefficients,
        side: Hemisphere<f64>,
        (n, l, v): (DVec3, DVec3, DVec3),
    ) -> f64 {
        match side {
            Hemisphere::Above { .. } | Hemisphere::Undefined => self.evaluate(record, c, n, l, v),
            Hemisphere::LightBelow => {
                record.step(|| {
                    say!(
                        lang,
                        "f_r = 0: the light is at or below the surface (N · L ≤ 0)",
                        "f_r = 0: a fényforrás a felület síkjában vagy alatta van (N · L ≤ 0)"
                    )
                });
                0.0
            }
            Hemisphere::ViewerBelow => {
                record.step(|| {
                    say!(
                        lang,
                        "f_r = 0: the viewer is at or below the surface (N · V = {} ≤ 0)",
                        "f_r = 0: a néző a felület síkjában vagy alatta van (N · V = {} ≤ 0)",
                        number(n.dot(v))
                    )
                });
                0.0
            }
        }
    }
}

impl ShadeModel {
    /// `value`, or its overflow: finite inputs whose product is not (the
    /// radiance and the coefficients are unbounded). The overflow names
    /// `also` and the coefficients this model multiplies.
    fn finite(self, quantity: &'static str, value: f64, via: Via, also: &[&str]) -> Result<f64> {
        if value.is_finite() {
            return Ok(value);
        }
        let coefficients: &[&str] = match self {
            ShadeModel::Lambert | ShadeModel::CourseLambert => &["kd"],
            _ => &["kd", "ks"],
        };
        let inputs = also.iter().chain(coefficients);
        let inputs = inputs.map(|field| via.name(field)).collect();
        Err(ErrorKind::Overflow { quantity, inputs }.into())
    }
}

/// The diffuse and specular coefficients and the shininess, as checked.
#[derive(Clone, Copy)]
struct Coefficients {
    kd: f64,
    ks: f64,
    shine: f64,
}

impl ShadeModel {
    /// Evaluates this BRDF for light along `l` seen along `v` about `n`,
    /// narrating its terms; its `f_r` in 1/sr.
    fn evaluate(self, record: &mut Record, c: Coefficients, n: DVec3, l: DVec3, v: DVec3) -> f64 {
        let Coefficients { kd, ks, shine } = c;
        match self {
            ShadeModel::Lambert => {
                let f = Lambert { albedo: kd }.eval(n, l, v);
                record.step(|| format!("f_r = kd / π = {} 1/sr", number(f)));
                f
            }
            ShadeModel::CourseLambert => {
                let f = CourseLambert { kd }.eval(n, l, v);
                record.step(|| format!("f_r = kd = {} 1/sr", number(f)));
                f
            }
            ShadeModel::Phong => {
                let cos_alpha = reflect(l, n).dot(v);
                record.step(|| format!("cos α = R · V = {}", number(cos_alpha)));
                let f = Phong { kd, ks, shine }.eval(n, l, v);
                record
                    .step(|| format!("f_r = kd + ks (cos⁺α)^shine / cos θin = {} 1/sr", number(f)));
                f
            }
            ShadeModel::BlinnPhong | ShadeModel::BlinnPhongReciprocal => {
                step_half_vector(record, n, l, v);
                let f = if self == ShadeModel::BlinnPhong {
                    let f = BlinnPhong { kd, ks, shine }.eval(n, l, v);
                    record.step(|| {
                        format!("f_r = kd + ks (cos⁺δ)^shine / cos⁺θin = {} 1/sr", number(f))
                    });
                    f
                } else {
                    let f = BlinnPhongReciprocal { kd, ks, shine }.eval(n, l, v);
                    record.step(|| {
                        format!(
                            "f_r = kd + ks (cos⁺δ)^shine / |L + V|² = {} 1/sr",
                            number(f)
                        )
                    });
                    f
                };
                f
            }
        }
    }
}

fn step_half_vector(record: &mut Record, n: DVec3, l: DVec3, v: DVec3) {
    match half_vector(l, v) {
        Some(h) => {
            record.step(|| format!("H = (L + V) / |L + V| = {}", vector(h.to_array())));
            record.step(|| format!("cos δ = N · H = {}", number(n.dot(h))));
        }
        None => {
            record.step(|| "L = −V: no half vector, the highlight term is 0".to_owned());
        }
    }
}

/// Notes that `model`'s coefficients are all 0 (their value when not
/// given): the surface reflects nothing.
fn note_no_coefficients(
    record: &mut Record,
    model: ShadeModel,
    (kd, ks): (f64, f64),
    via: Via,
    lang: Lang,
) {
    let coefficients_used: &[(&str, f64)] = match model {
        ShadeModel::Lambert | ShadeModel::CourseLambert => &[("kd", kd)],
        _ => &[("kd", kd), ("ks", ks)],
    };
    if coefficients_used.iter().all(|&(_, c)| c == 0.0) {
        let names: Vec<String> = coefficients_used.iter().map(|(f, _)| via.name(f)).collect();
        let names = names.join(lang.pick(" and ", " és "));
        record.note(match coefficients_used.len() {
            1 => say!(
                lang,
                "{} is 0 (its value when not given): this surface reflects nothing",
                "{} értéke 0 (megadás nélkül ennyi): ez a felület semmit sem ver vissza",
                names
            ),
            _ => say!(
                lang,
                "{} are both 0 (their value when not given): this surface reflects nothing",
                "{} értéke egyaránt 0 (megadás nélkül ennyi): ez a felület semmit sem ver vissza",
                names
            ),
        });
    }
}
