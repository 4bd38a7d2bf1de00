//! `optics quiz seed`: the whole quiz worked, each answer checked against
//! the answer the course prints, at the precision it prints.

use super::exercises::{BlinnPhongArgs, CriticalAngleArgs, F0Args, LambertArgs};
use super::statements::question_one;
use crate::error::Result;
use crate::input::{Vec3Arg, Via};
use record::{number, Answer, Record, Steps};
use record::{say, Lang};
use serde_json::Value;

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

/// Each of questions 2–5: its answer's scale in the printed answer (F0 is
/// printed as a percentage), and the printed answer.
const PRINTED: [(f64, Printed); 4] = [
    (
        100.0,
        Printed {
            text: "2.77 %",
            value: 2.77,
            decimals: 2,
        },
    ),
    (
        1.0,
        Printed {
            text: "2.4",
            value: 2.4,
            decimals: 1,
        },
    ),
    (
        1.0,
        Printed {
            text: "5.74°",
            value: 5.74,
            decimals: 2,
        },
    ),
    (
        1.0,
        Printed {
            text: "2.5",
            value: 2.5,
            decimals: 1,
        },
    ),
];

/// Questions 2–5 solved with the quiz's numbers.
fn solved(lang: Lang) -> Result<[Record; 4]> {
    let (via, steps) = (Via::Flags, Steps::Wanted);
    let f0 = F0Args { n: 1.4, kappa: 0.0 }.solve(via, lang, steps)?;
    let lambert = LambertArgs {
        normal: Vec3Arg([0.0, 0.0, 1.0]),
        light_dir: Vec3Arg([0.0, 3.0, 4.0]),
        view_dir: Some(Vec3Arg([1.0, 2.0, 3.0])),
        radiance: 5.0,
        kd: 0.6,
    }
    .solve(via, lang, steps)?;
    let critical = CriticalAngleArgs {
        n: 10.0,
        n_outside: 1.0,
    }
    .solve(via, lang, steps)?;
    let blinn_phong = BlinnPhongArgs {
        normal: Vec3Arg([0.0, 0.0, 1.0]),
        light_dir: Vec3Arg([0.0, 3.0, 4.0]),
        view_dir: Vec3Arg([0.0, 4.0, 3.0]),
        radiance: 5.0,
        ks: std::f64::consts::SQRT_2,
        shine: 3.0,
        kd: 0.0,
    }
    .solve(via, lang, steps)?;
    Ok([f0, lambert, critical, blinn_phong])
}

/// Every question of the course's quiz, worked, each answer checked
/// against the one the course prints.
pub fn seed(lang: Lang) -> Result<Vec<Record>> {
    let mut questions = vec![question_one(lang)];
    for (mut record, (scale, printed)) in solved(lang)?.into_iter().zip(PRINTED) {
        let n = questions.len() + 1;
        record.title = say!(lang, "Question {n}: {}", "{n}. kérdés: {}", record.title);
        let ours = number_answer(&record) * scale;
        check_printed(&mut record, lang, ours, printed);
        questions.push(record);
    }
    questions[3].note(say!(
        lang,
        "the printed working labels the angle in the medium θ and then writes θin = arcsin(1/10); θin there is the angle in the air, 90°",
        "a közölt levezetés a közegbeli szöget θ-nak nevezi, majd θin = arcsin(1/10)-et ír; ott θin a levegőbeli szög, 90°"
    ));
    // Questions 3 and 5 give the light as "5 W/m^2/st sugársűrűségű
    // irányfényforrás"; the laws take it as the irradiance it delivers.
    for q in [2, 4] {
        questions[q].note(say!(
            lang,
            "the course gives the directional light as a radiance, 5 W/m^2/st; a directional light has no finite radiance (it arrives from one direction, a zero solid angle): its 5 is what it delivers to a surface facing it, W/m², and only so is L_in cos θin f_r in W/(sr m²)",
            "a kurzus az irányfényforrást sugársűrűséggel adja meg (5 W/m^2/st); egy irányfényforrásnak nincs véges sugársűrűsége (egyetlen irányból, nulla térszögből érkezik): az 5 a rá merőleges felületen keltett irradiancia, W/m², és csak így lesz L_in cos θin f_r mértékegysége W/(sr m²)"
        ));
    }
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
        record.step(|| {
            format!(
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
            )
        });
    }
    let values: Vec<Value> = questions
        .iter()
        .map(|q| serde_json::to_value(q).unwrap_or(Value::Null))
        .collect();
    record.detail("questions", values);
    Ok(record)
}

#[cfg(test)]
mod tests {
    use super::seed;
    use record::Lang;

    /// What the quiz says reads as sentences in either language: no test's
    /// name (an identifier of two underscores or more) stands in one.
    #[test]
    fn the_quiz_names_no_test_in_its_sentences() {
        for lang in [Lang::En, Lang::Hu] {
            for record in seed(lang).expect("the quiz is worked") {
                let text = [record.title.clone()]
                    .into_iter()
                    .chain(record.steps.iter().cloned())
                    .chain(record.notes.iter().cloned())
                    .collect::<Vec<_>>()
                    .join("\n");
                for word in text.split(|c: char| !(c.is_alphanumeric() || c == '_')) {
                    assert!(word.matches('_').count() < 2, "{lang:?}: {word} in\n{text}");
                }
            }
        }
    }
}
