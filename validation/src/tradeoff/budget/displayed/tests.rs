//! The displayed measures' prediction on small synthetic renders of
//! known bias and noise, measured by the sweep's own code.

use super::*;
use crate::tradeoff::budget::Rays;

const NO_RAYS: Rays = Rays {
    fixed: 0.0,
    per_sample: 0.0,
};

/// Uniform on [−1, 1) from a fixed xorshift: the tests are deterministic.
fn uniform(state: &mut u64) -> f32 {
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    (*state >> 11) as f32 / (1u64 << 53) as f32 * 2.0 - 1.0
}

const WIDTH: u32 = 24;
const HEIGHT: u32 = 16;

/// A scene of known light: a smooth colour ramp `t` (0.05 to 0.75 per
/// channel), a candidate biased by +0.03 on every third pixel, and
/// per-sample noise uniform of half-width `shared` that the candidate and
/// the truth's settings draw alike (their paths) plus `own` of the
/// candidate's alone.
struct Synthetic {
    truth: Vec<Vec3>,
    bias: Vec<Vec3>,
    shared: f32,
    own: f32,
}

impl Synthetic {
    fn new() -> Self {
        let count = (WIDTH * HEIGHT) as usize;
        let truth = (0..count)
            .map(|i| {
                let (x, y) = ((i as u32 % WIDTH) as f32, (i as u32 / WIDTH) as f32);
                let u = x / WIDTH as f32;
                let v = y / HEIGHT as f32;
                Vec3::new(0.05 + 0.7 * u, 0.05 + 0.7 * v, 0.4 - 0.3 * u * v)
            })
            .collect();
        let bias = (0..count)
            .map(|i| Vec3::splat(if i % 3 == 0 { 0.03 } else { 0.0 }))
            .collect();
        Synthetic {
            truth,
            bias,
            shared: 0.6,
            own: 0.05,
        }
    }

    fn image(pixels: Vec<Vec3>) -> Image {
        Image {
            width: WIDTH,
            height: HEIGHT,
            pixels,
        }
    }

    /// One render at `spp` samples: the truth's settings' (`candidate`
    /// false) or the candidate's, the shared noise from `paths`, the
    /// candidate's own from `own`.
    fn render(&self, spp: u32, candidate: bool, paths: &mut u64, own: &mut u64) -> Image {
        let noise = |state: &mut u64, width: f32| -> Vec3 {
            (0..spp)
                .map(|_| Vec3::new(uniform(state), uniform(state), uniform(state)) * width)
                .sum::<Vec3>()
                / spp as f32
        };
        Self::image(
            self.truth
                .iter()
                .zip(&self.bias)
                .map(|(&t, &b)| {
                    let shared = noise(paths, self.shared);
                    if candidate {
                        t + b + shared + noise(own, self.own)
                    } else {
                        t + shared
                    }
                })
                .collect(),
        )
    }
}

/// For each measure and tolerance, 12 pilots (two halves of 2 samples,
/// the candidate and the truth's settings on the same paths) choose the
/// fewest samples whose prediction is within the tolerance, and 12 final
/// renders at those samples are measured by `measure::errors` against
/// the exact truth: every one of the 144 holds its bound (the bound is
/// the largest of 8 simulated renders plus 3 of their deviations; the
/// generators are fixed, so the test is deterministic). And the bound is
/// not vacuous: the mean achieved is over a third of the bound.
#[test]
fn the_simulated_bound_holds_for_each_displayed_measure_over_seeds() {
    let scene = Synthetic::new();
    let mask = Mask::all((WIDTH * HEIGHT) as usize);
    let exact = Truth::new(Synthetic::image(scene.truth.clone()), 0.0, &mask);
    let cases = [
        (Shown::DeltaEMean, 4.0),
        (Shown::DeltaEP99, 20.0),
        (Shown::FlipMean, 0.15),
    ];
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    for (measure, tolerance) in cases {
        let (mut achieved_sum, mut bound_sum, mut count) = (0.0, 0.0, 0);
        for _ in 0..12 {
            let seeds = [state, state ^ 0x5555, state ^ 0xaaaa, state ^ 0x3333];
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1);
            let pair = |first: usize, second: usize, candidate: bool| {
                let (mut paths, mut own) = (seeds[first], seeds[second]);
                scene.render(2, candidate, &mut paths, &mut own)
            };
            let [ra, rb] = [pair(0, 2, false), pair(1, 3, false)];
            let [ca, cb] = [pair(0, 2, true), pair(1, 3, true)];
            let pilot = Pilot::measure([&ca, &cb], [&ra, &rb], &mask, 2, true, NO_RAYS);
            let reference = Reference::new([&ra, &rb], 2, &mask, 1 << 20);
            let simulation = Simulation::new([&ca, &cb], &reference, 2, pilot);
            let chosen = simulation
                .cheapest(&reference, measure, tolerance, 1 << 12)
                .expect("reachable");
            let spp = chosen.spp.unwrap();
            assert!(spp > 1, "{measure:?}: one sample is within {tolerance}");
            for _ in 0..12 {
                let (mut paths, mut own) = (state, state ^ 0x7777);
                state = state
                    .wrapping_mul(2_862_933_555_777_941_757)
                    .wrapping_add(3);
                let render = scene.render(spp, true, &mut paths, &mut own);
                let achieved = measure.of(&measure::errors(&[render], &exact, &mask));
                assert!(
                    achieved <= chosen.bound,
                    "{measure:?}: achieved {achieved} over the predicted {chosen:?}"
                );
                achieved_sum += achieved;
                bound_sum += chosen.bound;
                count += 1;
            }
        }
        let (achieved, bound) = (achieved_sum / count as f64, bound_sum / count as f64);
        println!("{measure:?} T {tolerance}: mean achieved {achieved:.4}, mean bound {bound:.4}");
        assert!(
            achieved > bound / 3.0,
            "{measure:?}: the bound is vacuous: mean {achieved} against {bound}"
        );
    }
}

