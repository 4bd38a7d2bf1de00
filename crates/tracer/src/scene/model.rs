//! The validated scene, in the tracer's `f32`, and its objects, materials
//! and lights at a tracer's precision tier: what the integrators read.

use std::sync::Arc;

use glam::Vec3;

use techniques::bump::HeightField;

use super::settings::Settings;
use crate::camera::Camera;
use crate::environment::Environment;
use crate::geometry::Object;
use radiometry::{Real, Vector3};

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

/// A material, in the validated scene's `f32` or at a tracer's tier.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Material<V: Vector3 = Vec3> {
    /// See [`MaterialSpec::Flat`](super::schema::MaterialSpec::Flat).
    Flat {
        /// Radiance, W/(sr·m²).
        radiance: V,
    },
    /// See [`MaterialSpec::NormalColour`](super::schema::MaterialSpec::NormalColour).
    NormalColour,
    /// See [`MaterialSpec::CourseRough`](super::schema::MaterialSpec::CourseRough).
    CourseRough {
        /// `ka`.
        ambient: V,
        /// `kd`, 1/sr.
        diffuse: V,
        /// `ks`, 1/sr.
        specular: V,
        /// Exponent.
        shininess: V::Scalar,
    },
    /// See [`MaterialSpec::Lambert`](super::schema::MaterialSpec::Lambert).
    Lambert {
        /// Albedo.
        albedo: V,
    },
    /// See [`MaterialSpec::Conductor`](super::schema::MaterialSpec::Conductor).
    Conductor {
        /// Real index per channel.
        n: [V::Scalar; 3],
        /// Extinction per channel.
        kappa: [V::Scalar; 3],
        /// The exact law per channel, its angle-free parts computed once.
        exact: [radiometry::fresnel::Conductor<V::Scalar>; 3],
    },
    /// See [`MaterialSpec::Dielectric`](super::schema::MaterialSpec::Dielectric).
    Dielectric {
        /// `n_inside / n_outside`.
        eta: V::Scalar,
    },
}

impl Material {
    /// This material at tier `V`: its numbers widened exactly, a
    /// conductor's law built again at the tier from them.
    pub fn at_tier<V: Vector3>(&self) -> Material<V> {
        let widen = V::Scalar::of_f32;
        match *self {
            Material::Flat { radiance } => Material::Flat {
                radiance: V::of_f32(radiance),
            },
            Material::NormalColour => Material::NormalColour,
            Material::CourseRough {
                ambient,
                diffuse,
                specular,
                shininess,
            } => Material::CourseRough {
                ambient: V::of_f32(ambient),
                diffuse: V::of_f32(diffuse),
                specular: V::of_f32(specular),
                shininess: widen(shininess),
            },
            Material::Lambert { albedo } => Material::Lambert {
                albedo: V::of_f32(albedo),
            },
            Material::Conductor { n, kappa, .. } => {
                let (n, kappa) = (n.map(widen), kappa.map(widen));
                let exact = core::array::from_fn(|c| {
                    radiometry::fresnel::Conductor::new(n[c], kappa[c])
                        .expect("the law took these indices in f32, whose range is narrower")
                });
                Material::Conductor { n, kappa, exact }
            }
            Material::Dielectric { eta } => Material::Dielectric { eta: widen(eta) },
        }
    }
}

impl<V: Vector3> Material<V> {
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

/// A light, in the validated scene's `f32` or at a tracer's tier.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Light<V: Vector3 = Vec3> {
    /// See [`LightSpec::Directional`](super::schema::LightSpec::Directional).
    Directional {
        /// Unit direction towards the light.
        towards: V,
        /// W/m² per channel, on a surface facing the light.
        irradiance: V,
    },
    /// See [`LightSpec::Point`](super::schema::LightSpec::Point).
    Point {
        /// Position, m.
        position: V,
        /// W/sr per channel.
        intensity: V,
    },
}

impl Light {
    /// This light at tier `V`, its numbers widened exactly.
    pub fn at_tier<V: Vector3>(&self) -> Light<V> {
        match *self {
            Light::Directional {
                towards,
                irradiance,
            } => Light::Directional {
                towards: V::of_f32(towards),
                irradiance: V::of_f32(irradiance),
            },
            Light::Point {
                position,
                intensity,
            } => Light::Point {
                position: V::of_f32(position),
                intensity: V::of_f32(intensity),
            },
        }
    }
}

/// What a tracer at tier `V` reads of a [`Scene`]: its objects, materials
/// and lights, and the constant radiances, widened once when the tracer is
/// built (exact, and the same numbers at both tiers: the scene's own for
/// `f32`).
#[derive(Clone, Debug)]
pub struct World<V: Vector3 = Vec3> {
    /// [`Scene::objects`] at the tier.
    pub objects: Vec<Object<V>>,
    /// [`Scene::materials`] at the tier.
    pub materials: Vec<Material<V>>,
    /// [`Scene::lights`] at the tier.
    pub lights: Vec<Light<V>>,
    /// [`Scene::ambient`] at the tier.
    pub ambient: V,
}

impl<V: Vector3> World<V> {
    /// `scene`'s objects, materials and lights at tier `V`.
    pub fn of(scene: &Scene) -> Self {
        World {
            objects: scene.objects.iter().map(Object::at_tier).collect(),
            materials: scene.materials.iter().map(Material::at_tier).collect(),
            lights: scene.lights.iter().map(Light::at_tier).collect(),
            ambient: V::of_f32(scene.ambient),
        }
    }
}

impl Scene {
    /// The radiance a ray travelling in `direction` receives when it meets
    /// nothing: the environment's there, else the constant background. A
    /// map's texels are `f32`: a tracer at another tier looks them up
    /// along its direction rounded to `f32`.
    pub fn escaped<V: Vector3>(&self, direction: V) -> V {
        V::of_f32(match &self.environment {
            Some(environment) => environment.radiance(direction.to_f32()),
            None => self.background,
        })
    }

    /// Whether the course's final GLSL shader has everything this scene
    /// holds: its lights are all directional (the shader's one light) and
    /// none of its materials is glass (it has no refraction). Its
    /// integrator, `course`, draws such a scene as the course did.
    pub fn within_course_shader(&self) -> bool {
        self.lights
            .iter()
            .all(|light| matches!(light, Light::Directional { .. }))
            && !self
                .materials
                .iter()
                .any(|material| matches!(material, Material::Dielectric { .. }))
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
