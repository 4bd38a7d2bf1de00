//! The precision tier a render computes in: `f32` (`glam::Vec3`), the
//! course's shaders' and the default, or `f64` (`glam::DVec3`), as the
//! `radiometry` laws already are ([`radiometry::Real`],
//! [`radiometry::Vector3`]).
//!
//! The geometry, the camera ray, the direct light and the `local` and
//! `whitted` integrators are written once, over [`Vector`]; the laws are
//! called at the same tier. The scene is validated once, in `f32`
//! ([`crate::scene::Scene`]); a tracer at another tier widens its objects,
//! materials and lights once, exactly, when it is built
//! ([`crate::scene::model::World`]), so both tiers read the same numbers and
//! differ only in the arithmetic. The image stays `f32` radiance (the
//! film): each pixel's mean is rounded once at the end.

use core::ops::{AddAssign, Div, Index, Mul};

use glam::{DVec3, Vec3};
use radiometry::{Real, Vector3};

/// A tracer's scalar: `f32` or `f64`.
pub trait Tier: Real {
    /// Widens an `f32` of the validated scene (exact for both tiers).
    fn of_f32(x: f32) -> Self;
    /// Widens to `f64` (exact for both tiers).
    fn to_f64(self) -> f64;
    /// `γ(n) = n ε / (1 − n ε)` with this tier's unit roundoff `ε`: the
    /// bound on the relative error of `n` successive roundings (Higham,
    /// *Accuracy and Stability of Numerical Algorithms*, §3.1; pbrt-v4
    /// §6.8.1).
    fn gamma(n: u32) -> Self;
}

impl Tier for f32 {
    #[inline]
    fn of_f32(x: f32) -> Self {
        x
    }
    #[inline]
    fn to_f64(self) -> f64 {
        self.into()
    }
    #[inline]
    fn gamma(n: u32) -> Self {
        let ne = n as f32 * f32::EPSILON * 0.5;
        ne / (1.0 - ne)
    }
}

impl Tier for f64 {
    #[inline]
    fn of_f32(x: f32) -> Self {
        x.into()
    }
    #[inline]
    fn to_f64(self) -> f64 {
        self
    }
    #[inline]
    fn gamma(n: u32) -> Self {
        let ne = n as f64 * f64::EPSILON * 0.5;
        ne / (1.0 - ne)
    }
}

/// A tracer's 3-vector: `Vec3` for `f32`, `DVec3` for `f64`. Points in
/// metres, directions, and radiance per channel alike. Each method is
/// glam's own, so the `f32` tier computes the bits it always did.
pub trait Vector:
    Vector3<Scalar: Tier>
    + Mul<Output = Self>
    + Div<<Self as Vector3>::Scalar, Output = Self>
    + AddAssign
    + Index<usize, Output = <Self as Vector3>::Scalar>
    + Default
    + Send
    + Sync
    + 'static
{
    /// `(0, 0, 0)`.
    const ZERO: Self;
    /// `(1, 1, 1)`.
    const ONE: Self;
    /// The x axis.
    const X: Self;
    /// The y axis.
    const Y: Self;
    /// Every component `x`.
    fn splat(x: Self::Scalar) -> Self;
    /// The components' absolute values.
    fn abs(self) -> Self;
    /// The larger of each pair of components.
    fn max(self, other: Self) -> Self;
    /// The largest component.
    fn max_element(self) -> Self::Scalar;
    /// The x component.
    fn x(self) -> Self::Scalar;
    /// The unit vector along `self` (glam's `normalize`).
    fn normalize(self) -> Self;
    /// The unit vector along `self`, or zero where it has none.
    fn normalize_or_zero(self) -> Self;
    /// Widens a vector of the validated scene (exact).
    fn of_f32(v: Vec3) -> Self;
    /// Rounds to `f32` once: the film's radiance, an environment's lookup.
    fn to_f32(self) -> Vec3;
    /// Rounds an `f64` construction (the camera's, the bump map's) once.
    fn of_f64(v: DVec3) -> Self;
    /// Widens to `f64` (exact).
    fn to_f64(self) -> DVec3;
}

macro_rules! impl_vector {
    ($vec:ty, $scalar:ty, $of_f32:expr, $to_f32:expr, $of_f64:expr, $to_f64:expr) => {
        impl Vector for $vec {
            const ZERO: Self = <$vec>::ZERO;
            const ONE: Self = <$vec>::ONE;
            const X: Self = <$vec>::X;
            const Y: Self = <$vec>::Y;
            #[inline]
            fn splat(x: $scalar) -> Self {
                <$vec>::splat(x)
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
            fn x(self) -> $scalar {
                self.x
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
                $of_f32(v)
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
                $to_f64(self)
            }
        }
    };
}

impl_vector!(
    Vec3,
    f32,
    |v: Vec3| v,
    |v: Vec3| v,
    |v: DVec3| v.as_vec3(),
    |v: Vec3| v.as_dvec3()
);
impl_vector!(
    DVec3,
    f64,
    |v: Vec3| v.as_dvec3(),
    |v: DVec3| v.as_vec3(),
    |v: DVec3| v,
    |v: DVec3| v
);

/// A colour from a function of its channel index.
pub(crate) fn rgb<V: Vector>(f: impl Fn(usize) -> V::Scalar) -> V {
    V::new(f(0), f(1), f(2))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `γ(n) = n u / (1 − n u)` with each tier's unit roundoff, `u = 2⁻²⁴`
    /// for `f32` and `2⁻⁵³` for `f64` (Higham §3.1), within one ulp of the
    /// tier (the formula evaluated in the tier against it in `f64`, for
    /// `f32`, and against `n u` plus its square, the next term, for `f64`).
    #[test]
    fn gamma_is_the_bound_of_n_roundings_at_each_tier() {
        for n in [1_u32, 6, 8, 100] {
            let u = 2f64.powi(-24) * f64::from(n);
            let exact = u / (1.0 - u);
            let single = f64::from(<f32 as Tier>::gamma(n));
            assert!(
                (single - exact).abs() <= f32::ulp_at(exact),
                "f32 γ({n}) = {single:e}"
            );
            let u = 2f64.powi(-53) * f64::from(n);
            let double = <f64 as Tier>::gamma(n);
            assert!(
                (double - (u + u * u)).abs() <= f64::ulp_at(u),
                "f64 γ({n}) = {double:e}"
            );
        }
    }
}
