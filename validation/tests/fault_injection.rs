//! Deliberately broken laws, injected into the harness in place of the
//! radiometry crate's, must be reported as failures: a harness that passes
//! everything would pass these too. (The renders' faults, a doubled light
//! to glass 2 % too dense and radiance carried across glass without its
//! `1/η²`, are planted in `renders_vs_mitsuba.rs`, beside the comparison.)

mod caught;

use caught::{caught_at, caught_only, failures_of};
use glam::Vec3;
use radiometry::fresnel::{self, DielectricFresnel};
use radiometry::specular::{self, Refraction};
use validation::laws::{self, Laws, MitsubaLaws};
use validation::reference::committed_dir;
use validation::Check;

fn reference() -> MitsubaLaws {
    MitsubaLaws::load(&committed_dir()).expect("committed Mitsuba reference")
}

/// `(1 − cos)^(−5)` instead of `(1 − cos)^5`.
fn schlick_wrong_exponent_sign(cos_i: f32, f0: f32) -> f32 {
    f0 + (1.0 - f0) * (1.0 - cos_i.abs()).powi(-5)
}

/// The refracted direction with its tangential part pointing the wrong way.
fn refract_tangent_sign_flipped(wi: Vec3, n: Vec3, eta: f32) -> Option<Refraction<Vec3>> {
    specular::refract(wi, n, eta).map(|mut r| {
        let normal_part = n * r.direction.dot(n);
        r.direction = normal_part - (r.direction - normal_part);
        r
    })
}

/// The refracted direction with one component not a number, as a
/// `0 / 0` in a normalisation would leave it.
fn refract_with_a_nan_component(wi: Vec3, n: Vec3, eta: f32) -> Option<Refraction<Vec3>> {
    specular::refract(wi, n, eta).map(|mut r| {
        r.direction.y = f32::NAN;
        r
    })
}

/// `eta` read as `n_outside / n_inside`, the opposite of the crate convention.
fn dielectric_eta_inverted(cos_i: f32, eta: f32) -> DielectricFresnel<f32> {
    fresnel::dielectric_polarized(cos_i, 1.0 / eta)
}

#[test]
fn schlick_with_the_wrong_exponent_sign_is_caught() {
    let broken = Laws {
        schlick: schlick_wrong_exponent_sign,
        ..Laws::radiometry()
    };
    let check = laws::check_schlick(&broken, &reference());
    // Only cos = 0 escapes, where 1 − cos = 1 and both exponents give 1.
    assert!(
        failures_of(&check) >= check.cases / 2,
        "{:#?}",
        check.failures
    );
}

#[test]
fn refraction_with_a_sign_flip_is_caught() {
    let broken = Laws {
        refract: refract_tangent_sign_flipped,
        ..Laws::radiometry()
    };
    let check = laws::check_directions(&broken, &reference());
    caught_only(&check, |f| f.starts_with("refract"));
    // Normal incidence has no tangential part: the flip is invisible there, and only there.
    caught_only(&check, |f| !f.contains(" 0deg "));
}

#[test]
fn a_refracted_direction_that_is_not_a_number_is_caught() {
    let broken = Laws {
        refract: refract_with_a_nan_component,
        ..Laws::radiometry()
    };
    let check = laws::check_directions(&broken, &reference());
    let refracting = reference()
        .directions
        .iter()
        .filter(|c| c.exact.refract.is_some())
        .count();
    // Every refracting case, twice: off the exact direction and off Mitsuba's.
    assert_eq!(failures_of(&check), 2 * refracting, "{:#?}", check.failures);
}

#[test]
fn inverted_eta_convention_is_caught() {
    let broken = Laws {
        dielectric: dielectric_eta_inverted,
        ..Laws::radiometry()
    };
    let check = laws::check_dielectric(&broken, &reference());
    failures_of(&check);
}

/// If the exact reference shared our mistake, Mitsuba still catches it: the
/// reference's exact values are replaced by the broken law's own (in f64), so
/// that only the comparison with Mitsuba can tell.
#[test]
fn a_mistake_shared_by_ours_and_the_exact_reference_is_caught_by_mitsuba() {
    let mut reference = reference();
    for case in &mut reference.dielectric {
        let f = fresnel::dielectric_polarized(case.cos_i, 1.0 / case.eta);
        case.exact.r = f.reflectance();
        case.exact.r_s = f.r_s;
        case.exact.r_p = f.r_p;
        case.exact.tir = f.is_total_internal_reflection();
    }
    let broken = Laws {
        dielectric: dielectric_eta_inverted,
        ..Laws::radiometry()
    };
    let check = laws::check_dielectric(&broken, &reference);
    caught_at(&check, |f| f.contains("Mitsuba"));
}

#[test]
fn the_unbroken_laws_pass_the_same_checks() {
    let checks = laws::check_all(&Laws::radiometry(), &reference());
    assert!(checks.iter().all(Check::passed));
}

