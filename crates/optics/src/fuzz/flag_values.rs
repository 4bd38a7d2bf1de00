//! Flag values: every law's command line with numbers at the edges of
//! `f64`, typed as people type them, through the parser and the law.

use super::{check_error_field, check_record, number_text, run_and_report, runner, Coverage};
use crate::law_table::schema::{self, Field, Kind};
use crate::law_table::{command_words, LAWS};
use clap::{CommandFactory, FromArgMatches};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use record::Lang;

fn flag(field: &str) -> String {
    format!("--{}", field.replace('_', "-"))
}

/// Text that is not a value of the flag it is given to.
const NOT_VALUES: [&str; 10] = [
    "", "-", "--", "abc", "1,2", "1e", "-1e", "0x10", "1,,2,3", "--eta",
];

/// A command line: the law's flags with values typed as numbers, vectors
/// and models; `clean` when every value is one the flag takes.
#[derive(Clone, Debug)]
struct Line {
    law: &'static str,
    args: Vec<String>,
    clean: bool,
}

fn value(field: &Field) -> BoxedStrategy<String> {
    match &field.kind {
        Kind::Choice(names) => prop::sample::select(names.clone()).boxed(),
        Kind::Vector => prop::array::uniform3(number_text())
            .prop_map(|v| v.join(","))
            .boxed(),
        Kind::Number => number_text().boxed(),
        Kind::List => prop::collection::vec(number_text(), 1..5)
            .prop_map(|v| v.join(","))
            .boxed(),
    }
}

/// A command line: one in eight a refraction near normal incidence, the
/// rest any law's flags.
fn command_line() -> impl Strategy<Value = Line> {
    prop_oneof![7 => any_law(), 1 => near_normal_refraction()]
}

/// `optics refract` within 1e-12 to 1 rad of the normal, into a medium up
/// to 1e50 times rarer or denser: where the tangential part of the
/// direction grows by `n_i / n_t` and its length and `cos θt` must come
/// from one sine to stay unit, which a uniform draw of `wi` almost never
/// reaches.
fn near_normal_refraction() -> impl Strategy<Value = Line> {
    let component = || prop::array::uniform3(-1.0..1.0f64);
    (
        component(),
        component(),
        -12.0..0.0f64,
        -50.0..50.0f64,
        any::<bool>(),
    )
        .prop_map(|(normal, tangent, log_offset, log_eta, json)| {
            let offset = 10f64.powf(log_offset);
            let wi: Vec<String> = (0..3)
                .map(|k| format!("{:e}", normal[k] + offset * tangent[k]))
                .collect();
            let normal: Vec<String> = normal.iter().map(|x| format!("{x:e}")).collect();
            let mut args = vec!["optics".to_owned()];
            args.extend(json.then(|| "--json".to_owned()));
            args.extend(
                [
                    "refract",
                    "--wi",
                    &wi.join(","),
                    "--normal",
                    &normal.join(","),
                ]
                .map(String::from),
            );
            args.extend(["--eta".to_owned(), format!("{:e}", 10f64.powf(log_eta))]);
            Line {
                law: "refract",
                args,
                clean: true,
            }
        })
}

