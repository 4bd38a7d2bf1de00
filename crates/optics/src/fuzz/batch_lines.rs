//! Batch lines: the course's requests mutated field by field and byte by
//! byte, a line's `"steps"` among the fields, several to an input, through
//! [`crate::batch::run`] with and without `--no-steps`; and each line read
//! both ways [`crate::batch::request`] reads it, which must agree.

use super::{
    check_error_field, check_record, edge_number, is_vector, run_and_report, runner, schema,
    Coverage,
};
use crate::batch::request::{self, LINE_STEPS_IGNORED, REPEATED_KEYS_KEPT};
use crate::batch::{self, BatchArgs, NOT_UTF8_STOPS_THE_RUN};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use record::Lang;
use record::Steps;
use safe_io::json::UniqueKeys;
use serde_json::error::Category;
use serde_json::{json, Map, Value};

/// One request of each law, as the course's quiz and the docs give them,
/// and the example of every law's `--help` (`law_table::schema::example`),
/// so that a new law is fuzzed too.
fn course_requests() -> Vec<Value> {
    let examples = crate::law_table::LAWS.iter().map(|&law| {
        let (mut request, _) = crate::law_table::schema::example(law);
        request.insert("law".into(), json!(law));
        Value::Object(request)
    });
    let course = vec![
        json!({"law": "fresnel", "eta": 1.5, "cos_i": 0.3}),
        json!({"law": "fresnel", "eta": 0.17, "kappa": 3.1, "theta_i_deg": 60, "model": "schlick-incident"}),
        json!({"law": "fresnel", "eta": 1.5, "theta_i_deg": 120, "model": "schlick-rarer"}),
        json!({"law": "fresnel", "eta": 1.5, "cos_i": 0.3, "model": "schlick"}),
        json!({"law": "refract", "wi": [0, 0.6, 0.8], "normal": [0, 0, 1], "eta": 1.5}),
        json!({"law": "reflect", "wi": [1, 2, 3], "normal": [0, 0, 1]}),
        json!({"law": "shade", "model": "phong", "normal": [0, 0, 1], "light_dir": [0, 3, 4], "view_dir": [0, 4, 3], "radiance": 5, "kd": 0.2, "ks": 1.5, "shine": 3}),
        json!({"law": "f0", "n": 1.4}),
        json!({"law": "lambert", "normal": [0, 0, 1], "light_dir": [0, 3, 4], "view_dir": [1, 2, 3], "radiance": 5, "kd": 0.6}),
        json!({"law": "critical_angle", "n": 10}),
        json!({"law": "blinn_phong", "normal": [0, 0, 1], "light_dir": [0, 3, 4], "view_dir": [0, 4, 3], "radiance": 5, "ks": std::f64::consts::SQRT_2, "shine": 3}),
        json!({"law": "envmap", "dir": [-3.2, 5.1, -8.4], "map": "cube"}),
        json!({"law": "reflection_matrix", "plane_point": [0, 1, 0], "plane_normal": [0, 1, 0], "point": [2, 3, 4]}),
        json!({"law": "shadow_matrix", "light": [0, 4, 0], "plane_point": [0, 0, 0], "plane_normal": [0, 1, 0], "vertex": [1, 2, 0]}),
    ];
    course.into_iter().chain(examples).collect()
}

/// A value for a field: mostly numbers and vectors at the edges, else the
/// wrong shape.
fn field_value() -> impl Strategy<Value = Value> {
    prop_oneof![
        4 => edge_number().prop_map(|x| json!(x)),
        4 => prop::array::uniform3(edge_number()).prop_map(|v| json!(v)),
        1 => prop::collection::vec(edge_number(), 0..5).prop_map(|v| json!(v)),
        1 => prop::sample::select(vec![
            json!(null), json!(true), json!("1.5"), json!({}), json!("schlick"), json!("schlick-incident"),
            json!("course-lambert"), json!(-1), json!([[0, 0, 1]]),
        ]),
    ]
}

/// How a request is changed before it is written.
#[derive(Clone, Debug)]
enum Change {
    Set(usize, Value),
    Remove(usize),
    Unknown(Value),
    Law(String),
    /// The line's own `"steps"`.
    Steps(Value),
}

fn change() -> impl Strategy<Value = Change> {
    let laws: Vec<String> = crate::law_table::LAWS
        .iter()
        .map(|&law| law.to_owned())
        .collect();
    prop_oneof![
        6 => (any::<usize>(), field_value()).prop_map(|(i, v)| Change::Set(i, v)),
        1 => any::<usize>().prop_map(Change::Remove),
        1 => field_value().prop_map(Change::Unknown),
        1 => prop::sample::select([laws, vec!["teleport".into()]].concat()).prop_map(Change::Law),
        2 => prop_oneof![
            3 => any::<bool>().prop_map(|wanted| json!(wanted)),
            1 => field_value(),
        ]
        .prop_map(Change::Steps),
    ]
}

