//! Trade-off jobs: the job lines `optics tradeoff --plan` writes and the
//! result lines `optics tradeoff-job` writes, for a real plan (the course's
//! `shadow` at 8 × 6), mutated field by field (numbers at the edges, wrong
//! types, missing and unknown fields, another schema or version, a job
//! index past the plan) and byte by byte, read as `optics tradeoff-job`
//! and `--collect` read them. The promises: an unmutated line is accepted;
//! nothing panics; a refusal names a field of the line's schema or one the
//! line gave, or none only for a line that is not a JSON object.

use std::path::PathBuf;
use std::sync::OnceLock;

use super::{edge_number, run_and_report, runner, Coverage};
use crate::error::jobs::{JobError, LineKind, Place};
use glam::Vec3;
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use serde_json::{json, Map, Value};
use tracer::render::Image;
use validation::tradeoff::engine::{accept, Setup, SweepRequest};
use validation::tradeoff::jobs::{
    self, Job, JobResult, Planned, INDEX_UNCHECKED, JOB_FIELDS, RESULT_FIELDS,
};

/// The plan of `shadow` at 8 × 6, made once.
fn planned() -> &'static (Setup, Planned) {
    static PLAN: OnceLock<(Setup, Planned)> = OnceLock::new();
    PLAN.get_or_init(|| {
        let scene = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../tracer/scenes/shadow.json");
        let args = SweepRequest {
            scene,
            width: Some(8),
            height: Some(6),
            spp: 16,
            truth_spp: 8,
            repeats: 2,
            min_seconds: 0.0,
            out: PathBuf::from("unused"),
            lambert: true,
            fresh: false,
            threads: Some(1),
            checkout: validation::checkout::Lookup::default(),
        };
        let setup = Setup::new(&args).expect("the course's shadow scene loads");
        let planned = Planned::new(&setup.key, &setup.job, &setup.plan);
        (setup, planned)
    })
}

/// The result job `job` of the plan writes after two renders.
fn result_of(planned: &Planned, job: usize) -> JobResult {
    let image = Image {
        width: 8,
        height: 6,
        pixels: vec![Vec3::new(0.25, 0.5, 1.0); 48],
    };
    let line = &planned.jobs[job];
    let renders = if line.is_truth() { 1 } else { 2 };
    JobResult {
        schema: LineKind::Result.schema().to_owned(),
        version: jobs::VERSION,
        plan: line.plan.clone(),
        planned_as: "optics tradeoff shadow.json".into(),
        scene_fnv1a: line.scene_fnv1a.clone(),
        job,
        jobs: line.jobs,
        label: line.label.clone(),
        seconds: vec![1e-3; renders],
        rays: 96.0,
        machine: "a machine".into(),
        date: "2026-12-04".into(),
        load: None,
        images: vec![jobs::encode(&image); planned.kept(job, renders)],
    }
}

/// A value for a field: numbers at the edges, else the wrong shape.
fn field_value() -> impl Strategy<Value = Value> {
    prop_oneof![
        3 => edge_number().prop_map(|x| json!(x)),
        2 => (0u64..64).prop_map(|n| json!(n)),
        1 => prop::collection::vec(edge_number(), 0..4).prop_map(|v| json!(v)),
        2 => prop::sample::select(vec![
            json!(null), json!(true), json!(""), json!({}), json!("optics.tradeoff"),
            json!("optics.tradeoff-job"), json!("optics.tradeoff-result"), json!(-1),
            json!(2), json!(u64::MAX), json!("UEYK"), json!(["UEYKOCA2Ci0xCg=="]),
        ]),
    ]
}

/// How a line is changed before it is written.
#[derive(Clone, Debug)]
enum Change {
    /// A field (by its place in the schema) given another value.
    Set(usize, Value),
    /// A field removed.
    Remove(usize),
    /// A field no schema has.
    Unknown(Value),
    /// Another job's index, up to twice the plan's.
    Job(usize),
}

fn change() -> impl Strategy<Value = Change> {
    prop_oneof![
        5 => (any::<usize>(), field_value()).prop_map(|(i, v)| Change::Set(i, v)),
        1 => any::<usize>().prop_map(Change::Remove),
        1 => field_value().prop_map(Change::Unknown),
        2 => (0..40usize).prop_map(Change::Job),
    ]
}

fn apply(mut line: Map<String, Value>, change: Change, fields: &[&str]) -> Map<String, Value> {
    match change {
        Change::Set(i, value) => drop(line.insert(fields[i % fields.len()].into(), value)),
        Change::Remove(i) => drop(line.remove(fields[i % fields.len()])),
        Change::Unknown(value) => drop(line.insert("colour".into(), value)),
        Change::Job(job) => drop(line.insert("job".into(), json!(job))),
    }
    line
}

