//! What the exact Fresnel equations cost next to Schlick's approximation and
//! next to the textbook form of the exact law, in both precision tiers: the
//! speed half of "is Schlick good enough?" (the accuracy half is
//! `cargo run --release -p radiometry --example schlick_error`).
//!
//! Run: `cargo bench -p radiometry --bench fresnel`. Each law is timed as a
//! caller uses it: called through a generic closure, inlined, over a slice
//! of the same 4096 cosines, the result written to a slice (the compiler
//! may vectorise the loop; nothing is called through a pointer). The
//! material's constants are fixed for the slice, as they are for a surface.
//! The slice forms of the crate ([`dielectric_slice`], [`conductor_slice`])
//! are timed too: they run on the widest instructions the CPU has
//! ([`Lanes::widest`]), where the closure runs on the build's target.
//!
//! The two textbook laws are the baselines, not laws of the suite: the
//! exact equations as shaders write them, one square root and two
//! divisions for the dielectric (light from the outside only, no care for
//! cancellation), and the `a² + b²` form of the conductor (two square roots
//! and two divisions).

use criterion::{black_box, criterion_group, BenchmarkId, Criterion, Throughput};
use radiometry::fresnel::{
    conductor, conductor_slice, dielectric, dielectric_slice, f0, schlick, schlick_dielectric,
    Lanes,
};
use radiometry::Real;

/// The laws in the order of the table, each with the cosines it is timed
/// over: both sides of a dielectric, the outside of a conductor.
const LAWS: [&str; 9] = [
    "dielectric_schlick",
    "dielectric_schlick_both_sides",
    "dielectric_textbook",
    "dielectric_exact",
    "dielectric_exact_slice",
    "conductor_schlick",
    "conductor_textbook",
    "conductor_exact",
    "conductor_exact_slice",
];

#[path = "shared/textbook.rs"]
mod textbook;
use textbook::{conductor_textbook, dielectric_textbook};
#[path = "shared/workload.rs"]
mod workload;
use workload::{over, Workload, COSINES};

fn bench_tier<T: Real>(c: &mut Criterion, tier: &str) {
    let Workload {
        both_sides,
        outside,
        eta,
        inv_eta2,
        n,
        kappa,
    } = Workload::<T>::new();
    let mut out = vec![T::zero(); COSINES];
    let (f0_glass, f0_gold) = (f0(eta, T::zero()), f0(n, kappa));

    let mut group = c.benchmark_group(format!("fresnel_{tier}"));
    group.throughput(Throughput::Elements(COSINES as u64));
    let mut run = |name: &str, time: &mut dyn FnMut(&mut [T])| {
        group.bench_function(BenchmarkId::from_parameter(name), |b| {
            b.iter(|| {
                time(&mut out);
                black_box(&mut out);
            })
        });
    };
    let (both, outer) = (&both_sides[..], &outside[..]);
    run(LAWS[0], &mut |out| {
        over(black_box(both), out, |c| schlick(c, f0_glass))
    });
    run(LAWS[1], &mut |out| {
        over(black_box(both), out, |c| schlick_dielectric(c, eta))
    });
    run(LAWS[2], &mut |out| {
        over(black_box(both), out, |c| {
            dielectric_textbook(c, eta, inv_eta2)
        })
    });
    run(LAWS[3], &mut |out| {
        over(black_box(both), out, |c| dielectric(c, eta))
    });
    run(LAWS[4], &mut |out| {
        dielectric_slice(black_box(both), eta, out)
    });
    run(LAWS[5], &mut |out| {
        over(black_box(outer), out, |c| schlick(c, f0_gold))
    });
    run(LAWS[6], &mut |out| {
        over(black_box(outer), out, |c| conductor_textbook(c, n, kappa))
    });
    run(LAWS[7], &mut |out| {
        over(black_box(outer), out, |c| conductor(c, n, kappa))
    });
    run(LAWS[8], &mut |out| {
        conductor_slice(black_box(outer), n, kappa, out)
    });
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

/// The section `fresnel-speed` of `docs/results.md`: time per evaluation,
/// and each law's time over the textbook form's and Schlick's.
fn record(run: &results::criterion::Run) -> Result<results::Section, results::Error> {
    let tiers = ["f32", "f64"];
    let ids: Vec<String> = tiers
        .iter()
        .flat_map(|tier| LAWS.map(|law| format!("fresnel_{tier}/{law}")))
        .collect();
    let estimates = run.estimates(&ids)?;
    let ns = |tier: usize, law: &str| {
        let k = LAWS.iter().position(|l| *l == law).expect("a timed law");
        estimates[tier * LAWS.len() + k].mean_ns / COSINES as f64
    };
    let fma = if cfg!(target_feature = "fma") {
        "in the build"
    } else {
        "not in the build"
    };
    let lanes = Lanes::widest();
    let mut table = format!(
        "Fused multiply-add: {fma}. The `_slice` forms run on `{lanes:?}`, the \
         others on the build's target. Time per evaluation over {COSINES} cosines; \
         `÷ textbook` and `÷ Schlick` are the law's time over the textbook \
         form's and Schlick's, in the same tier.\n\n\
         | law | f32 | ÷ textbook | ÷ Schlick | f64 | ÷ textbook | ÷ Schlick |\n\
         |---|---|---|---|---|---|---|\n"
    );
    for law in LAWS {
        let kind = if law.starts_with("dielectric") {
            "dielectric"
        } else {
            "conductor"
        };
        table += &format!("| {law} |");
        for tier in 0..tiers.len() {
            let t = ns(tier, law);
            let textbook = t / ns(tier, &format!("{kind}_textbook"));
            let schlick = t / ns(tier, &format!("{kind}_schlick"));
            table += &format!(" {t:.2} ns | {textbook:.2} | {schlick:.1} |");
        }
        table += "\n";
    }
    Ok(results::Section::measured(
        "fresnel-speed",
        "cargo bench -p radiometry --bench fresnel",
        &table,
    ))
}
