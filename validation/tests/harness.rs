//! The harness end to end: every kind of check against the committed
//! references, the report it writes (in English and in Hungarian), a
//! broken law reported as a failed check, and broken reference files
//! refused with the file and field named.

mod page;
use page::{english_left_in, number_marks, words};

mod caught;

use std::collections::BTreeSet;
use std::path::Path;
use std::sync::OnceLock;

use glam::Vec3;
use radiometry::specular::{self, Refraction};
use record::Lang;
use validation::checkout::Checkout;
use validation::colorimetry::ColourLaws;
use validation::exchange::{self, LawCase, LawResult};
use validation::laws::Laws;
use validation::metals::MetalLaws;
use validation::mpmath::Laws64;
use validation::reference::committed_dir;
use validation::report::{to_html, to_json, Report};
use validation::suite::{self, CheckKind, ColourChecks, Context, LawChecks, MetalChecks};
use validation::ReferenceError;

fn context(dir: &Path) -> Context {
    Context {
        reference_dir: dir.to_owned(),
        checkout: Checkout::at_build_time().root().to_owned(),
        quick: true,
    }
}

/// `kinds` against the references in `dir`, without progress.
fn run(kinds: &[Box<dyn CheckKind>], dir: &Path) -> Result<Report, ReferenceError> {
    suite::run(kinds, &context(dir), "test", |_, _| {})
}

fn kinds(laws: Laws) -> Vec<Box<dyn CheckKind>> {
    vec![
        Box::new(LawChecks(laws, Laws64::radiometry())),
        Box::new(ColourChecks(ColourLaws::radiometry())),
        Box::new(MetalChecks(MetalLaws::radiometry())),
    ]
}

/// Every standard kind against the committed references, run once for
/// the tests that read its report, and the progress calls it made.
fn standard_run() -> &'static (Report, Vec<(usize, String)>) {
    static RUN: OnceLock<(Report, Vec<(usize, String)>)> = OnceLock::new();
    RUN.get_or_init(|| {
        let mut seen = Vec::new();
        let mut report = suite::run(
            &suite::standard_kinds(),
            &context(&committed_dir()),
            "test",
            |i, name| seen.push((i, name.to_owned())),
        )
        .expect("committed references load");
        report.word_tradeoffs();
        (report, seen)
    })
}

#[test]
fn every_check_passes_against_the_committed_references() {
    let (report, seen) = standard_run();
    assert_eq!(seen.len(), 9, "one progress call per kind: {seen:?}");
    assert!(report.passed(), "{:#?}", report.checks);
    assert_eq!(report.summary.failed, 0);
    assert_eq!(report.summary.checks, report.checks.len());
    assert_eq!(report.references.len(), 8, "{:?}", report.references.keys());
    assert_eq!(report.fresnel_curves.len(), 9);
    assert!(report
        .fresnel_curves
        .iter()
        .all(|c| c.exact.len() == 91 && c.mitsuba.len() == 91));
    assert_eq!(report.speed.len(), 2);
    assert_eq!(
        report.tradeoffs.len(),
        8,
        "a trade-off record a swept scene"
    );
    // The report is JSON the figure script can read.
    let json: serde_json::Value = serde_json::from_str(&to_json(report)).unwrap();
    assert_eq!(json["schema"], "validation-report/2");
}

/// The standard run's page in English and in Hungarian, with the render
/// figures the command would write beside it.
fn pages() -> [String; 2] {
    let report = &standard_run().0;
    let figures: Vec<String> = (report.render_figures.iter())
        .map(|f| format!("figures/{}", f.file))
        .collect();
    [Lang::En, Lang::Hu].map(|lang| to_html(report, &figures, lang))
}

/// What the page names rather than says: the checks' ids, part by part,
/// the swept scenes' stems (`diffuse: …`, `diffuse-lambert: …`), the
/// environment maps' kind that the tracer calls `lat-long`, the reference
/// `colour-science`, and the laws' functions `reflect` and `refract`.
fn names(report: &Report) -> BTreeSet<String> {
    let ids = report.checks.iter().flat_map(|c| c.id.split('.'));
    let stems = report.tradeoffs.iter().map(|r| r.stem());
    let kinds = ["lat-long", "colour-science", "reflect", "refract"].map(str::to_owned);
    ids.map(str::to_owned).chain(stems).chain(kinds).collect()
}