/// A line to read: a job or a result line of the plan, changed, then its
/// bytes mutated; whether it was left as written.
#[derive(Clone, Debug)]
struct Case {
    kind: LineKind,
    text: String,
    untouched: bool,
}

fn case() -> impl Strategy<Value = Case> {
    let jobs = planned().1.jobs.len();
    let mutation = (
        any::<prop::sample::Index>(),
        0..3u8,
        prop::sample::select(b"\"{}[],:0\n \\".to_vec()),
    );
    (
        any::<bool>(),
        0..jobs,
        prop::collection::vec(change(), 0..3),
        prop::collection::vec(mutation, 0..2),
    )
        .prop_map(|(job_line, job, changes, mutations)| {
            let planned = &planned().1;
            let (kind, value, fields): (_, _, &[&str]) = if job_line {
                let value = serde_json::to_value(&planned.jobs[job]);
                (LineKind::Job, value, &JOB_FIELDS)
            } else {
                let value = serde_json::to_value(result_of(planned, job));
                (LineKind::Result, value, &RESULT_FIELDS)
            };
            let Ok(Value::Object(line)) = value else {
                unreachable!("a line is an object")
            };
            let untouched = changes.is_empty() && mutations.is_empty();
            let line = changes.into_iter().fold(line, |l, c| apply(l, c, fields));
            let mut bytes = Value::Object(line).to_string().into_bytes();
            for (at, op, byte) in mutations {
                let i = at.index(bytes.len() + 1);
                match op {
                    0 => bytes.insert(i, byte),
                    1 if i < bytes.len() => drop(bytes.remove(i)),
                    _ => bytes.truncate(i),
                }
            }
            Case {
                kind,
                text: String::from_utf8_lossy(&bytes).into_owned(),
                untouched,
            }
        })
}

/// The line read as `optics tradeoff-job` (a job line) or `--collect` (a
/// result line) reads it.
fn read(case: &Case) -> Result<(), JobError> {
    let (setup, planned) = planned();
    let at = Place {
        path: "lines.jsonl".into(),
        line: 1,
    };
    match case.kind {
        LineKind::Job => {
            let line: Job = jobs::read_line(&case.text, case.kind, &at)?;
            planned.check(&line, &at).map(drop)
        }
        LineKind::Result => {
            let result: JobResult = jobs::read_line(&case.text, case.kind, &at)?;
            let job = accept(planned, setup, &result, &at)?;
            let kept = planned.kept(job, result.seconds.len());
            result.images(&at, kept, (8, 6)).map(drop)
        }
    }
}

fn check(case: &Case, coverage: &Coverage) -> Result<(), TestCaseError> {
    let error = match read(case) {
        Ok(()) => {
            coverage.answer();
            return Ok(());
        }
        Err(error) => error,
    };
    let json = crate::Error::from(error).to_json(record::Lang::En);
    coverage.error(&json);
    prop_assert!(
        !case.untouched,
        "{:?} refused as written: {json}",
        case.text
    );
    let fields: &[&str] = match case.kind {
        LineKind::Job => &JOB_FIELDS,
        LineKind::Result => &RESULT_FIELDS,
    };
    let given = serde_json::from_str::<Map<String, Value>>(&case.text).ok();
    let Some(field) = json["field"].as_str() else {
        prop_assert!(given.is_none(), "{json} names no field for an object");
        return Ok(());
    };
    // A field of the schema, or one the line gave (an unknown one).
    let base = field.split(['.', '[']).next().unwrap_or_default();
    let real = fields.contains(&base) || given.is_some_and(|g| g.contains_key(field));
    prop_assert!(
        real,
        "{json}: {field:?} is not a field of {} or of the line",
        case.kind.schema()
    );
    Ok(())
}

fn fuzz(cases: u32, coverage: &Coverage) -> Result<(), String> {
    runner(cases)
        .run(&case(), |case| check(&case, coverage))
        .map_err(|e| e.to_string())
}

#[test]
fn tradeoff_jobs_are_read_or_refused_by_a_field_of_their_line() {
    run_and_report("tradeoff jobs", fuzz);
}

#[test]
fn tradeoff_jobs_find_a_job_index_not_checked_against_the_plan() {
    INDEX_UNCHECKED.set(true);
    let failure = fuzz(256, &Coverage::default());
    INDEX_UNCHECKED.set(false);
    let failure = failure.expect_err("the unchecked job index is found");
    assert!(failure.contains("out of bounds"), "{failure}");
}
