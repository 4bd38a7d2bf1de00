//! Bump mapping in the tracer: the hit's shading normal bent by its
//! object's height field ([`techniques::bump`]), over the sphere's
//! latitude–longitude parameters or the plane's tangent coordinates.
//!
//! Only [`Hit::shading`] changes. The geometric normal, the hit point, its
//! error bound and the object's outline stay the smooth surface's, so the
//! silhouette is unchanged and secondary rays start off the real surface;
//! a light below the geometric horizon stays dark and shadows are those of
//! the smooth surface (the bumps cast none, on themselves or elsewhere),
//! the technique's known limits (`001`: "az objektumok körvonalai körül
//! azonban a hatás eltűnik", "az egyenetlenségek nem vetnek árnyékot").

use glam::Vec3;
use techniques::bump::{self, HeightField, SurfacePoint};

use crate::geometry::{Hit, Object};

/// The shading normal of `hit` on `object` under `field`, in the tracer's
/// `f32`, outward like `hit.normal`. The bend is computed in `f64` about
/// `hit.normal` itself, so a flat field hands `hit.normal` back to the bit.
/// The tube has no bump maps (the schema has none for it); its hits keep
/// their normal, as do points where the bend is undefined (the sphere's
/// poles).
pub fn shading_normal(object: &Object, field: &HeightField, hit: &Hit) -> Vec3 {
    let point = hit.point.as_dvec3();
    let at: Option<SurfacePoint> = match object {
        Object::Sphere(s) => bump::on_sphere(s.center.as_dvec3(), f64::from(s.radius), point),
        Object::Plane(p) => Some(bump::on_plane(
            p.point.as_dvec3(),
            p.normal.as_dvec3(),
            point,
        )),
        Object::Tube(_) => None,
    };
    let Some(at) = at else {
        return hit.normal;
    };
    let at = SurfacePoint {
        normal: hit.normal.as_dvec3(),
        ..at
    };
    bump::shading_normal(field, &at).as_vec3()
}
