//! N-BK7's dispersion: its Sellmeier index against Schott's data sheet,
//! the traced prism against the analytic minimum deviation, and a glass
//! sphere rendered with the three etas and one index against the spectrum.

use techniques::dispersion::prism::{Passage, Prism};
use techniques::dispersion::{fraunhofer_nm, Sellmeier};

use super::dispersion;
use crate::check::Check;

/// Schott's N-BK7 data sheet: the indices it prints (five decimals) at the
/// Fraunhofer lines (SCHOTT AG, Optical Glass Data Sheets, glass code
/// 517642.251).
pub const N_BK7_DATA_SHEET: [(&str, f64, f64); 4] = [
    ("n_F", fraunhofer_nm::F, 1.52238),
    ("n_e", fraunhofer_nm::E, 1.51872),
    ("n_d", fraunhofer_nm::D, 1.51680),
    ("n_C", fraunhofer_nm::C, 1.51432),
];

/// Half a unit in the data sheet's last printed digit.
pub const DATA_SHEET_ABS: f64 = 5e-6;

/// The Sellmeier index against the data sheet.
pub fn check_sellmeier(glass: &Sellmeier) -> Check {
    let mut check = Check::new(
        "techniques.dispersion.n_bk7",
        [
            "N-BK7's refractive index by the Sellmeier equation at the Fraunhofer lines",
            "Az N-BK7 törésmutatója a Sellmeier-egyenletből a Fraunhofer-vonalaknál",
        ],
        [
            "Schott's N-BK7 data sheet (five printed decimals)",
            "a Schott N-BK7 adatlapja (öt nyomtatott tizedesjegy)",
        ],
        [
            &format!("within {DATA_SHEET_ABS:e}, half a unit in the last printed digit"),
            &format!("legfeljebb {DATA_SHEET_ABS:e}, fél egység az utolsó nyomtatott jegyben"),
        ],
    );
    for (line, nm, printed) in N_BK7_DATA_SHEET {
        check.cases += 1;
        let Some(n) = glass.index_at(nm) else {
            check.fail(format!("{line} ({nm} nm): no index"));
            continue;
        };
        let err = (n - printed).abs();
        check.measure_in_both(
            ["|Sellmeier − data sheet|", "|Sellmeier − adatlap|"],
            err,
            &format!("{line}, {nm} nm"),
        );
        if !(err <= DATA_SHEET_ABS) {
            check.fail(format!(
                "{line} ({nm} nm): {n:.7}, the data sheet {printed}"
            ));
        }
    }
    check
}

/// How close the traced symmetric passage comes to the analytic minimum
/// deviation, radians: a few ulps of the angles involved.
pub const PRISM_ABS: f64 = 1e-12;

/// A 60° prism of `glass` across the visible: the ray traced at the
/// symmetric incidence with the radiometry refraction law deviates by the
/// analytic `2 asin(n sin(A/2)) − A`, and rays 0.01 rad to either side
/// deviate more; the spread between the F and C lines measured.
pub fn check_prism(glass: &Sellmeier) -> Check {
    let mut check = Check::new(
        "techniques.dispersion.prism",
        [
            "A 60° prism: the traced deviation at symmetric incidence is the analytic minimum deviation",
            "Egy 60°-os prizma: a szimmetrikus beesésnél követett eltérítés az analitikus legkisebb eltérítés",
        ],
        [
            "δ_min = 2 asin(n sin(A/2)) − A (Snell's law at both faces of a symmetric passage)",
            "δ_min = 2 arcsin(n sin(A/2)) − A (a Snellius–Descartes-törvény mindkét lapon, szimmetrikus áthaladásnál)",
        ],
        [&format!("within {PRISM_ABS:e} rad; any other incidence deviates more"), &format!("legfeljebb {PRISM_ABS:e} rad; minden más beesés jobban eltérít")],
    );
    let prism = Prism::new(60f64.to_radians()).expect("60° is an apex angle");
    let deviation = |n: f64, theta: f64| match prism.trace(n, theta) {
        Some(Passage::Emerges { deviation, .. }) => Some(deviation),
        _ => None,
    };
    for nm in (400..=700).step_by(25).map(f64::from) {
        check.cases += 1;
        let (Some(n), at) = (glass.index_at(nm), format!("{nm} nm")) else {
            check.fail(format!("{nm} nm: no index"));
            continue;
        };
        let (Some(theta), Some(analytic)) =
            (prism.symmetric_incidence(n), prism.minimum_deviation(n))
        else {
            check.fail(format!("{at}: no symmetric passage for n = {n}"));
            continue;
        };
        let Some(traced) = deviation(n, theta) else {
            check.fail(format!("{at}: the symmetric ray does not emerge"));
            continue;
        };
        check.measure_in_both(
            ["|traced − analytic| (rad)", "|követett − analitikus| (rad)"],
            (traced - analytic).abs(),
            &at,
        );
        if !((traced - analytic).abs() <= PRISM_ABS) {
            check.fail(format!("{at}: traced {traced}, analytic {analytic}"));
        }
        for other in [theta - 0.01, theta + 0.01] {
            if deviation(n, other).is_some_and(|d| d <= traced) {
                check.fail(format!(
                    "{at}: incidence {other} rad deviates no more than the minimum"
                ));
            }
        }
    }
    let spread = [fraunhofer_nm::F, fraunhofer_nm::C]
        .map(|nm| glass.index_at(nm).and_then(|n| prism.minimum_deviation(n)));
    if let [Some(f), Some(c)] = spread {
        check.measure_in_both(
            [
                "F − C spread of the minimum deviation (°)",
                "a legkisebb eltérítés F − C szórása (°)",
            ],
            (f - c).to_degrees(),
            "",
        );
    }
    check
}

