//! The fuzz target of scene files: the course scenes mutated as JSON
//! (values replaced by hostile ones, fields removed, renamed or added,
//! values wrapped in arrays, bump maps given to objects) and then as bytes (flipped, inserted, cut,
//! a scene appended, a byte-order mark), read through `scene::parse_bytes`
//! and, when accepted, rendered at 4 × 3 by each integrator (the photon
//! map with 2 passes of 64 photons). The promises checked on every
//! case:
//!
//! - no panic;
//! - a refusal names a field of the schema (`docs/scene-schema.md`), `.`,
//!   or, for a field the schema does not have, that field under one it has;
//! - an accepted file is one JSON value, each of whose values sits at a
//!   field of the schema;
//! - an accepted scene renders finite under the local integrator, whose
//!   radiance the validation bounds (`scene::bound`), and any render either
//!   is finite or is refused as not finite.
//!
//! `OPTICS_FUZZ_CASES` sets the number of cases (default 1000); the
//! coverage (error kinds and schema fields reached) is printed, seen with
//! `--nocapture`. Each test-only fault (`scene::faults`) undoes one fix,
//! and the target must then fail.

use std::collections::BTreeMap;
use std::sync::Mutex;

use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestError, TestRng, TestRunner};
use serde_json::Value;
use tracer::job::{Overrides, RenderError, RenderJob};
use tracer::scene::faults::{self, Fault};
use tracer::scene::{self, IntegratorKind, PixelFilter, Precision, RenderSpec};

use tracer::scene::fields::{field_of, FIELDS};

/// An unknown field `key`, named as the file spells it, under the whole
/// file or a field of the schema.
fn under_a_field(path: &str, key: &str) -> bool {
    match path.strip_suffix(key) {
        Some("") => true,
        Some(parent) => parent.strip_suffix('.').and_then(field_of).is_some(),
        None => false,
    }
}

/// The paths of every value in `value`, as the reader writes them.
fn paths(value: &Value, at: String, out: &mut Vec<String>) {
    let child = |key: &str| {
        if at.is_empty() {
            key.to_owned()
        } else {
            format!("{at}.{key}")
        }
    };
    match value {
        Value::Object(map) => map.iter().for_each(|(k, v)| paths(v, child(k), out)),
        Value::Array(items) => {
            for (i, v) in items.iter().enumerate() {
                paths(v, format!("{at}[{i}]"), out);
            }
        }
        _ => {}
    }
    if !at.is_empty() {
        out.push(at);
    }
}

