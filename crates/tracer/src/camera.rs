//! Cameras: how a pixel becomes a primary ray.
//!
//! A ray passes through a point of its pixel given as a position within
//! it, `(0, 0)` the pixel's top-left corner and `(1, 1)` its bottom-right
//! ([`Camera::ray_at`]); [`Camera::ray`] takes the centre, as the course's
//! fragment shaders do (`gl_FragCoord` is the centre). Which point each
//! sample takes is the pixel filter's choice (`crate::filter`). Pixel
//! `(0, 0)` is the top-left corner of the image; `ndc.y` grows upwards.

use glam::{DMat4, DVec3, DVec4, Vec3};

use crate::geometry::Ray;
use radiometry::Vector3;

/// How primary rays are made.
// One camera per scene: the size difference between the variants costs nothing.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Camera {
    /// The course's pinhole (`000`, `getRay`): eye at (0, 0, −2), the
    /// pixel's point on the plane z = 0 at `(ndc.x · aspect, ndc.y, 0)`.
    CoursePinhole {
        /// Width / height.
        aspect: f64,
        /// Image size, pixels.
        width: u32,
        /// Image size, pixels.
        height: u32,
    },
    /// A look-at camera unprojected through the inverse view-projection
    /// matrix (`002`, vertex shader): the ray starts on the near plane and
    /// points at the same pixel on the far plane.
    LookAt {
        /// Inverse of `projection · view` (OpenGL clip space, z in [−1, 1]).
        inverse_view_projection: DMat4,
        /// The parameters it was built from, to rebuild it at another size.
        view: LookAtView,
        /// Image size, pixels.
        width: u32,
        /// Image size, pixels.
        height: u32,
    },
}

/// A look-at camera's placement and lens.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LookAtView {
    /// Eye position, m.
    pub eye: DVec3,
    /// Point looked at, m.
    pub target: DVec3,
    /// Up direction.
    pub up: DVec3,
    /// Vertical field of view, radians.
    pub fov_y: f64,
    /// Near plane distance, m.
    pub near: f64,
    /// Far plane distance, m.
    pub far: f64,
}

/// The centre of a pixel, as a position within it.
pub const PIXEL_CENTRE: (f64, f64) = (0.5, 0.5);

/// The course's eye position, m.
pub const COURSE_EYE: Vec3 = Vec3::new(0.0, 0.0, -2.0);

impl Camera {
    /// The course's pinhole for an image of `width × height`.
    pub fn course_pinhole(width: u32, height: u32) -> Self {
        Camera::CoursePinhole {
            aspect: width as f64 / height as f64,
            width,
            height,
        }
    }

    /// A right-handed look-at camera with an OpenGL perspective projection.
    pub fn look_at(view: LookAtView, width: u32, height: u32) -> Self {
        let LookAtView {
            eye,
            target,
            up,
            fov_y,
            near,
            far,
        } = view;
        let world_to_camera = DMat4::look_at_rh(eye, target, up);
        let projection = DMat4::perspective_rh_gl(fov_y, width as f64 / height as f64, near, far);
        Camera::LookAt {
            inverse_view_projection: (projection * world_to_camera).inverse(),
            view,
            width,
            height,
        }
    }

    /// The same camera for an image of another size.
    pub fn resized(&self, width: u32, height: u32) -> Self {
        match *self {
            Camera::CoursePinhole { .. } => Camera::course_pinhole(width, height),
            Camera::LookAt { view, .. } => Camera::look_at(view, width, height),
        }
    }

    /// Normalised device coordinates of the point `within` pixel `(x, y)`
    /// (`(0.5, 0.5)` its centre, `(0, 0)` its top-left corner): `(−1, −1)`
    /// at the bottom-left corner of the image, `(1, 1)` at the top-right.
    pub fn ndc(width: u32, height: u32, x: u32, y: u32, within: (f64, f64)) -> (f64, f64) {
        let nx = (x as f64 + within.0) / width as f64 * 2.0 - 1.0;
        let ny = 1.0 - (y as f64 + within.1) / height as f64 * 2.0;
        (nx, ny)
    }

    /// The primary ray through the centre of pixel `(x, y)`.
    pub fn ray(&self, x: u32, y: u32) -> Ray {
        self.ray_at(x, y, PIXEL_CENTRE)
    }

    /// The primary ray through the point `within` pixel `(x, y)`, each
    /// coordinate in `[0, 1]` from the pixel's top-left corner, in `f32`:
    /// [`Camera::ray_in`].
    pub fn ray_at(&self, x: u32, y: u32, within: (f64, f64)) -> Ray {
        self.ray_in(x, y, within)
    }

    /// [`Camera::ray_at`] at tier `V`: the construction is carried in
    /// `f64` and rounded once to the tier.
    pub fn ray_in<V: Vector3>(&self, x: u32, y: u32, within: (f64, f64)) -> Ray<V> {
        let [ray] = self.rays_in(x, y, [within]);
        ray
    }

