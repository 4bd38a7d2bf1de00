//! `optics quiz`: the worked exercises of the course's quiz (`003`, "Kvíz"),
//! solved with the radiometry laws, step by step, and compared with the
//! answers printed in the course.

use crate::error::{Error, ErrorKind};
use crate::input::{Vec3Arg, Via};
use crate::lang::{say, Lang};
use crate::laws::{ShadeArgs, ShadeModel};
use crate::record::{number, percent, Answer, Record};
use anyhow::Result;
use glam::DVec3;
use radiometry::fresnel::f0;
use radiometry::radiance::point_irradiance;
use radiometry::snell::critical_angle;
use serde::Deserialize;
use serde_json::{json, Value};

#[derive(clap::Args, Debug)]
#[command(
    allow_negative_numbers = true,
    after_help = "Examples:
  optics quiz                 (lists the exercises)
  optics quiz seed            (works every question of the course's quiz)
  optics quiz f0 --n 1.4
  optics --lang hu quiz seed"
)]
pub struct QuizArgs {
    #[command(subcommand)]
    pub exercise: Option<Exercise>,
}

#[derive(clap::Subcommand, Debug)]
pub enum Exercise {
    /// Every question of the course's quiz, with the printed answers checked.
    #[command(after_help = "Examples:
  optics quiz seed
  optics --lang hu quiz seed          (in the course's language)
  optics --json quiz seed             (one JSON object; the questions under details.questions)")]
    Seed,
    /// Reflectance at normal incidence, F0, from the refractive index.
    F0(F0Args),
    /// Radiance reflected by the course's Lambert surface under a directional light.
    Lambert(LambertArgs),
    /// The critical angle of total internal reflection, from a medium into air.
    CriticalAngle(CriticalAngleArgs),
    /// Radiance reflected by the course's Phong-Blinn surface under a directional light.
    BlinnPhong(BlinnPhongArgs),
}

/// The exercises, for `optics quiz` without one: name, what it solves, example.
const EXERCISES: [(&str, &str, &str, &str); 5] = [
    (
        "seed",
        "every question of the course's quiz (003), printed answers checked",
        "a kurzus kvízének (003) minden kérdése, a közölt megoldások ellenőrzésével",
        "optics quiz seed",
    ),
    (
        "f0",
        "reflectance at normal incidence from n (and kappa)",
        "merőleges visszaverődés n-ből (és kappából)",
        "optics quiz f0 --n 1.4",
    ),
    (
        "lambert",
        "radiance from the course's diffuse surface",
        "a kurzus diffúz felületéről visszavert sugársűrűség",
        "optics quiz lambert --normal 0,0,1 --light-dir 0,3,4 --view-dir 1,2,3 --radiance 5 --kd 0.6",
    ),
    (
        "critical-angle",
        "the critical angle from a medium of index n into air",
        "a teljes visszaverődés határszöge n törésmutatójú közegből levegőbe",
        "optics quiz critical-angle --n 10",
    ),
    (
        "blinn-phong",
        "radiance from the course's Phong-Blinn surface",
        "a kurzus Phong–Blinn felületéről visszavert sugársűrűség",
        "optics quiz blinn-phong --normal 0,0,1 --light-dir 0,3,4 --view-dir 0,4,3 --radiance 5 --ks 1.41421356 --shine 3",
    ),
];

/// The list of exercises, as a record.
pub fn list(lang: Lang) -> Record {
    let mut record = Record::new(
        "quiz",
        say!(
            lang,
            "Exercises `optics quiz` solves:",
            "Az `optics quiz` feladatai:"
        ),
        "",
    );
    for (name, en, hu, example) in EXERCISES {
        record.step(format!(
            "{name:<15} {}\n                    {example}",
            lang.pick(en, hu)
        ));
    }
    record.answer = Answer::List(EXERCISES.iter().map(|e| Value::from(e.0)).collect());
    record
}

/// Normal-incidence reflectance from the index (and extinction).
#[derive(clap::Args, Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[command(
    allow_negative_numbers = true,
    after_help = "Example (quiz question 2):\n  optics quiz f0 --n 1.4"
)]
pub struct F0Args {
    /// Refractive index (relative to the outside medium).
    #[arg(long)]
    pub n: f64,
    /// Extinction coefficient (0 for a dielectric).
    #[arg(long, default_value_t = 0.0)]
    #[serde(default)]
    pub kappa: f64,
}

