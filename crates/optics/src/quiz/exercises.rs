//! The quiz's exercises that take other numbers too: `optics quiz f0`,
//! `lambert`, `critical-angle` and `blinn-phong`, each also a law of
//! `optics batch`.

use crate::error::Result;
use crate::error::{Error, ErrorKind};
use crate::input::{Vec3Arg, Via};
use crate::laws::{lit_surface_args, ShadeArgs, ShadeModel};
use radiometry::fresnel::f0;
use radiometry::snell::critical_angle;
use record::{number, percent, Answer, Record, Steps};
use record::{say, Lang};
use serde::Deserialize;

/// Normal-incidence reflectance from the index (and extinction).
#[derive(clap::Args, Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[command(
    allow_negative_numbers = true,
    after_help = "Example (quiz question 2):\n  optics quiz f0 --n 1.4"
)]
pub struct F0Args {
    /// Refractive index (relative to the outside medium).
    #[arg(long, allow_hyphen_values = true)]
    pub n: f64,
    /// Extinction coefficient (0 for a dielectric).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    #[serde(default)]
    pub kappa: f64,
}

impl F0Args {
    /// Evaluates the law: its inputs checked (named as `via` gives them), the working in `lang`.
    pub fn solve(&self, via: Via, lang: Lang, steps: Steps) -> Result<Record> {
        let n = via.index("n", self.n)?;
        let kappa = via.extinction("kappa", self.kappa)?;
        let mut record = Record::new(
            Self::LAW,
            say!(
                lang,
                "Reflectance at normal incidence, F0",
                "Merőleges beesésű visszaverődés, F0"
            ),
            "1",
        )
        .with_steps(steps);
        record.input("n", n).input("kappa", kappa);
        record.step(|| "F0 = ((n − 1)² + κ²) / ((n + 1)² + κ²)".to_owned());
        record.step(|| {
            format!(
                "   = (({} − 1)² + {}²) / (({} + 1)² + {}²)",
                number(n),
                number(kappa),
                number(n),
                number(kappa)
            )
        });
        let value = f0(n, kappa);
        record.step(|| format!("   = {} = {}", number(value), percent(value, 2)));
        record.answer = Answer::Number(value);
        record.answer_text = Some(format!("{} ({})", number(value), percent(value, 2)));
        record.detail("percent", value * 100.0);
        Ok(record)
    }
}

lit_surface_args! {
/// The course's Lambert exercise (quiz question 3).
#[derive(clap::Args, Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[command(
    allow_negative_numbers = true,
    after_help = "Example (quiz question 3):
  optics quiz lambert --normal 0,0,1 --light-dir 0,3,4 --view-dir 1,2,3 --radiance 5 --kd 0.6"
)]
pub struct LambertArgs {
    /// Direction towards the camera (any length; optional: a Lambert
    /// surface looks alike from every direction above it, and nothing is
    /// seen from below).
    view_dir: Option<Vec3Arg>,
    /// The course's diffuse coefficient kd (f_r = kd, without 1/π).
    #[arg(long, allow_hyphen_values = true)]
    pub kd: f64,
}
}

impl LambertArgs {
    /// Evaluates the law: its inputs checked (named as `via` gives them), the working in `lang`.
    pub fn solve(&self, via: Via, lang: Lang, steps: Steps) -> Result<Record> {
        let shade = ShadeArgs {
            model: ShadeModel::CourseLambert,
            normal: self.normal,
            light_dir: self.light_dir,
            // Without a view direction, the viewer looks along the normal.
            view_dir: self.view_dir.unwrap_or(self.normal),
            radiance: self.radiance,
            kd: self.kd,
            ks: 0.0,
            shine: 1.0,
        };
        let mut shading = shade.shade(Self::LAW, via, lang, steps)?;
        let record = &mut shading.record;
        record.title = say!(
            lang,
            "The course's Lambert law: L_ref = L_in · kd · cos⁺θin",
            "Lambert-törvény a kurzus alakjában: L_ref = L_in · kd · cos⁺θin"
        );
        record.step(|| match self.view_dir {
            Some(_) => say!(
                lang,
                "the view direction does not enter: a Lambert surface looks equally bright from everywhere above it",
                "a nézeti irány nem számít: a Lambert-felület minden fölötte lévő irányból egyformán fényesnek látszik"
            ),
            None => say!(
                lang,
                "no view direction is needed: a Lambert surface looks equally bright from everywhere above it",
                "nézeti irány nem kell: a Lambert-felület minden fölötte lévő irányból egyformán fényesnek látszik"
            ),
        });
        let normalized = shading.radiance / std::f64::consts::PI;
        record.note(say!(
            lang,
            "physically normalised, f_r = kd/π, the same surface reflects {} W/(sr m^2); the course's kd is π times the albedo",
            "fizikailag normált alakban (f_r = kd/π) ugyanez a felület {} W/(sr m^2) sugársűrűséget ver vissza; a kurzus kd-je az albedó π-szerese",
            number(normalized)
        ));
        record.detail("normalized_lambert", normalized);
        Ok(shading.record)
    }
}

