//! The tolerances of the module docs and the rule that separates failures
//! from findings.

/// Our reflectances against the exact value: f32 ulps of the exact value.
pub const OURS_ULPS: f64 = 8.0;
/// Our unit directions against the exact ones, per component: 8 ulps of 1.
pub const DIRECTION_ABS: f64 = 8.0 * f32::EPSILON as f64;
/// Mitsuba's float32 textbook evaluation against the exact value, absolute.
pub const MITSUBA_ABS: f64 = 16.0 * f32::EPSILON as f64;
/// A disagreement with Mitsuba no float32 rounding explains, absolute.
pub const GROSS_ABS: f64 = 1e-3;

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
