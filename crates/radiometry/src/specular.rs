//! Directions of ideal (specular) reflection and refraction at a smooth
//! interface: the law of reflection, `θ_r = θ_i` in the plane of incidence,
//! and Snell's law in vector form. Directions are unit vectors pointing away
//! from the surface (see the crate's conventions).

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use crate::snell::Incidence;
use crate::Vector3;

/// The mirror direction of `w` about the normal `n`: `2 (w·n) n − w`.
///
/// Both `w` and the result point away from the surface, on the same side;
/// the sign of `n` does not matter. Reflecting twice gives `w` back. The law
/// of reflection, `θ_r = θ_i` in the plane of incidence, as the course
/// states it (`003`, "Visszaverődés"; `001`); Born & Wolf §1.5.1.
///
/// The course's GLSL `reflect(I, N) = I − 2 (N·I) N` takes the incident ray's
/// direction of travel `I = −w`; it returns the same vector.
///
/// ```
/// use glam::DVec3;
/// let r = radiometry::specular::reflect(DVec3::new(0.0, 0.6, 0.8), DVec3::Z);
/// assert_eq!(r, DVec3::new(0.0, -0.6, 0.8));
/// ```
#[inline]
pub fn reflect<V: Vector3>(w: V, n: V) -> V {
    let two_cos = w.dot(n) + w.dot(n);
    n * two_cos - w
}

/// A refracted ray: its direction and the relative index along the path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Refraction<V: Vector3> {
    /// The transmitted direction, a unit vector pointing away from the
    /// surface on the side opposite to the incident light.
    pub direction: V,
    /// The effective relative index along the path, `n_t / n_i`: `eta` when
    /// `wi` lies on the outside, `1 / eta` when it lies on the inside.
    /// Radiance arriving along `−direction` and leaving along `wi`, as a
    /// camera path traced through `wi` carries it back, scales by
    /// `1 / eta²` ([`crate::radiance::across_interface`]); light travelling
    /// the other way, from `wi`'s side into `direction`, gains `eta²`.
    pub eta_path: V::Scalar,
    /// `cos θ_t ≥ 0`, the cosine between the transmitted direction and the
    /// normal on its side.
    pub cos_t: V::Scalar,
}

/// The incidence of direction `wi` on an interface with unit normal `n` and
/// relative index `eta = n_inside / n_outside`, resolved from the vectors:
/// the side and `|cos θ_i|` from `dot(n, wi)`, and near normal incidence
/// also `sin θ_i = |n × (n × wi)|`, which there says more than the cosine
/// ([`Incidence::resolve_measured`]). `None` for input that describes no
/// interface (a NaN component, `eta` not positive and finite).
///
/// Every law that meets a pair of directions at an interface takes its
/// incidence from here: [`refract`], and the Fresnel laws a renderer
/// evaluates at the same hit ([`crate::fresnel::dielectric_resolved`],
/// [`crate::fresnel::schlick_dielectric_resolved`]), so that the direction
/// and the weight come from one `cos θ_t`.
///
/// ```
/// use glam::DVec3;
/// use radiometry::specular::incidence;
/// let near_normal = incidence(DVec3::new(0.0, 0.6, 0.8), DVec3::Z, 1.5).unwrap();
/// assert_eq!(near_normal.sin_i, Some(0.6));
/// ```
#[inline]
pub fn incidence<V: Vector3>(wi: V, n: V, eta: V::Scalar) -> Option<Incidence<V::Scalar>> {
    Incidence::resolve_measured(n.dot(wi), eta, || tangential(wi, n).length())
}

/// `n cos θ_i − wi`, the part of `wi` along the surface, negated, as
/// `n × (n × wi)`: exactly perpendicular to `n` but for its last bits, and
/// of length `sin θ_i` (for unit vectors) also where `wi` and `n` are so
/// close that `n × wi` is mostly rounding.
#[inline]
fn tangential<V: Vector3>(wi: V, n: V) -> V {
    n.cross(n.cross(wi))
}

