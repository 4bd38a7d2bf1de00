//! The random cases compared: our `f32` laws against Mitsuba's results and
//! our `f64` laws, by the tolerances and the failure/finding rule of
//! [`crate::laws`].

use glam::DVec3;

use super::cases::{CasesFile, LawCase, LawResult, ResultsFile};
use crate::case_words;
use crate::check::{ulps_f32, Check};
use crate::laws::directions::{max_abs, vec3};
use crate::laws::{
    refraction_allowance_at, Laws, Laws64, Verdict, DIRECTION_ABS, GROSS_ABS, MITSUBA_ABS,
    OURS_ULPS,
};

/// Compares our `f32` laws with Mitsuba and with our `f64` laws at every
/// exported case.
pub fn check_random(
    laws: &Laws,
    laws64: &Laws64,
    cases: &CasesFile,
    results: &ResultsFile,
) -> Check {
    let mut check = Check::new(
        "laws.mitsuba.random",
        [
            "Fresnel (dielectric, conductor), reflection and refraction at random inputs exported by the harness, \
             against Mitsuba, with our f64 laws standing in for the exact value (the random cases against \
             50 digits are laws.mpmath.random.*)",
            "Fresnel (dielektrikum, vezető), visszaverődés és törés a keretrendszer exportálta véletlen \
             bemeneteken, a Mitsubához mérve, a pontos érték helyén f64 törvényeinkkel (az 50 jegyhez mért \
             véletlen esetek: laws.mpmath.random.*)",
        ],
        [
            &format!("{} on cases.json (seed {})", results.evaluator, cases.seed),
            &format!("{} a cases.json eseteire (mag: {})", results.evaluator, cases.seed),
        ],
        [&format!(
            "ours (f32) within {OURS_ULPS} f32 ulps of our f64 law (itself within 8 f64 ulps of exact), directions within {DIRECTION_ABS:.1e} plus the refraction allowance near the critical angle; Mitsuba beyond {MITSUBA_ABS:.1e} is a finding; ours and Mitsuba within {GROSS_ABS:e}"
        ), &format!("a miénk (f32) legfeljebb {OURS_ULPS} f32 ulp-re az f64 törvényünktől (amely maga legfeljebb 8 f64 ulp-re a pontostól), az irányok legfeljebb {DIRECTION_ABS:.1e} eltéréssel, plusz a törés ráhagyása a határszög közelében; a Mitsuba {MITSUBA_ABS:.1e} fölötti eltérése megállapítás; a miénk és a Mitsubáé legfeljebb {GROSS_ABS:e} eltéréssel")],
    );
    if cases.cases.len() != results.results.len() {
        let (cases, results) = (cases.cases.len(), results.results.len());
        check.fail_in_both([
            format!("{cases} cases but {results} results"),
            format!("{cases} eset, de {results} eredmény"),
        ]);
        return check;
    }
    for (i, (case, result)) in cases.cases.iter().zip(&results.results).enumerate() {
        check.cases += 1;
        let label = format!(
            "case {i}: {}",
            serde_json::to_string(case).unwrap_or_default()
        );
        compare_case(&mut check, laws, laws64, &label, case, result);
    }
    check
}

/// One exported case: ours (`f32`) against Mitsuba and our `f64` law.
fn compare_case(
    check: &mut Check,
    laws: &Laws,
    laws64: &Laws64,
    label: &str,
    case: &LawCase,
    result: &LawResult,
) {
    match *case {
        LawCase::Fresnel { cos_i, eta } => {
            let ours = (laws.dielectric)(cos_i as f32, eta as f32);
            let exact = (laws64.dielectric)(cos_i, eta);
            if ours.is_total_internal_reflection() != exact.is_total_internal_reflection() {
                check.fail_in_both(tir_differs(label));
            }
            scalar(
                check,
                "fresnel R",
                label,
                ours.reflectance().into(),
                result.f,
                exact.reflectance(),
            );
        }
        LawCase::FresnelConductor { cos_i, n, kappa } => {
            let ours = (laws.conductor)(cos_i as f32, n as f32, kappa as f32);
            let exact = (laws64.conductor)(cos_i, n, kappa);
            scalar(
                check,
                "fresnel_conductor R",
                label,
                ours.reflectance().into(),
                result.f,
                exact.reflectance(),
            );
        }
        LawCase::Directions { wi, n, eta } => {
            compare_directions(check, laws, laws64, label, (wi, n, eta), result)
        }
    }
}

/// One exported direction case: the mirror and the refracted direction.
fn compare_directions(
    check: &mut Check,
    laws: &Laws,
    laws64: &Laws64,
    label: &str,
    (wi, n, eta): ([f64; 3], [f64; 3], f64),
    result: &LawResult,
) {
    let (wi64, n64) = (DVec3::from_array(wi), DVec3::from_array(n));
    let ours = (laws.reflect)(vec3(wi), vec3(n)).to_array().map(f64::from);
    let exact = (laws64.reflect)(wi64, n64).to_array();
    direction(check, "reflect", label, ours, result.reflect, exact, 0.0);
    let ours = (laws.refract)(vec3(wi), vec3(n), eta as f32);
    let exact = (laws64.refract)(wi64, n64, eta);
    match (ours, exact) {
        (Some(o), Some(e)) => {
            let exact = e.direction.to_array();
            let allowance = refraction_allowance_at(wi, n, eta, exact);
            let ours = o.direction.to_array().map(f64::from);
            direction(
                check,
                "refract",
                label,
                ours,
                result.refract,
                exact,
                allowance,
            )
        }
        (None, None) => {
            if result.cos_t.is_some_and(|c| c != 0.0) {
                check.find([
                    format!("Mitsuba at {label}: refracts under total internal reflection"),
                    format!(
                        "a Mitsuba itt: {}: teljes visszaverődésnél is megtöri a sugarat",
                        case_words::in_hungarian(label)
                    ),
                ]);
            }
        }
        _ => check.fail_in_both(tir_differs(label)),
    }
}

