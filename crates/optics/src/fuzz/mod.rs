//! Fuzz targets of the calculator's inputs, run by `cargo test` on stable
//! Rust: batch lines (`batch_lines`), flag values (`flag_values`), the
//! render settings' choices (`render_flags`), the images `optics
//! compare` reads (`compare_images`), `optics tradeoff`'s numeric flags
//! (`tradeoff_flags`), the accuracy budget's flags of `optics render`
//! (`budget_flags`), the job and result lines of a sweep spread over
//! machines (`tradeoff_jobs`), the vectors of `optics envmap`,
//! `reflection-matrix` and `shadow-matrix` (`technique_flags`) and the
//! ids and classes of `optics errata` (`errata_args`).
//!
//! Each target generates inputs from the course's own requests, mutates
//! them (numbers at the edges of `f64`, wrong types, missing and unknown
//! fields, bytes that are not UTF-8), and asserts the promises: no panic,
//! an error naming a real field, no NaN, no reflectance outside `[0, 1]`,
//! no direction off unit length, one batch record per line. Each has a
//! test that reverts one fix through a test-only switch and must fail.
//!
//! `OPTICS_FUZZ_CASES=10000 cargo test -p optics --lib fuzz -- --nocapture`
//! runs longer and prints which error kinds and fields the cases reached.

mod batch_lines;
#[cfg(feature = "harness")]
mod budget_flags;
#[cfg(feature = "harness")]
mod compare_images;
mod errata_args;
mod flag_values;
mod render_flags;
mod technique_flags;
#[cfg(feature = "harness")]
mod tradeoff_flags;
#[cfg(feature = "harness")]
mod tradeoff_jobs;

use proptest::prelude::*;
use proptest::test_runner::{Config, TestCaseError, TestRunner};
use serde_json::Value;
use std::collections::BTreeMap;
use std::sync::Mutex;

