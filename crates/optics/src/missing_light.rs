//! The light `optics inspect` says the chosen integrator misses: each chain
//! delta light → mirrors or glass → rough surface the scene holds
//! (`tracer::chains`), and, where the harness's reference measured the
//! scene (`mitsuba_full_light.json`), the share of the light Mitsuba's path
//! tracer misses there, which the tracer's `path` misses too (the harness
//! checks that they agree).

use std::path::Path;

use serde_json::{json, Value};
use tracer::chains;
use tracer::job::RenderJob;
use tracer::scene::IntegratorKind;

use crate::lang::needs;
use record::{say, Lang};

/// The report's lines and its JSON detail; with `measure`, the share
/// measured on the scene itself by rendering it (a render can fail).
pub fn report(
    job: &RenderJob,
    scene_file: &Path,
    lang: Lang,
    measure: bool,
) -> crate::error::Result<(Vec<String>, Value)> {
    let scene = job.scene();
    let found = chains::find(scene, job.needs());
    let integrator = job.settings().integrator;
    // The photon map carries exactly these chains; every other integrator
    // drops them.
    let computes = integrator == IntegratorKind::Photon;
    let mut lines: Vec<String> = found
        .iter()
        .map(|c| {
            let chain = needs::chain(c, scene, lang);
            if computes {
                say!(
                    lang,
                    "light the {} integrator computes by its caustic photon map: {}",
                    "fény, amelyet a(z) {} integrátor a kausztikus fotontérképével számol: {}",
                    integrator,
                    chain
                )
            } else {
                say!(
                    lang,
                    "light the {} integrator does not compute: {}",
                    "fény, amelyet a(z) {} integrátor nem számol: {}",
                    integrator,
                    chain
                )
            }
        })
        .collect();
    let measured = if found.is_empty() {
        None
    } else {
        measured_share(scene_file)
    };
    if let Some(m) = &measured {
        lines.push(reference_line(m, integrator, lang));
    }
    let here = if measure && !found.is_empty() {
        measured_here(job)?
    } else {
        None
    };
    if let Some(h) = &here {
        lines.push(here_line(h, job, lang));
    }
    let detail = json!({
        "integrator_computes_the_chains": computes,
        "chains": found.iter().map(|c| json!({
            "light": c.light,
            "kind": c.kind,
            "via": c.via.iter().map(|&m| &scene.material_names[m]).collect::<Vec<_>>(),
            "to": &scene.material_names[c.to],
        })).collect::<Vec<_>>(),
        "measured": measured.map(|m| json!({
            "reference": m.file,
            "surface": {"share": m.surface.0, "standard_error": m.surface.1},
            "diffuse": m.diffuse.map(|d| json!({"share": d.0, "standard_error": d.1})),
        })),
        "measured_here": here.map(|h| json!({
            "passes": h.passes,
            "seconds": h.seconds,
            "surface": {"share": h.surface.0, "standard_error": h.surface.1},
            "diffuse": h.diffuse.map(|d| json!({"share": d.0, "standard_error": d.1})),
        })),
    });
    Ok((lines, detail))
}

/// The line of the share Mitsuba's path misses, as the checkout's reference
/// measured it, and what `integrator` does with that light.
fn reference_line(m: &Measured, integrator: IntegratorKind, lang: Lang) -> String {
    let verdict = match integrator {
        IntegratorKind::Path => lang.pick(
            "; the tracer's path misses the same share (checked by `optics validate`: full_light.tracer.<scene>.path.missing_share)",
            "; a követő path integrátora ugyanennyit (az `optics validate` ellenőrzi: full_light.tracer.<scene>.path.missing_share)",
        ),
        IntegratorKind::Photon => lang.pick(
            "; the photon integrator computes this light on the diffuse surfaces (checked by `optics validate` against Mitsuba's light tracer and area lights: full_light.tracer.<scene>.photon.all_the_light)",
            "; a photon integrátor a diffúz felületeken kiszámolja ezt a fényt (az `optics validate` ellenőrzi Mitsuba fénykövetője és felületi fényforrásai ellen: full_light.tracer.<scene>.photon.all_the_light)",
        ),
        _ => lang.pick(
            "; this integrator misses at least as much",
            "; ez az integrátor legalább ennyit",
        ),
    };
    say!(
        lang,
        "measured by Mitsuba ({}, course_rough as Lambert, black background): its path integrator misses {:.3} ± {:.3} of the light where the camera sees a surface, {} where it sees a diffuse one{}",
        "Mitsuba mérése ({}, course_rough helyett Lambert, fekete háttér): útkövetője a fény {:.3} ± {:.3} részét nem látja, ahol a kamera felületet lát, {} ahol diffúz felületet{}",
        m.file,
        m.surface.0,
        m.surface.1,
        diffuse_share(m.diffuse, lang),
        verdict
    )
}

