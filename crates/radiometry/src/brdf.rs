//! Bidirectional reflectance distribution functions (BRDFs), in 1/sr:
//! `f_r(wi, wo) = dL_o(wo) / (L_i(wi) cos θ_i dω_i)`, the radiance reflected
//! towards `wo` per unit irradiance arriving from `wi`.
//!
//! Two laws every physical BRDF obeys, each with a generic checker here:
//!
//! - **Helmholtz reciprocity**, `f_r(wi, wo) = f_r(wo, wi)`: [`reciprocity`].
//! - **Energy conservation**, the directional albedo
//!   `ρ(wi) = ∫ f_r(wi, wo) cos θ_o dω_o ≤ 1` for every `wi`: of the power
//!   arriving from `wi`, no more than all is reflected
//!   ([`directional_albedo`]). The integral runs over the outgoing
//!   directions; the one over incoming directions, `∫ f_r(wi, wo) cos θ_i
//!   dω_i`, is the radiance towards `wo` under unit uniform light, and
//!   equals it only for a reciprocal BRDF (E. Veach, thesis, 1997, ch. 6).
//!
//! The models: the course's (`003`, "Rücskös felületek", whose specular
//! model is Phong-Blinn), and classic Phong beside them for comparison:
//!
//! | model | `f_r` | reciprocal | conserves energy |
//! |---|---|---|---|
//! | [`Lambert`] | `albedo / π` | yes | yes, albedo = `albedo` |
//! | [`CourseLambert`] | `kd` (the course's un-normalised form) | yes | only for `kd ≤ 1/π` |
//! | [`Phong`] | `kd + ks (cos⁺α)^shine / cos θ_i`, α from the mirror direction | no | no: `ρ(wi)` grows like `1 / cos θ_i` towards grazing |
//! | [`BlinnPhong`] | `kd + ks (cos⁺δ)^shine / cos θ_i`, δ from the half vector (course form) | no | no: `ρ(wi)` grows like `1 / cos θ_i` towards grazing |
//! | [`BlinnPhongReciprocal`] | `kd + ks (cos⁺δ)^shine / ‖wi + wo‖²` (the course's fix) | yes | not in general |
//!
//! All return 0 when either direction is at or below the surface, and NaN
//! for a NaN direction, as [`hemisphere`] decides it.

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use crate::radiance::cos_plus;
use crate::specular::reflect;
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
fn above<V: Vector3>(
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

/// The physically normalised Lambertian (ideal diffuse) BRDF,
/// `f_r = albedo / π`: it reflects the fraction `albedo` of the light it
/// receives, whatever the directions.
///
/// ```
/// use glam::DVec3;
/// use radiometry::brdf::{directional_albedo, Lambert};
/// let white = Lambert { albedo: 0.8 };
/// let rho = directional_albedo(&white, DVec3::Z, DVec3::Z, 16);
/// assert!((rho.albedo - 0.8).abs() < 1e-12);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lambert<T> {
    /// The fraction of incident power reflected, in `[0, 1]`.
    pub albedo: T,
}

impl<T: Real> Brdf<T> for Lambert<T> {
    #[inline]
    fn eval<V: Vector3<Scalar = T>>(&self, n: V, wi: V, wo: V) -> T {
        above(n, wi, wo, |_, _| self.albedo * T::FRAC_1_PI())
    }
}

/// The course's diffuse BRDF, `f_r = kd`, without the `1/π`: the reflected
/// radiance is `L_in kd cos⁺θ` (`003`, Lambert-törvény). Its albedo is
/// `π kd`, so it creates energy for `kd > 1/π`; it equals [`Lambert`] with
/// `albedo = π kd`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CourseLambert<T> {
    /// The diffuse coefficient `kd`, in 1/sr.
    pub kd: T,
}

impl<T: Real> Brdf<T> for CourseLambert<T> {
    #[inline]
    fn eval<V: Vector3<Scalar = T>>(&self, n: V, wi: V, wo: V) -> T {
        above(n, wi, wo, |_, _| self.kd)
    }
}