/// A deterministic candidate that is the truth itself, against a noiseless
/// pilot: every draw is the truth, so the bound is 0 for each measure
/// (to 1e-12), and a bias of 0.1 on every channel is bounded at no less
/// than its own ΔE.
#[test]
fn a_noiseless_pilot_predicts_exactly_what_its_bias_shows() {
    let scene = Synthetic::new();
    let mask = Mask::all((WIDTH * HEIGHT) as usize);
    let truth = Synthetic::image(scene.truth.clone());
    let exact = Truth::new(truth.clone(), 0.0, &mask);
    let reference = Reference::new([&truth, &truth], 2, &mask, 1 << 20);
    let same = Pilot::measure([&truth; 2], [&truth; 2], &mask, 2, false, NO_RAYS);
    let simulation = Simulation::new([&truth, &truth], &reference, 2, same);
    let biased = Synthetic::image(scene.truth.iter().map(|&t| t + 0.1).collect());
    let off = Pilot::measure([&biased; 2], [&truth; 2], &mask, 2, false, NO_RAYS);
    let shifted = Simulation::new([&biased, &biased], &reference, 2, off);
    for measure in [Shown::DeltaEMean, Shown::DeltaEP99, Shown::FlipMean] {
        let p = simulation.predict(&reference, measure, 1);
        assert!(p.bound.abs() < 1e-12, "{measure:?}: {p:?}");
        assert_eq!(p.spp, None);
        let seen = measure.of(&measure::errors(
            std::slice::from_ref(&biased),
            &exact,
            &mask,
        ));
        let q = shifted.predict(&reference, measure, 1);
        assert!(
            seen > 0.0 && (q.bound - seen).abs() < 1e-9,
            "{measure:?}: {q:?} against {seen}"
        );
    }
}

/// A candidate with no bias at all, piloted with noise (two halves of 2
/// samples, shared paths half-width 0.6, its own 0.05), still has a floor
/// above 0 for each measure: the pilot's noise and the truth's. A
/// tolerance of half that floor is answered `Need::Floor`, not a bias
/// above it; one of twice the floor is reached by samples.
#[test]
fn an_unbiased_candidate_has_a_floor_of_the_pilot_and_truth_noise() {
    let mut scene = Synthetic::new();
    scene.bias = vec![Vec3::ZERO; scene.truth.len()];
    let mask = Mask::all((WIDTH * HEIGHT) as usize);
    let seeds = [0x2545_f491_4f6c_dd1d_u64, 0x5555, 0xaaaa, 0x3333];
    let pair = |first: usize, second: usize, candidate: bool| {
        let (mut paths, mut own) = (seeds[first], seeds[second]);
        scene.render(2, candidate, &mut paths, &mut own)
    };
    let [ra, rb] = [pair(0, 2, false), pair(1, 3, false)];
    let [ca, cb] = [pair(0, 2, true), pair(1, 3, true)];
    let pilot = Pilot::measure([&ca, &cb], [&ra, &rb], &mask, 2, true, NO_RAYS);
    let reference = Reference::new([&ra, &rb], 2, &mask, 1 << 10);
    let simulation = Simulation::new([&ca, &cb], &reference, 2, pilot);
    for measure in [Shown::DeltaEMean, Shown::DeltaEP99, Shown::FlipMean] {
        let floor = simulation.floor(&reference, measure);
        assert!(floor > 0.0, "{measure:?}: floor {floor}");
        assert_eq!(
            simulation.need(&reference, measure, floor / 2.0),
            Need::Floor,
            "{measure:?}: floor {floor}"
        );
        assert!(
            matches!(
                simulation.need(&reference, measure, 2.0 * floor),
                Need::Samples { .. }
            ),
            "{measure:?}: floor {floor}"
        );
    }
}

/// The variance map pools a pixel with its 3 × 3 neighbours and keeps the
/// larger: one noisy pixel among quiet ones keeps its own, and lends a
/// ninth of it (a quarter at a corner) to its neighbours.
#[test]
fn the_variance_is_the_larger_of_the_pixel_and_its_neighbourhood() {
    let like = Image {
        width: 3,
        height: 3,
        pixels: vec![Vec3::ZERO; 9],
    };
    let map = variance(&like, |i| DVec3::splat(if i == 4 { 9.0 } else { 0.0 }));
    assert_eq!(map[4], Vec3::splat(9.0));
    assert_eq!(map[1], Vec3::splat(9.0 / 6.0));
    assert_eq!(map[0], Vec3::splat(9.0 / 4.0));
}
