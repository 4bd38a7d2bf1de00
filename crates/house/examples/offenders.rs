//! Prints every offender against the house rules in this workspace, then a
//! count per rule: `cargo run -p house --example offenders [ROOT]`; with
//! `--identities`, each offence's stable identity alone, one a line, as
//! `crates/house/known_offenders.txt` lists the work still owed.

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::process::ExitCode;

fn main() -> ExitCode {
    let identities = std::env::args().any(|a| a == "--identities");
    let root = std::env::args_os()
        .skip(1)
        .find(|a| a != "--identities")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../.."));
    let found = match house::offenders(&root) {
        Ok(found) => found,
        Err(error) => {
            eprintln!("error: {error}");
            return ExitCode::from(2);
        }
    };
    if identities {
        let mut lines: Vec<String> = found.iter().map(house::Offender::identity).collect();
        lines.sort();
        lines.dedup();
        for line in lines {
            println!("{line}");
        }
        return ExitCode::SUCCESS;
    }
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
