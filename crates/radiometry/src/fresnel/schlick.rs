//! Schlick's approximation, `F ≈ F0 + (1 − F0)(1 − cos θ)⁵` (C. Schlick,
//! *Computer Graphics Forum* 13(3), 1994), for any interface, and in two
//! forms for a dielectric seen from either side, each named by the cosine
//! it takes: the rarer medium's ([`schlick_dielectric`], Schlick's own, which
//! knows total internal reflection) and the incident one
//! ([`schlick_dielectric_incident`], the course's and most renderers', which
//! misses it).

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use super::normal_incidence::f0;
use crate::snell::{clamp_unit, Incidence};
use crate::specular::{refract_resolved, Refraction};
use crate::{Real, Vector3};

/// Schlick's approximation `F ≈ F0 + (1 − F0)(1 − cos θ)⁵`, as the course
/// uses it for dielectrics and metals alike (`003`, boxed formula).
///
/// `cos_i` is the cosine of the angle on the side the light arrives from;
/// its sign is ignored. For light leaving a denser dielectric this is the
/// wrong angle: see [`schlick_dielectric`].
///
/// ```
/// use radiometry::fresnel::schlick;
/// assert_eq!(schlick(1.0_f64, 0.04), 0.04); // exact at normal incidence
/// assert_eq!(schlick(0.0_f64, 0.04), 1.0); // and at grazing incidence
/// ```
#[inline]
pub fn schlick<T: Real>(cos_i: T, f0: T) -> T {
    let c = clamp_unit(cos_i.abs());
    // 1 − c is exact for c in [1/2, 1] (Sterbenz), where it matters most.
    f0 + (T::one() - f0) * (T::one() - c).powi(5)
}

/// [`schlick`] per channel, sharing one angle.
#[inline]
pub fn schlick_rgb<T: Real>(cos_i: T, f0: [T; 3]) -> [T; 3] {
    f0.map(|f0| schlick(cos_i, f0))
}

/// Which cosine Schlick's approximation took at a dielectric interface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SchlickCosine<T> {
    /// `|cos θ_i|`: the incident form took it whichever side the light
    /// arrives from; the rarer-medium form took it because the light
    /// arrives from the less dense side (or the indices match), and
    /// `cos θ_t` was not needed.
    Incident,
    /// `cos θ_t`, given: the light arrives from the denser side, and the
    /// angle in the rarer medium is the transmitted one.
    Transmitted(T),
    /// None: beyond the critical angle nothing is transmitted and `R = 1`
    /// exactly.
    TotalInternalReflection,
}

/// Schlick's approximation at a dielectric interface, with its working: the
/// `F0` and the cosine it took, and the side it resolved.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SchlickDielectric<T> {
    /// The approximate unpolarised reflectance, in `[0, 1]`.
    pub reflectance: T,
    /// The normal-incidence reflectance `((η − 1)/(η + 1))²`, the same from
    /// both sides.
    pub f0: T,
    /// Which cosine the approximation took, with `cos θ_t` when it took it.
    pub cosine: SchlickCosine<T>,
    /// The side, the indices `n_i`, `n_t` and `|cos θ_i|`.
    pub incidence: Incidence<T>,
}

impl<T: Real> SchlickDielectric<T> {
    /// The cosine the approximation was evaluated at, `|cos θ_i|` or
    /// `cos θ_t` as [`SchlickDielectric::cosine`] says; `None` under total
    /// internal reflection, where no cosine was used.
    #[inline]
    pub fn cosine_used(&self) -> Option<T> {
        match self.cosine {
            SchlickCosine::Incident => Some(self.incidence.abs_cos_i),
            SchlickCosine::Transmitted(cos_t) => Some(cos_t),
            SchlickCosine::TotalInternalReflection => None,
        }
    }

