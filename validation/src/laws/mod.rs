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

pub use directions::{check_directions, refraction_allowance, refraction_allowance_at};
pub use fresnel::{check_conductor, check_dielectric, check_schlick};
pub use reference::{
    ConductorCase, Curve, DielectricCase, DirectionCase, ExactConductor, ExactDielectric,
    ExactDirections, MitsubaConductor, MitsubaDielectric, MitsubaDirections, MitsubaLaws,
    SchlickCase,
};
pub use under_test::{Laws, Laws64, RefractLaw, Tier};

use crate::check::Check;

/// Our reflectances against the exact value: f32 ulps of the exact value.
pub const OURS_ULPS: f64 = 8.0;
/// Our unit directions against the exact ones, per component: 8 ulps of 1.
pub const DIRECTION_ABS: f64 = 8.0 * f32::EPSILON as f64;
/// Mitsuba's float32 textbook evaluation against the exact value, absolute.
pub const MITSUBA_ABS: f64 = 16.0 * f32::EPSILON as f64;
/// A disagreement with Mitsuba no float32 rounding explains, absolute.
pub const GROSS_ABS: f64 = 1e-3;

/// The file name of the reference.
pub const FILE: &str = "mitsuba_laws.json";
/// Its schema.
pub const SCHEMA: &str = "mitsuba-laws/1";

/// The rule of the module docs, decided once for every comparison of ours,
/// Mitsuba's and the exact value of one quantity (here and in
/// [`crate::exchange`]); each caller words the outcome.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Verdict {
    /// Ours beyond its bound of the exact value: a failure.
    pub ours_off: bool,
    /// Ours and Mitsuba more than [`GROSS_ABS`] apart: a failure.
    pub gross: bool,
    /// Mitsuba beyond its bound of the exact value, ours within its own and
    /// the two not grossly apart: a finding about Mitsuba.
    pub mitsuba_off: bool,
}

impl Verdict {
    /// Judges `ours_err` against `ours_bound` (in the caller's unit),
    /// `gap = |ours − Mitsuba|` against [`GROSS_ABS`] and `mitsuba_err`
    /// against `mitsuba_bound`. A NaN error is beyond any bound, but a NaN
    /// from Mitsuba is never a finding.
    pub fn of(
        ours_err: f64,
        ours_bound: f64,
        gap: f64,
        mitsuba_err: f64,
        mitsuba_bound: f64,
    ) -> Self {
        let ours_off = !(ours_err <= ours_bound);
        let gross = !(gap <= GROSS_ABS);
        Self {
            ours_off,
            gross,
            mitsuba_off: !gross && !ours_off && mitsuba_err > mitsuba_bound,
        }
    }
}

/// Every law check against `mitsuba_laws.json`.
pub fn check_all(laws: &Laws, reference: &MitsubaLaws) -> Vec<Check> {
    vec![
        check_dielectric(laws, reference),
        check_conductor(laws, reference),
        check_directions(laws, reference),
        check_schlick(laws, reference),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_verdict_separates_failures_from_findings() {
        let v = |ours_off, gross, mitsuba_off| Verdict {
            ours_off,
            gross,
            mitsuba_off,
        };
        let nan = f64::NAN;
        // (ours error, gap, Mitsuba error) against bounds 1, GROSS_ABS, 1.
        for (case, (ours, gap, mitsuba), expected) in [
            ("all within", (0.5, 0.0, 0.5), v(false, false, false)),
            ("Mitsuba off", (0.5, 0.0, 2.0), v(false, false, true)),
            ("ours off", (2.0, 0.0, 2.0), v(true, false, false)),
            ("grossly apart", (0.5, 1.0, 2.0), v(false, true, false)),
            ("ours NaN", (nan, 0.0, 0.5), v(true, false, false)),
            ("gap NaN", (0.5, nan, 0.5), v(false, true, false)),
            ("Mitsuba NaN", (0.5, 0.0, nan), v(false, false, false)),
        ] {
            assert_eq!(
                Verdict::of(ours, 1.0, gap, mitsuba, 1.0),
                expected,
                "{case}"
            );
        }
    }
}
