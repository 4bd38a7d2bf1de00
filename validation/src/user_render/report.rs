//! The comparison's record, in English or Hungarian: the verdict as the
//! answer, a line for the reference, the test and each region, and every
//! number in the details. The inputs are the caller's to fill in, as its
//! user gave them.

use record::{number, percent, say, Answer, Lang, Record};
use serde_json::{json, Value};
use tracer::geometry::Object;
use tracer::job::RenderJob;

use super::judge::Outcome;
use super::reference::{Reference, FIRST_SEED};
use super::request::Comparison;
use crate::compare::map::LEGEND;
use crate::compare::regions::Region;
use crate::compare::Tolerance;
use crate::renders::ALPHA;

/// The record of one comparison, without its inputs.
pub fn record(comparison: &Comparison, lang: Lang) -> Record {
    let Comparison {
        reference,
        outcome,
        diff,
    } = comparison;
    let (summary, verdicts) = (&outcome.summary, &outcome.verdicts);
    let job = &reference.job;
    let names = region_names(job, lang);
    let unit = verdicts.unit;
    let mut record = Record::new("compare", String::new(), unit);
    record.set_answer(Answer::Verdict(summary.agrees()), None);
    record.step(|| match summary.agrees() {
        true => say!(
            lang,
            "agrees: all {} pixels compared are within the test",
            "egyezik: mind a(z) {} összevetett képpont a próba határán belül van",
            summary.pixels
        ),
        false => say!(
            lang,
            "disagrees: {} of {} pixels compared ({})",
            "eltér: {} képpont a(z) {} összevetettből ({})",
            summary.disagreeing,
            summary.pixels,
            percent(summary.fraction, 2)
        ),
    });
    record.step(|| reference_line(reference, lang));
    record.step(|| test_line(outcome, lang));
    let masked: usize = summary.regions.iter().map(|r| r.masked).sum();
    record.step(|| {
        say!(
            lang,
            "not compared: {} pixels on silhouettes (a neighbour sees another object)",
            "nincs összevetve: {} képpont körvonalon (egy szomszédja más tárgyat lát)",
            masked
        )
    });
    for region in &summary.regions {
        record.step(|| region_line(&names[region.region], region, unit, lang));
    }
    if let Some(diff) = diff {
        record.step(|| say!(
            lang,
            "difference map: {} (black 0, red to yellow at the test's limit, magenta beyond, dark blue not compared)",
            "eltéréstérkép: {} (fekete 0, pirostól a próba határán sárgáig, azon túl bíbor, sötétkék: nincs összevetve)",
            diff.display()
        ));
    }
    details(&mut record, comparison, masked);
    record
}

/// Every number of the comparison, for scripts.
fn details(record: &mut Record, comparison: &Comparison, masked: usize) {
    let Comparison {
        reference,
        outcome,
        diff,
    } = comparison;
    let (summary, verdicts) = (&outcome.summary, &outcome.verdicts);
    let job = &reference.job;
    let scene = job.scene();
    let unit = verdicts.unit;
    let names_en = region_names(job, Lang::En);
    let regions: Vec<Value> = summary
        .regions
        .iter()
        .map(|r| region_json(job, &names_en, r))
        .collect();
    let (width, height) = (scene.width, scene.height);
    record
        .detail("agrees", summary.agrees())
        .detail("pixels_compared", summary.pixels)
        .detail("pixels_disagreeing", summary.disagreeing)
        .detail("fraction_disagreeing", summary.fraction)
        .detail("pixels_masked", masked)
        .detail("test", &verdicts.test)
        .detail("tolerance", Tolerance::RENDERS)
        .detail("alpha", ALPHA)
        .detail("difference_unit", unit)
        .detail("regions", regions)
        .detail(
            "reference",
            json!({
                "width": width,
                "height": height,
                "settings": job.settings(),
                "samples": reference.noise.as_ref().map(|(_, n)| n),
                "first_seed": reference.noise.as_ref().map(|_| FIRST_SEED),
            }),
        );
    if let Some(tests) = outcome.tests {
        record.detail(
            "t_tests",
            json!({ "count": tests.count, "threshold": tests.threshold }),
        );
    }
    if let Some(diff) = diff {
        record.detail(
            "difference_map",
            json!({ "path": diff.display().to_string(), "legend": LEGEND }),
        );
    }
}

