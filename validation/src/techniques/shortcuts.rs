//! The slides' shortcuts for the laws: the cheap refraction against
//! Snell's law and the fitted empirical Fresnel form against the exact law
//! and Schlick, with the curves the report draws.

use radiometry::course::EmpiricalFresnel;
use techniques::empirical_fresnel::{self, AngleGrid, Interface, SUITE};
use techniques::refraction::{self, Constant, Side};

use super::curves::{FitCurve, RefractionCurve, DRAWN_FITS};
use crate::check::Check;

/// The slides' cheap refraction `t = normalize(−c n + i)` against Snell's
/// law entering water (their `c = 1`) and glass, and the first-order
/// `c = η − 1`: the worst angle between the two rays over 0° to 89°. The
/// check is the identity the erratum rests on: with `c = 1` the cheap ray
/// bends to exactly half the incidence angle.
pub fn check_cheap_refraction(curves: &mut Vec<RefractionCurve>) -> Check {
    let mut check = Check::new(
        "techniques.refraction.cheap",
        [
            "The slides' cheap refraction against Snell's law, entering water and glass",
            "A diák olcsó fénytörése a Snellius–Descartes-törvényhez mérve, vízbe és üvegbe lépve",
        ],
        [
            "Snell's law in vector form (radiometry::specular::refract)",
            "a Snellius–Descartes-törvény vektoros alakja ('radiometry::specular::refract')",
        ],
        ["c = 1 bends by exactly half the incidence angle (to 1e-12 rad); the angles from Snell's law measured", "c = 1 pontosan a beesési szög felével tör (1e-12 rad-ig); a Snellius–Descartes-törvénytől való szögeltérés mérve"],
    );
    for ((medium, into_hu), eta) in [(("water", "vízbe"), 1.33), (("glass", "üvegbe"), 1.5)] {
        for (name, constant) in [
            ("c = 1", refraction::SLIDES_WATER),
            ("c = η − 1", Constant::FirstOrder),
        ] {
            let mut curve = RefractionCurve {
                label: format!("into {medium}, {name}"),
                angle_deg: Vec::new(),
                error_deg: Vec::new(),
            };
            for degree in 0..90 {
                let theta = f64::from(degree).to_radians();
                check.cases += 1;
                let Some(compared) = refraction::compare_at(theta, Side::Outside, eta, constant)
                else {
                    check.fail(format!("{medium}, {name}, {degree}°: no comparison"));
                    continue;
                };
                let Some(error) = compared.error() else {
                    check.fail(format!(
                        "{medium}, {name}, {degree}°: total internal reflection entering"
                    ));
                    continue;
                };
                check.measure_in_both(
                    [
                        &format!("into {medium}, {name}: angle from Snell's law (°)"),
                        &format!("{into_hu}, {name}: eltérés a Snellius–Descartes-törvénytől (°)"),
                    ],
                    error.to_degrees(),
                    &format!("{degree}°"),
                );
                curve.angle_deg.push(f64::from(degree));
                curve.error_deg.push(error.to_degrees());
                if let (refraction::Comparison::Refracts { cheap, .. }, Constant::Fixed(_)) =
                    (compared, constant)
                {
                    let bend = refraction::angle_between(
                        -refraction::in_plane(theta, Side::Outside),
                        cheap,
                    );
                    if !((bend - theta / 2.0).abs() <= 1e-12) {
                        check.fail(format!(
                            "{medium}, {degree}°: c = 1 bends {bend} rad, not half of {theta}"
                        ));
                    }
                }
            }
            curves.push(curve);
        }
    }
    check
}

/// The slides' empirical Fresnel form fitted to the exact law of each of
/// the suite's interfaces, beside Schlick: the fit's family holds
/// Schlick's curve, so its RMS can be no larger unless the fit failed.
pub fn check_empirical_fresnel(curves: &mut Vec<FitCurve>) -> Check {
    let mut check = Check::new(
        "techniques.empirical_fresnel.fit",
        [
            "The slides' bias + scale (1 + I·N)^power fitted to the exact Fresnel law, beside Schlick",
            "A diák eltolás + skála · (1 + I·N)^power alakja a pontos Fresnel-törvényhez illesztve, a Schlick-közelítés mellett",
        ],
        [
            "the exact dielectric and conductor laws (radiometry), every 0.1° from 0° to 90°",
            "a dielektrikum és a vezető pontos törvényei (a 'radiometry' könyvtárban), 0°-tól 90°-ig 0,1°-onként",
        ],
        ["the fit's RMS no larger than Schlick's (Schlick is one member of the form's family)", "az illesztés RMS-hibája nem nagyobb a Schlick-közelítésénél (a Schlick-közelítés is az alak családjába tartozik)"],
    );
    for (name, interface) in SUITE {
        check.cases += 1;
        match empirical_fresnel::compare(interface, &AngleGrid::TENTH_OF_A_DEGREE) {
            Ok(c) => {
                let errors = [
                    (
                        ["fitted form: RMS error", "illesztett alak: RMS-hiba"],
                        c.fit.errors.rms,
                    ),
                    (
                        [
                            "fitted form: largest error",
                            "illesztett alak: legnagyobb hiba",
                        ],
                        c.fit.errors.max,
                    ),
                    (["Schlick: RMS error", "Schlick: RMS-hiba"], c.schlick.rms),
                    (
                        ["Schlick: largest error", "Schlick: legnagyobb hiba"],
                        c.schlick.max,
                    ),
                ];
                for (quantity, value) in errors {
                    check.measure_in_both(quantity, value, name);
                }
                if DRAWN_FITS.contains(&name) {
                    curves.push(fit_curve(name, interface, &c.fit.form));
                }
                if !(c.fit.errors.rms <= c.schlick.rms) {
                    check.fail(format!(
                        "{name}: the fit's RMS {:.3e} exceeds Schlick's {:.3e}",
                        c.fit.errors.rms, c.schlick.rms
                    ));
                }
            }
            Err(e) => check.fail(format!("{name}: the fit failed: {e:?}")),
        }
    }
    check
}

/// `interface`'s exact reflectance, its fitted `form` and Schlick, one
/// value per degree.
fn fit_curve(name: &str, interface: Interface, form: &EmpiricalFresnel<f64>) -> FitCurve {
    let angle_deg: Vec<f64> = (0..=90).map(f64::from).collect();
    let at = |f: &dyn Fn(f64) -> f64| -> Vec<f64> {
        angle_deg.iter().map(|a| f(a.to_radians().cos())).collect()
    };
    FitCurve {
        label: name.to_owned(),
        exact: at(&|c| interface.reflectance(c)),
        fitted: at(&|c| empirical_fresnel::reflectance(form, c)),
        schlick: at(&|c| interface.schlick(c)),
        form: [form.bias, form.scale, form.power],
        angle_deg,
    }
}
