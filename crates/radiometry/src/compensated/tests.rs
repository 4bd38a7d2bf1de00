//! The error-free transformations and the short sums, against the fused
//! multiply-add and the full compensated sums.

use super::dielectric::*;
use super::error_free::*;
use super::*;
use crate::Real;

/// A xorshift generator of 64-bit words from `state`: reproducible
/// random operands.
fn xorshift(mut state: u64) -> impl FnMut() -> u64 {
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    }
}

#[test]
fn dekkers_product_error_is_the_fused_multiply_adds() {
    // Both are exact, so they agree bit for bit: over 2^±450 (products
    // far from underflow), and for products of widened f32s (error 0).
    let mut next = xorshift(0x9e37_79b9_7f4a_7c15);
    for _ in 0..100_000 {
        let magnitude = |bits: u64| 2f64.powi((bits % 900) as i32 - 450);
        let (ra, rb) = (next(), next());
        let a = (ra >> 11) as f64 / (1u64 << 53) as f64 * magnitude(ra);
        let b = -((rb >> 11) as f64) / (1u64 << 53) as f64 * magnitude(rb);
        let p = a * b;
        assert_eq!(
            dekker_error(a, b, p).to_bits(),
            a.mul_add(b, -p).to_bits(),
            "{a:e} · {b:e}"
        );
        let narrow =
            |x: f64, bits: u64| (x / magnitude(bits) * 2f64.powi((bits % 120) as i32 - 60)) as f32;
        let (fa, fb) = (f64::from(narrow(a, ra)), f64::from(narrow(b, rb)));
        assert_eq!(dekker_error(fa, fb, fa * fb), 0.0, "{fa:e} · {fb:e}");
    }
    let big = 2f64.powi(994) * 1.999;
    assert_eq!(
        dekker_error(big, 0.75, big * 0.75),
        big.mul_add(0.75, -big * 0.75)
    );
}

#[test]
fn scaled_dekker_error_is_the_fused_multiply_adds_for_huge_operands() {
    // Operands from 2^990 to the largest double, against factors whose
    // product stays finite: the scaled split must give the exact error.
    let mut next = xorshift(0x2545_f491_4f6c_dd1d);
    let mut scaled = 0;
    for _ in 0..100_000 {
        let (ra, rb) = (next(), next());
        let a = (1.0 + (ra >> 12) as f64 / (1u64 << 52) as f64) * 2f64.powi(990 + (ra % 34) as i32);
        let b = -((rb >> 11) as f64) / (1u64 << 53) as f64 * 2f64.powi(-((rb % 900) as i32));
        let (a, b) = if ra & 1 == 0 { (a, b) } else { (b, a) };
        let p = a * b;
        if !p.is_finite() {
            continue;
        }
        scaled += usize::from(a.abs().max(b.abs()) >= 2f64.powi(995));
        assert_eq!(
            scaled_dekker_error(a, b, p).to_bits(),
            a.mul_add(b, -p).to_bits(),
            "{a:e} · {b:e}"
        );
    }
    assert!(scaled > 50_000, "only {scaled} cases took the scaled split");
    assert_eq!(
        scaled_dekker_error(f64::MAX, 0.75, f64::MAX * 0.75),
        f64::MAX.mul_add(0.75, -f64::MAX * 0.75)
    );
}

#[test]
fn two_sum_and_two_prod_are_error_free() {
    // 1 + 2⁻⁶⁰ is not representable; the error term must hold the 2⁻⁶⁰.
    let tiny = 2f64.powi(-60);
    assert_eq!(two_sum(1.0, tiny), (1.0, tiny));
    // (1 + 2⁻³⁰)² = 1 + 2⁻²⁹ + 2⁻⁶⁰: the last term is the product's error.
    let a = 1.0 + 2f64.powi(-30);
    assert_eq!(two_prod(a, a), (1.0 + 2f64.powi(-29), tiny));
}

/// The square of a product of two widened `f32`s is the exact product's
/// square, `q + e` (`two_prod`, error-free: Dekker's split in this build),
/// to the bit, both with the error split by Dekker's method and with it
/// fused: over random `f32`s from 2^-40 to 2^40. Tolerance zero: both
/// parts are exact numbers, not roundings.
#[test]
fn the_square_of_a_narrow_product_is_exact_fused_or_split() {
    let mut next = xorshift(0x51_7cc1_b727_220a);
    for _ in 0..100_000 {
        let narrow = |bits: u64| {
            let m = (bits >> 40) as f32 / (1u64 << 24) as f32 + 0.5;
            f64::from(m * 2f32.powi((bits % 81) as i32 - 40))
        };
        let (a, b) = (narrow(next()), narrow(next()));
        let (q, e) = two_prod(a * b, a * b);
        for square in [
            square_of_narrow_product::<_, false>(a, b),
            square_of_narrow_product::<_, true>(a, b),
        ] {
            assert_eq!(
                (square.high.to_bits(), square.low.to_bits()),
                (q.to_bits(), e.to_bits()),
                "({a:e} · {b:e})²"
            );
        }
    }
}

