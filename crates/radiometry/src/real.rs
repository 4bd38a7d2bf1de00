//! The two precision tiers, `f32` and `f64`, and their 3-vectors.

use core::fmt::{Debug, Display};
use core::ops::{Add, Mul, Neg, Sub};

use num_traits::{Float, FloatConst, Zero};

/// A floating-point scalar the laws are written over: `f32` or `f64`.
pub trait Real: Float + FloatConst + Debug + Display + Default + Send + Sync + 'static {
    /// The precision in which the few sums that cancel are carried (in
    /// twice *its* precision): `f64` for both tiers. Products of `f32`s are
    /// exact in `f64`, so the `f32` tier gets those sums essentially exact.
    type Wide: Real;
    /// Converts a literal `f64` constant (rounding once for `f32`).
    fn lit(x: f64) -> Self;
    /// Converts exactly into [`Real::Wide`].
    fn widen(self) -> Self::Wide;
    /// Rounds from [`Real::Wide`] once.
    fn narrow(wide: Self::Wide) -> Self;
    /// The spacing of this tier's numbers in the binade of `x` (its unit in
    /// the last place there), down to the tier's smallest subnormal, as an
    /// `f64`: the unit every accuracy statement of the workspace counts in.
    /// `x` is an exact value, not yet rounded to the tier, so the binade is
    /// `x`'s own even where rounding would carry it to the next power of two.
    ///
    /// ```
    /// use radiometry::Real;
    /// assert_eq!(f32::ulp_at(1.0), f64::from(f32::EPSILON));
    /// assert_eq!(f64::ulp_at(0.75), f64::EPSILON / 2.0);
    /// assert_eq!(f64::ulp_at(0.0), f64::from_bits(1)); // the smallest subnormal
    /// ```
    fn ulp_at(x: f64) -> f64;
    /// Whether a product of two of this tier's numbers is exact in
    /// [`Real::Wide`]: `true` for `f32` (24 + 24 bits fit `f64`'s 53), so
    /// the compensated sums skip the error terms that are then zero.
    const PRODUCTS_EXACT_IN_WIDE: bool;
    /// Dekker's splitting constant `2^⌈p/2⌉ + 1` for this tier's `p`-bit
    /// significand: `a · SPLITTER` splits `a` into two halves whose products
    /// are exact.
    const SPLITTER: f64;
    /// `√(self² + other²)`, without overflow or underflow on the way:
    /// `f32` squares and sums in `f64`, where neither can overflow, and
    /// rounds once more (within one rounding of the tier); `f64` scales by
    /// a power of two where it must (within about one ulp).
    fn hypotenuse(self, other: Self) -> Self;
    /// [`Real::hypotenuse`] of two values in [`Real::Wide`] computed from
    /// this tier's numbers by the laws (squares and products of a few of
    /// them): for `f32` those cannot overflow or underflow when squared in
    /// `f64`, so this is `√(a² + b²)` there, without the scaling.
    fn wide_hypotenuse(a: Self::Wide, b: Self::Wide) -> Self::Wide;
    /// `[a / x, b / y]` in [`Real::Wide`] for the positive denominators `x`,
    /// `y` of a law computed from this tier's numbers (sums of their squares
    /// and products, up to the fourth power of an index). `f32` divides
    /// once, by `x · y`, which cannot overflow or underflow in `f64` for
    /// such values, and multiplies: a few more roundings of `f64`, far
    /// below the one rounding to `f32`, for one division instead of two,
    /// the slowest step of the law. `f64` divides twice, rounding each
    /// quotient once.
    fn wide_quotients(
        a: Self::Wide,
        x: Self::Wide,
        b: Self::Wide,
        y: Self::Wide,
    ) -> [Self::Wide; 2];
    /// `[k / x, k b / y]` in [`Real::Wide`], for the same denominators as
    /// [`Real::wide_quotients`] and a numerator factor `k` they share.
    /// `f32` divides once, `k` by `x · y`, and multiplies: the factor rides
    /// in the division's numerator, two multiplications fewer than
    /// [`Real::wide_quotients`] of `k` and `k b`. `f64` divides twice,
    /// `k / x` and `(k b) / y`, as [`Real::wide_quotients`] does.
    fn wide_quotients_sharing(
        k: Self::Wide,
        x: Self::Wide,
        b: Self::Wide,
        y: Self::Wide,
    ) -> [Self::Wide; 2];
}

