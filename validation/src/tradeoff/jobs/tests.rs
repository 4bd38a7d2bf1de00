//! The job lines' field lists and plan ids.

use serde::Serialize;
use serde_json::Value;

use super::*;

fn keys(value: impl Serialize) -> Vec<String> {
    match serde_json::to_value(value) {
        Ok(Value::Object(map)) => map.keys().cloned().collect(),
        _ => Vec::new(),
    }
}

fn sorted(fields: &[&str]) -> Vec<String> {
    let mut fields: Vec<String> = fields.iter().map(|&f| f.to_owned()).collect();
    fields.sort();
    fields
}

fn job() -> Job {
    Job {
        schema: LineKind::Job.schema().into(),
        version: VERSION,
        plan: "0".into(),
        job: 0,
        jobs: 1,
        scene: "s.json".into(),
        scene_fnv1a: "0".into(),
        lambert: false,
        width: 1,
        height: 1,
        spp: 1,
        truth_spp: 2,
        repeats: 1,
        min_seconds: 0.0,
        axis: "truth".into(),
        label: "truth, half 1 of 2".into(),
        settings: Value::Null,
    }
}

/// The lists the checks and the fuzz target name fields by are the
/// lines' own fields, every one.
#[test]
fn the_field_lists_are_the_lines_fields() {
    assert_eq!(keys(job()), sorted(&JOB_FIELDS));
    let result = JobResult {
        schema: LineKind::Result.schema().into(),
        version: VERSION,
        plan: "0".into(),
        planned_as: "optics tradeoff s.json".into(),
        scene_fnv1a: "0".into(),
        job: 0,
        jobs: 1,
        label: "l".into(),
        seconds: vec![0.0],
        rays: 0.0,
        machine: "m".into(),
        date: "d".into(),
        load: None,
        images: Vec::new(),
    };
    assert_eq!(keys(result), sorted(&RESULT_FIELDS));
}

/// `--min-seconds` 0.1 read back one unit in the last place off is the
/// same plan; 0.1 against 0.2 is not.
#[test]
fn a_plan_id_survives_a_float_read_back_one_ulp_off() {
    let key = job().key();
    let nudged = PlanKey {
        min_seconds: f64::from_bits(0.1_f64.to_bits() + 1),
        ..PlanKey {
            min_seconds: 0.1,
            ..key.clone()
        }
    };
    let exact = PlanKey {
        min_seconds: 0.1,
        ..key.clone()
    };
    assert_eq!(nudged.id(), exact.id());
    let other = PlanKey {
        min_seconds: 0.2,
        ..key
    };
    assert_ne!(other.id(), exact.id());
    assert!(same(
        &serde_json::json!(0.1),
        &serde_json::json!(nudged.min_seconds)
    ));
    assert!(!same(&serde_json::json!(0.1), &serde_json::json!(0.2)));
}
