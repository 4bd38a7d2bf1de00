//! The mirror and refracted directions against Mitsuba and the exact ones,
//! with the allowance the critical angle's conditioning needs.

use glam::Vec3;

use super::reference::{DirectionCase, MitsubaLaws};
use super::under_test::Laws;
use super::verdict::{Verdict, DIRECTION_ABS, GROSS_ABS, MITSUBA_ABS};
use crate::case_words;
use crate::check::Check;

/// The extra allowance for a refracted direction near the critical angle,
/// per component.
///
/// A law that takes `wi` and `n` computes `cos θ_i = n·wi` itself, in float32,
/// off by up to about 2 ε₃₂; the transmitted direction
/// `t = −wi/η + (cos θ_i/η − cos θ_t) n` moves with it at the rate
/// `|1/η − cos θ_i / (η² cos θ_t)|`, which grows without bound as
/// `cos θ_t → 0`. There the square root caps it instead: the discriminant
/// `η²cos²θ_t = η² − sin²θ_i` moves by at most `2 cos θ_i · 2ε₃₂ ≤ 4ε₃₂`, so
/// `cos θ_t` moves by at most `2√ε₃₂ / η`, and the other terms by `2ε₃₂ / η`.
/// The allowance is the smaller of the two bounds. `cos_i = |n·wi|`,
/// `eta_path` the effective `n_t / n_i` (written η above), `cos_t` the exact
/// transmitted cosine.
pub fn refraction_allowance(cos_i: f64, eta_path: f64, cos_t: f64) -> f64 {
    let eps = f64::from(f32::EPSILON);
    let eta = eta_path;
    let linear = 2.0 * eps * (1.0 / eta - cos_i / (eta * eta * cos_t)).abs();
    let root = (2.0 * eps.sqrt() + 2.0 * eps) / eta;
    linear.min(root)
}

/// [`refraction_allowance`] from the input and the exact refracted direction.
pub fn refraction_allowance_at(wi: [f64; 3], n: [f64; 3], eta: f64, refracted: [f64; 3]) -> f64 {
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let cos_i = dot(wi, n);
    let eta_path =
        radiometry::snell::Incidence::resolve(cos_i, eta).map_or(f64::NAN, |i| i.eta_path());
    refraction_allowance(cos_i.abs(), eta_path, dot(refracted, n).abs())
}

/// The largest per-component difference of two directions; a NaN component
/// counts as infinitely far, so a NaN direction is never within a bound.
pub(crate) fn max_abs(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|i| (a[i] - b[i]).abs()).fold(
        0.0,
        |m, d| if d.is_nan() { f64::INFINITY } else { m.max(d) },
    )
}

/// A reference's direction (float32 values stored as doubles) as the `f32`
/// laws take it.
pub(crate) fn vec3(v: [f64; 3]) -> Vec3 {
    Vec3::new(v[0] as f32, v[1] as f32, v[2] as f32)
}

