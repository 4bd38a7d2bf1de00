//! Planar reflections rendered beside the traced truth: a mirror floor
//! under three spheres, and a fourth sphere below the floor, out of sight.
//!
//! The shortcut is the slides' two passes: the scene drawn with the
//! mirror dark, then the objects and the light drawn again through the
//! reflection matrix `M` (`techniques::planar::reflection_matrix`), seen
//! through the mirror's pixels (the stencil) and blended in with the
//! mirror's reflectance at normal incidence, one constant. Both passes are
//! the tracer's, so that only the technique differs: the truth is the
//! same tracer (Whitted) with the floor a mirror, each reflected ray
//! traced and weighted by the exact Fresnel law at its angle.
//!
//! The shortcut has two errors, each measured on its own:
//!
//! - **the mirror's Fresnel**: one constant where the law's reflectance
//!   grows towards grazing incidence. Weighted by the law instead
//!   (`radiometry::fresnel::conductor_rgb` at each pixel's angle), the
//!   mirrored pass is the traced reflection but for `f32` rounding: the
//!   geometry of `M` is exact.
//! - **objects behind the plane**: without a clip plane the sphere below
//!   the floor, mirrored, floats above it and shows in the mirror, where
//!   nothing is (the slides' caveat).

use glam::{DVec3, Vec3};
use serde_json::json;
use techniques::planar::{reflection_matrix, Plane};
use tracer::geometry::Object;
use tracer::job::RenderJob;
use tracer::output::srgb8;
use tracer::render::Image;
use tracer::scene::{self, Light, Material, Scene};

use super::figure::strip;
use crate::check::Check;
use crate::renders::RenderFigure;
use crate::tradeoff::measure::{errors, Mask, Truth};

/// The floor's index per channel: a polished metal reflecting 0.41 (red),
/// 0.29 and 0.17 (blue) at normal incidence, and all of the light at
/// grazing incidence.
const MIRROR_N: [f64; 3] = [1.5, 1.5, 1.5];
/// The floor's extinction per channel.
const MIRROR_KAPPA: [f64; 3] = [2.0, 1.5, 1.0];

/// Displayed 8-bit codes two pixels may differ by and still agree.
pub const CODES: u8 = 2;

/// How far, relative, the mirrored pass weighted by the exact law may be
/// from the traced reflection at a mirror pixel: `f32` rounding of two
/// paths to the same point.
pub const GEOMETRY_RELATIVE: f64 = 1e-3;

/// How many mirror pixels may exceed [`GEOMETRY_RELATIVE`]: those on the
/// edges of the reflected spheres, where the two `f32` rays may land on
/// either side (at most 1 % of the mirror's pixels).
pub const GEOMETRY_EDGE_SHARE: f64 = 0.01;

/// The least pixels where the object below the floor shows in the
/// shortcut's mirror: the caveat, shown.
pub const PHANTOM_FLOOR: usize = 100;

/// The mirror floor `y = 0`, first among the objects, three spheres above
/// it and one below, lit by a point light; `width × height` pixels.
pub fn mirror_scene(width: u32, height: u32) -> Scene {
    let file = json!({
        "version": 1,
        "image": { "width": width, "height": height },
        "camera": { "type": "look_at", "eye": [0, 2, -6], "target": [0, 0.5, 0], "up": [0, 1, 0],
                    "fov_y_deg": 40, "near": 0.01, "far": 1000 },
        "background": [0.25, 0.3, 0.4],
        "materials": {
            "mirror": { "type": "conductor", "n": MIRROR_N, "kappa": MIRROR_KAPPA },
            "red": { "type": "lambert", "albedo": [0.8, 0.15, 0.1] },
            "green": { "type": "lambert", "albedo": [0.2, 0.7, 0.2] },
            "blue": { "type": "lambert", "albedo": [0.15, 0.25, 0.8] },
            "yellow": { "type": "lambert", "albedo": [0.9, 0.8, 0.1] }
        },
        "objects": [
            { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "mirror" },
            { "type": "sphere", "center": [-1.3, 0.6, 0.5], "radius": 0.6, "material": "red" },
            { "type": "sphere", "center": [1.0, 0.8, 1.4], "radius": 0.8, "material": "green" },
            { "type": "sphere", "center": [0.2, 0.35, -1.2], "radius": 0.35, "material": "blue" },
            { "type": "sphere", "center": [0.3, -1.6, 3.0], "radius": 0.8, "material": "yellow" }
        ],
        "lights": [ { "type": "point", "position": [-1, 5, -2], "intensity": [30, 30, 30] } ],
        "render": { "integrator": "whitted", "max_depth": 4 }
    });
    scene::parse(&file.to_string()).expect("the mirror scene is valid")
}

