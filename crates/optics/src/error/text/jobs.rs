//! The errors of a sweep spread over machines: the library's English,
//! naming the flag or argument each input came from, and an exhaustive
//! `match` over their kinds in Hungarian.

use record::Lang;

use crate::error::jobs::{flag, listed, ImageProblem, Input, JobError, LineKind};

use super::output::output;

/// A sweep's job or result refused, in `lang`.
pub(super) fn jobs(error: &JobError, lang: Lang) -> String {
    match lang {
        Lang::En => error.named(flag).to_string(),
        Lang::Hu => jobs_hu(error),
    }
}

/// `feladatsor` or `eredménysor`: what a line was read as.
fn line_hu(kind: LineKind) -> &'static str {
    match kind {
        LineKind::Job => "feladatsor",
        LineKind::Result => "eredménysor",
    }
}

fn image_hu(problem: &ImageProblem) -> String {
    match problem {
        ImageProblem::Encoding { index } => {
            format!("images[{index}] nem egy PFM-kép base64 kódolással")
        }
        ImageProblem::Size {
            index,
            got,
            expected,
        } => format!(
            "images[{index}] {} × {} képpontos, a terv szerint {} × {}",
            got.0, got.1, expected.0, expected.1
        ),
        ImageProblem::Count { got, expected } => format!(
            "az images {got} képet tartalmaz, a feladat renderelései közül {expected} marad meg"
        ),
    }
}

/// A sweep's job or result refused, in Hungarian.
fn jobs_hu(error: &JobError) -> String {
    match error {
        JobError::Read {
            input,
            path,
            source,
        } => format!(
            "{} {}: nem olvasható: {source}",
            flag(*input),
            path.display()
        ),
        JobError::Line {
            kind,
            at,
            field,
            message,
        } => {
            let field = field
                .as_ref()
                .map_or_else(String::new, |f| format!("{f}: "));
            format!(
                "{at}: nem érvényes {} ({}): {field}{message}",
                line_hu(*kind),
                kind.schema()
            )
        }
        JobError::Schema { kind, at, found } => format!(
            "{at}: a schema értéke {found:?}, {:?} kellene",
            kind.schema()
        ),
        JobError::Version { kind, at, found } => format!(
            "{at}: a(z) {} {found}. változata; ez az optics a(z) {}. változatot olvassa",
            kind.schema(),
            validation::tradeoff::JOB_VERSION
        ),
        JobError::NoSuchJob {
            input,
            at,
            index,
            jobs: 0,
        } => format!(
            "{} {index}: a(z) {} terv nem tartalmaz feladatot (üres)",
            flag(*input),
            at.path.display()
        ),
        JobError::NoSuchJob {
            input,
            at,
            index,
            jobs,
        } => format!(
            "{} {index}: a(z) {} terv {jobs} feladatból áll (0–{})",
            flag(*input),
            at.path.display(),
            jobs.saturating_sub(1)
        ),
        JobError::NotPlanned { at, field, job } => format!(
            "{at}: a(z) {field} nem az, amit a terv a(z) {job}. feladatnak ad: a sort \
             átírták, vagy az optics egy másik változata tervezte; újra kell tervezni"
        ),
        _ => plan_hu(error),
    }
}

/// A sweep's results refused against their plan, or a file unwritten.
fn plan_hu(error: &JobError) -> String {
    match error {
        JobError::SceneChanged { scene, at } => format!(
            "a(z) {} jelenetfájl megváltozott a tervezés óta ({at}); újra kell tervezni",
            scene.display()
        ),
        JobError::OtherPlan {
            at,
            found,
            planned_as,
            expected,
        } => format!(
            "{at}: a(z) {found} terv (`{planned_as}`) eredménye, ez a mérés a(z) {expected} \
             terv: a {} ugyanazt a jelenetet és kapcsolókat kapja, mint a {}",
            flag(Input::Collect),
            flag(Input::Plan)
        ),
        JobError::Duplicate { job, first, second } => {
            format!("a(z) {job}. feladatnak két eredménye van: {first} és {second}")
        }
        JobError::Missing { jobs, count, of } => format!(
            "{of} feladatból {count} eredménye hiányzik: {}",
            listed(jobs, *count)
        ),
        JobError::Image { at, problem } => format!("{at}: {}", image_hu(problem)),
        JobError::Times { at, field } => format!(
            "{at}: a(z) {field} értékei véges, nemnegatív számok kellenek legyenek, egy–64 \
             renderelésnyi"
        ),
        JobError::NoResults { path } => format!(
            "{} {}: nincs benne eredményfájl (*.json, *.jsonl)",
            flag(Input::Collect),
            path.display()
        ),
        JobError::IndexNeeded { path, lines: 0 } => format!(
            "{}: a(z) {} nem tartalmaz feladatot (üres): nincs mit futtatni",
            flag(Input::Jobs),
            path.display()
        ),
        JobError::IndexNeeded { path, lines } => format!(
            "{}: a(z) {} {lines} sort tartalmaz; meg kell adni a feladat sorszámát (0–{})",
            flag(Input::Index),
            path.display(),
            lines.saturating_sub(1)
        ),
        JobError::Write { input, error } => {
            format!("{}: {}", flag(*input), output(error, Lang::Hu))
        }
        JobError::Read { .. }
        | JobError::Line { .. }
        | JobError::Schema { .. }
        | JobError::Version { .. }
        | JobError::NoSuchJob { .. }
        | JobError::NotPlanned { .. } => jobs_hu(error),
    }
}
