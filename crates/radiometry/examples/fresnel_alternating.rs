//! The exact laws' slice forms against the textbook form of the same law,
//! timed alternately in one process: textbook, exact, textbook, exact, …
//! over the same 4096 cosines, so that a loaded machine's drift falls on
//! both alike. Prints, per tier and law, the best and the first-quartile
//! time per evaluation of each and their ratio.
//!
//! Run: `cargo run --release -p radiometry --example fresnel_alternating [ROUNDS]`
//! (40 rounds of 100 passes each by default). The criterion bench
//! (`cargo bench -p radiometry --bench fresnel`) times each law in turn
//! and writes the table of docs/results.md; this one is for comparing
//! builds under load, where only ratios taken side by side mean anything.

use std::hint::black_box;
use std::time::Instant;

use radiometry::fresnel::{conductor_slice, dielectric_slice};
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
    let mut pairs: [(&str, [Pass<T>; 2]); 2] = [
        (
            "dielectric",
            [
                Box::new(|o: &mut [T]| {
                    over(black_box(&both[..]), o, |c| {
                        dielectric_textbook(c, eta, inv_eta2)
                    })
                }),
                Box::new(|o: &mut [T]| dielectric_slice(black_box(&both[..]), eta, o)),
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
            ],
        ),
    ];
    for (law, [textbook, exact]) in &mut pairs {
        let (mut a, mut b) = (Vec::new(), Vec::new());
        for _ in 0..rounds {
            a.push(time(&mut out, textbook.as_mut()));
            b.push(time(&mut out, exact.as_mut()));
        }
        let ((a0, a1), (b0, b1)) = (best_and_quartile(a), best_and_quartile(b));
        println!(
            "| {name} | {law} | {a0:.2} ns | {b0:.2} ns | {:.2} | {a1:.2} ns | {b1:.2} ns | {:.2} |",
            b0 / a0,
            b1 / a1
        );
    }
}

fn main() {
    let rounds = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .filter(|&r: &usize| r > 0)
        .unwrap_or(40);
    println!("{rounds} rounds of {PASSES} passes over {COSINES} cosines, textbook and exact alternately; the exact laws' slice forms run on {:?}.\n", radiometry::fresnel::Lanes::widest());
    println!("| tier | law | textbook, best | exact, best | ÷ textbook | textbook, q1 | exact, q1 | ÷ textbook |");
    println!("|---|---|---|---|---|---|---|---|");
    tier::<f32>("f32", rounds);
    tier::<f64>("f64", rounds);
}
