//! The checks `optics validate` makes of the trade-off records
//! (`docs/tradeoffs/*.json`): the committed records pass them, and each
//! kind of wrong record fails them, naming what is wrong.

use std::path::Path;

use validation::reference::ReferenceError;
use validation::tradeoff::checks::{check, read, DIR};
use validation::tradeoff::findings::Findings;
use validation::tradeoff::record::Record;

/// Two settings whose fronts and verdict are the ones their numbers give
/// (their findings are added from them: [`with_findings`]).
const RECORD: &str = r#"{"schema": "optics.tradeoff", "version": 2,
  "scene": "crates/tracer/scenes/gold_spheres.json", "lambert": true, "width": 80, "height": 60,
  "machine": "a machine", "date": "2026-12-04", "load": "", "command": "optics tradeoff",
  "truth": {"spp": 64, "noise_relative": 3.56e-5},
  "points": [
    {"axis": "scene", "label": "scene", "settings": {"integrator": "whitted", "max_depth": 63, "fresnel": "exact"}, "seconds_median": 0.00025, "rays": 5304.0,
     "errors": {"rel_rmse": 0.18, "delta_e_mean": 2.06, "delta_e_p99": 28.04, "flip_mean": 0.068},
     "against_scene": {"rel_rmse": 0.0, "delta_e_mean": 0.0, "delta_e_p99": 0.0, "flip_mean": 0.0},
     "pareto": ["delta_e_mean", "delta_e_p99", "flip_mean"]},
    {"axis": "fresnel", "label": "fresnel schlick-rarer", "settings": {"integrator": "whitted", "max_depth": 63, "fresnel": "schlick-rarer"}, "seconds_median": 0.0002, "rays": 5304.0,
     "errors": {"rel_rmse": 0.17, "delta_e_mean": 2.26, "delta_e_p99": 28.05, "flip_mean": 0.072},
     "against_scene": {"rel_rmse": 0.01, "delta_e_mean": 0.1, "delta_e_p99": 0.5, "flip_mean": 0.01},
     "pareto": ["rel_rmse", "delta_e_mean", "delta_e_p99", "flip_mean"], "verdict": "worth_it"}
  ]}"#;

/// `value` with the findings its rows give, as the command writes them
/// (none where its rows do not parse).
fn with_findings(mut value: serde_json::Value) -> serde_json::Value {
    if let Ok(record) = serde_json::from_value::<Record>(value.clone()) {
        value["findings"] = serde_json::to_value(Findings::of(&record)).unwrap();
    }
    value
}

fn record(edit: impl FnOnce(&mut serde_json::Value)) -> Result<Record, ReferenceError> {
    let mut value: serde_json::Value = serde_json::from_str(RECORD).unwrap();
    edit(&mut value);
    let text = with_findings(value).to_string();
    validation::reference::parse(Path::new("x.json"), &text, "optics.tradeoff")
}

fn failures(edit: impl FnOnce(&mut serde_json::Value)) -> Vec<String> {
    check(Path::new("docs/tradeoffs/x.json"), &record(edit)).failures
}

#[test]
fn a_record_whose_fronts_and_verdicts_are_its_numbers_passes() {
    let c = check(Path::new("docs/tradeoffs/x.json"), &record(|_| {}));
    assert!(c.passed(), "{:?}", c.failures);
    assert_eq!(c.id, "tradeoff.x");
    assert_eq!(c.cases, 2);
}

#[test]
fn a_front_its_numbers_contradict_fails() {
    let f = failures(|v| v["points"][0]["pareto"] = serde_json::json!(["rel_rmse"]));
    // On the rel_rmse front though beaten; off three it is on.
    assert_eq!(f.len(), 4, "{f:?}");
    assert!(f[0].contains("recorded on the rel_rmse front"), "{f:?}");
}

#[test]
fn a_verdict_the_rule_contradicts_fails() {
    let f = failures(|v| v["points"][1]["verdict"] = serde_json::json!("trade"));
    assert_eq!(f.len(), 1, "{f:?}");
    assert!(f[0].contains("numbers give WorthIt"), "{f:?}");
    let f = failures(|v| {
        v["points"][1].as_object_mut().unwrap().remove("verdict");
    });
    assert_eq!(f.len(), 1, "a shortcut without its verdict: {f:?}");
}

#[test]
fn a_flip_beyond_one_or_a_negative_error_fails() {
    let f = failures(|v| v["points"][1]["errors"]["flip_mean"] = serde_json::json!(1.5));
    assert!(
        f.iter()
            .any(|f| f.contains("flip_mean against the truth is 1.5")),
        "{f:?}"
    );
    let f = failures(|v| v["points"][0]["against_scene"]["rel_rmse"] = serde_json::json!(-0.1));
    assert!(
        f.iter()
            .any(|f| f.contains("rel_rmse against the scene is -0.1")),
        "{f:?}"
    );
}

