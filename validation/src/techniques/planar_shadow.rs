//! Projected planar shadows rendered beside the traced truth: a sphere
//! hovering over a floor, a second sphere on the floor partly in the
//! first one's shadow, one point light.
//!
//! The shortcut is the slides' (`techniques::planar::shadow_matrix`): the
//! scene drawn without shadows, then each object's triangles (a sphere
//! tessellated in latitude and longitude) flattened onto the floor by the
//! shadow matrix and drawn over it, dark (the floor lit by the ambient
//! term alone). Both passes are the tracer's, so that only the technique
//! differs: the truth is the same tracer (Whitted) with its shadow rays.
//! The shortcut darkens the floor only: the shadow the hovering sphere
//! casts on the other one is missing, as is every shadow on an object.

use glam::{DMat4, DVec2, DVec3};
use serde_json::json;
use techniques::planar::{self, Plane};
use tracer::geometry::Object;
use tracer::integrator::Machinery;
use tracer::job::RenderJob;
use tracer::output::srgb8;
use tracer::render::Image;
use tracer::scene::{self, Light, Scene};

use super::figure::strip;
use super::planar_reflection::{disagree, CODES};
use crate::check::Check;
use crate::renders::RenderFigure;

/// Triangles around each sphere's equator, and half as many rings.
pub const SEGMENTS: u32 = 96;

/// How many of the floor's pixels may disagree: those on the shadows'
/// edges, where the tessellated outline (inside the sphere's by
/// `r (1 − cos(π / SEGMENTS))`, 5e-4 r) and the pixel's centre decide.
pub const FLOOR_EDGE_SHARE: f64 = 0.005;

/// The least pixels of an object in another's shadow, which the shortcut
/// leaves lit: its failure, shown.
pub const MISSED_FLOOR: usize = 50;

