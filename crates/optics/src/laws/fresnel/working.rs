//! The working of `optics fresnel`, narrated from what each law returned.

use radiometry::course;
use radiometry::fresnel::{
    conductor_polarized, f0, schlick, DielectricFresnel, SchlickCosine, SchlickDielectric,
};
use radiometry::snell::Incidence;
use record::{number, Record};
use record::{say, Lang};
use tracer::scene::FresnelModel;

/// The side and angle of incidence, as resolved.
pub(super) fn narrate_incidence(
    record: &mut Record,
    lang: Lang,
    incidence: &Incidence<f64>,
    eta: f64,
    kappa: f64,
) {
    if kappa > 0.0 {
        record.step(|| {
            say!(
            lang,
            "light arrives from outside onto a conductor of complex index ñ = η + iκ = {} + {}i",
            "a fény kívülről érkezik egy ñ = η + iκ = {} + {}i komplex törésmutatójú vezetőre",
            number(eta),
            number(kappa)
        )
        });
    } else if incidence.from_inside {
        record.step(|| {
            say!(
                lang,
                "cos θi < 0: light arrives from inside, n_i = η = {}, n_t = 1",
                "cos θi < 0: a fény belülről érkezik, n_i = η = {}, n_t = 1",
                number(eta)
            )
        });
    } else {
        record.step(|| {
            say!(
                lang,
                "cos θi ≥ 0: light arrives from outside, n_i = 1, n_t = η = {}",
                "cos θi ≥ 0: a fény kívülről érkezik, n_i = 1, n_t = η = {}",
                number(eta)
            )
        });
    }
    record.step(|| {
        format!(
            "|cos θi| = {}, θi = {}°",
            number(incidence.abs_cos_i),
            number(incidence.abs_cos_i.acos().to_degrees())
        )
    });
}

/// The exact dielectric law's working, from what it returned; its `R`.
pub(super) fn exact_dielectric(
    record: &mut Record,
    lang: Lang,
    fresnel: &DielectricFresnel<f64>,
) -> f64 {
    match fresnel.cos_t {
        Some(cos_t) => record.step(|| {
            say!(
                lang,
                "Snell: cos θt = √(n_t² − n_i² sin²θi) / n_t = {} (θt = {}°)",
                "Snellius–Descartes: cos θt = √(n_t² − n_i² sin²θi) / n_t = {} (θt = {}°)",
                number(cos_t),
                number(cos_t.acos().to_degrees())
            )
        }),
        None => record.step(|| {
            say!(
                lang,
                "Snell: sin θt = n_i sin θi / n_t = {} > 1: total internal reflection",
                "Snellius–Descartes: sin θt = n_i sin θi / n_t = {} > 1: teljes visszaverődés",
                number(fresnel.incidence.sin_transmitted())
            )
        }),
    };
    if fresnel.is_total_internal_reflection() {
        record.step(|| {
            format!(
                "R_s = {}, R_p = {}",
                number(fresnel.r_s),
                number(fresnel.r_p)
            )
        });
    } else {
        record.step(|| {
            format!(
                "R_s = ((n_i cos θi − n_t cos θt) / (n_i cos θi + n_t cos θt))² = {}",
                number(fresnel.r_s)
            )
        });
        record.step(|| {
            format!(
                "R_p = ((n_t cos θi − n_i cos θt) / (n_t cos θi + n_i cos θt))² = {}",
                number(fresnel.r_p)
            )
        });
    }
    let r = fresnel.reflectance();
    record.step(|| format!("R = (R_s + R_p) / 2 = {}", number(r)));
    record.step(|| format!("T = 1 − R = {}", number(fresnel.transmittance())));
    record
        .detail("r_s", fresnel.r_s)
        .detail("r_p", fresnel.r_p)
        .detail("transmittance", fresnel.transmittance())
        .detail("cos_t", fresnel.cos_t)
        .detail(
            "total_internal_reflection",
            fresnel.is_total_internal_reflection(),
        );
    r
}