/// Phong's original model (B. T. Phong, "Illumination for computer generated
/// pictures", CACM 18(6), 1975), which the course replaces by Phong-Blinn,
/// written as a BRDF in the course's shape: a diffuse `kd` plus a lobe
/// around the mirror direction, divided by `cos θ_i` so that the reflected
/// radiance is `L_in (kd cos θ_i + ks (cos⁺α)^shine)`, with `cos α` between
/// the mirror image of `wi` and `wo`.
///
/// The division by `cos θ_i` breaks reciprocity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Phong<T> {
    /// Diffuse coefficient, in 1/sr.
    pub kd: T,
    /// Specular coefficient, in 1/sr.
    pub ks: T,
    /// The exponent: the larger, the smaller the highlight.
    pub shine: T,
}

impl<T: Real> Brdf<T> for Phong<T> {
    #[inline]
    fn eval<V: Vector3<Scalar = T>>(&self, n: V, wi: V, wo: V) -> T {
        above(n, wi, wo, |cos_i, _| {
            let cos_alpha = cos_plus(reflect(wi, n).dot(wo));
            self.kd + self.ks * cos_alpha.powf(self.shine) / cos_i
        })
    }
}

/// The course's Phong-Blinn BRDF (`003`, boxed formula):
/// `f_r = kd + ks (cos⁺δ)^shine / cos⁺θ_i`, with `cos δ = n · h` and the half
/// vector `h = (wi + wo) / ‖wi + wo‖`. The reflected radiance is
/// `L_in (kd + ks (cos⁺δ)^shine / cos⁺θ_i) cos⁺θ_i`.
///
/// The course notes that this violates Helmholtz reciprocity; the test
/// `helmholtz_reciprocity_fails_for_course_blinn_phong` measures by how much.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BlinnPhong<T> {
    /// Diffuse coefficient, in 1/sr.
    pub kd: T,
    /// Specular coefficient, in 1/sr.
    pub ks: T,
    /// The exponent: the larger, the smaller the highlight.
    pub shine: T,
}

impl<T: Real> Brdf<T> for BlinnPhong<T> {
    #[inline]
    fn eval<V: Vector3<Scalar = T>>(&self, n: V, wi: V, wo: V) -> T {
        above(n, wi, wo, |cos_i, _| {
            self.kd + self.ks * half_vector_lobe(n, wi, wo, self.shine) / cos_i
        })
    }
}

/// The course's reciprocal fix of [`BlinnPhong`]: `cos⁺θ_i` in the
/// denominator replaced by `‖wi + wo‖²`, which is symmetric in the two
/// directions: `f_r = kd + ks (cos⁺δ)^shine / ‖wi + wo‖²`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BlinnPhongReciprocal<T> {
    /// Diffuse coefficient, in 1/sr.
    pub kd: T,
    /// Specular coefficient, in 1/sr.
    pub ks: T,
    /// The exponent: the larger, the smaller the highlight.
    pub shine: T,
}

impl<T: Real> Brdf<T> for BlinnPhongReciprocal<T> {
    #[inline]
    fn eval<V: Vector3<Scalar = T>>(&self, n: V, wi: V, wo: V) -> T {
        above(n, wi, wo, |_, _| {
            let sum = wi + wo;
            self.kd + self.ks * half_vector_lobe(n, wi, wo, self.shine) / sum.dot(sum)
        })
    }
}

/// The half vector `h = (wi + wo) / ‖wi + wo‖` of Blinn's model, halfway
/// between the directions to the light and to the viewer; `None` when they
/// are opposite (`wi = −wo`) and no half vector exists.
///
/// ```
/// use glam::DVec3;
/// // The course's quiz 5: light from (0, 3, 4)/5, viewer at (0, 4, 3)/5.
/// let h = radiometry::brdf::half_vector(DVec3::new(0.0, 0.6, 0.8), DVec3::new(0.0, 0.8, 0.6)).unwrap();
/// assert!((h.z - 0.5_f64.sqrt()).abs() < 1e-15);
/// ```
#[inline]
pub fn half_vector<V: Vector3>(wi: V, wo: V) -> Option<V> {
    (wi + wo).try_normalize()
}

