use super::*;
use crate::rng::Pcg32;

/// Draws slot `slot` (the earlier slots drawn and dropped) of sample
/// `index` of pixel `pixel`.
fn pair(seed: u64, pixel: u64, index: u32, slot: u32) -> [f32; 2] {
    let mut sample = Sampler::for_pixel(seed, pixel).sample(index);
    for _ in 0..slot {
        sample.next_1d();
    }
    sample.next_2d()
}

/// Pearson's χ² of `values` in `bins` equal bins of `[0, 1)`.
fn chi_square(values: &[f32], bins: usize) -> f64 {
    let mut counts = vec![0_u32; bins];
    for &v in values {
        counts[((v as f64 * bins as f64) as usize).min(bins - 1)] += 1;
    }
    let expected = values.len() as f64 / bins as f64;
    counts
        .iter()
        .map(|&c| (c as f64 - expected).powi(2) / expected)
        .sum()
}

/// Each number, taken across pixels (so across independent scrambles) at
/// a fixed sample index, is uniform on `[0, 1)`: Pearson's χ² over 64 bins
/// of 6400 pixels (63 degrees of freedom) stays below 132, its 1 − 10⁻⁶
/// quantile (Wilson–Hilferty), for every slot's two coordinates and its
/// one-dimensional number, at the first, a middle and a late index.
#[test]
fn each_dimension_is_uniform_by_chi_square() {
    for slot in 0..8 {
        for index in [0, 5, 1000] {
            let draws: Vec<[f32; 2]> = (0..6400).map(|p| pair(9, p, index, slot)).collect();
            let ones: Vec<f32> = (0..6400)
                .map(|p| {
                    let mut sample = Sampler::for_pixel(9, p).sample(index);
                    for _ in 0..slot {
                        sample.next_2d();
                    }
                    sample.next_1d()
                })
                .collect();
            for (name, values) in [
                ("x", draws.iter().map(|d| d[0]).collect::<Vec<_>>()),
                ("y", draws.iter().map(|d| d[1]).collect()),
                ("1d", ones),
            ] {
                assert!(values.iter().all(|v| (0.0..1.0).contains(v)));
                let chi2 = chi_square(&values, 64);
                assert!(chi2 < 132.0, "slot {slot} index {index} {name}: χ² {chi2}");
            }
        }
    }
}

/// Whether the points are a (0, m, 2)-net in base 2 (`points.len() = 2^m`):
/// every elementary interval `[i/2^a, (i+1)/2^a) × [j/2^b, (j+1)/2^b)`
/// with `a + b = m` holds exactly one point.
fn is_02_net(points: &[[f32; 2]]) -> bool {
    let m = points.len().trailing_zeros();
    assert_eq!(points.len(), 1 << m);
    (0..=m).all(|a| {
        let b = m - a;
        let mut seen = vec![false; points.len()];
        points.iter().all(|p| {
            let i = (p[0] as f64 * (1u64 << a) as f64) as usize;
            let j = (p[1] as f64 * (1u64 << b) as f64) as usize;
            !std::mem::replace(&mut seen[(i << b) | j], true)
        })
    })
}

/// The (0,2) property, whatever the scramble and the shuffle: a pixel's
/// first `2^m` samples of each slot put exactly one point in every
/// elementary interval of area `2^-m`, for m up to 12 (exact: no tolerance).
/// The check has the power to see a scramble that is not nested: flipping
/// each bit by the bits *below* it (the same steps unmirrored) breaks the
/// net at the first prefix past 2 points.
#[test]
fn power_of_two_prefixes_are_elementary_interval_stratified() {
    for pixel in 0..4 {
        for slot in 0..6 {
            for m in 0..=12 {
                let points: Vec<[f32; 2]> = (0..1 << m).map(|k| pair(3, pixel, k, slot)).collect();
                assert!(is_02_net(&points), "pixel {pixel} slot {slot} m {m}");
            }
        }
    }
    let unnested = |x: u32, seed: u32| {
        let mut y = x.wrapping_add(seed);
        y ^= y.wrapping_mul(0x6c50_b47c);
        y = y.wrapping_mul(seed.rotate_right(16) | 1);
        y ^ y.wrapping_mul(0xb82f_1e52)
    };
    let points: Vec<[f32; 2]> = (0..16)
        .map(|k| {
            [
                unit(unnested(sobol_0(k), 17)),
                unit(unnested(sobol_1(k), 29)),
            ]
        })
        .collect();
    assert!(!is_02_net(&points), "an unnested scramble breaks the net");
}

/// A smooth integrand over two slots (four dimensions):
/// `f = (1 + sin 2πx₀) · y₀² · e^{x₁} · (1 + y₁)`, whose integral over the
/// unit hypercube is `1 · ⅓ · (e − 1) · 3/2 = (e − 1)/2`.
fn smooth(u: [f32; 2], v: [f32; 2]) -> f64 {
    let [x0, y0] = u.map(f64::from);
    let [x1, y1] = v.map(f64::from);
    (1.0 + (std::f64::consts::TAU * x0).sin()) * y0 * y0 * x1.exp() * (1.0 + y1)
}