fn reference_line(reference: &Reference, lang: Lang) -> String {
    let scene = reference.job.scene();
    let integrator = reference.job.settings().integrator;
    match &reference.noise {
        Some((_, samples)) => say!(
            lang,
            "reference: the tracer's {} at {}×{}, {} samples per pixel (seeds from 2^32)",
            "referencia: a sugárkövető {} integrátora, {}×{}, {} minta képpontonként (magok 2^32-től)",
            integrator,
            scene.width,
            scene.height,
            samples
        ),
        None => say!(
            lang,
            "reference: the tracer's {} at {}×{}",
            "referencia: a sugárkövető {} integrátora, {}×{}",
            integrator,
            scene.width,
            scene.height
        ),
    }
}

fn test_line(outcome: &Outcome, lang: Lang) -> String {
    let t = Tolerance::RENDERS;
    match (outcome.tests, outcome.verdicts.unit) {
        (Some(tests), _) => say!(
            lang,
            "test: Welch's t per pixel-channel, {} tests, p < α/m = {:.2e} (α = {}) and |Δ| > {:e} + {:e} · |reference|",
            "próba: Welch-féle t képpontonként és csatornánként, {} próba, p < α/m = {:.2e} (α = {}) és |Δ| > {:e} + {:e} · |referencia|",
            tests.count,
            tests.threshold,
            ALPHA,
            t.absolute,
            t.relative
        ),
        (None, "8-bit codes") => say!(
            lang,
            "test: 8-bit sRGB codes within those of reference ± ({:e} + {:e} · |reference| + its noise), one code more either side",
            "próba: a 8 bites sRGB kódok a referencia ± ({:e} + {:e} · |referencia| + zaja) kódjain belül, mindkét oldalon egy kóddal tágabban",
            t.absolute,
            t.relative
        ),
        (None, _) => say!(
            lang,
            "test: |Δ| ≤ {:e} + {:e} · |reference| + its noise, per pixel-channel",
            "próba: |Δ| ≤ {:e} + {:e} · |referencia| + zaja, képpontonként és csatornánként",
            t.absolute,
            t.relative
        ),
    }
}

fn region_line(name: &str, r: &Region, unit: &str, lang: Lang) -> String {
    let unit = match (unit, lang) {
        ("8-bit codes", Lang::Hu) => "8 bites kód",
        (unit, _) => unit,
    };
    let Some((x, y, c)) = r.worst_at else {
        return say!(
            lang,
            "  {}: all {} of its pixels on silhouettes, none compared",
            "  {}: mind a(z) {} képpontja körvonalon van, egy sincs összevetve",
            name,
            r.masked
        );
    };
    say!(
        lang,
        "  {0}: {1} of {2} pixels disagree; mean difference {3} {4} ({5}), worst {6} at ({7}, {8}) {9}",
        "  {0}: {2} képpontból {1} eltér; átlagos eltérés {3} {4} ({5}), legnagyobb {6} itt: ({7}, {8}) {9}",
        name,
        r.disagreeing,
        r.pixels,
        number(r.mean_difference),
        unit,
        match r.relative_difference.is_finite() {
            true => percent(r.relative_difference, 2),
            false => lang.pick("reference black", "a referencia fekete").to_owned(),
        },
        number(r.worst_difference),
        x,
        y,
        c
    )
}

fn region_json(job: &RenderJob, names: &[String], r: &Region) -> Value {
    let scene = job.scene();
    let object = scene.objects.get(r.region);
    let mut value = serde_json::to_value(r).unwrap_or_default();
    value["name"] = json!(names[r.region]);
    value["object"] = json!(object.map(|_| r.region));
    value["shape"] = json!(object.map(|o| shape(o).0));
    value["material"] = json!(object.map(|o| &scene.material_names[o.material() as usize]));
    value
}

/// The name of each region in `lang`, by label: `object 2 (sphere, gold)`,
/// then the background.
pub fn region_names(job: &RenderJob, lang: Lang) -> Vec<String> {
    let scene = job.scene();
    let mut names: Vec<String> = scene
        .objects
        .iter()
        .enumerate()
        .map(|(i, object)| {
            let material = &scene.material_names[object.material() as usize];
            let (en, hu) = shape(object);
            say!(
                lang,
                "object {} ({}, {})",
                "{}. objektum ({}, {})",
                i,
                lang.pick(en, hu),
                material
            )
        })
        .collect();
    names.push(lang.pick("background", "háttér").to_owned());
    names
}

/// An object's shape as the scene file names it, and in Hungarian.
pub fn shape(object: &Object) -> (&'static str, &'static str) {
    match object {
        Object::Sphere(_) => ("sphere", "gömb"),
        Object::Plane(_) => ("plane", "sík"),
        Object::Tube(_) => ("mirror_tube", "tükörcső"),
    }
}
