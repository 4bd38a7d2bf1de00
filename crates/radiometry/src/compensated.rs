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
//! The Fresnel laws evaluate in the tier's wide precision ([`Real::Wide`],
//! `f64` for both tiers) and round once at the end, so the `f32` tier's
//! results are limited only by that rounding. Its products are exact in
//! `f64` ([`Real::PRODUCTS_EXACT_IN_WIDE`]): their error terms are zero and
//! are neither computed nor summed, and what is left to compensate is the
//! square of a product of two of them (96 bits), split by Dekker's method.
//! The sums still cancel there: summed plainly in `f64`, R near the
//! critical angle and R_p near Brewster's angle miss by 10 to 25 `f32`
//! ulps (`cargo test -p radiometry --test precision_tiers`, which scans the
//! `f32` cosines around both angles).
//!
//! `two_prod` takes a product's rounding error by a fused multiply-add where
//! the target has the instruction, and by Dekker's splitting otherwise: the
//! default x86-64 target has no FMA, so `mul_add` would be a call into libm
//! for every product, the cost of the whole law. Both give the exact error
//! (Dekker's for operands below `2^995` in magnitude, whose splitting cannot
//! overflow; larger ones are split scaled down by a power of two), so the
//! results are the same bits on every target. No branch is taken on the
//! way, so loops over the laws vectorise.
//!
//! Reference: T. Ogita, S. M. Rump, S. Oishi, "Accurate sum and dot product",
//! SIAM J. Sci. Comput. 26(6), 2005 (algorithms TwoSum, TwoProduct, Sum2).

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use crate::Real;

/// `a + b` as `(s, e)` with `s = fl(a + b)` and `a + b = s + e` exactly.
#[inline(always)]
fn two_sum<T: Real>(a: T, b: T) -> (T, T) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

/// `a + b` as `(s, e)` with `s = fl(a + b)` and, where `|a| ≥ |b|`,
/// `a + b = s + e` exactly (Dekker's Fast2Sum, three operations where
/// [`two_sum`] takes six).
#[inline(always)]
fn fast_two_sum<T: Real>(a: T, b: T) -> (T, T) {
    let s = a + b;
    (s, b - (s - a))
}