/// The critical angle exercise (quiz question 4).
#[derive(clap::Args, Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[command(
    allow_negative_numbers = true,
    after_help = "Example (quiz question 4: index 1/0.1 = 10, into air):\n  optics quiz critical-angle --n 10"
)]
pub struct CriticalAngleArgs {
    /// Index of the medium the light comes from.
    #[arg(long, allow_hyphen_values = true)]
    pub n: f64,
    /// Index of the medium beyond the boundary (air: 1).
    #[arg(long, default_value_t = 1.0, allow_hyphen_values = true)]
    #[serde(default = "air")]
    pub n_outside: f64,
}

fn air() -> f64 {
    1.0
}

impl CriticalAngleArgs {
    /// Evaluates the law: its inputs checked (named as `via` gives them), the working in `lang`.
    pub fn solve(&self, via: Via, lang: Lang, steps: Steps) -> Result<Record> {
        let n = via.index("n", self.n)?;
        let n_out = via.index("n_outside", self.n_outside)?;
        let mut record = Record::new(
            Self::LAW,
            say!(
                lang,
                "Critical angle of total internal reflection",
                "A teljes visszaverődés határszöge"
            ),
            "deg",
        )
        .with_steps(steps);
        record.input("n", n).input("n_outside", n_out);
        record.step(|| {
            say!(
            lang,
            "Snell: n sin θ = n_out sin θ_out; nothing leaves once θ_out would reach 90°",
            "Snellius–Descartes: n sin θ = n_out sin θ_out; semmi sem lép ki, ha θ_out elérné a 90°-ot"
        )
        });
        let Some(theta_c) = critical_angle(n_out / n) else {
            let kind = ErrorKind::NoCriticalAngle {
                name: via.name("n"),
                n,
                name_outside: via.name("n_outside"),
                n_outside: n_out,
            };
            return Err(Error::from(kind));
        };
        record.step(|| {
            format!(
                "sin θc = n_out / n = {} / {} = {}",
                number(n_out),
                number(n),
                number(n_out / n)
            )
        });
        let degrees = theta_c.to_degrees();
        record.step(|| format!("θc = arcsin({}) = {}°", number(n_out / n), number(degrees)));
        // Into air (the quiz's case) the normal points towards the air; any
        // other outside medium is named by its index.
        record.step(|| {
            if n_out == 1.0 {
                say!(
                    lang,
                    "θc is measured inside the medium, between the ray and the normal pointing towards the air",
                    "θc a közegen belül mérendő, a sugár és a levegő felé mutató normális között"
                )
            } else {
                say!(
                    lang,
                    "θc is measured inside the medium, between the ray and the normal pointing towards the outside medium (n_out = {})",
                    "θc a közegen belül mérendő, a sugár és a külső közeg (n_out = {}) felé mutató normális között",
                    number(n_out)
                )
            }
        });
        record.answer = Answer::Number(degrees);
        record.detail("radians", theta_c);
        Ok(record)
    }
}

lit_surface_args! {
/// The course's Phong-Blinn exercise (quiz question 5).
#[derive(clap::Args, Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[command(
    allow_negative_numbers = true,
    after_help = "Example (quiz question 5):
  optics quiz blinn-phong --normal 0,0,1 --light-dir 0,3,4 --view-dir 0,4,3 --radiance 5 --ks 1.41421356 --shine 3"
)]
pub struct BlinnPhongArgs {
    /// Direction towards the camera (any length).
    view_dir: Vec3Arg,
    /// Specular coefficient.
    #[arg(long, allow_hyphen_values = true)]
    pub ks: f64,
    /// Shininess exponent.
    #[arg(long, allow_hyphen_values = true)]
    pub shine: f64,
    /// Diffuse coefficient.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    #[serde(default)]
    pub kd: f64,
}
}

impl BlinnPhongArgs {
    /// Evaluates the law: its inputs checked (named as `via` gives them), the working in `lang`.
    pub fn solve(&self, via: Via, lang: Lang, steps: Steps) -> Result<Record> {
        let shade = ShadeArgs {
            model: ShadeModel::BlinnPhong,
            normal: self.normal,
            light_dir: self.light_dir,
            view_dir: self.view_dir,
            radiance: self.radiance,
            kd: self.kd,
            ks: self.ks,
            shine: self.shine,
        };
        let mut shading = shade.shade(Self::LAW, via, lang, steps)?;
        shading.record.title = say!(
            lang,
            "The course's Phong-Blinn law: L_ref = L_in (kd + ks (cos⁺δ)^shine / cos⁺θin) cos⁺θin",
            "Phong–Blinn-modell a kurzus alakjában: L_ref = L_in (kd + ks (cos⁺δ)^shine / cos⁺θin) cos⁺θin"
        );
        Ok(shading.record)
    }
}
