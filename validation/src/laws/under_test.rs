//! The laws under test, one struct for both precision tiers: the radiometry
//! crate's by default ([`Laws::radiometry`]), or deliberately broken ones in
//! the fault-injection tests.

use radiometry::fresnel::{self, ConductorFresnel, DielectricFresnel};
use radiometry::specular::{self, Refraction};
use radiometry::{snell, Real};

/// A precision tier, `f32` or `f64`, with the vector its direction laws
/// take ([`Real::Vec3`]): the laws' own abstraction, under the name the
/// checks use.
pub use radiometry::Real as Tier;

/// A refraction law of tier `T`: `(wi, n, eta)` to the refracted direction
/// and the effective index, `None` under total internal reflection.
pub type RefractLaw<T> =
    fn(<T as Real>::Vec3, <T as Real>::Vec3, T) -> Option<Refraction<<T as Real>::Vec3>>;

/// The laws under test in tier `T`: `f32` ([`Laws`] alone, the tier the
/// tracer uses and Mitsuba is compared in) or `f64` ([`Laws64`]).
#[derive(Clone, Copy)]
pub struct Laws<T: Real = f32> {
    /// Exact dielectric Fresnel, `(cos_i, eta)`, either side.
    pub dielectric: fn(T, T) -> DielectricFresnel<T>,
    /// Exact conductor Fresnel, `(cos_i, n, kappa)`.
    pub conductor: fn(T, T, T) -> ConductorFresnel<T>,
    /// Mirror direction, `(w, n)`.
    pub reflect: fn(T::Vec3, T::Vec3) -> T::Vec3,
    /// Refracted direction, `(wi, n, eta)`; `None` under TIR.
    pub refract: RefractLaw<T>,
    /// Schlick's approximation, `(cos_i, f0)`.
    pub schlick: fn(T, T) -> T,
    /// Snell's law for angles, `(theta_i, eta_path)`; `None` under TIR.
    pub transmitted_angle: fn(T, T) -> Option<T>,
    /// The critical angle, `eta_path`.
    pub critical_angle: fn(T) -> Option<T>,
    /// Brewster's angle, `eta_path`.
    pub brewster_angle: fn(T) -> Option<T>,
}

/// The laws under test in `f64`.
pub type Laws64 = Laws<f64>;

impl<T: Real> Laws<T> {
    /// The radiometry crate's laws.
    pub fn radiometry() -> Self {
        Self {
            dielectric: fresnel::dielectric_polarized,
            conductor: fresnel::conductor_polarized,
            reflect: specular::reflect,
            refract: specular::refract,
            schlick: fresnel::schlick,
            transmitted_angle: snell::transmitted_angle,
            critical_angle: snell::critical_angle,
            brewster_angle: snell::brewster_angle,
        }
    }
}
