//! The optics laws of radiometry and ray tracing, each written once and
//! exactly, beside the approximations renderers use in their place.
//!
//! This crate is pure: no I/O, no global state, no panics on any input. The
//! tracer and the `optics` calculator compose these functions and never
//! re-derive a formula.
//!
//! ```
//! use radiometry::fresnel;
//!
//! // Glass (n = 1.5) in air reflects 4 % of the light at normal incidence.
//! let r = fresnel::dielectric(1.0_f64, 1.5);
//! assert!((r - 0.04).abs() < 1e-15);
//!
//! // Schlick's approximation agrees at normal incidence and departs elsewhere.
//! let f0 = fresnel::f0(1.5, 0.0);
//! let cos_60deg = 0.5_f64;
//! let (exact, schlick) = (fresnel::dielectric(cos_60deg, 1.5), fresnel::schlick(cos_60deg, f0));
//! assert!((exact - 0.0892).abs() < 1e-4 && (schlick - 0.0700).abs() < 1e-4);
//! ```
//!
//! # Modules
//!
//! | module | law or model |
//! |---|---|
//! | [`snell`] | Snell's law for angles and cosines, the critical and Brewster angles |
//! | [`specular`] | directions of mirror reflection and refraction |
//! | [`fresnel`] | exact dielectric and conductor reflectance, F0, Schlick |
//! | [`radiance`] | radiance, irradiance, directional and point lights, `cos⁺` |
//! | [`brdf`] | Lambert, Phong, Blinn-Phong, their checkers (reciprocity, albedo) |
//! | [`spectrum`] | sampled spectra on the CIE grid, CIE 1931 XYZ under D65 |
//! | [`colour`] | linear and encoded sRGB, CIELAB, the CIEDE2000 colour difference |
//! | [`course`] | the course's formulas exactly as written, errors included, for auditing |
//! | [`domain`] | validation of user input into the domain of the laws |
//!
//! # Conventions
//!
//! Every function in this crate follows these; none restates a different one.
//!
//! - **Directions point away from the surface.** `wi` points from the
//!   surface point towards where the light comes from, `wo` towards the
//!   viewer, and a refracted `wt` away from the surface on the other side.
//!   All direction arguments are unit vectors.
//! - **The normal `n` points to the outside.** The outside is the side the
//!   normal points into; the inside is the other side.
//! - **`cos_i` is `dot(n, wi)`, signed.** `cos_i > 0` means the light arrives
//!   from the outside, `cos_i < 0` from the inside. Laws valid from both sides
//!   (dielectric Fresnel, refraction) take the sign into account themselves.
//! - **`eta` is `n_inside / n_outside`**, the relative index of refraction
//!   across the interface. For light arriving from the outside (`cos_i > 0`)
//!   this is `n_t / n_i`; from the inside the laws use `1 / eta`. Glass in air
//!   has `eta = 1.5`. A conductor's index is complex, `n + i·kappa`, with
//!   `kappa ≥ 0` the extinction coefficient (absorption), and light is assumed
//!   to arrive from the outside (the dielectric side). The functions of
//!   unsigned angles in [`snell`] (`transmitted_angle`, `critical_angle`,
//!   `brewster_angle`) have no sign to read the side from; they take the
//!   index along the path, named `eta_path = n_t / n_i`, and every
//!   [`specular::Refraction`] reports the `eta_path` it took.
//! - **A law hands back what it decided.** The side of the interface is
//!   resolved once, by [`snell::Incidence::resolve`], and whether light is
//!   transmitted, with `cos θ_t`, once, by
//!   [`snell::Incidence::cos_transmitted`]. [`fresnel::DielectricFresnel`]
//!   carries that incidence and `cos θ_t`, [`fresnel::SchlickDielectric`]
//!   the incidence and the cosine it took, and
//!   [`specular::refract_resolved`] builds the refracted ray from them, so a
//!   caller never decides again what a law decided (the test
//!   `decided_once` holds the handed-back values to the law's, bit for bit).
//! - **Angles are in radians**, measured from the normal.
//! - **SI units**: radiance in W/(sr·m²), irradiance in W/m², radiant
//!   intensity in W/sr, BRDFs in 1/sr, lengths in metres. Reflectances and
//!   transmittances are unitless fractions in `[0, 1]`.
//! - **Precision**: every law is generic over [`Real`] (`f32` and `f64`). `f64`
//!   is the reference; `f32` is what a tracer uses, and the test suite
//!   measures the difference against 50-digit references.
//! - **Indices** (`eta`, `eta_path`, `n`, `kappa > 0`) are valid from 1e-50
//!   to 1e50 in `f64` and from 1e-9 to 1e9 in `f32`: the laws form fourth
//!   powers of them, which must stay finite and normal. Within that range no
//!   law of an index (Fresnel, Schlick, refraction, the angles, radiance
//!   across an interface) gives NaN or infinity for a valid input (the test
//!   `valid_input_never_gives_nan_or_infinity`); [`domain::INDEX_RANGE`]
//!   refuses what lies beyond it in user input.
//! - **Out-of-domain input** never panics. A NaN argument, or an index that
//!   is not positive and finite, gives NaN where the law returns a number and
//!   `None` where it returns an optional outcome (a refracted direction, a
//!   transmitted cosine, an angle). A cosine slightly outside `[-1, 1]` (as
//!   rounding produces from a dot product) is clamped into it. Callers that
//!   take user input validate it first with [`domain`].
//!
//! ```
//! use glam::DVec3;
//! use radiometry::specular::{reflect, refract};
//!
//! let n = DVec3::Z; // the outside is +z
//! let wi = DVec3::new(0.6, 0.0, 0.8); // light from the outside: dot(n, wi) > 0
//! assert!((reflect(wi, n) - DVec3::new(-0.6, 0.0, 0.8)).length() < 1e-15);
//!
//! // Into glass: the refracted direction points away on the inside, and the
//! // effective eta along the path is n_t / n_i = 1.5.
//! let t = refract(wi, n, 1.5).expect("no total internal reflection entering glass");
//! assert!(t.direction.z < 0.0 && t.eta_path == 1.5);
//!
//! // Out of glass at a steep angle: total internal reflection is `None`.
//! let from_inside = DVec3::new(0.8, 0.0, -0.6);
//! assert!(refract(from_inside, n, 1.5).is_none());
//! ```

// One module may call code compiled for wider instructions, after checking
// the CPU has them (`fresnel::slice`); nothing else is `unsafe`.
#![deny(unsafe_code)]
#![warn(missing_docs)]
// `!(x > 0)` is written on purpose throughout: unlike `x <= 0` it is also true for NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod brdf;
#[rustfmt::skip]
mod cie_tables;
pub mod colour;
mod compensated;
pub mod course;
pub mod domain;
pub mod fresnel;
pub mod photon;
pub mod radiance;
mod real;
pub mod snell;
pub mod spectrum;
pub mod specular;

pub use real::{Real, Vector3};
