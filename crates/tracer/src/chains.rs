//! Which delta lights reach a diffuse surface through delta surfaces: the
//! light paths light → mirror, conductor or smooth glass (one or more) →
//! rough surface that no integrator of the tracer computes (a shadow ray
//! stops at the first delta surface; a sampled bounce never hits a point
//! light or a direction). `optics inspect` names each chain.
//!
//! The analysis is conservative: it may name a chain that carries no light
//! (it ignores occlusion by third objects and the directions a curved
//! mirror sends light), and never misses one. Light passes between two
//! surfaces unless one of these separates them:
//!
//! - an **enclosure**: an opaque sphere (any material but glass) with one
//!   strictly inside it and the other strictly outside, or a closed mirror
//!   tube with one strictly inside every side and the other strictly outside
//!   one (a directional light is outside every enclosure, but a tube whose
//!   axis it runs along, as [`crate::needs`] decides for the tube);
//! - a **plane** seen edge-on: a point light in a plane mirror's plane, or a
//!   directional light parallel to it;
//! - a **convex** object cannot send light to itself (a sphere, a plane);
//!   a tube can (its sides see each other);
//! - an opaque enclosure's mirror sends light back to the side it came from.
//!
//! Past [`MAX_TESTS`] enclosure tests (a scene of thousands of mirrors)
//! the enclosures are not tested: more chains are named, none missed.
//!
//! A light the needs analysis finds unused ([`crate::needs::Unused`]) has no
//! chain. Chains are found breadth first, so each names the fewest delta
//! surfaces that connect the light to a rough surface; chains that differ
//! only in objects of the same materials are named once.

use glam::Vec3;
use serde::Serialize;

use crate::geometry::Object;
use crate::needs::{LightKind, Needs};
use crate::scene::{Light, Scene};

/// One chain: a light, the delta surfaces in the order the light meets
/// them, and the rough surface it reaches, by material.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Chain {
    /// The light's index in `lights`.
    pub light: usize,
    /// Its kind.
    pub kind: LightKind,
    /// The delta surfaces' material indices, light side first.
    pub via: Vec<usize>,
    /// The rough surface's material index.
    pub to: usize,
}

/// Where a thing lies against an enclosure.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Side {
    Inside,
    Outside,
    Both,
}

/// A light or a surface, for the enclosure tests.
#[derive(Clone, Copy)]
enum Thing<'a> {
    Light(&'a Light),
    Object(usize),
}

/// The chains of `scene`, for the lights `needs` found used.
pub fn find(scene: &Scene, needs: &Needs) -> Vec<Chain> {
    let material = |i: usize| scene.materials[scene.objects[i].material() as usize];
    let delta: Vec<usize> = (0..scene.objects.len())
        .filter(|&i| material(i).is_specular())
        .collect();
    let rough: Vec<usize> = (0..scene.objects.len())
        .filter(|&i| material(i).is_rough())
        .collect();
    let enclosures = enclosures(scene, needs, delta.len(), rough.len());
    let enclosures = enclosures.as_slice();
    let mut chains = Vec::new();
    for use_ in needs.lights.iter().filter(|l| l.used) {
        let light = &scene.lights[use_.index];
        // Breadth first over the delta surfaces: each reached by its
        // shortest chain from the light, with the side of it the light
        // arrives on (an opaque enclosure sends it back to that side).
        let mut paths: Vec<Option<(Vec<usize>, Side)>> = vec![None; scene.objects.len()];
        let mut frontier: Vec<usize> = delta
            .iter()
            .copied()
            .filter(|&d| light_reaches(scene, enclosures, light, d))
            .collect();
        for &d in &frontier {
            paths[d] = Some((vec![d], side(scene, d, Thing::Light(light))));
        }
        while !frontier.is_empty() {
            let mut next = Vec::new();
            for &a in &frontier {
                for &b in &delta {
                    let arrives = paths[a].as_ref().map_or(Side::Both, |p| p.1);
                    if paths[b].is_none() && passes(scene, enclosures, a, arrives, b) {
                        let mut path = paths[a].clone().map(|p| p.0).unwrap_or_default();
                        path.push(b);
                        paths[b] = Some((path, side(scene, b, Thing::Object(a))));
                        next.push(b);
                    }
                }
            }
            frontier = next;
        }
        for (last, path) in paths.iter().enumerate() {
            let Some((path, arrives)) = path else {
                continue;
            };
            for &r in rough
                .iter()
                .filter(|&&r| passes(scene, enclosures, last, *arrives, r))
            {
                let chain = Chain {
                    light: use_.index,
                    kind: use_.kind,
                    via: path
                        .iter()
                        .map(|&o| scene.objects[o].material() as usize)
                        .collect(),
                    to: scene.objects[r].material() as usize,
                };
                if !chains.contains(&chain) {
                    chains.push(chain);
                }
            }
        }
    }
    chains
}

