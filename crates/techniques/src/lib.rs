//! The rasteriser-side techniques of the course's realistic-scene slides
//! (`001_...`): formulas a rasteriser uses in place of tracing rays. They
//! are not laws of light, so they live apart from `radiometry`; each is
//! checked against the exact answer a ray gives.
//!
//! | module | technique | slides |
//! |---|---|---|
//! | [`envmap`] | environment maps: a reflected direction to its texel in a latitude–longitude, cube or sphere map, and back | "Környezet leképezés" |
//! | [`planar`] | the reflection matrix `M = F⁻¹ S(1, −1, 1) F` of a plane; the projected-shadow matrix of a point light onto a plane | "Tükröződések", "Vetített árnyék" |
//!
//! Conventions: `f64` throughout (these are 4 × 4 matrices built once per
//! plane, not per pixel); column vectors, `M v`, as the slides and glam
//! write them; a plane is `n · x + d = 0` with `n` a unit vector.

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod envmap;
pub mod planar;