/// The index of the object below the mirror in [`mirror_scene`].
const BELOW: u32 = 4;

fn render(scene: &Scene) -> Image {
    RenderJob::with_settings(scene.clone(), scene.settings)
        .expect("renderable")
        .render(None, &|_| {})
        .expect("rendered")
        .image
}

/// The second pass: every sphere and light through `m`, the mirror gone.
fn mirrored(scene: &Scene, m: glam::DMat4) -> Scene {
    let mut s = scene.clone();
    s.objects.remove(0);
    s.bumps.remove(0);
    for object in &mut s.objects {
        if let Object::Sphere(sphere) = object {
            sphere.center = m.transform_point3(sphere.center.as_dvec3()).as_vec3();
        }
    }
    for light in &mut s.lights {
        if let Light::Point { position, .. } = light {
            *position = m.transform_point3(position.as_dvec3()).as_vec3();
        }
    }
    s
}

/// What the shortcut and the truth rendered, pixel by pixel.
pub struct Reflections {
    /// The traced truth.
    pub truth: Image,
    /// The two passes blended with the constant reflectance.
    pub shortcut: Image,
    /// The mirrored pass weighted by the exact law at each pixel's angle.
    pub fresnel_weighted: Image,
    /// Which pixels see the mirror (the stencil).
    pub on_mirror: Vec<bool>,
    /// Which mirror pixels show the mirrored object from below the floor.
    pub phantom: Vec<bool>,
}

/// Renders the shortcut and the truth of `scene` ([`mirror_scene`]),
/// the mirrored pass made through `m` (the reflection matrix of the floor
/// in the suite; a parameter, so that a wrong matrix can be shown to be
/// caught).
pub fn reflections(scene: &Scene, m: glam::DMat4) -> Reflections {
    let truth = render(scene);
    let job = RenderJob::with_settings(scene.clone(), scene.settings).expect("renderable");
    let on_mirror: Vec<bool> = job.first_hits().iter().map(|h| *h == Some(0)).collect();
    let mut dark = scene.clone();
    let mirror = dark.objects[0].material() as usize;
    dark.materials[mirror] = Material::Flat {
        radiance: Vec3::ZERO,
    };
    let first = render(&dark);
    let second_scene = mirrored(scene, m);
    let second = render(&second_scene);
    let second_hits = RenderJob::with_settings(second_scene.clone(), second_scene.settings)
        .expect("renderable")
        .first_hits();
    let r0 = radiometry::fresnel::conductor_rgb(1.0, MIRROR_N, MIRROR_KAPPA);
    let (w, n) = (scene.width, first.pixels.len());
    let blend = |p: usize, r: [f64; 3]| {
        first.pixels[p] + second.pixels[p] * Vec3::from_array(r.map(|v| v as f32))
    };
    let mut shortcut = first.clone();
    let mut fresnel_weighted = first.clone();
    for p in (0..n).filter(|&p| on_mirror[p]) {
        let ray = scene.camera.ray(p as u32 % w, p as u32 / w);
        let cos = f64::from(ray.direction.y.abs());
        shortcut.pixels[p] = blend(p, r0);
        fresnel_weighted.pixels[p] = blend(
            p,
            radiometry::fresnel::conductor_rgb(cos, MIRROR_N, MIRROR_KAPPA),
        );
    }
    // The object below the floor is the last sphere, one before in the
    // mirrored pass (the mirror is gone).
    let phantom = (0..n)
        .map(|p| on_mirror[p] && second_hits[p] == Some(BELOW - 1))
        .collect();
    Reflections {
        truth,
        shortcut,
        fresnel_weighted,
        on_mirror,
        phantom,
    }
}

