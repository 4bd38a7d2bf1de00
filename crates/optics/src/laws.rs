//! The law evaluators: `optics fresnel`, `refract`, `reflect`, `shade`.
//!
//! Each takes its inputs either as flags or as a JSON request (the same
//! struct serves both), checks them, calls the radiometry crate for every
//! number, and returns a [`Record`] with the working.

use crate::input::{Vec3Arg, Via};
use crate::lang::{say, Lang};
use crate::record::{number, vector, Answer, Record};
use anyhow::{bail, Result};
use glam::DVec3;
use radiometry::brdf::{
    half_vector, BlinnPhong, BlinnPhongReciprocal, Brdf, CourseLambert, Lambert, Phong,
};
use radiometry::domain::Direction;
use radiometry::fresnel::{
    conductor_polarized, dielectric_polarized, f0, schlick, schlick_dielectric,
};
use radiometry::radiance::{directional_irradiance, reflected_radiance};
use radiometry::snell::Incidence;
use radiometry::specular::{reflect, refract};
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

        let incidence = Incidence::resolve(cos_i, eta)
            .expect("cos_i and eta were validated by radiometry::domain above");
        let theta_deg = incidence.abs_cos_i.acos().to_degrees();
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
            number(theta_deg)
        ));

        let reflectance = match (self.model, kappa > 0.0) {
            (FresnelModel::Exact, false) => {
                let fresnel = dielectric_polarized(cos_i, eta);
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
                        number(incidence.n_i * incidence.abs_cos_i.acos().sin() / incidence.n_t)
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
            (FresnelModel::Exact, true) => {
                let fresnel = conductor_polarized(cos_i, eta, kappa);
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
            (FresnelModel::Schlick, conductor) => {
                let f_0 = f0(eta, kappa);
                record.step(format!(
                    "F0 = ((η − 1)² + κ²) / ((η + 1)² + κ²) = {}",
                    number(f_0)
                ));
                let r = if conductor {
                    schlick(incidence.abs_cos_i, f_0)
                } else {
                    schlick_dielectric(cos_i, eta)
                };
                let cos = if !conductor && incidence.n_t < incidence.n_i {
                    match dielectric_polarized(cos_i, eta).cos_t {
                        Some(cos_t) => {
                            record.step(say!(
                                lang,
                                "from the denser side Schlick takes the angle in the rarer medium: cos θt = {}",
                                "a sűrűbb oldalról Schlick a ritkább közegbeli szöget használja: cos θt = {}",
                                number(cos_t)
                            ));
                            Some(cos_t)
                        }
                        None => {
                            record.step(say!(
                                lang,
                                "beyond the critical angle: total internal reflection, R = 1",
                                "a határszögön túl: teljes visszaverődés, R = 1"
                            ));
                            None
                        }
                    }
                } else {
                    Some(incidence.abs_cos_i)
                };
                if let Some(cos) = cos {
                    record.step(format!(
                        "R ≈ F0 + (1 − F0)(1 − cos θ)⁵ = {} + {}·{}⁵ = {}",
                        number(f_0),
                        number(1.0 - f_0),
                        number(1.0 - cos),
                        number(r)
                    ));
                }
                let exact = if conductor {
                    conductor_polarized(cos_i, eta, kappa).reflectance()
                } else {
                    dielectric_polarized(cos_i, eta).reflectance()
                };
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
        };
        record.answer = Answer::Number(reflectance);
        Ok(record)
    }
}

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
    #[arg(long)]
    pub eta: f64,
}

