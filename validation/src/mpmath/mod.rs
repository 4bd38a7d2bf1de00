//! The exact Fresnel laws, and the angle laws of `snell`, against 50-digit
//! references, in both precision tiers.
//!
//! Reference: `validation/reference/fresnel_mpmath.json` (schema
//! `fresnel-reference/1`), written by `python-checks/fresnel_mpmath.py`:
//! extremes included (grazing `cos θ = 1e-300`, 1e-12 rad and one ulp either side
//! of the critical angle on every path that has one, `η = 1 ± 1e-12`,
//! `η = 1e-3` and `1e3`, `n = 1e3`, `κ = 1e3`).
//!
//! Tolerance: [`BOUND_ULPS`] ulps of the exact value in the tier's own
//! precision ([`CONDUCTOR_BOUND_ULPS`] for the conductor law and
//! [`DIELECTRIC_F64_BOUND_ULPS`] for the dielectric law in `f64`, whose
//! worst cases, in the grid, reach past it). Every input is exactly representable, so a correctly rounded
//! law would be within 0.5 ulp; each quantity is a handful of roundings from
//! that (a square root, a few products and quotients, a sum carried in twice
//! the precision). The bound is just above the worst error measured (6.6
//! ulps, conductor R_p in f32), so that a regression costing one digit fails;
//! where the exact value is subnormal the ulps are those of the smallest
//! subnormal, and an exact value just below a power of two is measured in
//! the spacing of its own binade. Each quantity's worst relative error
//! `|ours − exact| / exact` is reported beside its ulps; the bound is on the
//! ulps, which say the same everywhere but where the exact value is
//! subnormal. The workspace test `tests/fresnel_reference.rs` runs this
//! check on the radiometry crate's laws and prints its table; a broken law
//! injected through [`Laws`](crate::laws::Laws) / [`Laws64`] fails it.
//!
//! The same laws at seeded random inputs, uniform over the reals and over
//! the floating-point numbers, are [`random`]'s (`fresnel_random.json`).

mod angles;
mod bounds;
mod fresnel;
mod measure;
pub mod random;
mod reference;

pub use angles::{check_angles, transmitted_angle_bound_ulps};
pub use bounds::{
    dielectric_bound_ulps, BOUND_ULPS, CONDUCTOR_BOUND_ULPS, DIELECTRIC_F64_BOUND_ULPS,
};
pub use fresnel::{check_conductor, check_dielectric};
pub use reference::{
    AngleCase, ConductorCase, DielectricCase, Exact, FresnelMpmath, Tiers, FILE, SCHEMA,
};

pub use crate::laws::Laws64;
