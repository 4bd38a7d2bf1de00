//! The exact Fresnel laws, dielectric and conductor, against the 50-digit
//! values in both tiers.

use super::bounds::{
    dielectric_bound_ulps, BOUND_ULPS, CONDUCTOR_BOUND_ULPS, DIELECTRIC_F64_BOUND_ULPS,
};
use super::measure::compare_within;
use super::reference::FresnelMpmath;
use crate::check::Check;
use crate::laws::Laws;
use crate::laws::Laws64;
use radiometry::fresnel::DielectricFresnel;

fn widen(f: DielectricFresnel<f32>) -> [f64; 4] {
    [f.r_s, f.r_p, f.reflectance(), f.transmittance()].map(f64::from)
}

/// Dielectric R_s, R_p, R, T in both tiers against the 50-digit values.
pub fn check_dielectric(laws: &Laws, laws64: &Laws64, reference: &FresnelMpmath) -> Check {
    let mut check = Check::new(
        "laws.mpmath.fresnel_dielectric",
        [
            "Dielectric Fresnel R_s, R_p, R, T in f64 and f32, extremes included",
            "Dielektrikum Fresnel-egyenletei: R_s, R_p, R, T f64-ben és f32-ben, a szélsőségekkel együtt",
        ],
        [
            &format!("mpmath {}, 50 digits", reference.mpmath_version),
            &format!("mpmath {}, 50 jegyre", reference.mpmath_version),
        ],
        [&format!(
            "within {DIELECTRIC_F64_BOUND_ULPS} ulps in f64 and {BOUND_ULPS} in f32: a handful of \
             roundings from correctly rounded, doubled in R_p's square"
        ), &format!("legfeljebb {DIELECTRIC_F64_BOUND_ULPS} ulp f64-ben és {BOUND_ULPS} f32-ben: néhány kerekítés a helyesen kerekítettől, R_p négyzetében megkétszerezve")],
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
                let at = (tier, *name, case.label.as_str());
                compare_within(&mut check, dielectric_bound_ulps(tier), at, g, e);
            }
        }
    }
    check
}

/// Conductor R_s, R_p, R in both tiers against the 50-digit values, within
/// [`CONDUCTOR_BOUND_ULPS`].
pub fn check_conductor(laws: &Laws, laws64: &Laws64, reference: &FresnelMpmath) -> Check {
    let mut check = Check::new(
        "laws.mpmath.fresnel_conductor",
        [
            "Conductor Fresnel R_s, R_p, R in f64 and f32, extremes included",
            "Vezető Fresnel-egyenletei: R_s, R_p, R f64-ben és f32-ben, a szélsőségekkel együtt",
        ],
        [
            &format!("mpmath {}, 50 digits", reference.mpmath_version),
            &format!("mpmath {}, 50 jegyre", reference.mpmath_version),
        ],
        [&format!(
            "within {CONDUCTOR_BOUND_ULPS} ulps of the tier: about ten roundings, squared in R_p"
        ), &format!("legfeljebb {CONDUCTOR_BOUND_ULPS} ulp a szint szerint: nagyjából tíz kerekítés, R_p-ben négyzetre emelve")],
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
                let at = (tier, *name, case.label.as_str());
                compare_within(&mut check, CONDUCTOR_BOUND_ULPS, at, g, e);
            }
        }
    }
    check
}