impl RefractArgs {
    pub fn solve(&self, via: Via, lang: Lang) -> Result<Record> {
        let wi = via.direction("wi", self.wi)?;
        let n = via.direction("normal", self.normal)?;
        let eta = via.index("eta", self.eta)?;
        let mut record = Record::new(
            "refract",
            say!(lang, "Refracted direction", "Törési irány"),
            "1",
        );
        record
            .input("wi", self.wi.0)
            .input("normal", self.normal.0)
            .input("eta", eta);
        note_normalized(&mut record, lang, "wi", &wi);
        note_normalized(&mut record, lang, "normal", &n);
        let cos_i = wi.unit.dot(n.unit);
        let incidence = Incidence::resolve(cos_i, eta)
            .expect("wi, normal and eta were validated by radiometry::domain above");
        record.step(format!("cos θi = n · ωi = {}", number(cos_i)));
        record.step(if incidence.from_inside {
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
        });
        match refract(wi.unit, n.unit, eta) {
            Some(t) => {
                record.step(say!(
                    lang,
                    "Snell: cos θt = {} (θt = {}°)",
                    "Snellius–Descartes: cos θt = {} (θt = {}°)",
                    number(t.cos_t),
                    number(t.cos_t.acos().to_degrees())
                ));
                record.step(format!(
                    "ωt = −ωi/η' + (cos θi/η' − cos θt) n' = {}",
                    vector(t.direction.to_array())
                ));
                record.answer = Answer::Vector(t.direction.to_array());
                record
                    .detail("outcome", "refracted")
                    .detail("eta_path", t.eta_path)
                    .detail("cos_t", t.cos_t);
            }
            None => {
                let mirror = reflect(wi.unit, n.unit);
                record.step(say!(
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
        }
        Ok(record)
    }
}

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
    pub fn solve(&self, via: Via, lang: Lang) -> Result<Record> {
        let wi = via.direction("wi", self.wi)?;
        let n = via.direction("normal", self.normal)?;
        let mut record = Record::new("reflect", say!(lang, "Mirror direction", "Tükörirány"), "1");
        record.input("wi", self.wi.0).input("normal", self.normal.0);
        note_normalized(&mut record, lang, "wi", &wi);
        note_normalized(&mut record, lang, "normal", &n);
        let r = reflect(wi.unit, n.unit);
        record.step(format!("cos θi = n · ωi = {}", number(wi.unit.dot(n.unit))));
        record.step(format!("ωr = 2 (n · ωi) n − ωi = {}", vector(r.to_array())));
        record.answer = Answer::Vector(r.to_array());
        Ok(record)
    }
}

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
    /// The BRDF model.
    #[arg(long, value_enum, default_value_t)]
    #[serde(default)]
    pub model: ShadeModel,
    /// Surface normal (any length).
    #[arg(long, allow_hyphen_values = true)]
    pub normal: Vec3Arg,
    /// Direction towards the light (any length).
    #[arg(long, allow_hyphen_values = true)]
    pub light_dir: Vec3Arg,
    /// Direction towards the viewer (any length).
    #[arg(long, allow_hyphen_values = true)]
    pub view_dir: Vec3Arg,
    /// The light's L_in, W/m² on a surface facing it.
    #[arg(long)]
    pub radiance: f64,
    /// Diffuse coefficient (the albedo for `lambert`).
    #[arg(long, default_value_t = 0.0)]
    #[serde(default)]
    pub kd: f64,
    /// Specular coefficient.
    #[arg(long, default_value_t = 0.0)]
    #[serde(default)]
    pub ks: f64,
    /// Shininess exponent.
    #[arg(long, default_value_t = 1.0)]
    #[serde(default = "one")]
    pub shine: f64,
}

fn one() -> f64 {
    1.0
}

/// A shading evaluation's numbers, for the quiz solvers built on it.
pub struct Shading {
    pub record: Record,
    pub radiance: f64,
}

impl ShadeArgs {
    pub fn solve(&self, via: Via, lang: Lang) -> Result<Record> {
        Ok(self.shade("shade", via, lang)?.record)
    }