/// Whether two pixels' displayed codes differ by more than [`CODES`].
pub fn disagree(a: &[u8], b: &[u8], p: usize) -> bool {
    (0..3).any(|c| a[3 * p + c].abs_diff(b[3 * p + c]) > CODES)
}

/// The slides' planar reflection against the traced mirror floor
/// ([`reflections`] of `scene` through `m`): weighted by the exact law,
/// the mirrored pass is the traced reflection (all but
/// [`GEOMETRY_EDGE_SHARE`] of the mirror's pixels to [`GEOMETRY_RELATIVE`]);
/// the pixels where the shortcut disagrees are counted by their reason,
/// and the object below the floor must show at more than
/// [`PHANTOM_FLOOR`] of them.
pub fn check_planar_reflection(
    scene: &Scene,
    m: glam::DMat4,
    figures: &mut Vec<RenderFigure>,
) -> Check {
    let mut check = Check::new(
        "techniques.planar.reflection_render",
        [
            "Planar reflection (the reflection matrix, two passes) against the traced mirror floor",
            "Síktükrözés (a tükrözési mátrix, két menet) a követett tükörpadlóhoz mérve",
        ],
        [
            "the same tracer (Whitted) with the floor a conductor, every reflected ray traced",
            "ugyanaz a sugárkövető (Whitted) vezető padlóval, minden visszavert sugarat követve",
        ],
        [&format!(
            "weighted by the exact Fresnel law, the mirrored pass within {GEOMETRY_RELATIVE:e} \
             (relative) of the truth at all but {GEOMETRY_EDGE_SHARE} of the mirror's pixels; \
             expected to fail as a shortcut: the object below the floor shows at more than \
             {PHANTOM_FLOOR} pixels; pixels disagree beyond {CODES} displayed codes"
        ), &format!("a pontos Fresnel-törvénnyel súlyozva a tükrözött menet legfeljebb {GEOMETRY_RELATIVE:e} (relatív) eltéréssel egyezik a pontos képpel a tükör képpontjain, legfeljebb {GEOMETRY_EDGE_SHARE} részük kivételével; rövidítésként várhatóan elbukik: a padló alatti tárgy több mint {PHANTOM_FLOOR} képpontban látszik; a képpontok több mint {CODES} megjelenített kóddal térnek el")],
    );
    let r = reflections(scene, m);
    figures.push(strip(
        "techniques_planar_reflection.png",
        &r.shortcut,
        &r.truth,
        2,
    ));
    let mirror_pixels = r.on_mirror.iter().filter(|&&m| m).count();
    check.cases = r.truth.pixels.len();
    let counts = Disagreements::count(&mut check, &r);
    let at = format!("{mirror_pixels} mirror pixels");
    mirror_errors(&mut check, &r, &at);
    counts.measure(&mut check, &at);
    let Disagreements {
        off_geometry,
        phantom,
        elsewhere,
        ..
    } = counts;
    if off_geometry as f64 > GEOMETRY_EDGE_SHARE * mirror_pixels as f64 {
        check.fail(format!(
            "weighted by the exact law, {off_geometry} of {mirror_pixels} mirror pixels differ from the traced reflection"
        ));
    }
    if elsewhere > 0 {
        check.fail(format!("{elsewhere} pixels off the mirror disagree"));
    }
    if phantom <= PHANTOM_FLOOR {
        check.fail(format!(
            "the object below the floor shows at {phantom} pixels, not more than {PHANTOM_FLOOR}"
        ));
    }
    check
}