/// The most enclosure tests an analysis makes; past it the enclosures are
/// dropped, which names more chains and misses none.
pub const MAX_TESTS: f64 = 1e7;

/// The objects that can enclose (opaque spheres, tubes), or none where
/// testing them would cost more than [`MAX_TESTS`].
fn enclosures(scene: &Scene, needs: &Needs, delta: usize, rough: usize) -> Vec<usize> {
    let enclosing: Vec<usize> = (0..scene.objects.len())
        .filter(|&e| match &scene.objects[e] {
            Object::Sphere(_) => !matches!(
                scene.materials[scene.objects[e].material() as usize],
                crate::scene::Material::Dielectric { .. }
            ),
            Object::Tube(_) => true,
            Object::Plane(_) => false,
        })
        .collect();
    let lights = needs.lights.iter().filter(|l| l.used).count() as f64;
    let (d, r) = (delta as f64, rough as f64);
    let tests = lights * (d * d + d * r + d) * enclosing.len() as f64;
    if tests > MAX_TESTS {
        Vec::new()
    } else {
        enclosing
    }
}

/// Whether `light` can shine on object `o`.
fn light_reaches(scene: &Scene, enclosures: &[usize], light: &Light, o: usize) -> bool {
    if let Object::Plane(p) = &scene.objects[o] {
        let edge_on = match *light {
            Light::Point { position, .. } => (position - p.point).dot(p.normal) == 0.0,
            Light::Directional { towards, .. } => towards.dot(p.normal) == 0.0,
        };
        if edge_on {
            return false;
        }
    }
    !separated(scene, enclosures, Thing::Light(light), Thing::Object(o))
}

/// Whether light leaving object `a`, which it reached on side `arrives` of
/// `a`, can reach object `b`: an opaque enclosure reflects light back to
/// the side it came from.
fn passes(scene: &Scene, enclosures: &[usize], a: usize, arrives: Side, b: usize) -> bool {
    if a == b && scene.objects[a].is_convex() {
        return false;
    }
    let opposite = matches!(
        (arrives, side(scene, a, Thing::Object(b))),
        (Side::Inside, Side::Outside) | (Side::Outside, Side::Inside)
    );
    !opposite && !separated(scene, enclosures, Thing::Object(a), Thing::Object(b))
}

/// Whether an enclosure has one of `a`, `b` strictly inside and the other
/// strictly outside.
fn separated(scene: &Scene, enclosures: &[usize], a: Thing, b: Thing) -> bool {
    enclosures.iter().any(|&e| {
        let (sa, sb) = (side(scene, e, a), side(scene, e, b));
        matches!(
            (sa, sb),
            (Side::Inside, Side::Outside) | (Side::Outside, Side::Inside)
        )
    })
}

/// Where `thing` lies against object `e` as an enclosure; `Both` where `e`
/// encloses nothing (glass, a plane) or `thing` is `e` itself.
///
/// A glass sphere encloses nothing: light crosses it.
fn side(scene: &Scene, e: usize, thing: Thing) -> Side {
    if matches!(thing, Thing::Object(o) if o == e) {
        return Side::Both;
    }
    let opaque = !matches!(
        scene.materials[scene.objects[e].material() as usize],
        crate::scene::Material::Dielectric { .. }
    );
    match &scene.objects[e] {
        Object::Sphere(s) if opaque => {
            let distance = |p: Vec3, r: f32| {
                let d = (p - s.center).length();
                if d + r < s.radius {
                    Side::Inside
                } else if d - r > s.radius {
                    Side::Outside
                } else {
                    Side::Both
                }
            };
            match thing {
                Thing::Light(Light::Point { position, .. }) => distance(*position, 0.0),
                Thing::Light(Light::Directional { .. }) => Side::Outside,
                Thing::Object(o) => match &scene.objects[o] {
                    Object::Sphere(t) => distance(t.center, t.radius),
                    _ => Side::Both,
                },
            }
        }
        Object::Tube(tube) => {
            // Signed distances to every side (negative inside).
            let within = |p: Vec3, r: f32| {
                let d = tube.faces.iter().map(|f| (p - f.point).dot(f.normal));
                let d: Vec<f32> = d.collect();
                if d.iter().all(|&x| x < -r) {
                    Side::Inside
                } else if d.iter().any(|&x| x > r) {
                    Side::Outside
                } else {
                    Side::Both
                }
            };
            match thing {
                Thing::Light(Light::Point { position, .. }) => within(*position, 0.0),
                Thing::Light(Light::Directional { towards, .. }) => {
                    if towards.cross(tube.axis).length() == 0.0 {
                        Side::Both
                    } else {
                        Side::Outside
                    }
                }
                Thing::Object(o) => match &scene.objects[o] {
                    Object::Sphere(t) => within(t.center, t.radius),
                    _ => Side::Both,
                },
            }
        }
        _ => Side::Both,
    }
}
