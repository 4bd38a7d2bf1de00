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
//! | [`envmap`] | environment maps: a reflected direction to its texel in a latitude–longitude, cube or sphere map, and back | "Környezet leképezés" |
//! | [`planar`] | the reflection matrix `M = F⁻¹ S(1, −1, 1) F` of a plane; the projected-shadow matrix of a point light onto a plane | "Tükröződések", "Vetített árnyék" |
//!
//! Conventions: `f64` throughout (these are the reference answers, not a
//! renderer's per-pixel code); column vectors, `M v`, as the slides and
//! glam write them; a plane is `n · x + d = 0` with `n` a unit vector; the
//! environment maps' own conventions (their frame, seams and texel
//! ranges) are stated once, in [`envmap`].

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod envmap;
pub mod planar;
