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
//! precision. Every input is exactly representable, so a correctly rounded
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
//! injected through [`Laws`] / [`Laws64`] fails it.

use radiometry::fresnel::DielectricFresnel;
use serde::Deserialize;

use crate::check::{ulp_f32, ulp_f64, Check};
use crate::laws::Laws;

/// The bound, in ulps of the tier.
pub const BOUND_ULPS: f64 = 8.0;

/// The file name of the reference.
pub const FILE: &str = "fresnel_mpmath.json";
/// Its schema.
pub const SCHEMA: &str = "fresnel-reference/1";

/// The `f64` laws under test (the `f32` ones are [`Laws`]).
pub use crate::laws::Laws64;

/// A value carried as the unevaluated sum `hi + lo` of two doubles.
#[derive(Clone, Copy, Debug, Deserialize)]
pub struct Exact(pub f64, pub f64);

/// `fresnel_mpmath.json`.
#[derive(Clone, Debug, Deserialize)]
pub struct FresnelMpmath {
    /// mpmath's version.
    pub mpmath_version: String,
    /// Dielectric cases per tier.
    pub dielectric: Tiers<DielectricCase>,
    /// Conductor cases per tier.
    pub conductor: Tiers<ConductorCase>,
    /// The angle laws per tier.
    pub angles: Tiers<AngleCase>,
}

/// Cases whose inputs are exact in `f64`, and in `f32`.
#[derive(Clone, Debug, Deserialize)]
pub struct Tiers<C> {
    /// Inputs exact in `f64`.
    pub f64: Vec<C>,
    /// Inputs exact in `f32`.
    pub f32: Vec<C>,
}

impl<C> Tiers<C> {
    /// Both tiers' cases, each with its tier's name.
    pub fn by_tier(&self) -> [(&'static str, &[C]); 2] {
        [("f64", &self.f64), ("f32", &self.f32)]
    }
}

/// One dielectric case.
#[derive(Clone, Debug, Deserialize)]
pub struct DielectricCase {
    /// Where on the grid.
    pub label: String,
    /// Signed cosine.
    pub cos_i: f64,
    /// `n_inside / n_outside`.
    pub eta: f64,
    /// Total internal reflection.
    pub tir: bool,
    /// Exact R_s.
    pub r_s: Exact,
    /// Exact R_p.
    pub r_p: Exact,
    /// Exact R.
    pub r: Exact,
    /// Exact T = 1 − R.
    pub t: Exact,
    /// The condition number of T at this input: how much a relative change
    /// of the inputs is amplified in T (large where `1 − R` cancels).
    pub cond_t: f64,
}

/// One case of an angle law.
#[derive(Clone, Debug, Deserialize)]
pub struct AngleCase {
    /// Where on the grid.
    pub label: String,
    /// `transmitted_angle`, `critical_angle` or `brewster_angle`.
    pub law: String,
    /// The angle of incidence (radians; `transmitted_angle` only).
    pub theta_i: f64,
    /// The index along the path, `n_t / n_i`.
    pub eta_path: f64,
    /// The exact angle, or `None` where the law has none (total internal
    /// reflection, no critical angle).
    pub value: Option<Exact>,
    /// The relative condition number of the angle over `theta_i` alone,
    /// `|θ_i ∂θ_t/∂θ_i| / θ_t` (`transmitted_angle`; 0 for the others,
    /// whose one input reaches them exact).
    pub cond_theta: f64,
}

/// One conductor case.
#[derive(Clone, Debug, Deserialize)]
pub struct ConductorCase {
    /// Where on the grid.
    pub label: String,
    /// Cosine.
    pub cos_i: f64,
    /// Real index.
    pub n: f64,
    /// Extinction coefficient.
    pub kappa: f64,
    /// Exact R_s.
    pub r_s: Exact,
    /// Exact R_p.
    pub r_p: Exact,
    /// Exact R.
    pub r: Exact,
}

impl FresnelMpmath {
    /// Loads the reference from `dir`.
    pub fn load(dir: &std::path::Path) -> Result<Self, crate::ReferenceError> {
        crate::reference::load(dir, FILE, SCHEMA)
    }
}

impl Exact {
    /// The spacing of the tier's numbers at the exact value `hi + lo`. When
    /// `hi` is a power of two and `lo` points towards zero, the value lies in
    /// the binade below, whose spacing is half that at `hi`.
    fn ulp(self, tier: &str) -> f64 {
        let at = |x: f64| {
            if tier == "f32" {
                ulp_f32(x)
            } else {
                ulp_f64(x)
            }
        };
        let power_of_two = self.0 != 0.0 && self.0.to_bits() & ((1 << 52) - 1) == 0;
        // `lo` pointing towards zero puts the exact value inside |hi|'s binade below.
        let below = power_of_two && self.1 != 0.0 && self.1.signum() != self.0.signum();
        if below {
            at(self.0.abs() * 0.75) // any value of the binade below
        } else {
            at(self.0)
        }
    }
}

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
    // `got − hi` is exact (Sterbenz) when the two are close, so the error
    // resolves below one ulp of the tier.
    let err = ((got - exact.0) - exact.1).abs();
    let ulps = if err.is_nan() {
        f64::INFINITY
    } else {
        err / exact.ulp(tier)
    };
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
    let ulps = measure(check, tier, quantity, label, got, exact);
    if !(ulps <= BOUND_ULPS) {
        check.fail(format!(
            "{tier} {quantity} at {label}: got {got:e}, exact {:e} ({ulps:.1} ulps)",
            exact.0
        ));
    }
}

