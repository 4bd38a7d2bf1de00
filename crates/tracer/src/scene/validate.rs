//! The second pass over a scene file: every value against its domain
//! (finite numbers, positive radii, non-zero directions, at least three tube
//! sides, a bounded resolution), each refusal naming the JSON path. Only a
//! validated scene becomes a [`Scene`].

use glam::{DVec3, Vec3};
use radiometry::domain::{self, DomainError};
use radiometry::fresnel;

use techniques::bump::HeightField;

use super::error::{ErrorKind, SceneError};
use super::model::{Light, Material, Scene};
use super::schema::{BumpSpec, CameraSpec, LightSpec, MaterialSpec, ObjectSpec, SceneFile};
use super::settings::Settings;
use super::values::{count, direction, finite3, image_size, non_negative3, positive};
use crate::camera::{Camera, LookAtView};
use crate::geometry::{Object, Plane, Sphere, Tube};
use crate::kinds::SCHEMA_VERSION;

impl SceneFile {
    /// Checks every value against its domain and builds the [`Scene`];
    /// an environment's files are named relative to the current directory.
    pub fn validate(&self) -> Result<Scene, SceneError> {
        self.validate_in(std::path::Path::new(""))
    }

    /// [`SceneFile::validate`], an environment's files named relative to
    /// `dir` (the scene file's directory).
    pub fn validate_in(&self, dir: &std::path::Path) -> Result<Scene, SceneError> {
        if self.version != SCHEMA_VERSION {
            return Err(SceneError::new(
                "version",
                ErrorKind::Version { got: self.version },
            ));
        }
        let (width, height) = image_size("image", self.image.width, self.image.height)?;
        let camera = validate_camera(&self.camera, width, height)?;
        let background = match self.background {
            Some(_) if self.environment.is_some() => {
                return Err(SceneError::new(
                    "background",
                    ErrorKind::BackgroundWithEnvironment,
                ))
            }
            Some(background) => non_negative3("background", background)?,
            None => Vec3::ZERO,
        };
        let ambient = non_negative3("ambient", self.ambient)?;
        let mut material_names = Vec::new();
        let mut materials = Vec::new();
        for (name, spec) in &self.materials {
            materials.push(validate_material(&format!("materials.{name}"), spec)?);
            material_names.push(name.clone());
        }
        let (objects, bumps) = self
            .objects
            .iter()
            .enumerate()
            .map(|(i, spec)| {
                let p = format!("objects[{i}]");
                let object = validate_object(&p, spec, &material_names, &materials)?;
                let material = &materials[object.material() as usize];
                let bump = validate_bump(&p, spec, material)?;
                Ok((object, bump))
            })
            .collect::<Result<(Vec<_>, Vec<_>), SceneError>>()?;
        let lights = self
            .lights
            .iter()
            .enumerate()
            .map(|(i, spec)| validate_light(&format!("lights[{i}]"), spec))
            .collect::<Result<_, _>>()?;
        let settings = Settings::default().settle("render", &self.render)?;
        let environment = self
            .environment
            .as_ref()
            .map(|spec| super::environment::validate(spec, dir))
            .transpose()?;
        let scene = Scene {
            width,
            height,
            camera,
            background,
            environment,
            ambient,
            materials,
            material_names,
            objects,
            bumps,
            lights,
            settings,
        };
        super::bound::check(&scene)?;
        Ok(scene)
    }
}

fn validate_camera(spec: &CameraSpec, width: u32, height: u32) -> Result<Camera, SceneError> {
    let CameraSpec::LookAt {
        eye,
        target,
        up,
        fov_y_deg,
        near,
        far,
    } = *spec
    else {
        return Ok(Camera::course_pinhole(width, height));
    };
    let eye_v = finite3("camera.eye", eye)?;
    let target_v = finite3("camera.target", target)?;
    let forward = direction(
        "camera.target",
        [target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]],
    )
    .map_err(|_| SceneError::new("camera.target", ErrorKind::TargetIsEye))?;
    let up_v = direction("camera.up", up)?;
    if forward.cross(up_v).length() < 1e-6 {
        return Err(SceneError::new("camera.up", ErrorKind::UpAlongView));
    }
    domain::finite("camera.fov_y_deg", fov_y_deg)?;
    if !(fov_y_deg > 0.0 && fov_y_deg < 180.0) {
        return Err(SceneError::new(
            "camera.fov_y_deg",
            ErrorKind::FieldOfView { degrees: fov_y_deg },
        ));
    }
    positive("camera.near", near)?;
    positive("camera.far", far)?;
    if !(far > near) {
        return Err(SceneError::new(
            "camera.far",
            ErrorKind::FarNotBeyondNear { near, far },
        ));
    }
    let view = LookAtView {
        eye: eye_v.as_dvec3(),
        target: target_v.as_dvec3(),
        up: up_v.as_dvec3(),
        fov_y: fov_y_deg.to_radians(),
        near,
        far,
    };
    Ok(Camera::look_at(view, width, height))
}

