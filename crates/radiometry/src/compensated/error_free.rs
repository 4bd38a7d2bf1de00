//! The error-free transformations (TwoSum, TwoProduct by a fused
//! multiply-add or Dekker's splitting), the sum carried in two parts
//! (Sum2), and the squares and products of two parts that the interface
//! quantities are summed from.

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use crate::real::power_of_two;
use crate::Real;

/// `a + b` as `(s, e)` with `s = fl(a + b)` and `a + b = s + e` exactly.
#[inline(always)]
pub(super) fn two_sum<T: Real>(a: T, b: T) -> (T, T) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

/// `a + b` as `(s, e)` with `s = fl(a + b)` and, where `|a| ≥ |b|`,
/// `a + b = s + e` exactly (Dekker's Fast2Sum, three operations where
/// [`two_sum`] takes six).
#[inline(always)]
pub(super) fn fast_two_sum<T: Real>(a: T, b: T) -> (T, T) {
    let s = a + b;
    (s, b - (s - a))
}

/// `a · b` as `(p, e)` with `p = fl(a · b)` and `a · b = p + e` exactly
/// (barring underflow).
#[inline(always)]
pub(super) fn two_prod<T: Real>(a: T, b: T) -> (T, T) {
    let p = a * b;
    if cfg!(target_feature = "fma") {
        return (p, a.mul_add(b, -p));
    }
    (p, scaled_dekker_error(a, b, p))
}

/// [`dekker_error`] for any operands: one of `2^995` or more in magnitude
/// (whose splitting would overflow) is scaled down by `2^-64` first and the
/// error scaled back, exactly, as powers of two scale exactly (the scaled
/// product stays far from underflow: with `|a| ≥ 2^995`, `|a b| ≥ 2^-79`).
/// The scale is chosen by value, not by branch, so that loops vectorise.
#[inline(always)]
pub(super) fn scaled_dekker_error<T: Real>(a: T, b: T, p: T) -> T {
    let limit = T::lit(power_of_two(995));
    let (one, down, up) = (
        T::one(),
        T::lit(power_of_two(-64)),
        T::lit(power_of_two(64)),
    );
    // Each scale with its inverse, so that the error is scaled back by a
    // multiplication: the same value as dividing (both exact), without the
    // division, the slowest step there is.
    let scale = |x: T| {
        if x.abs() < limit {
            (one, one)
        } else {
            (down, up)
        }
    };
    let ((sa, ua), (sb, ub)) = (scale(a), scale(b));
    let scaled = dekker_error(a * sa, b * sb, p * sa * sb);
    scaled * ua * ub
}

/// The rounding error of `p = fl(a · b)` by Dekker's product (1971): each
/// operand split into halves of at most half the significand, whose four
/// products are exact. Exact for `|a|, |b| < 2^995` barring underflow.
#[inline(always)]
pub(super) fn dekker_error<T: Real>(a: T, b: T, p: T) -> T {
    let split = |x: T| {
        let c = T::lit(T::SPLITTER) * x;
        let high = c - (c - x);
        (high, x - high)
    };
    let ((ah, al), (bh, bl)) = (split(a), split(b));
    ((ah * bh - p) + ah * bl + al * bh) + al * bl
}

/// The rounding error of `p = fl(a · b)`, exactly, for operands in
/// Dekker's range whose error does not underflow (a narrow tier's numbers
/// and their products, widened): one fused multiply-add where the
/// instructions the caller is compiled for have it (`FUSED`, fixed per
/// compiled path: the slice laws' AVX2 and AVX-512 loops), Dekker's
/// product otherwise. The error is a number, not a rounding, so both give
/// the same bits; the fused one takes one operation where Dekker's takes
/// eleven.
#[inline(always)]
pub(super) fn exact_error<T: Real, const FUSED: bool>(a: T, b: T, p: T) -> T {
    if FUSED {
        a.mul_add(b, -p)
    } else {
        dekker_error(a, b, p)
    }
}

/// [`two_prod`] of two numbers widened from a tier whose products are exact
/// in the wide one (`exact`, a constant per tier): the error term is zero,
/// and is not computed.
#[inline(always)]
pub(super) fn narrow_prod<T: Real>(a: T, b: T, exact: bool) -> (T, T) {
    if exact {
        (a * b, T::zero())
    } else {
        two_prod(a, b)
    }
}

/// A sum carried as if in twice the working precision (Sum2): each term
/// added with [`two_sum`], the errors gathered apart. Terms that are zero by
/// construction (a tier's exact products' errors, the imaginary part of a
/// real index) are not added at all, which changes no value: adding an
/// exact zero is exact.
#[derive(Clone, Copy)]
pub(super) struct Sum2<T> {
    sum: T,
    error: T,
    /// Whether the tier's products are exact in the wide precision, so that
    /// their rounding errors are zero and are not added.
    exact: bool,
}

