//! The angle laws of `snell` (Snell's law for angles, the critical and
//! Brewster angles) against the 50-digit values in both tiers.

use super::bounds::BOUND_ULPS;
use super::measure::{compare, measure};
use super::reference::FresnelMpmath;
use crate::check::Check;
use crate::laws::Laws;
use crate::laws::Laws64;

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
        [
            "Snell's law for angles, the critical and Brewster angles, in f64 and f32",
            "A Snellius–Descartes-törvény a szögekre, a határszög és a Brewster-szög, f64-ben és f32-ben",
        ],
        [
            &format!("mpmath {}, 50 digits", reference.mpmath_version),
            &format!("mpmath {}, 50 jegyre", reference.mpmath_version),
        ],
        [&format!(
            "transmitted_angle within {BOUND_ULPS} + (8/π)·cond_θ ulps of the tier, cond_θ its \
             condition number over θ_i (the law reads a sine or cosine of θ_i, rounded once), \
             and the same decision on total internal reflection; critical_angle and \
             brewster_angle within {BOUND_ULPS} ulps"
        ), &format!("transmitted_angle legfeljebb {BOUND_ULPS} + (8/π)·cond_θ ulp-re a szint szerint, ahol cond_θ a θ_i szerinti kondíciószáma (a törvény θ_i szinuszát vagy koszinuszát olvassa, egyszer kerekítve), és ugyanaz a döntés a teljes visszaverődésről; critical_angle és brewster_angle legfeljebb {BOUND_ULPS} ulp-re")],
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
                    let name = format!("{tier} {} (ulps / (1 + cond_θ))", case.law);
                    check.measure_in_both([&name, &name], conditioned, &case.label);
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
