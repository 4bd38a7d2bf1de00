//! Bidirectional reflectance distribution functions (BRDFs), in 1/sr:
//! `f_r(wi, wo) = dL_o(wo) / (L_i(wi) cos θ_i dω_i)`, the radiance reflected
//! towards `wo` per unit irradiance arriving from `wi`.
//!
//! Two laws every physical BRDF obeys, each with a generic checker here:
//!
//! - **Helmholtz reciprocity**, `f_r(wi, wo) = f_r(wo, wi)`: [`reciprocity`].
//! - **Energy conservation**, the directional albedo
//!   `ρ(wi) = ∫ f_r(wi, wo) cos θ_o dω_o ≤ 1` for every `wi`: of the power
//!   arriving from `wi`, no more than all is reflected
//!   ([`directional_albedo`]). The integral runs over the outgoing
//!   directions; the one over incoming directions, `∫ f_r(wi, wo) cos θ_i
//!   dω_i`, is the radiance towards `wo` under unit uniform light, and
//!   equals it only for a reciprocal BRDF (E. Veach, thesis, 1997, ch. 6).
//!
//! The models: the course's (`003`, "Rücskös felületek", whose specular
//! model is Phong-Blinn), and classic Phong beside them for comparison:
//!
//! | model | `f_r` | reciprocal | conserves energy |
//! |---|---|---|---|
//! | [`Lambert`] | `albedo / π` | yes | yes, albedo = `albedo` |
//! | [`CourseLambert`] | `kd` (the course's un-normalised form) | yes | only for `kd ≤ 1/π` |
//! | [`Phong`] | `kd + ks (cos⁺α)^shine / cos θ_i`, α from the mirror direction | no | no: `ρ(wi)` grows like `1 / cos θ_i` towards grazing |
//! | [`BlinnPhong`] | `kd + ks (cos⁺δ)^shine / cos θ_i`, δ from the half vector (course form) | no | no: `ρ(wi)` grows like `1 / cos θ_i` towards grazing |
//! | [`BlinnPhongReciprocal`] | `kd + ks (cos⁺δ)^shine / ‖wi + wo‖²` (the course's fix) | yes | not in general |
//!
//! All return 0 when either direction is at or below the surface, and NaN
//! for a NaN direction, as [`hemisphere`] decides it.

mod albedo;
mod hemisphere;
mod models;
mod reciprocity;

pub use albedo::{directional_albedo, AlbedoEstimate};
pub use hemisphere::{hemisphere, Brdf, Hemisphere};
pub use models::{half_vector, BlinnPhong, BlinnPhongReciprocal, CourseLambert, Lambert, Phong};
pub use reciprocity::{hemisphere_directions, reciprocity, ReciprocityReport};