fn apply(mut request: Map<String, Value>, change: Change) -> Map<String, Value> {
    if let Change::Steps(value) = change {
        request.insert("steps".into(), value);
        return request;
    }
    let law = request["law"].as_str().unwrap_or_default().to_owned();
    let fields = schema(&law);
    if fields.is_empty() {
        return request; // an unknown law: nothing more to change
    }
    match change {
        Change::Set(i, value) => {
            let field = &fields[i % fields.len()];
            // A vector field is mostly given a vector, a number a number.
            let value = match (&value, is_vector(&law, field)) {
                (Value::Number(_), true) | (Value::Array(_), false) if i % 4 != 0 => {
                    request.get(field).cloned().unwrap_or(value)
                }
                _ => value,
            };
            request.insert(field.to_owned(), value);
        }
        Change::Remove(i) => {
            request.remove(&fields[i % fields.len()]);
        }
        Change::Unknown(value) => {
            request.insert("colour".into(), value);
        }
        Change::Law(law) => {
            request.insert("law".into(), json!(law));
        }
        Change::Steps(_) => unreachable!("set above"),
    }
    request
}

/// Bytes that break lines, strings, objects and UTF-8.
const HOSTILE_BYTES: [u8; 12] = [
    0xff, 0xfe, 0xc3, 0x80, b'\n', b'\r', b'"', b'{', b'}', b',', 0, b' ',
];

/// A request as a line of JSON: its `law` first (as people and scripts
/// write it, and as the typed reading takes it), or its keys in byte
/// order.
fn line_text(request: &Map<String, Value>, law_first: bool) -> String {
    if !law_first {
        return Value::Object(request.clone()).to_string();
    }
    let law = request.get("law").map(|law| format!("\"law\":{law}"));
    let rest = request
        .iter()
        .filter(|(name, _)| *name != "law")
        .map(|(name, value)| format!("{}:{value}", Value::from(name.as_str())));
    let fields: Vec<String> = law.into_iter().chain(rest).collect();
    format!("{{{}}}", fields.join(","))
}

/// One line: a course request with its changes, then byte mutations.
fn request_line() -> impl Strategy<Value = Vec<u8>> {
    let requests = course_requests();
    let mutation = (
        any::<prop::sample::Index>(),
        0..3u8,
        prop::sample::select(HOSTILE_BYTES.to_vec()),
    );
    (
        prop::sample::select(requests),
        prop::collection::vec(change(), 0..3),
        prop::collection::vec(mutation, 0..3),
        prop::bool::weighted(0.8),
        prop::option::weighted(0.15, any::<prop::sample::Index>()),
    )
        .prop_map(|(request, changes, mutations, law_first, repeat)| {
            let Value::Object(request) = request else {
                unreachable!()
            };
            let request = changes.into_iter().fold(request, apply);
            let mut text = line_text(&request, law_first);
            // One of its keys given again, first, with the value it has.
            if let Some(at) = repeat.filter(|_| !request.is_empty()) {
                let (key, value) = request.iter().nth(at.index(request.len())).unwrap();
                text.insert_str(1, &format!("{}:{value},", Value::from(key.as_str())));
            }
            let mut bytes = text.into_bytes();
            for (at, op, byte) in mutations {
                let i = at.index(bytes.len() + 1);
                match op {
                    0 => bytes.insert(i, byte),
                    1 if i < bytes.len() => drop(bytes.remove(i)),
                    _ => bytes.truncate(i),
                }
            }
            bytes
        })
}

/// An input of a few lines, `\n` or `\r\n` between them, with or without
/// a last newline.
fn batch_input() -> impl Strategy<Value = Vec<u8>> {
    (
        prop::collection::vec(request_line(), 1..6),
        any::<bool>(),
        any::<bool>(),
    )
        .prop_map(|(lines, crlf, last)| {
            let end: &[u8] = if crlf { b"\r\n" } else { b"\n" };
            let mut input = lines.join(end);
            if last {
                input.extend_from_slice(end);
            }
            input
        })
}

/// The lines the reader will see: `\n`-separated, a last empty one not.
fn lines_of(input: &[u8]) -> Vec<&[u8]> {
    let mut lines: Vec<&[u8]> = input.split(|&b| b == b'\n').collect();
    if lines.last().is_some_and(|l| l.is_empty()) {
        lines.pop();
    }
    lines
}

/// Whether a line's record carries its working: the line's own `"steps"`
/// when it gives a boolean, else the run's choice.
fn steps_wanted(line: &[u8], no_steps: bool) -> bool {
    let fields = serde_json::from_slice::<Map<String, Value>>(line).unwrap_or_default();
    fields
        .get("steps")
        .and_then(Value::as_bool)
        .unwrap_or(!no_steps)
}

/// The key a line that is UTF-8 and JSON gives twice in an object, as a
/// path.
fn repeated_key(line: &[u8]) -> Option<String> {
    let line = line.strip_suffix(b"\r").unwrap_or(line);
    let json = &mut serde_json::Deserializer::from_str(std::str::from_utf8(line).ok()?);
    let err = serde_path_to_error::deserialize::<_, UniqueKeys>(json).err()?;
    (err.inner().classify() == Category::Data).then(|| err.path().to_string())
}

