//! Technique flags: `optics envmap`, `reflection-matrix` and
//! `shadow-matrix` command lines with vectors at the edges of `f64` (NaN
//! and infinities among them), typed as people type them, some spoiled,
//! through the parser and the command. The promises: a clean line is not
//! refused by the parser; an error names a flag given; a record holds no
//! NaN (no `null`), texels lie in `[0, 1]`, a shadow is `parallel` only
//! where the line from the light runs along the plane and `degenerate`
//! only where the light lies on it; an overflow is claimed only of finite
//! inputs.

use super::{check_error_field, number_text, run_and_report, runner, Coverage};
use clap::{CommandFactory, FromArgMatches};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use record::Lang;
use serde_json::Value;

/// Each command's flags, as the record's inputs name them.
const COMMANDS: [(&str, &[&str]); 3] = [
    ("envmap", &["dir", "map"]),
    (
        "reflection-matrix",
        &["plane_point", "plane_normal", "point", "direction"],
    ),
    (
        "shadow-matrix",
        &["light", "plane_point", "plane_normal", "vertex"],
    ),
];

const MAPS: [&str; 4] = ["cube", "lat-long", "sphere", "all"];

/// Text that is not a value of the flag it is given to.
const NOT_VALUES: [&str; 8] = ["", "-", "abc", "1,2", "1,,2,3", "1e", "octahedral", "--dir"];

#[derive(Clone, Debug)]
struct Line {
    command: &'static str,
    args: Vec<String>,
    clean: bool,
}

/// A component as typed: an edge of `f64`, or now and then NaN or an
/// infinity, which parse as numbers and must be refused by name.
fn component() -> impl Strategy<Value = String> {
    prop_oneof![
        9 => number_text(),
        1 => prop::sample::select(vec!["NaN", "inf", "-inf"]).prop_map(str::to_owned),
    ]
}

fn value(field: &str) -> BoxedStrategy<String> {
    match field {
        "map" => prop::sample::select(MAPS.to_vec())
            .prop_map(str::to_owned)
            .boxed(),
        _ => prop::array::uniform3(component())
            .prop_map(|v| v.join(","))
            .boxed(),
    }
}

fn command_line() -> impl Strategy<Value = Line> {
    (0..COMMANDS.len()).prop_flat_map(|i| {
        let (command, fields) = COMMANDS[i];
        let values: Vec<_> = fields
            .iter()
            .map(|&field| (Just(field), value(field), any::<bool>()))
            .collect();
        let spoil = (
            any::<prop::sample::Index>(),
            prop::sample::select(NOT_VALUES.to_vec()),
        );
        (values, prop::option::weighted(0.2, spoil), any::<bool>()).prop_map(
            move |(values, spoil, json)| {
                let mut args = vec!["optics".to_owned()];
                args.extend(json.then(|| "--json".to_owned()));
                args.push(command.to_owned());
                for (field, text, given) in values {
                    let optional = ["map", "vertex", "point", "direction"].contains(&field);
                    if given || !optional {
                        args.extend([format!("--{}", field.replace('_', "-")), text]);
                    }
                }
                let clean = spoil.is_none();
                if let Some((at, text)) = spoil {
                    let first = 2 + usize::from(json);
                    let i = first + at.index(args.len() - first);
                    args[i] = text.to_owned();
                }
                Line {
                    command,
                    args,
                    clean,
                }
            },
        )
    })
}

fn check_line(line: &Line, coverage: &Coverage) -> Result<(), TestCaseError> {
    let outcome = crate::Cli::command()
        .try_get_matches_from(&line.args)
        .and_then(|m| crate::Cli::from_arg_matches(&m))
        .map_err(|usage| crate::Error::from(crate::ErrorKind::Usage(usage)))
        .and_then(|cli| crate::law_record(&cli.command, Lang::En).expect("a technique's command"));
    match outcome {
        Ok(record) => {
            coverage.answer();
            check_record(&serde_json::to_value(&record).expect("a record is JSON"))
        }
        Err(error) => {
            let json = error.to_json(Lang::En);
            coverage.error(&json);
            let kind = json["kind"].as_str().unwrap_or_default();
            prop_assert!(
                !(kind == "usage" && line.clean),
                "{:?} refused: {json}",
                line.args
            );
            if kind == "overflow" {
                prop_assert!(
                    all_finite(&line.args),
                    "{:?}: an overflow claimed of input that is not finite: {json}",
                    line.args
                );
            }
            check_error_field(&json, &line.args, line.command, |f| {
                format!("--{}", f.replace('_', "-"))
            })
        }
    }
}

/// Whether every vector given on the line is three finite numbers.
fn all_finite(args: &[String]) -> bool {
    args.iter().filter(|a| a.contains(',')).all(|a| {
        a.split(',')
            .all(|c| c.trim().parse::<f64>().is_ok_and(f64::is_finite))
    })
}

fn check_record(record: &Value) -> Result<(), TestCaseError> {
    prop_assert!(!super::has_null(record), "a NaN in {record}");
    let answer = &record["answer"];
    for map in ["cube", "lat_long", "sphere"] {
        for coordinate in ["u", "v"] {
            if let Some(x) = answer[map][coordinate].as_f64() {
                prop_assert!(
                    (0.0..=1.0).contains(&x),
                    "{map} {coordinate} = {x}: {record}"
                );
            }
        }
    }
    let vector = |name: &str| {
        let v: Vec<f64> = record["inputs"][name]
            .as_array()
            .map(|a| a.iter().filter_map(Value::as_f64).collect())
            .unwrap_or_default();
        glam::DVec3::from_slice(&v)
    };
    if record["details"]["matrix"] == "degenerate" {
        let (light, point) = (vector("light"), vector("plane_point"));
        let n = radiometry::domain::direction("n", vector("plane_normal"))
            .map_err(|e| TestCaseError::fail(e.to_string()))?
            .unit;
        // On the plane to the rounding of the inputs' sizes.
        let height = n.dot(light - point).abs();
        let scale = light.abs().max_element() + point.abs().max_element();
        prop_assert!(
            height <= 1e-12 * scale,
            "degenerate, but n · (l − p) = {height}: {record}"
        );
    }
    if record["details"]["outcome"] == "parallel" {
        let (light, vertex) = (vector("light"), vector("vertex"));
        let n = radiometry::domain::direction("n", vector("plane_normal"))
            .map_err(|e| TestCaseError::fail(e.to_string()))?
            .unit;
        // Along the plane to the rounding of the inputs' sizes.
        let along = n.dot(vertex - light).abs();
        let scale = light.abs().max_element() + vertex.abs().max_element();
        prop_assert!(
            along <= 1e-12 * scale,
            "parallel, but n · (v − l) = {along}: {record}"
        );
    }
    Ok(())
}

fn fuzz(cases: u32, coverage: &Coverage) -> Result<(), String> {
    runner(cases)
        .run(&command_line(), |line| check_line(&line, coverage))
        .map_err(|e| e.to_string())
}

#[test]
fn technique_flags_keep_their_promises() {
    run_and_report("technique flags", fuzz);
}

#[test]
fn technique_flags_find_a_nan_vertex_let_through() {
    use crate::planar::UNCHECKED_VERTEX;
    UNCHECKED_VERTEX.set(true);
    let outcome = fuzz(512, &Coverage::default());
    UNCHECKED_VERTEX.set(false);
    let failure = outcome.expect_err("the reverted check is found");
    assert!(failure.contains("not finite"), "{failure}");
}