fn any_law() -> impl Strategy<Value = Line> {
    (0..LAWS.len()).prop_flat_map(|i| {
        let law = LAWS[i];
        let values: Vec<_> = schema::fields(law)
            .into_iter()
            .map(|field| (value(&field), Just(field), any::<bool>()))
            .collect();
        let spoil = (
            any::<prop::sample::Index>(),
            prop::sample::select(NOT_VALUES.to_vec()),
        );
        (values, prop::option::weighted(0.2, spoil), any::<bool>()).prop_map(
            move |(values, spoil, json)| {
                let mut args = vec!["optics".to_owned()];
                args.extend(json.then(|| "--json".to_owned()));
                args.extend(command_words(law));
                let mut given: Vec<String> = Vec::new();
                for (text, field, optional_given) in values {
                    // Of a group one of which is required (Fresnel's
                    // incidence), exactly one: the last if none before.
                    let wanted = match &field.one_of {
                        _ if field.required => true,
                        Some(members) => {
                            !given.iter().any(|g| members.contains(g))
                                && (optional_given || members.last() == Some(&field.name))
                        }
                        None => optional_given,
                    };
                    if wanted {
                        // A field given drops one it excludes given
                        // before it (a metal named drops `--kappa`).
                        for excluded in &field.excludes {
                            if let Some(at) = args.iter().position(|a| *a == flag(excluded)) {
                                args.drain(at..at + 2);
                                given.retain(|g| g != excluded);
                            }
                        }
                        args.extend([flag(&field.name), text]);
                        given.push(field.name);
                    }
                }
                let clean = spoil.is_none();
                if let Some((at, text)) = spoil {
                    let i = 2 + json as usize + at.index(args.len() - 2 - json as usize);
                    args[i] = text.to_owned();
                }
                Line { law, args, clean }
            },
        )
    })
}

/// The parser as built, or with the fix for negative exponents reverted:
/// numbers no longer take values that start with `-`, as before it.
fn parse(args: &[String], reverted: bool) -> Result<crate::Cli, clap::Error> {
    let mut command = crate::Cli::command();
    if reverted {
        for &law in LAWS {
            let numbers_refuse_hyphens = |mut c: clap::Command| {
                for field in schema::fields(law) {
                    if field.kind == Kind::Number {
                        c = c.mut_arg(&field.name, |a| a.allow_hyphen_values(false));
                    }
                }
                c
            };
            command = match command_words(law).as_slice() {
                [name] => command.mut_subcommand(name, numbers_refuse_hyphens),
                [quiz, name] => {
                    command.mut_subcommand(quiz, |q| q.mut_subcommand(name, numbers_refuse_hyphens))
                }
                words => unreachable!("{words:?}"),
            };
        }
    }
    crate::Cli::from_arg_matches(&command.try_get_matches_from(args)?)
}

fn check_line(line: &Line, reverted: bool, coverage: &Coverage) -> Result<(), TestCaseError> {
    // The parser may name any argument given, a value taken for a flag too.
    let given = &line.args;
    let outcome = parse(&line.args, reverted)
        .map_err(|usage| crate::Error::from(crate::ErrorKind::Usage(usage)))
        .and_then(|cli| crate::law_record(&cli.command, Lang::En).expect("a law's command"));
    match outcome {
        Ok(record) => {
            coverage.answer();
            check_record(&serde_json::to_value(&record).expect("a record is JSON"))
        }
        Err(error) => {
            let json = error.to_json(Lang::En);
            coverage.error(&json);
            let usage = matches!(error.kind(), crate::ErrorKind::Usage(_));
            prop_assert!(!(usage && line.clean), "{:?} refused: {json}", line.args);
            check_error_field(&json, given, line.law, flag)
        }
    }
}

fn fuzz(cases: u32, reverted: bool, coverage: &Coverage) -> Result<(), String> {
    runner(cases)
        .run(&command_line(), |line| {
            check_line(&line, reverted, coverage)
        })
        .map_err(|e| e.to_string())
}

#[test]
fn flag_values_keep_their_promises() {
    run_and_report("flag values", |cases, coverage| {
        fuzz(cases, false, coverage)
    });
}

#[test]
fn flag_values_find_a_refraction_off_unit_length() {
    use crate::laws::refract::FROM_THE_COSINE_ALONE;
    FROM_THE_COSINE_ALONE.set(true);
    let outcome = fuzz(256, false, &Coverage::default());
    FROM_THE_COSINE_ALONE.set(false);
    let failure = outcome.expect_err("the reverted fix is found");
    assert!(failure.contains("|answer| = "), "{failure}");
}

#[test]
fn flag_values_find_numbers_that_refuse_a_leading_hyphen() {
    let failure = fuzz(256, true, &Coverage::default()).expect_err("the reverted fix is found");
    assert!(failure.contains("refused"), "{failure}");
}