/// `2^⌊log₂|x|⌋`, no smaller than `min_positive`, times `epsilon`: the
/// spacing at `x` of a binary format with that machine epsilon and smallest
/// normal number. Built from the bits, which are exact where `powi` of a
/// large negative exponent would overflow on the way.
#[inline]
fn spacing(x: f64, epsilon: f64, min_positive: f64) -> f64 {
    const EXPONENT: u64 = 0x7ff << 52;
    // 0 for a subnormal x, whose spacing is the subnormals' anyway.
    let binade = f64::from_bits(x.abs().to_bits() & EXPONENT);
    binade.max(min_positive) * epsilon
}

impl Real for f32 {
    type Wide = f64;
    #[inline]
    fn lit(x: f64) -> Self {
        x as f32
    }
    #[inline]
    fn widen(self) -> f64 {
        self.into()
    }
    #[inline]
    fn narrow(wide: f64) -> Self {
        wide as f32
    }
    #[inline]
    fn ulp_at(x: f64) -> f64 {
        spacing(x, f32::EPSILON.into(), f32::MIN_POSITIVE.into())
    }
    const PRODUCTS_EXACT_IN_WIDE: bool = true;
    const SPLITTER: f64 = 4097.0;
    #[inline]
    fn hypotenuse(self, other: Self) -> Self {
        f32::wide_hypotenuse(self.into(), other.into()) as f32
    }
    #[inline]
    fn wide_hypotenuse(a: f64, b: f64) -> f64 {
        (a * a + b * b).sqrt()
    }
    #[inline]
    fn wide_quotients(a: f64, x: f64, b: f64, y: f64) -> [f64; 2] {
        let q = 1.0 / (x * y);
        [a * (y * q), b * (x * q)]
    }
    #[inline]
    fn wide_quotients_sharing(k: f64, x: f64, b: f64, y: f64) -> [f64; 2] {
        let q = k / (x * y);
        [y * q, b * (x * q)]
    }
}

impl Real for f64 {
    type Wide = f64;
    #[inline]
    fn lit(x: f64) -> Self {
        x
    }
    #[inline]
    fn widen(self) -> f64 {
        self
    }
    #[inline]
    fn narrow(wide: f64) -> Self {
        wide
    }
    #[inline]
    fn ulp_at(x: f64) -> f64 {
        spacing(x, f64::EPSILON, f64::MIN_POSITIVE)
    }
    const PRODUCTS_EXACT_IN_WIDE: bool = false;
    const SPLITTER: f64 = 134_217_729.0;
    #[inline]
    fn hypotenuse(self, other: Self) -> Self {
        // Scaled by a power of two (exact) only where a square could
        // overflow or lose bits to underflow; the rest is √(a² + b²), within
        // about one ulp, without the library call of `hypot`.
        let (a, b) = (self.abs(), other.abs());
        let larger = a.max(b);
        let (scale, unscale) = if larger > power_of_two(500) {
            (power_of_two(-600), power_of_two(600))
        } else if larger < power_of_two(-500) {
            (power_of_two(600), power_of_two(-600))
        } else {
            (1.0, 1.0)
        };
        let (a, b) = (a * scale, b * scale);
        (a * a + b * b).sqrt() * unscale
    }
    #[inline]
    fn wide_hypotenuse(a: f64, b: f64) -> f64 {
        a.hypotenuse(b)
    }
    #[inline]
    fn wide_quotients(a: f64, x: f64, b: f64, y: f64) -> [f64; 2] {
        [a / x, b / y]
    }
    #[inline]
    fn wide_quotients_sharing(k: f64, x: f64, b: f64, y: f64) -> [f64; 2] {
        [k / x, (k * b) / y]
    }
}

