//! The course's ray tracers, built only from the laws of the `radiometry`
//! crate: scene files, the course's primitives and cameras, three levels of
//! light transport (`local`, `whitted`, `path`), the path tracer with a
//! caustic photon map (`photon`) and the course shader's own loop
//! (`course`), images in PNG and PFM.
//!
//! Every shading formula (BRDFs, Fresnel, irradiance of the lights, mirror
//! and refraction directions, radiance across an interface) is a call into
//! `radiometry`; this crate adds geometry, sampling and bookkeeping.
//!
//! ```
//! use tracer::job::{Overrides, RenderJob};
//! use tracer::scene;
//!
//! // The course's first picture: a red sphere at (1, 1, 4), seen from (0, 0, −2).
//! let scene = scene::parse(r#"{
//!     "version": 1,
//!     "image": { "width": 32, "height": 24 },
//!     "camera": { "type": "course_pinhole" },
//!     "materials": { "red": { "type": "flat", "radiance": [1, 0, 0] } },
//!     "objects": [ { "type": "sphere", "center": [1, 1, 4], "radius": 0.8, "material": "red" } ]
//! }"#).unwrap();
//! let job = RenderJob::new(scene, &Overrides::default()).unwrap();
//! let out = job.render(Some(1), &|_| {}).unwrap();
//! // Up and to the right of the centre, as the course says; the centre is empty.
//! assert_eq!(out.image.get(20, 8).to_array(), [1.0, 0.0, 0.0]);
//! assert_eq!(out.image.get(16, 12).to_array(), [0.0, 0.0, 0.0]);
//! ```
//!
//! # Modules
//!
//! | module | what |
//! |---|---|
//! | [`job`] | the way in: a scene with its settings settled once, rendered and written |
//! | [`kinds`] | the settings' vocabulary: integrator, Fresnel law, glass shortcut, pixel filter, ray offset, precision, the counts' limits |
//! | [`scene`] | the JSON scene schema, parsing and validation (`docs/scene-schema.md`), the settings |
//! | [`geometry`] | rays, spheres, two-sided planes, the kaleidoscope's mirror tube |
//! | [`bump`] | an object's bump map: the hit's shading normal bent, its geometry untouched |
//! | [`camera`] | the course's pinhole and the look-at camera unprojected through the inverse view-projection |
//! | [`environment`] | what rays that leave the scene receive: a procedural sky, a lat-long or cube map looked up through `techniques::envmap`, |
//! | [`capture`] | the slides' capture of a cube map by tracing |
//! | [`filter`] | the pixel filter: stratified rays over the pixel (box) or its centre |
//! | [`spawn`] | where secondary rays start: the hit's error bound, or the course's fixed epsilon |
//! | [`integrator`] | `local`, `whitted`, `path`, `photon` (the path tracer plus a caustic photon map) and the course shader's loop, one file each, and the shared scatter step |
//! | [`needs`] | what a scene needs, so the renderer runs only that |
//! | [`trap`] | the rays a mirror tube holds until their depth runs out, whose paths end early |
//! | [`chains`] | which delta lights reach a rough surface through mirrors or glass: the light no integrator computes |
//! | [`render`] | the image, in parallel, identical for any thread count |
//! | [`sampler`] | the camera paths' numbers: Owen-scrambled Sobol pairs, each pixel's samples stratified in every pair of dimensions |
//! | [`rng`] | PCG32 streams, one per photon |
//! | [`output`] | PNG (sRGB, stated tone mapping) and PFM, the destination checked before the render, the pair written atomically (through `safe_io`) |
//!
//! # Precision
//!
//! The tracer computes in `f32` by default, the precision of the course's
//! shaders and of production renderers, so that the course's precision
//! problems are reproduced and their fixes shown where they matter: the
//! sphere intersection is the stable form ([`geometry::Sphere::roots`]), hit
//! points are re-projected onto their surface and carry an error bound, and
//! secondary rays are offset by that bound ([`spawn`]). Cameras are built in
//! `f64` and rounded once; pixel means are summed in `f64`.
//!
//! `local` and `whitted` also compute in `f64` (`render.precision`,
//! [`kinds::Precision`]): the geometry, the camera ray, the direct light and
//! the specular lobes are written once over [`radiometry::Vector3`] and
//! call the laws at the same tier; the scene, validated in `f32`, is
//! widened once, exactly, when a tier's world is built
//! ([`scene::model::World`]), so both tiers read the same numbers and
//! differ only in the arithmetic. The image is `f32` radiance either way,
//! each pixel's mean rounded once at the end. `path`, `photon` and
//! `course` stay `f32`.

#![forbid(unsafe_code)]
#![warn(missing_docs)]
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod bump;
pub mod camera;
pub mod capture;
pub mod chains;
pub mod environment;
pub mod filter;
pub mod geometry;
pub mod integrator;
pub mod job;
pub mod kinds;
pub mod needs;
pub mod output;
pub mod render;
pub mod rng;
pub mod sampler;
pub mod scene;
pub mod spawn;
pub mod trap;