const SMOOTH_INTEGRAL: f64 = (std::f64::consts::E - 1.0) / 2.0;

/// Mean and variance, over `pixels` pixels, of the `n`-sample estimate of
/// the smooth integral, the samples drawn by `draw(pixel, k)`.
fn estimates(pixels: u64, n: u32, draw: impl Fn(u64, u32) -> ([f32; 2], [f32; 2])) -> (f64, f64) {
    let values: Vec<f64> = (0..pixels)
        .map(|p| {
            (0..n)
                .map(|k| smooth(draw(p, k).0, draw(p, k).1))
                .sum::<f64>()
                / n as f64
        })
        .collect();
    let mean = values.iter().sum::<f64>() / pixels as f64;
    let variance = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (pixels - 1) as f64;
    (mean, variance)
}

fn scrambled(p: u64, k: u32) -> ([f32; 2], [f32; 2]) {
    let mut sample = Sampler::for_pixel(21, p).sample(k);
    (sample.next_2d(), sample.next_2d())
}

/// Unbiased: over 2000 pixels (independent scrambles), the mean of the
/// 1-, 16- and 100-sample estimates of a four-dimensional integral (two
/// slots) lies within 5 standard errors of its value.
#[test]
fn the_estimate_of_a_known_integral_is_unbiased_over_seeds() {
    let pixels = 2000;
    for n in [1, 16, 100] {
        let (mean, variance) = estimates(pixels, n, scrambled);
        let standard_error = (variance / pixels as f64).sqrt();
        assert!(
            (mean - SMOOTH_INTEGRAL).abs() < 5.0 * standard_error,
            "n {n}: mean {mean}, integral {SMOOTH_INTEGRAL}, standard error {standard_error}"
        );
    }
}

/// Variance, over `pixels` pixels, of the `n`-sample mean of `f` at the
/// points `draw(pixel, k)`.
fn variance_of_mean(
    pixels: u64,
    n: u32,
    f: impl Fn([f32; 2]) -> f64,
    draw: impl Fn(u64, u32) -> [f32; 2],
) -> f64 {
    let values: Vec<f64> = (0..pixels)
        .map(|p| (0..n).map(|k| f(draw(p, k))).sum::<f64>() / n as f64)
        .collect();
    let mean = values.iter().sum::<f64>() / pixels as f64;
    values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (pixels - 1) as f64
}

/// For a smooth integrand of one slot's pair, the variance of a scrambled
/// net's estimate falls as `N^-3 (log N)` (Owen, "Scrambled net variance
/// for integrals of smooth functions", Ann. Statist. 25(4), 1997), against
/// `N^-1` for independent samples: from 16 to 256 samples it must fall at
/// least 64 times (16 times is `1/N`; 200 pixels estimate each variance
/// within about ±20 %, so a 4 × margin). Independent PCG samples, measured
/// the same way, fall about 16 times, below the bar: the bar tells the two
/// apart. (Across slots the pairs are shuffled apart, so an integrand's
/// interaction between two slots keeps `1/N`: the unbiased test above
/// holds there, this one only within a pair.)
#[test]
fn variance_falls_faster_than_one_over_n_for_a_smooth_integrand() {
    let pixels = 200;
    let f = |[x, y]: [f32; 2]| {
        let (x, y) = (x as f64, y as f64);
        (1.0 + (std::f64::consts::TAU * x).sin()) * y * y * (x * y).exp()
    };
    let fall = |draw: &dyn Fn(u64, u32) -> [f32; 2]| {
        variance_of_mean(pixels, 16, f, draw) / variance_of_mean(pixels, 256, f, draw)
    };
    let ours = fall(&|p, k| pair(21, p, k, 1));
    assert!(
        ours > 64.0,
        "variance fell {ours} times from 16 to 256 samples"
    );
    let independent = fall(&|p, k| {
        let mut rng = Pcg32::for_pixel(p, k as u64);
        [rng.next_f32(), rng.next_f32()]
    });
    assert!(
        independent < 64.0,
        "independent samples fell {independent} times"
    );
    println!(
        "variance fall from 16 to 256 samples: scrambled nets {ours}, independent {independent}"
    );
}

