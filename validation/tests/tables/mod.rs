// Each test binary that includes this module uses only part of it.
#![allow(dead_code)]

//! The checks' measurements as Markdown tables, for their sections of
//! `docs/results.md`.

use validation::Check;

/// A number as the tables print it: whole numbers (counts) as they are,
/// others to three significant digits, in scientific notation outside
/// [0.01, 10⁴).
pub fn number(value: f64) -> String {
    if value.fract() == 0.0 && value.abs() < 1e6 {
        format!("{value}")
    } else if (0.01..1e4).contains(&value.abs()) {
        let decimals = (2 - value.abs().log10().floor() as i32).max(0) as usize;
        format!("{value:.decimals$}")
    } else {
        format!("{value:.2e}")
    }
}

/// A table cell: Markdown's column separator escaped.
pub fn cell(text: &str) -> String {
    text.replace('|', "\\|")
}

/// Every metric of `checks`, one row each, under a row per check with its
/// cases and findings.
pub fn metrics(checks: &[Check]) -> String {
    let mut table = String::from("| check | quantity | worst | at |\n|---|---|---|---|\n");
    for check in checks {
        table += &format!(
            "| `{}` | {} cases, {} findings | | |\n",
            check.id,
            check.cases,
            check.findings.len()
        );
        for m in &check.metrics {
            table += &format!(
                "| | {} | {} | {} |\n",
                cell(&m.name),
                number(m.worst),
                cell(&m.at)
            );
        }
    }
    table
}

/// Prints each check's metrics (with `--nocapture`) and its first failures.
pub fn print(checks: &[Check]) {
    println!("{}", metrics(checks));
    for check in checks {
        for f in check.failures.iter().take(3) {
            println!("{} FAIL {f}", check.id);
        }
    }
}

/// Prints `checks`, asserts that every one passed, and settles their
/// [`metrics`] as the deterministic section `name` of `docs/results.md`,
/// produced by `command`.
pub fn assert_passed_and_settled(name: &str, command: &str, checks: &[Check]) {
    print(checks);
    let failures: Vec<_> = checks.iter().flat_map(|c| &c.failures).collect();
    assert!(failures.is_empty(), "{failures:#?}");
    assert!(checks.iter().all(Check::passed), "every check has cases");
    results::assert_settled(&results::Section::deterministic(
        name,
        command,
        &metrics(checks),
    ));
}