#[test]
fn discriminant_keeps_digits_that_cancel() {
    // eta = 1 + 2⁻³⁰, c = 0: eta² − 1 = 2⁻²⁹ + 2⁻⁶⁰ exactly; the naive
    // form drops the 2⁻⁶⁰, the compensated one keeps it.
    let eta = 1.0 + 2f64.powi(-30);
    let exact = 2f64.powi(-29) + 2f64.powi(-60);
    let squares = IndexSquares::of(eta, false);
    assert_eq!(
        snell_discriminant::<_, false>(&squares, false, 0.0, false),
        exact
    );
    assert_eq!(squares.contrast(false).value(), exact);
    assert_eq!(squares.contrast(true).value(), -exact);
    assert_ne!(eta * eta - 1.0, exact);
}

/// The narrow tier's short sums against the wide tier's compensated
/// ones (Sum2, or the products split exactly) of the same widened
/// inputs, where they cancel: Snell's discriminant at cosines
/// around the critical angle, Brewster's factor around Brewster's
/// angle, a conductor's two of each, for indices from 1 + 2^-20 to 10^3,
/// from both sides. Both add the terms that cancel exactly and round
/// what is left: within 2 f64 ulps of each other.
#[test]
fn a_narrow_tiers_short_sums_are_within_2_ulps_of_sum2_where_they_cancel() {
    let mut worst = 0.0f64;
    let mut check = |short: f64, full: f64, what: &str| {
        let ulps = (short - full).abs() / f64::ulp_at(full);
        assert!(
            ulps <= 2.0,
            "{what}: {short:e} against {full:e}, {ulps} ulps"
        );
        worst = worst.max(ulps);
    };
    for &eta in &[1.0 + 2f32.powi(-20), 1.0001, 1.333, 1.5, 2.4, 10.0, 1000.0] {
        for (n_t, n_i) in [(eta, 1.0), (1.0, eta)] {
            let (n_t, n_i) = (f64::from(n_t), f64::from(n_i));
            // The cosines of the critical angle (from inside) and of
            // Brewster's, and 200 f32 neighbours either side.
            let critical = (1.0 - (n_t / n_i).powi(2)).max(0.0).sqrt() as f32;
            let brewster = (n_i / (n_t * n_t + n_i * n_i).sqrt()) as f32;
            for centre in [critical, brewster] {
                let mut c = centre;
                for _ in 0..200 {
                    c = f32::from_bits(c.to_bits().saturating_sub(1));
                }
                for _ in 0..400 {
                    let w = f64::from(c);
                    let s = f64::from((1.0 - c * c).max(0.0).sqrt());
                    let eta = f64::from(eta);
                    let inside = n_i != 1.0;
                    let (narrow, wide) =
                        (IndexSquares::of(eta, true), IndexSquares::of(eta, false));
                    // The fused and the split exact errors: the same bits.
                    let fused = [
                        snell_discriminant::<_, true>(&narrow, inside, w, true),
                        brewster_factor::<_, true>(&narrow, inside, w, true),
                    ];
                    let split = [
                        snell_discriminant::<_, false>(&narrow, inside, w, true),
                        brewster_factor::<_, false>(&narrow, inside, w, true),
                    ];
                    assert_eq!(fused.map(f64::to_bits), split.map(f64::to_bits), "{w:e}");
                    check(
                        split[0],
                        snell_discriminant::<_, false>(&wide, inside, w, false),
                        "Snell's discriminant",
                    );
                    check(
                        snell_discriminant_from_sine(n_t, n_i, s, true),
                        snell_discriminant_from_sine(n_t, n_i, s, false),
                        "Snell's discriminant from the sine",
                    );
                    check(
                        split[1],
                        brewster_factor::<_, false>(&wide, inside, w, false),
                        "Brewster's factor",
                    );
                    // A conductor of small κ from outside.
                    let (x, y) = (f64::from((n_t / n_i) as f32), f64::from(1e-6f32));
                    let contrast = squares_plus(x, y, -1.0, true);
                    let contrast_full = squares_plus(x, y, -1.0, false);
                    check(
                        discriminant_from(contrast, w, true),
                        discriminant_from(contrast_full, w, false),
                        "a conductor's discriminant",
                    );
                    let a = squares_plus(x, y, 1.0, true);
                    let a_full = squares_plus(x, y, 1.0, false);
                    let from = brewster_from::<_, false>(a, w, true);
                    let fused = brewster_from::<_, true>(a, w, true);
                    assert_eq!(from.to_bits(), fused.to_bits(), "{w:e}");
                    check(
                        from,
                        brewster_from::<_, false>(a_full, w, false),
                        "a conductor's Brewster factor",
                    );
                    c = f32::from_bits(c.to_bits() + 1);
                }
            }
        }
    }
    println!("worst {worst:.2} f64 ulps");
}
