//! Error-free transformations for the few sums where the laws cancel.
//!
//! Near the critical angle `n_t² − n_i² sin²θ` is a difference of nearly equal
//! numbers, and near Brewster's angle so is `cos²θ (n_t² + n_i²) − n_i²`. Evaluated
//! naively each loses as many digits as cancel (all of them within 1e-12 rad
//! of the critical angle). Here every product is split exactly into a rounded
//! value and its rounding error (`two_prod`, via a fused multiply-add) and
//! the terms are summed with their errors carried along (`two_sum`), so the
//! result is as accurate as if it had been computed in twice the working
//! precision and rounded once.
//!
//! The `f32` tier carries these sums in `f64` ([`Real::Wide`]), where its
//! products are exact, so its results are limited only by the final rounding;
//! the error terms of those products are zero and are not computed
//! ([`Real::PRODUCTS_EXACT_IN_WIDE`]).
//!
//! `two_prod` takes a product's rounding error by a fused multiply-add where
//! the target has the instruction, and by Dekker's splitting otherwise: the
//! default x86-64 target has no FMA, so `mul_add` would be a call into libm
//! for every product, the cost of the whole law. Both give the exact error
//! (Dekker's for operands below `2^995` in magnitude, whose splitting cannot
//! overflow; larger ones take `mul_add`), so the results are the same bits
//! on every target.
//!
//! Reference: T. Ogita, S. M. Rump, S. Oishi, "Accurate sum and dot product",
//! SIAM J. Sci. Comput. 26(6), 2005 (algorithms TwoSum, TwoProduct, Sum2).

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use crate::Real;

/// `a + b` as `(s, e)` with `s = fl(a + b)` and `a + b = s + e` exactly.
#[inline]
fn two_sum<T: Real>(a: T, b: T) -> (T, T) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

/// `a · b` as `(p, e)` with `p = fl(a · b)` and `a · b = p + e` exactly
/// (barring underflow).
#[inline]
fn two_prod<T: Real>(a: T, b: T) -> (T, T) {
    let p = a * b;
    if cfg!(target_feature = "fma") {
        return (p, a.mul_add(b, -p));
    }
    let limit = T::lit(2f64.powi(995));
    if !(a.abs() < limit && b.abs() < limit) {
        return (p, a.mul_add(b, -p));
    }
    (p, dekker_error(a, b, p))
}

/// The rounding error of `p = fl(a · b)` by Dekker's product (1971): each
/// operand split into halves of at most half the significand, whose four
/// products are exact. Exact for `|a|, |b| < 2^995` barring underflow.
#[inline]
fn dekker_error<T: Real>(a: T, b: T, p: T) -> T {
    let split = |x: T| {
        let c = T::lit(T::SPLITTER) * x;
        let high = c - (c - x);
        (high, x - high)
    };
    let ((ah, al), (bh, bl)) = (split(a), split(b));
    ((ah * bh - p) + ah * bl + al * bh) + al * bl
}

/// [`two_prod`] of two numbers widened from a tier whose products are exact
/// in the wide one (`exact`, a constant per tier): the error term is zero.
#[inline]
fn narrow_prod<T: Real>(a: T, b: T, exact: bool) -> (T, T) {
    if exact {
        (a * b, T::zero())
    } else {
        two_prod(a, b)
    }
}

/// Sums `terms` as if in twice the working precision (Sum2).
#[inline]
fn sum<T: Real, const N: usize>(terms: [T; N]) -> T {
    let mut s = T::zero();
    let mut err = T::zero();
    for t in terms {
        let (next, e) = two_sum(s, t);
        s = next;
        err = err + e;
    }
    s + err
}

/// `(a · b)²` as an unevaluated sum of three terms, exact to about `ε³`
/// relative: with `a b = p + e` exactly, `(a b)² = p² + 2pe + e²`, and the
/// first two products are split again.
#[inline]
fn square_of_product<T: Real>(a: T, b: T, exact: bool) -> [T; 3] {
    let (p, e) = narrow_prod(a, b, exact);
    let (q, qe) = two_prod(p, p);
    if exact {
        return [q, T::zero(), qe];
    }
    let (m, me) = two_prod(p + p, e);
    [q, m, qe + me + e * e]
}

// The interface quantities below are written for light going from a medium
// of real index `n_i` into one of index `n_t = x + i·y` (`y = 0` for a
// dielectric). The crate always has one of the two indices equal to 1, so no
// ratio of indices is ever rounded.

/// `x² − y² − n_i²`, the real part of `n_t² − n_i²`.
#[inline]
fn index_contrast_in<T: Real>(x: T, y: T, n_i: T, exact: bool) -> T {
    let (x2, x2e) = narrow_prod(x, x, exact);
    let (y2, y2e) = narrow_prod(y, y, exact);
    let (i2, i2e) = narrow_prod(n_i, n_i, exact);
    sum([x2, -i2, -y2, x2e, -i2e, -y2e])
}