/// `a · b` as `(p, e)` with `p = fl(a · b)` and `a · b = p + e` exactly
/// (barring underflow).
#[inline(always)]
fn two_prod<T: Real>(a: T, b: T) -> (T, T) {
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
fn scaled_dekker_error<T: Real>(a: T, b: T, p: T) -> T {
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

/// `2^k` for a normal double's exponent, from the bits: a constant where
/// `powi` is a call that blocks a loop's vectorisation.
pub(crate) const fn power_of_two(k: i32) -> f64 {
    f64::from_bits(((1023 + k) as u64) << 52)
}

/// The rounding error of `p = fl(a · b)` by Dekker's product (1971): each
/// operand split into halves of at most half the significand, whose four
/// products are exact. Exact for `|a|, |b| < 2^995` barring underflow.
#[inline(always)]
fn dekker_error<T: Real>(a: T, b: T, p: T) -> T {
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
fn exact_error<T: Real, const FUSED: bool>(a: T, b: T, p: T) -> T {
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
fn narrow_prod<T: Real>(a: T, b: T, exact: bool) -> (T, T) {
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
struct Sum2<T> {
    sum: T,
    error: T,
    /// Whether the tier's products are exact in the wide precision, so that
    /// their rounding errors are zero and are not added.
    exact: bool,
}

impl<T: Real> Sum2<T> {
    #[inline(always)]
    fn of(first: T, exact: bool) -> Self {
        Self {
            sum: first,
            error: T::zero(),
            exact,
        }
    }

    #[inline(always)]
    fn plus(self, term: T) -> Self {
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
    fn plus_error(self, term: T, exact: bool) -> Self {
        if exact && self.exact {
            self
        } else {
            self.plus(term)
        }
    }

    #[inline(always)]
    fn value(self) -> T {
        self.sum + self.error
    }

    /// The sum unevaluated, to be carried on.
    #[inline(always)]
    fn parts(self) -> TwoPart<T> {
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
fn square_of_product<T: Real>(a: T, b: T, exact: bool) -> [T; 3] {
    let (p, e) = narrow_prod(a, b, exact);
    if exact {
        let q = p * p;
        return [q, T::zero(), dekker_error(p, p, q)];
    }
    let (q, qe) = two_prod(p, p);
    let (m, me) = two_prod(p + p, e);
    [q, m, qe + me + e * e]
}

// The interface quantities below are written for light going from a medium
// of real index `n_i` into one of real index `n_t` (a dielectric). The crate
// always has one of the two indices equal to 1, so no ratio of indices is
// ever rounded. Each sums its terms in one fixed order (large terms first,
// then the rounding errors), skipping the ones that are zero by
// construction.
//
// Where the tier's products are exact in the wide precision the sums need
// less than Sum2: each cancels in one place only, between two terms whose
// values are exact (squares of narrow numbers, or a `two_sum`'s result), and
// two such terms within a factor of two of each other subtract exactly
// (Sterbenz's lemma). So the large terms are added exactly where they
// cancel, the error terms (a square's low part, a `two_sum`'s error) are
// added after, and what is rounded is the small result, once or twice:
// within about one ulp of the wide precision, whatever cancels.

/// `n_t² − (n_i s)²` `= n_t² cos²θ_t` with `s = sin θ_i`: Snell's
/// discriminant from the sine.
#[inline(always)]
pub(crate) fn snell_discriminant_from_sine<T: Real>(n_t: T, n_i: T, s: T, exact: bool) -> T {
    if exact {
        // n_t² and the square's high part cancel at the critical angle,
        // exactly.
        let [is2, _, is2e] = square_of_product(n_i, s, exact);
        return (n_t * n_t - is2) - is2e;
    }
    let (t2, t2e) = narrow_prod(n_t, n_t, exact);
    let [is2, is2m, is2e] = square_of_product(n_i, s, exact);
    Sum2::of(t2, exact)
        .plus(-is2)
        .plus_error(t2e, exact)
        .plus_error(-is2m, exact)
        .plus(-is2e)
        .value()
}

// A dielectric's index `η` is fixed per material, and one of the two
// indices of its interface is 1 (crate conventions): from the outside
// `n_i = 1`, `n_t = η`; from the inside `n_i = η`, `n_t = 1`. So the
// squares the laws need at every angle, `η²`, `η² − 1` and `η² + 1`, are
// summed once per material ([`IndexSquares`]), each angle adds its own
// `c²` terms to them, and the only products taken per angle are `c · c`,
// `η² · c²` and `(η² + 1) · c²`, where the interface as `(n_i, n_t)` took a
// dozen. Each result cancels in one place only, between two high parts
// within a factor of two of each other, which subtract exactly (Sterbenz's
// lemma); the low parts are added after, so what is rounded is the small
// result: within a few ulps of the wide precision, whatever cancels.
//
// Where the tier's products are exact in the wide precision (`f32` in
// `f64`), both `η² · c²` and `(η² + 1) · c² = (η c)² + c²` come from one
// product, `η c`, exact, squared in two parts with its exact error
// ([`square_of_narrow_product`]); Brewster's factor is then
// `(η c)² + (c² − n_i²)`, the difference carried by Fast2Sum: three
// operations with a fused multiply-add (thirteen without) and three,
// where the two products with their errors by Dekker's method took
// thirty-eight.

/// The squares of a dielectric's index `η = n_inside / n_outside` that its
/// laws take at every angle, each carried unevaluated as if in twice the
/// precision, computed once per material.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct IndexSquares<T> {
    /// `η` itself: a narrow tier's laws square `η c` rather than multiply
    /// `η²` by `c²` ([`square_of_narrow_product`]).
    eta: T,
    /// `η²`: `n_i²` from the inside.
    eta2: TwoPart<T>,
    /// `η² − 1`: Snell's contrast `n_t² − n_i²` from the outside, negated
    /// from the inside.
    minus_one: TwoPart<T>,
    /// `η² + 1 = n_t² + n_i²` from either side: Brewster's factor is
    /// `c² (η² + 1) − n_i²`.
    plus_one: TwoPart<T>,
}

impl<T: Real> IndexSquares<T> {
    /// The squares of `eta`, in the wide precision of a tier whose products
    /// are `exact` there or not.
    #[inline(always)]
    pub(crate) fn of(eta: T, exact: bool) -> Self {
        let (e2, e2e) = narrow_prod(eta, eta, exact);
        Self {
            eta,
            eta2: TwoPart { high: e2, low: e2e },
            minus_one: square_plus(eta, -T::one(), exact),
            plus_one: square_plus(eta, T::one(), exact),
        }
    }

    /// `n_t² − n_i²`: `η² − 1` from the outside, `1 − η²` from the inside.
    #[inline(always)]
    pub(crate) fn contrast(&self, inside: bool) -> TwoPart<T> {
        let k = self.minus_one;
        if inside {
            TwoPart {
                high: -k.high,
                low: -k.low,
            }
        } else {
            k
        }
    }

    /// `η`, widened.
    #[inline(always)]
    pub(crate) fn eta(&self) -> T {
        self.eta
    }

    /// `n_t²` rounded to the wide precision: `η²` from the outside, 1
    /// from the inside.
    #[inline(always)]
    pub(crate) fn transmitted(&self, inside: bool) -> T {
        if inside {
            T::one()
        } else {
            self.eta2.high
        }
    }

    /// `n_i²`: 1 from the outside, `η²` from the inside.
    #[inline(always)]
    fn incident(&self, inside: bool) -> TwoPart<T> {
        if inside {
            self.eta2
        } else {
            TwoPart {
                high: T::one(),
                low: T::zero(),
            }
        }
    }
}

/// `x² + k` for an exact constant `k` (±1).
#[inline(always)]
fn square_plus<T: Real>(x: T, k: T, exact: bool) -> TwoPart<T> {
    let (x2, x2e) = narrow_prod(x, x, exact);
    Sum2::of(x2, exact).plus(k).plus_error(x2e, exact).parts()
}

/// `c²` for `0 ≤ c ≤ 1`, exact as two parts (no range check: `c` is far
/// below Dekker's limit).
#[inline(always)]
fn unit_square<T: Real>(c: T, exact: bool) -> TwoPart<T> {
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
fn times_square<T: Real, const FUSED: bool>(
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

/// `n_t² − n_i² + n_i² c²` `= n_t² − n_i² sin²θ_i = n_t² cos²θ_t` at
/// `c = |cos θ_i|`, from the side `inside` or not: Snell's discriminant,
/// which vanishes at the critical angle. `FUSED`: [`exact_error`]'s, for
/// a tier whose products are `exact`.
#[inline(always)]
pub(crate) fn snell_discriminant<T: Real, const FUSED: bool>(
    squares: &IndexSquares<T>,
    inside: bool,
    c: T,
    exact: bool,
) -> T {
    let c2 = unit_square(c, exact);
    let x = if inside {
        if exact {
            square_of_narrow_product::<T, FUSED>(squares.eta, c)
        } else {
            times_square::<T, FUSED>(squares.eta2, c2, exact)
        }
    } else {
        c2
    };
    let k = squares.contrast(inside);
    let d = (k.high + x.high) + (x.low + k.low);
    // From the inside at normal incidence d = n_t² = 1 exactly. Beyond
    // η ≈ 1.27e16 (η² ≈ 2^107) the two parts of 1 − η² no longer hold
    // its 1 (the part below η²'s rounding is a double whose ulp exceeds
    // 1), and the sum gives 0: cos θ_t = 0 and R_p = 0 where both are 1.
    // There no cosine below 1 transmits (sin θ_c = 1/η, and the largest
    // cosine below 1 has a sine of 1.5e-8), so that one input is chosen
    // by value, not branched around. A tier whose products are exact in
    // the wide precision stops at η = 1e9 (`domain::INDEX_RANGE_F32`).
    if !exact && inside && c == T::one() {
        T::one()
    } else {
        d
    }
}

/// `c² (n_t² + n_i²) − n_i²` at `c = |cos θ_i|`, from the side `inside` or
/// not: Brewster's factor, which vanishes at Brewster's angle. `FUSED`:
/// [`exact_error`]'s, for a tier whose products are `exact`.
#[inline(always)]
pub(crate) fn brewster_factor<T: Real, const FUSED: bool>(
    squares: &IndexSquares<T>,
    inside: bool,
    c: T,
    exact: bool,
) -> T {
    if exact {
        // (η c)² + (c² − n_i²): the square split exactly, the difference
        // carried with its rounding error, the large parts added first
        // (they cancel at Brewster's angle, exactly). The error is taken
        // by Fast2Sum, exact where `n_i² ≥ c²`: from the outside always
        // (n_i = 1), from the inside wherever the factor can vanish
        // (`c_B = η / √(1 + η²) < η`); elsewhere it is a rounding-sized
        // term beside a factor far from zero.
        let p2 = square_of_narrow_product::<T, FUSED>(squares.eta, c);
        let (m, me) = fast_two_sum(-squares.incident(inside).high, c * c);
        return (p2.high + m) + (p2.low + me);
    }
    let m = times_square::<T, FUSED>(squares.plus_one, unit_square(c, exact), exact);
    let n_i2 = squares.incident(inside);
    let factor = (m.high - n_i2.high) + (m.low - n_i2.low);
    // From the inside at normal incidence the factor is n_t² = 1 exactly,
    // which the two parts of η² + 1 and η² lose beyond η ≈ 1.27e16, as
    // `snell_discriminant`'s do.
    if inside && c == T::one() {
        T::one()
    } else {
        factor
    }
}

/// `(a b)²` for `a`, `b` widened from a tier whose products are exact in
/// the wide precision, exactly, as an unevaluated sum: `p = a b` is exact
/// (a product of two narrow numbers has at most 48 bits), its square is
/// rounded once and the rounding error taken exactly ([`exact_error`]).
/// Three operations where the path fuses a multiply-add, thirteen by
/// Dekker's split elsewhere, the same bits on both; `η² · c²` (two 48-bit
/// squares) with its error by Dekker's method took nineteen.
#[inline(always)]
fn square_of_narrow_product<T: Real, const FUSED: bool>(a: T, b: T) -> TwoPart<T> {
    let p = a * b;
    let high = p * p;
    TwoPart {
        high,
        low: exact_error::<T, FUSED>(p, p, high),
    }
}

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

#[cfg(test)]
mod tests;
