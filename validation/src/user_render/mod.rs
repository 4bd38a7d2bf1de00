//! A user's own render of a scene held against the suite's reference
//! render of it, by the harness's own machinery ([`crate::compare`]): which
//! test fits the image, the verdict, the regions that disagree and by how
//! much, and a difference map. `optics compare` fronts it; any other front
//! end calls [`compare`] the same way.
//!
//! | image | test |
//! |---|---|
//! | PNG (8-bit sRGB) | its codes within those of the reference's tolerance interval, one code more either side |
//! | PFM (linear radiance) | per pixel-channel `\|Δ\| ≤ 1e-5 + 1e-3 · \|reference\|`, plus the reference's own noise |
//! | PFM with its variance and samples | Welch's t per pixel-channel, Bonferroni-corrected, and beyond that tolerance |
//!
//! The reference is the scene rendered by the tracer at the image's size
//! with its own physical integrator; pixels on silhouettes (a neighbour
//! sees another object) are not compared.
//!
//! ```no_run
//! use std::path::Path;
//! use record::Lang;
//! use validation::user_render::{compare, Names, Request};
//!
//! let request = Request {
//!     image: Path::new("mine.png"),
//!     scene: Path::new("crates/tracer/scenes/gold_spheres.json"),
//!     variance: None,
//!     diff: None,
//!     integrator: None,
//!     reference_samples: 256,
//!     names: Names::default(),
//! };
//! let comparison = compare(&request, |_job| {}).unwrap();
//! let lines = validation::user_render::record(&comparison, Lang::En).steps;
//! println!("{}", lines.join("\n"));
//! ```
//!
//! `examples/compare_a_render.rs` renders a course scene and compares it.

mod error;
mod judge;
mod reference;
mod report;
mod request;
mod user_image;

pub use error::{CompareError, Error, PfmProblem};
pub use judge::{judge, Noise, Outcome};
pub use reference::{Reference, FIRST_SEED};
pub use report::{record, region_names, shape};
pub use request::{admit, compare, Comparison, Names, Request};
#[cfg(any(test, feature = "faults"))]
pub use user_image::LENGTH_UNCHECKED;
pub use user_image::{check_values, decode, read, read_bytes, UserImage};
