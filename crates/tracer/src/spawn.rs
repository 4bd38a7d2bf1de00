//! Where a secondary ray starts: off the surface it leaves, on the side it
//! travels into, by as little as rounding allows.
//!
//! A hit point is only known to within its rounding error; a ray started
//! exactly there may find the surface again at `t ≈ 0` ("shadow acne",
//! mirrors that reflect themselves). The course moves the origin by a fixed
//! `EPSILON = 0.001` m along the normal (`000`), which is too much for a
//! small scene and too little far from the origin: at 10⁵ m one `f32` ulp is
//! 7.8 mm, and the moved point rounds back onto the surface. Here the offset
//! is twice the hit's error bound ([`Hit::error`]), which scales with the
//! coordinates of the surface; twice, because the bound is per component and
//! the point may lie up to `√3` bounds off the surface. At the `f64` tier
//! the same bound is some 5·10⁸ times smaller ([`radiometry::Real::gamma`]).

use num_traits::Float;
use radiometry::{Real, Vector3};

use crate::geometry::Hit;
use crate::kinds::RayOffset;

/// The smallest offset used, m: keeps a hit at the origin (error bound 0)
/// from restarting on its own surface.
const MIN_OFFSET: f64 = 1e-30;

/// The origin of a ray leaving `hit` on the side of `side` (a unit normal
/// pointing where the new ray goes).
pub fn origin<V: Vector3>(hit: &Hit<V>, side: V, offset: RayOffset) -> V {
    let lit = V::Scalar::lit;
    let distance = match offset {
        RayOffset::Robust => (lit(2.0) * hit.error).max(lit(MIN_OFFSET)),
        RayOffset::Fixed(eps) => lit(eps),
        RayOffset::Scaled(eps) => lit(eps) * (V::Scalar::lit(1.0) + hit.point.abs().max_element()),
    };
    hit.point + side * distance
}
