//! The validated scene, in the tracer's `f32`: what the integrators read.

use glam::Vec3;

use super::Settings;
use crate::camera::Camera;
use crate::geometry::Object;

/// A validated scene in the tracer's `f32`.
#[derive(Clone, Debug)]
pub struct Scene {
    /// Image width, pixels.
    pub width: u32,
    /// Image height, pixels.
    pub height: u32,
    /// The camera.
    pub camera: Camera,
    /// Radiance of escaping rays.
    pub background: Vec3,
    /// The course's ambient radiance.
    pub ambient: Vec3,
    /// Materials, indexed by the objects.
    pub materials: Vec<Material>,
    /// Material names, parallel to `materials`.
    pub material_names: Vec<String>,
    /// The objects.
    pub objects: Vec<Object>,
    /// The lights.
    pub lights: Vec<Light>,
    /// The scene's own settings, settled over the defaults (a
    /// [`RenderJob`](crate::job::RenderJob) settles its overrides over them).
    pub settings: Settings,
}

/// A material in the tracer's `f32`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Material {
    /// See [`MaterialSpec::Flat`](super::schema::MaterialSpec::Flat).
    Flat {
        /// Radiance, W/(sr·m²).
        radiance: Vec3,
    },
    /// See [`MaterialSpec::NormalColour`](super::schema::MaterialSpec::NormalColour).
    NormalColour,
    /// See [`MaterialSpec::CourseRough`](super::schema::MaterialSpec::CourseRough).
    CourseRough {
        /// `ka`.
        ambient: Vec3,
        /// `kd`, 1/sr.
        diffuse: Vec3,
        /// `ks`, 1/sr.
        specular: Vec3,
        /// Exponent.
        shininess: f32,
    },
    /// See [`MaterialSpec::Lambert`](super::schema::MaterialSpec::Lambert).
    Lambert {
        /// Albedo.
        albedo: Vec3,
    },
    /// See [`MaterialSpec::Conductor`](super::schema::MaterialSpec::Conductor).
    Conductor {
        /// Real index per channel.
        n: [f32; 3],
        /// Extinction per channel.
        kappa: [f32; 3],
        /// The exact law per channel, its angle-free parts computed once.
        exact: [radiometry::fresnel::Conductor<f32>; 3],
    },
    /// See [`MaterialSpec::Dielectric`](super::schema::MaterialSpec::Dielectric).
    Dielectric {
        /// `n_inside / n_outside`.
        eta: f32,
    },
}

impl Material {
    /// Whether light is shaded here from the lights (a rough surface).
    pub fn is_rough(&self) -> bool {
        matches!(
            self,
            Material::CourseRough { .. } | Material::Lambert { .. }
        )
    }

    /// Whether the surface scatters only into discrete directions.
    pub fn is_specular(&self) -> bool {
        matches!(
            self,
            Material::Conductor { .. } | Material::Dielectric { .. }
        )
    }
}

/// A light in the tracer's `f32`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Light {
    /// See [`LightSpec::Directional`](super::schema::LightSpec::Directional).
    Directional {
        /// Unit direction towards the light.
        towards: Vec3,
        /// W/m² per channel, on a surface facing the light.
        irradiance: Vec3,
    },
    /// See [`LightSpec::Point`](super::schema::LightSpec::Point).
    Point {
        /// Position, m.
        position: Vec3,
        /// W/sr per channel.
        intensity: Vec3,
    },
}

impl Scene {
    /// The same scene rendered at another size (the camera keeps its view).
    pub fn resized(&self, width: u32, height: u32) -> Scene {
        Scene {
            width,
            height,
            camera: self.camera.resized(width, height),
            ..self.clone()
        }
    }
}
