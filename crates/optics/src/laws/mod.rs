//! The law evaluators: `optics fresnel`, `refract`, `reflect`, `shade`.
//!
//! Each takes its inputs either as flags or as a JSON request (the same
//! struct serves both), checks them, calls the radiometry crate for every
//! number, and returns a [`record::Record`] with the working. The working narrates
//! what the laws returned (the side and indices of the `Incidence`, the
//! transmitted cosine, the cosine Schlick took); it never decides again what
//! a law decided, and each law is evaluated at most once per request.

mod fresnel;
mod fresnel_bulk;
mod lit_surface;
mod normalized;
mod reflect;
pub(crate) mod refract;
mod shade;

pub use fresnel::{FresnelArgs, FresnelModel};
pub use fresnel_bulk::FresnelBulkArgs;
pub(crate) use lit_surface::lit_surface_args;
pub use normalized::note_normalized;
pub use reflect::ReflectArgs;
pub use refract::RefractArgs;
pub use shade::{ShadeArgs, ShadeModel, Shading};