    /// Shades and records the working under the name `law`.
    pub fn shade(&self, law: &'static str, via: Via, lang: Lang) -> Result<Shading> {
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
        );
        record
            .input("model", model.name())
            .input("normal", self.normal.0)
            .input("light_dir", self.light_dir.0)
            .input("view_dir", self.view_dir.0)
            .input("radiance", l_in);
        match model {
            ShadeModel::Lambert | ShadeModel::CourseLambert => record.input("kd", kd),
            _ => record.input("kd", kd).input("ks", ks).input("shine", shine),
        };
        note_normalized(&mut record, lang, "normal", &n);
        note_normalized(&mut record, lang, "light_dir", &l);
        note_normalized(&mut record, lang, "view_dir", &v);
        let (n, l, v) = (n.unit, l.unit, v.unit);
        record.step(format!(
            "L = {}, V = {}",
            vector(l.to_array()),
            vector(v.to_array())
        ));
        let cos_in = n.dot(l);
        record.step(format!("cos θin = N · L = {}", number(cos_in)));
        let f = match model {
            ShadeModel::Lambert => {
                let f = Lambert { albedo: kd }.eval(n, l, v);
                record.step(format!("f_r = kd / π = {}", number(f)));
                f
            }
            ShadeModel::CourseLambert => {
                let f = CourseLambert { kd }.eval(n, l, v);
                record.step(format!("f_r = kd = {}", number(f)));
                f
            }
            ShadeModel::Phong => {
                let cos_alpha = reflect(l, n).dot(v);
                record.step(format!("cos α = R · V = {}", number(cos_alpha)));
                let f = Phong { kd, ks, shine }.eval(n, l, v);
                record.step(format!(
                    "f_r = kd + ks (cos⁺α)^shine / cos θin = {}",
                    number(f)
                ));
                f
            }
            ShadeModel::BlinnPhong | ShadeModel::BlinnPhongReciprocal => {
                step_half_vector(&mut record, n, l, v);
                let f = if model == ShadeModel::BlinnPhong {
                    let f = BlinnPhong { kd, ks, shine }.eval(n, l, v);
                    record.step(format!(
                        "f_r = kd + ks (cos⁺δ)^shine / cos⁺θin = {}",
                        number(f)
                    ));
                    f
                } else {
                    let f = BlinnPhongReciprocal { kd, ks, shine }.eval(n, l, v);
                    record.step(format!(
                        "f_r = kd + ks (cos⁺δ)^shine / |L + V|² = {}",
                        number(f)
                    ));
                    f
                };
                f
            }
        };
        let e = directional_irradiance(l_in, n, l);
        record.step(format!(
            "E = L_in cos⁺θin = {} · {} = {}",
            number(l_in),
            number(cos_in.max(0.0)),
            number(e)
        ));
        let radiance = reflected_radiance(f, e);
        record.step(format!(
            "L_ref = f_r · E = {} · {} = {}",
            number(f),
            number(e),
            number(radiance)
        ));
        if n.dot(v) <= 0.0 {
            record.note(say!(
                lang,
                "the viewer is below the surface: nothing is reflected towards it",
                "a néző a felület alatt van: felé semmi sem verődik vissza"
            ));
        }
        record.answer = Answer::Number(radiance);
        record.detail("brdf", f).detail("irradiance", e);
        Ok(Shading { record, radiance })
    }
}

fn step_half_vector(record: &mut Record, n: DVec3, l: DVec3, v: DVec3) {
    match half_vector(l, v) {
        Some(h) => {
            record.step(format!("H = (L + V) / |L + V| = {}", vector(h.to_array())));
            record.step(format!("cos δ = N · H = {}", number(n.dot(h))));
        }
        None => {
            record.step("L = −V: no half vector, the highlight term is 0".to_owned());
        }
    }
}

/// Says in the working when a direction was not unit length.
pub fn note_normalized(record: &mut Record, lang: Lang, field: &str, d: &Direction) {
    if d.was_normalized() {
        record.step(say!(
            lang,
            "{field} has length {}: normalised to {}",
            "{field} hossza {}: normalizálva {}",
            number(d.given_length),
            vector(d.unit.to_array())
        ));
    }
}