/// The cases each target runs: `OPTICS_FUZZ_CASES`, else 256.
fn cases() -> u32 {
    std::env::var("OPTICS_FUZZ_CASES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(256)
}

/// A runner of `cases` cases, deterministic, without failure files.
fn runner(cases: u32) -> TestRunner {
    let config = Config {
        cases,
        failure_persistence: None,
        max_shrink_iters: 256,
        ..Config::default()
    };
    TestRunner::new_with_rng(
        config,
        proptest::test_runner::TestRng::deterministic_rng(
            proptest::test_runner::RngAlgorithm::ChaCha,
        ),
    )
}

/// The fields of a law's request, as `optics batch` names them (the
/// flags are the same with `--` and `-` for `_`): the law table's.
fn schema(law: &str) -> Vec<String> {
    crate::law_table::schema::fields(law)
        .into_iter()
        .map(|field| field.name)
        .collect()
}

/// Whether the field `field` of the law `law` holds a vector.
fn is_vector(law: &str, field: &str) -> bool {
    crate::law_table::schema::fields(law)
        .iter()
        .any(|f| f.name == field && f.kind == crate::law_table::schema::Kind::Vector)
}

/// A number at the edges of `f64` as often as an ordinary one: zeros,
/// subnormals, the squares' underflow and overflow, the largest finite,
/// cosines near ±1, and negative ones with negative exponents.
fn edge_number() -> impl Strategy<Value = f64> {
    prop_oneof![
        -2.0..2.0f64,
        prop::sample::select(vec![
            0.0,
            -0.0,
            1.0,
            -1.0,
            1.5,
            1e-5,
            -1e-5,
            5e-324,
            -5e-324,
            3e-162,
            4e-162,
            1e-300,
            3e200,
            1e300,
            1.7e308,
            -1.7e308,
            f64::MAX,
            f64::MIN_POSITIVE,
            1e50,
            1e-50,
            1.0 - f64::EPSILON,
            -1.0 + f64::EPSILON,
            180.0,
            90.0,
        ]),
        (-330i32..310, -9.9..9.9f64).prop_map(|(e, m)| m * 10f64.powi(e)),
    ]
}

/// A number as a person might type it: `0.5`, `5e-1`, `5E-1`, `+0.5`.
fn number_text() -> impl Strategy<Value = String> {
    (edge_number(), 0..4u8).prop_map(|(x, form)| match form {
        0 => format!("{x}"),
        1 => format!("{x:e}"),
        2 => format!("{x:E}"),
        _ if x.is_sign_negative() => format!("{x:e}"),
        _ => format!("+{x:e}"),
    })
}

/// The error kinds and fields the cases of one target reached.
#[derive(Default)]
struct Coverage {
    kinds: Mutex<BTreeMap<String, usize>>,
    fields: Mutex<BTreeMap<String, usize>>,
    answers: Mutex<usize>,
}

impl Coverage {
    fn error(&self, error: &Value) {
        let kind = error["kind"].as_str().unwrap_or("?").to_owned();
        *self.kinds.lock().unwrap().entry(kind).or_default() += 1;
        if let Some(field) = error["field"].as_str() {
            *self
                .fields
                .lock()
                .unwrap()
                .entry(field.to_owned())
                .or_default() += 1;
        }
    }

    fn answer(&self) {
        *self.answers.lock().unwrap() += 1;
    }

    fn print(&self, target: &str, cases: u32, seconds: f64) {
        let answers = self.answers.lock().unwrap();
        println!("{target}: {cases} cases in {seconds:.1} s, {answers} answers");
        println!("  error kinds: {:?}", self.kinds.lock().unwrap());
        println!("  fields named: {:?}", self.fields.lock().unwrap());
    }
}

/// Runs a target's `fuzz` over [`cases`] cases and prints the error
/// kinds and fields they reached (`--nocapture` shows it), then fails
/// where a case broke a promise.
fn run_and_report(target: &str, fuzz: impl FnOnce(u32, &Coverage) -> Result<(), String>) {
    let (cases, coverage) = (cases(), Coverage::default());
    let start = std::time::Instant::now();
    let outcome = fuzz(cases, &coverage);
    coverage.print(target, cases, start.elapsed().as_secs_f64());
    outcome.unwrap();
}

/// The promises of a command line `args` of `command` that the parser
/// refused: it was spoiled (`spoiled`, the flag it spoiled), and the usage
/// error names that flag, or one of `or_named` (the other side of a
/// conflict), and only fields the line gave.
fn refused_by_usage(
    usage: clap::Error,
    args: &[String],
    spoiled: Option<&str>,
    or_named: &[&str],
    command: &str,
    coverage: &Coverage,
) -> Result<(), TestCaseError> {
    let error = crate::Error::from(crate::ErrorKind::Usage(usage));
    let json = error.to_json(record::Lang::En);
    coverage.error(&json);
    prop_assert!(spoiled.is_some(), "{args:?} refused: {json}");
    let flag = spoiled.unwrap_or_default();
    let field = json["field"].as_str().unwrap_or_default();
    let named = field.contains(flag) || or_named.iter().any(|other| field.contains(other));
    prop_assert!(named, "{json} does not name {flag}");
    check_error_field(&json, args, command, |f| f.to_owned())
}

/// An error names a real field: `None` only for kinds about the line
/// itself, else each name (`wi.x` is `wi`) a field of the law's schema or
/// one the request gave.
fn check_error_field(
    error: &Value,
    given: &[String],
    law: &str,
    name: impl Fn(&str) -> String,
) -> Result<(), TestCaseError> {
    let kind = error["kind"].as_str().unwrap_or_default();
    let Some(field) = error["field"].as_str() else {
        let unnamed = [
            "empty_line",
            "malformed_json",
            "not_an_object",
            "not_utf8",
            "line_too_long",
        ];
        prop_assert!(
            unnamed.contains(&kind)
                || kind == "request"
                || kind == "usage"
                || kind.starts_with("vector_"),
            "{error} names no field"
        );
        return Ok(());
    };
    for part in field.split(", ") {
        let base = part.split(['.', '[', ' ']).next().unwrap_or_default();
        // The parser names a cluster of short flags by its first (`-1e`
        // is `-1`).
        let usage = kind == "usage";
        let real = given
            .iter()
            .any(|g| *g == base || *g == part || (usage && g.starts_with(base)))
            || schema(law).iter().any(|f| name(f) == base)
            || base == name("law");
        prop_assert!(real, "{error}: {part:?} is not a field of {law}");
    }
    Ok(())
}

/// The promises of an answer: no NaN (`null`) in the answer or details
/// but a refraction's and its cosine under total internal reflection, reflectances in
/// `[0, 1]`, directions of unit length.
fn check_record(record: &Value) -> Result<(), TestCaseError> {
    let law = record["law"].as_str().unwrap_or_default();
    let answer = &record["answer"];
    prop_assert!(
        !answer.is_null() || law == "refract",
        "{record}: null answer"
    );
    // Under total internal reflection there is no transmitted cosine.
    let mut details = record.get("details").cloned().unwrap_or_default();
    if details["total_internal_reflection"] == Value::Bool(true) {
        details["cos_t"].take();
        details.as_object_mut().map(|d| d.remove("cos_t"));
    }
    prop_assert!(
        details.is_null() || !has_null(&details),
        "{record}: null detail"
    );
    if ["fresnel", "f0"].contains(&law) && !answer.is_array() {
        let r = answer.as_f64().unwrap_or(f64::NAN);
        prop_assert!((0.0..=1.0).contains(&r), "{record}: R = {r}");
    }
    // A metal named is answered per channel, each channel a reflectance.
    if law == "fresnel_bulk" || (law == "fresnel" && answer.is_array()) {
        for r in answer.as_array().into_iter().flatten() {
            let r = r.as_f64().unwrap_or(f64::NAN);
            prop_assert!((0.0..=1.0).contains(&r), "{record}: R = {r}");
        }
    }
    // The laws whose answer is a direction.
    let direction = ["reflect", "refract"].contains(&law);
    if let Some(v) = answer.as_array().filter(|_| direction) {
        let length = v
            .iter()
            .filter_map(Value::as_f64)
            .map(|c| c * c)
            .sum::<f64>()
            .sqrt();
        // 4 ulp: each component rounded once, the check's squares again.
        let tolerance = 4.0 * f64::EPSILON;
        prop_assert!(
            (length - 1.0).abs() <= tolerance,
            "{record}: |answer| = {length}"
        );
    }
    Ok(())
}

fn has_null(value: &Value) -> bool {
    match value {
        Value::Null => true,
        Value::Array(items) => items.iter().any(has_null),
        Value::Object(fields) => fields.values().any(has_null),
        _ => false,
    }
}
