//! The rasteriser-side techniques of the course's realistic-scene slides
//! (`001_...`): formulas a rasteriser uses in place of tracing rays. They
//! are not laws of light, so they live apart from `radiometry` (whose
//! laws they call, and whose conventions they follow: directions point away
//! from the surface); each is checked against an exact answer, the one a
//! traced ray gives or the technique's own way back.
//!
//! ```
//! use glam::DVec3;
//! use techniques::envmap::{cube, Direction};
//! use techniques::planar::{project_shadow, Plane, Shadow};
//!
//! // The slides' cube-map example: (−3.2, 5.1, −8.4) is looked up on −Z.
//! let r = Direction::new(DVec3::new(-3.2, 5.1, -8.4)).unwrap();
//! assert_eq!(cube::Face::of(r), cube::Face::NegativeZ);
//!
//! // A light 4 m above the floor casts the shadow of a vertex 2 m up, 1 m
//! // aside, 2 m aside.
//! let floor = Plane::through(DVec3::ZERO, DVec3::Y).unwrap();
//! let shadow = project_shadow(DVec3::new(0.0, 4.0, 0.0), &floor, DVec3::new(1.0, 2.0, 0.0));
//! assert_eq!(shadow, Shadow::Cast(DVec3::new(2.0, 0.0, 0.0)));
//! ```
//!
//! | module | technique | slides |
//! |---|---|---|
//! | [`bump`] | bump mapping: a height field's finite-difference slopes `b_u`, `b_v` bend the shading normal, `N' = N + b_u (n̂ × P_v) − b_v (n̂ × P_u)` (Blinn) | "Felületi egyenetlenség leképezés - Bump mapping" |
//! | [`envmap`] | environment maps: a reflected direction to its texel in a latitude–longitude, cube or sphere map, and back | "Környezet leképezés" |
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
//! writes the direction of travel `I`, it is `−wi`. The environment maps'
//! own conventions (their frame, seams and texel ranges) are stated once, in
//! [`envmap`].

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod bump;
pub mod dispersion;
pub mod empirical_fresnel;
pub mod envmap;
pub mod planar;
pub mod refraction;
