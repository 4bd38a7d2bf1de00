//! Trade-off flags: `optics tradeoff` command lines with its numeric
//! settings (`--spp`, `--truth-spp`, `--repeats`, `--min-seconds`,
//! `--width`, `--height`) typed as people type them, some spoiled (zero,
//! negative, past the range, NaN, infinite, text), through the parser. The
//! promises: a clean line parses to the values it gives, each finite and in
//! its range; a spoiled value is a usage error naming its flag; nothing
//! panics.

use super::{refused_by_usage, run_and_report, runner, Coverage};
use crate::tradeoff::SECONDS_UNCHECKED;
use clap::Parser;
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

/// Each flag, a value it takes and values it must refuse.
const FLAGS: [(&str, &[&str], &[&str]); 6] = [
    (
        "--spp",
        &["1", "16", "1048576"],
        &["0", "-1", "1048577", "1.5", "NaN", ""],
    ),
    (
        "--truth-spp",
        &["2", "256", "1048576"],
        &["1", "0", "-4", "1e3", "inf"],
    ),
    (
        "--repeats",
        &["1", "3", "100"],
        &["0", "101", "-3", "three"],
    ),
    (
        "--min-seconds",
        &["0", "0.5", "60", "1e-3", "+2"],
        &["NaN", "nan", "inf", "-inf", "-1", "60.5", "1e400", "half"],
    ),
    (
        "--width",
        &["1", "160", "16384"],
        &["0", "16385", "-160", "1e2"],
    ),
    ("--height", &["1", "120", "16384"], &["0", "16385", "x"]),
];

/// A command line and the flag it spoiled, if any.
#[derive(Clone, Debug)]
struct Line {
    args: Vec<String>,
    given: Vec<(&'static str, &'static str)>,
    spoiled: Option<&'static str>,
}

fn command_line() -> impl Strategy<Value = Line> {
    let flag = (0..FLAGS.len(), any::<bool>(), 0..16usize);
    prop::collection::vec(flag, 0..5).prop_map(|picks| {
        let mut given: Vec<(&'static str, &'static str)> = Vec::new();
        let mut spoiled = None;
        for (which, spoil, k) in picks {
            let (flag, good, bad) = FLAGS[which];
            if given.iter().any(|(f, _)| *f == flag) {
                continue;
            }
            if spoil && spoiled.is_none() {
                given.push((flag, bad[k % bad.len()]));
                spoiled = Some(flag);
            } else {
                given.push((flag, good[k % good.len()]));
            }
        }
        let mut args = vec![
            "optics".to_owned(),
            "tradeoff".to_owned(),
            "scene.json".to_owned(),
        ];
        for (flag, value) in &given {
            // `=` keeps a value that starts with `-` a value.
            args.push(format!("{flag}={value}"));
        }
        Line {
            args,
            given,
            spoiled,
        }
    })
}

fn check_line(line: &Line, coverage: &Coverage) -> Result<(), TestCaseError> {
    match crate::Cli::try_parse_from(&line.args) {
        Ok(cli) => {
            prop_assert!(line.spoiled.is_none(), "{:?} accepted", line.args);
            let crate::Command::Tradeoff(args) = &cli.command else {
                unreachable!("the lines are tradeoff lines")
            };
            coverage.answer();
            prop_assert!(
                args.min_seconds.is_finite() && (0.0..=60.0).contains(&args.min_seconds),
                "{:?}: --min-seconds {}",
                line.args,
                args.min_seconds
            );
            for (flag, value) in &line.given {
                let parsed = match *flag {
                    "--spp" => f64::from(args.spp),
                    "--truth-spp" => f64::from(args.truth_spp),
                    "--repeats" => f64::from(args.repeats),
                    "--min-seconds" => args.min_seconds,
                    "--width" => args.size.width.map_or(f64::NAN, f64::from),
                    _ => args.size.height.map_or(f64::NAN, f64::from),
                };
                let want: f64 = value.parse().unwrap_or(f64::NAN);
                prop_assert_eq!(parsed, want, "{:?}: {} settled wrongly", line.args, flag);
            }
            Ok(())
        }
        Err(usage) => refused_by_usage(usage, &line.args, line.spoiled, &[], "tradeoff", coverage),
    }
}

fn fuzz(cases: u32, coverage: &Coverage) -> Result<(), String> {
    runner(cases)
        .run(&command_line(), |line| check_line(&line, coverage))
        .map_err(|e| e.to_string())
}

#[test]
fn tradeoff_flags_parse_to_their_values_or_refuse_by_flag() {
    run_and_report("tradeoff flags", fuzz);
}

#[test]
fn tradeoff_flags_find_a_seconds_range_not_checked() {
    SECONDS_UNCHECKED.set(true);
    let failure = fuzz(256, &Coverage::default());
    SECONDS_UNCHECKED.set(false);
    let failure = failure.expect_err("the unchecked --min-seconds is found");
    assert!(failure.contains("accepted"), "{failure}");
}
