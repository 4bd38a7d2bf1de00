//! The two small steps every Fresnel law shares: a square, and a fraction
//! clamped against rounding.

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use crate::Real;

#[inline]
pub(super) fn sqr<T: Real>(x: T) -> T {
    x * x
}

/// Clamps a fraction into `[0, 1]` against rounding, keeping NaN.
#[inline]
pub(super) fn fraction<T: Real>(x: T) -> T {
    if x > T::one() {
        T::one()
    } else {
        x
    }
}