/// `(cos⁺δ)^shine` with `cos δ = n · h`; 0 if `wi = −wo`.
#[inline]
fn half_vector_lobe<V: Vector3>(n: V, wi: V, wo: V, shine: V::Scalar) -> V::Scalar {
    half_vector(wi, wo).map_or(V::Scalar::zero(), |h| cos_plus(n.dot(h)).powf(shine))
}

/// The worst violation of Helmholtz reciprocity found over a set of
/// direction pairs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReciprocityReport<V: Vector3> {
    /// The largest `|f_r(a, b) − f_r(b, a)|`, in 1/sr.
    pub worst_abs: V::Scalar,
    /// The largest `|f_r(a, b) − f_r(b, a)| / max(f_r(a, b), f_r(b, a))`.
    pub worst_rel: V::Scalar,
    /// The pair `(a, b)` where the relative violation is worst.
    pub worst_pair: (V, V),
    /// How many ordered pairs were compared.
    pub pairs: usize,
}

/// Checks Helmholtz reciprocity, `f_r(a, b) = f_r(b, a)`, over every pair
/// of `directions` at a surface with normal `n`, and reports the worst
/// asymmetry found (zero for a reciprocal BRDF up to rounding).
///
/// ```
/// use glam::DVec3;
/// use radiometry::brdf::{hemisphere_directions, reciprocity, BlinnPhongReciprocal};
/// let dirs = hemisphere_directions::<DVec3>(64);
/// let fixed = BlinnPhongReciprocal { kd: 0.2, ks: 0.5, shine: 20.0 };
/// assert!(reciprocity(&fixed, DVec3::Z, &dirs).worst_rel < 1e-14);
/// ```
pub fn reciprocity<V: Vector3, B: Brdf<V::Scalar>>(
    brdf: &B,
    n: V,
    directions: &[V],
) -> ReciprocityReport<V> {
    let zero = V::Scalar::zero();
    let mut report = ReciprocityReport {
        worst_abs: zero,
        worst_rel: zero,
        worst_pair: (n, n),
        pairs: 0,
    };
    for (i, &a) in directions.iter().enumerate() {
        for &b in &directions[i + 1..] {
            let (ab, ba) = (brdf.eval(n, a, b), brdf.eval(n, b, a));
            report.pairs += 2;
            let diff = (ab - ba).abs();
            let scale = ab.abs().max(ba.abs());
            report.worst_abs = report.worst_abs.max(diff);
            if scale > zero && diff / scale > report.worst_rel {
                report.worst_rel = diff / scale;
                report.worst_pair = (a, b);
            }
        }
    }
    report
}

/// `count` unit directions spread evenly over the hemisphere around +z
/// (a Fibonacci lattice), none exactly at the horizon.
pub fn hemisphere_directions<V: Vector3>(count: usize) -> Vec<V> {
    let golden_angle = V::Scalar::PI() * (V::Scalar::lit(3.0) - V::Scalar::lit(5.0).sqrt());
    (0..count)
        .map(|k| {
            let k = V::Scalar::lit(k as f64);
            let cos_theta =
                V::Scalar::one() - (k + V::Scalar::lit(0.5)) / V::Scalar::lit(count as f64);
            let sin_theta = (V::Scalar::one() - cos_theta * cos_theta).sqrt();
            let phi = golden_angle * k;
            V::new(sin_theta * phi.cos(), sin_theta * phi.sin(), cos_theta)
        })
        .collect()
}

/// A directional albedo with the estimated error of its quadrature.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AlbedoEstimate<T> {
    /// `ρ(wi) = ∫ f_r(wi, wo) cos θ_o dω_o` over the hemisphere, unitless.
    pub albedo: T,
    /// `|ρ_2N − ρ_N|`, the change from halving the quadrature step: an
    /// estimate of the quadrature error of `ρ_N`, so a conservative one of
    /// `albedo` (which is `ρ_2N`).
    pub error_estimate: T,
    /// How many BRDF evaluations the estimate took.
    pub evaluations: usize,
}

