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

use crate::help_example::first_example;
use record::{say, Lang};
use record::{Answer, Record};
use serde_json::Value;

/// The list of exercises, as a record: each of `quiz`'s subcommands (the
/// command as the parser for `lang` built it), its description and the
/// first example of its help.
pub fn list(lang: Lang, quiz: &clap::Command) -> Record {
    let mut record = Record::new(
        "quiz",
        say!(
            lang,
            "Exercises `optics quiz` solves:",
            "Az `optics quiz` feladatai:"
        ),
        "",
    );
    let exercises: Vec<&clap::Command> = quiz
        .get_subcommands()
        .filter(|exercise| exercise.get_name() != "help")
        .collect();
    for exercise in &exercises {
        let name = exercise.get_name();
        let about = exercise
            .get_about()
            .map(ToString::to_string)
            .unwrap_or_default();
        let words = format!("optics quiz {name}");
        let example = first_example(exercise, &words).unwrap_or(words);
        record.step(|| format!("{name:<15} {about}\n                    {example}"));
    }
    record.answer = Answer::List(
        exercises
            .iter()
            .map(|e| Value::from(e.get_name()))
            .collect(),
    );
    record
}
