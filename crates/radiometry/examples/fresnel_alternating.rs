//! The exact laws' slice forms against the textbook form of the same law,
//! timed alternately in one process: textbook, exact, floor, textbook,
//! exact, floor, … over the same 4096 cosines, so that a loaded machine's
//! drift falls on all alike. Prints, per tier and law, the best and the
//! first-quartile time per evaluation of each and their ratios.
//!
//! The floor is the divider's share of the exact law: per cosine, the
//! square roots and the division the law takes in its wide precision
//! (`f64` for both tiers; the dielectric one of each, the conductor two
//! roots and one division), independent of each other and of nothing
//! else, on the instructions the slice laws run on. No law that takes its
//! roots and division in `f64` can run faster than that loop on this CPU.
//!
//! Run: `cargo run --release -p radiometry --example fresnel_alternating [ROUNDS]`
//! (40 rounds of 100 passes each by default). The criterion bench
//! (`cargo bench -p radiometry --bench fresnel`) times each law in turn
//! and writes the table of docs/results.md; this one is for comparing
//! builds under load, where only ratios taken side by side mean anything.

use std::hint::black_box;
use std::time::Instant;

use num_traits::Float;
use radiometry::fresnel::{conductor_slice, dielectric_slice, Lanes};
use radiometry::Real;

/// One pass of a law over the cosines, into the given results.
type Pass<'a, T> = Box<dyn FnMut(&mut [T]) + 'a>;
const PASSES: usize = 100;

#[path = "../benches/shared/textbook.rs"]
mod textbook;
use textbook::{conductor_textbook, dielectric_textbook};
#[path = "../benches/shared/workload.rs"]
mod workload;
use workload::{over, Workload, COSINES};

/// Nanoseconds per evaluation of `PASSES` passes of `law`.
fn time<T: Real>(out: &mut [T], law: &mut dyn FnMut(&mut [T])) -> f64 {
    let start = Instant::now();
    for _ in 0..PASSES {
        law(out);
        black_box(&mut *out);
    }
    start.elapsed().as_secs_f64() * 1e9 / (PASSES * COSINES) as f64
}

/// The square roots and division of the exact law, per cosine: `ROOTS`
/// roots and one division in the wide precision, each of a value of its
/// own so that none waits for another, rounded back to the tier as the
/// law's result is.
#[inline(always)]
fn divider_share<T: Real, const ROOTS: usize>(cosines: &[T], out: &mut [T]) {
    for (r, &c) in out.iter_mut().zip(cosines) {
        // In [1, 2]: no zero, no special value on the divider's way.
        let x = Float::abs(c.widen()) + <T::Wide as Real>::lit(1.0);
        let mut sum = Float::recip(x);
        for k in 0..ROOTS {
            sum = sum + Float::sqrt(x + <T::Wide as Real>::lit(k as f64));
        }
        *r = T::narrow(sum);
    }
}

/// [`divider_share`] on the widest instructions this CPU has, the slice
/// laws' ([`Lanes::widest`]).
fn floor<T: Real, const ROOTS: usize>(cosines: &[T], out: &mut [T]) {
    #[cfg(target_arch = "x86_64")]
    #[allow(unsafe_code)]
    {
        #[target_feature(enable = "avx512f,avx512dq,avx512vl,fma")]
        fn avx512<T: Real, const ROOTS: usize>(cosines: &[T], out: &mut [T]) {
            divider_share::<T, ROOTS>(cosines, out)
        }
        #[target_feature(enable = "avx2,fma")]
        fn avx2<T: Real, const ROOTS: usize>(cosines: &[T], out: &mut [T]) {
            divider_share::<T, ROOTS>(cosines, out)
        }
        match Lanes::widest() {
            // SAFETY: `Lanes::widest` answers only widths this CPU runs.
            Lanes::Avx512 => return unsafe { avx512::<T, ROOTS>(cosines, out) },
            // SAFETY: as above.
            Lanes::Avx2 => return unsafe { avx2::<T, ROOTS>(cosines, out) },
            Lanes::Baseline => {}
        }
    }
    divider_share::<T, ROOTS>(cosines, out)
}

/// The best and the first quartile of `times`.
fn best_and_quartile(mut times: Vec<f64>) -> (f64, f64) {
    times.sort_by(f64::total_cmp);
    (times[0], times[times.len() / 4])
}

fn tier<T: Real>(name: &str, rounds: usize) {
    let Workload {
        both_sides: both,
        outside: outer,
        eta,
        inv_eta2,
        n,
        kappa,
    } = Workload::<T>::new();
    let mut out = vec![T::zero(); COSINES];
    let mut pairs: [(&str, [Pass<T>; 3]); 2] = [
        (
            "dielectric",
            [
                Box::new(|o: &mut [T]| {
                    over(black_box(&both[..]), o, |c| {
                        dielectric_textbook(c, eta, inv_eta2)
                    })
                }),
                Box::new(|o: &mut [T]| dielectric_slice(black_box(&both[..]), eta, o)),
                Box::new(|o: &mut [T]| floor::<T, 1>(black_box(&both[..]), o)),
            ],
        ),
        (
            "conductor",
            [
                Box::new(|o: &mut [T]| {
                    over(black_box(&outer[..]), o, |c| {
                        conductor_textbook(c, n, kappa)
                    })
                }),
                Box::new(|o: &mut [T]| conductor_slice(black_box(&outer[..]), n, kappa, o)),
                Box::new(|o: &mut [T]| floor::<T, 2>(black_box(&outer[..]), o)),
            ],
        ),
    ];
    for (law, passes) in &mut pairs {
        let mut times: [Vec<f64>; 3] = Default::default();
        for _ in 0..rounds {
            for (pass, t) in passes.iter_mut().zip(&mut times) {
                t.push(time(&mut out, pass.as_mut()));
            }
        }
        let [(a0, a1), (b0, b1), (f0, f1)] = times.map(best_and_quartile);
        println!(
            "| {name} | {law} | {a0:.2} ns | {b0:.2} ns | {:.2} | {f0:.2} ns | {:.2} | {a1:.2} ns | {b1:.2} ns | {:.2} | {f1:.2} ns | {:.2} |",
            b0 / a0,
            f0 / a0,
            b1 / a1,
            f1 / a1
        );
    }
}

fn main() {
    let rounds = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .filter(|&r: &usize| r > 0)
        .unwrap_or(40);
    println!("{rounds} rounds of {PASSES} passes over {COSINES} cosines, textbook, exact and floor in turn; the exact laws' slice forms and the floor run on {:?}. The floor: the law's `f64` square roots and division alone (one and one for the dielectric, two and one for the conductor).\n", Lanes::widest());
    println!("| tier | law | textbook, best | exact, best | ÷ textbook | floor, best | ÷ textbook | textbook, q1 | exact, q1 | ÷ textbook | floor, q1 | ÷ textbook |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|");
    tier::<f32>("f32", rounds);
    tier::<f64>("f64", rounds);
}