/// A diffuse region's share and its standard error, or that there is none.
fn diffuse_share(share: Option<(f64, f64)>, lang: Lang) -> String {
    share.map_or_else(
        || lang.pick("none", "nincs ilyen").to_owned(),
        |d| format!("{:.3} ± {:.3}", d.0, d.1),
    )
}

/// What the path tracer misses on the scene itself, rendered here.
struct Here {
    passes: u32,
    seconds: f64,
    surface: (f64, f64),
    diffuse: Option<(f64, f64)>,
}

/// The line of a measurement on the scene itself.
fn here_line(h: &Here, job: &RenderJob, lang: Lang) -> String {
    let diffuse = diffuse_share(h.diffuse, lang);
    say!(
        lang,
        "measured on the scene as written, its materials, background and ambient light included ({} renders each of path and photon, {} samples per pixel, {:.1} s): path misses {:.3} ± {:.3} of the light photon finds where the camera sees a surface, {} where it sees a diffuse one; the photon map's own blur of a caustic is not in that error",
        "a jelenet úgy mérve, ahogy írva van, anyagaival, hátterével és környezeti fényével (a path és a photon integrátorral is {} kép, képpontonként {} minta, {:.1} s): a path a photon által talált fény {:.3} ± {:.3} részét nem látja, ahol a kamera felületet lát, {} ahol diffúz felületet; a fotontérkép saját elmosása ebben a hibában nincs benne",
        h.passes,
        job.settings().spp,
        h.seconds,
        h.surface.0,
        h.surface.1,
        diffuse
    )
}

/// The share measured by rendering the scene with path and photon; `None`
/// without the harness, or where the camera sees no lit surface.
#[cfg(feature = "harness")]
fn measured_here(job: &RenderJob) -> crate::error::Result<Option<Here>> {
    use validation::full_light::{missing_share, PASSES};
    let pair = |s: validation::full_light::Share| (s.share, s.standard_error);
    let measured = missing_share(job, PASSES, None)?;
    Ok(measured.map(|m| Here {
        passes: m.passes,
        seconds: m.seconds,
        surface: pair(m.surface),
        diffuse: m.diffuse.map(pair),
    }))
}

#[cfg(not(feature = "harness"))]
fn measured_here(_: &RenderJob) -> crate::error::Result<Option<Here>> {
    Ok(None)
}

/// A share and its standard error per region.
struct Measured {
    file: &'static str,
    surface: (f64, f64),
    diffuse: Option<(f64, f64)>,
}

/// The share Mitsuba's path misses, where the checkout's reference holds
/// the scene file inspected; `None` without the harness, a checkout or an
/// entry for it.
#[cfg(feature = "harness")]
fn measured_share(scene_file: &Path) -> Option<Measured> {
    use validation::full_light::{self, Estimate, FullLight, Region, RegionMean};
    let checkout = crate::checkout::lookup(None).find().ok()?;
    let reference = FullLight::load(&checkout.reference_dir()).ok()?;
    let inspected = scene_file.canonicalize().ok()?;
    let (index, s) = reference.scenes.iter().enumerate().find(|(_, s)| {
        checkout
            .root()
            .join(&s.scene_file)
            .canonicalize()
            .ok()
            .as_ref()
            == Some(&inspected)
    })?;
    let file = checkout.reference_dir().join(full_light::FILE);
    let decoded = full_light::decode(&file, index, s).ok()?;
    let mean = |e: Estimate, r: Region| {
        let passes = decoded.passes.get(&(e, r))?;
        Some(RegionMean::from_passes(
            passes.iter().map(|p| p.iter().sum()),
        ))
    };
    let share = |r: Region, full: Estimate| {
        let s = full_light::share(mean(Estimate::Path, r)?, mean(full, r)?);
        Some((s.share, s.standard_error))
    };
    Some(Measured {
        file: full_light::FILE,
        surface: share(Region::Surface, Estimate::Area)?,
        diffuse: share(Region::Diffuse, Estimate::Ptracer),
    })
}

#[cfg(not(feature = "harness"))]
fn measured_share(_: &Path) -> Option<Measured> {
    None
}