/// Schlick's approximation in place of the exact law: the shortcut passed
/// off as the law is caught by the 50-digit check in both tiers.
#[test]
fn schlick_passed_off_as_the_exact_law_is_caught_by_the_50_digit_check() {
    use validation::mpmath::{self, FresnelMpmath, Laws64};
    fn schlick_as_exact(cos_i: f64, eta: f64) -> DielectricFresnel<f64> {
        let mut f = fresnel::dielectric_polarized(cos_i, eta);
        let r = fresnel::schlick_dielectric(cos_i, eta);
        (f.r_s, f.r_p, f.t_s, f.t_p) = (r, r, 1.0 - r, 1.0 - r);
        f
    }
    let exact = FresnelMpmath::load(&committed_dir()).expect("committed mpmath reference");
    let broken = Laws64 {
        dielectric: schlick_as_exact,
        ..Laws64::radiometry()
    };
    let check = mpmath::check_dielectric(&Laws::radiometry(), &broken, &exact);
    // The f32 tier is untouched.
    caught_only(&check, |f| f.starts_with("f64"));
    let unbroken = mpmath::check_dielectric(&Laws::radiometry(), &Laws64::radiometry(), &exact);
    assert!(unbroken.passed(), "{:#?}", unbroken.failures);
}

/// Broken angle laws are caught by the 50-digit angle check, each in the
/// tier it breaks: Snell's law with the index read the wrong way round; the
/// textbook `asin(sin θ_i / η)` and a discriminant summed exactly but from
/// the sine alone, both of which misjudge total internal reflection within
/// 1e-12 rad of a grazing critical angle (one ulp of `sin θ` spans 8e-11 rad
/// there); a critical angle off by a relative 1e-7.
#[test]
fn broken_angle_laws_are_caught_by_the_50_digit_check() {
    use radiometry::snell;
    use validation::mpmath::{self, FresnelMpmath, Laws64};
    fn inverted(theta_i: f32, eta_path: f32) -> Option<f32> {
        snell::transmitted_angle(theta_i, 1.0 / eta_path)
    }
    fn textbook(theta_i: f64, eta_path: f64) -> Option<f64> {
        let x = theta_i.sin() / eta_path;
        (x <= 1.0).then(|| x.asin())
    }
    fn from_the_sine_alone(theta_i: f64, eta_path: f64) -> Option<f64> {
        // η² − sin²θ_i with the square split exactly (fma), summed in f64.
        let s = theta_i.sin();
        let (e2, s2) = (eta_path * eta_path, s * s);
        let d = (e2 - s2) + (eta_path.mul_add(eta_path, -e2) - s.mul_add(s, -s2));
        (d >= 0.0).then(|| s.atan2(d.sqrt()))
    }
    fn critical_off(eta_path: f64) -> Option<f64> {
        snell::critical_angle(eta_path * (1.0 + 1e-7))
    }
    let exact = FresnelMpmath::load(&committed_dir()).expect("committed mpmath reference");
    let broken = Laws {
        transmitted_angle: inverted,
        ..Laws::radiometry()
    };
    let check = mpmath::check_angles(&broken, &Laws64::radiometry(), &exact);
    caught_only(&check, |f| f.starts_with("f32 transmitted_angle"));
    for (name, law) in [
        ("textbook", textbook as fn(f64, f64) -> Option<f64>),
        ("from the sine alone", from_the_sine_alone),
    ] {
        let broken64 = Laws64 {
            transmitted_angle: law,
            ..Laws64::radiometry()
        };
        let check = mpmath::check_angles(&Laws::radiometry(), &broken64, &exact);
        println!("{name}");
        caught_at(&check, |f| {
            f.contains("eta=1-1e-12") && f.contains("critical")
        });
    }
    let broken64 = Laws64 {
        critical_angle: critical_off,
        ..Laws64::radiometry()
    };
    let check = mpmath::check_angles(&Laws::radiometry(), &broken64, &exact);
    caught_only(&check, |f| f.starts_with("f64 critical_angle"));
    let unbroken = mpmath::check_angles(&Laws::radiometry(), &Laws64::radiometry(), &exact);
    assert!(unbroken.passed(), "{:#?}", unbroken.failures);
}

/// The random cases of `laws.mpmath.random.*`, decoded.
fn random_reference() -> (
    validation::mpmath::random::FresnelRandom,
    Vec<validation::mpmath::random::CaseSet>,
) {
    validation::mpmath::random::FresnelRandom::load(&committed_dir())
        .expect("committed random reference")
}

/// The random checks of `broken` (f32) and `broken64`, by law name.
fn random_check(broken: &Laws, broken64: &validation::mpmath::Laws64, law: &str) -> Check {
    let (random, sets) = random_reference();
    validation::mpmath::random::check_random(broken, broken64, &random, &sets)
        .into_iter()
        .find(|c| c.id == format!("laws.mpmath.random.{law}"))
        .expect("a check per law")
}