/// The floor `y = 0`, first among the objects, a sphere hovering over it
/// and one on it, a point light above; `width × height` pixels.
pub fn shadow_scene(width: u32, height: u32) -> Scene {
    let file = json!({
        "version": 1,
        "image": { "width": width, "height": height },
        "camera": { "type": "look_at", "eye": [0, 3, -6], "target": [0.3, 0.5, 0], "up": [0, 1, 0],
                    "fov_y_deg": 40, "near": 0.01, "far": 1000 },
        "background": [0.25, 0.3, 0.4],
        "ambient": [0.1, 0.1, 0.1],
        "materials": {
            "floor": { "type": "lambert", "albedo": [0.7, 0.7, 0.7] },
            "red": { "type": "lambert", "albedo": [0.8, 0.15, 0.1] },
            "blue": { "type": "lambert", "albedo": [0.15, 0.25, 0.8] }
        },
        "objects": [
            { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor" },
            { "type": "sphere", "center": [0, 1.5, 0], "radius": 0.6, "material": "red" },
            { "type": "sphere", "center": [0.9, 0.4, 0.45], "radius": 0.4, "material": "blue" }
        ],
        "lights": [ { "type": "point", "position": [-2, 5, -1], "intensity": [30, 30, 30] } ],
        "render": { "integrator": "whitted" }
    });
    scene::parse(&file.to_string()).expect("the shadow scene is valid")
}

/// A sphere's triangles: `SEGMENTS` around, `SEGMENTS / 2` rings.
fn triangles(center: DVec3, radius: f64) -> Vec<[DVec3; 3]> {
    let (around, rings) = (SEGMENTS, SEGMENTS / 2);
    let vertex = |i: u32, j: u32| {
        let theta = std::f64::consts::PI * f64::from(j) / f64::from(rings);
        let phi = std::f64::consts::TAU * f64::from(i) / f64::from(around);
        center
            + radius
                * DVec3::new(
                    theta.sin() * phi.cos(),
                    theta.cos(),
                    theta.sin() * phi.sin(),
                )
    };
    let mut out = Vec::new();
    for j in 0..rings {
        for i in 0..around {
            let (a, b, c, d) = (
                vertex(i, j),
                vertex(i + 1, j),
                vertex(i, j + 1),
                vertex(i + 1, j + 1),
            );
            out.push([a, b, d]);
            out.push([a, d, c]);
        }
    }
    out
}

/// Whether `p` lies in the triangle `t` (inclusive), by the signs of the
/// three edge functions.
fn inside(t: &[DVec2; 3], p: DVec2) -> bool {
    let edge = |a: DVec2, b: DVec2| (b - a).perp_dot(p - a);
    let e = [edge(t[0], t[1]), edge(t[1], t[2]), edge(t[2], t[0])];
    e.iter().all(|&v| v >= 0.0) || e.iter().all(|&v| v <= 0.0)
}

/// The shadow the shortcut draws: every object's triangles projected by
/// `matrix` (the shadow matrix of the light and the floor in the suite;
/// a parameter, so that a wrong one can be shown to be caught), in the
/// plane's own coordinates, with their bounding boxes; and how many
/// vertices fell outside the slides' assumptions (not cast).
fn projected(
    scene: &Scene,
    light: DVec3,
    plane: &Plane,
    matrix: DMat4,
) -> (Vec<[DVec2; 3]>, usize) {
    let (u, v) = plane.normal().any_orthonormal_pair();
    let mut out = Vec::new();
    let mut not_cast = 0;
    for object in &scene.objects {
        let Object::Sphere(s) = object else { continue };
        for t in triangles(s.center.as_dvec3(), f64::from(s.radius)) {
            let cast = t.iter().all(|&x| {
                matches!(
                    planar::project_shadow(light, plane, x),
                    planar::Shadow::Cast(_)
                )
            });
            not_cast += usize::from(!cast);
            let flat = t.map(|x| {
                let p = matrix.project_point3(x);
                DVec2::new(p.dot(u), p.dot(v))
            });
            out.push(flat);
        }
    }
    (out, not_cast)
}

/// What the shortcut and the truth rendered, pixel by pixel.
pub struct Shadows {
    /// The traced truth.
    pub truth: Image,
    /// The unshadowed pass with the projected shadow drawn on the floor.
    pub shortcut: Image,
    /// Which pixels see the floor.
    pub on_floor: Vec<bool>,
    /// Triangles with a vertex the slides' caveats exclude (on or beyond
    /// the plane, behind the light, parallel): drawn all the same, as the
    /// matrix draws them.
    pub not_cast: usize,
}

/// Renders the shortcut and the truth of `scene` ([`shadow_scene`]) with
/// the shadow drawn through `matrix`.
pub fn shadows(scene: &Scene, matrix: impl Fn(DVec3, &Plane) -> DMat4) -> Shadows {
    let Some(Light::Point { position, .. }) = scene.lights.first() else {
        panic!("the shadow scene has a point light first");
    };
    let light = position.as_dvec3();
    let plane = match &scene.objects[0] {
        Object::Plane(p) => {
            Plane::through(p.point.as_dvec3(), p.normal.as_dvec3()).expect("a plane")
        }
        _ => panic!("the shadow scene's floor comes first"),
    };
    let job = RenderJob::with_settings(scene.clone(), scene.settings).expect("renderable");
    let truth = job.render(None, &|_| {}).expect("rendered").image;
    let on_floor: Vec<bool> = job.first_hits().iter().map(|h| *h == Some(0)).collect();
    let pass = |shadow_rays: bool, lit: bool| {
        let machinery = Machinery {
            shadow_rays,
            lights: vec![lit; scene.lights.len()],
            ..job.machinery().clone()
        };
        job.render_with(&machinery, None, &|_| {})
            .expect("rendered")
            .image
    };
    let (unshadowed, dark) = (pass(false, true), pass(false, false));
    let (flat, not_cast) = projected(scene, light, &plane, matrix(light, &plane));
    let (u, v) = plane.normal().any_orthonormal_pair();
    let mut shortcut = unshadowed;
    for (p, _) in on_floor.iter().enumerate().filter(|(_, &f)| f) {
        let ray = scene
            .camera
            .ray(p as u32 % scene.width, p as u32 / scene.width);
        let (o, d) = (ray.origin.as_dvec3(), ray.direction.as_dvec3());
        let x = o - plane.distance(o) / plane.normal().dot(d) * d;
        let at = DVec2::new(x.dot(u), x.dot(v));
        if flat.iter().any(|t| inside(t, at)) {
            shortcut.pixels[p] = dark.pixels[p];
        }
    }
    Shadows {
        truth,
        shortcut,
        on_floor,
        not_cast,
    }
}

/// The slides' projected shadow against the traced one ([`shadows`] of
/// `scene` through `matrix`): on the floor the two agree but at the
/// shadows' edges (at most [`FLOOR_EDGE_SHARE`] of its pixels), and off
/// it the shortcut leaves lit more than [`MISSED_FLOOR`] pixels the
/// truth has in shadow.
pub fn check_planar_shadow(
    scene: &Scene,
    matrix: impl Fn(DVec3, &Plane) -> DMat4,
    figures: &mut Vec<RenderFigure>,
) -> Check {
    let mut check = Check::new(
        "techniques.planar.shadow_render",
        [
            "Projected planar shadows (the shadow matrix) against the traced shadows",
            "Síkra vetített árnyékok (az árnyékmátrix) a követett árnyékokhoz mérve",
        ],
        [
            "the same tracer (Whitted) with its shadow rays",
            "ugyanaz a sugárkövető (Whitted) az árnyéksugaraival",
        ],
        [&format!(
            "on the floor all but {FLOOR_EDGE_SHARE} of the pixels agree (the shadows' edges); \
             expected to fail as a shortcut: more than {MISSED_FLOOR} pixels of an object in \
             another's shadow left lit; pixels disagree beyond {CODES} displayed codes"
        ), &format!("a padlón a képpontok legfeljebb {FLOOR_EDGE_SHARE} részét kivéve egyeznek (az árnyékok szélei); rövidítésként várhatóan elbukik: egy másik árnyékában álló tárgy több mint {MISSED_FLOOR} képpontja megvilágítva marad; a képpontok több mint {CODES} megjelenített kóddal térnek el")],
    );
    let s = shadows(scene, matrix);
    figures.push(strip(
        "techniques_planar_shadow.png",
        &s.shortcut,
        &s.truth,
        2,
    ));
    let (truth8, shortcut8) = (srgb8(&s.truth), srgb8(&s.shortcut));
    check.cases = s.truth.pixels.len();
    let floor_pixels = s.on_floor.iter().filter(|&&f| f).count();
    let (mut floor, mut objects) = (0usize, 0usize);
    for (p, &on_floor) in s.on_floor.iter().enumerate() {
        if disagree(&truth8, &shortcut8, p) {
            if on_floor {
                floor += 1;
            } else {
                objects += 1;
            }
        }
    }
    let at = format!("{floor_pixels} floor pixels");
    check.measure_in_both(
        [
            "pixels that disagree: the floor (edges)",
            "eltérő képpontok: a padló (élek)",
        ],
        floor as f64,
        &at,
    );
    check.measure_in_both(
        [
            "pixels that disagree: objects in another's shadow",
            "eltérő képpontok: tárgyak egy másik árnyékában",
        ],
        objects as f64,
        "",
    );
    check.measure_in_both(
        [
            "triangles with a vertex not before the plane (on it: the sphere resting there)",
            "háromszögek, amelyeknek egy csúcsa nem a sík előtt van (rajta: az ott nyugvó gömb)",
        ],
        s.not_cast as f64,
        "",
    );
    if floor as f64 > FLOOR_EDGE_SHARE * floor_pixels as f64 {
        check.fail(format!("{floor} of {floor_pixels} floor pixels disagree"));
    }
    if objects <= MISSED_FLOOR {
        check.fail(format!(
            "the shortcut misses the shadow on objects at {objects} pixels, not more than {MISSED_FLOOR}"
        ));
    }
    check
}
