//! The Fresnel laws and Schlick's approximation against Mitsuba and the
//! exact values: each reflectance compared three ways (module docs of
//! [`crate::laws`]).

use super::reference::MitsubaLaws;
use super::under_test::Laws;
use super::verdict::{Verdict, GROSS_ABS, MITSUBA_ABS, OURS_ULPS};
use crate::case_words;
use crate::check::{ulps_f32, Check};

fn power(amplitude: [f64; 2]) -> f64 {
    amplitude[0] * amplitude[0] + amplitude[1] * amplitude[1]
}

/// Compares one scalar quantity three ways (see the module docs) and records
/// the outcome in `check`.
fn compare_scalar(
    check: &mut Check,
    quantity: &str,
    label: &str,
    ours: f64,
    mitsuba: f64,
    exact: f64,
) {
    let ours_ulps = ulps_f32(ours, exact);
    let mitsuba_err = (mitsuba - exact).abs();
    let disagreement = (ours - mitsuba).abs();
    check.measure_in_both(
        [
            &format!("{quantity}: |ours − exact| (f32 ulps)"),
            &format!("{quantity}: |miénk − pontos| (f32 ulps)"),
        ],
        ours_ulps,
        label,
    );
    check.measure_in_both(
        [
            &format!("{quantity}: |Mitsuba − exact|"),
            &format!("{quantity}: |Mitsuba − pontos|"),
        ],
        mitsuba_err,
        label,
    );
    check.measure_in_both(
        [
            &format!("{quantity}: |ours − Mitsuba|"),
            &format!("{quantity}: |miénk − Mitsuba|"),
        ],
        disagreement,
        label,
    );
    let verdict = Verdict::of(ours_ulps, OURS_ULPS, disagreement, mitsuba_err, MITSUBA_ABS);
    let label_hu = case_words::in_hungarian(label);
    if verdict.ours_off {
        check.fail_in_both([
            format!(
                "{quantity} at {label}: ours {ours:e}, exact {exact:e} ({ours_ulps:.1} ulps > {OURS_ULPS})"
            ),
            format!(
                "{quantity} itt: {label_hu}: a miénk {ours:e}, a pontos {exact:e} ({ours_ulps:.1} ulps > {OURS_ULPS})"
            ),
        ]);
    }
    if verdict.gross {
        check.fail_in_both([
            format!(
                "{quantity} at {label}: ours {ours:e}, Mitsuba {mitsuba:e} differ by {disagreement:.2e} > {GROSS_ABS:e}"
            ),
            format!(
                "{quantity} itt: {label_hu}: a miénk {ours:e} és a Mitsubáé {mitsuba:e} {disagreement:.2e}-vel tér el (> {GROSS_ABS:e})"
            ),
        ]);
    } else if verdict.mitsuba_off {
        let ulps = ulps_f32(mitsuba, exact);
        check.find([
            format!(
                "Mitsuba {quantity} at {label}: {mitsuba:e}, exact {exact:e} (off by {mitsuba_err:.2e}, {ulps:.0} f32 ulps)"
            ),
            format!(
                "a Mitsuba {quantity} értéke itt: {}: {mitsuba:e}, a pontos {exact:e} (eltérés {mitsuba_err:.2e}, {ulps:.0} f32 ulps)",
                case_words::in_hungarian(label)
            ),
        ]);
    }
}

/// R, R_s and R_p, each compared three ways: ours (`f32`), Mitsuba's
/// (unpolarised `f`, the powers of its amplitudes) and the exact values.
fn compare_polarised(
    check: &mut Check,
    label: &str,
    ours: [f32; 3],
    mitsuba: [f64; 3],
    exact: [f64; 3],
) {
    for (i, quantity) in ["R", "R_s", "R_p"].into_iter().enumerate() {
        compare_scalar(check, quantity, label, ours[i].into(), mitsuba[i], exact[i]);
    }
}

