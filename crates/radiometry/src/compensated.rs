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
//! products are exact, so its results are limited only by the final rounding.
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
    (p, a.mul_add(b, -p))
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
fn square_of_product<T: Real>(a: T, b: T) -> [T; 3] {
    let (p, e) = two_prod(a, b);
    let (q, qe) = two_prod(p, p);
    let (m, me) = two_prod(p + p, e);
    [q, m, qe + me + e * e]
}

// The interface quantities below are written for light going from a medium
// of real index `n_i` into one of index `n_t = x + i·y` (`y = 0` for a
// dielectric). The crate always has one of the two indices equal to 1, so no
// ratio of indices is ever rounded.

/// `x² − y² − n_i²`, the real part of `n_t² − n_i²`.
#[inline]
fn index_contrast_in<T: Real>(x: T, y: T, n_i: T) -> T {
    let (x2, x2e) = two_prod(x, x);
    let (y2, y2e) = two_prod(y, y);
    let (i2, i2e) = two_prod(n_i, n_i);
    sum([x2, -i2, -y2, x2e, -i2e, -y2e])
}

/// `x² − y² − n_i² + (n_i c)²`, the real part of `n_t² − n_i² sin²θ_i`
/// (`= n_t² cos²θ_t`), which vanishes at the critical angle.
#[inline]
fn snell_discriminant_in<T: Real>(x: T, y: T, n_i: T, c: T) -> T {
    let (x2, x2e) = two_prod(x, x);
    let (y2, y2e) = two_prod(y, y);
    let (i2, i2e) = two_prod(n_i, n_i);
    let [ic2, ic2m, ic2e] = square_of_product(n_i, c);
    sum([x2, -i2, ic2, -y2, ic2m, x2e, -i2e, ic2e, -y2e])
}

/// `n_t² − (n_i s)²` for a dielectric (`n_t` real), `= n_t² cos²θ_t` with
/// `s = sin θ_i`: Snell's discriminant from the sine.
#[inline]
fn snell_discriminant_from_sine_in<T: Real>(n_t: T, n_i: T, s: T) -> T {
    let (t2, t2e) = two_prod(n_t, n_t);
    let [is2, is2m, is2e] = square_of_product(n_i, s);
    sum([t2, -is2, t2e, -is2m, -is2e])
}

/// `(c x)² − (c y)² + (c n_i)² − n_i²`, the real part of
/// `c² (n_t² + n_i²) − n_i²`, which vanishes at Brewster's angle.
#[inline]
fn brewster_factor_in<T: Real>(x: T, y: T, n_i: T, c: T) -> T {
    let [cx2, cx2m, cx2e] = square_of_product(c, x);
    let [cy2, cy2m, cy2e] = square_of_product(c, y);
    let [ci2, ci2m, ci2e] = square_of_product(c, n_i);
    let (i2, i2e) = two_prod(n_i, n_i);
    sum([
        cx2, -cy2, ci2, -i2, cx2m, -cy2m, ci2m, cx2e, -cy2e, ci2e, -i2e,
    ])
}

/// Real part of `n_t² − n_i²`, `n_t = x + i·y`; see [`index_contrast_in`].
#[inline]
pub(crate) fn index_contrast<T: Real>(x: T, y: T, n_i: T) -> T {
    T::narrow(index_contrast_in(x.widen(), y.widen(), n_i.widen()))
}

/// Real part of `n_t² − n_i² sin²θ_i`; see [`snell_discriminant_in`].
#[inline]
pub(crate) fn snell_discriminant<T: Real>(x: T, y: T, n_i: T, c: T) -> T {
    T::narrow(snell_discriminant_in(
        x.widen(),
        y.widen(),
        n_i.widen(),
        c.widen(),
    ))
}

/// `n_t² − (n_i sin θ_i)²`; see [`snell_discriminant_from_sine_in`].
#[inline]
pub(crate) fn snell_discriminant_from_sine<T: Real>(n_t: T, n_i: T, sin_i: T) -> T {
    T::narrow(snell_discriminant_from_sine_in(
        n_t.widen(),
        n_i.widen(),
        sin_i.widen(),
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
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

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
