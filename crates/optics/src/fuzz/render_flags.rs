//! Render flags: `optics render` and `optics inspect` command lines with
//! the settings that pick a choice (`--integrator`, `--pixel-filter`,
//! `--fresnel`, `--precision`) typed as people type them, some spoiled,
//! through the parser and the job's settling over a course scene. The
//! promises: a clean line parses and settles to the filter it names, else
//! to the default of the integrator it names, else to the scene's, and to
//! the tier it names (else `f32`) where its integrator computes in it, a
//! refusal naming `overrides.precision` where not, and to the Fresnel law
//! it names, the bare `schlick` refused naming `overrides.fresnel`; a
//! spoiled value is a usage error naming its flag; nothing panics.

use std::path::PathBuf;

use super::{refused_by_usage, run_and_report, runner, Coverage};
use crate::render::JobArgs;
use clap::Parser;
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use tracer::scene::{IntegratorKind, PixelFilter, Precision};

/// The scene the lines render: its `render` names `whitted`, so its own
/// filter is `center`.
fn scene() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../tracer/scenes/gold_spheres.json")
}

const INTEGRATORS: [&str; 4] = ["local", "whitted", "path", "course"];
const FILTERS: [&str; 2] = ["box", "center"];
const FRESNELS: [&str; 5] = [
    "exact",
    "schlick-incident",
    "schlick-rarer",
    "course",
    "schlick",
];
const PRECISIONS: [&str; 2] = ["f32", "f64"];
/// The flags whose values are choices, in the order a spoiling picks them.
const CHOICE_FLAGS: [&str; 4] = ["--integrator", "--pixel-filter", "--fresnel", "--precision"];
/// Text that is no choice of these flags: near misses and others' values.
const NOT_CHOICES: [&str; 10] = [
    "F64",
    "f16",
    "",
    "Box",
    "centre",
    "gaussian",
    "1",
    "--spp",
    "box,center",
    "path",
];

/// A command line and the choices it gives, `None` for a flag not given.
#[derive(Clone, Debug)]
struct Line {
    args: Vec<String>,
    integrator: Option<&'static str>,
    filter: Option<&'static str>,
    fresnel: Option<&'static str>,
    precision: Option<&'static str>,
    spoiled: Option<&'static str>,
}

fn choice(values: &'static [&'static str]) -> impl Strategy<Value = Option<&'static str>> {
    prop::option::of(prop::sample::select(values))
}

fn command_line() -> impl Strategy<Value = Line> {
    (
        any::<bool>(),
        choice(&INTEGRATORS),
        (choice(&FILTERS), choice(&FRESNELS), choice(&PRECISIONS)),
        prop::option::weighted(0.3, (0..4usize, prop::sample::select(NOT_CHOICES.to_vec()))),
        any::<bool>(),
    )
        .prop_map(
            |(inspect, integrator, (filter, fresnel, tier), spoil, reversed)| {
                let mut flags: Vec<(&'static str, &'static str)> = Vec::new();
                flags.extend(integrator.map(|v| ("--integrator", v)));
                flags.extend(filter.map(|v| ("--pixel-filter", v)));
                flags.extend(fresnel.map(|v| ("--fresnel", v)));
                flags.extend(tier.map(|v| ("--precision", v)));
                // A spoiled value replaces one flag's, or arrives as a new flag.
                let mut spoiled = None;
                if let Some((which, text)) = spoil {
                    let flag = CHOICE_FLAGS[which];
                    flags.retain(|(f, _)| *f != flag);
                    // "path" is a value of --integrator: not a spoiling there.
                    if !(flag == "--integrator" && text == "path") {
                        flags.push((flag, text));
                        spoiled = Some(flag);
                    }
                }
                if reversed {
                    flags.reverse();
                }
                let mut args = vec!["optics".to_owned()];
                args.push(if inspect { "inspect" } else { "render" }.to_owned());
                args.push(scene().display().to_string());
                if !inspect {
                    args.extend(["-o".to_owned(), "never-written.png".to_owned()]);
                }
                for (flag, value) in &flags {
                    args.extend([flag.to_string(), value.to_string()]);
                }
                let given = |name: &str| flags.iter().find(|(f, _)| *f == name).map(|(_, v)| *v);
                Line {
                    integrator: given("--integrator").filter(|v| INTEGRATORS.contains(v)),
                    filter: given("--pixel-filter").filter(|v| FILTERS.contains(v)),
                    fresnel: given("--fresnel").filter(|v| FRESNELS.contains(v)),
                    precision: given("--precision").filter(|v| PRECISIONS.contains(v)),
                    spoiled,
                    args,
                }
            },
        )
}