/// Findings that are not those the rows give fail, and so does a record
/// without any (written before they were recorded).
#[test]
fn findings_the_rows_contradict_fail() {
    let mut value = with_findings(serde_json::from_str(RECORD).unwrap());
    value["findings"]["worth_it"] = serde_json::json!([]);
    let parsed =
        validation::reference::parse(Path::new("x.json"), &value.to_string(), "optics.tradeoff");
    let f = check(Path::new("docs/tradeoffs/x.json"), &parsed).failures;
    assert_eq!(f.len(), 1, "{f:?}");
    assert!(f[0].contains("not those its rows give"), "{f:?}");
    let bare: serde_json::Value = serde_json::from_str(RECORD).unwrap();
    let parsed =
        validation::reference::parse(Path::new("x.json"), &bare.to_string(), "optics.tradeoff");
    let f = check(Path::new("docs/tradeoffs/x.json"), &parsed).failures;
    assert!(f.len() == 1 && f[0].contains("no findings"), "{f:?}");
}

#[test]
fn an_unconverged_truth_fails() {
    let f = failures(|v| v["truth"]["noise_relative"] = serde_json::json!(0.02));
    assert_eq!(f.len(), 1, "{f:?}");
    assert!(f[0].contains("not converged"), "{f:?}");
}

#[test]
fn a_record_of_another_version_or_malformed_fails_naming_it() {
    let f = failures(|v| v["version"] = serde_json::json!(3));
    assert!(
        f[0].contains("version 3") && f[0].contains("docs/tradeoffs/make"),
        "{f:?}"
    );
    let f = failures(|v| v["points"][1]["seconds_median"] = serde_json::json!("fast"));
    assert!(f[0].contains("points[1].seconds_median"), "{f:?}");
    let f = failures(|v| v["schema"] = serde_json::json!("optics.other"));
    assert!(f[0].contains("optics.other"), "{f:?}");
}

/// The records `docs/tradeoffs/make` committed pass the checks, and there
/// is one for every lit course scene it sweeps.
#[test]
fn the_committed_records_pass() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(DIR);
    let records = read(&dir).expect("docs/tradeoffs");
    assert_eq!(records.len(), 8, "one record a swept scene");
    for (file, record) in &records {
        let c = check(file, record);
        assert!(c.passed(), "{}: {:?}", file.display(), c.failures);
    }
}

// -- fuzz ---------------------------------------------------------------------

/// Every number and string leaf of the sample record, by JSON pointer.
fn leaves(value: &serde_json::Value, at: String, out: &mut Vec<String>) {
    match value {
        serde_json::Value::Object(map) => {
            for (k, v) in map {
                leaves(v, format!("{at}/{k}"), out);
            }
        }
        serde_json::Value::Array(items) => {
            for (i, v) in items.iter().enumerate() {
                leaves(v, format!("{at}/{i}"), out);
            }
        }
        _ => out.push(at),
    }
}

/// What a leaf becomes: values at the edges of `f64`, a wrong type, or
/// nothing at all.
fn mutations() -> Vec<serde_json::Value> {
    use serde_json::json;
    vec![
        json!(-1.0),
        json!(0.0),
        json!(-0.0),
        json!(1e308),
        json!(-1e308),
        json!(5e-324),
        json!(1.0000001),
        json!(null),
        json!("x"),
        json!([]),
        json!({}),
        json!(true),
        json!(u64::MAX),
    ]
}

/// A record with any one or two leaves changed or removed is checked
/// without a panic, and passes only if every measure it carries is still a
/// value the measure can take and its fronts and verdicts still follow
/// from its numbers: no forbidden number reaches the report as a pass.
#[test]
fn fuzz_a_mutated_record_never_passes_with_a_forbidden_number() {
    use proptest::prelude::*;
    let base = with_findings(serde_json::from_str(RECORD).unwrap());
    let mut paths = Vec::new();
    leaves(&base, String::new(), &mut paths);
    let edits = proptest::collection::vec((0..paths.len(), 0..mutations().len() + 1), 1..=2);
    let caught = std::cell::Cell::new(0u32);
    proptest::proptest!(ProptestConfig::with_cases(512), |(edit in edits)| {
        let mut value = base.clone();
        for &(leaf, to) in &edit {
            let path = &paths[leaf];
            let (parent, key) = path.rsplit_once('/').unwrap();
            match (value.pointer_mut(parent), mutations().get(to)) {
                (Some(serde_json::Value::Object(map)), Some(new)) => { map.insert(key.into(), new.clone()); }
                (Some(serde_json::Value::Object(map)), None) => { map.remove(key); }
                (Some(serde_json::Value::Array(items)), Some(new)) => {
                    if let Ok(i) = key.parse::<usize>() { if i < items.len() { items[i] = new.clone(); } }
                }
                _ => {}
            }
        }
        let text = value.to_string();
        let parsed = validation::reference::parse::<Record>(Path::new("x.json"), &text, "optics.tradeoff");
        let c = check(Path::new("docs/tradeoffs/x.json"), &parsed);
        if !c.passed() {
            caught.set(caught.get() + 1);
            prop_assert!(c.failures.iter().all(|f| !f.is_empty()));
        }
        if let (true, Ok(record)) = (c.passed(), &parsed) {
            for p in &record.points {
                for e in [p.errors, p.against_scene] {
                    for m in validation::tradeoff::MEASURES {
                        let v = e.get(m);
                        prop_assert!(v.is_finite() && v >= 0.0, "{m} = {v} passed");
                        prop_assert!(m != "flip_mean" || v <= 1.0, "ꟻLIP {v} passed");
                    }
                }
                prop_assert!(p.seconds_median > 0.0 && p.seconds_median.is_finite());
            }
            prop_assert!(record.truth.noise_relative <= validation::tradeoff::checks::UNCONVERGED);
        }
    });
    // The mutations reach the checks: most records made wrong are refused.
    assert!(
        caught.get() > 256,
        "only {} of 512 mutated records refused",
        caught.get()
    );
}

