//! The BRDF trait, and where the light and the viewer lie about the
//! surface: the one place every BRDF here decides whether it has a lobe.

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use crate::{Real, Vector3};

/// A BRDF: `f_r(wi, wo)` in 1/sr at a surface with unit normal `n`, for unit
/// directions `wi` (towards the light) and `wo` (towards the viewer).
pub trait Brdf<T: Real> {
    /// Evaluates `f_r(wi, wo)`.
    fn eval<V: Vector3<Scalar = T>>(&self, n: V, wi: V, wo: V) -> T;
}

/// Where the light and the viewer lie about the surface, as every BRDF here
/// decides it: a BRDF has a lobe only where both are strictly above.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Hemisphere<T> {
    /// Both strictly above.
    Above {
        /// `cos θ_i = n · wi > 0`.
        cos_i: T,
        /// `cos θ_o = n · wo > 0`.
        cos_o: T,
    },
    /// The light is at or below the surface (`n · wi ≤ 0`), whichever side
    /// the viewer is on: `f_r = 0`.
    LightBelow,
    /// The light is above, the viewer at or below (`n · wo ≤ 0`): `f_r = 0`.
    ViewerBelow,
    /// A NaN direction: `f_r` is NaN (crate conventions: NaN in, NaN out).
    Undefined,
}

/// Decides the [`Hemisphere`] of `wi` (towards the light) and `wo` (towards
/// the viewer) about the unit normal `n`: the one place every BRDF here
/// decides whether it has a lobe.
///
/// ```
/// use glam::DVec3;
/// use radiometry::brdf::{hemisphere, Hemisphere};
/// // The course's quiz 3: light from (0, 3, 4)/5, seen from below.
/// let side = hemisphere(DVec3::Z, DVec3::new(0.0, 0.6, 0.8), DVec3::new(0.0, 0.6, -0.8));
/// assert_eq!(side, Hemisphere::ViewerBelow);
/// ```
#[inline]
pub fn hemisphere<V: Vector3>(n: V, wi: V, wo: V) -> Hemisphere<V::Scalar> {
    let (cos_i, cos_o) = (n.dot(wi), n.dot(wo));
    let zero = V::Scalar::zero();
    if cos_i > zero && cos_o > zero {
        Hemisphere::Above { cos_i, cos_o }
    } else if cos_i.is_nan() || cos_o.is_nan() {
        Hemisphere::Undefined
    } else if cos_i <= zero {
        Hemisphere::LightBelow
    } else {
        Hemisphere::ViewerBelow
    }
}

/// `lobe(cos θ_i, cos θ_o)` where both directions are strictly above the
/// surface, 0 where either is at or below it, and NaN for a NaN direction
/// ([`hemisphere`]).
#[inline]
pub(super) fn above<V: Vector3>(
    n: V,
    wi: V,
    wo: V,
    lobe: impl FnOnce(V::Scalar, V::Scalar) -> V::Scalar,
) -> V::Scalar {
    match hemisphere(n, wi, wo) {
        Hemisphere::Above { cos_i, cos_o } => lobe(cos_i, cos_o),
        Hemisphere::Undefined => V::Scalar::nan(),
        Hemisphere::LightBelow | Hemisphere::ViewerBelow => V::Scalar::zero(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::brdf::CourseLambert;
    use glam::DVec3;

    #[test]
    fn hemisphere_names_the_direction_at_or_below_the_surface() {
        // Exact: the cosines are the z components, 0.8 and 0 in binary as
        // the dot products with +z compute them.
        let n = DVec3::Z;
        let (up, down, grazing) = (
            DVec3::new(0.0, 0.6, 0.8),
            DVec3::new(0.0, 0.6, -0.8),
            DVec3::Y,
        );
        let cases = [
            (
                (up, up),
                Hemisphere::Above {
                    cos_i: 0.8,
                    cos_o: 0.8,
                },
            ),
            ((down, up), Hemisphere::LightBelow),
            ((down, down), Hemisphere::LightBelow),
            ((grazing, up), Hemisphere::LightBelow),
            ((up, down), Hemisphere::ViewerBelow),
            ((up, grazing), Hemisphere::ViewerBelow),
            ((up, DVec3::NAN), Hemisphere::Undefined),
        ];
        for ((wi, wo), side) in cases {
            assert_eq!(hemisphere(n, wi, wo), side, "wi = {wi}, wo = {wo}");
            let f = CourseLambert { kd: 0.6 }.eval(n, wi, wo);
            match side {
                Hemisphere::Above { .. } => assert_eq!(f, 0.6),
                Hemisphere::Undefined => assert!(f.is_nan()),
                _ => assert_eq!(f, 0.0),
            }
        }
    }
}