impl<T: Real> Sum2<T> {
    #[inline(always)]
    pub(super) fn of(first: T, exact: bool) -> Self {
        Self {
            sum: first,
            error: T::zero(),
            exact,
        }
    }

    #[inline(always)]
    pub(super) fn plus(self, term: T) -> Self {
        let (sum, e) = two_sum(self.sum, term);
        Self {
            sum,
            error: self.error + e,
            ..self
        }
    }

    /// Adds a product's rounding error, which is zero when the tier's
    /// products are `exact`.
    #[inline(always)]
    pub(super) fn plus_error(self, term: T, exact: bool) -> Self {
        if exact && self.exact {
            self
        } else {
            self.plus(term)
        }
    }

    #[inline(always)]
    pub(super) fn value(self) -> T {
        self.sum + self.error
    }

    /// The sum unevaluated, to be carried on.
    #[inline(always)]
    pub(super) fn parts(self) -> TwoPart<T> {
        TwoPart {
            high: self.sum,
            low: self.error,
        }
    }
}

/// A number carried as the unevaluated sum `high + low`, as accurate as
/// twice the working precision: a constant of a material that a law uses
/// at every angle, computed once.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct TwoPart<T> {
    pub(crate) high: T,
    pub(crate) low: T,
}

impl<T: Real> TwoPart<T> {
    /// Rounded to one number.
    #[inline(always)]
    pub(crate) fn value(self) -> T {
        self.high + self.low
    }
}

/// `(a · b)²` as an unevaluated sum `[high, middle, low]`, exact to about
/// `ε³` relative: with `a b = p + e` exactly, `(a b)² = p² + 2pe + e²`, and
/// the first two products are split again. Where the tier's products are
/// `exact`, `e = 0`, the middle term is zero and `p` (a product of two
/// widened numbers of the narrow tier, below `2^256`) is split without the
/// range check.
#[inline(always)]
pub(super) fn square_of_product<T: Real>(a: T, b: T, exact: bool) -> [T; 3] {
    let (p, e) = narrow_prod(a, b, exact);
    if exact {
        let q = p * p;
        return [q, T::zero(), dekker_error(p, p, q)];
    }
    let (q, qe) = two_prod(p, p);
    let (m, me) = two_prod(p + p, e);
    [q, m, qe + me + e * e]
}

/// `x² + k` for an exact constant `k` (±1).
#[inline(always)]
pub(super) fn square_plus<T: Real>(x: T, k: T, exact: bool) -> TwoPart<T> {
    let (x2, x2e) = narrow_prod(x, x, exact);
    Sum2::of(x2, exact).plus(k).plus_error(x2e, exact).parts()
}

/// `c²` for `0 ≤ c ≤ 1`, exact as two parts (no range check: `c` is far
/// below Dekker's limit).
#[inline(always)]
pub(super) fn unit_square<T: Real>(c: T, exact: bool) -> TwoPart<T> {
    let high = c * c;
    let low = if exact {
        T::zero()
    } else if cfg!(target_feature = "fma") {
        c.mul_add(c, -high)
    } else {
        dekker_error(c, c, high)
    };
    TwoPart { high, low }
}

/// `k · c²` for a material's constant `k` and an angle's `c²`, to about
/// `ε²` relative: the high parts' product split exactly, the cross terms
/// added, the product of the low parts (`ε²` smaller) dropped. Low parts
/// that are zero by construction where the tier's products are `exact`
/// (`c²`'s) are not added.
#[inline(always)]
pub(super) fn times_square<T: Real, const FUSED: bool>(
    k: TwoPart<T>,
    c2: TwoPart<T>,
    exact: bool,
) -> TwoPart<T> {
    let high = k.high * c2.high;
    // A narrow tier's constants lie below 2^256, in Dekker's range, and
    // their products with c² far above underflow.
    let error = if exact {
        exact_error::<T, FUSED>(k.high, c2.high, high)
    } else {
        two_prod(k.high, c2.high).1
    };
    let low = if exact {
        error + k.low * c2.high
    } else {
        error + (k.high * c2.low + k.low * c2.high)
    };
    TwoPart { high, low }
}

/// `(a b)²` for `a`, `b` widened from a tier whose products are exact in
/// the wide precision, exactly, as an unevaluated sum: `p = a b` is exact
/// (a product of two narrow numbers has at most 48 bits), its square is
/// rounded once and the rounding error taken exactly ([`exact_error`]).
/// Three operations where the path fuses a multiply-add, thirteen by
/// Dekker's split elsewhere, the same bits on both; `η² · c²` (two 48-bit
/// squares) with its error by Dekker's method took nineteen.
#[inline(always)]
pub(super) fn square_of_narrow_product<T: Real, const FUSED: bool>(a: T, b: T) -> TwoPart<T> {
    let p = a * b;
    let high = p * p;
    TwoPart {
        high,
        low: exact_error::<T, FUSED>(p, p, high),
    }
}