    /// `cos θ_t ≥ 0`, or `None` under total internal reflection: the one
    /// Schlick took from the denser side; from the rarer side, where the
    /// approximation needs none, Snell's law is evaluated here, when asked
    /// ([`Incidence::cos_transmitted`]).
    #[inline]
    pub fn cos_t(&self) -> Option<T> {
        match self.cosine {
            SchlickCosine::Incident => self.incidence.cos_transmitted(),
            SchlickCosine::Transmitted(cos_t) => Some(cos_t),
            SchlickCosine::TotalInternalReflection => None,
        }
    }

    /// The transmitted fraction `1 − R` (Schlick's approximation has no
    /// separate law for it).
    #[inline]
    pub fn transmittance(&self) -> T {
        T::one() - self.reflectance
    }

    /// Whether the form decided that Snell's law has no solution and all
    /// light is reflected: the rarer-medium form past the critical angle;
    /// never the incident form, which misses it.
    #[inline]
    pub fn is_total_internal_reflection(&self) -> bool {
        matches!(self.cosine, SchlickCosine::TotalInternalReflection)
    }

    /// The effective relative index along the path, `n_t / n_i`.
    #[inline]
    pub fn eta_path(&self) -> T {
        self.incidence.eta_path()
    }

    /// The refracted ray of `wi` about `n`, the vectors whose `dot(n, wi)`
    /// this working was made at, from the side it resolved and
    /// [`SchlickDielectric::cos_t`] ([`refract_resolved`]); `None` under
    /// total internal reflection.
    #[inline]
    pub fn refraction<V: Vector3<Scalar = T>>(&self, wi: V, n: V) -> Option<Refraction<V>> {
        let cos_t = self.cos_t()?;
        Some(refract_resolved(wi, n, &self.incidence, cos_t))
    }
}

/// Schlick's approximation in its rarer-medium form, for a dielectric
/// interface seen from either side, with `F0 = ((η − 1)/(η + 1))²` and the
/// cosine taken in the less dense medium: from the denser side it uses `cos θ_t`, and under total internal
/// reflection it returns exactly 1. NaN for input that describes no
/// interface (a NaN cosine, `eta` not positive and finite).
///
/// Schlick (1994) states the approximation in terms of the angle in the
/// rarer medium; applied with `cos θ_i` from inside glass it misses total
/// internal reflection entirely (by up to 0.975 for water, measured by
/// `cargo run --release -p radiometry --example schlick_error`), while with
/// `cos θ_t` it is as close as from the outside. That other form is
/// [`schlick_dielectric_incident`].
///
/// This is [`schlick_dielectric_working`]'s reflectance.
#[inline(always)]
pub fn schlick_dielectric<T: Real>(cos_i: T, eta: T) -> T {
    // Evaluated whatever the input, NaN chosen after it for input that
    // describes no interface: no branch, so loops vectorise.
    let (incidence, valid) = Incidence::resolve_unchecked(cos_i, eta);
    let reflectance = schlick_dielectric_resolved(&incidence).reflectance;
    if valid {
        reflectance
    } else {
        T::nan()
    }
}

/// [`schlick_dielectric`] with its working, for a signed `cos_i` and
/// `eta = n_inside / n_outside`; `None` for input that describes no
/// interface.
///
/// ```
/// use radiometry::fresnel::{schlick_dielectric, schlick_dielectric_working, SchlickCosine};
/// // From inside glass at 60°, beyond the critical angle: R = 1, no cosine used.
/// let tir = schlick_dielectric_working(-0.5_f64, 1.5).unwrap();
/// assert_eq!((tir.reflectance, tir.cosine), (1.0, SchlickCosine::TotalInternalReflection));
/// // From inside at normal incidence it takes cos θ_t, here 1: R = F0 = 0.04.
/// let inside = schlick_dielectric_working(-1.0_f64, 1.5).unwrap();
/// assert_eq!(inside.cosine, SchlickCosine::Transmitted(1.0));
/// assert_eq!(inside.reflectance, schlick_dielectric(-1.0, 1.5));
/// assert!((inside.reflectance - 0.04).abs() < 1e-16);
/// ```
#[inline]
pub fn schlick_dielectric_working<T: Real>(cos_i: T, eta: T) -> Option<SchlickDielectric<T>> {
    Incidence::resolve(cos_i, eta).map(|incidence| schlick_dielectric_resolved(&incidence))
}