#[test]
fn the_hungarian_report_of_every_check_has_no_english_left() {
    let [en, hu] = pages();
    assert!(
        hu.starts_with("<!doctype html>\n<html lang=hu>"),
        "{}",
        &hu[..40]
    );
    let left = english_left_in(&hu, &en, &names(&standard_run().0));
    assert!(
        left.is_empty(),
        "{} lines of the Hungarian report have English left:\n{}",
        left.len(),
        left.join("\n")
    );
}

/// The check above can fail: a frame text left in English, and a text
/// the suite has only in English shown unmarked, are both found.
#[test]
fn english_left_in_the_hungarian_report_is_found() {
    let [en, hu] = pages();
    let names = names(&standard_run().0);
    let frame = hu.replacen("Az összes fény</", "All the light</", 1);
    assert_ne!(frame, hu, "the area's Hungarian title is on the page");
    let found = english_left_in(&frame, &en, &names);
    assert!(found.iter().any(|l| l.contains("light")), "{found:?}");
    let unmarked = hu.replacen("<span lang=en>", "<span>", 1);
    assert!(!english_left_in(&unmarked, &en, &names).is_empty());
}

#[test]
fn both_languages_show_the_same_numbers_from_the_same_places() {
    let [en, hu] = pages();
    let marks = number_marks(&en);
    assert!(marks.len() > 100, "{} numbers marked", marks.len());
    assert_eq!(number_marks(&hu), marks);
}

/// The check above can fail: a number the Hungarian page drops is missed.
#[test]
fn a_number_the_hungarian_page_drops_is_caught() {
    let [en, hu] = pages();
    let dropped = hu.replacen(" data-quote=", " data-dropped=", 1);
    assert_ne!(number_marks(&dropped), number_marks(&en));
}

fn refract_normal_flipped(wi: Vec3, n: Vec3, eta: f32) -> Option<Refraction<Vec3>> {
    specular::refract(wi, -n, eta)
}

#[test]
fn a_broken_law_fails_its_check_in_the_report() {
    let broken = Laws {
        refract: refract_normal_flipped,
        ..Laws::radiometry()
    };
    let report = run(&kinds(broken), &committed_dir()).expect("committed references load");
    assert!(!report.passed());
    let failed: Vec<_> = report
        .checks
        .iter()
        .filter(|c| !c.passed())
        .map(|c| c.id.as_str())
        .collect();
    assert_eq!(failed, ["laws.mitsuba.directions"]);
    assert_eq!(report.summary.failed, 1);
    let html = to_html(&report, &[], Lang::En);
    let verdict = format!("1 of {} checks FAIL.", report.summary.checks);
    assert!(words(&html).contains(&verdict), "the page says so");
}

#[test]
fn a_malformed_reference_is_refused_naming_the_file_and_field() {
    let dir = tempfile::tempdir().unwrap();
    for name in [
        "fresnel_mpmath.json",
        "fresnel_random.json",
        "mitsuba_laws.json",
        "colorimetry.json",
        "metals.json",
    ] {
        std::fs::copy(committed_dir().join(name), dir.path().join(name)).unwrap();
    }
    let path = dir.path().join("mitsuba_laws.json");
    let text = std::fs::read_to_string(&path).unwrap();
    let broken = text.replacen("\"f\": ", "\"f\": \"not a number\", \"was\": ", 1);
    std::fs::write(&path, broken).unwrap();
    let err = run(&suite::standard_kinds(), dir.path()).unwrap_err();
    let message = err.to_string();
    assert!(
        message.contains("mitsuba_laws.json") && message.contains("dielectric[0].mitsuba.f"),
        "{message}"
    );
}

