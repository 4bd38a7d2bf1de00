//! The BRDF models: Lambert's, the course's (its Lambert and Phong-Blinn,
//! and the reciprocal fix), and classic Phong.

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use super::hemisphere::{above, Brdf};
use crate::radiance::cos_plus;
use crate::specular::reflect;
use crate::{Real, Vector3};

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
