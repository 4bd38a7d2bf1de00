// Each test binary that includes this module uses only part of it.
#![allow(dead_code)]

//! What a test asserts of a check run on a deliberately broken law: that the
//! check failed, and where its failures lie.

use validation::Check;

/// Asserts that `check` caught the broken law, and returns how many
/// failures it recorded.
#[track_caller]
pub fn failures_of(check: &Check) -> usize {
    assert!(!check.passed(), "{} passed with a broken law", check.id);
    check.failures.len()
}

/// Asserts that `check` caught the broken law and that every failure is
/// `where_` (a predicate on the message): the break shows nowhere else.
#[track_caller]
pub fn caught_only(check: &Check, where_: impl Fn(&str) -> bool) {
    failures_of(check);
    assert!(
        check.failures.iter().all(|f| where_(f)),
        "{}: a failure elsewhere: {:#?}",
        check.id,
        check.failures
    );
}

/// Asserts that `check` caught the broken law with at least one failure
/// that is `where_`.
#[track_caller]
pub fn caught_at(check: &Check, where_: impl Fn(&str) -> bool) {
    failures_of(check);
    assert!(
        check.failures.iter().any(|f| where_(f)),
        "{}: no such failure: {:#?}",
        check.id,
        check.failures
    );
}
