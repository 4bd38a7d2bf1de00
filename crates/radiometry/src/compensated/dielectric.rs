//! The interface quantities of a dielectric, where the laws cancel:
//! Snell's discriminant and Brewster's factor, summed from a material's
//! index squares computed once.

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use super::error_free::{
    fast_two_sum, narrow_prod, square_of_narrow_product, square_of_product, square_plus,
    times_square, unit_square, Sum2, TwoPart,
};
use crate::Real;

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