/// A 3-vector of [`Real`]s: `glam::Vec3` for `f32`, `glam::DVec3` for `f64`.
///
/// The laws that take directions are generic over this trait, so the same
/// code serves both precision tiers.
pub trait Vector3:
    Copy
    + Debug
    + PartialEq
    + Add<Output = Self>
    + Sub<Output = Self>
    + Neg<Output = Self>
    + Mul<<Self as Vector3>::Scalar, Output = Self>
{
    /// The scalar type of the components.
    type Scalar: Real;
    /// Builds a vector from its components.
    fn new(x: Self::Scalar, y: Self::Scalar, z: Self::Scalar) -> Self;
    /// The dot product.
    fn dot(self, other: Self) -> Self::Scalar;
    /// The cross product.
    fn cross(self, other: Self) -> Self;
    /// The components as an array.
    fn to_array(self) -> [Self::Scalar; 3];

    /// The Euclidean length.
    #[inline]
    fn length(self) -> Self::Scalar {
        self.dot(self).sqrt()
    }

    /// The unit vector along `self`, or `None` for a zero, infinite or NaN
    /// vector, which has no direction.
    #[inline]
    fn try_normalize(self) -> Option<Self> {
        let len = self.length();
        if len.is_finite() && len > Self::Scalar::zero() {
            // Dividing (not multiplying by 1/len) rounds once per component,
            // so (0, 3, 4) normalises to exactly (0, 0.6, 0.8).
            let [x, y, z] = self.to_array();
            Some(Self::new(x / len, y / len, z / len))
        } else {
            None
        }
    }
}

macro_rules! impl_vector3 {
    ($vec:ty, $scalar:ty) => {
        impl Vector3 for $vec {
            type Scalar = $scalar;
            #[inline]
            fn new(x: $scalar, y: $scalar, z: $scalar) -> Self {
                <$vec>::new(x, y, z)
            }
            #[inline]
            fn dot(self, other: Self) -> $scalar {
                <$vec>::dot(self, other)
            }
            #[inline]
            fn cross(self, other: Self) -> Self {
                <$vec>::cross(self, other)
            }
            #[inline]
            fn to_array(self) -> [$scalar; 3] {
                <$vec>::to_array(&self)
            }
        }
    };
}

impl_vector3!(glam::Vec3, f32);
impl_vector3!(glam::DVec3, f64);

/// `2^k` for a normal double's exponent, from the bits: a constant where
/// `powi` is a call that blocks a loop's vectorisation.
pub(crate) const fn power_of_two(k: i32) -> f64 {
    f64::from_bits(((1023 + k) as u64) << 52)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ulp_at_is_the_float32_spacing() {
        assert_eq!(f32::ulp_at(1.0), f32::EPSILON as f64);
        assert_eq!(f32::ulp_at(0.75), f32::EPSILON as f64 / 2.0);
        assert_eq!(f32::ulp_at(0.0), 2f64.powi(-149));
        assert_eq!(f32::ulp_at(-1.0), f32::EPSILON as f64);
        for x in [1e-40f32, f32::MIN_POSITIVE, 0.04, 3.0, 1e30] {
            let spacing = f64::from(x.next_up()) - f64::from(x);
            assert_eq!(f32::ulp_at(x.into()), spacing, "{x:e}");
        }
        // An exact value just below 1 is in the binade below, even though
        // it rounds to 1 in f32.
        assert_eq!(f32::ulp_at(1.0 - 1e-12), f32::EPSILON as f64 / 2.0);
    }

    #[test]
    fn ulp_at_is_the_double_spacing() {
        assert_eq!(f64::ulp_at(1.0), f64::EPSILON);
        assert_eq!(f64::ulp_at(0.75), f64::EPSILON / 2.0);
        assert_eq!(f64::ulp_at(0.0), f64::from_bits(1));
        assert_eq!(f64::ulp_at(f64::MIN_POSITIVE), f64::from_bits(1));
        assert_eq!(f64::ulp_at(1e-300), 1e-300f64.next_up() - 1e-300);
        for x in [
            f64::from_bits(1 << 52),
            f64::from_bits(60 << 52),
            5.8e-300,
            0.04,
        ] {
            assert_eq!(f64::ulp_at(x), x.next_up() - x, "{x:e}");
        }
    }
}
