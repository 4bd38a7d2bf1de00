//! Error-free transformations for the few sums where the laws cancel.
//!
//! Near the critical angle `eta² − 1 + cos²θ` is a difference of nearly equal
//! numbers, and near Brewster's angle so is `cos²θ (eta² + 1) − 1`. Evaluated
//! naively each loses as many digits as cancel (all of them within 1e-12 rad
//! of the critical angle). Here every product is split exactly into a rounded
//! value and its rounding error (`two_prod`, via a fused multiply-add) and
//! the terms are summed with their errors carried along (`two_sum`), so the
//! result is as accurate as if it had been computed in twice the working
//! precision and rounded once.
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

/// `(a · b)²` as an unevaluated sum `hi + lo`, accurate to about `ε²`.
#[inline]
fn square_of_product<T: Real>(a: T, b: T) -> (T, T) {
    let (p, pe) = two_prod(a, b);
    let (q, qe) = two_prod(p, p);
    (q, qe + (p + p) * pe)
}

/// `x² − y² − 1 + c²` for the real part of `eta² − 1 + cos²θ` with a complex
/// index `eta = x + i·y` (`y = 0` for a dielectric).
#[inline]
pub(crate) fn eta2_minus_1_plus_c2<T: Real>(x: T, y: T, c: T) -> T {
    let (x2, x2e) = two_prod(x, x);
    let (y2, y2e) = two_prod(y, y);
    let (c2, c2e) = two_prod(c, c);
    sum([x2, -T::one(), c2, -y2, x2e, c2e, -y2e])
}

/// `x² − y² − 1`, the real part of `eta² − 1` with `eta = x + i·y`.
#[inline]
pub(crate) fn eta2_minus_1<T: Real>(x: T, y: T) -> T {
    let (x2, x2e) = two_prod(x, x);
    let (y2, y2e) = two_prod(y, y);
    sum([x2, -T::one(), -y2, x2e, -y2e])
}

/// `c²(x² − y² + 1) − 1`, the real part of `cos²θ (eta² + 1) − 1`, which
/// vanishes at Brewster's angle for a dielectric.
#[inline]
pub(crate) fn brewster_factor<T: Real>(x: T, y: T, c: T) -> T {
    let (cx2, cx2e) = square_of_product(c, x);
    let (cy2, cy2e) = square_of_product(c, y);
    let (c2, c2e) = two_prod(c, c);
    sum([cx2, -cy2, c2, -T::one(), cx2e, -cy2e, c2e])
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
        assert_eq!(eta2_minus_1_plus_c2(eta, 0.0, 0.0), exact);
        assert_eq!(eta2_minus_1(eta, 0.0), exact);
        assert_ne!(eta * eta - 1.0, exact);
    }
}
