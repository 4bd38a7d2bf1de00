//! The dispersing prism: the deviation (radians) of a ray refracted through
//! two plane faces meeting at the apex angle `A`, traced with radiometry's
//! refraction law, beside the analytic minimum deviation
//! `δ_min = 2 asin(n sin(A/2)) − A` (Born & Wolf, *Principles of Optics*,
//! §4.7.2), reached when the ray crosses the prism symmetrically.
//!
//! Geometry, in the `xy` plane: the apex points up (`+y`), light enters the
//! left face travelling right and leaves by the right face. The faces'
//! outward normals are `(∓cos(A/2), sin(A/2), 0)`. The incidence angle
//! `θ₁` is measured from the left face's inward normal, positive when the
//! ray arrives from the base's side (rotated towards `+y`), as in a
//! spectroscope. The faces are taken as unbounded: whether a ray meets the
//! second face depends on its direction only.

use glam::{DQuat, DVec3};
use radiometry::specular::refract;

use crate::refraction::angle_between;

/// A prism of apex angle `A` (radians) in air, of relative index `n`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Prism {
    apex: f64,
}

/// What becomes of a ray entering the prism.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Passage {
    /// It leaves by the second face.
    Emerges {
        /// The angle between the entering and the leaving direction,
        /// radians.
        deviation: f64,
        /// The leaving direction of travel (unit).
        direction: DVec3,
        /// The direction of travel inside the prism (unit).
        inside: DVec3,
    },
    /// It meets the second face beyond the critical angle and is reflected
    /// back inside: Snell's law has no transmitted ray.
    TotalInternalReflection,
    /// It travels inside away from the second face (it would leave through
    /// the base).
    MissesSecondFace,
}

impl Prism {
    /// A prism of apex angle `apex` (radians), `None` unless in `(0, π)`.
    pub fn new(apex: f64) -> Option<Self> {
        (apex > 0.0 && apex < std::f64::consts::PI).then_some(Self { apex })
    }

    /// The apex angle, radians.
    pub fn apex(&self) -> f64 {
        self.apex
    }

    /// The outward normals of the entering and the leaving face.
    fn normals(&self) -> (DVec3, DVec3) {
        let (sin, cos) = (self.apex / 2.0).sin_cos();
        (DVec3::new(-cos, sin, 0.0), DVec3::new(cos, sin, 0.0))
    }

    /// The incidence angle of the symmetric passage, `asin(n sin(A/2))`:
    /// inside, the ray runs parallel to the base. `None` when
    /// `n sin(A/2) > 1` (no ray crosses symmetrically) or `n` is not
    /// positive and finite.
    pub fn symmetric_incidence(&self, n: f64) -> Option<f64> {
        let sin = n * (self.apex / 2.0).sin();
        (n > 0.0 && n.is_finite() && sin <= 1.0).then(|| sin.asin())
    }

    /// The minimum deviation `2 asin(n sin(A/2)) − A`, radians; `None`
    /// where [`Prism::symmetric_incidence`] is.
    pub fn minimum_deviation(&self, n: f64) -> Option<f64> {
        Some(2.0 * self.symmetric_incidence(n)? - self.apex)
    }

    /// Traces a ray arriving at the first face at incidence `theta_1`
    /// (radians, in `(−π/2, π/2)`) through a prism of index `n`, with
    /// [`radiometry::specular::refract`] at each face. `None` for input
    /// the law refuses (NaN, `n` not positive and finite) or `theta_1`
    /// outside its range.
    pub fn trace(&self, n: f64, theta_1: f64) -> Option<Passage> {
        if theta_1.is_nan() || theta_1.abs() >= std::f64::consts::FRAC_PI_2 {
            return None;
        }
        let (entering, leaving) = self.normals();
        let arriving = DQuat::from_rotation_z(theta_1) * -entering;
        // Entering from the outside (air) nothing is reflected totally.
        let inside = refract(-arriving, entering, n)?.direction;
        if inside.dot(leaving) <= 0.0 {
            return Some(Passage::MissesSecondFace);
        }
        // `n` passed the law at the first face: `None` here is only Snell's
        // law without a transmitted ray.
        Some(match refract(-inside, leaving, n) {
            None => Passage::TotalInternalReflection,
            Some(out) => Passage::Emerges {
                deviation: angle_between(arriving, out.direction),
                direction: out.direction,
                inside,
            },
        })
    }
}
