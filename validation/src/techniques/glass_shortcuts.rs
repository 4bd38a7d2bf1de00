//! The slides' cheap refraction and the fitted empirical Fresnel form,
//! each rendered through a glass sphere beside the traced truth.
//!
//! The scene is the dispersion sphere's (`crates/techniques/scenes/
//! dispersion_sphere.json`, N-BK7 at `n_d` = 1.5168): black beads behind
//! the glass under a white sky, so the refracted image is a picture of the
//! beads and the reflected one of the sky and the floor. The truth is the
//! tracer (Whitted) under the laws; each shortcut is the same render with
//! the shortcut in place of one law at the glass
//! (`tracer::scene::GlassShortcut`), everything else the same, so a pixel
//! that does not see the sphere must come out bit for bit the same.
//!
//! Measured over the sphere's pixels by the suite's fixed measures
//! ([`crate::tradeoff::measure`]: relative RMSE of radiance, ΔE2000 of the
//! displayed image, mean and 99th percentile), and, for the cheap
//! refraction, by ring: each pixel's primary ray meets the sphere at
//! `sin θi = b / R`, `b` its distance from the centre, so the centre of
//! the disc is near-normal incidence, where the cheap form agrees with
//! Snell's law to first order, and the rim grazing incidence, where the
//! refracted image is displaced.

use std::path::Path;

use radiometry::course::EmpiricalFresnel;
use techniques::empirical_fresnel::{compare, AngleGrid, Interface};
use techniques::refraction::Constant;
use tracer::geometry::Object;
use tracer::job::RenderJob;
use tracer::render::Image;
use tracer::scene::{self, FresnelModel, GlassShortcut, Material, Scene};

use super::dispersion::render;
use super::figure::strip;
use crate::check::Check;
use crate::renders::RenderFigure;
use crate::tradeoff::measure::{errors, Errors, Mask, Truth};

/// The rings' bounds in `sin θi` at the first hit: the centre below the
/// first (θi < 30°), the rim above the second (θi > 58°).
pub const RINGS: (f64, f64) = (0.5, 0.85);

/// The glass sphere scene, under its own settings (the exact law).
pub fn glass_scene() -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../crates/techniques/scenes/dispersion_sphere.json");
    scene::load(&path).expect("the dispersion scene")
}

/// The glass's index in `scene` (its one dielectric).
fn glass_eta(scene: &Scene) -> f64 {
    scene
        .materials
        .iter()
        .find_map(|m| match m {
            Material::Dielectric { eta } => Some(f64::from(*eta)),
            _ => None,
        })
        .expect("a glass")
}

/// The empirical form fitted by least squares to the exact reflectance
/// of `scene`'s glass seen from the air (`techniques::empirical_fresnel`).
pub fn fitted_form(scene: &Scene) -> EmpiricalFresnel<f64> {
    let glass = Interface::Dielectric {
        eta: glass_eta(scene),
    };
    compare(glass, &AngleGrid::TENTH_OF_A_DEGREE)
        .expect("glass's reflectance is fitted within the power scan")
        .fit
        .form
}

/// `scene` rendered with `fresnel` and `shortcut` at its glass.
pub fn render_with(scene: &Scene, fresnel: FresnelModel, shortcut: GlassShortcut) -> Image {
    let mut scene = scene.clone();
    scene.settings.fresnel = fresnel;
    scene.settings.glass_shortcut = shortcut;
    render(&scene)
}

/// Each pixel's `sin θi` where its primary ray meets the glass sphere,
/// `None` where the pixel sees something else first.
pub fn sphere_incidence(scene: &Scene) -> Vec<Option<f64>> {
    let job = RenderJob::with_settings(scene.clone(), scene.settings).expect("renderable");
    job.first_hits()
        .iter()
        .enumerate()
        .map(|(p, hit)| {
            let Object::Sphere(s) = &scene.objects[(*hit)? as usize] else {
                return None;
            };
            if !matches!(
                scene.materials[s.material as usize],
                Material::Dielectric { .. }
            ) {
                return None;
            }
            let ray = scene
                .camera
                .ray(p as u32 % scene.width, p as u32 / scene.width);
            let (o, d) = (ray.origin.as_dvec3(), ray.direction.as_dvec3().normalize());
            let b = (s.center.as_dvec3() - o).cross(d).length();
            Some((b / f64::from(s.radius)).min(1.0))
        })
        .collect()
}

/// The pixels whose `sin θi` is in `range`, as a mask.
fn ring(incidence: &[Option<f64>], range: std::ops::Range<f64>) -> Mask {
    Mask::from_hits(
        &incidence
            .iter()
            .map(|s| s.filter(|s| range.contains(s)).map(|_| 0))
            .collect::<Vec<_>>(),
    )
}

/// `image` against `truth` over `mask` by the suite's fixed measures.
fn measures(image: &Image, truth: &Image, mask: &Mask) -> Errors {
    errors(
        std::slice::from_ref(image),
        &Truth::new(truth.clone(), 0.0, mask),
        mask,
    )
}

