//! What the exact Fresnel equations cost next to Schlick's approximation, in
//! both precision tiers: the speed half of "is Schlick good enough?" (the
//! accuracy half is `cargo run --release -p radiometry --example schlick_error`).
//!
//! Run: `cargo bench -p radiometry --bench fresnel`. Each benchmark evaluates
//! the law over the same 1024 angles, so times compare directly.

use criterion::{black_box, criterion_group, BenchmarkId, Criterion, Throughput};
use radiometry::fresnel::{conductor, dielectric, f0, schlick, schlick_dielectric};
use radiometry::Real;

const ANGLES: usize = 1024;
const LAWS: [&str; 5] = [
    "dielectric_exact",
    "dielectric_schlick",
    "dielectric_schlick_both_sides",
    "conductor_exact",
    "conductor_schlick",
];

/// Cosines spread over both sides of the interface.
fn cosines<T: Real>() -> Vec<T> {
    (0..ANGLES)
        .map(|k| T::lit(-1.0 + 2.0 * (k as f64 + 0.5) / ANGLES as f64))
        .collect()
}

fn bench_tier<T: Real>(c: &mut Criterion, tier: &str) {
    let cosines = cosines::<T>();
    let (eta, n, kappa) = (T::lit(1.5), T::lit(0.17), T::lit(3.1));
    let (f0_glass, f0_gold) = (f0(eta, T::zero()), f0(n, kappa));
    let mut group = c.benchmark_group(format!("fresnel_{tier}"));
    group.throughput(Throughput::Elements(ANGLES as u64));
    let mut run = |name: &str, law: &dyn Fn(T) -> T| {
        group.bench_function(BenchmarkId::from_parameter(name), |b| {
            b.iter(|| {
                cosines
                    .iter()
                    .fold(T::zero(), |acc, &c| acc + law(black_box(c)))
            })
        });
    };
    run("dielectric_exact", &|c| dielectric(c, eta));
    run("dielectric_schlick", &|c| schlick(c, f0_glass));
    run("dielectric_schlick_both_sides", &|c| {
        schlick_dielectric(c, eta)
    });
    run("conductor_exact", &|c| conductor(c, n, kappa));
    run("conductor_schlick", &|c| schlick(c, f0_gold));
    group.finish();
}

fn benches(c: &mut Criterion) {
    bench_tier::<f32>(c, "f32");
    bench_tier::<f64>(c, "f64");
}

criterion_group!(fresnel, benches);

fn main() {
    results::criterion::main(fresnel, record);
}

/// The section `fresnel-speed` of `docs/results.md`: time per evaluation.
fn record(run: &results::criterion::Run) -> Result<results::Section, results::Error> {
    let ids: Vec<String> = ["f32", "f64"]
        .iter()
        .flat_map(|tier| LAWS.map(|law| format!("fresnel_{tier}/{law}")))
        .collect();
    let estimates = run.estimates(&ids)?;
    let fma = if cfg!(target_feature = "fma") {
        "hardware"
    } else {
        "software"
    };
    let mut table = format!("Fused multiply-add: {fma}.\n\n| law | f32 | f64 |\n|---|---|---|\n");
    for (k, law) in LAWS.iter().enumerate() {
        let per = |e: &results::criterion::Estimate| e.mean_ns / ANGLES as f64;
        let (f32_, f64_) = (per(&estimates[k]), per(&estimates[k + LAWS.len()]));
        table += &format!("| {law} | {f32_:.1} ns | {f64_:.1} ns |\n");
    }
    Ok(results::Section::measured(
        "fresnel-speed",
        "cargo bench -p radiometry --bench fresnel",
        &table,
    ))
}
