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
