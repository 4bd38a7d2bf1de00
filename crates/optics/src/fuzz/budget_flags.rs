//! Budget flags: `optics render --tolerance T --metric M` command lines
//! with the budget's flags (`--tolerance`, `--metric`, `--pilot-spp`,
//! `--verify` with `--truth-spp`, `--lambert`) typed as people type them, some spoiled
//! (zero, negative, NaN, infinite, text, an unknown metric, a setting the
//! budget chooses given beside it, a value given to the switch
//! `--lambert`), through the parser and the budget's
//! settling. The promises: a clean line settles to the tolerance and the
//! metric it gives (every fixed measure is predicted), the tolerance
//! finite and above 0, `--lambert` set exactly where given; a spoiled one
//! is a usage error naming its flag; nothing panics.

use super::{refused_by_usage, run_and_report, runner, Coverage};
use crate::budget::TOLERANCE_UNCHECKED;
use clap::Parser;
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

/// Each flag, values it takes and values it must refuse.
const FLAGS: [(&str, &[&str], &[&str]); 4] = [
    (
        "--tolerance",
        &["0.05", "1", "1e-3", "+0.2", "3"],
        &[
            "0", "-0", "-0.1", "NaN", "nan", "inf", "-inf", "1e400", "five", "",
        ],
    ),
    (
        "--metric",
        &["rel_rmse", "delta_e_mean", "delta_e_p99", "flip_mean"],
        &["psnr", "RMSE", "rel-rmse", ""],
    ),
    (
        "--pilot-spp",
        &["2", "8", "1024"],
        &["1", "0", "1025", "-8", "x"],
    ),
    ("--truth-spp", &["2", "256"], &["1", "0", "1e3"]),
];

/// A setting the budget chooses itself, refused beside `--tolerance`.
const CHOSEN: [(&str, &str); 3] = [
    ("--spp", "4"),
    ("--max-depth", "3"),
    ("--fresnel", "schlick-incident"),
];

/// How `--lambert` is given: left out, as the switch it is, or with a
/// value a switch refuses.
const LAMBERT: [Option<&str>; 4] = [
    None,
    Some("--lambert"),
    Some("--lambert=yes"),
    Some("--lambert="),
];

/// A command line and the flag it spoiled, if any.
#[derive(Clone, Debug)]
struct Line {
    args: Vec<String>,
    given: Vec<(&'static str, &'static str)>,
    lambert: bool,
    spoiled: Option<&'static str>,
}

fn command_line() -> impl Strategy<Value = Line> {
    let pick = (any::<bool>(), 0..16usize);
    (
        prop::collection::vec(pick, FLAGS.len()),
        prop::option::weighted(0.1, 0..CHOSEN.len()),
        0..LAMBERT.len(),
    )
        .prop_map(|(picks, chosen, lambert)| {
            let mut given: Vec<(&'static str, &'static str)> = Vec::new();
            let mut spoiled = None;
            for ((flag, good, bad), (spoil, k)) in FLAGS.iter().zip(picks) {
                if spoil && spoiled.is_none() {
                    given.push((flag, bad[k % bad.len()]));
                    spoiled = Some(*flag);
                } else {
                    given.push((flag, good[k % good.len()]));
                }
            }
            let mut args: Vec<String> = [
                "optics",
                "render",
                "scene.json",
                "-o",
                "out.png",
                "--verify",
            ]
            .map(str::to_owned)
            .to_vec();
            for (flag, value) in &given {
                // `=` keeps a value that starts with `-` a value.
                args.push(format!("{flag}={value}"));
            }
            let lambert = LAMBERT[lambert];
            if let Some(flag) = lambert {
                args.push(flag.to_owned());
                if flag != "--lambert" && spoiled.is_none() {
                    spoiled = Some("--lambert");
                }
            }
            if let Some(i) = chosen.filter(|_| spoiled.is_none()) {
                let (flag, value) = CHOSEN[i];
                args.push(format!("{flag}={value}"));
                spoiled = Some(flag);
            }
            Line {
                args,
                given,
                lambert: lambert.is_some(),
                spoiled,
            }
        })
}

fn check_line(line: &Line, coverage: &Coverage) -> Result<(), TestCaseError> {
    match crate::Cli::try_parse_from(&line.args) {
        Ok(cli) => {
            prop_assert!(line.spoiled.is_none(), "{:?} accepted", line.args);
            let crate::Command::Render(args) = &cli.command else {
                unreachable!("the lines are render lines")
            };
            prop_assert_eq!(
                args.budget.lambert,
                line.lambert,
                "{:?}: --lambert settled wrongly",
                line.args
            );
            let tolerance = args.budget.tolerance.unwrap_or(f64::NAN);
            prop_assert!(
                tolerance.is_finite() && tolerance > 0.0,
                "{:?}: --tolerance {}",
                line.args,
                tolerance
            );
            let want: f64 = line.given[0].1.parse().unwrap_or(f64::NAN);
            prop_assert_eq!(
                tolerance,
                want,
                "{:?}: --tolerance settled wrongly",
                line.args
            );
            let Some(budget) = args.budget.settle() else {
                return Err(TestCaseError::fail(format!(
                    "{:?}: no budget settled",
                    line.args
                )));
            };
            coverage.answer();
            prop_assert_eq!(budget.metric.name(), line.given[1].1);
            prop_assert_eq!(budget.tolerance, want);
            Ok(())
        }
        Err(usage) => {
            // A conflict names either side of it.
            let conflict: &[&str] = match line.spoiled {
                Some(flag) if CHOSEN.iter().any(|(f, _)| *f == flag) => &["--tolerance"],
                _ => &[],
            };
            refused_by_usage(
                usage,
                &line.args,
                line.spoiled,
                conflict,
                "render",
                coverage,
            )
        }
    }
}

fn fuzz(cases: u32, coverage: &Coverage) -> Result<(), String> {
    runner(cases)
        .run(&command_line(), |line| check_line(&line, coverage))
        .map_err(|e| e.to_string())
}

#[test]
fn budget_flags_settle_to_their_values_or_refuse_by_flag() {
    run_and_report("budget flags", fuzz);
}

#[test]
fn budget_flags_find_a_tolerance_not_checked() {
    TOLERANCE_UNCHECKED.set(true);
    let failure = fuzz(256, &Coverage::default());
    TOLERANCE_UNCHECKED.set(false);
    let failure = failure.expect_err("the unchecked --tolerance is found");
    assert!(failure.contains("accepted"), "{failure}");
}