#[test]
fn a_malformed_random_reference_is_refused_naming_the_set_and_column() {
    let dir = tempfile::tempdir().unwrap();
    for name in ["fresnel_mpmath.json", "fresnel_random.json"] {
        std::fs::copy(committed_dir().join(name), dir.path().join(name)).unwrap();
    }
    let path = dir.path().join("fresnel_random.json");
    let text = std::fs::read_to_string(&path).unwrap();
    // The first set's first column, cos_i, cut to a few bytes.
    let at = text.find("\"cos_i\": \"").unwrap() + "\"cos_i\": \"".len();
    let end = at + text[at..].find('"').unwrap();
    std::fs::write(
        &path,
        format!("{}AAAAAAAAAAA={}", &text[..at], &text[end..]),
    )
    .unwrap();
    let err = run(&suite::standard_kinds(), dir.path()).unwrap_err();
    let message = err.to_string();
    assert!(
        message.contains("fresnel_random.json") && message.contains("sets[0].columns.cos_i"),
        "{message}"
    );
}

#[test]
fn a_missing_reference_is_named() {
    let dir = tempfile::tempdir().unwrap();
    let err = run(&suite::standard_kinds(), dir.path()).unwrap_err();
    assert!(err.to_string().contains("fresnel_mpmath.json"), "{err}");
}

/// Results for exported cases as a perfect evaluator would give them: the
/// radiometry crate's f64 laws in place of Mitsuba.
fn f64_results(cases: &exchange::CasesFile) -> exchange::ResultsFile {
    use glam::DVec3;
    use radiometry::fresnel;
    let results = cases
        .cases
        .iter()
        .map(|case| match *case {
            LawCase::Fresnel { cos_i, eta } => {
                let f = fresnel::dielectric_polarized(cos_i, eta);
                LawResult {
                    f: Some(f.reflectance()),
                    cos_t: Some(f.cos_t.unwrap_or(0.0)),
                    ..LawResult::default()
                }
            }
            LawCase::FresnelConductor { cos_i, n, kappa } => LawResult {
                f: Some(fresnel::conductor(cos_i, n, kappa)),
                ..LawResult::default()
            },
            LawCase::Directions { wi, n, eta } => {
                let (wi, n) = (DVec3::from_array(wi), DVec3::from_array(n));
                let t = specular::refract(wi, n, eta);
                LawResult {
                    f: None,
                    cos_t: Some(t.map_or(0.0, |t| t.cos_t)),
                    reflect: Some(specular::reflect(wi, n).to_array()),
                    refract: Some(t.map_or([0.0; 3], |t| t.direction.to_array())),
                }
            }
        })
        .collect();
    exchange::ResultsFile {
        schema: exchange::RESULTS_SCHEMA.to_owned(),
        evaluator: "the radiometry crate in f64".to_owned(),
        results,
    }
}

#[test]
fn exported_cases_round_trip_and_pass_against_a_perfect_evaluator() {
    let cases = exchange::random_cases(2005, 400);
    let text = serde_json::to_string(&cases).unwrap();
    let back: exchange::CasesFile = serde_json::from_str(&text).unwrap();
    assert_eq!(back.cases, cases.cases, "every number crosses exactly");
    let check = exchange::check_random(
        &Laws::radiometry(),
        &Laws64::radiometry(),
        &cases,
        &f64_results(&cases),
    );
    assert!(check.passed(), "{:#?}", check.failures);
    assert_eq!(check.cases, 1200);
}

#[test]
fn a_broken_law_is_caught_at_random_inputs() {
    let cases = exchange::random_cases(2005, 400);
    let broken = Laws {
        refract: refract_normal_flipped,
        ..Laws::radiometry()
    };
    let check =
        exchange::check_random(&broken, &Laws64::radiometry(), &cases, &f64_results(&cases));
    caught::caught_only(&check, |f| f.contains("directions"));
}

#[test]
fn results_that_do_not_match_the_cases_fail() {
    let cases = exchange::random_cases(1, 10);
    let mut results = f64_results(&cases);
    results.results.pop();
    let check =
        exchange::check_random(&Laws::radiometry(), &Laws64::radiometry(), &cases, &results);
    assert!(!check.passed() && check.failures[0].contains("30 cases but 29 results"));
}

/// A kind of check that starts `delay` late: a way to make the kinds
/// finish in another order than theirs.
struct Late(Box<dyn CheckKind>, std::time::Duration);