/// One structured change to a scene's JSON.
#[derive(Clone, Debug)]
enum Edit {
    Number(usize, f64),
    Replace(usize, Value),
    Remove(usize),
    AddField(usize, String, Value),
    WrapInArray(usize),
    /// `render.ray_offset` set to a choice that carries a value (`fixed`,
    /// `scaled`), the value hostile: the renders must stay finite.
    RayOffset(&'static str, f64),
    /// `objects[i].bump` set to a bump map, its kind or numbers often
    /// hostile: the bent normals must keep the renders finite.
    Bump(usize, Value),
}

/// One change to the bytes of a file.
#[derive(Clone, Debug)]
enum ByteEdit {
    Flip(usize, u8),
    Insert(usize, Vec<u8>),
    Cut(usize, usize),
    AppendScene,
    Append(Vec<u8>),
    ByteOrderMark,
}

/// The numbers a hostile file puts where a good one had its own.
fn hostile_number() -> impl Strategy<Value = f64> + Clone {
    prop_oneof![
        Just(0.0),
        Just(-0.0),
        Just(1.0),
        Just(-1.0),
        Just(0.5),
        Just(3.0),
        Just(64.0),
        Just(65.0),
        Just(1e-300),
        Just(1e-45),
        Just(1e-9),
        Just(1e9),
        Just(1e12),
        Just(1e20),
        Just(1e30),
        Just(3.4e38),
        Just(3.5e38),
        Just(1e300),
        Just(-1e300),
        Just(4294967296.0),
        Just(16384.0),
        Just(16385.0),
        Just(1048577.0),
        Just(1025.0),
        -1e6..1e6f64,
    ]
}

/// The values a hostile file puts where a good one had its own.
fn hostile_value() -> impl Strategy<Value = Value> {
    let numbers = hostile_number().prop_map(|x| serde_json::json!(x));
    let names = prop_oneof![
        Just("sphere"),
        Just("plane"),
        Just("mirror_tube"),
        Just("point"),
        Just("directional"),
        Just("look_at"),
        Just("course_pinhole"),
        Just("dielectric"),
        Just("conductor"),
        Just("lambert"),
        Just("flat"),
        Just("path"),
        Just("course"),
        Just("local"),
        Just("schlick"),
        Just("schlick-incident"),
        Just("schlick-rarer"),
        Just("robust"),
        Just(""),
        Just("gold"),
        Just("green"),
    ]
    .prop_map(|s| Value::String(s.to_owned()));
    let leaf = prop_oneof![
        4 => numbers.clone(),
        2 => names,
        1 => Just(Value::Null),
        1 => any::<bool>().prop_map(Value::Bool),
        1 => "[a-z_]{0,8}".prop_map(Value::String),
    ];
    leaf.prop_recursive(2, 8, 4, move |inner| {
        prop_oneof![
            prop::collection::vec(numbers.clone(), 0..5).prop_map(Value::Array),
            prop::collection::vec(inner.clone(), 0..3).prop_map(Value::Array),
            prop::collection::btree_map("[a-z_]{1,8}", inner, 0..3)
                .prop_map(|m| Value::Object(m.into_iter().collect())),
        ]
    })
}

/// The bump maps a hostile file gives an object: each kind with hostile
/// numbers, a gentle sine (so that some are accepted and rendered), and
/// any value at all.
fn bump() -> impl Strategy<Value = Value> {
    prop_oneof![
        1 => Just(serde_json::json!({ "type": "flat" })),
        2 => (hostile_number(), hostile_number())
            .prop_map(|(du, dv)| serde_json::json!({ "type": "slope", "du": du, "dv": dv })),
        2 => (hostile_number(), hostile_number()).prop_map(|(amplitude, period)| {
            serde_json::json!({ "type": "sine", "amplitude": amplitude, "period": period })
        }),
        2 => (-0.1..0.1f64, 0.004..1.0f64).prop_map(|(amplitude, period)| {
            serde_json::json!({ "type": "sine", "amplitude": amplitude, "period": period })
        }),
        1 => hostile_value(),
    ]
}

fn edit() -> impl Strategy<Value = Edit> {
    let field = prop_oneof![
        Just("type".to_owned()),
        Just("fixed".to_owned()),
        Just("scaled".to_owned()),
        Just("zoom".to_owned()),
        Just("pixel_filter".to_owned()),
        Just("precision".to_owned()),
        "[a-z_]{1,10}"
    ];
    prop_oneof![
        12 => (any::<usize>(), hostile_number()).prop_map(|(i, x)| Edit::Number(i, x)),
        3 => (any::<usize>(), hostile_value()).prop_map(|(i, v)| Edit::Replace(i, v)),
        2 => any::<usize>().prop_map(Edit::Remove),
        1 => (any::<usize>(), field, hostile_value()).prop_map(|(i, k, v)| Edit::AddField(i, k, v)),
        1 => any::<usize>().prop_map(Edit::WrapInArray),
        1 => (prop_oneof![Just("fixed"), Just("scaled")], hostile_number())
            .prop_map(|(kind, x)| Edit::RayOffset(kind, x)),
        2 => (any::<usize>(), bump()).prop_map(|(i, b)| Edit::Bump(i, b)),
    ]
}

fn byte_edit() -> impl Strategy<Value = ByteEdit> {
    let bytes = prop::collection::vec(any::<u8>(), 1..6);
    prop_oneof![
        3 => (any::<usize>(), prop_oneof![3 => 0x20..0x7fu8, 1 => any::<u8>()])
            .prop_map(|(i, b)| ByteEdit::Flip(i, b)),
        2 => (any::<usize>(), bytes.clone()).prop_map(|(i, b)| ByteEdit::Insert(i, b)),
        2 => (any::<usize>(), 1..40usize).prop_map(|(i, n)| ByteEdit::Cut(i, n)),
        1 => Just(ByteEdit::AppendScene),
        1 => bytes.prop_map(ByteEdit::Append),
        1 => Just(ByteEdit::ByteOrderMark),
    ]
}

/// A case: a course scene, its JSON edits, then its byte edits (often none).
type Case = (usize, Vec<Edit>, Vec<ByteEdit>);

/// Generates a [`Case`].
fn case() -> impl Strategy<Value = Case> {
    (
        0..scene::course_scenes().len(),
        prop::collection::vec(edit(), 0..6),
        prop_oneof![4 => Just(Vec::new()), 1 => prop::collection::vec(byte_edit(), 1..4)],
    )
}

/// The course scene `index`, with the photon map's settings in its
/// `render` (no course file has them), so that the edits reach them.
fn course_value(index: usize) -> Value {
    let path = format!(
        "{}/scenes/{}.json",
        env!("CARGO_MANIFEST_DIR"),
        scene::course_scenes()[index]
    );
    let mut value: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let render = value
        .as_object_mut()
        .unwrap()
        .entry("render")
        .or_insert_with(|| serde_json::json!({}));
    render["photons"] = serde_json::json!(1000);
    render["photon_passes"] = serde_json::json!(4);
    render["photon_radius"] = serde_json::json!(0.05);
    value
}

/// The value at `path` (as [`paths`] writes it), as a JSON pointer.
fn pointer(path: &str) -> String {
    let mut out = String::new();
    for part in path.split('.') {
        let (key, indices) = part.split_once('[').map_or((part, ""), |(k, i)| (k, i));
        if !key.is_empty() {
            out.push('/');
            out.push_str(&key.replace('~', "~0").replace('/', "~1"));
        }
        for index in indices.split('[').filter(|i| !i.is_empty()) {
            out.push('/');
            out.push_str(index.trim_end_matches(']'));
        }
    }
    out
}

fn apply(value: &mut Value, edit: &Edit) {
    let mut all = Vec::new();
    paths(value, String::new(), &mut all);
    all.push(String::new()); // the whole scene
    let at = |i: usize| pointer(&all[i % all.len()]);
    match edit {
        Edit::Number(i, x) => {
            let numbers: Vec<&String> = all
                .iter()
                .filter(|p| value.pointer(&pointer(p)).is_some_and(Value::is_number))
                .collect();
            if let Some(p) = numbers.get(i % numbers.len().max(1)) {
                *value.pointer_mut(&pointer(p)).unwrap() = serde_json::json!(x);
            }
        }
        Edit::Replace(i, v) => {
            if let Some(slot) = value.pointer_mut(&at(*i)) {
                *slot = v.clone();
            }
        }
        Edit::Remove(i) => {
            let p = at(*i);
            if let Some((parent, key)) = p.rsplit_once('/') {
                match value.pointer_mut(parent) {
                    Some(Value::Object(m)) => drop(m.remove(key)),
                    Some(Value::Array(a)) => {
                        if let Ok(k) = key.parse::<usize>() {
                            if k < a.len() {
                                a.remove(k);
                            }
                        }
                    }
                    _ => {}
                }
            }
        }
        Edit::AddField(i, key, v) => {
            if let Some(Value::Object(m)) = value.pointer_mut(&at(*i)) {
                m.insert(key.clone(), v.clone());
            }
        }
        Edit::WrapInArray(i) => {
            if let Some(slot) = value.pointer_mut(&at(*i)) {
                *slot = Value::Array(vec![slot.take()]);
            }
        }
        Edit::Bump(i, bump) => {
            if let Some(Value::Array(objects)) = value.get_mut("objects") {
                let n = objects.len();
                if let Some(Value::Object(object)) = objects.get_mut(i % n.max(1)) {
                    object.insert("bump".into(), bump.clone());
                }
            }
        }
        Edit::RayOffset(kind, x) => {
            if let Some(render) = value.get_mut("render").and_then(Value::as_object_mut) {
                let offset = serde_json::Number::from_f64(*x).map_or(Value::Null, Value::Number);
                render.insert("ray_offset".into(), serde_json::json!({ *kind: offset }));
            }
        }
    }
}

fn apply_bytes(bytes: &mut Vec<u8>, edit: &ByteEdit, scene: &[u8]) {
    let at = |i: usize, len: usize| if len == 0 { 0 } else { i % (len + 1) };
    match edit {
        ByteEdit::Flip(i, b) if !bytes.is_empty() => {
            let i = i % bytes.len();
            bytes[i] = *b;
        }
        ByteEdit::Flip(..) => {}
        ByteEdit::Insert(i, b) => {
            let i = at(*i, bytes.len());
            bytes.splice(i..i, b.iter().copied());
        }
        ByteEdit::Cut(i, n) => {
            let i = at(*i, bytes.len());
            let end = (i + n).min(bytes.len());
            bytes.drain(i..end);
        }
        ByteEdit::AppendScene => bytes.extend_from_slice(scene),
        ByteEdit::Append(b) => bytes.extend_from_slice(b),
        ByteEdit::ByteOrderMark => drop(bytes.splice(0..0, *b"\xEF\xBB\xBF")),
    }
}

/// The file a case writes.
fn file_of(case: &Case) -> Vec<u8> {
    let (index, edits, byte_edits) = case;
    let mut value = course_value(*index);
    for edit in edits {
        apply(&mut value, edit);
    }
    let text = if byte_edits.len() % 2 == 0 {
        value.to_string()
    } else {
        serde_json::to_string_pretty(&value).unwrap()
    };
    let mut bytes = text.clone().into_bytes();
    for edit in byte_edits {
        apply_bytes(&mut bytes, edit, text.as_bytes());
    }
    bytes
}

/// What the cases reached: each error kind and each schema field, counted.
#[derive(Default)]
struct Coverage {
    kinds: BTreeMap<String, usize>,
    fields: BTreeMap<&'static str, usize>,
    accepted: usize,
    /// Accepted with a bump map on some object.
    bumped: usize,
    rendered: usize,
    not_finite: usize,
}

/// Checks the promises on one file; records what it reached.
fn check(bytes: &[u8], coverage: &Mutex<Coverage>) -> Result<(), String> {
    let mut coverage = coverage.lock().unwrap();
    let scene = match scene::parse_bytes(bytes) {
        Err(error) => {
            let kind = format!("{:?}", error.kind());
            let kind = kind.split([' ', '(', '{']).next().unwrap_or("").to_owned();
            *coverage.kinds.entry(kind).or_default() += 1;
            let field = error.field();
            if field == "." {
                return Ok(());
            }
            if let Some(f) = field_of(field) {
                *coverage.fields.entry(f).or_default() += 1;
                return Ok(());
            }
            if let scene::ErrorKind::Schema { message } = error.kind() {
                // serde writes "unknown field `KEY`, expected …": the key
                // ends at "`, " (a key may hold a backtick itself).
                let key = message
                    .strip_prefix("unknown field `")
                    .and_then(|m| m.split_once("`, "));
                if key.is_some_and(|(key, _)| under_a_field(field, key)) {
                    return Ok(());
                }
            }
            return Err(format!(
                "{error:?} names {field:?}, not a field of the schema"
            ));
        }
        Ok(scene) => scene,
    };
    coverage.accepted += 1;
    coverage.bumped += usize::from(scene.bumps.iter().any(Option::is_some));
    accepted_is_the_schema(bytes)?;
    // Each integrator under its default pixel filter, and Whitted under the
    // box filter too (its jittered rays meet what the centre's do not);
    // local and Whitted at the f64 tier too.
    let f64_tier = Some(Precision::F64);
    for (integrator, pixel_filter, precision) in [
        (IntegratorKind::Local, None, None),
        (IntegratorKind::Local, None, f64_tier),
        (IntegratorKind::Whitted, None, None),
        (IntegratorKind::Whitted, None, f64_tier),
        (IntegratorKind::Whitted, Some(PixelFilter::Box), None),
        (IntegratorKind::Path, None, Some(Precision::F32)),
        (IntegratorKind::Photon, None, Some(Precision::F32)),
    ] {
        let overrides = Overrides {
            render: RenderSpec {
                integrator: Some(integrator),
                spp: Some(2.0),
                max_depth: Some(4.0),
                pixel_filter,
                // A small map: the file's own counts are validated, not spent.
                photons: Some(64.0),
                photon_passes: Some(2.0),
                precision,
                ..RenderSpec::default()
            },
            width: Some(4),
            height: Some(3),
            allow_expensive: false,
        };
        let Ok(job) = RenderJob::new(scene.clone(), &overrides) else {
            continue; // refused with its field, checked by the job's tests
        };
        match job.render(Some(1), &|_| {}) {
            Ok(r) if r.image.pixels.iter().all(|p| p.is_finite()) => coverage.rendered += 1,
            Ok(_) => return Err("a render returned a pixel that is not finite".into()),
            Err(RenderError::NotFinite { x, y }) if integrator == IntegratorKind::Local => {
                return Err(format!(
                    "local render not finite at ({x}, {y}), within the bound"
                ))
            }
            Err(RenderError::NotFinite { .. }) => coverage.not_finite += 1,
            Err(other) => return Err(format!("render failed: {other}")),
        }
    }
    Ok(())
}

/// An accepted file is one JSON value (after a byte-order mark), each of
/// whose values sits at a field of the schema.
fn accepted_is_the_schema(bytes: &[u8]) -> Result<(), String> {
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    let value: Value = serde_json::from_slice(bytes)
        .map_err(|e| format!("accepted a file that is not one JSON value: {e}"))?;
    if !value.is_object() {
        return Err("accepted a scene that is not an object".into());
    }
    let mut all = Vec::new();
    paths(&value, String::new(), &mut all);
    match all.iter().find(|p| field_of(p).is_none()) {
        Some(p) => Err(format!(
            "accepted a value at {p:?}, not a field of the schema"
        )),
        None => Ok(()),
    }
}

fn cases() -> u32 {
    std::env::var("OPTICS_FUZZ_CASES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(1000)
}

fn run(cases: u32, coverage: &Mutex<Coverage>) -> Result<(), TestError<Case>> {
    let config = Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    };
    // A fixed stream: the same cases on every run, so CI is reproducible;
    // `OPTICS_FUZZ_CASES` runs further along it.
    let rng = TestRng::deterministic_rng(RngAlgorithm::ChaCha);
    let mut runner = TestRunner::new_with_rng(config, rng);
    runner.run(&case(), |case| {
        check(&file_of(&case), coverage).map_err(TestCaseError::fail)
    })
}

#[test]
fn hostile_scene_files_keep_the_readers_promises() {
    let coverage = Mutex::new(Coverage::default());
    let n = cases();
    let start = std::time::Instant::now();
    if let Err(error) = run(n, &coverage) {
        panic!("{error}");
    }
    let c = coverage.into_inner().unwrap();
    println!(
        "scene fuzz: {n} cases in {:.1} s",
        start.elapsed().as_secs_f64()
    );
    println!(
        "accepted {} ({} with a bump map), renders finite {}, renders refused as not finite {}",
        c.accepted, c.bumped, c.rendered, c.not_finite
    );
    println!("error kinds reached: {:?}", c.kinds);
    println!(
        "schema fields named by errors ({} of {}): {:?}",
        c.fields.len(),
        FIELDS.len(),
        c.fields
    );
    assert!(
        c.accepted > 0 && c.bumped > 0 && c.kinds.len() >= 8,
        "a timid generator: {} bumped, {:?}",
        c.bumped,
        c.kinds
    );
}

/// With one fix undone, the target finds what it fixed: a failure of the
/// promise that fix keeps.
#[test]
fn the_fuzz_target_finds_each_fix_undone() {
    // The cases searched, in multiples of `cases()`: an unbounded radiance
    // needs two large numbers to meet in one case (a rough material's and
    // a light's), which this stream first does between 40 and 80 times
    // `cases()` along it; the other two are found in the first few hundred.
    let faults = [
        (Fault::TrailingTextIgnored, "not one JSON value", 10),
        (Fault::ShapesUnchecked, "not a field of the schema", 10),
        (Fault::RadianceUnbounded, "not finite", 80),
    ];
    for (fault, promise, budget) in faults {
        let coverage = Mutex::new(Coverage::default());
        let found = faults::with(fault, || run(budget * cases(), &coverage));
        match found {
            Err(TestError::Fail(reason, case)) if reason.message().contains(promise) => {
                println!(
                    "{fault:?} found: {reason} (scene {})",
                    scene::course_scenes()[case.0]
                )
            }
            other => panic!("{fault:?} not found: {other:?}"),
        }
    }
}