    /// The rays of [`Camera::ray_in`] through the points `within` of pixel
    /// `(x, y)`, each with the bits `ray_in` gives it. Made together, the
    /// rays' `f64` divisions and square roots, which nothing else waits
    /// on, go through the vector units side by side instead of each
    /// stalling the path traced behind it.
    #[inline]
    pub fn rays_in<V: Vector3, const N: usize>(
        &self,
        x: u32,
        y: u32,
        within: [(f64, f64); N],
    ) -> [Ray<V>; N] {
        let mut origins = [DVec3::ZERO; N];
        let mut directions = [DVec3::ZERO; N];
        match *self {
            Camera::CoursePinhole {
                aspect,
                width,
                height,
            } => {
                let eye = COURSE_EYE.as_dvec3();
                for ((origin, direction), within) in
                    origins.iter_mut().zip(&mut directions).zip(within)
                {
                    let (nx, ny) = Self::ndc(width, height, x, y, within);
                    let on_plane = DVec3::new(nx * aspect, ny, 0.0);
                    *origin = eye;
                    *direction = (on_plane - eye).normalize();
                }
            }
            Camera::LookAt {
                inverse_view_projection,
                width,
                height,
                ..
            } => {
                for ((origin, direction), within) in
                    origins.iter_mut().zip(&mut directions).zip(within)
                {
                    let (nx, ny) = Self::ndc(width, height, x, y, within);
                    let (near, far) = unproject_near_far(&inverse_view_projection, nx, ny);
                    *origin = near;
                    *direction = (far - near).normalize();
                }
            }
        }
        std::array::from_fn(|i| Ray::new(V::of_f64(origins[i]), V::of_f64(directions[i])))
    }
}

/// The points of NDC `(nx, ny)` on OpenGL's near plane (z = −1 in clip
/// space) and far plane (z = +1), unprojected through `m`: `M · (nx, ny,
/// z, 1)` divided by its `w`. Summed in glam's order, ((c₀ nx + c₁ ny) +
/// c₂ z) + c₃, with the part the two points share taken once: `c₂ · (∓1)`
/// and `c₃ · 1` are exact, so both points have the bits of the two full
/// matrix products, at half their cost.
fn unproject_near_far(m: &DMat4, nx: f64, ny: f64) -> (DVec3, DVec3) {
    let shared = m.x_axis * nx + m.y_axis * ny;
    let on_plane = |p: DVec4| p.truncate() / p.w;
    (
        on_plane((shared - m.z_axis) + m.w_axis),
        on_plane((shared + m.z_axis) + m.w_axis),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The look-at camera's points on the near and far planes, with the
    /// columns' shared part taken once, have the bits of the full
    /// `M · (nx, ny, ∓1, 1)` (tolerance: none, `f64` compared exactly),
    /// and its rays are made from them: at every pixel of a small
    /// image and at points across each pixel, for cameras placed off every
    /// axis (so that no column is zero and every sum rounds).
    #[test]
    fn look_at_rays_have_the_bits_of_the_full_unprojection() {
        let view = |eye: DVec3, target: DVec3, fov_y: f64, near: f64, far: f64| LookAtView {
            eye,
            target,
            up: DVec3::Y,
            fov_y,
            near,
            far,
        };
        let views = [
            view(
                DVec3::new(0.0, 1.6, 6.0),
                DVec3::new(0.0, 0.8, 0.0),
                0.7,
                0.1,
                100.0,
            ),
            view(
                DVec3::new(-3.3, 2.1, -7.7),
                DVec3::new(0.4, -0.2, 1.3),
                1.1,
                0.37,
                55.0,
            ),
        ];
        let mut compared = 0;
        for view in views {
            let camera = Camera::look_at(view, 37, 23);
            let Camera::LookAt {
                inverse_view_projection: m,
                ..
            } = camera
            else {
                unreachable!("a look-at camera")
            };
            for y in 0..23 {
                for x in 0..37 {
                    for within in [(0.5, 0.5), (0.0, 0.0), (0.13, 0.91), (0.999, 0.3)] {
                        let (nx, ny) = Camera::ndc(37, 23, x, y, within);
                        let unproject = |z: f64| {
                            let p = m * DVec4::new(nx, ny, z, 1.0);
                            p.truncate() / p.w
                        };
                        let full = (unproject(-1.0), unproject(1.0));
                        let (near, far) = unproject_near_far(&m, nx, ny);
                        assert_eq!((near, far), full, "{x} {y} {within:?}");
                        let ray = Ray::new(near.as_vec3(), (far - near).normalize().as_vec3());
                        assert_eq!(camera.ray_at(x, y, within), ray, "{x} {y} {within:?}");
                        compared += 1;
                    }
                }
            }
        }
        assert_eq!(compared, 2 * 37 * 23 * 4);
    }
}
