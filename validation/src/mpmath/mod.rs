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
mod fresnel;
pub mod random;
mod reference;

pub use angles::{check_angles, transmitted_angle_bound_ulps};
pub use fresnel::{check_conductor, check_dielectric};
pub use reference::{AngleCase, ConductorCase, DielectricCase, Exact, FresnelMpmath, Tiers};

use crate::check::Check;

/// The bound, in ulps of the tier.
pub const BOUND_ULPS: f64 = 8.0;

/// The dielectric law's `f64` bound, in ulps. Nothing cancels where it is
/// reached: `R_p = (contrast · brewster / (n_t² c + n_i s)²)²` is the square
/// of a ratio of a product of two compensated sums and a sum of three
/// rounded products (`s = √d` among them), about six roundings of order one,
/// doubled by the square. At `cos θi = 0.7652819693198041`,
/// `η = 1.7020537855601314` (the grid's "worst R_p found") `R_p` is 10.9
/// ulps from exact: Snell's discriminant `d`, summed compensated but rounded
/// once to `f64` (here half an ulp off), and `n_t² c` move the denominator
/// by 8 of them, the product `contrast · brewster` the numerator by the
/// rest. It was found among 2·10⁴ random doubles near the random cases'
/// 9.1 ulps, 1 in 4000 of which are past 8; 12 is a tenth above it. The
/// `f32` tier, evaluated in `f64` and rounded once, stays within
/// [`BOUND_ULPS`].
pub const DIELECTRIC_F64_BOUND_ULPS: f64 = 12.0;

/// The dielectric law's bound in `tier` (`"f64"` or `"f32"`).
pub fn dielectric_bound_ulps(tier: &str) -> f64 {
    if tier == "f64" {
        DIELECTRIC_F64_BOUND_ULPS
    } else {
        BOUND_ULPS
    }
}

/// The conductor law's bound, in ulps of the tier. Its `R_p` is the square
/// of a ratio of two `hypot`s, a product and a sum of three rounded terms,
/// each after compensated discriminants, about ten roundings of order one;
/// the square doubles the ratio's relative error. In `f64`, where no
/// product is exact, `R_p` is 11.9 ulps from exact at
/// `cos θi = 0.7915797852215061`, `n = 0.7020224126588795`,
/// `κ = 6.646724002409787` and `R_s` 10.8 ulps at
/// `cos θi = 0.6754425507263279`, `n = 0.18348744872677603`,
/// `κ = 4.060512106629868` (the grid's "worst … found" cases, the worst of
/// 1.9·10⁵ random doubles); the random cases of [`random`] reach 10.5. 14
/// is a sixth above the worst found, and a regression costing one digit
/// still fails it.
pub const CONDUCTOR_BOUND_ULPS: f64 = 14.0;

/// The file name of the reference.
pub const FILE: &str = "fresnel_mpmath.json";
/// Its schema.
pub const SCHEMA: &str = "fresnel-reference/1";

pub use crate::laws::Laws64;

/// Records `got` against `exact` in ulps of the tier and relative to the
/// exact value (0 when both are 0, infinite when only the exact value is),
/// and returns the ulps.
fn measure(
    check: &mut Check,
    tier: &str,
    quantity: &str,
    label: &str,
    got: f64,
    exact: Exact,
) -> f64 {
    let err = exact.error(got);
    let ulps = exact.ulps(got, tier);
    let relative = if err == 0.0 {
        0.0
    } else {
        err / (exact.0 + exact.1).abs()
    };
    check.measure(&format!("{tier} {quantity} (ulps)"), ulps, label);
    check.measure(&format!("{tier} {quantity} (relative)"), relative, label);
    ulps
}

/// [`measure`], failing above [`BOUND_ULPS`].
fn compare(check: &mut Check, tier: &str, quantity: &str, label: &str, got: f64, exact: Exact) {
    compare_within(check, BOUND_ULPS, (tier, quantity, label), got, exact)
}

/// [`measure`], failing above `bound` ulps.
fn compare_within(
    check: &mut Check,
    bound: f64,
    (tier, quantity, label): (&str, &str, &str),
    got: f64,
    exact: Exact,
) {
    let ulps = measure(check, tier, quantity, label, got, exact);
    if !(ulps <= bound) {
        check.fail(format!(
            "{tier} {quantity} at {label}: got {got:e}, exact {:e} ({ulps:.1} ulps)",
            exact.0
        ));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An exact value just below a power of two is measured in the spacing
    /// of the binade it lies in, not in the coarser one of its rounded `hi`.
    #[test]
    fn ulps_are_those_of_the_exact_value_at_a_power_of_two() {
        let just_below = Exact(1.0, -f64::EPSILON / 8.0);
        assert_eq!(just_below.ulp("f64"), f64::EPSILON / 2.0);
        assert_eq!(just_below.ulp("f32"), f32::EPSILON as f64 / 2.0);
        assert_eq!(Exact(1.0, f64::EPSILON / 8.0).ulp("f64"), f64::EPSILON);
        assert_eq!(Exact(0.75, -1e-20).ulp("f64"), f64::EPSILON / 2.0);
        assert_eq!(
            Exact(-1.0, f64::EPSILON / 8.0).ulp("f64"),
            f64::EPSILON / 2.0
        );
        assert_eq!(Exact(-1.0, -f64::EPSILON / 8.0).ulp("f64"), f64::EPSILON);
        let mut check = Check::new("t", "t", "t", "t");
        compare(
            &mut check,
            "f64",
            "R",
            "one below",
            1.0,
            Exact(1.0, -f64::EPSILON / 4.0),
        );
        assert_eq!(check.worst("f64 R (ulps)").unwrap().worst, 0.5);
        let relative = check.worst("f64 R (relative)").unwrap().worst;
        assert!(
            (relative - f64::EPSILON / 4.0).abs() < 1e-30,
            "{relative:e}"
        );
    }
}