/// The line read straight into its law's arguments, where that reading
/// takes it, is the request the general reading gives.
fn check_readings_agree(line: &[u8], steps: Steps) -> Result<(), TestCaseError> {
    let line = line.strip_suffix(b"\r").unwrap_or(line);
    let Ok(text) = std::str::from_utf8(line) else {
        return Ok(());
    };
    let Some(typed) = request::typed(text, steps) else {
        return Ok(());
    };
    let general = request::general(text, steps);
    prop_assert!(
        general.is_ok(),
        "{text:?}: read typed as {typed:?}, refused by the general reading: {:?}",
        general.as_ref().err()
    );
    let general = general.expect("checked above");
    prop_assert_eq!(format!("{typed:?}"), format!("{general:?}"), "{:?}", text);
    Ok(())
}

/// A line that gives a key twice is refused naming that key, by the run
/// and by the general reading on this thread (whose test switches the
/// run's worker threads do not see).
fn check_repeat_refused(line: &[u8], record: &Value) -> Result<(), TestCaseError> {
    let Some(key) = repeated_key(line) else {
        return Ok(());
    };
    let field = &record["error"]["field"];
    prop_assert_eq!(field, &json!(key), "{}: a key given twice", record);
    let text = std::str::from_utf8(line).expect("checked by repeated_key");
    let text = text.strip_suffix('\r').unwrap_or(text);
    let general = request::general(text, Steps::from_wanted(true));
    let field = general
        .err()
        .map(|(_, error)| error.to_json(Lang::En)["field"].clone());
    prop_assert_eq!(field, Some(json!(key)), "{:?}: a key given twice", text);
    Ok(())
}

fn check_batch(
    input: &[u8],
    block: u32,
    no_steps: bool,
    coverage: &Coverage,
) -> Result<(), TestCaseError> {
    let mut output = Vec::new();
    let args = BatchArgs { block, no_steps };
    let run = batch::run(&args, input, &mut output, Lang::En);
    prop_assert!(
        run.is_ok(),
        "{:?} on {:?}",
        run.err(),
        String::from_utf8_lossy(input)
    );
    let text = String::from_utf8(output).expect("the output is UTF-8");
    let records: Vec<&str> = text.lines().collect();
    let lines = lines_of(input);
    prop_assert_eq!(records.len(), lines.len(), "one record per line");
    for (i, (record, line)) in records.iter().zip(lines).enumerate() {
        let record: Value = serde_json::from_str(record).expect("each record is JSON");
        check_readings_agree(line, Steps::from_wanted(!no_steps))?;
        check_repeat_refused(line, &record)?;
        let Some(error) = record.get("error") else {
            coverage.answer();
            check_record(&record)?;
            let steps = record["steps"].as_array().map(Vec::len);
            let wanted = steps_wanted(line, no_steps);
            prop_assert!(
                steps.is_some() && (steps != Some(0)) == wanted,
                "{record}: steps wanted {wanted}, no_steps {no_steps}"
            );
            continue;
        };
        coverage.error(error);
        prop_assert_eq!(&record["line"], &json!(i + 1));
        // The keys of the line, and one it gives twice before any error.
        let mut given: Vec<String> = serde_json::from_slice::<Map<String, Value>>(line)
            .map(|m| m.keys().cloned().collect())
            .unwrap_or_default();
        given.extend(repeated_key(line));
        let law = record["law"].as_str().unwrap_or_default();
        check_error_field(error, &given, law, str::to_owned)?;
    }
    Ok(())
}

/// Runs the target; `Err` with the first failing case, shrunk.
fn fuzz(cases: u32, coverage: &Coverage) -> Result<(), String> {
    let strategy = (batch_input(), 1..4u32, any::<bool>());
    runner(cases)
        .run(&strategy, |(input, block, no_steps)| {
            check_batch(&input, block, no_steps, coverage)
        })
        .map_err(|e| e.to_string())
}

#[test]
fn batch_lines_keep_their_promises() {
    run_and_report("batch lines", fuzz);
}

#[test]
fn batch_lines_find_a_reader_that_stops_at_bytes_that_are_not_utf8() {
    NOT_UTF8_STOPS_THE_RUN.set(true);
    let outcome = fuzz(256, &Coverage::default());
    NOT_UTF8_STOPS_THE_RUN.set(false);
    let failure = outcome.expect_err("the reverted fix is found");
    assert!(failure.contains("ReadLine"), "{failure}");
}

#[test]
fn batch_lines_find_a_line_whose_steps_are_ignored() {
    LINE_STEPS_IGNORED.set(true);
    let outcome = fuzz(256, &Coverage::default());
    LINE_STEPS_IGNORED.set(false);
    let failure = outcome.expect_err("the reverted fix is found");
    assert!(failure.contains("steps"), "{failure}");
}

#[test]
fn batch_lines_find_a_key_given_twice_that_is_kept() {
    REPEATED_KEYS_KEPT.set(true);
    let outcome = fuzz(256, &Coverage::default());
    REPEATED_KEYS_KEPT.set(false);
    let failure = outcome.expect_err("the reverted fix is found");
    assert!(failure.contains("a key given twice"), "{failure}");
}
