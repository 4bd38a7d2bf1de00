//! The validated scene, in the tracer's `f32`: what the integrators read.

use std::sync::Arc;

use glam::Vec3;

use techniques::bump::HeightField;

use super::Settings;
use crate::camera::Camera;
use crate::environment::Environment;
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
    /// Radiance of escaping rays, where there is no `environment`.
    pub background: Vec3,
    /// What escaping rays receive by direction, in place of `background`
    /// (shared: a map is read once however often the scene is copied).
    pub environment: Option<Arc<Environment>>,
    /// The course's ambient radiance.
    pub ambient: Vec3,
    /// Materials, indexed by the objects.
    pub materials: Vec<Material>,
    /// Material names, parallel to `materials`.
    pub material_names: Vec<String>,
    /// The objects.
    pub objects: Vec<Object>,
    /// Each object's bump map, parallel to `objects`: `None` where the
    /// geometric normal shades (see [`crate::bump`]).
    pub bumps: Vec<Option<HeightField>>,
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
    /// The radiance a ray travelling in `direction` receives when it meets
    /// nothing: the environment's there, else the constant background.
    pub fn escaped(&self, direction: Vec3) -> Vec3 {
        match &self.environment {
            Some(environment) => environment.radiance(direction),
            None => self.background,
        }
    }

    /// The same scene rendered at another size (the camera keeps its view).
    pub fn resized(&self, width: u32, height: u32) -> Scene {
        Scene {
            width,
            height,
            camera: self.camera.resized(width, height),
            ..self.clone()
        }
    }

    /// The scene with every `course_rough` material made `lambert` of
    /// albedo `kd`, each channel at most 1: the suite's energy-conserving
    /// stand-in for the course's material wherever a physical answer is
    /// measured (the full-light cross-check, `optics tradeoff --lambert`).
    /// The course's `kd` is in 1/sr, so its own diffuse albedo is `π kd`.
    pub fn course_rough_as_lambert(&self) -> Scene {
        let materials = self
            .materials
            .iter()
            .map(|&m| match m {
                Material::CourseRough { diffuse, .. } => Material::Lambert {
                    albedo: diffuse.min(Vec3::ONE),
                },
                other => other,
            })
            .collect();
        Scene {
            materials,
            ..self.clone()
        }
    }

    /// The most light a rough material reflects for what it receives,
    /// where that is more than 1: the course material's diffuse albedo
    /// `π kd` (its largest channel) and the material's name; `None` where
    /// every rough material conserves energy in its diffuse part.
    pub fn diffuse_gain(&self) -> Option<(f32, &str)> {
        self.materials
            .iter()
            .zip(&self.material_names)
            .filter_map(|(m, name)| match m {
                Material::CourseRough { diffuse, .. } => {
                    Some((std::f32::consts::PI * diffuse.max_element(), name.as_str()))
                }
                _ => None,
            })
            .filter(|&(gain, _)| gain > 1.0)
            .max_by(|a, b| a.0.total_cmp(&b.0))
    }
}

#[cfg(test)]
mod tests {
    use super::Material;
    use glam::Vec3;

    fn two_spheres() -> super::Scene {
        crate::scene::parse(
            r#"{ "version": 1, "image": { "width": 4, "height": 3 },
                 "camera": { "type": "course_pinhole" },
                 "materials": {
                   "green": { "type": "course_rough", "ambient": [0, 0, 0],
                              "diffuse": [0.1, 0.8, 0.3], "specular": [1, 1, 1], "shininess": 10 },
                   "white": { "type": "lambert", "albedo": [0.5, 0.5, 0.5] } },
                 "objects": [
                   { "type": "sphere", "center": [0, 0, 4], "radius": 1, "material": "green" },
                   { "type": "sphere", "center": [3, 0, 4], "radius": 1, "material": "white" } ] }"#,
        )
        .unwrap()
    }

    /// π · 0.8 = 2.513: the course material reflects 2.5 times the light
    /// it receives in its diffuse part alone; Lambert never more than 1.
    #[test]
    fn the_course_materials_diffuse_albedo_is_pi_kd() {
        let scene = two_spheres();
        let (gain, name) = scene.diffuse_gain().unwrap();
        assert!((gain - 2.513_274).abs() < 1e-5, "{gain}");
        assert_eq!(name, "green");
        assert_eq!(scene.course_rough_as_lambert().diffuse_gain(), None);
    }

    #[test]
    fn the_lambert_stand_in_has_albedo_kd_and_leaves_the_rest() {
        let scene = two_spheres().course_rough_as_lambert();
        assert_eq!(
            scene.materials[0],
            Material::Lambert {
                albedo: Vec3::new(0.1, 0.8, 0.3)
            }
        );
        assert_eq!(scene.materials[1], two_spheres().materials[1]);
    }
}