fn widen(f: DielectricFresnel<f32>) -> [f64; 4] {
    [f.r_s, f.r_p, f.reflectance(), f.transmittance()].map(f64::from)
}

/// Dielectric R_s, R_p, R, T in both tiers against the 50-digit values.
pub fn check_dielectric(laws: &Laws, laws64: &Laws64, reference: &FresnelMpmath) -> Check {
    let mut check = Check::new(
        "laws.mpmath.fresnel_dielectric",
        "Dielectric Fresnel R_s, R_p, R, T in f64 and f32, extremes included",
        &format!("mpmath {}, 50 digits", reference.mpmath_version),
        &format!(
            "within {BOUND_ULPS} ulps of the tier: a handful of roundings from correctly rounded"
        ),
    );
    for (tier, cases) in reference.dielectric.by_tier() {
        for case in cases {
            check.cases += 1;
            let (got, tir) = if tier == "f64" {
                let f = (laws64.dielectric)(case.cos_i, case.eta);
                (
                    [f.r_s, f.r_p, f.reflectance(), f.transmittance()],
                    f.is_total_internal_reflection(),
                )
            } else {
                let f = (laws.dielectric)(case.cos_i as f32, case.eta as f32);
                (widen(f), f.is_total_internal_reflection())
            };
            if tir != case.tir {
                check.fail(format!(
                    "{tier} at {}: total internal reflection {tir} but exactly {}",
                    case.label, case.tir
                ));
            }
            let exact = [case.r_s, case.r_p, case.r, case.t];
            for ((name, g), e) in ["R_s", "R_p", "R", "T"].iter().zip(got).zip(exact) {
                compare(&mut check, tier, name, &case.label, g, e);
            }
        }
    }
    check
}

/// Conductor R_s, R_p, R in both tiers against the 50-digit values.
pub fn check_conductor(laws: &Laws, laws64: &Laws64, reference: &FresnelMpmath) -> Check {
    let mut check = Check::new(
        "laws.mpmath.fresnel_conductor",
        "Conductor Fresnel R_s, R_p, R in f64 and f32, extremes included",
        &format!("mpmath {}, 50 digits", reference.mpmath_version),
        &format!("within {BOUND_ULPS} ulps of the tier"),
    );
    for (tier, cases) in reference.conductor.by_tier() {
        for case in cases {
            check.cases += 1;
            let got = if tier == "f64" {
                let f = (laws64.conductor)(case.cos_i, case.n, case.kappa);
                [f.r_s, f.r_p, f.reflectance()]
            } else {
                let f = (laws.conductor)(case.cos_i as f32, case.n as f32, case.kappa as f32);
                [f.r_s, f.r_p, f.reflectance()].map(f64::from)
            };
            let exact = [case.r_s, case.r_p, case.r];
            for ((name, g), e) in ["R_s", "R_p", "R"].iter().zip(got).zip(exact) {
                compare(&mut check, tier, name, &case.label, g, e);
            }
        }
    }
    check
}