/// A cosine clamped at machine epsilon, as renderers do to avoid a division
/// by zero: a law that loses precision at tiny cosines. T ∝ cos θ there,
/// so it is off by up to 2^126 times in f32. Uniform over the reals, the
/// random cases almost never draw a cosine below ε (none of 5000 do), so
/// only the sampling uniform over the floats catches it, in both tiers.
#[test]
fn a_cosine_clamped_at_epsilon_is_caught_by_the_floats_sampling_only() {
    use validation::mpmath::Laws64;
    fn clamped(cos_i: f32, eta: f32) -> DielectricFresnel<f32> {
        let c = if cos_i.abs() < f32::EPSILON {
            f32::EPSILON.copysign(cos_i)
        } else {
            cos_i
        };
        fresnel::dielectric_polarized(c, eta)
    }
    fn clamped64(cos_i: f64, eta: f64) -> DielectricFresnel<f64> {
        let c = if cos_i.abs() < f64::EPSILON {
            f64::EPSILON.copysign(cos_i)
        } else {
            cos_i
        };
        fresnel::dielectric_polarized(c, eta)
    }
    let broken = Laws {
        dielectric: clamped,
        ..Laws::radiometry()
    };
    let check = random_check(&broken, &Laws64::radiometry(), "fresnel_dielectric");
    caught_only(&check, |f| f.starts_with("f32 floats"));
    assert!(
        check.failures.iter().any(|f| f.contains("T = ")),
        "{:#?}",
        check.failures
    );
    let broken64 = Laws64 {
        dielectric: clamped64,
        ..Laws64::radiometry()
    };
    let check = random_check(&Laws::radiometry(), &broken64, "fresnel_dielectric");
    caught_only(&check, |f| f.starts_with("f64 floats"));
}

/// T as the textbook's `1 − R` in f32, which cancels wherever R is near 1:
/// at grazing incidence, most of the floats sampling, and near the
/// critical angle.
#[test]
fn the_textbook_transmittance_is_caught_by_the_random_cases() {
    use validation::mpmath::Laws64;
    fn one_minus_r(cos_i: f32, eta: f32) -> DielectricFresnel<f32> {
        let mut f = fresnel::dielectric_polarized(cos_i, eta);
        (f.t_s, f.t_p) = (1.0 - f.r_s, 1.0 - f.r_p);
        f
    }
    let broken = Laws {
        dielectric: one_minus_r,
        ..Laws::radiometry()
    };
    let check = random_check(&broken, &Laws64::radiometry(), "fresnel_dielectric");
    caught_only(&check, |f| f.starts_with("f32") && f.contains(" T"));
    caught_at(&check, |f| f.starts_with("f32 floats"));
}

/// Snell's law for angles through `acos √(1 − sin²θ_t)`, which loses every
/// digit of a small refracted angle (its cosine rounds to 1): caught where
/// the angles are tiny, which is most of the floats sampling.
#[test]
fn a_transmitted_angle_through_its_cosine_is_caught_at_tiny_angles() {
    use validation::mpmath::Laws64;
    fn through_cosine(theta_i: f32, eta_path: f32) -> Option<f32> {
        let s = theta_i.sin() / eta_path;
        (s <= 1.0).then(|| (1.0 - s * s).sqrt().acos())
    }
    let broken = Laws {
        transmitted_angle: through_cosine,
        ..Laws::radiometry()
    };
    let check = random_check(&broken, &Laws64::radiometry(), "transmitted_angle");
    caught_at(&check, |f| {
        f.starts_with("f32 floats") && f.contains("on average")
    });
    let tiny = |f: &String| f.starts_with("f32 floats #") && f.contains("θ_t");
    assert!(
        check.failures.iter().filter(|f| tiny(f)).count() > 4000,
        "{}",
        check.failures.len()
    );
}

/// A law within its per-case bound everywhere but three numbers off on
/// every case is caught by the average alone: Brewster's angle, correctly
/// rounded almost everywhere (worst 1), moved three floats up.
#[test]
fn a_law_off_by_three_floats_everywhere_is_caught_by_the_average_bits() {
    use validation::mpmath::Laws64;
    fn three_up(eta_path: f32) -> Option<f32> {
        radiometry::snell::brewster_angle(eta_path).map(|b| f32::from_bits(b.to_bits() + 3))
    }
    let broken = Laws {
        brewster_angle: three_up,
        ..Laws::radiometry()
    };
    let check = random_check(&broken, &Laws64::radiometry(), "brewster_angle");
    caught_only(&check, |f| f.starts_with("f32") && f.contains("on average"));
    assert_eq!(check.failures.len(), 2, "{:#?}", check.failures);
    let (random, sets) = random_reference();
    for unbroken in validation::mpmath::random::check_random(
        &Laws::radiometry(),
        &Laws64::radiometry(),
        &random,
        &sets,
    ) {
        assert!(
            unbroken.passed(),
            "{}: {:#?}",
            unbroken.id,
            unbroken.failures
        );
    }
}
