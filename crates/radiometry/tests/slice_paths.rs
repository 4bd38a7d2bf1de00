//! The slice forms of the exact laws give the same bits on every width of
//! instructions they are compiled for, and the same bits as the scalar law:
//! tolerance zero, NaN matched by NaN. Images and references must not
//! depend on the CPU that computed them.

use radiometry::fresnel::{conductor, conductor_slice_on, dielectric, dielectric_slice_on, Lanes};
use radiometry::Real;

/// Cosines where the laws do something special or cancel: both signs of
/// zero and one, just past one (clamped), subnormal, NaN and the infinities,
/// the critical and Brewster cosines of each index and their neighbours,
/// and an even spread over `[-1, 1]`, in an order that puts special values
/// in every lane position.
fn cosines<T: Real>(indices: &[f64]) -> Vec<T> {
    let mut c: Vec<f64> = vec![
        0.0,
        -0.0,
        1.0,
        -1.0,
        1.0 + 1e-7,
        -1.0 - 1e-7,
        1e-40,
        -1e-40,
        1e-310,
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
    ];
    for &eta in indices.iter().filter(|e| e.is_finite() && **e > 0.0) {
        let critical = (1.0 - 1.0 / (eta * eta)).max(0.0).sqrt();
        let brewster = 1.0 / (1.0 + eta * eta).sqrt();
        for centre in [-critical, critical, -brewster, brewster] {
            for k in -3..=3 {
                c.push(centre + f64::from(k) * 1e-8);
            }
        }
    }
    c.extend((0..997).map(|k| -1.0 + 2.0 * f64::from(k) / 996.0));
    // And a spread of pseudo-random ones (splitmix64), so that each tier
    // compares at least a million results.
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    c.extend((0..RANDOM_COSINES).map(|_| {
        state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }));
    c.into_iter().map(T::lit).collect()
}

/// The pseudo-random cosines added to the special ones.
const RANDOM_COSINES: usize = 50_000;

/// The fewest results each tier compares.
const AT_LEAST: usize = 1_000_000;

fn same_bits<T: Real>(a: T, b: T) -> bool {
    a == b && a.is_sign_negative() == b.is_sign_negative() || a.is_nan() && b.is_nan()
}

fn check<T: Real + std::fmt::LowerExp>(tier: &str) {
    let lanes: Vec<Lanes> = Lanes::ALL.into_iter().filter(|l| l.available()).collect();
    println!("{tier}: comparing {lanes:?} with the scalar law");
    let indices = [
        1.0,
        1.5,
        1.0 / 1.5,
        1.333,
        2.42,
        1.0001,
        1e-30,
        1e30,
        0.0,
        -1.5,
        f64::NAN,
        f64::INFINITY,
    ];
    let metals = [
        (0.17, 3.1),
        (0.35, 2.7),
        (1.5, 1.9),
        (1.0, 0.0),
        (1.5, 0.0),
        (1e-3, 1e3),
        (0.0, 1.0),
        (1.0, -1.0),
        (f64::NAN, 1.0),
    ];
    let cos: Vec<T> = cosines(&indices);
    let mut out = vec![T::zero(); cos.len()];
    let mut compared = 0usize;
    for eta in indices.map(T::lit) {
        for &path in &lanes {
            dielectric_slice_on(path, &cos, eta, &mut out);
            for (&c, &r) in cos.iter().zip(&out) {
                let scalar = dielectric(c, eta);
                assert!(same_bits(r, scalar), "{tier} dielectric on {path:?}, eta {eta}, cos {c:e}: {r:e} against the scalar law's {scalar:e}");
                compared += 1;
            }
        }
    }
    for (n, kappa) in metals.map(|(n, k)| (T::lit(n), T::lit(k))) {
        for &path in &lanes {
            conductor_slice_on(path, &cos, n, kappa, &mut out);
            for (&c, &r) in cos.iter().zip(&out) {
                let scalar = conductor(c, n, kappa);
                assert!(same_bits(r, scalar), "{tier} conductor on {path:?}, n {n}, κ {kappa}, cos {c:e}: {r:e} against the scalar law's {scalar:e}");
                compared += 1;
            }
        }
    }
    println!("{tier}: {compared} results, all the same bits");
    assert!(
        compared >= AT_LEAST,
        "{tier}: only {compared} results compared"
    );
}

#[test]
fn fresnel_slice_paths_agree_bit_for_bit() {
    check::<f32>("f32");
    check::<f64>("f64");
}
