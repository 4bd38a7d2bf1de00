//! The working of `optics fresnel` reports the laws' own numbers.

use super::*;
use radiometry::fresnel::SchlickCosine;
use radiometry::fresnel::{dielectric_polarized, schlick_dielectric_working};
use record::number;
use record::Steps;

fn solve(eta: f64, cos_i: f64, model: FresnelModel) -> Record {
    let args = FresnelArgs {
        eta: Some(eta),
        kappa: 0.0,
        metal: None,
        cos_i: Some(cos_i),
        theta_i_deg: None,
        model: model.into(),
    };
    args.solve(Via::Flags, Lang::En, Steps::Wanted)
        .expect("a valid request")
}

fn answer(record: &Record) -> f64 {
    match record.answer {
        Answer::Number(r) => r,
        ref other => panic!("a number, got {other:?}"),
    }
}

fn detail(record: &Record, name: &str) -> Option<f64> {
    record.details.get(name).and_then(|v| v.as_f64())
}

fn has_step(record: &Record, line: &str) -> bool {
    record.steps.iter().any(|s| s.contains(line))
}

/// Entering and leaving glass, below and beyond the critical angle, at
/// grazing incidence, and index-matched.
const CASES: [(f64, f64); 7] = [
    (1.5, 0.5),
    (1.5, -0.9),
    (1.5, -0.5),
    (0.7, 0.3),
    (0.7, 0.9),
    (1.0, -0.3),
    (1.5, 0.0),
];

/// The exact law's working reports the law's own numbers, bit for bit,
/// and narrates the `cos θt` (or the Snell sine of the incidence) it
/// returned: nothing in it is computed by a second evaluation.
#[test]
fn exact_working_reports_the_laws_own_numbers() {
    for (eta, cos_i) in CASES {
        let law = dielectric_polarized(cos_i, eta);
        let record = solve(eta, cos_i, FresnelModel::Exact);
        let at = format!("eta {eta}, cos_i {cos_i}");
        assert_eq!(
            answer(&record).to_bits(),
            law.reflectance().to_bits(),
            "{at}"
        );
        assert_eq!(
            detail(&record, "cos_t").map(f64::to_bits),
            law.cos_t.map(f64::to_bits),
            "{at}"
        );
        assert_eq!(
            detail(&record, "r_s").map(f64::to_bits),
            Some(law.r_s.to_bits()),
            "{at}"
        );
        let snell = match law.cos_t {
            Some(cos_t) => format!("/ n_t = {} (θt", number(cos_t)),
            None => format!("= {} > 1", number(law.incidence.sin_transmitted())),
        };
        assert!(has_step(&record, &snell), "{at}: {:#?}", record.steps);
    }
}

/// Schlick's working reports the working's numbers and the exact law's,
/// bit for bit, and narrates the cosine the working says it took.
#[test]
fn schlick_working_narrates_the_cosine_the_law_took() {
    for (eta, cos_i) in CASES {
        let working = schlick_dielectric_working(cos_i, eta).expect("a valid interface");
        let exact = dielectric_polarized(cos_i, eta).reflectance();
        let record = solve(eta, cos_i, FresnelModel::SchlickRarer);
        let at = format!("eta {eta}, cos_i {cos_i}");
        assert_eq!(
            answer(&record).to_bits(),
            working.reflectance.to_bits(),
            "{at}"
        );
        assert_eq!(
            detail(&record, "exact").map(f64::to_bits),
            Some(exact.to_bits()),
            "{at}"
        );
        assert_eq!(
            detail(&record, "f0").map(f64::to_bits),
            Some(working.f0.to_bits()),
            "{at}"
        );
        let rarer = "Schlick takes the angle in the rarer medium";
        let tir = "total internal reflection, R = 1";
        let formula = working
            .cosine_used()
            .map(|cos| format!("·{}⁵ = {}", number(1.0 - cos), number(working.reflectance)));
        match working.cosine {
            SchlickCosine::Incident => assert!(!has_step(&record, rarer), "{at}"),
            SchlickCosine::Transmitted(_) => assert!(has_step(&record, rarer), "{at}"),
            SchlickCosine::TotalInternalReflection => assert!(has_step(&record, tir), "{at}"),
        }
        match formula {
            Some(line) => assert!(has_step(&record, &line), "{at}: {:#?}", record.steps),
            None => assert!(!has_step(&record, "R ≈"), "{at}"),
        }
    }
}

/// `--model course` is the course shader's law as the tracer's
/// `--fresnel course` evaluates it, beside the exact law, bit for bit.
#[test]
fn course_working_reports_the_course_shaders_own_numbers() {
    for (eta, cos_i) in CASES {
        let f_0 = radiometry::fresnel::f0(eta, 0.0);
        let course = radiometry::course::fresnel_000_glsl(f_0, cos_i.abs());
        let exact = dielectric_polarized(cos_i, eta).reflectance();
        let record = solve(eta, cos_i, FresnelModel::Course);
        let at = format!("eta {eta}, cos_i {cos_i}");
        assert_eq!(answer(&record).to_bits(), course.to_bits(), "{at}");
        assert_eq!(
            detail(&record, "exact").map(f64::to_bits),
            Some(exact.to_bits()),
            "{at}"
        );
        assert_eq!(
            detail(&record, "error").map(f64::to_bits),
            Some((course - exact).to_bits()),
            "{at}"
        );
        assert!(has_step(&record, "course − exact"), "{at}");
    }
}