/// The bound on `transmitted_angle`, in ulps of the tier:
/// [`BOUND_ULPS`] + (8/π) `cond_theta`.
///
/// The law's one rounded input is the sine (below π/4) or the cosine (above)
/// of the exact `θ_i`, off by at most one ulp, a relative `ε`. `θ_t` moves by
/// that relative error times its condition number over that trig value,
/// which is `cond_theta · tan θ_i / θ_i` for the sine and
/// `cond_theta · cot θ_i / θ_i` for the cosine: at most `(4/π) cond_theta`
/// on the side where each is read (the other would be unbounded near 0 or
/// π/2). A relative error `r` is at most `2r/ε` ulps, so `(8/π) cond_theta`
/// ulps; the rest (the discriminant, the square root, `atan2`) is a handful
/// of roundings, [`BOUND_ULPS`]. Near the critical angle `cond_theta` grows
/// without bound, and so may the error: the input is exact, but the trig
/// value the law needs is not.
pub fn transmitted_angle_bound_ulps(cond_theta: f64) -> f64 {
    BOUND_ULPS + 8.0 / std::f64::consts::PI * cond_theta
}

/// Snell's law for angles, the critical and Brewster angles, in both tiers,
/// against the 50-digit values: `transmitted_angle` within
/// [`transmitted_angle_bound_ulps`] and with the same decision on total
/// internal reflection, the other two (whose one input reaches them exact)
/// within [`BOUND_ULPS`].
pub fn check_angles(laws: &Laws, laws64: &Laws64, reference: &FresnelMpmath) -> Check {
    let mut check = Check::new(
        "laws.mpmath.angles",
        "Snell's law for angles, the critical and Brewster angles, in f64 and f32",
        &format!("mpmath {}, 50 digits", reference.mpmath_version),
        &format!(
            "transmitted_angle within {BOUND_ULPS} + (8/π)·cond_θ ulps of the tier, cond_θ its \
             condition number over θ_i (the law reads a sine or cosine of θ_i, rounded once), \
             and the same decision on total internal reflection; critical_angle and \
             brewster_angle within {BOUND_ULPS} ulps"
        ),
    );
    for (tier, cases) in reference.angles.by_tier() {
        for case in cases {
            check.cases += 1;
            let (theta, eta) = (case.theta_i, case.eta_path);
            let got = match (tier, case.law.as_str()) {
                ("f64", "transmitted_angle") => (laws64.transmitted_angle)(theta, eta),
                ("f64", "critical_angle") => (laws64.critical_angle)(eta),
                ("f64", "brewster_angle") => (laws64.brewster_angle)(eta),
                (_, "transmitted_angle") => {
                    (laws.transmitted_angle)(theta as f32, eta as f32).map(f64::from)
                }
                (_, "critical_angle") => (laws.critical_angle)(eta as f32).map(f64::from),
                (_, "brewster_angle") => (laws.brewster_angle)(eta as f32).map(f64::from),
                (_, other) => {
                    check.fail(format!("{}: unknown law {other:?}", case.label));
                    continue;
                }
            };
            match (got, case.value) {
                (Some(got), Some(exact)) if case.law == "transmitted_angle" => {
                    let bound = transmitted_angle_bound_ulps(case.cond_theta);
                    let ulps = measure(&mut check, tier, &case.law, &case.label, got, exact);
                    let conditioned = ulps / (1.0 + case.cond_theta);
                    check.measure(
                        &format!("{tier} {} (ulps / (1 + cond_θ))", case.law),
                        conditioned,
                        &case.label,
                    );
                    if !(ulps <= bound) {
                        check.fail(format!(
                            "{tier} {} at {}: got {got:e}, exact {:e} ({ulps:.1} ulps, bound {bound:.1})",
                            case.law, case.label, exact.0
                        ));
                    }
                }
                (Some(got), Some(exact)) => {
                    compare(&mut check, tier, &case.law, &case.label, got, exact)
                }
                (None, None) => {}
                (got, exact) => check.fail(format!(
                    "{tier} {} at {}: got {got:?}, exactly {:?}",
                    case.law,
                    case.label,
                    exact.map(|e| e.0)
                )),
            }
        }
    }
    check
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ulp_f64_is_the_double_spacing() {
        assert_eq!(ulp_f64(1.0), f64::EPSILON);
        assert_eq!(ulp_f64(0.75), f64::EPSILON / 2.0);
        assert_eq!(ulp_f64(0.0), f64::from_bits(1));
        assert_eq!(ulp_f64(f64::MIN_POSITIVE), f64::from_bits(1));
        assert_eq!(ulp_f64(1e-300), 1e-300f64.next_up() - 1e-300);
        for x in [
            f64::from_bits(1 << 52),
            f64::from_bits(60 << 52),
            5.8e-300,
            0.04,
        ] {
            assert_eq!(ulp_f64(x), x.next_up() - x, "{x:e}");
        }
    }

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
