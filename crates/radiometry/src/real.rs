//! The two precision tiers, `f32` and `f64`, and their 3-vectors: the one
//! abstraction over the float type that the laws, the tracer and the
//! cross-checks are all written over.

use core::convert::identity;
use core::fmt::{Debug, Display};
use core::ops::{Add, AddAssign, Div, Index, Mul, Neg, Sub};

use glam::{DVec3, Vec3};
use num_traits::{Float, FloatConst, Zero};

/// A floating-point scalar the laws are written over: `f32` or `f64`.
///
/// Widening to `f64` (`Into<f64>`) is exact for both tiers.
pub trait Real:
    Float + FloatConst + Debug + Display + Default + Into<f64> + Send + Sync + 'static
{
    /// The tier's 3-vector: `glam::Vec3` for `f32`, `glam::DVec3` for `f64`.
    type Vec3: Vector3<Scalar = Self>;
    /// The precision in which the few sums that cancel are carried (in
    /// twice *its* precision): `f64` for both tiers. Products of `f32`s are
    /// exact in `f64`, so the `f32` tier gets those sums essentially exact.
    type Wide: Real;
    /// Converts a literal `f64` constant (rounding once for `f32`).
    fn lit(x: f64) -> Self;
    /// Widens an `f32` (exact for both tiers): a number of a scene, which
    /// is validated in `f32` whatever the tier it is rendered at.
    fn of_f32(x: f32) -> Self;
    /// `γ(n) = n ε / (1 − n ε)` with this tier's unit roundoff `ε`: the
    /// bound on the relative error of `n` successive roundings (Higham,
    /// *Accuracy and Stability of Numerical Algorithms*, §3.1; pbrt-v4
    /// §6.8.1).
    fn gamma(n: u32) -> Self;
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
    type Vec3 = Vec3;
    type Wide = f64;
    #[inline]
    fn lit(x: f64) -> Self {
        x as f32
    }
    #[inline]
    fn of_f32(x: f32) -> Self {
        x
    }
    #[inline]
    fn gamma(n: u32) -> Self {
        let ne = n as f32 * f32::EPSILON * 0.5;
        ne / (1.0 - ne)
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
    type Vec3 = DVec3;
    type Wide = f64;
    #[inline]
    fn lit(x: f64) -> Self {
        x
    }
    #[inline]
    fn of_f32(x: f32) -> Self {
        x.into()
    }
    #[inline]
    fn gamma(n: u32) -> Self {
        let ne = n as f64 * f64::EPSILON * 0.5;
        ne / (1.0 - ne)
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
/// Points in metres, directions, and radiance per channel alike.
///
/// The laws that take directions, and the tracer's geometry and
/// integrators, are generic over this trait, so the same code serves both
/// precision tiers. Each method is glam's own, so the `f32` tier computes
/// the bits glam does.
pub trait Vector3:
    Copy
    + Debug
    + Default
    + PartialEq
    + Add<Output = Self>
    + AddAssign
    + Sub<Output = Self>
    + Neg<Output = Self>
    + Mul<Output = Self>
    + Mul<<Self as Vector3>::Scalar, Output = Self>
    + Div<<Self as Vector3>::Scalar, Output = Self>
    + Index<usize, Output = <Self as Vector3>::Scalar>
    + Send
    + Sync
    + 'static
{
    /// The scalar type of the components.
    type Scalar: Real;
    /// `(0, 0, 0)`.
    const ZERO: Self;
    /// `(1, 1, 1)`.
    const ONE: Self;
    /// The x axis.
    const X: Self;
    /// The y axis.
    const Y: Self;
    /// Builds a vector from its components.
    fn new(x: Self::Scalar, y: Self::Scalar, z: Self::Scalar) -> Self;
    /// Every component `x`.
    fn splat(x: Self::Scalar) -> Self;
    /// The dot product.
    fn dot(self, other: Self) -> Self::Scalar;
    /// The cross product.
    fn cross(self, other: Self) -> Self;
    /// The components as an array.
    fn to_array(self) -> [Self::Scalar; 3];
    /// The x component.
    fn x(self) -> Self::Scalar;
    /// The components' absolute values.
    fn abs(self) -> Self;
    /// The larger of each pair of components.
    fn max(self, other: Self) -> Self;
    /// The largest component.
    fn max_element(self) -> Self::Scalar;
    /// The unit vector along `self` (glam's `normalize`).
    fn normalize(self) -> Self;
    /// The unit vector along `self`, or zero where it has none.
    fn normalize_or_zero(self) -> Self;
    /// Widens an `f32` vector (exact): a scene's, validated in `f32`.
    fn of_f32(v: Vec3) -> Self;
    /// Rounds to `f32` once: a film's radiance, an environment's lookup.
    fn to_f32(self) -> Vec3;
    /// Rounds an `f64` construction (a camera's, a bump map's) once.
    fn of_f64(v: DVec3) -> Self;
    /// Widens to `f64` (exact).
    fn to_f64(self) -> DVec3;

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

/// Forwards each method to glam's own of the same name; the roundings to
/// `f32` are `$to_f32` and `$of_f64`, the widenings glam's `From`.
macro_rules! impl_vector3 {
    ($vec:ty, $scalar:ty, $to_f32:expr, $of_f64:expr) => {
        impl Vector3 for $vec {
            type Scalar = $scalar;
            const ZERO: Self = <$vec>::ZERO;
            const ONE: Self = <$vec>::ONE;
            const X: Self = <$vec>::X;
            const Y: Self = <$vec>::Y;
            #[inline]
            fn new(x: $scalar, y: $scalar, z: $scalar) -> Self {
                <$vec>::new(x, y, z)
            }
            #[inline]
            fn splat(x: $scalar) -> Self {
                <$vec>::splat(x)
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
            #[inline]
            fn x(self) -> $scalar {
                self.x
            }
            #[inline]
            fn abs(self) -> Self {
                <$vec>::abs(self)
            }
            #[inline]
            fn max(self, other: Self) -> Self {
                <$vec>::max(self, other)
            }
            #[inline]
            fn max_element(self) -> $scalar {
                <$vec>::max_element(self)
            }
            #[inline]
            fn normalize(self) -> Self {
                <$vec>::normalize(self)
            }
            #[inline]
            fn normalize_or_zero(self) -> Self {
                <$vec>::normalize_or_zero(self)
            }
            #[inline]
            fn of_f32(v: Vec3) -> Self {
                v.into()
            }
            #[inline]
            fn to_f32(self) -> Vec3 {
                $to_f32(self)
            }
            #[inline]
            fn of_f64(v: DVec3) -> Self {
                $of_f64(v)
            }
            #[inline]
            fn to_f64(self) -> DVec3 {
                self.into()
            }
        }
    };
}

impl_vector3!(Vec3, f32, identity, |v: DVec3| v.as_vec3());
impl_vector3!(DVec3, f64, |v: DVec3| v.as_vec3(), identity);

/// `2^k` for a normal double's exponent, from the bits: a constant where
/// `powi` is a call that blocks a loop's vectorisation.
pub(crate) const fn power_of_two(k: i32) -> f64 {
    f64::from_bits(((1023 + k) as u64) << 52)
}

#[cfg(test)]
mod tests;