/// `mi.fresnel` and `mi.fresnel_polarized` (real index) against ours and the exact law.
pub fn check_dielectric(laws: &Laws, reference: &MitsubaLaws) -> Check {
    let mut check = Check::new(
        "laws.mitsuba.fresnel_dielectric",
        [
            "Dielectric Fresnel R, R_s, R_p, both sides, normal to grazing, TIR",
            "Dielektrikum Fresnel-egyenletei: R, R_s, R_p, mindkét oldalról, merőlegestől súrolóig, teljes visszaverődéssel",
        ],
        reference.version().each_ref().map(String::as_str),
        [&format!(
            "ours within {OURS_ULPS} f32 ulps of exact; Mitsuba beyond {MITSUBA_ABS:.1e} of exact is a finding; ours and Mitsuba within {GROSS_ABS:e}"
        ), &format!("a miénk legfeljebb {OURS_ULPS} f32 ulp-re a pontostól; a Mitsuba {MITSUBA_ABS:.1e} fölötti eltérése a pontostól megállapítás; a miénk és a Mitsubáé legfeljebb {GROSS_ABS:e} eltéréssel")],
    );
    for case in &reference.dielectric {
        let ours = (laws.dielectric)(case.cos_i as f32, case.eta as f32);
        let label = &case.label;
        check.cases += 1;
        let ours_tir = ours.is_total_internal_reflection();
        if ours_tir != case.exact.tir {
            let yes_no = |tir: bool| if tir { "igen" } else { "nem" };
            check.fail_in_both([
                format!(
                    "{label}: total internal reflection {ours_tir} but exactly {}",
                    case.exact.tir
                ),
                format!(
                    "{}: teljes visszaverődés: {}, a pontos: {}",
                    case_words::in_hungarian(label),
                    yes_no(ours_tir),
                    yes_no(case.exact.tir)
                ),
            ]);
        }
        // Mitsuba signals TIR by cos_t = 0, which index-matched grazing light also gives.
        let mitsuba_tir = case.mitsuba.cos_t == 0.0 && case.eta != 1.0;
        if mitsuba_tir != case.exact.tir {
            let yes_no = |tir: bool| if tir { "igen" } else { "nem" };
            check.find([
                format!(
                    "Mitsuba at {label}: total internal reflection {mitsuba_tir} but exactly {}",
                    case.exact.tir
                ),
                format!(
                    "a Mitsuba itt: {}: teljes visszaverődés: {}, a pontos: {}",
                    case_words::in_hungarian(label),
                    yes_no(mitsuba_tir),
                    yes_no(case.exact.tir)
                ),
            ]);
        }
        let (m, e) = (&case.mitsuba, &case.exact);
        compare_polarised(
            &mut check,
            label,
            [ours.reflectance(), ours.r_s, ours.r_p],
            [m.f, power(m.a_s), power(m.a_p)],
            [e.r, e.r_s, e.r_p],
        );
        // The effective index along the path is a convention, not a rounding.
        if (f64::from(ours.eta_path()) - m.eta_it).abs() > 1e-6 * m.eta_it {
            let eta = ours.eta_path();
            check.fail_in_both([
                format!(
                    "{label}: eta along the path {eta} but Mitsuba's eta_it is {}",
                    m.eta_it
                ),
                format!(
                    "{}: az út menti eta {eta}, de a Mitsuba eta_it értéke {}",
                    case_words::in_hungarian(label),
                    m.eta_it
                ),
            ]);
        }
    }
    check.sum_up(|c| mitsuba_gist(c, "fresnel"));
    check
}

