//! The Fresnel equations: the fraction of light power reflected (and
//! transmitted) by a smooth interface, for dielectrics and conductors, with
//! the course's approximations beside them. All results are unitless
//! fractions in `[0, 1]`.
//!
//! | function | law | source |
//! |---|---|---|
//! | [`dielectric_polarized`], [`dielectric`], [`dielectric_transmittance`] | exact, real index, either side | Born & Wolf, *Principles of Optics*, §1.5.2 |
//! | [`conductor_polarized`], [`conductor`] | exact, complex index `n + i·kappa` | Born & Wolf §14.2; pbrt-v4 §9.5 |
//! | [`f0`] | normal-incidence reflectance `((n−1)² + κ²) / ((n+1)² + κ²)` | course text `003`, Born & Wolf §14.2 eq. 15 |
//! | [`schlick`], [`schlick_dielectric`] | Schlick's approximation | C. Schlick, *Computer Graphics Forum* 13(3), 1994 |
//!
//! # What the dielectric laws hand back
//!
//! A dielectric law decides the side of the interface, and whether Snell's
//! law has a solution, once: [`dielectric_polarized`] returns them in its
//! [`DielectricFresnel`] (the [`Incidence`](crate::snell::Incidence) and
//! `cos_t`), and [`schlick_dielectric_working`] in its [`SchlickDielectric`],
//! with the cosine Schlick took (and `cos θ_t` when it took that one). Callers narrate or refract from those
//! ([`crate::specular::refract_resolved`]); the `*_resolved` forms take an
//! incidence already resolved, so a caller evaluating several laws at one
//! incidence resolves it once.

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use crate::Real;

mod conductor;
mod dielectric;
mod schlick;
mod slice;

pub use conductor::{conductor, conductor_polarized, conductor_rgb, Conductor, ConductorFresnel};
pub use dielectric::{
    dielectric, dielectric_polarized, dielectric_resolved, dielectric_rgb,
    dielectric_transmittance, DielectricFresnel,
};
pub use schlick::{
    schlick, schlick_dielectric, schlick_dielectric_resolved, schlick_dielectric_working,
    schlick_rgb, SchlickCosine, SchlickDielectric,
};
pub use slice::{
    conductor_slice, conductor_slice_on, dielectric_slice, dielectric_slice_on, Lanes,
};

/// Normal-incidence reflectance `F0 = ((n − 1)² + κ²) / ((n + 1)² + κ²)` of
/// an interface from a medium of index 1 into one of index `n + i·kappa`.
///
/// For a dielectric (`kappa = 0`) this is `((η − 1) / (η + 1))²` for either
/// direction of travel. NaN for `n ≤ 0` or `kappa < 0`.
///
/// ```
/// use radiometry::fresnel::{f0, f0_rgb};
/// // Glass: 4 %.
/// assert!((f0(1.5_f64, 0.0) - 0.04).abs() < 1e-16);
/// // The course's gold, n = (0.17, 0.35, 1.5), κ = (3.1, 2.7, 1.9): yellow.
/// let gold = f0_rgb([0.17_f64, 0.35, 1.5], [3.1, 2.7, 1.9]);
/// let expected = [0.938064, 0.846365, 0.391481];
/// for (got, want) in gold.iter().zip(expected) {
///     assert!((got - want).abs() < 1e-6);
/// }
/// ```
#[inline]
pub fn f0<T: Real>(n: T, kappa: T) -> T {
    let k2 = kappa * kappa;
    let below = (n - T::one()) * (n - T::one()) + k2;
    let above = (n + T::one()) * (n + T::one()) + k2;
    // Chosen after the computation, not branched around it, so that loops
    // over the laws that use it vectorise.
    if n > T::zero() && kappa >= T::zero() {
        below / above
    } else {
        T::nan()
    }
}

/// [`f0`] per channel.
#[inline]
pub fn f0_rgb<T: Real>(n: [T; 3], kappa: [T; 3]) -> [T; 3] {
    core::array::from_fn(|ch| f0(n[ch], kappa[ch]))
}

#[inline]
fn sqr<T: Real>(x: T) -> T {
    x * x
}

/// Clamps a fraction into `[0, 1]` against rounding, keeping NaN.
#[inline]
fn fraction<T: Real>(x: T) -> T {
    if x > T::one() {
        T::one()
    } else {
        x
    }
}