/// The record's settings against Mitsuba's truth, ranked alike under both.
fn mitsuba() -> serde_json::Value {
    let against = |label: &str, rmse: f64| {
        serde_json::json!({"label": label, "light": 1.0, "light_se": 0.001,
                           "rel_rmse": rmse, "rel_rmse_truth": rmse})
    };
    serde_json::json!({"measured": {
        "scene": "gold_spheres", "estimate": "ptracer", "region": "diffuse",
        "width": 40, "height": 30, "factor": 2, "pixels": 11, "passes": 16, "spp": 64,
        "max_depth": 16, "floor": against("truth", 0.02),
        "points": [against("scene", 0.2), against("fresnel schlick-rarer", 0.1)],
        "ranking": {"concordant": 1, "discordant": []}}})
}

#[test]
fn a_mitsuba_truth_is_held_to_its_numbers_and_its_settings() {
    let c = check(
        Path::new("docs/tradeoffs/x.json"),
        &record(|v| v["mitsuba"] = mitsuba()),
    );
    assert!(c.passed(), "{:?}", c.failures);
    let f = failures(|v| {
        v["mitsuba"] = mitsuba();
        v["mitsuba"]["measured"]["ranking"]["concordant"] = serde_json::json!(0);
    });
    assert_eq!(f.len(), 1, "{f:?}");
    assert!(f[0].contains("ranking"), "{f:?}");
    let f = failures(|v| {
        v["mitsuba"] = mitsuba();
        v["mitsuba"]["measured"]["points"][1]["label"] = serde_json::json!("fresnel course");
    });
    assert!(f.iter().any(|m| m.contains("not the record's")), "{f:?}");
    let f = failures(|v| v["mitsuba"] = serde_json::json!({"no_reference": ""}));
    assert_eq!(f.len(), 1, "{f:?}");
    let c = check(
        Path::new("docs/tradeoffs/x.json"),
        &record(|v| v["mitsuba"] = serde_json::json!({"no_reference": "a reason"})),
    );
    assert!(c.passed(), "{:?}", c.failures);
}

/// A record of version 1 named Schlick's rarer-medium form `schlick`: it
/// is read with that name mapped (`record::upgrade`), as version 2, and
/// passes as the same record written with the new names does; a
/// version-2 record is read as written.
#[test]
fn a_version_1_record_is_read_with_its_schlick_named_as_the_rarer_form() {
    let current = with_findings(serde_json::from_str(RECORD).unwrap()).to_string();
    // As version 1 wrote it: every name of the form bare.
    let old = current
        .replace("schlick-rarer", "schlick")
        .replace("\"version\":2", "\"version\":1");
    assert!(
        old.contains("\"fresnel schlick\"") && old.contains("\"version\":1"),
        "{old}"
    );
    let upgraded = validation::tradeoff::record::upgrade(&old);
    let read: Record =
        validation::reference::parse(Path::new("x.json"), &upgraded, "optics.tradeoff").unwrap();
    assert_eq!(read.version, 2);
    assert_eq!(read.points[1].label, "fresnel schlick-rarer");
    assert_eq!(read.points[1].settings.fresnel, "schlick-rarer");
    let schlick = read
        .findings
        .as_ref()
        .and_then(|f| f.schlick.as_ref())
        .expect("the finding");
    assert_eq!(schlick.shortcut.label, "fresnel schlick-rarer");
    let c = check(Path::new("docs/tradeoffs/x.json"), &Ok(read));
    assert!(c.passed(), "{:?}", c.failures);
    assert_eq!(validation::tradeoff::record::upgrade(RECORD), RECORD);
}
