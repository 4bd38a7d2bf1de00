//! The radiometry crate's laws against Mitsuba 3 and the exact values, from
//! the committed `validation/reference/mitsuba_laws.json` (regenerate with
//! `.venv/bin/python python-checks/mitsuba_laws.py`). The tolerances and the
//! rule that tells a failure of ours from a finding about Mitsuba are stated
//! in `validation::laws`. Run with `--nocapture` for the table.

mod tables;

use validation::laws::{self, Laws, MitsubaLaws};
use validation::reference::committed_dir;

fn reference() -> MitsubaLaws {
    MitsubaLaws::load(&committed_dir()).expect("committed Mitsuba reference")
}

#[test]
fn radiometry_laws_agree_with_mitsuba_and_the_exact_values() {
    let checks = laws::check_all(&Laws::radiometry(), &reference());
    for check in &checks {
        println!("{} ({} cases)", check.id, check.cases);
        for m in &check.metrics {
            println!("  {:<50} {:>10.3e}  at {}", m.name, m.worst, m.at);
        }
        for f in &check.findings {
            println!("  finding: {f}");
        }
    }
    let failures: Vec<_> = checks.iter().flat_map(|c| &c.failures).collect();
    assert!(failures.is_empty(), "{failures:#?}");
    assert!(checks.iter().all(|c| c.passed()));
    results::assert_settled(&results::Section::deterministic(
        "laws-vs-mitsuba",
        "cargo test -p validation --test laws_vs_mitsuba",
        &tables::metrics(&checks),
    ));
}