/// How many pixels off the sphere differ at all between two renders.
fn off_sphere_changes(a: &Image, b: &Image, incidence: &[Option<f64>]) -> usize {
    (0..a.pixels.len())
        .filter(|&p| incidence[p].is_none() && a.pixels[p] != b.pixels[p])
        .count()
}

/// The pixels off the sphere a shortcut changed, a quantity of both checks.
const OFF_SPHERE: [&str; 2] = [
    "pixels off the sphere changed",
    "megváltozott képpontok a gömbön kívül",
];

/// `errors`' three numbers as measures of `check`, named `what` in
/// English and in Hungarian.
fn record(check: &mut Check, [what, hu]: [&str; 2], e: &Errors, at: &str) {
    let rmse = [
        format!("{what}: relative RMSE"),
        format!("{hu}: relatív négyzetes középhiba"),
    ];
    let mean = [
        format!("{what}: ΔE2000 mean"),
        format!("{hu}: ΔE2000 átlag"),
    ];
    let p99 = [format!("{what}: ΔE2000 p99"), format!("{hu}: ΔE2000 p99")];
    for (name, value) in [
        (rmse, e.rel_rmse),
        (mean, e.delta_e_mean),
        (p99, e.delta_e_p99),
    ] {
        check.measure_in_both([&name[0], &name[1]], value, at);
    }
}

/// The band the cheap refraction's relative RMSE at the rim must fall in:
/// visibly wrong there, the outer beads smeared into dark patches against
/// the rim (0.85 measured), yet not unrelated to the truth; the render is
/// deterministic, so the band only has to hold the scene's next small
/// change.
pub const CHEAP_RIM_RMSE: (f64, f64) = (0.6, 1.1);

/// The most relative RMSE the cheap refraction may show at the disc's
/// centre, where it agrees with Snell's law to first order (0.28
/// measured, all of it at the beads' edges, moved a pixel or so; the
/// slides' `c = 1` is 0.98 there).
pub const CHEAP_CENTRE_RMSE: f64 = 0.4;

/// The band the fitted empirical form's relative RMSE over the sphere
/// must fall in (0.013 measured; Schlick's 0.023; a form fitted to water
/// instead of the glass, 0.052).
pub const EMPIRICAL_RMSE: (f64, f64) = (0.006, 0.03);

/// Whether `value` lies in `band`, ends included.
fn within(value: f64, band: (f64, f64)) -> bool {
    band.0 <= value && value <= band.1
}

/// The slides' cheap refraction (`c = η − 1`, first order, in the suite;
/// `shortcut` a parameter so that a wrong one can be shown to be caught)
/// rendered through the glass sphere against Snell's law: close at the
/// disc's centre (relative RMSE at most [`CHEAP_CENTRE_RMSE`]), visibly
/// wrong at its rim (within [`CHEAP_RIM_RMSE`]), and nothing off the
/// sphere changed.
pub fn check_cheap_refraction_render(
    shortcut: GlassShortcut,
    figures: &mut Vec<RenderFigure>,
) -> Check {
    let (lo, hi) = CHEAP_RIM_RMSE;
    let (centre, rim) = RINGS;
    let mut check = Check::new(
        "techniques.refraction.render",
        [
            "The slides' cheap refraction (c = η − 1) rendered through a glass sphere against Snell's law",
            "A diák olcsó fénytörése (c = η − 1) üveggömbön át leképezve, a Snellius–Descartes-törvényhez mérve",
        ],
        [
            "the same tracer (Whitted) with Snell's refracted direction, the dispersion sphere at n_d",
            "ugyanaz a sugárkövető (Whitted) a Snellius–Descartes-törvény szerint megtört iránnyal, a diszperziós gömb n_d-nél",
        ],
        [&format!(
            "relative RMSE at most {CHEAP_CENTRE_RMSE} where sin θi < {centre}; expected to fail as \
             a shortcut at the rim (sin θi > {rim}): relative RMSE within [{lo}, {hi}]; no pixel off \
             the sphere changed"
        ), &format!("relatív négyzetes középhiba legfeljebb {CHEAP_CENTRE_RMSE}, ahol sin θi < {centre}; rövidítésként várhatóan elbukik a peremen (sin θi > {rim}): relatív négyzetes középhiba [{lo}, {hi}] között; a gömbön kívül egy képpont sem változik")],
    );
    let scene = glass_scene();
    let truth = render(&scene);
    let cheap = render_with(&scene, scene.settings.fresnel, shortcut);
    figures.push(strip("techniques_cheap_refraction.png", &cheap, &truth, 2));
    let incidence = sphere_incidence(&scene);
    check.cases = incidence.len();
    let whole = ring(&incidence, 0.0..1.5);
    let (inner, outer) = (ring(&incidence, 0.0..centre), ring(&incidence, rim..1.5));
    let e_whole = measures(&cheap, &truth, &whole);
    let e_inner = measures(&cheap, &truth, &inner);
    let e_outer = measures(&cheap, &truth, &outer);
    record(
        &mut check,
        ["sphere", "gömb"],
        &e_whole,
        &format!("{} pixels", whole.count()),
    );
    record(
        &mut check,
        ["centre", "közép"],
        &e_inner,
        &format!("{} pixels", inner.count()),
    );
    record(
        &mut check,
        ["rim", "perem"],
        &e_outer,
        &format!("{} pixels", outer.count()),
    );
    let off = off_sphere_changes(&cheap, &truth, &incidence);
    check.measure_in_both(OFF_SPHERE, off as f64, "");
    if e_inner.rel_rmse > CHEAP_CENTRE_RMSE {
        check.fail(format!(
            "at the centre the cheap refraction is {:.4} off (relative RMSE), above {CHEAP_CENTRE_RMSE}",
            e_inner.rel_rmse
        ));
    }
    if !within(e_outer.rel_rmse, CHEAP_RIM_RMSE) {
        check.fail(format!(
            "at the rim the cheap refraction is {:.4} off (relative RMSE), outside [{lo}, {hi}]",
            e_outer.rel_rmse
        ));
    }
    if off > 0 {
        check.fail(format!("{off} pixels off the sphere changed"));
    }
    check
}

