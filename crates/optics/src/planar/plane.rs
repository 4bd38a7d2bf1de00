//! The plane both matrices are of: its flags, checked once, and its
//! equation as the first line of the working.

use crate::error::Result;
use crate::input::{Vec3Arg, Via};
use glam::DVec3;
use record::{number, vector, Record};
use record::{say, Lang};
use techniques::planar::Plane;

/// A plane, by a point of it and its normal, as both matrices' flags
/// `--plane-point` and `--plane-normal` give it (fields of their own in
/// each, so that a batch request names them as its own).
#[derive(Clone, Copy, Debug)]
pub struct PlaneArgs {
    pub plane_point: Vec3Arg,
    pub plane_normal: Vec3Arg,
}

impl PlaneArgs {
    /// The plane, its flags checked once.
    pub(super) fn plane(&self, via: Via) -> Result<Plane> {
        let point = via.point("plane_point", self.plane_point)?;
        let normal = via.direction("plane_normal", self.plane_normal)?;
        Ok(Plane::through(point, normal.unit)
            .expect("the point and normal were validated by radiometry::domain above"))
    }

    pub(super) fn inputs(&self, record: &mut Record) {
        record
            .input("plane_point", self.plane_point.0)
            .input("plane_normal", self.plane_normal.0);
    }
}

/// The plane's equation, the first line of both matrices' working.
pub(super) fn narrate_plane(record: &mut Record, lang: Lang, plane: &Plane) {
    record.step(|| {
        say!(
            lang,
            "plane n · x + d = 0: n = {}, d = −n · p = {}",
            "sík: n · x + d = 0, n = {}, d = −n · p = {}",
            vector(plane.normal().to_array()),
            number(plane.d())
        )
    });
}

/// A point or direction flag, checked where it enters.
pub(super) fn finite_point(via: Via, field: &str, v: Option<Vec3Arg>) -> Result<Option<DVec3>> {
    Ok(v.map(|v| via.point(field, v)).transpose()?)
}