/// `x² − y² − n_i² + (n_i c)²`, the real part of `n_t² − n_i² sin²θ_i`
/// (`= n_t² cos²θ_t`), which vanishes at the critical angle.
#[inline]
fn snell_discriminant_in<T: Real>(x: T, y: T, n_i: T, c: T, exact: bool) -> T {
    let (x2, x2e) = narrow_prod(x, x, exact);
    let (y2, y2e) = narrow_prod(y, y, exact);
    let (i2, i2e) = narrow_prod(n_i, n_i, exact);
    let [ic2, ic2m, ic2e] = square_of_product(n_i, c, exact);
    sum([x2, -i2, ic2, -y2, ic2m, x2e, -i2e, ic2e, -y2e])
}

/// `n_t² − (n_i s)²` for a dielectric (`n_t` real), `= n_t² cos²θ_t` with
/// `s = sin θ_i`: Snell's discriminant from the sine.
#[inline]
fn snell_discriminant_from_sine_in<T: Real>(n_t: T, n_i: T, s: T, exact: bool) -> T {
    let (t2, t2e) = narrow_prod(n_t, n_t, exact);
    let [is2, is2m, is2e] = square_of_product(n_i, s, exact);
    sum([t2, -is2, t2e, -is2m, -is2e])
}

/// `(c x)² − (c y)² + (c n_i)² − n_i²`, the real part of
/// `c² (n_t² + n_i²) − n_i²`, which vanishes at Brewster's angle.
#[inline]
fn brewster_factor_in<T: Real>(x: T, y: T, n_i: T, c: T, exact: bool) -> T {
    let [cx2, cx2m, cx2e] = square_of_product(c, x, exact);
    let [cy2, cy2m, cy2e] = square_of_product(c, y, exact);
    let [ci2, ci2m, ci2e] = square_of_product(c, n_i, exact);
    let (i2, i2e) = narrow_prod(n_i, n_i, exact);
    sum([
        cx2, -cy2, ci2, -i2, cx2m, -cy2m, ci2m, cx2e, -cy2e, ci2e, -i2e,
    ])
}

/// Real part of `n_t² − n_i²`, `n_t = x + i·y`; see [`index_contrast_in`].
#[inline]
pub(crate) fn index_contrast<T: Real>(x: T, y: T, n_i: T) -> T {
    T::narrow(index_contrast_in(
        x.widen(),
        y.widen(),
        n_i.widen(),
        T::PRODUCTS_EXACT_IN_WIDE,
    ))
}

/// Real part of `n_t² − n_i² sin²θ_i`; see [`snell_discriminant_in`].
#[inline]
pub(crate) fn snell_discriminant<T: Real>(x: T, y: T, n_i: T, c: T) -> T {
    T::narrow(snell_discriminant_in(
        x.widen(),
        y.widen(),
        n_i.widen(),
        c.widen(),
        T::PRODUCTS_EXACT_IN_WIDE,
    ))
}

/// `n_t² − (n_i sin θ_i)²`; see [`snell_discriminant_from_sine_in`].
#[inline]
pub(crate) fn snell_discriminant_from_sine<T: Real>(n_t: T, n_i: T, sin_i: T) -> T {
    T::narrow(snell_discriminant_from_sine_in(
        n_t.widen(),
        n_i.widen(),
        sin_i.widen(),
        T::PRODUCTS_EXACT_IN_WIDE,
    ))
}

/// Real part of `c² (n_t² + n_i²) − n_i²`; see [`brewster_factor_in`].
#[inline]
pub(crate) fn brewster_factor<T: Real>(x: T, y: T, n_i: T, c: T) -> T {
    T::narrow(brewster_factor_in(
        x.widen(),
        y.widen(),
        n_i.widen(),
        c.widen(),
        T::PRODUCTS_EXACT_IN_WIDE,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dekkers_product_error_is_the_fused_multiply_adds() {
        // Both are exact, so they agree bit for bit: over 2^±450 (products
        // far from underflow), and for products of widened f32s (error 0).
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
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
            let narrow = |x: f64, bits: u64| {
                (x / magnitude(bits) * 2f64.powi((bits % 120) as i32 - 60)) as f32
            };
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
    fn two_sum_and_two_prod_are_error_free() {
        // 1 + 2⁻⁶⁰ is not representable; the error term must hold the 2⁻⁶⁰.
        let tiny = 2f64.powi(-60);
        assert_eq!(two_sum(1.0, tiny), (1.0, tiny));
        // (1 + 2⁻³⁰)² = 1 + 2⁻²⁹ + 2⁻⁶⁰: the last term is the product's error.
        let a = 1.0 + 2f64.powi(-30);
        assert_eq!(two_prod(a, a), (1.0 + 2f64.powi(-29), tiny));
    }

    #[test]
    fn discriminant_keeps_digits_that_cancel() {
        // eta = 1 + 2⁻³⁰, c = 0: eta² − 1 = 2⁻²⁹ + 2⁻⁶⁰ exactly; the naive
        // form drops the 2⁻⁶⁰, the compensated one keeps it.
        let eta = 1.0 + 2f64.powi(-30);
        let exact = 2f64.powi(-29) + 2f64.powi(-60);
        assert_eq!(snell_discriminant(eta, 0.0, 1.0, 0.0), exact);
        assert_eq!(index_contrast(eta, 0.0, 1.0), exact);
        assert_ne!(eta * eta - 1.0, exact);
    }
}
