//! Metal colours: the exact spectral colour against colour-science, and the
//! colour error of the three-wavelength shortcuts, from the committed
//! `validation/reference/metals.json` (regenerate with
//! `.venv/bin/python python-checks/metals.py`). Run with `--nocapture` for
//! the ΔE00 table.

mod caught;
mod tables;

use validation::metals::{self, MetalLaws, MetalsReference};
use validation::reference::committed_dir;

fn reference() -> MetalsReference {
    MetalsReference::load(&committed_dir()).expect("committed metals reference")
}

#[test]
fn spectral_metal_colours_agree_with_colour_science() {
    let check = metals::check_spectral_colours(&MetalLaws::radiometry(), &reference());
    assert_eq!(check.cases, 4 * 5, "four metals at five angles");
    tables::assert_passed_and_settled(
        "metals-vs-colour-science",
        "cargo test -p validation --test metals_vs_colour_science",
        std::slice::from_ref(&check),
    );
}

#[test]
fn shortcut_colour_errors_are_measured_for_every_metal() {
    let rows = metals::shortcut_colours(&MetalLaws::radiometry(), &reference());
    let mut table = String::from("| metal | shortcut | worst ΔE00 | at |\n|---|---|---|---|\n");
    let worst = metals::worst_delta_e(&rows);
    for (metal, method, de, angle) in &worst {
        table += &format!("| {metal} | {method} | {de:.2} | {angle}° |\n");
    }
    println!("{table}");
    // Four shortcuts per metal, and the course's RGB for gold.
    assert_eq!(worst.len(), 4 * 4 + 1);
    assert!(worst.iter().all(|w| w.2.is_finite()));
    // The spectral colour is its own reference.
    assert!(rows
        .iter()
        .filter(|r| r.method == "spectral (exact)")
        .all(|r| r.delta_e_2000 == 0.0));
    // Schlick from the spectral F0 is exact at normal incidence, to rounding:
    // Schlick(1, F0) = F0 = the exact reflectance.
    let at_normal = rows
        .iter()
        .filter(|r| r.angle_deg == 0.0 && r.method == "Schlick, spectral F0");
    for row in at_normal {
        assert!(row.delta_e_2000 < 1e-9, "{row:?}");
    }
    results::assert_settled(&results::Section::deterministic(
        "metal-shortcuts",
        "cargo test -p validation --test metals_vs_colour_science",
        &table,
    ));
}

#[test]
fn a_broken_conductor_law_is_caught_in_colour() {
    // κ ignored: a metal becomes a dielectric, grey and dull.
    fn conductor_without_absorption(cos_i: f64, n: f64, _kappa: f64) -> f64 {
        radiometry::fresnel::conductor(cos_i, n, 0.0)
    }
    let broken = MetalLaws {
        conductor: conductor_without_absorption,
        ..MetalLaws::radiometry()
    };
    let check = metals::check_spectral_colours(&broken, &reference());
    assert!(
        caught::failures_of(&check) >= 20,
        "every metal at every angle: {:#?}",
        check.failures
    );
}

/// A scene's metal is held to its spectrum by the same steps as the
/// course's gold in the shortcut table: the course's gold `n, κ` through
/// [`metals::three_channel_delta_e`] gives that table's ΔE at every angle,
/// to the last bit (the same code, not a copy of it).
#[test]
fn a_scenes_three_channel_metal_is_measured_as_the_course_gold() {
    let laws = MetalLaws::radiometry();
    let reference = reference();
    let gold = reference.metals.iter().find(|m| m.name == "gold").unwrap();
    let measured = metals::three_channel_delta_e(
        &laws,
        gold,
        radiometry::course::GOLD_000_N,
        radiometry::course::GOLD_000_KAPPA,
    )
    .unwrap();
    let table: Vec<(f64, f64)> = metals::shortcut_colours(&laws, &reference)
        .into_iter()
        .filter(|r| r.metal == "gold" && r.method == "course RGB n, κ (seed 000)")
        .map(|r| (r.angle_deg, r.delta_e_2000))
        .collect();
    assert_eq!(measured.len(), 5, "five angles");
    assert_eq!(measured, table);
}
