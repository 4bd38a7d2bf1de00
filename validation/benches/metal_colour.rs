//! The cost of a metal's colour from its spectrum (85 wavelengths, the CIE
//! integral) against three per-channel Fresnel evaluations (the course's
//! gold), both ending in CIELAB. Read the ratio; the absolute times belong to
//! the machine.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use validation::metals::{MetalLaws, MetalsReference, COURSE_GOLD_KAPPA, COURSE_GOLD_N};
use validation::reference::committed_dir;
use validation::speed::{rgb_lab, spectral_lab};

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
    c.bench_function("gold colour, spectral (85 wavelengths)", |b| {
        b.iter(|| spectral_lab(&laws, &index, black_box(cos_60deg)))
    });
    c.bench_function("gold colour, course RGB (3 wavelengths)", |b| {
        b.iter(|| {
            rgb_lab(
                &laws,
                COURSE_GOLD_N,
                COURSE_GOLD_KAPPA,
                black_box(cos_60deg),
            )
        })
    });
}

criterion_group!(benches, metal_colour);
criterion_main!(benches);