/// Sobol's second dimension from its generator columns 1/2, 3/4, 5/8
/// (`v_j = v_{j-1} ⊕ v_{j-1}/2`): point `k` is the xor of the columns of
/// `k`'s set bits, so in index order 0, 1/2, 3/4, 1/4, 5/8, 1/8, 3/8, 7/8
/// (the superset sum gives the columns' xor for 10⁴ random 32-bit indices);
/// with the van der Corput dimension every power-of-two prefix is a
/// (0, m, 2)-net, up to 2^16 points (Sobol's sequence in its first two
/// dimensions is a (0,2)-sequence).
#[test]
fn sobol_second_dimension_is_the_pascal_generator_and_a_02_sequence() {
    let expected = [0.0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875];
    for (k, want) in expected.into_iter().enumerate() {
        assert_eq!(unit(sobol_1(k as u32)), want, "point {k}");
    }
    let mut rng = Pcg32::new(5, 7);
    for _ in 0..10_000 {
        let index = rng.next_u32();
        let by_column = (0..32)
            .filter(|j| index >> j & 1 == 1)
            .fold(0, |x, j| x ^ SOBOL_1_COLUMNS[j]);
        assert_eq!(sobol_1(index), by_column, "index {index:#x}");
    }
    for m in 0..=16 {
        let plain: Vec<[f32; 2]> = (0..1 << m)
            .map(|k| [unit(sobol_0(k)), unit(sobol_1(k))])
            .collect();
        assert!(is_02_net(&plain), "Sobol's first 2^{m} points");
    }
}

/// The scramble is a bijection (a permutation of the 2^32 fractions): on
/// 2^16 consecutive inputs, no two outputs collide.
#[test]
fn the_scramble_is_a_permutation() {
    let mut outputs: Vec<u32> = (0..1 << 16)
        .map(|x| owen_scramble(x << 7, 0xdead_beef))
        .collect();
    outputs.sort_unstable();
    outputs.dedup();
    assert_eq!(outputs.len(), 1 << 16);
}

#[test]
fn samples_repeat_for_a_seed_and_differ_between_seeds_and_pixels() {
    assert_eq!(pair(1, 2, 3, 4), pair(1, 2, 3, 4));
    assert_ne!(pair(1, 2, 3, 4), pair(2, 2, 3, 4));
    assert_ne!(pair(1, 2, 3, 4), pair(1, 3, 3, 4));
}

/// A slot taken now and worked out later, or never, draws what drawing it
/// at once would: its number is the first coordinate of the slot's pair
/// (bit for bit), and the slots after it are the same whether or not it
/// was worked out, for 1000 pixels and samples 0..8 over 6 slots.
#[test]
fn a_slot_taken_without_its_number_leaves_every_number_unchanged() {
    for p in 0..1000 {
        for index in 0..8 {
            let pixel = Sampler::for_pixel(5, p);
            let mut eager = pixel.sample(index);
            let mut lazy = pixel.sample(index);
            let mut taken = Vec::new();
            for slot in 0..6 {
                let pair = eager.next_2d();
                if slot % 2 == 0 {
                    assert_eq!(lazy.next_2d(), pair, "pixel {p} sample {index} slot {slot}");
                } else {
                    taken.push((lazy.take_1d(), pair[0]));
                }
            }
            for (slot, first) in taken {
                assert_eq!(
                    slot.value().to_bits(),
                    first.to_bits(),
                    "pixel {p} sample {index}"
                );
            }
            assert_eq!(lazy.slots_drawn(), eager.slots_drawn());
        }
    }
}

/// Slot `slot` of sample `index` of pixel `pixel` drawn as the
/// construction states it, step by step: the slot's seeds hashed from the
/// pixel's key, the index shuffled, Sobol's point in both dimensions (the
/// second as the xor of its generator columns), each coordinate scrambled.
fn constructed_pair(seed: u64, pixel: u64, index: u32, slot: u32) -> [f32; 2] {
    let key = splitmix64(seed ^ splitmix64(pixel ^ SAMPLER_SALT));
    let seeds = slot_seeds(key, slot);
    let i = shuffled(index, seeds[0]);
    let by_column = (0..32)
        .filter(|j| i >> j & 1 == 1)
        .fold(0, |x, j| x ^ SOBOL_1_COLUMNS[j]);
    [
        unit(owen_scramble(sobol_0(i), seeds[1])),
        unit(owen_scramble(by_column, seeds[2])),
    ]
}

/// The sampler's pairs have the bits of the construction (tolerance: none,
/// `f32` compared exactly), the first slot's seeds taken once per pixel
/// and the scramble entered mirrored: every slot 0..6 of samples 0..64 of
/// 200 pixels under two seeds, and each slot's taken number the first of
/// its pair.
#[test]
fn pairs_have_the_bits_of_the_scrambled_sobol_construction() {
    for seed in [0, 0x5eed] {
        for p in 0..200 {
            let pixel = Sampler::for_pixel(seed, p);
            for index in 0..64 {
                let mut sample = pixel.sample(index);
                for slot in 0..6 {
                    let want = constructed_pair(seed, p, index, slot).map(f32::to_bits);
                    let mut taken = sample.clone();
                    assert_eq!(
                        taken.take_1d().value().to_bits(),
                        want[0],
                        "seed {seed} pixel {p} sample {index} slot {slot}"
                    );
                    let got = sample.next_2d().map(f32::to_bits);
                    assert_eq!(
                        got, want,
                        "seed {seed} pixel {p} sample {index} slot {slot}"
                    );
                }
            }
        }
    }
}