/// `mi.fresnel_conductor` and complex `mi.fresnel_polarized` against ours and the exact law.
pub fn check_conductor(laws: &Laws, reference: &MitsubaLaws) -> Check {
    let mut check = Check::new(
        "laws.mitsuba.fresnel_conductor",
        [
            "Conductor Fresnel R, R_s, R_p (n + iκ), normal to grazing",
            "Vezető Fresnel-egyenletei: R, R_s, R_p (n + iκ), merőlegestől súrolóig",
        ],
        reference.version().each_ref().map(String::as_str),
        [&format!(
            "ours within {OURS_ULPS} f32 ulps of exact; Mitsuba beyond {MITSUBA_ABS:.1e} of exact is a finding; ours and Mitsuba within {GROSS_ABS:e}"
        ), &format!("a miénk legfeljebb {OURS_ULPS} f32 ulp-re a pontostól; a Mitsuba {MITSUBA_ABS:.1e} fölötti eltérése a pontostól megállapítás; a miénk és a Mitsubáé legfeljebb {GROSS_ABS:e} eltéréssel")],
    );
    for case in &reference.conductor {
        let ours = (laws.conductor)(case.cos_i as f32, case.n as f32, case.kappa as f32);
        let (label, m, e) = (&case.label, &case.mitsuba, &case.exact);
        check.cases += 1;
        compare_polarised(
            &mut check,
            label,
            [ours.reflectance(), ours.r_s, ours.r_p],
            [m.f, power(m.a_s), power(m.a_p)],
            [e.r, e.r_s, e.r_p],
        );
    }
    check.sum_up(|c| mitsuba_gist(c, "fresnel_conductor"));
    check
}

/// The findings of a law check in one sentence: how far Mitsuba's float32
/// `law` strays from the exact law at worst, and where.
fn mitsuba_gist(check: &Check, law: &str) -> [String; 2] {
    let worst = ["R", "R_s", "R_p"]
        .iter()
        .filter_map(|q| check.worst(&format!("{q}: |Mitsuba − exact|")))
        .max_by(|a, b| a.worst.total_cmp(&b.worst));
    let n = check.findings.len();
    match worst {
        Some(m) => [
            format!(
                "Mitsuba's float32 `{law}` departs from the exact law by up to {:.1e}, at {} \
                 ({n} values beyond {MITSUBA_ABS:.1e}).",
                m.worst, m.at
            ),
            format!(
                "A Mitsuba float32 `{law}` függvénye legfeljebb {:.1e} eltéréssel tér el a pontos \
                 törvénytől, itt: `{}` ({n} érték {MITSUBA_ABS:.1e} fölött).",
                m.worst, m.at
            ),
        ],
        None => [
            format!("Mitsuba's float32 `{law}` departs from the exact law."),
            format!("A Mitsuba float32 `{law}` függvénye eltér a pontos törvénytől."),
        ],
    }
}

/// Schlick's approximation against its exact definition (Mitsuba has no
/// binding for it, so this is a check of the formula, not of a renderer).
pub fn check_schlick(laws: &Laws, reference: &MitsubaLaws) -> Check {
    let mut check = Check::new(
        "laws.mpmath.schlick",
        [
            "Schlick's approximation F0 + (1 − F0)(1 − cos)⁵ against its definition",
            "A Schlick-közelítés, F0 + (1 − F0)(1 − cos)⁵, a definíciójához mérve",
        ],
        ["mpmath, 50 digits", "mpmath, 50 jegyre"],
        [&format!("within {OURS_ULPS} f32 ulps: five products and a sum, each rounded once"), &format!("legfeljebb {OURS_ULPS} f32 ulp: öt szorzat és egy összeg, mindegyik egyszer kerekítve")],
    );
    for case in &reference.schlick {
        let ours: f64 = (laws.schlick)(case.cos_i as f32, case.f0 as f32).into();
        let ulps = ulps_f32(ours, case.exact);
        check.cases += 1;
        check.measure_in_both(
            ["|ours − exact| (f32 ulps)", "|miénk − pontos| (f32 ulps)"],
            ulps,
            &case.label,
        );
        if !(ulps <= OURS_ULPS) {
            check.fail_in_both([
                format!(
                    "{}: ours {ours:e}, exact {:e} ({ulps:.1} ulps)",
                    case.label, case.exact
                ),
                format!(
                    "{}: a miénk {ours:e}, a pontos {:e} ({ulps:.1} ulps)",
                    case_words::in_hungarian(&case.label),
                    case.exact
                ),
            ]);
        }
    }
    check
}