/// The incident form's working reports its own number, and the comparison
/// names both forms beside the exact law with a verdict each: inside glass
/// at 60° (θi = 120°) the exact law and the rarer-medium form give 1, the
/// incident form 0.07; entering glass at 30° both forms lie within 0.01 of
/// the exact law (0.0415 against 0.0400).
#[test]
fn the_comparison_names_both_schlick_forms_with_a_verdict_each() {
    let record = solve(1.5, -0.5, FresnelModel::SchlickIncident);
    assert!(
        (answer(&record) - 0.07).abs() <= 1e-12,
        "{}",
        answer(&record)
    );
    assert!((detail(&record, "schlick-incident").unwrap() - 0.07).abs() <= 1e-12);
    assert_eq!(detail(&record, "schlick-rarer"), Some(1.0));
    assert_eq!(detail(&record, "exact"), Some(1.0));
    let line = "schlick-incident R = 0.07: misses total internal reflection here; \
                schlick-rarer R = 1: within 0.01 of exact here";
    assert!(has_step(&record, line), "{:#?}", record.steps);
    let rarer = solve(1.5, -0.5, FresnelModel::SchlickRarer);
    assert_eq!(answer(&rarer), 1.0);
    assert!(has_step(&rarer, line), "{:#?}", rarer.steps);
    let entering = solve(
        1.5,
        30_f64.to_radians().cos(),
        FresnelModel::SchlickIncident,
    );
    let close = "within 0.01 of exact here";
    assert_eq!(
        entering.steps.last().unwrap().matches(close).count(),
        2,
        "{:#?}",
        entering.steps
    );
    // Inside glass at 40°, below the critical angle: the incident form is
    // off by more than 0.01, and says by how much.
    let below = solve(
        1.5,
        -40_f64.to_radians().cos(),
        FresnelModel::SchlickIncident,
    );
    let off =
        (detail(&below, "schlick-incident").unwrap() - detail(&below, "exact").unwrap()).abs();
    assert!(off > 0.01, "{off}");
    assert!(
        has_step(&below, &format!("off by {} here", number(off))),
        "{:#?}",
        below.steps
    );
}

/// The bare `schlick` names no form: it is refused, naming the flag (or
/// the request's field) and both forms, whatever else the request says.
#[test]
fn a_bare_schlick_model_is_refused_naming_the_field() {
    for (via, name) in [(Via::Flags, "--model"), (Via::Json, "model")] {
        let args = FresnelArgs {
            eta: Some(1.5),
            kappa: 0.0,
            metal: None,
            cos_i: Some(0.5),
            theta_i_deg: None,
            model: FresnelName::UnnamedSchlick,
        };
        let error = args.solve(via, Lang::En, Steps::Wanted).unwrap_err();
        assert!(matches!(error.kind(), ErrorKind::SchlickFormUnnamed { name: n } if n == name));
        let message = error.kind().message(Lang::En);
        assert!(message.starts_with(&format!("{name}: ")), "{message}");
        assert!(
            message.contains("schlick-incident") && message.contains("schlick-rarer"),
            "{message}"
        );
    }
}

/// A metal named is the law per channel at its index: each channel's
/// reflectance is, to the bit, the scalar law's at that channel's `n + iκ`.
#[test]
fn a_named_metal_is_the_conductor_law_per_channel() {
    for metal in [MetalName::CourseGold, MetalName::Silver] {
        let args = FresnelArgs {
            eta: None,
            kappa: 0.0,
            metal: Some(metal),
            cos_i: None,
            theta_i_deg: Some(60.0),
            model: FresnelModel::Exact.into(),
        };
        let record = args.solve(Via::Flags, Lang::En, Steps::Wanted).unwrap();
        let Answer::Vector(rgb) = record.answer else {
            panic!("an RGB triple, got {:?}", record.answer)
        };
        let c = metal.channels();
        for (i, channel) in rgb.iter().enumerate() {
            let one = FresnelArgs {
                eta: Some(c.n[i]),
                kappa: c.kappa[i],
                metal: None,
                ..args.clone()
            };
            let scalar = answer(&one.solve(Via::Flags, Lang::En, Steps::Wanted).unwrap());
            assert_eq!(channel.to_bits(), scalar.to_bits(), "{metal:?} channel {i}");
        }
        assert!(
            record.steps.iter().any(|s| s == "B channel:"),
            "{:?}",
            record.steps
        );
    }
}

/// The material is given once: an index and a name together, a name with
/// an extinction coefficient, or neither, are refused naming all three.
#[test]
fn a_material_given_twice_or_not_at_all_is_refused_naming_the_fields() {
    let base = FresnelArgs {
        eta: None,
        kappa: 0.0,
        metal: None,
        cos_i: Some(1.0),
        theta_i_deg: None,
        model: FresnelModel::Exact.into(),
    };
    for args in [
        base.clone(),
        FresnelArgs {
            eta: Some(1.5),
            metal: Some(MetalName::Gold),
            ..base.clone()
        },
        FresnelArgs {
            kappa: 3.0,
            metal: Some(MetalName::Gold),
            ..base.clone()
        },
    ] {
        let error = args.solve(Via::Json, Lang::En, Steps::Wanted).unwrap_err();
        assert!(
            matches!(error.kind(), ErrorKind::IndexOrMetal { eta, kappa, metal }
                if eta == "eta" && kappa == "kappa" && metal == "metal"),
            "{args:?}: {error:?}"
        );
    }
}
