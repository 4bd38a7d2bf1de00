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
    for f in checks.iter().flat_map(|c| &c.findings) {
        println!("finding: {}", f.en);
    }
    tables::assert_passed_and_settled(
        "laws-vs-mitsuba",
        "cargo test -p validation --test laws_vs_mitsuba",
        &checks,
    );
}
