//! Radiance and irradiance, and the abstract light sources of the course.
//!
//! Radiance `L = dΦ / (dA cos θ dω)` in W/(sr·m²): power per projected area
//! per solid angle. It is constant along a ray in a vacuum, which is why a
//! ray tracer can carry it from surface to eye unchanged. Irradiance `E` in
//! W/m² is the power arriving per unit area; a surface of BRDF `f_r` (1/sr)
//! under irradiance `E` from one direction sends radiance `L = f_r E` towards
//! the viewer.
//!
//! Abstract lights, as in the course (`003`, "Fényforrások"):
//!
//! - a **directional light** sends parallel light from one direction; it is
//!   described by the irradiance `E⊥` it delivers to a surface facing it
//!   (W/m²), and a surface tilted by θ receives `E⊥ cos⁺θ`. The course calls
//!   `E⊥` the light's "radiance" and gives it in W/m²/sr; numerically it is the
//!   same number, and this crate names it for what it measures.
//! - a **point light** of radiant intensity `I` (W/sr) at distance `r` gives
//!   `E = I cos⁺θ / r²`: the inverse-square law. It is irradiance that falls
//!   with distance, not radiance.

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use crate::{Real, Vector3};

/// The clamped cosine `cos⁺x = max(x, 0)`: light from below the surface
/// contributes nothing. NaN stays NaN.
///
/// ```
/// assert_eq!(radiometry::radiance::cos_plus(-0.3_f64), 0.0);
/// assert_eq!(radiometry::radiance::cos_plus(0.8_f64), 0.8);
/// ```
#[inline]
pub fn cos_plus<T: Real>(x: T) -> T {
    if x < T::zero() {
        T::zero()
    } else {
        x
    }
}

/// The geometry term `cos⁺θ = cos⁺(n · w)` between the unit normal `n` and
/// the unit direction `w` towards the light.
#[inline]
pub fn geometry_term<V: Vector3>(n: V, w: V) -> V::Scalar {
    cos_plus(n.dot(w))
}

/// Radiance from its definition, `L = ΔΦ / (ΔA cos θ Δω)`, in W/(sr·m²):
/// the power `flux` (W) leaving the area `area` (m²) into the solid angle
/// `solid_angle` (sr) around a direction at `cos_theta` to the normal.
///
/// ```
/// // 1 mW from 1 mm² seen head-on, into 1 msr: 1e6 W/(sr·m²).
/// let l = radiometry::radiance::radiance_from_flux(1e-3_f64, 1e-6, 1.0, 1e-3);
/// assert!((l - 1e6).abs() < 1e-6);
/// ```
#[inline]
pub fn radiance_from_flux<T: Real>(flux: T, area: T, cos_theta: T, solid_angle: T) -> T {
    flux / (area * cos_theta * solid_angle)
}

/// Irradiance (W/m²) on a surface with unit normal `n` from a directional
/// light delivering `e_perpendicular` (W/m², to a surface facing it) from
/// the unit direction `to_light`: `E = E⊥ cos⁺θ`.
///
/// ```
/// use glam::DVec3;
/// use radiometry::radiance::directional_irradiance;
/// // The course's quiz 3: 5 W/m² from (0, 3, 4)/5 onto a floor.
/// let e = directional_irradiance(5.0, DVec3::Z, DVec3::new(0.0, 0.6, 0.8));
/// assert!((e - 4.0).abs() < 1e-15);
/// ```
#[inline]
pub fn directional_irradiance<V: Vector3>(
    e_perpendicular: V::Scalar,
    n: V,
    to_light: V,
) -> V::Scalar {
    e_perpendicular * geometry_term(n, to_light)
}

/// Light arriving at a point from a point light: where it comes from and how
/// much irradiance it delivers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLightSample<V: Vector3> {
    /// Unit direction from the shaded point towards the light.
    pub to_light: V,
    /// Distance to the light, in metres: a shadow ray stops there.
    pub distance: V::Scalar,
    /// Irradiance on the surface, `I cos⁺θ / r²`, in W/m².
    pub irradiance: V::Scalar,
}

/// Irradiance (W/m²) at `point` on a surface with unit normal `n` from a
/// point light of radiant intensity `intensity` (W/sr) at `light`:
/// `E = I cos⁺θ / r²`, the inverse-square law.
///
/// Returns `None` when the light sits on the point (`r = 0`), where the
/// irradiance of an ideal point light is undefined.
///
/// ```
/// use glam::DVec3;
/// use radiometry::radiance::point_irradiance;
/// let near = point_irradiance(100.0, DVec3::new(0.0, 0.0, 1.0), DVec3::ZERO, DVec3::Z).unwrap();
/// let far = point_irradiance(100.0, DVec3::new(0.0, 0.0, 2.0), DVec3::ZERO, DVec3::Z).unwrap();
/// assert_eq!(near.irradiance, 100.0);
/// assert_eq!(far.irradiance, 25.0); // twice as far, a quarter of the light
/// ```
#[inline]
pub fn point_irradiance<V: Vector3>(
    intensity: V::Scalar,
    light: V,
    point: V,
    n: V,
) -> Option<PointLightSample<V>> {
    let offset = light - point;
    let distance2 = offset.dot(offset);
    if !(distance2 > V::Scalar::zero()) || !distance2.is_finite() {
        return None;
    }
    let distance = distance2.sqrt();
    let to_light = offset * distance.recip();
    let irradiance = intensity * geometry_term(n, to_light) / distance2;
    Some(PointLightSample {
        to_light,
        distance,
        irradiance,
    })
}

/// Radiance reflected towards the viewer, `L = f_r · E`, from a BRDF value
/// `brdf` (1/sr) and the irradiance `irradiance` (W/m²) from one direction.
#[inline]
pub fn reflected_radiance<T: Real>(brdf: T, irradiance: T) -> T {
    brdf * irradiance
}

/// Radiance carried across a smooth interface: `L_t = τ L / η²`, where `τ`
/// is the transmitted fraction of power (the Fresnel transmittance) and
/// `η = eta_path = n_t / n_i` the effective relative index along the
/// direction the *radiance is traced* (the
/// [`crate::specular::Refraction::eta_path`] of a camera path). Radiance
/// divided by `n²` is invariant along a ray across refractions (the beam's
/// projected solid angle is compressed by `n_i² / n_t²`,
/// `n_i² cos θ_i dω_i = n_t² cos θ_t dω_t`; Nicodemus 1963; Veach's
/// thesis §5.2; pbrt-v4 §9.5.2), so the factor cancels over a path that
/// enters and leaves the same medium.
///
/// ```
/// use radiometry::radiance::across_interface;
/// // Into glass and back out: the two factors cancel.
/// let inside = across_interface(1.0_f64, 1.5);
/// assert!((inside - 1.0 / 2.25).abs() < 1e-16);
/// assert!((across_interface(inside, 1.0 / 1.5) - 1.0).abs() < 1e-15);
/// ```
#[inline]
pub fn across_interface<T: Real>(transmitted: T, eta_path: T) -> T {
    transmitted / (eta_path * eta_path)
}
