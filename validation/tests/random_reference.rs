//! The laws of the radiometry crate at 10⁴ seeded random inputs per law and
//! tier against mpmath's 50 digits (`python-checks/fresnel_random.py`,
//! regenerate with `python3 python-checks/fresnel_random.py`), drawn
//! uniformly over the reals and over the floating-point numbers, and at
//! 2·10⁴ more f64 dielectric inputs drawn near the worst of its roundings.
//!
//! The comparison is the harness's check (`validation::mpmath::random`,
//! bounds and reasons stated there); this test runs it on the radiometry
//! crate's laws and writes its two tables into `docs/results.md`: the error,
//! in Herbie's bits and in floating-point numbers from the correctly rounded
//! value, and where the cases fall.

mod tables;

use tables::{cell, number};
use validation::laws::Laws;
use validation::mpmath::random::{self, CaseSet, FresnelRandom, Law, Sampling, Tier};
use validation::mpmath::Laws64;
use validation::reference::committed_dir;
use validation::Check;

const COMMAND: &str = "cargo test -p validation --test random_reference";

fn reference() -> (FresnelRandom, Vec<CaseSet>) {
    FresnelRandom::load(&committed_dir()).expect("the committed fresnel_random.json")
}

fn worst(check: &Check, name: &str) -> f64 {
    check
        .worst(name)
        .unwrap_or_else(|| panic!("{}: no metric {name}", check.id))
        .worst
}

/// The error table: per law, quantity and tier, each sampling's average and
/// worst bits and worst count of numbers from the correctly rounded value.
fn error_table(checks: &[Check]) -> String {
    let mut table = String::from(
        "| law | quantity | tier | reals: average bits | worst bits | worst ulps \
         | floats: average bits | worst bits | worst ulps |\n|---|---|---|---|---|---|---|---|---|\n",
    );
    for (law, check) in random::LAWS.iter().zip(checks) {
        for (_, quantity) in law.values() {
            for tier in [Tier::F64, Tier::F32] {
                let mut row = format!("| {} | {quantity} | {} |", law.name(), tier.name());
                for sampling in [Sampling::Reals, Sampling::Floats] {
                    let prefix = format!("{} {} {quantity}", tier.name(), sampling.name());
                    row += &format!(
                        " {:.3} | {:.2} | {} |",
                        worst(check, &format!("{prefix} (bits, average)")),
                        worst(check, &format!("{prefix} (bits, worst)")),
                        number(worst(check, &format!("{prefix} (ulps)")))
                    );
                }
                table += &row;
                table += "\n";
            }
        }
    }
    table
}

/// The region table: per law and region, the cases of each tier and
/// sampling that fall in it (of 5000 each).
fn region_table(checks: &[Check], sets: &[CaseSet]) -> String {
    let mut table = String::from(
        "| law | region | f64 reals | f64 floats | f32 reals | f32 floats |\n|---|---|---|---|---|---|\n",
    );
    for (law, check) in random::LAWS.iter().zip(checks) {
        let first = sets.iter().find(|s| s.law == *law).expect("a set per law");
        for (region, _) in random::regions::count(first) {
            let mut row = format!("| {} | {} |", law.name(), cell(region));
            for tier in ["f64", "f32"] {
                for sampling in ["reals", "floats"] {
                    let name = format!("{tier} {sampling}: {region} (cases)");
                    row += &format!(" {} |", worst(check, &name));
                }
            }
            table += &row;
            table += "\n";
        }
    }
    table
}

#[test]
fn the_laws_at_random_inputs_are_within_their_ulps_of_50_digits_and_1_5_bits_on_average() {
    let (random, sets) = reference();
    let checks = random::check_random(&Laws::radiometry(), &Laws64::radiometry(), &random, &sets);
    let errors = error_table(&checks);
    let regions = region_table(&checks, &sets);
    println!("{errors}\n{regions}");
    for (law, check) in random::LAWS.iter().zip(&checks) {
        let near: usize = sets
            .iter()
            .filter(|s| s.law == *law && s.sampling == Sampling::Near)
            .map(|s| s.count)
            .sum();
        assert_eq!(
            check.cases,
            20_000 + near,
            "{}: 5000 per tier and sampling, and its targeted cases",
            law.name()
        );
        assert!(check.passed(), "{}: {:#?}", check.id, check.failures);
    }
    results::assert_settled(&results::Section::deterministic(
        "random-50-digits",
        COMMAND,
        &errors,
    ));
    results::assert_settled(&results::Section::deterministic(
        "random-50-digits-regions",
        COMMAND,
        &regions,
    ));
}