impl F0Args {
    pub fn solve(&self, via: Via, lang: Lang) -> Result<Record> {
        let n = via.index("n", self.n)?;
        let kappa = via.extinction("kappa", self.kappa)?;
        let mut record = Record::new(
            "f0",
            say!(
                lang,
                "Reflectance at normal incidence, F0",
                "Merőleges beesésű visszaverődés, F0"
            ),
            "1",
        );
        record.input("n", n).input("kappa", kappa);
        record.step("F0 = ((n − 1)² + κ²) / ((n + 1)² + κ²)".to_owned());
        record.step(format!(
            "   = (({} − 1)² + {}²) / (({} + 1)² + {}²)",
            number(n),
            number(kappa),
            number(n),
            number(kappa)
        ));
        let value = f0(n, kappa);
        record.step(format!("   = {} = {}", number(value), percent(value, 2)));
        record.answer = Answer::Number(value);
        record.answer_text = Some(format!("{} ({})", number(value), percent(value, 2)));
        record.detail("percent", value * 100.0);
        Ok(record)
    }
}

/// The course's Lambert exercise (quiz question 3).
#[derive(clap::Args, Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[command(
    allow_negative_numbers = true,
    after_help = "Example (quiz question 3):
  optics quiz lambert --normal 0,0,1 --light-dir 0,3,4 --view-dir 1,2,3 --radiance 5 --kd 0.6"
)]
pub struct LambertArgs {
    /// Surface normal (any length).
    #[arg(long, allow_hyphen_values = true)]
    pub normal: Vec3Arg,
    /// Direction towards the light (any length).
    #[arg(long, allow_hyphen_values = true)]
    pub light_dir: Vec3Arg,
    /// Direction towards the camera (any length).
    #[arg(long, allow_hyphen_values = true)]
    pub view_dir: Vec3Arg,
    /// The light's L_in, W/m² on a surface facing it.
    #[arg(long)]
    pub radiance: f64,
    /// The course's diffuse coefficient kd (f_r = kd, without 1/π).
    #[arg(long)]
    pub kd: f64,
}

