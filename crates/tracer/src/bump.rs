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

use techniques::bump::{self, HeightField, SurfacePoint};

use crate::geometry::{Hit, Object};
use radiometry::Vector3;

/// The shading normal of `hit` on `object` under `field`, at the tracer's
/// tier, outward like `hit.normal`. The bend is computed in `f64` about
/// `hit.normal` itself, so a flat field hands `hit.normal` back to the bit.
/// The tube has no bump maps (the schema has none for it); its hits keep
/// their normal, as do points where the bend is undefined (the sphere's
/// poles).
pub fn shading_normal<V: Vector3>(object: &Object<V>, field: &HeightField, hit: &Hit<V>) -> V {
    let point = hit.point.to_f64();
    let at: Option<SurfacePoint> = match object {
        Object::Sphere(s) => bump::on_sphere(s.center.to_f64(), s.radius.into(), point),
        Object::Plane(p) => Some(bump::on_plane(p.point.to_f64(), p.normal.to_f64(), point)),
        Object::Tube(_) => None,
    };
    let Some(at) = at else {
        return hit.normal;
    };
    let at = SurfacePoint {
        normal: hit.normal.to_f64(),
        ..at
    };
    V::of_f64(bump::shading_normal(field, &at))
}