fn scalar(check: &mut Check, law: &str, label: &str, ours: f64, mitsuba: Option<f64>, exact: f64) {
    let ulps = ulps_f32(ours, exact);
    let (err, gap) = mitsuba.map_or((f64::NAN, f64::NAN), |m| {
        ((m - exact).abs(), (ours - m).abs())
    });
    let verdict = Verdict::of(ulps, OURS_ULPS, gap, err, MITSUBA_ABS);
    check.measure_in_both(
        [
            &format!("{law}: |ours − f64 law| (f32 ulps)"),
            &format!("{law}: |miénk − f64 törvény| (f32 ulps)"),
        ],
        ulps,
        label,
    );
    if verdict.ours_off {
        check.fail_in_both([
            format!("{law} at {label}: ours {ours:e}, f64 law {exact:e} ({ulps:.1} ulps)"),
            format!(
                "{law} itt: {}: a miénk {ours:e}, az f64 törvény {exact:e} ({ulps:.1} ulps)",
                case_words::in_hungarian(label)
            ),
        ]);
    }
    let Some(mitsuba) = mitsuba else {
        check.fail_in_both(no_result(law, label));
        return;
    };
    check.measure_in_both(
        [
            &format!("{law}: |Mitsuba − f64 law|"),
            &format!("{law}: |Mitsuba − f64 törvény|"),
        ],
        err,
        label,
    );
    if verdict.gross {
        check.fail_in_both([
            format!("{law} at {label}: ours {ours:e}, Mitsuba {mitsuba:e}"),
            format!(
                "{law} itt: {}: a miénk {ours:e}, a Mitsubáé {mitsuba:e}",
                case_words::in_hungarian(label)
            ),
        ]);
    } else if verdict.mitsuba_off {
        check.find([
            format!("Mitsuba {law} at {label}: {mitsuba:e}, exact {exact:e} (off by {err:.2e})"),
            format!(
                "a Mitsuba {law} értéke itt: {}: {mitsuba:e}, a pontos {exact:e} (eltérés {err:.2e})",
                case_words::in_hungarian(label)
            ),
        ]);
    }
}

fn direction(
    check: &mut Check,
    law: &str,
    label: &str,
    ours: [f64; 3],
    mitsuba: Option<[f64; 3]>,
    exact: [f64; 3],
    allowance: f64,
) {
    let err = max_abs(ours, exact);
    let bound = DIRECTION_ABS + allowance;
    let (m_err, gap) = mitsuba.map_or((f64::NAN, f64::NAN), |m| {
        (max_abs(m, exact), max_abs(ours, m))
    });
    let verdict = Verdict::of(err, bound, gap, m_err, MITSUBA_ABS + allowance);
    check.measure_in_both(
        [
            &format!("{law}: max |ours − f64 law| per component"),
            &format!("{law}: max |miénk − f64 törvény| komponensenként"),
        ],
        err,
        label,
    );
    if verdict.ours_off {
        check.fail_in_both([
            format!(
                "{law} at {label}: ours {ours:?}, f64 law {exact:?} (off by {err:.2e} > {bound:.1e})"
            ),
            format!(
                "{law} itt: {}: a miénk {ours:?}, az f64 törvény {exact:?} (eltérés {err:.2e} > {bound:.1e})",
                case_words::in_hungarian(label)
            ),
        ]);
    }
    let Some(mitsuba) = mitsuba else {
        check.fail_in_both(no_result(law, label));
        return;
    };
    check.measure_in_both(
        [
            &format!("{law}: max |Mitsuba − f64 law| per component"),
            &format!("{law}: max |Mitsuba − f64 törvény| komponensenként"),
        ],
        m_err,
        label,
    );
    if verdict.gross {
        check.fail_in_both([
            format!("{law} at {label}: ours {ours:?}, Mitsuba {mitsuba:?}"),
            format!(
                "{law} itt: {}: a miénk {ours:?}, a Mitsubáé {mitsuba:?}",
                case_words::in_hungarian(label)
            ),
        ]);
    } else if verdict.mitsuba_off {
        check.find([
            format!("Mitsuba {law} at {label}: off the exact direction by {m_err:.2e}"),
            format!(
                "a Mitsuba {law} iránya itt: {}: {m_err:.2e} eltérés a pontos iránytól",
                case_words::in_hungarian(label)
            ),
        ]);
    }
}

/// The failure of a case whose total internal reflection differs between
/// the tiers, `[English, Hungarian]`.
fn tir_differs(label: &str) -> [String; 2] {
    [
        format!("{label}: total internal reflection differs between f32 and f64"),
        format!(
            "{}: a teljes visszaverődés eltér f32 és f64 között",
            case_words::in_hungarian(label)
        ),
    ]
}

/// The failure of a case Mitsuba gave no result for, `[English, Hungarian]`.
fn no_result(law: &str, label: &str) -> [String; 2] {
    [
        format!("{law} at {label}: no result from Mitsuba"),
        format!(
            "{law} itt: {}: a Mitsuba nem adott eredményt",
            case_words::in_hungarian(label)
        ),
    ]
}