/// [`schlick_dielectric_working`] at an incidence already resolved, for a
/// caller that evaluates several laws at one incidence and decides its side
/// once.
#[inline(always)]
pub fn schlick_dielectric_resolved<T: Real>(incidence: &Incidence<T>) -> SchlickDielectric<T> {
    let eta = if incidence.from_inside {
        incidence.n_i
    } else {
        incidence.n_t
    };
    // F0 is the same from both sides: ((η−1)/(η+1))² = ((1/η−1)/(1/η+1))².
    let f0 = f0(eta, T::zero());
    // Snell's law is decided whichever cosine is taken and the outcome chosen
    // after it, by value, so that a loop over many cosines vectorises; the
    // same decision and cosine as `Incidence::cos_transmitted`.
    let snell = incidence.snell::<false>();
    let cos_t = incidence.cos_from_root(snell.discriminant.max(T::Wide::zero()).sqrt());
    let (cosine, reflectance) = if incidence.n_t >= incidence.n_i {
        (SchlickCosine::Incident, schlick(incidence.abs_cos_i, f0))
    } else if snell.transmits {
        (SchlickCosine::Transmitted(cos_t), schlick(cos_t, f0))
    } else {
        (SchlickCosine::TotalInternalReflection, T::one())
    };
    SchlickDielectric {
        reflectance,
        f0,
        cosine,
        incidence: *incidence,
    }
}

/// Schlick's approximation in its incident form, for a dielectric interface
/// seen from either side: `F0 = ((η − 1)/(η + 1))²` and `|cos θ_i|`
/// wherever the light arrives from, as the course (`003`) and most real-time
/// renderers write it. NaN for input that describes no interface.
///
/// From the rarer side it is [`schlick_dielectric`] to the bit. From the
/// denser side it misses total internal reflection: beyond the critical
/// angle it reflects less than 1 where nothing can be transmitted (inside
/// glass at 60°, 0.0700 where the exact law gives 1), and a renderer using
/// it loses the rest.
///
/// ```
/// use radiometry::fresnel::{dielectric, schlick_dielectric_incident};
/// // Entering glass at normal incidence it is exact: F0 = 0.04.
/// assert!((schlick_dielectric_incident(1.0_f64, 1.5) - 0.04).abs() < 1e-16);
/// // Inside glass at 60°, past the critical angle (41.8°), it reflects 7 %.
/// let (exact, incident) = (dielectric(-0.5_f64, 1.5), schlick_dielectric_incident(-0.5_f64, 1.5));
/// assert_eq!(exact, 1.0);
/// assert!((incident - 0.0700).abs() < 1e-4);
/// ```
#[inline]
pub fn schlick_dielectric_incident<T: Real>(cos_i: T, eta: T) -> T {
    match Incidence::resolve(cos_i, eta) {
        Some(incidence) => schlick_dielectric_incident_resolved(&incidence).reflectance,
        None => T::nan(),
    }
}

/// [`schlick_dielectric_incident`] with its working at an incidence already
/// resolved: its cosine is always [`SchlickCosine::Incident`], and under
/// total internal reflection its reflectance is below 1 while
/// [`SchlickDielectric::cos_t`] and [`SchlickDielectric::refraction`] are
/// `None` (Snell's law, evaluated when asked, has no solution).
#[inline]
pub fn schlick_dielectric_incident_resolved<T: Real>(
    incidence: &Incidence<T>,
) -> SchlickDielectric<T> {
    let eta = if incidence.from_inside {
        incidence.n_i
    } else {
        incidence.n_t
    };
    let f0 = f0(eta, T::zero());
    SchlickDielectric {
        reflectance: schlick(incidence.abs_cos_i, f0),
        f0,
        cosine: SchlickCosine::Incident,
        incidence: *incidence,
    }
}
