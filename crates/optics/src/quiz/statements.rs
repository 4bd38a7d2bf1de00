//! Question 1 of the quiz: nine true/false statements, each with the
//! printed verdict, the verdict of the laws, and why.

use glam::DVec3;
use radiometry::photon::compton_shift_m;
use radiometry::radiance::point_irradiance;
use record::{number, Answer, Record};
use record::{say, Lang};
use serde_json::{json, Value};

/// One true/false statement of question 1: the course's text, a translation,
/// the printed verdict, the verdict of the laws and why. The reasons name
/// the numbers they quote as `{falloff}`, `{compton_pm}` and `{relative}`
/// ([`Facts`]).
struct Statement {
    hu: &'static str,
    en: &'static str,
    printed: bool,
    correct: bool,
    why_en: &'static str,
    why_hu: &'static str,
}

/// The numbers the reasons quote, from the laws.
struct Facts {
    /// Irradiance from a point light, facing it, at 1 m over that at 2 m.
    falloff: f64,
    /// The largest Compton shift, at back-scattering, pm.
    compton_pm: f64,
    /// That shift as a fraction of the shortest visible wavelength, 380 nm.
    relative: f64,
}

impl Facts {
    fn measured() -> Self {
        let compton_pm = compton_shift_m(std::f64::consts::PI) * 1e12;
        // Irradiance from a 1 W/sr point light, facing it, at 1 m and 2 m.
        let irradiance_at = |r: f64| {
            point_irradiance(1.0, DVec3::new(0.0, 0.0, r), DVec3::ZERO, DVec3::Z)
                .map_or(f64::NAN, |s| s.irradiance)
        };
        Facts {
            falloff: irradiance_at(1.0) / irradiance_at(2.0),
            compton_pm,
            relative: compton_pm * 1e-12 / 380e-9,
        }
    }

    /// A reason with the numbers it names written in.
    fn fill(&self, why: &str) -> String {
        why.replace("{falloff}", &number(self.falloff))
            .replace("{compton_pm}", &number(self.compton_pm))
            .replace("{relative}", &number(self.relative))
    }
}