/// The directional albedo `ρ(wi) = ∫_H f_r(wi, wo) cos θ_o dω_o`, the
/// fraction of the power arriving from `wi` that the surface reflects into
/// the hemisphere; energy conservation requires `ρ ≤ 1` for every `wi`.
///
/// The integral is over the outgoing directions `wo`, whatever the BRDF: a
/// BRDF that is not reciprocal (the course's Phong-Blinn, which divides by
/// `cos θ_i`) can send a grazing `wi` more power than it received while
/// every integral over incoming directions stays below 1. For a reciprocal
/// BRDF the two integrals are the same.
///
/// Integrated with the midpoint rule in `(cos θ_o, φ_o)`, where
/// `dω = d(cos θ) dφ`, on an `n × 4n` grid and again on a `2n × 8n` grid;
/// the finer result is returned with their difference as its error
/// estimate. The midpoint rule is exact for an integrand linear in
/// `cos θ_o`, so Lambertian albedos come out exact to rounding.
pub fn directional_albedo<V: Vector3, B: Brdf<V::Scalar>>(
    brdf: &B,
    n: V,
    wi: V,
    resolution: usize,
) -> AlbedoEstimate<V::Scalar> {
    let resolution = resolution.max(1);
    let coarse = midpoint_albedo(brdf, n, wi, resolution);
    let fine = midpoint_albedo(brdf, n, wi, 2 * resolution);
    AlbedoEstimate {
        albedo: fine,
        error_estimate: (fine - coarse).abs(),
        evaluations: 4 * resolution * resolution + 16 * resolution * resolution,
    }
}

fn midpoint_albedo<V: Vector3, B: Brdf<V::Scalar>>(
    brdf: &B,
    n: V,
    wi: V,
    rows: usize,
) -> V::Scalar {
    let (t, b) = orthonormal_frame(n);
    let one = V::Scalar::one();
    let half = V::Scalar::lit(0.5);
    let columns = 4 * rows;
    let d_mu = one / V::Scalar::lit(rows as f64);
    let d_phi = V::Scalar::TAU() / V::Scalar::lit(columns as f64);
    let mut total = V::Scalar::zero();
    for row in 0..rows {
        let mu = (V::Scalar::lit(row as f64) + half) * d_mu;
        let sin_theta = (one - mu * mu).sqrt();
        let mut ring = V::Scalar::zero();
        for column in 0..columns {
            let phi = (V::Scalar::lit(column as f64) + half) * d_phi;
            let wo = t * (sin_theta * phi.cos()) + b * (sin_theta * phi.sin()) + n * mu;
            ring = ring + brdf.eval(n, wi, wo) * mu;
        }
        total = total + ring;
    }
    total * d_mu * d_phi
}

/// Two unit tangents completing the unit normal `n` to a right-handed
/// orthonormal frame (Duff et al., "Building an orthonormal basis,
/// revisited", JCGT 6(1), 2017).
fn orthonormal_frame<V: Vector3>(n: V) -> (V, V) {
    let [x, y, z] = n.to_array();
    let one = V::Scalar::one();
    let sign = one.copysign(z);
    let a = -one / (sign + z);
    let b = x * y * a;
    (
        V::new(one + sign * x * x * a, sign * b, -sign * x),
        V::new(b, sign + y * y * a, -y),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn orthonormal_frame_is_orthonormal() {
        for n in
            hemisphere_directions::<DVec3>(50)
                .into_iter()
                .chain([DVec3::Z, -DVec3::Z, DVec3::X])
        {
            let (t, b) = orthonormal_frame(n);
            for (u, v) in [(t, b), (t, n), (b, n)] {
                assert!(u.dot(v).abs() < 1e-15, "{u} · {v}");
            }
            for u in [t, b] {
                assert!((u.length() - 1.0).abs() < 1e-15);
            }
        }
    }

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