/// The filter a line must settle to: the one it names, else its
/// integrator's default, else the scene's own (`center`, under `whitted`).
fn expected(line: &Line) -> PixelFilter {
    let parse = |v: &str| match v {
        "box" => PixelFilter::Box,
        _ => PixelFilter::Center,
    };
    let integrator = |v: &str| match v {
        "local" => IntegratorKind::Local,
        "path" => IntegratorKind::Path,
        "course" => IntegratorKind::Course,
        _ => IntegratorKind::Whitted,
    };
    match (line.filter, line.integrator) {
        (Some(f), _) => parse(f),
        (None, Some(i)) => PixelFilter::default_for(integrator(i)),
        (None, None) => PixelFilter::Center,
    }
}

fn job_args(cli: &crate::Cli) -> &JobArgs {
    match &cli.command {
        crate::Command::Render(args) => &args.job,
        crate::Command::Inspect(args) => &args.job,
        _ => unreachable!("the lines are render and inspect lines"),
    }
}

/// The flag whose value is not handed on to the job: the fault a run
/// must find, or none.
#[derive(Clone, Copy, PartialEq)]
enum Dropped {
    Nothing,
    PixelFilter,
    Precision,
}

/// The tier a line names, else the scene's `f32`, and whether its
/// integrator (the one it names, else the scene's `whitted`) computes in it.
fn expected_tier(line: &Line) -> (Precision, bool) {
    let precision = match line.precision {
        Some("f64") => Precision::F64,
        _ => Precision::F32,
    };
    let served = precision == Precision::F32
        || matches!(line.integrator, None | Some("local") | Some("whitted"));
    (precision, served)
}

/// One line: parsed, then settled by the job (`dropped`: a flag's value
/// not handed on to the job, the fault the target must find).
fn check_line(line: &Line, dropped: Dropped, coverage: &Coverage) -> Result<(), TestCaseError> {
    match crate::Cli::try_parse_from(&line.args) {
        Ok(cli) => {
            prop_assert!(line.spoiled.is_none(), "{:?} accepted", line.args);
            let mut args = job_args(&cli).clone();
            match dropped {
                Dropped::Nothing => {}
                Dropped::PixelFilter => args.pixel_filter = None,
                Dropped::Precision => args.precision = None,
            }
            let (precision, served) = expected_tier(line);
            let job = match args.job(&scene()) {
                // Settled before the tier is checked against the integrator.
                Err(e) if line.fresnel == Some("schlick") => {
                    let json = e.to_json(record::Lang::En);
                    coverage.error(&json);
                    prop_assert_eq!(json["field"].as_str(), Some("overrides.fresnel"));
                    prop_assert_eq!(json["kind"].as_str(), Some("scene.schlick_form_unnamed"));
                    return Ok(());
                }
                Ok(_) if line.fresnel == Some("schlick") => {
                    return Err(TestCaseError::fail(format!(
                        "{:?}: the bare schlick settled",
                        line.args
                    )))
                }
                Err(e) if !served => {
                    let json = e.to_json(record::Lang::En);
                    coverage.error(&json);
                    prop_assert_eq!(json["field"].as_str(), Some("overrides.precision"));
                    return Ok(());
                }
                Err(e) => return Err(TestCaseError::fail(format!("{:?}: {e}", line.args))),
                Ok(_) if !served => {
                    return Err(TestCaseError::fail(format!(
                        "{:?}: f64 settled beside an f32-only integrator",
                        line.args
                    )))
                }
                Ok(job) => job,
            };
            coverage.answer();
            if let Some(fresnel) = line.fresnel {
                prop_assert_eq!(job.settings().fresnel.to_string(), fresnel);
            }
            prop_assert_eq!(
                job.settings().precision,
                precision,
                "{:?} settled the tier wrongly",
                line.args
            );
            prop_assert_eq!(
                job.settings().pixel_filter,
                expected(line),
                "{:?} settled wrongly",
                line.args
            );
            Ok(())
        }
        Err(usage) => refused_by_usage(usage, &line.args, line.spoiled, &[], "render", coverage),
    }
}

fn fuzz(cases: u32, dropped: Dropped, coverage: &Coverage) -> Result<(), String> {
    runner(cases)
        .run(&command_line(), |line| check_line(&line, dropped, coverage))
        .map_err(|e| e.to_string())
}

#[test]
fn render_flags_settle_to_the_filter_they_name_or_refuse_by_flag() {
    run_and_report("render flags", |cases, coverage| {
        fuzz(cases, Dropped::Nothing, coverage)
    });
}

#[test]
fn render_flags_find_a_pixel_filter_not_handed_on() {
    let failure = fuzz(256, Dropped::PixelFilter, &Coverage::default())
        .expect_err("the dropped flag is found");
    assert!(failure.contains("settled wrongly"), "{failure}");
}

#[test]
fn render_flags_find_a_precision_not_handed_on() {
    let failure =
        fuzz(256, Dropped::Precision, &Coverage::default()).expect_err("the dropped flag is found");
    assert!(
        failure.contains("the tier wrongly") || failure.contains("f64 settled beside"),
        "{failure}"
    );
}