/// Refracts the incident direction `wi` through an interface with unit
/// normal `n` and relative index `eta = n_inside / n_outside`.
///
/// The side is read from the sign of `dot(n, wi)`: from the outside the
/// light bends by `eta`, from the inside by `1 / eta`. Returns `None` when no
/// refracted ray exists: under total internal reflection (Snell's law would
/// need `sin θ_t > 1`), and for inputs that describe no interface (a NaN
/// component, `eta ≤ 0` or not finite).
///
/// The incidence is resolved by [`incidence`], `cos θ_t` comes from
/// [`Incidence::cos_transmitted`] (accurate near the critical angle), and the
/// direction from [`refract_resolved`]: a caller that already holds the
/// incidence and `cos θ_t` (a [`crate::fresnel::DielectricFresnel`], a
/// [`crate::fresnel::SchlickDielectric`]) calls that instead and gets the
/// same bits.
///
/// For unit `wi` and `n` the direction is a unit vector to a few ulps at any
/// index, also going into a much rarer medium near normal incidence, where
/// the tangential part grows by `n_i / n_t` and `cos θ_t` is taken from the
/// same measured sine.
///
/// ```
/// use glam::DVec3;
/// use radiometry::specular::refract;
/// // Straight through at normal incidence, from either side.
/// assert_eq!(refract(DVec3::Z, DVec3::Z, 1.5).unwrap().direction, -DVec3::Z);
/// assert_eq!(refract(-DVec3::Z, DVec3::Z, 1.5).unwrap().eta_path, 1.0 / 1.5);
/// ```
#[inline]
pub fn refract<V: Vector3>(wi: V, n: V, eta: V::Scalar) -> Option<Refraction<V>> {
    let incidence = incidence(wi, n, eta)?;
    let cos_t = incidence.cos_transmitted()?;
    Some(refract_resolved(wi, n, &incidence, cos_t))
}

/// The refracted ray for an incidence already resolved: `incidence` is
/// [`incidence`]`(wi, n, eta)` (or [`Incidence::resolve`]`(dot(n, wi), eta)`)
/// and `cos_t` its [`Incidence::cos_transmitted`] (or the `cos_t` of a
/// Fresnel law that returned them), so neither the side nor Snell's
/// discriminant is decided again.
///
/// The transmitted direction is `−wi / η + (cos θ_i / η − cos θ_t) n'`, with
/// `η` and `n'` the effective index and the normal on the incident side
/// (pbrt-v4 §9.3, eq. 9.4). Where the incidence carries a measured
/// `sin θ_i`, the tangential part `n' cos θ_i − wi` is formed as
/// `n × (n × wi)`, whose length that sine is: the tangential and normal parts
/// of the result then come from one sine and make a unit vector.
///
/// ```
/// use glam::DVec3;
/// use radiometry::fresnel::dielectric_resolved;
/// use radiometry::specular::{incidence, refract, refract_resolved};
/// let (wi, n) = (DVec3::new(0.0, 0.6, 0.8), DVec3::Z);
/// let f = dielectric_resolved(&incidence(wi, n, 1.5).unwrap());
/// let t = refract_resolved(wi, n, &f.incidence, f.cos_t.unwrap());
/// assert_eq!(Some(t), refract(wi, n, 1.5));
/// ```
#[inline]
pub fn refract_resolved<V: Vector3>(
    wi: V,
    n: V,
    incidence: &Incidence<V::Scalar>,
    cos_t: V::Scalar,
) -> Refraction<V> {
    let n_facing = if incidence.from_inside { -n } else { n };
    let tangential = match incidence.sin_i {
        Some(_) => tangential(wi, n),
        None => n_facing * incidence.abs_cos_i - wi,
    };
    // The tangential part scales by n_i / n_t; one of the two is exactly 1.
    let tangential = if incidence.from_inside {
        tangential * incidence.n_i
    } else {
        tangential * (V::Scalar::one() / incidence.n_t)
    };
    let direction = tangential - n_facing * cos_t;
    Refraction {
        direction,
        eta_path: incidence.eta_path(),
        cos_t,
    }
}
