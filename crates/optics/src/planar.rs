//! `optics reflection-matrix` and `optics shadow-matrix`: the slides'
//! 4 × 4 matrices of a plane (`techniques::planar`), with the working.
//!
//! The inputs are checked here, where they enter: every component finite,
//! the normal not zero. `techniques::planar::project_shadow` reads a NaN
//! light or vertex, and a product that overflowed, as `Parallel`; neither
//! reaches it from here.
//!
//! Numbers are printed, and written to JSON, with the rounding of their
//! computation cleaned: an entry within [`ROUNDING`](matrix::ROUNDING) of its block's
//! largest is 0 (`−3.3e-16` where the matrix of the plane `x + y = 1` has
//! an exact 0), the rest to six significant digits.

mod matrix;
mod plane;
mod reflection;
mod shadow;

pub use reflection::ReflectionMatrixArgs;
pub use shadow::ShadowMatrixArgs;
#[cfg(test)]
pub(crate) use shadow::UNCHECKED_VERTEX;