impl LambertArgs {
    pub fn solve(&self, via: Via, lang: Lang) -> Result<Record> {
        let shade = ShadeArgs {
            model: ShadeModel::CourseLambert,
            normal: self.normal,
            light_dir: self.light_dir,
            view_dir: self.view_dir,
            radiance: self.radiance,
            kd: self.kd,
            ks: 0.0,
            shine: 1.0,
        };
        let mut shading = shade.shade("lambert", via, lang)?;
        let record = &mut shading.record;
        record.title = say!(
            lang,
            "The course's Lambert law: L_ref = L_in · kd · cos⁺θin",
            "Lambert-törvény a kurzus alakjában: L_ref = L_in · kd · cos⁺θin"
        );
        record.step(say!(
            lang,
            "the view direction does not enter: a Lambert surface looks equally bright from everywhere above it",
            "a nézeti irány nem számít: a Lambert-felület minden irányból egyformán fényes"
        ));
        let normalized = shading.radiance / std::f64::consts::PI;
        record.note(say!(
            lang,
            "physically normalised, f_r = kd/π, the same surface reflects {} W/(sr m^2); the course's kd is π times the albedo",
            "fizikailag normált alakban (f_r = kd/π) ugyanez {} W/(sr m^2); a kurzus kd-je az albedó π-szerese",
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
    #[arg(long)]
    pub n: f64,
    /// Index of the medium beyond the boundary (air: 1).
    #[arg(long, default_value_t = 1.0)]
    #[serde(default = "air")]
    pub n_outside: f64,
}

fn air() -> f64 {
    1.0
}

impl CriticalAngleArgs {
    pub fn solve(&self, via: Via, lang: Lang) -> Result<Record> {
        let n = via.index("n", self.n)?;
        let n_out = via.index("n_outside", self.n_outside)?;
        let mut record = Record::new(
            "critical_angle",
            say!(
                lang,
                "Critical angle of total internal reflection",
                "A teljes visszaverődés határszöge"
            ),
            "deg",
        );
        record.input("n", n).input("n_outside", n_out);
        record.step(say!(
            lang,
            "Snell: n sin θ = n_out sin θ_out; nothing leaves once θ_out would reach 90°",
            "Snellius–Descartes: n sin θ = n_ki sin θ_ki; semmi sem lép ki, ha θ_ki elérné a 90°-ot"
        ));
        let Some(theta_c) = critical_angle(n_out / n) else {
            let kind = ErrorKind::NoCriticalAngle {
                name: via.name("n"),
                n,
                name_outside: via.name("n_outside"),
                n_outside: n_out,
            };
            return Err(Error::from(kind).into());
        };
        record.step(format!(
            "sin θc = n_out / n = {} / {} = {}",
            number(n_out),
            number(n),
            number(n_out / n)
        ));
        let degrees = theta_c.to_degrees();
        record.step(format!(
            "θc = arcsin({}) = {}°",
            number(n_out / n),
            number(degrees)
        ));
        record.step(say!(
            lang,
            "θc is measured inside the medium, between the ray and the normal pointing towards the air",
            "θc a közegen belül mérendő, a sugár és a levegő felé mutató normális között"
        ));
        record.answer = Answer::Number(degrees);
        record.detail("radians", theta_c);
        Ok(record)
    }
}

/// The course's Phong-Blinn exercise (quiz question 5).
#[derive(clap::Args, Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[command(
    allow_negative_numbers = true,
    after_help = "Example (quiz question 5):
  optics quiz blinn-phong --normal 0,0,1 --light-dir 0,3,4 --view-dir 0,4,3 --radiance 5 --ks 1.41421356 --shine 3"
)]
pub struct BlinnPhongArgs {
    /// Surface normal (any length).
    #[arg(long, allow_hyphen_values = true)]
    pub normal: Vec3Arg,
    /// Direction towards the light (any length).
    #[arg(long, allow_hyphen_values = true)]
    pub light_dir: Vec3Arg,
    /// Direction towards the camera (any length).
    #[arg(long, allow_hyphen_values = true)]
    pub view_dir: Vec3Arg,
    /// The light's L_in, W/m² on a surface facing it.
    #[arg(long)]
    pub radiance: f64,
    /// Specular coefficient.
    #[arg(long)]
    pub ks: f64,
    /// Shininess exponent.
    #[arg(long)]
    pub shine: f64,
    /// Diffuse coefficient.
    #[arg(long, default_value_t = 0.0)]
    #[serde(default)]
    pub kd: f64,
}

impl BlinnPhongArgs {
    pub fn solve(&self, via: Via, lang: Lang) -> Result<Record> {
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
        let mut shading = shade.shade("blinn_phong", via, lang)?;
        shading.record.title = say!(
            lang,
            "The course's Phong-Blinn law: L_ref = L_in (kd + ks (cos⁺δ)^shine / cos⁺θin) cos⁺θin",
            "Phong–Blinn-modell a kurzus alakjában: L_ref = L_in (kd + ks (cos⁺δ)^shine / cos⁺θin) cos⁺θin"
        );
        Ok(shading.record)
    }
}

/// A record's answer as a number (NaN if it has none).
fn number_answer(record: &Record) -> f64 {
    match record.answer {
        Answer::Number(x) => x,
        _ => f64::NAN,
    }
}

/// An answer as printed in the course: its value and the digits shown.
struct Printed {
    text: &'static str,
    value: f64,
    decimals: usize,
}

/// Compares `ours` (in the printed answer's scale) with the printed answer
/// at the printed precision, and says how they differ.
fn check_printed(record: &mut Record, lang: Lang, ours: f64, printed: Printed) {
    let rounded = format!("{ours:.*}", printed.decimals);
    let agrees = rounded.parse::<f64>() == Ok(printed.value);
    record
        .detail("printed", printed.text)
        .detail("agrees_with_printed", agrees);
    if agrees {
        record.note(say!(
            lang,
            "agrees with the printed answer {}",
            "egyezik a közölt megoldással ({})",
            printed.text
        ));
        return;
    }
    let scale = 10f64.powi(printed.decimals as i32);
    let truncated = (ours * scale).trunc() / scale;
    let how = if truncated == printed.value {
        lang.pick("truncated instead of rounded", "csonkolva, nem kerekítve")
    } else {
        lang.pick("wrong", "hibás")
    };
    record.note(say!(
        lang,
        "the printed answer {} is {how}: the value is {} which rounds to {rounded}",
        "a közölt megoldás ({}) {how}: az érték {}, kerekítve {rounded}",
        printed.text,
        number(ours)
    ));
}

/// One true/false statement of question 1: the course's text, a translation,
/// the printed verdict, the verdict of the laws and why.
struct Statement {
    hu: &'static str,
    en: &'static str,
    printed: bool,
    correct: bool,
    why_en: String,
    why_hu: String,
}

fn statements() -> Vec<Statement> {
    // The largest Compton shift, at back-scattering: Δλ = 2h / (m_e c).
    const PLANCK: f64 = 6.626_070_15e-34; // J s, exact (SI 2019)
    const ELECTRON_MASS: f64 = 9.109_383_701_5e-31; // kg, CODATA 2018
    const LIGHT_SPEED: f64 = 299_792_458.0; // m/s, exact
    let compton_pm = 2.0 * PLANCK / (ELECTRON_MASS * LIGHT_SPEED) * 1e12;
    let relative = compton_pm * 1e-12 / 380e-9;
    // Irradiance from a 1 W/sr point light, facing it, at 1 m and 2 m.
    let irradiance_at = |r: f64| {
        point_irradiance(1.0, DVec3::new(0.0, 0.0, r), DVec3::ZERO, DVec3::Z)
            .map_or(f64::NAN, |s| s.irradiance)
    };
    let falloff = irradiance_at(1.0) / irradiance_at(2.0);
    vec![
        Statement {
            hu: "Egy kiterjedt felületről induló fénysugár sugársűrűsége a sugár mentén állandó.",
            en: "The radiance of a ray leaving an extended surface is constant along the ray.",
            printed: true,
            correct: true,
            why_en: "radiance is invariant along a ray in a non-participating medium: dΦ/(dA cos θ dω) keeps its value as the ray's footprint and solid angle trade off".into(),
            why_hu: "nem részt vevő közegben a sugársűrűség a sugár mentén állandó: a sugárnyaláb keresztmetszete és térszöge kiegyenlíti egymást".into(),
        },
        Statement {
            hu: "Egy pontszerű fényforrásból induló fénysugár sugársűrűsége a forrástól vett távolság négyzetével csökken.",
            en: "The radiance of a ray from a point source falls with the square of the distance from the source.",
            printed: true,
            correct: false,
            why_en: format!("radiance is invariant along a ray for every source; what falls as 1/r² is the irradiance a point source delivers, E = I cos θ / r² (at 1 m vs 2 m: ratio {})", number(falloff)),
            why_hu: format!("a sugársűrűség minden forrásnál állandó a sugár mentén; a pontforrás által keltett megvilágítás (irradiancia) csökken 1/r² szerint, E = I cos θ / r² (1 m és 2 m között: {}-szeres)", number(falloff)),
        },
        Statement {
            hu: "A fotontranszport szimulációnál a látható tartományba eső frekvenciájú fotonok elektronokkal rugalmasan ütközve sohasem változtatják meg a frekvenciájukat.",
            en: "In photon transport simulation, visible-frequency photons colliding elastically with electrons never change their frequency.",
            printed: true,
            correct: true,
            why_en: format!("as the rendering model assumes: the Compton shift is at most 2h/(m_e c) = {} pm, at most {} of a visible wavelength", number(compton_pm), number(relative)),
            why_hu: format!("a képszintézis modelljében igaz: a Compton-eltolódás legfeljebb 2h/(m_e c) = {} pm, a látható hullámhossz legfeljebb {}-szerese", number(compton_pm), number(relative)),
        },
        Statement {
            hu: "A törésmutató a két közegbeli fénysebességek arányával egyezik meg.",
            en: "The refractive index equals the ratio of the speeds of light in the two media.",
            printed: true,
            correct: true,
            why_en: "the relative index n₂/n₁ equals v₁/v₂ (the absolute index is c/v)".into(),
            why_hu: "a relatív törésmutató n₂/n₁ = v₁/v₂ (az abszolút törésmutató c/v)".into(),
        },
        Statement {
            hu: "A Fresnel függvény értékkészlete a [0,1] tartomány.",
            en: "The range of the Fresnel function is [0, 1].",
            printed: true,
            correct: true,
            why_en: "it is the reflected fraction of the incident power, and energy conservation bounds it (property test fresnel_is_a_fraction)".into(),
            why_hu: "a beeső teljesítmény visszavert hányada, az energiamegmaradás korlátozza (fresnel_is_a_fraction tulajdonságteszt)".into(),
        },
        Statement {
            hu: "Csak a 444, 526 és 645 nm hullámhosszú fényből állítható elő bármilyen színérzet additív keveréssel.",
            en: "Any colour sensation can be produced by additive mixing from light of 444, 526 and 645 nm only.",
            printed: false,
            correct: false,
            why_en: "three real primaries mix only the colours of a triangle in the chromaticity diagram, and the region of all colours is bounded by the curved spectral locus, so no three wavelengths cover it; other primaries mix colours too".into(),
            why_hu: "három valós alapszín csak a színpatkóba írt háromszög színeit keveri ki, a színek tartományát pedig a görbült spektrális vonal határolja, így három hullámhossz sem fedi le; más alapszínekkel is lehet keverni".into(),
        },
        Statement {
            hu: "Az emberi szem kizárólag a 444, 526 és 645 nm hullámhosszú fényre érzékeny.",
            en: "The human eye is sensitive only to light of 444, 526 and 645 nm.",
            printed: false,
            correct: false,
            why_en: "the cones respond to the whole visible band, about 380–780 nm, with overlapping sensitivity curves".into(),
            why_hu: "a csapok a teljes látható tartományra (kb. 380–780 nm) érzékenyek, átfedő görbékkel".into(),
        },
        Statement {
            hu: "A Fresnel függvény mértékegysége [W/m^2/st] (Watt per négyzetméter per szteradián).",
            en: "The unit of the Fresnel function is W/(m² sr).",
            printed: false,
            correct: false,
            why_en: "Fresnel reflectance is a ratio of powers, dimensionless; W/(sr m²) is the unit of radiance".into(),
            why_hu: "a Fresnel-függvény teljesítmények aránya, mértékegység nélküli; a W/(sr m²) a sugársűrűség egysége".into(),
        },
        Statement {
            hu: "A fotontranszport szimulációnál a fotonok elektronokkal rugalmasan ütközve sohasem változtatják meg a frekvenciájukat.",
            en: "In photon transport simulation, photons colliding elastically with electrons never change their frequency.",
            printed: false,
            correct: false,
            why_en: format!("at high energies the Compton shift (up to {} pm) is a large part of the wavelength: X-rays and gamma rays change frequency", number(compton_pm)),
            why_hu: format!("nagy energián a Compton-eltolódás (legfeljebb {} pm) a hullámhossz jelentős része: röntgen- és gammafotonok frekvenciája változik", number(compton_pm)),
        },
    ]
}

fn question_one(lang: Lang) -> Record {
    let mut record = Record::new(
        "quiz_true_false",
        say!(
            lang,
            "Question 1: which statements are true?",
            "1. kérdés: mely állítások igazak?"
        ),
        "",
    );
    let mut answers = Vec::new();
    let mut table = Vec::new();
    for (i, s) in statements().into_iter().enumerate() {
        let verdict = |b: bool| match (b, lang) {
            (true, Lang::En) => "true",
            (false, Lang::En) => "false",
            (true, Lang::Hu) => "igaz",
            (false, Lang::Hu) => "hamis",
        };
        let text = lang.pick(s.en, s.hu);
        let why = lang.pick(&s.why_en, &s.why_hu).to_owned();
        record.step(format!(
            "{}. [{}] {text} — {why}",
            i + 1,
            verdict(s.correct)
        ));
        if s.printed != s.correct {
            record.note(say!(
                lang,
                "statement {} is printed as {} but is {}: {}",
                "a(z) {}. állítás a megoldásban {}, valójában {}: {}",
                i + 1,
                verdict(s.printed),
                verdict(s.correct),
                why
            ));
        }
        answers.push(Value::Bool(s.correct));
        table.push(json!({
            "statement_hu": s.hu, "statement_en": s.en,
            "printed": s.printed, "correct": s.correct, "why": why,
        }));
    }
    let agrees = table.iter().all(|t| t["printed"] == t["correct"]);
    record.answer = Answer::List(answers);
    record
        .detail("statements", table)
        .detail("agrees_with_printed", agrees);
    record
}

/// Every question of the course's quiz, worked.
pub fn seed(lang: Lang) -> Result<Vec<Record>> {
    let via = Via::Flags;
    let mut q2 = F0Args { n: 1.4, kappa: 0.0 }.solve(via, lang)?;
    let f = number_answer(&q2);
    q2.title = say!(lang, "Question 2: {}", "2. kérdés: {}", q2.title);
    check_printed(
        &mut q2,
        lang,
        f * 100.0,
        Printed {
            text: "2.77 %",
            value: 2.77,
            decimals: 2,
        },
    );

    let mut q3 = LambertArgs {
        normal: Vec3Arg([0.0, 0.0, 1.0]),
        light_dir: Vec3Arg([0.0, 3.0, 4.0]),
        view_dir: Vec3Arg([1.0, 2.0, 3.0]),
        radiance: 5.0,
        kd: 0.6,
    }
    .solve(via, lang)?;
    let l3 = number_answer(&q3);
    q3.title = say!(lang, "Question 3: {}", "3. kérdés: {}", q3.title);
    check_printed(
        &mut q3,
        lang,
        l3,
        Printed {
            text: "2.4",
            value: 2.4,
            decimals: 1,
        },
    );

    let mut q4 = CriticalAngleArgs {
        n: 10.0,
        n_outside: 1.0,
    }
    .solve(via, lang)?;
    let theta = number_answer(&q4);
    q4.title = say!(lang, "Question 4: {}", "4. kérdés: {}", q4.title);
    check_printed(
        &mut q4,
        lang,
        theta,
        Printed {
            text: "5.74°",
            value: 5.74,
            decimals: 2,
        },
    );
    q4.note(say!(
        lang,
        "the printed working labels the angle in the medium θ and then writes θin = arcsin(1/10); θin there is the angle in the air, 90°",
        "a közölt levezetés a közegbeli szöget θ-nak nevezi, majd θin = arcsin(1/10)-et ír; ott θin a levegőbeli szög, 90°"
    ));

    let mut q5 = BlinnPhongArgs {
        normal: Vec3Arg([0.0, 0.0, 1.0]),
        light_dir: Vec3Arg([0.0, 3.0, 4.0]),
        view_dir: Vec3Arg([0.0, 4.0, 3.0]),
        radiance: 5.0,
        ks: std::f64::consts::SQRT_2,
        shine: 3.0,
        kd: 0.0,
    }
    .solve(via, lang)?;
    let l5 = number_answer(&q5);
    q5.title = say!(lang, "Question 5: {}", "5. kérdés: {}", q5.title);
    check_printed(
        &mut q5,
        lang,
        l5,
        Printed {
            text: "2.5",
            value: 2.5,
            decimals: 1,
        },
    );

    let mut questions = vec![question_one(lang), q2, q3, q4, q5];
    for (i, q) in questions.iter_mut().enumerate() {
        q.detail("question", i + 1);
    }
    Ok(questions)
}

/// The whole quiz as one record, for `--json`.
pub fn seed_record(lang: Lang) -> Result<Record> {
    let questions = seed(lang)?;
    let mut record = Record::new(
        "quiz_seed",
        say!(lang, "The course's quiz (003)", "A kurzus kvíze (003)"),
        "",
    );
    record.input("source", "003_4d80759929b48f79.txt");
    record.answer = Answer::List(
        questions
            .iter()
            .map(|q| serde_json::to_value(&q.answer).unwrap_or(Value::Null))
            .collect(),
    );
    for q in &questions {
        let agrees = q.details.get("agrees_with_printed") == Some(&Value::Bool(true));
        record.step(format!(
            "{} — {}",
            q.title,
            if agrees {
                lang.pick(
                    "agrees with the printed answer",
                    "egyezik a közölt megoldással",
                )
            } else {
                lang.pick(
                    "differs from the printed answer",
                    "eltér a közölt megoldástól",
                )
            }
        ));
    }
    let values: Vec<Value> = questions
        .iter()
        .map(|q| serde_json::to_value(q).unwrap_or(Value::Null))
        .collect();
    record.detail("questions", values);
    Ok(record)
}