/// How far a pixel that does not see the sphere may move between the
/// spectral render and the single-index one, relative: nothing there
/// depends on the index, so only the CIE integral of a flat spectrum,
/// whose white (the tabulated D65, x = 0.31271, y = 0.32902) is not the
/// sRGB standard's (0.3127, 0.3290) to the last digit: a flat spectrum
/// comes back as linear sRGB (0.99992, 1.00009, 0.99998).
pub const FLAT_SPECTRUM_RELATIVE: f64 = 2e-4;

/// How far the spectral render departs from the single-index one off
/// the sphere, in English and in Hungarian.
const AWAY: [&str; 2] = [
    "away from the sphere: |spectral − one index|, relative",
    "a gömbön kívül: |spektrális − egy törésmutató|, relatív",
];

/// A glass sphere of N-BK7 rendered with dispersion
/// ([`dispersion`]): the three etas and one index measured against the
/// spectral answer; the three etas must come closer than one index (a
/// channel taken from the wrong render would not), and a pixel that does
/// not see the sphere must come out of the spectral integral as it went in.
///
/// `three` makes the three-eta render ([`dispersion::three_etas`] in the
/// suite).
pub fn check_dispersion_render(three: fn(&tracer::scene::Scene) -> tracer::render::Image) -> Check {
    let mut check = Check::new(
        "techniques.dispersion.sphere",
        [
            "A glass sphere of N-BK7: the slides' three etas and one index against the spectral render",
            "N-BK7 üveggömb: a diák három eta-értéke és egyetlen törésmutatója a spektrális képhez mérve",
        ],
        [
            "85 Whitted renders at the Sellmeier index, integrated with the CIE 1931 tables under D65",
            "85 Whitted-féle kép a Sellmeier-féle törésmutatóval, a CIE 1931 táblázataival integrálva D65 alatt",
        ],
        [&format!(
            "the three etas closer than one index in ΔE2000 mean and relative RMSE; away from the \
             sphere the spectral render equals the single-index one within {FLAT_SPECTRUM_RELATIVE:e}, relative"
        ), &format!("a három eta közelebb, mint egy törésmutató, ΔE2000 átlagban és relatív négyzetes középhibában; a gömbön kívül a spektrális kép legfeljebb {FLAT_SPECTRUM_RELATIVE:e} relatív eltéréssel egyezik az egy törésmutatós képpel")],
    );
    let r = dispersion::renders_with(three);
    check.cases = r.sphere.len();
    let (three, one) = (
        dispersion::measures(&r.three, &r),
        dispersion::measures(&r.single, &r),
    );
    let kinds = [
        (["three etas", "három eta"], three),
        (["one index", "egy törésmutató"], one),
    ];
    for ([what, what_hu], e) in kinds {
        let at = "the sphere's pixels";
        check.measure_in_both(
            [
                &format!("{what}: ΔE2000 mean"),
                &format!("{what_hu}: ΔE2000 átlag"),
            ],
            e.delta_e_mean,
            at,
        );
        check.measure_in_both(
            [
                &format!("{what}: ΔE2000 p99"),
                &format!("{what_hu}: ΔE2000 p99"),
            ],
            e.delta_e_p99,
            at,
        );
        check.measure_in_both(
            [
                &format!("{what}: relative RMSE"),
                &format!("{what_hu}: relatív négyzetes középhiba"),
            ],
            e.rel_rmse,
            at,
        );
    }
    if !(three.delta_e_mean < one.delta_e_mean && three.rel_rmse < one.rel_rmse) {
        check.fail(format!(
            "three etas (ΔE mean {:.3}, RMSE {:.4}) no closer than one index ({:.3}, {:.4})",
            three.delta_e_mean, three.rel_rmse, one.delta_e_mean, one.rel_rmse
        ));
    }
    for (p, _) in r.sphere.iter().enumerate().filter(|(_, s)| s.is_none()) {
        let (a, b) = (
            r.spectral.pixels[p].as_dvec3(),
            r.single.pixels[p].as_dvec3(),
        );
        let off = (a - b).abs().max_element() / b.abs().max_element().max(1e-3);
        check.measure_at_in_both(AWAY, off, || format!("pixel {p}"));
    }
    if let Some(m) = check.worst(AWAY[0]) {
        if !(m.worst <= FLAT_SPECTRUM_RELATIVE) {
            check.fail(format!(
                "{}: a flat spectrum comes back {:e} off",
                m.at, m.worst
            ));
        }
    }
    check
}