/// The exact conductor law's working, lit from outside at `incidence`; its `R`.
pub(super) fn exact_conductor(
    record: &mut Record,
    incidence: &Incidence<f64>,
    eta: f64,
    kappa: f64,
) -> f64 {
    let fresnel = conductor_polarized(incidence.abs_cos_i, eta, kappa);
    record.step(|| {
        format!(
            "R_s = |(cos θi − √(ñ² − sin²θi)) / (cos θi + √(ñ² − sin²θi))|² = {}",
            number(fresnel.r_s)
        )
    });
    record.step(|| {
        format!(
            "R_p = |(ñ² cos θi − √(ñ² − sin²θi)) / (ñ² cos θi + √(ñ² − sin²θi))|² = {}",
            number(fresnel.r_p)
        )
    });
    let r = fresnel.reflectance();
    record.step(|| format!("R = (R_s + R_p) / 2 = {}", number(r)));
    record.detail("r_s", fresnel.r_s).detail("r_p", fresnel.r_p);
    r
}

/// Schlick's working at a dielectric in the form `model` names, from the
/// cosine it says it took; both `forms` (`[incident, rarer]`, as
/// [`FresnelModel::SCHLICK_FORMS`] orders them) compared with the `exact`
/// law; its `R`.
pub(super) fn schlick_for_dielectric(
    record: &mut Record,
    lang: Lang,
    model: FresnelModel,
    forms: &[SchlickDielectric<f64>; 2],
    exact: &DielectricFresnel<f64>,
) -> f64 {
    let [incident, rarer] = forms;
    let working = if model == FresnelModel::SchlickIncident {
        incident
    } else {
        rarer
    };
    step_f0(record, working.f0);
    match working.cosine {
        SchlickCosine::Transmitted(cos_t) => {
            record.step(|| {
                say!(
                    lang,
                    "from the denser side Schlick takes the angle in the rarer medium: cos θt = {}",
                    "a sűrűbb oldalról Schlick a ritkább közegbeli szöget használja: cos θt = {}",
                    number(cos_t)
                )
            });
        }
        SchlickCosine::TotalInternalReflection => {
            record.step(|| {
                say!(
                    lang,
                    "beyond the critical angle: total internal reflection, R = 1",
                    "a határszögön túl: teljes visszaverődés, R = 1"
                )
            });
        }
        SchlickCosine::Incident if working.incidence.from_inside => {
            record.step(|| {
                say!(
                    lang,
                    "the incident form takes cos θi from the denser side too",
                    "a beesési alak a sűrűbb oldalról is a cos θi-t használja"
                )
            });
        }
        SchlickCosine::Incident => {}
    }
    if let Some(cos) = working.cosine_used() {
        step_schlick(record, working.f0, cos, working.reflectance);
    }
    let both = [incident.reflectance, rarer.reflectance];
    let exact_tir = exact.is_total_internal_reflection();
    let r = working.reflectance;
    compare_forms(
        record,
        lang,
        working.f0,
        both,
        r,
        exact.reflectance(),
        exact_tir,
    )
}

/// Schlick's approximation at a conductor, with the incident cosine (lit
/// from outside, both forms take it), compared with the exact law; its `R`.
pub(super) fn schlick_for_conductor(
    record: &mut Record,
    lang: Lang,
    incidence: &Incidence<f64>,
    eta: f64,
    kappa: f64,
) -> f64 {
    let f_0 = f0(eta, kappa);
    step_f0(record, f_0);
    let r = schlick(incidence.abs_cos_i, f_0);
    step_schlick(record, f_0, incidence.abs_cos_i, r);
    let exact = conductor_polarized(incidence.abs_cos_i, eta, kappa).reflectance();
    compare_forms(record, lang, f_0, [r, r], r, exact, false)
}

