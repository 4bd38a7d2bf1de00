//! The three levels of light transport of `003` ("lokális illumináció",
//! "rekurzív sugárkövetés", "globális illumináció") and the course shader's
//! own loop, all on one scene, all shading with the `radiometry` laws.
//!
//! | integrator | at a rough surface | at a mirror or glass | cost |
//! |---|---|---|---|
//! | [`local`] | ambient + direct light, shadow rays | background seen in the mirror direction is not traced: black | 1 ray + 1 per light |
//! | [`whitted`] | ambient + direct light, shadow rays | recursion, Fresnel-weighted, to `max_depth`, cut below `throughput_cutoff` | grows with mirrors |
//! | [`path`] | direct light + one cosine-sampled bounce (no ambient: the indirect light is computed) | one branch, chosen with the Fresnel probability | `spp` paths per pixel |
//! | [`photon`] | as `path`, plus the caustic photon map's radiance (delta lights through mirrors and glass) | as `path`; photons follow one lobe each | `spp` paths per pixel + `photons × passes` photons |
//! | [`course`] | the final GLSL shader of `000`, bugs included | | |
//!
//! The physical integrators never look at a material: they ask the hit
//! what it does with light ([`scatter::Surface`]), take a rough surface's
//! direct light from [`direct`], and a smooth one's lobes from
//! [`scatter::Lobes`], where each specular decision is made once. The
//! course's loop keeps its own rules, intersection included, in [`course`].
//!
//! Radiance is in W/(sr·m²) per channel. The tracer computes at its
//! precision tier ([`radiometry::Vector3`], `Settings::precision`): `local`,
//! `whitted` and the steps they share in `f32` or `f64`; `path`, `photon`
//! and `course` in `f32` only.

pub mod course;
pub mod direct;
pub mod local;
pub mod path;
mod pending;
pub mod photon;
pub mod scatter;
mod shortcut;
pub mod whitted;

mod counts;
mod hemisphere;
mod machinery;
mod primary;
mod tracer;

pub use counts::{Bounce, RayCounts};
pub use hemisphere::cosine_sample;
pub use machinery::Machinery;
pub(crate) use primary::Primary;
pub use tracer::Tracer;