const STATEMENTS: [Statement; 9] = [
    Statement {
        hu: "Egy kiterjedt felületről induló fénysugár sugársűrűsége a sugár mentén állandó.",
        en: "The radiance of a ray leaving an extended surface is constant along the ray.",
        printed: true,
        correct: true,
        why_en: "radiance is invariant along a ray in a non-participating medium: dΦ/(dA cos θ dω) keeps its value as the ray's footprint and solid angle trade off",
        why_hu: "nem részt vevő közegben a sugársűrűség a sugár mentén állandó: dΦ/(dA cos θ dω) értéke megmarad, mert a sugárnyaláb keresztmetszete és térszöge kiegyenlíti egymást",
    },
    Statement {
        hu: "Egy pontszerű fényforrásból induló fénysugár sugársűrűsége a forrástól vett távolság négyzetével csökken.",
        en: "The radiance of a ray from a point source falls with the square of the distance from the source.",
        printed: true,
        correct: false,
        why_en: "radiance is invariant along a ray for every source; what falls as 1/r² is the irradiance a point source delivers, E = I cos θ / r² (at 1 m vs 2 m: ratio {falloff})",
        why_hu: "a sugársűrűség minden forrásnál állandó a sugár mentén; a pontforrás által keltett megvilágítás (irradiancia) csökken 1/r² szerint, E = I cos θ / r² (1 m és 2 m között: {falloff}-szeres)",
    },
    Statement {
        hu: "A fotontranszport szimulációnál a látható tartományba eső frekvenciájú fotonok elektronokkal rugalmasan ütközve sohasem változtatják meg a frekvenciájukat.",
        en: "In photon transport simulation, visible-frequency photons colliding elastically with electrons never change their frequency.",
        printed: true,
        correct: true,
        why_en: "as the rendering model assumes: the Compton shift is at most 2h/(m_e c) = {compton_pm} pm, at most {relative} of a visible wavelength",
        why_hu: "a képszintézis modelljében igaz: a Compton-eltolódás legfeljebb 2h/(m_e c) = {compton_pm} pm, a látható hullámhossz legfeljebb {relative}-szerese",
    },
    Statement {
        hu: "A törésmutató a két közegbeli fénysebességek arányával egyezik meg.",
        en: "The refractive index equals the ratio of the speeds of light in the two media.",
        printed: true,
        correct: true,
        why_en: "the relative index n₂/n₁ equals v₁/v₂ (the absolute index is c/v)",
        why_hu: "a relatív törésmutató n₂/n₁ = v₁/v₂ (az abszolút törésmutató c/v)",
    },
    Statement {
        hu: "A Fresnel függvény értékkészlete a [0,1] tartomány.",
        en: "The range of the Fresnel function is [0, 1].",
        printed: true,
        correct: true,
        why_en: "it is the reflected fraction of the incident power, and energy conservation bounds it (the suite's property tests check it over random inputs)",
        why_hu: "a beeső teljesítmény visszavert hányada, az energiamegmaradás korlátozza (a csomag tulajdonságtesztjei véletlen bemeneteken ellenőrzik)",
    },
    Statement {
        hu: "Csak a 444, 526 és 645 nm hullámhosszú fényből állítható elő bármilyen színérzet additív keveréssel.",
        en: "Any colour sensation can be produced by additive mixing from light of 444, 526 and 645 nm only.",
        printed: false,
        correct: false,
        why_en: "three real primaries mix only the colours of a triangle in the chromaticity diagram, and the region of all colours is bounded by the curved spectral locus, so no three wavelengths cover it; other primaries mix colours too",
        why_hu: "három valós alapszín csak a színpatkóba írt háromszög színeit keveri ki, a színek tartományát pedig a spektrálszínek íves görbéje határolja, így semelyik három hullámhossz sem fedi le; más alapszínekkel is lehet keverni",
    },
    Statement {
        hu: "Az emberi szem kizárólag a 444, 526 és 645 nm hullámhosszú fényre érzékeny.",
        en: "The human eye is sensitive only to light of 444, 526 and 645 nm.",
        printed: false,
        correct: false,
        why_en: "the cones respond to the whole visible band, about 380–780 nm, with overlapping sensitivity curves",
        why_hu: "a csapok a teljes látható tartományra (kb. 380–780 nm) érzékenyek, átfedő görbékkel",
    },
    Statement {
        hu: "A Fresnel függvény mértékegysége [W/m^2/st] (Watt per négyzetméter per szteradián).",
        en: "The unit of the Fresnel function is W/(m² sr).",
        printed: false,
        correct: false,
        why_en: "Fresnel reflectance is a ratio of powers, dimensionless; W/(sr m²) is the unit of radiance",
        why_hu: "a Fresnel-függvény teljesítmények aránya, mértékegység nélküli; a W/(sr m²) a sugársűrűség egysége",
    },
    Statement {
        hu: "A fotontranszport szimulációnál a fotonok elektronokkal rugalmasan ütközve sohasem változtatják meg a frekvenciájukat.",
        en: "In photon transport simulation, photons colliding elastically with electrons never change their frequency.",
        printed: false,
        correct: false,
        why_en: "at high energies the Compton shift (up to {compton_pm} pm) is a large part of the wavelength: X-rays and gamma rays change frequency",
        why_hu: "nagy energián a Compton-eltolódás (legfeljebb {compton_pm} pm) a hullámhossz jelentős része: röntgen- és gammafotonok frekvenciája változik",
    },
];

/// Question 1 as a record: the verdicts, and a note on each printed wrongly.
pub(super) fn question_one(lang: Lang) -> Record {
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
    let facts = Facts::measured();
    for (i, s) in STATEMENTS.iter().enumerate() {
        let verdict = |b: bool| match (b, lang) {
            (true, Lang::En) => "true",
            (false, Lang::En) => "false",
            (true, Lang::Hu) => "igaz",
            (false, Lang::Hu) => "hamis",
        };
        let text = lang.pick(s.en, s.hu);
        let why = facts.fill(lang.pick(s.why_en, s.why_hu));
        record.step(|| format!("{}. [{}] {text} — {why}", i + 1, verdict(s.correct)));
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