/// The course shader's Fresnel (`000`'s GLSL `Fresnel`), `F0 + (1 − F0)
/// cos⁵θ` at the incident cosine, as `optics render --fresnel course`
/// evaluates it, compared with the exact law; its `R`.
pub(super) fn course_form(
    record: &mut Record,
    lang: Lang,
    incidence: &Incidence<f64>,
    f_0: f64,
    exact: f64,
) -> f64 {
    step_f0(record, f_0);
    let cos = incidence.abs_cos_i;
    let r = course::fresnel_000_glsl(f_0, cos);
    record.step(|| say!(
        lang,
        "the course shader's R = F0 + (1 − F0) cos⁵θ = {} + {}·{}⁵ = {} (Schlick's term is (1 − cos θ)⁵: this is the Fresnel effect backwards)",
        "a kurzus shadere szerint R = F0 + (1 − F0) cos⁵θ = {} + {}·{}⁵ = {} (Schlick tagja (1 − cos θ)⁵: ez a Fresnel-hatás fordítva)",
        number(f_0),
        number(1.0 - f_0),
        number(cos),
        number(r)
    ));
    let label = lang.pick("course", "kurzus");
    compare_with_exact(record, lang, label, f_0, r, exact)
}

fn step_f0(record: &mut Record, f_0: f64) {
    record.step(|| format!("F0 = ((η − 1)² + κ²) / ((η + 1)² + κ²) = {}", number(f_0)));
}

fn step_schlick(record: &mut Record, f_0: f64, cos: f64, r: f64) {
    record.step(|| {
        format!(
            "R ≈ F0 + (1 − F0)(1 − cos θ)⁵ = {} + {}·{}⁵ = {}",
            number(f_0),
            number(1.0 - f_0),
            number(1.0 - cos),
            number(r)
        )
    });
}

/// How close a Schlick form must come to the exact law to be called close.
const CLOSE: f64 = 0.01;

/// `r`, the chosen form's `R`, and both Schlick `forms` (in
/// [`FresnelModel::SCHLICK_FORMS`]' order) beside the exact law's, each
/// with a verdict; the exact law's `exact_tir` says whether it decided
/// total internal reflection.
fn compare_forms(
    record: &mut Record,
    lang: Lang,
    f_0: f64,
    forms: [f64; 2],
    r: f64,
    exact: f64,
    exact_tir: bool,
) -> f64 {
    record.step(|| {
        let each: Vec<String> = FresnelModel::SCHLICK_FORMS
            .iter()
            .zip(forms)
            .map(|(model, form)| {
                let verdict = verdict(form, exact, exact_tir, lang);
                format!("{model} R = {}: {verdict}", number(form))
            })
            .collect();
        say!(
            lang,
            "for comparison, the exact law gives R = {}; {}",
            "összevetésül a pontos képlet: R = {}; {}",
            number(exact),
            each.join("; ")
        )
    });
    let named: std::collections::BTreeMap<String, f64> = FresnelModel::SCHLICK_FORMS
        .iter()
        .zip(forms)
        .map(|(model, form)| (model.to_string(), form))
        .collect();
    record
        .detail("f0", f_0)
        .detail("exact", exact)
        .detail("error", r - exact)
        .details_from(named);
    r
}

/// A Schlick form's `R` against the exact law's, in plain words.
fn verdict(form: f64, exact: f64, exact_tir: bool, lang: Lang) -> String {
    if exact_tir && form < 1.0 {
        say!(
            lang,
            "misses total internal reflection here",
            "itt nem ismeri a teljes visszaverődést"
        )
    } else if (form - exact).abs() <= CLOSE {
        say!(
            lang,
            "within {CLOSE} of exact here",
            "itt legfeljebb {CLOSE} az eltérése a pontostól"
        )
    } else {
        let off = number((form - exact).abs());
        say!(
            lang,
            "off by {off} here",
            "itt {off} az eltérése a pontostól"
        )
    }
}

/// `R` of an approximation (`label`) beside the exact law's, and its error.
fn compare_with_exact(
    record: &mut Record,
    lang: Lang,
    label: &str,
    f_0: f64,
    r: f64,
    exact: f64,
) -> f64 {
    record.step(|| {
        say!(
            lang,
            "for comparison, the exact law gives R = {}: {} − exact = {}",
            "összevetésül a pontos képlet: R = {}, {} − pontos = {}",
            number(exact),
            label,
            number(r - exact)
        )
    });
    record
        .detail("f0", f_0)
        .detail("exact", exact)
        .detail("error", r - exact);
    r
}
