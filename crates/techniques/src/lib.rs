//! The rasteriser-side techniques of the course's realistic-scene slides
//! (`001_...`): formulas a rasteriser uses in place of tracing rays. They
//! are not laws of light, so they live apart from `radiometry`; each is
//! checked against the exact answer a ray gives.
//!
//! | module | technique | slides |
//! |---|---|---|
//! | [`planar`] | the reflection matrix `M = F⁻¹ S(1, −1, 1) F` of a plane; the projected-shadow matrix of a point light onto a plane | "Tükröződések", "Vetített árnyék" |
//! | [`refraction`] | the cheap refraction `t = normalize(−c n + i)` against Snell's law, from either side | "Snell törvénye" |
//! | [`empirical_fresnel`] | `max(0, min(1, bias + scale (1 + I·N)^power))` fitted to the exact Fresnel law per material, beside Schlick | "Fresnel egyenletek", `C7E5v_dispersion` |
//! | [`dispersion`] | Schott N-BK7's Sellmeier index `n(λ)`, the per-channel "three eta" ratios, the prism's minimum deviation | "Fénytörés ... hullámhosszától", `C7E5v_dispersion` |
//!
//! ```
//! use techniques::dispersion::{fraunhofer_nm, prism::Prism, SELLMEIER_N_BK7};
//! use techniques::refraction::{compare_at, Constant, Side};
//!
//! // N-BK7 at the helium d line: 1.51680 on Schott's data sheet.
//! let n_d = SELLMEIER_N_BK7.index_at(fraunhofer_nm::D).unwrap();
//! assert!((n_d - 1.51680).abs() < 5e-6);
//!
//! // A 60° prism of it deviates the d line by 38.65° at least.
//! let prism = Prism::new(60f64.to_radians()).unwrap();
//! assert!((prism.minimum_deviation(n_d).unwrap().to_degrees() - 38.6467).abs() < 1e-4);
//!
//! // The slides' cheap refraction with c = 1 is 4.5° off Snell's law
//! // entering glass at 30°.
//! let off = compare_at(30f64.to_radians(), Side::Outside, 1.5, Constant::Fixed(1.0));
//! assert!((off.unwrap().error().unwrap().to_degrees() - 4.4712).abs() < 1e-4);
//! ```
//!
//! Conventions: `f64` throughout (these are checks of formulas, not a
//! renderer's inner loop). The matrices of [`planar`] act on column
//! vectors, `M v`, as the slides and glam write them; a plane is
//! `n · x + d = 0` with `n` a unit vector. Directions, normals, cosines and
//! `eta` follow the `radiometry` crate's conventions (directions point away
//! from the surface, `eta = n_inside / n_outside`, radians), and the laws of
//! light are called from there, never written again here; where a slide
//! writes the direction of travel `I`, it is `−wi`.

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod dispersion;
pub mod empirical_fresnel;
pub mod planar;
pub mod refraction;
