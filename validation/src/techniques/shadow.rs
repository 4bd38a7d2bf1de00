//! The slides' projected-shadow matrix against the tracer's ray–plane
//! intersection.

use glam::DVec3;
use techniques::planar::{self, Plane, Shadow};

use crate::check::Check;

/// The projected shadow against the tracer: over a grid of lights, planes
/// and vertices, the matrix's point is where the tracer's ray from the
/// light through the vertex meets the plane (`tracer::geometry::Plane`, in
/// `f32`), and it is `Cast` exactly when the vertex lies before that hit; where the
/// matrix puts the point behind the light, the ray misses the plane.
pub fn check_projected_shadow() -> Check {
    const RELATIVE: f64 = 1e-4;
    let mut check = Check::new(
        "techniques.planar.shadow",
        [
            "The slides' projected-shadow matrix against the tracer's ray–plane intersection",
            "A diák vetítettárnyék-mátrixa a sugárkövető sugár–sík metszéséhez mérve",
        ],
        [
            "tracer::geometry::Plane::intersect (f32) on the ray from the light through the vertex",
            "tracer::geometry::Plane::intersect (f32) a fényforrásból a csúcson át haladó sugáron",
        ],
        [&format!("the points within {RELATIVE:e} of the distance, relative; Cast exactly when the vertex comes first"), &format!("a pontok legfeljebb {RELATIVE:e} relatív eltéréssel a távolsághoz képest; pontosan akkor vet árnyékot, ha a csúcs van elöl")],
    );
    let normals = [
        DVec3::Y,
        DVec3::new(0.3, 1.0, -0.2),
        DVec3::new(-1.0, 0.5, 0.4),
    ];
    for (k, normal) in normals.into_iter().enumerate() {
        let plane = Plane::through(DVec3::new(0.0, -1.0, 0.0), normal).expect("a plane");
        let traced_plane = tracer::geometry::Plane {
            point: plane.point().as_vec3(),
            normal: plane.normal().as_vec3(),
            material: 0,
        };
        for light in [DVec3::new(0.0, 4.0, 0.0), DVec3::new(2.0, 3.0, -1.0)] {
            for vertex in [
                DVec3::new(0.3, 1.0, 0.2),
                DVec3::new(-1.5, 0.5, 2.0),
                DVec3::new(1.0, 2.5, -0.5),
            ] {
                check.cases += 1;
                let at = format!("plane {k}, light {light}, vertex {vertex}");
                let towards = (vertex - light).as_vec3().normalize();
                let ray = tracer::geometry::Ray::new(light.as_vec3(), towards);
                let hit = traced_plane.intersect(&ray, 0.0);
                match (planar::project_shadow(light, &plane, vertex), hit) {
                    (Shadow::Cast(p) | Shadow::BeyondPlane(p), Some(hit)) => {
                        let traced = hit.point.as_dvec3();
                        let distance = (traced - light).length();
                        let err = (p - traced).length() / distance.max(1.0);
                        check.measure_in_both(
                            [
                                "|matrix − traced| / distance",
                                "|mátrix − követett| / távolság",
                            ],
                            err,
                            &at,
                        );
                        if !(err <= RELATIVE) {
                            check.fail(format!(
                                "{at}: the matrix puts it at {p}, the ray at {traced}"
                            ));
                        }
                        let first = (vertex - light).length() < distance;
                        let cast = matches!(
                            planar::project_shadow(light, &plane, vertex),
                            Shadow::Cast(_)
                        );
                        if first != cast {
                            check.fail(format!("{at}: Cast is {cast}, the vertex first {first}"));
                        }
                    }
                    // The line meets the plane behind the light, or never:
                    // the ray from the light through the vertex misses it.
                    (Shadow::BehindLight(_) | Shadow::Parallel, None) => {}
                    (outcome, hit) => check.fail(format!(
                        "{at}: {outcome:?}, but the ray hits at {:?}",
                        hit.map(|h| h.point)
                    )),
                }
            }
        }
    }
    check
}
