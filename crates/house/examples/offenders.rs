//! Prints every offender against the house rules in this workspace, then a
//! count per rule: `cargo run -p house --example offenders [ROOT]`.

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::process::ExitCode;

fn main() -> ExitCode {
    let root = std::env::args_os()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../.."));
    let found = match house::offenders(&root) {
        Ok(found) => found,
        Err(error) => {
            eprintln!("error: {error}");
            return ExitCode::from(2);
        }
    };
    let mut counts: BTreeMap<house::Rule, usize> = BTreeMap::new();
    for offender in &found {
        println!("{}: {offender}", offender.rule);
        *counts.entry(offender.rule).or_default() += 1;
    }
    println!();
    for rule in house::Rule::ALL {
        println!("{:>4}  {rule}", counts.get(&rule).copied().unwrap_or(0));
    }
    println!("{:>4}  in all", found.len());
    if found.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}
