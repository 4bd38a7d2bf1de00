//! The laws against Mitsuba 3 and the exact values, in float32.
//!
//! Reference: `validation/reference/mitsuba_laws.json` (schema
//! `mitsuba-laws/1`), written by `python-checks/mitsuba_laws.py`. Each case
//! holds Mitsuba's float32 result and the exact value (mpmath, 50 digits) at
//! the same float32 input. The laws under test are a parameter ([`Laws`]) so
//! that a deliberately broken law can be checked to be caught.
//!
//! # Tolerances, and who is wrong
//!
//! - **Ours against the exact value**: [`OURS_ULPS`] f32 ulps for reflectances
//!   (the radiometry crate's f32 tier is measured within 6 ulps of 50-digit
//!   references, see `tests/fresnel_reference.rs`), and [`DIRECTION_ABS`] per
//!   component for unit directions. Beyond that is a **failure**.
//! - **Mitsuba against the exact value**: Mitsuba evaluates the textbook
//!   formulas in float32. Each of its roughly ten roundings is at most half an
//!   ulp of an intermediate of order one, so away from cancellations its
//!   error is a few `f32::EPSILON` in absolute terms; [`MITSUBA_ABS`]
//!   (16 ε₃₂ ≈ 1.9e-6) bounds that. A larger deviation, with ours within its
//!   own bound, is a **finding** about Mitsuba: it happens where the textbook
//!   form cancels (near the critical angle, `1 − sin²θ_t`; near `η = 1`).
//! - **Ours against Mitsuba, grossly**: even through that cancellation,
//!   float32 rounding moves a reflectance by at most about `√ε₃₂ ≈ 3.5e-4`
//!   (the square root of an absolute error of ε₃₂ in `cos²θ_t`). A difference
//!   beyond [`GROSS_ABS`] (1e-3) is a convention or a law that differs, not
//!   rounding, and is a **failure** even if our mpmath reference agrees with
//!   us: Mitsuba is the check on the reference itself.

pub(crate) mod directions;
mod fresnel;
mod reference;
mod under_test;
mod verdict;

pub use directions::{check_directions, refraction_allowance, refraction_allowance_at};
pub use fresnel::{check_conductor, check_dielectric, check_schlick};
pub use reference::{
    ConductorCase, Curve, DielectricCase, DirectionCase, ExactConductor, ExactDielectric,
    ExactDirections, MitsubaConductor, MitsubaDielectric, MitsubaDirections, MitsubaLaws,
    SchlickCase, FILE, SCHEMA,
};
pub use under_test::{Laws, Laws64, RefractLaw, Tier};
pub use verdict::{Verdict, DIRECTION_ABS, GROSS_ABS, MITSUBA_ABS, OURS_ULPS};

use crate::check::Check;

/// Every law check against `mitsuba_laws.json`.
pub fn check_all(laws: &Laws, reference: &MitsubaLaws) -> Vec<Check> {
    vec![
        check_dielectric(laws, reference),
        check_conductor(laws, reference),
        check_directions(laws, reference),
        check_schlick(laws, reference),
    ]
}
