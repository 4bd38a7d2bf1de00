//! The slides' cheap refraction, `t = normalize(−c n + i)` (`001` lines
//! 390–395), against Snell's law in vector form: the angle between the two
//! directions (radians), for light arriving from either side.
//!
//! The cheap direction is [`radiometry::course::refract_001_approx`] and the
//! exact one [`radiometry::specular::refract_resolved`]; the side of the
//! surface, the index along the path and whether Snell's law has a
//! transmitted ray at all are decided once, by
//! [`radiometry::specular::incidence`], and both directions are built from
//! that decision.
//!
//! In the plane of incidence the cheap direction makes
//! `atan2(sin α, cos α + c)` with the inward normal, against Snell's
//! `asin(sin α / η)` (`η = n_t / n_i`, the index along the path): equal at
//! normal incidence, and to first order in `α` only when `c = η − 1`. The
//! slides' `c ≈ 1` for water is an erratum (`docs/errata.md`). Leaving a
//! denser medium (`η < 1`) the first-order `c` is negative, and the form
//! bends away from the normal as it should, but it knows no critical angle:
//! past it the exact law has no transmitted ray ([`Comparison::TotalInternalReflection`])
//! while the cheap form still returns one.

use glam::DVec3;
use radiometry::course::refract_001_approx;
use radiometry::specular::{incidence, refract_resolved, Refraction};

/// The constant `c` of the cheap form.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Constant {
    /// A fixed `c`, the same on both sides of the surface.
    Fixed(f64),
    /// `c = η − 1` with `η` the index along the path the law resolved:
    /// the cheap form then agrees with Snell's law to first order in the
    /// incidence angle, from either side.
    FirstOrder,
}

impl Constant {
    /// The value of `c` along a path whose index (`n_t / n_i`, the one the
    /// law resolved) is `eta_path`.
    pub fn value(self, eta_path: f64) -> f64 {
        match self {
            Constant::Fixed(c) => c,
            Constant::FirstOrder => eta_path - 1.0,
        }
    }
}

/// The slides' constant for water, `c ≈ 1`.
pub const SLIDES_WATER: Constant = Constant::Fixed(1.0);

/// Which side of the surface the light arrives from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// From the side the normal points into (air, entering the medium).
    Outside,
    /// From the other side (inside the medium, leaving it).
    Inside,
}

/// The direction `wi` (pointing away from the surface, towards where the
/// light comes from) at incidence angle `theta_i` (radians) from the
/// normal `+z`, in the `xz` plane, on `side`.
pub fn in_plane(theta_i: f64, side: Side) -> DVec3 {
    let (sin, cos) = theta_i.sin_cos();
    match side {
        Side::Outside => DVec3::new(sin, 0.0, cos),
        Side::Inside => DVec3::new(sin, 0.0, -cos),
    }
}

/// The cheap direction beside the exact law's outcome.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Comparison {
    /// Snell's law transmits: the exact ray, the cheap direction and the
    /// angle between them.
    Refracts {
        /// The exact refracted ray.
        exact: Refraction<DVec3>,
        /// The cheap direction, a unit vector (direction of travel).
        cheap: DVec3,
        /// The angle between the two directions, radians, in `[0, π]`.
        error: f64,
    },
    /// Total internal reflection: Snell's law has no transmitted ray. The
    /// cheap form still returns a direction, with nothing to compare it to.
    TotalInternalReflection {
        /// The cheap direction.
        cheap: DVec3,
    },
}

impl Comparison {
    /// The angle between the cheap and the exact direction, `None` under
    /// total internal reflection.
    pub fn error(&self) -> Option<f64> {
        match *self {
            Self::Refracts { error, .. } => Some(error),
            Self::TotalInternalReflection { .. } => None,
        }
    }
}

/// The cheap refraction of `wi` (unit, pointing away from the surface)
/// through the interface with unit normal `n` and `eta = n_inside /
/// n_outside`, beside the exact one.
///
/// The cheap form is applied as the slides apply it, to the direction of
/// travel `i = −wi` and the normal facing the light (`n`, or `−n` from the
/// inside). `None` where the input describes no interface (the law's
/// `None`: a NaN component, `eta` not positive and finite).
pub fn compare(wi: DVec3, n: DVec3, eta: f64, constant: Constant) -> Option<Comparison> {
    let incidence = incidence(wi, n, eta)?;
    let facing = if incidence.from_inside { -n } else { n };
    let cheap = refract_001_approx(-wi, facing, constant.value(incidence.eta_path()));
    Some(match incidence.cos_transmitted() {
        None => Comparison::TotalInternalReflection { cheap },
        Some(cos_t) => {
            let exact = refract_resolved(wi, n, &incidence, cos_t);
            Comparison::Refracts {
                exact,
                cheap,
                error: angle_between(cheap, exact.direction),
            }
        }
    })
}

/// The angle between two unit vectors, `atan2(|a × b|, a · b)`: accurate
/// at every angle, where `acos(a · b)` loses half its digits near 0.
pub fn angle_between(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b))
}

/// [`compare`] at incidence angle `theta_i` (radians) on `side` of the
/// surface with normal `+z`.
pub fn compare_at(theta_i: f64, side: Side, eta: f64, constant: Constant) -> Option<Comparison> {
    compare(in_plane(theta_i, side), DVec3::Z, eta, constant)
}

#[cfg(test)]
mod tests;