/// The slides' empirical Fresnel form fitted to the glass (`form`, the
/// least-squares fit [`fitted_form`] in the suite; a parameter so that a
/// wrong one can be shown to be caught) rendered on the glass sphere
/// against the exact law, Schlick's approximation measured beside it: the
/// form's relative RMSE within [`EMPIRICAL_RMSE`] and below Schlick's (the
/// fit is the family's best in reflectance, Schlick one member), and
/// nothing off the sphere changed.
pub fn check_empirical_fresnel_render(
    form: EmpiricalFresnel<f64>,
    figures: &mut Vec<RenderFigure>,
) -> Check {
    let (lo, hi) = EMPIRICAL_RMSE;
    let mut check = Check::new(
        "techniques.empirical_fresnel.render",
        [
            "The slides' empirical Fresnel form, fitted to the glass, rendered on a glass sphere against the exact law",
            "A diák empirikus Fresnel-alakja az üveghez illesztve, üveggömbön leképezve, a pontos törvényhez mérve",
        ],
        [
            "the same tracer (Whitted) with the exact Fresnel equations, the dispersion sphere at n_d",
            "ugyanaz a sugárkövető (Whitted) a pontos Fresnel-egyenletekkel, a diszperziós gömb n_d-nél",
        ],
        [&format!(
            "expected to show the fit's error: relative RMSE over the sphere within [{lo}, {hi}], \
             below Schlick's; no pixel off the sphere changed"
        ), &format!("várhatóan megmutatja az illesztés hibáját: a gömbön a relatív négyzetes középhiba [{lo}, {hi}] között, a Schlick-közelítésé alatt; a gömbön kívül egy képpont sem változik")],
    );
    let scene = glass_scene();
    let truth = render(&scene);
    let empirical = render_with(
        &scene,
        FresnelModel::Exact,
        GlassShortcut::EmpiricalFresnel(form),
    );
    let schlick = render_with(&scene, FresnelModel::SchlickRarer, GlassShortcut::None);
    figures.push(strip(
        "techniques_empirical_fresnel.png",
        &empirical,
        &truth,
        2,
    ));
    let incidence = sphere_incidence(&scene);
    check.cases = incidence.len();
    let whole = ring(&incidence, 0.0..1.5);
    let at = format!("{} pixels", whole.count());
    let e = measures(&empirical, &truth, &whole);
    record(&mut check, ["fitted form", "illesztett alak"], &e, &at);
    let s = measures(&schlick, &truth, &whole);
    let schlick_rarer = FresnelModel::SchlickRarer.to_string();
    record(&mut check, [&schlick_rarer, &schlick_rarer], &s, &at);
    check.measure_in_both(["form: bias", "alak: eltolás"], form.bias, "");
    check.measure_in_both(["form: scale", "alak: skála"], form.scale, "");
    check.measure_in_both(["form: power", "alak: kitevő"], form.power, "");
    let off = off_sphere_changes(&empirical, &truth, &incidence);
    check.measure_in_both(OFF_SPHERE, off as f64, "");
    if !within(e.rel_rmse, EMPIRICAL_RMSE) {
        check.fail(format!(
            "the fitted form is {:.5} off (relative RMSE), outside [{lo}, {hi}]",
            e.rel_rmse
        ));
    }
    if e.rel_rmse >= s.rel_rmse {
        check.fail(format!(
            "the fitted form ({:.5}) is no closer than Schlick ({:.5}), relative RMSE",
            e.rel_rmse, s.rel_rmse
        ));
    }
    if off > 0 {
        check.fail(format!("{off} pixels off the sphere changed"));
    }
    check
}

/// The cheap refraction as the suite renders it: `c = η − 1`.
pub const CHEAP_REFRACTION: GlassShortcut = GlassShortcut::CheapRefraction(Constant::FirstOrder);
