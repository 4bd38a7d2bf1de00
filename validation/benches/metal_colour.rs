//! The cost of a metal's colour from its spectrum (85 wavelengths, the CIE
//! integral) against three per-channel Fresnel evaluations (the course's
//! gold), both ending in CIELAB. Read the ratio; the absolute times belong to
//! the machine.

use criterion::{black_box, criterion_group, Criterion};
use radiometry::course::{GOLD_000_KAPPA, GOLD_000_N};
use validation::metals::{MetalLaws, MetalsReference};
use validation::reference::committed_dir;
use validation::speed::{rgb_lab, spectral_lab};

const SPECTRAL: &str = "gold colour, spectral (85 wavelengths)";
const RGB: &str = "gold colour, course RGB (3 wavelengths)";

fn metal_colour(c: &mut Criterion) {
    let reference = MetalsReference::load(&committed_dir()).expect("committed metals reference");
    let gold = reference
        .metals
        .iter()
        .find(|m| m.name == "gold")
        .expect("gold in the reference");
    let index = gold.index_on_grid().expect("gold covers 360-780 nm");
    let laws = MetalLaws::radiometry();
    let cos_60deg = 0.5;
    c.bench_function(SPECTRAL, |b| {
        b.iter(|| spectral_lab(&laws, &index, black_box(cos_60deg)))
    });
    c.bench_function(RGB, |b| {
        b.iter(|| rgb_lab(&laws, GOLD_000_N, GOLD_000_KAPPA, black_box(cos_60deg)))
    });
}

criterion_group!(benches, metal_colour);

fn main() {
    results::criterion::main(benches, record);
}

/// The section `metal-colour-speed` of `docs/results.md`.
fn record(run: &results::criterion::Run) -> Result<results::Section, results::Error> {
    let e = run.estimates(&[SPECTRAL.into(), RGB.into()])?;
    let (spectral, rgb) = (e[0].mean_ns, e[1].mean_ns);
    let table = format!(
        "| gold's colour at 60°, to CIELAB | time per colour |\n|---|---|\n\
         | {SPECTRAL} | {spectral:.0} ns |\n| {RGB} | {rgb:.0} ns |\n\
         | ratio | {:.1}× |\n",
        spectral / rgb
    );
    Ok(results::Section::measured(
        "metal-colour-speed",
        "cargo bench -p validation --bench metal_colour",
        &table,
    ))
}