fn validate_object(
    p: &str,
    spec: &ObjectSpec,
    names: &[String],
    materials: &[Material],
) -> Result<Object, SceneError> {
    let material_index = |name: &str| -> Result<u32, SceneError> {
        names
            .iter()
            .position(|m| m == name)
            .map(|i| i as u32)
            .ok_or_else(|| {
                let kind = ErrorKind::UnknownMaterial {
                    name: name.to_owned(),
                    defined: names.to_vec(),
                };
                SceneError::new(format!("{p}.material"), kind)
            })
    };
    // A dielectric needs a closed surface with an inside.
    let not_dielectric = |m: u32| match materials[m as usize] {
        Material::Dielectric { .. } => Err(SceneError::new(
            format!("{p}.material"),
            ErrorKind::DielectricWithoutInside,
        )),
        _ => Ok(m),
    };
    Ok(match spec {
        ObjectSpec::Sphere {
            center,
            radius,
            material,
            ..
        } => Object::Sphere(Sphere {
            center: finite3(&format!("{p}.center"), *center)?,
            radius: positive(&format!("{p}.radius"), *radius)?,
            material: material_index(material)?,
        }),
        ObjectSpec::Plane {
            point,
            normal,
            material,
            ..
        } => {
            let material = not_dielectric(material_index(material)?)?;
            Object::Plane(Plane {
                point: finite3(&format!("{p}.point"), *point)?,
                normal: direction(&format!("{p}.normal"), *normal)?,
                material,
            })
        }
        ObjectSpec::MirrorTube {
            axis_point,
            axis,
            sides,
            radius,
            material,
        } => {
            let material = not_dielectric(material_index(material)?)?;
            let sides = count(&format!("{p}.sides"), *sides, 3, 64)?;
            Object::Tube(Tube::new(
                finite3(&format!("{p}.axis_point"), *axis_point)?,
                direction(&format!("{p}.axis"), *axis)?,
                sides,
                positive(&format!("{p}.radius"), *radius)?,
                material,
            ))
        }
    })
}

/// An object's bump map, `None` without one: its height field's
/// parameters in their domains (`techniques::bump`), on a rough or unlit
/// material. A mirror's or a glass's side and lobes are decided by the
/// normal they are given (`scatter`), which a bent normal could turn
/// against the surface's own, so a bump on one is refused.
fn validate_bump(
    p: &str,
    spec: &ObjectSpec,
    material: &Material,
) -> Result<Option<HeightField>, SceneError> {
    let (ObjectSpec::Sphere {
        bump: Some(bump), ..
    }
    | ObjectSpec::Plane {
        bump: Some(bump), ..
    }) = spec
    else {
        return Ok(None);
    };
    let path = format!("{p}.bump");
    let field = match *bump {
        BumpSpec::Flat {} => Ok(HeightField::Flat),
        BumpSpec::Slope { du, dv } => HeightField::slope(du, dv),
        BumpSpec::Sine { amplitude, period } => HeightField::sine(amplitude, period),
    }
    .map_err(|error| {
        let field = format!("{path}.{}", error.parameter().name());
        SceneError::new(field, ErrorKind::Bump(error))
    })?;
    if material.is_specular() {
        return Err(SceneError::new(path, ErrorKind::BumpOnSmoothSurface));
    }
    Ok(Some(field))
}

fn validate_light(p: &str, spec: &LightSpec) -> Result<Light, SceneError> {
    Ok(match *spec {
        LightSpec::Directional {
            towards,
            irradiance,
        } => Light::Directional {
            towards: direction(&format!("{p}.towards"), towards)?,
            irradiance: non_negative3(&format!("{p}.irradiance"), irradiance)?,
        },
        LightSpec::Point {
            position,
            intensity,
        } => Light::Point {
            position: finite3(&format!("{p}.position"), position)?,
            intensity: non_negative3(&format!("{p}.intensity"), intensity)?,
        },
    })
}

fn validate_material(p: &str, spec: &MaterialSpec) -> Result<Material, SceneError> {
    Ok(match *spec {
        MaterialSpec::Flat { radiance } => Material::Flat {
            radiance: non_negative3(&format!("{p}.radiance"), radiance)?,
        },
        MaterialSpec::NormalColour {} => Material::NormalColour,
        MaterialSpec::CourseRough {
            ambient,
            diffuse,
            specular,
            shininess,
        } => Material::CourseRough {
            ambient: non_negative3(&format!("{p}.ambient"), ambient)?,
            diffuse: non_negative3(&format!("{p}.diffuse"), diffuse)?,
            specular: non_negative3(&format!("{p}.specular"), specular)?,
            shininess: domain::non_negative(&format!("{p}.shininess"), shininess)? as f32,
        },
        MaterialSpec::Lambert { albedo } => {
            for (axis, c) in ["[0]", "[1]", "[2]"].into_iter().zip(albedo) {
                domain::fraction(&format!("{p}.albedo{axis}"), c)?;
            }
            Material::Lambert {
                albedo: DVec3::from_array(albedo).as_vec3(),
            }
        }
        MaterialSpec::Conductor { n, kappa } => {
            let channel = |ch: usize, axis: &str| -> Result<fresnel::Conductor<f32>, SceneError> {
                let name = format!("{p}.n{axis}");
                let n = domain::INDEX_RANGE_F32.refractive_index(&name, n[ch])? as f32;
                let k_name = format!("{p}.kappa{axis}");
                let k = domain::INDEX_RANGE_F32.extinction(&k_name, kappa[ch])? as f32;
                // Always a conductor once both are in range; the law's own
                // refusal is kept rather than assumed.
                let refused = || DomainError::NotFinite {
                    name,
                    value: f64::from(n),
                };
                Ok(fresnel::Conductor::new(n, k).ok_or_else(refused)?)
            };
            Material::Conductor {
                n: n.map(|x| x as f32),
                kappa: kappa.map(|x| x as f32),
                exact: [channel(0, "[0]")?, channel(1, "[1]")?, channel(2, "[2]")?],
            }
        }
        MaterialSpec::Dielectric { eta } => Material::Dielectric {
            eta: domain::INDEX_RANGE_F32.refractive_index(&format!("{p}.eta"), eta)? as f32,
        },
    })
}
