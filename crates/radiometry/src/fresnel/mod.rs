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
//! | [`schlick`] | Schlick's approximation at a given cosine | C. Schlick, *Computer Graphics Forum* 13(3), 1994 |
//! | [`schlick_dielectric`] | Schlick's, rarer-medium form: `cos θ_t` from the denser side, total internal reflection right | Schlick 1994 |
//! | [`schlick_dielectric_incident`] | Schlick's, incident form: `cos θ_i` from either side, as the course writes it; misses total internal reflection | course text `003` |
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

mod algebra;
mod conductor;
mod dielectric;
mod normal_incidence;
mod schlick;
mod slice;

pub use conductor::{conductor, conductor_polarized, conductor_rgb, Conductor, ConductorFresnel};
pub use dielectric::{
    dielectric, dielectric_polarized, dielectric_resolved, dielectric_rgb,
    dielectric_transmittance, DielectricFresnel,
};
pub use normal_incidence::{f0, f0_rgb};
pub use schlick::{
    schlick, schlick_dielectric, schlick_dielectric_incident, schlick_dielectric_incident_resolved,
    schlick_dielectric_resolved, schlick_dielectric_working, schlick_rgb, SchlickCosine,
    SchlickDielectric,
};
pub use slice::{
    conductor_slice, conductor_slice_on, dielectric_slice, dielectric_slice_on, Lanes,
};