impl CheckKind for Late {
    fn name(&self) -> &'static str {
        self.0.name()
    }
    fn name_hu(&self) -> &'static str {
        self.0.name_hu()
    }
    fn run(&self, context: &suite::Context, report: &mut Report) -> Result<(), ReferenceError> {
        std::thread::sleep(self.1);
        self.0.run(context, report)
    }
    fn feeds_figures(&self) -> bool {
        self.0.feeds_figures()
    }
    fn measures_time(&self) -> bool {
        self.0.measures_time()
    }
}

/// A render figure's file name and pixels.
type Figure = (String, Vec<[f32; 3]>);

/// The report as JSON without the wall-clock timings, with the render
/// figures' names and pixels (which `report.json` leaves out).
fn deterministic_part(report: &Report) -> (serde_json::Value, Vec<Figure>) {
    let mut json: serde_json::Value = serde_json::from_str(&to_json(report)).unwrap();
    json.as_object_mut().unwrap().remove("speed");
    let figures = report
        .render_figures
        .iter()
        .map(|f| {
            (
                f.file.clone(),
                f.image.pixels.iter().map(|p| p.to_array()).collect(),
            )
        })
        .collect();
    (json, figures)
}

/// The standard kinds but the two that render: each render is the same
/// image on any number of threads (`image_is_identical_for_any_thread_count`
/// in `crates/tracer/tests/integrators.rs`, and the photon map's
/// `photon_render_is_identical_on_one_and_several_threads`), and they take
/// most of a quick run's time.
fn kinds_that_do_not_render() -> Vec<Box<dyn CheckKind>> {
    let renders = [
        "renders against Mitsuba 3",
        "all the light against Mitsuba 3",
    ];
    let kinds: Vec<_> = suite::standard_kinds()
        .into_iter()
        .filter(|kind| !renders.contains(&kind.name()))
        .collect();
    assert_eq!(kinds.len(), suite::standard_kinds().len() - renders.len());
    kinds
}

/// The kinds run beside one another and their results are merged in the
/// kinds' order: with the first kinds made to finish last, the report is
/// the one running each kind in turn into one report writes, check for
/// check and number for number (all but the wall-clock timings).
#[test]
fn the_report_is_the_same_whichever_kind_finishes_first() {
    let context = context(&committed_dir());
    let mut in_turn = Report::new(true, "test");
    for kind in kinds_that_do_not_render() {
        kind.run(&context, &mut in_turn).unwrap();
    }
    in_turn.summarise();
    let kinds = kinds_that_do_not_render();
    let count = kinds.len() as u64;
    let reversed: Vec<Box<dyn CheckKind>> = kinds
        .into_iter()
        .zip((0..count).rev())
        .map(|(kind, late)| {
            let delay = std::time::Duration::from_millis(200 * late);
            Box::new(Late(kind, delay)) as Box<dyn CheckKind>
        })
        .collect();
    let beside = suite::run(&reversed, &context, "test", |_, _| {}).unwrap();
    assert!(beside.checks.len() > 20, "{} checks", beside.checks.len());
    assert_eq!(beside.speed.len(), in_turn.speed.len());
    assert!(deterministic_part(&beside) == deterministic_part(&in_turn));
}

/// Each kind of check is named in Hungarian too, in other words than its
/// English name's (the progress lines of `optics --lang hu validate`).
#[test]
fn every_kind_of_check_has_its_own_hungarian_name() {
    for kind in suite::standard_kinds() {
        let (en, hu) = (kind.name(), kind.name_hu());
        assert!(!hu.trim().is_empty(), "{en}: no Hungarian name");
        let english: Vec<&str> = en
            .split(|c: char| !c.is_alphabetic())
            // Names of tools stay as they are (colour-science).
            .filter(|w| {
                w.len() > 3
                    && !["Mitsuba", "mpmath", "NVIDIA", "ꟻLIP", "colour", "science"].contains(w)
            })
            .collect();
        let left: Vec<&&str> = english.iter().filter(|w| hu.contains(**w)).collect();
        assert!(left.is_empty(), "{en}: English {left:?} left in {hu:?}");
    }
}
