//! One value of a scene file checked into its domain: a finite `f32`, a
//! positive length, a whole count, a direction, an image size; each
//! refusal naming the value's JSON path. The first floor of the scene's
//! validation: the settings and the whole-scene checks build on it.

use glam::{DVec3, Vec3};
use radiometry::domain::{self, DomainError};

use super::error::{ErrorKind, SceneError};
use crate::kinds::{MAX_IMAGE_SIDE, MAX_PIXELS};

/// The tracer computes in f32: a finite f64 beyond f32's range (3.4e38)
/// would become infinite there, so it is refused by name like a NaN.
fn within_f32(name: String, c: f64) -> Result<(), DomainError> {
    if (c as f32).is_finite() {
        Ok(())
    } else {
        Err(DomainError::OutOfRange {
            name,
            value: c,
            expected: domain::Expected::WithinF32,
        })
    }
}

/// Three components, each checked by `domain_check` and within `f32`,
/// named `path[0]`, `path[1]`, `path[2]`.
fn each3(
    path: &str,
    v: [f64; 3],
    domain_check: fn(&str, f64) -> Result<f64, DomainError>,
) -> Result<Vec3, DomainError> {
    for (axis, c) in ["[0]", "[1]", "[2]"].into_iter().zip(v) {
        let name = format!("{path}{axis}");
        domain_check(&name, c)?;
        within_f32(name, c)?;
    }
    Ok(DVec3::from_array(v).as_vec3())
}

pub(super) fn finite3(path: &str, v: [f64; 3]) -> Result<Vec3, DomainError> {
    each3(path, v, domain::finite)
}

pub(super) fn non_negative3(path: &str, v: [f64; 3]) -> Result<Vec3, DomainError> {
    each3(path, v, domain::non_negative)
}

pub(super) fn direction(path: &str, v: [f64; 3]) -> Result<Vec3, SceneError> {
    let d = domain::direction(path, DVec3::from_array(v))?;
    // The unit vector must also survive rounding to f32.
    let unit = d.unit.as_vec3();
    if !(unit.length() > 0.5) {
        return Err(SceneError::new(path, ErrorKind::DirectionUnrepresentable));
    }
    Ok(unit)
}

/// A positive length that stays positive and finite in `f32`.
pub(super) fn positive(path: &str, value: f64) -> Result<f32, SceneError> {
    domain::finite(path, value)?;
    if !(value > 0.0) || (value as f32) == 0.0 || !(value as f32).is_finite() {
        return Err(DomainError::OutOfRange {
            name: path.to_owned(),
            value,
            expected: domain::Expected::PositiveF32,
        }
        .into());
    }
    Ok(value as f32)
}

/// A whole number from `min` to `max`.
pub(super) fn count(path: &str, value: f64, min: u32, max: u32) -> Result<u32, SceneError> {
    domain::finite(path, value)?;
    if value.fract() != 0.0 || value < min as f64 || value > max as f64 {
        return Err(SceneError::new(
            path,
            ErrorKind::NotACount { value, min, max },
        ));
    }
    Ok(value as u32)
}

/// An image size: each side 1 to [`MAX_IMAGE_SIDE`], at most [`MAX_PIXELS`]
/// in all. `path` names the image (`image`, or the overrides).
pub fn image_size(path: &str, width: f64, height: f64) -> Result<(u32, u32), SceneError> {
    let width = count(&format!("{path}.width"), width, 1, MAX_IMAGE_SIDE)?;
    let height = count(&format!("{path}.height"), height, 1, MAX_IMAGE_SIDE)?;
    if width as u64 * height as u64 > MAX_PIXELS {
        return Err(SceneError::new(
            path,
            ErrorKind::TooManyPixels { width, height },
        ));
    }
    Ok((width, height))
}