/// `mi.reflect` and `mi.refract` against ours and the exact directions.
pub fn check_directions(laws: &Laws, reference: &MitsubaLaws) -> Check {
    let mut check = Check::new(
        "laws.mitsuba.directions",
        [
            "Mirror and refracted directions, both sides, tilted normals, TIR",
            "Tükrözött és megtört irányok, mindkét oldalról, döntött normálisokkal, teljes visszaverődéssel",
        ],
        reference.version().each_ref().map(String::as_str),
        [&format!(
            "ours within {DIRECTION_ABS:.1e} of exact per component, plus the refraction_allowance for the conditioning near the critical angle; Mitsuba beyond {MITSUBA_ABS:.1e} is a finding; ours and Mitsuba within {GROSS_ABS:e}"
        ), &format!("a miénk komponensenként legfeljebb {DIRECTION_ABS:.1e} eltéréssel a pontostól, plusz a refraction_allowance a határszög közeli kondicionáltság miatt; a Mitsuba {MITSUBA_ABS:.1e} fölötti eltérése megállapítás; a miénk és a Mitsubáé legfeljebb {GROSS_ABS:e} eltéréssel")],
    );
    for case in &reference.directions {
        let (wi, n, label) = (vec3(case.wi), vec3(case.n), &case.label);
        check.cases += 1;
        let reflected = (laws.reflect)(wi, n);
        compare_direction(
            &mut check,
            "reflect",
            label,
            reflected,
            case.mitsuba.reflect,
            case.exact.reflect,
            0.0,
        );
        let refracted = (laws.refract)(wi, n, case.eta as f32);
        match (refracted, case.exact.refract) {
            (Some(ours), Some(exact)) => {
                let allowance = laws_allowance(case, exact);
                compare_direction(
                    &mut check,
                    "refract",
                    label,
                    ours.direction,
                    case.mitsuba.refract,
                    exact,
                    allowance,
                )
            }
            (None, None) => {
                if case.mitsuba.cos_t != 0.0 {
                    check.find([
                        format!("Mitsuba at {label}: refracts under total internal reflection"),
                        format!(
                            "a Mitsuba itt: {}: teljes visszaverődésnél is megtöri a sugarat",
                            case_words::in_hungarian(label)
                        ),
                    ]);
                }
            }
            (ours, exact) => check.fail_in_both([
                format!(
                    "{label}: refraction {} but exactly {}",
                    if ours.is_some() { "exists" } else { "is TIR" },
                    if exact.is_some() { "exists" } else { "is TIR" }
                ),
                format!(
                    "{}: a törés {}, a pontos szerint {}",
                    case_words::in_hungarian(label),
                    if ours.is_some() {
                        "létezik"
                    } else {
                        "teljes visszaverődés"
                    },
                    if exact.is_some() {
                        "létezik"
                    } else {
                        "teljes visszaverődés"
                    }
                ),
            ]),
        }
    }
    check
}

fn laws_allowance(case: &DirectionCase, exact: [f64; 3]) -> f64 {
    refraction_allowance_at(case.wi, case.n, case.eta, exact)
}

fn compare_direction(
    check: &mut Check,
    law: &str,
    label: &str,
    ours: Vec3,
    mitsuba: [f64; 3],
    exact: [f64; 3],
    allowance: f64,
) {
    let ours = ours.to_array().map(f64::from);
    let (ours_err, mitsuba_err) = (max_abs(ours, exact), max_abs(mitsuba, exact));
    let disagreement = max_abs(ours, mitsuba);
    check.measure_in_both(
        [
            &format!("{law}: max |ours − exact| per component"),
            &format!("{law}: max |miénk − pontos| komponensenként"),
        ],
        ours_err,
        label,
    );
    check.measure_in_both(
        [
            &format!("{law}: max |Mitsuba − exact| per component"),
            &format!("{law}: max |Mitsuba − pontos| komponensenként"),
        ],
        mitsuba_err,
        label,
    );
    check.measure_in_both(
        [
            &format!("{law}: max |ours − Mitsuba| per component"),
            &format!("{law}: max |miénk − Mitsuba| komponensenként"),
        ],
        disagreement,
        label,
    );
    let bound = DIRECTION_ABS + allowance;
    let verdict = Verdict::of(
        ours_err,
        bound,
        disagreement,
        mitsuba_err,
        MITSUBA_ABS + allowance,
    );
    let label_hu = case_words::in_hungarian(label);
    if verdict.ours_off {
        check.fail_in_both([
            format!(
                "{law} at {label}: ours {ours:?}, exact {exact:?} (off by {ours_err:.2e} > {bound:.1e})"
            ),
            format!(
                "{law} itt: {label_hu}: a miénk {ours:?}, a pontos {exact:?} (eltérés {ours_err:.2e} > {bound:.1e})"
            ),
        ]);
    }
    if verdict.gross {
        check.fail_in_both([
            format!(
                "{law} at {label}: ours {ours:?}, Mitsuba {mitsuba:?} differ by {disagreement:.2e}"
            ),
            format!(
                "{law} itt: {label_hu}: a miénk {ours:?} és a Mitsubáé {mitsuba:?} {disagreement:.2e}-vel tér el"
            ),
        ]);
    } else if verdict.mitsuba_off {
        check.find([
            format!("Mitsuba {law} at {label}: off the exact direction by {mitsuba_err:.2e}"),
            format!(
                "a Mitsuba {law} iránya itt: {}: {mitsuba_err:.2e} eltérés a pontos iránytól",
                case_words::in_hungarian(label)
            ),
        ]);
    }
}
