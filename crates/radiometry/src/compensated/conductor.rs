//! The interface quantities of a conductor, where its law cancels: the
//! real parts of Snell's discriminant and Brewster's factor, from a
//! material's constants summed once.

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use super::error_free::{narrow_prod, times_square, two_prod, unit_square, Sum2, TwoPart};
use crate::Real;

// A conductor's index `η = x + i·y` is fixed per material, so the parts of
// its law that do not depend on the angle are summed once, as [`TwoPart`]s,
// and each angle adds `c²` to them.

/// `x² − y² + k` for an exact constant `k` (−1, 0 or 1): the real part of
/// `η² − 1`, `η²` or `η² + 1`.
#[inline(always)]
pub(crate) fn squares_plus<T: Real>(x: T, y: T, k: T, exact: bool) -> TwoPart<T> {
    let (x2, x2e) = narrow_prod(x, x, exact);
    let (y2, y2e) = narrow_prod(y, y, exact);
    Sum2::of(x2, exact)
        .plus(k)
        .plus(-y2)
        .plus_error(x2e, exact)
        .plus_error(-y2e, exact)
        .parts()
}

/// `C + c²` for `C` the real part of `η² − 1` ([`squares_plus`]): the real
/// part of `η² − sin²θ_i = η² cos²θ_t`, Snell's discriminant from a medium
/// of index 1, which vanishes at a near-critical angle when `κ` is small.
#[inline(always)]
pub(crate) fn discriminant_from<T: Real>(contrast: TwoPart<T>, c: T, exact: bool) -> T {
    let c2 = unit_square(c, exact);
    if exact {
        // c² is exact, and cancels the contrast's high part exactly.
        return (contrast.high + c2.high) + contrast.low;
    }
    Sum2::of(contrast.high, exact)
        .plus(c2.high)
        .plus(contrast.low)
        .plus(c2.low)
        .value()
}

/// `c² A − 1` for `A` the real part of `η² + 1` ([`squares_plus`]): the real
/// part of Brewster's factor `c² (η² + 1) − 1`, which vanishes near
/// Brewster's angle when `κ` is small. With `c² = q + e`, the products
/// `q · A_high` (split exactly), `q · A_low` and `e · A_high` are summed;
/// the `ε²`-small rest is dropped. `FUSED`: [`exact_error`]'s, for a tier
/// whose products are `exact`.
#[inline(always)]
pub(crate) fn brewster_from<T: Real, const FUSED: bool>(a: TwoPart<T>, c: T, exact: bool) -> T {
    let c2 = unit_square(c, exact);
    if exact {
        // c² is exact; m = c² A_high is split exactly, and cancels the 1
        // exactly.
        let m = times_square::<T, FUSED>(a, c2, exact);
        return (m.high - T::one()) + m.low;
    }
    // Summed in full, not in the dielectric's short form, which rounds
    // twice where nothing cancels: a metal's R_p, the square of this
    // factor's modulus, would carry both roundings.
    let (m, me) = two_prod(c2.high, a.high);
    Sum2::of(m, exact)
        .plus(-T::one())
        .plus(me)
        .plus(c2.high * a.low)
        .plus(c2.low * a.high)
        .value()
}
