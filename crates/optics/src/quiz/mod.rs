//! `optics quiz`: the worked exercises of the course's quiz (`003`, "Kvíz"),
//! solved with the radiometry laws, step by step, and compared with the
//! answers printed in the course.
//!
//! | file | job |
//! |---|---|
//! | `exercises` | the exercises one can pose with other numbers: F0, Lambert, critical angle, Phong-Blinn |
//! | `statements` | question 1, the true/false statements, with the laws' verdicts |
//! | `seed` | the whole quiz worked, each answer checked against the printed one |

mod exercises;
mod seed;
mod statements;

pub use exercises::{BlinnPhongArgs, CriticalAngleArgs, F0Args, LambertArgs};
pub use seed::{seed, seed_record};

use record::{say, Lang};
use record::{Answer, Record};
use serde_json::Value;

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
        "merőleges beesésű visszaverődés n-ből (és kappából)",
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
        "a kurzus Phong–Blinn-felületéről visszavert sugársűrűség",
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
        record.step(|| {
            format!(
                "{name:<15} {}\n                    {example}",
                lang.pick(en, hu)
            )
        });
    }
    record.answer = Answer::List(EXERCISES.iter().map(|e| Value::from(e.0)).collect());
    record
}