/// The two samplings reach different places, as they are meant to: uniform
/// over the floats puts most cosines below 1e-3, uniform over the reals
/// almost none; both reach total internal reflection.
#[test]
fn the_floats_sampling_stresses_tiny_cosines_and_the_reals_sampling_does_not() {
    let (_, sets) = reference();
    for set in sets.iter().filter(|s| s.law == Law::Dielectric) {
        let counts = random::regions::count(set);
        let tiny = counts[0].1;
        match set.sampling {
            Sampling::Floats => assert!(tiny > set.count * 9 / 10, "{tiny} of {}", set.count),
            Sampling::Reals => assert!(tiny < set.count / 100, "{tiny} of {}", set.count),
            Sampling::Near => continue,
        }
        assert!(counts[2].1 > 0, "no total internal reflection");
    }
}

/// A reference that lacks a set (here the f32 floats of Schlick's) fails
/// that law's check rather than passing on fewer cases.
#[test]
fn a_missing_set_fails_its_law() {
    let (random, mut sets) = reference();
    sets.retain(|s| {
        !(s.law == Law::Schlick && s.tier == Tier::F32 && s.sampling == Sampling::Floats)
    });
    let checks = random::check_random(&Laws::radiometry(), &Laws64::radiometry(), &random, &sets);
    for check in &checks {
        if check.id == "laws.mpmath.random.schlick" {
            assert_eq!(check.failures, ["f32 floats: no sets, expected one"]);
        } else {
            assert!(check.passed(), "{}: {:#?}", check.id, check.failures);
        }
    }
}

/// The textbook form (pbrt's `FrDielectric` shape: `cos θt` from
/// `1 − sin²θt`, `T = 1 − R`) at the same random cases, in both tiers: what
/// the reformulation buys, in Herbie's bits.
fn textbook<T: validation::laws::Tier>(
    cos_i: T,
    eta: T,
) -> radiometry::fresnel::DielectricFresnel<T> {
    let mut f = radiometry::fresnel::dielectric_polarized(cos_i, eta);
    let one = T::one();
    let (c, eta) = if cos_i < T::zero() {
        (-cos_i, one / eta)
    } else {
        (cos_i, eta)
    };
    let sin2_t = (one - c * c) / (eta * eta);
    let (r_s, r_p) = if sin2_t >= one {
        (one, one)
    } else {
        let cos_t = (one - sin2_t).sqrt();
        let r_s = (c - eta * cos_t) / (c + eta * cos_t);
        let r_p = (eta * c - cos_t) / (eta * c + cos_t);
        (r_s * r_s, r_p * r_p)
    };
    (f.r_s, f.r_p, f.t_s, f.t_p) = (r_s, r_p, one - r_s, one - r_p);
    f
}

#[test]
fn the_textbook_dielectric_loses_bits_where_the_reformulation_does_not() {
    let (random, sets) = reference();
    let dielectric = |laws: &Laws, laws64: &Laws64| {
        random::check_random(laws, laws64, &random, &sets)
            .into_iter()
            .find(|c| c.id == "laws.mpmath.random.fresnel_dielectric")
            .expect("the dielectric check")
    };
    let ours = dielectric(&Laws::radiometry(), &Laws64::radiometry());
    let foil = dielectric(
        &Laws {
            dielectric: textbook,
            ..Laws::radiometry()
        },
        &Laws64 {
            dielectric: textbook,
            ..Laws64::radiometry()
        },
    );
    let mut table = String::from(
        "| quantity | tier | sampling | ours: average bits | worst bits | textbook: average bits | worst bits |\n\
         |---|---|---|---|---|---|---|\n",
    );
    for quantity in ["R", "T"] {
        for tier in ["f64", "f32"] {
            for sampling in ["reals", "floats"] {
                let at = |check: &Check, what: &str| {
                    worst(
                        check,
                        &format!("{tier} {sampling} {quantity} (bits, {what})"),
                    )
                };
                table += &format!(
                    "| {quantity} | {tier} | {sampling} | {:.3} | {:.2} | {:.3} | {:.2} |\n",
                    at(&ours, "average"),
                    at(&ours, "worst"),
                    at(&foil, "average"),
                    at(&foil, "worst")
                );
            }
        }
    }
    println!("{table}");
    assert!(ours.passed(), "{:#?}", ours.failures);
    assert!(
        !foil.passed(),
        "the textbook form was expected to lose digits"
    );
    assert!(
        worst(&foil, "f32 floats T (bits, average)") > 10.0,
        "the textbook T cancels at the floats sampling's tiny cosines"
    );
    results::assert_settled(&results::Section::deterministic(
        "random-50-digits-textbook",
        COMMAND,
        &table,
    ));
}