/// The pixels where the shortcut disagrees with the truth, by their
/// reason, and the mirror's pixels the Fresnel-weighted pass misses.
struct Disagreements {
    /// Mirror pixels whose Fresnel-weighted pass is beyond
    /// [`GEOMETRY_RELATIVE`] of the traced reflection.
    off_geometry: usize,
    /// Mirror pixels that disagree, the object below the floor not in
    /// them: the mirror's Fresnel.
    fresnel: usize,
    /// Mirror pixels that disagree where the object below the floor shows.
    phantom: usize,
    /// Pixels off the mirror that disagree.
    elsewhere: usize,
}

impl Disagreements {
    /// Counts them over every pixel of `r`, measuring each mirror pixel's
    /// Fresnel-weighted pass against the traced reflection on the way.
    fn count(check: &mut Check, r: &Reflections) -> Self {
        let (truth8, shortcut8) = (srgb8(&r.truth), srgb8(&r.shortcut));
        let (mut off_geometry, mut fresnel, mut phantom, mut elsewhere) = (0usize, 0, 0, 0);
        for p in 0..r.truth.pixels.len() {
            let differs = disagree(&truth8, &shortcut8, p);
            if !r.on_mirror[p] {
                elsewhere += usize::from(differs);
                continue;
            }
            if r.phantom[p] {
                phantom += usize::from(differs);
                continue;
            }
            let (t, f) = (
                r.truth.pixels[p].as_dvec3(),
                r.fresnel_weighted.pixels[p].as_dvec3(),
            );
            let relative = (t - f).abs().max_element() / t.max_element().max(1e-3);
            check.measure_at_in_both(
                [
                    "mirror, Fresnel-weighted: |pass − traced| / traced",
                    "tükör, Fresnel-súlyozva: |menet − követett| / követett",
                ],
                relative,
                || format!("pixel {p}"),
            );
            off_geometry += usize::from(relative > GEOMETRY_RELATIVE);
            fresnel += usize::from(differs);
        }
        Disagreements {
            off_geometry,
            fresnel,
            phantom,
            elsewhere,
        }
    }

    /// Measures each count, `at` naming the mirror's pixels.
    fn measure(&self, check: &mut Check, at: &str) {
        check.measure_in_both(
            [
                "mirror, Fresnel-weighted: pixels beyond the rounding",
                "tükör, Fresnel-súlyozva: a kerekítésen túli képpontok",
            ],
            self.off_geometry as f64,
            at,
        );
        check.measure_in_both(
            [
                "pixels that disagree: the mirror's Fresnel",
                "eltérő képpontok: a tükör Fresnel-tagja",
            ],
            self.fresnel as f64,
            at,
        );
        check.measure_in_both(
            [
                "pixels that disagree: the object behind the plane",
                "eltérő képpontok: a sík mögötti tárgy",
            ],
            self.phantom as f64,
            at,
        );
        check.measure_in_both(
            [
                "pixels that disagree: off the mirror",
                "eltérő képpontok: a tükrön kívül",
            ],
            self.elsewhere as f64,
            "",
        );
    }
}

/// The shortcut's relative RMSE and mean ΔE2000 against the truth over
/// the mirror's pixels, by the sweep's measures; `at` names them.
fn mirror_errors(check: &mut Check, r: &Reflections, at: &str) {
    let mask = Mask::from_hits(
        &r.on_mirror
            .iter()
            .map(|&m| m.then_some(0))
            .collect::<Vec<_>>(),
    );
    let e = errors(
        std::slice::from_ref(&r.shortcut),
        &Truth::new(r.truth.clone(), 0.0, &mask),
        &mask,
    );
    check.measure_in_both(
        [
            "mirror: relative RMSE",
            "tükör: relatív négyzetes középhiba",
        ],
        e.rel_rmse,
        at,
    );
    check.measure_in_both(
        ["mirror: mean ΔE2000", "tükör: ΔE2000 átlag"],
        e.delta_e_mean,
        at,
    );
}

/// The reflection matrix of [`mirror_scene`]'s floor.
pub fn floor_matrix() -> glam::DMat4 {
    reflection_matrix(&Plane::through(DVec3::ZERO, DVec3::Y).expect("a plane"))
}
