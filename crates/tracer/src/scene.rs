//! Scene files: the JSON schema (version 1), its parsing and its validation.
//!
//! A scene file is read in two passes. The first is serde's: syntax, types
//! and unknown fields, each error carrying the JSON path of the bad value
//! (via `serde_path_to_error`). The second is [`SceneFile::validate`]: the
//! values' domains (finite numbers, positive radii, non-zero directions, at
//! least three tube sides, a bounded resolution, at least one sample), again
//! naming the path. Only a validated scene becomes a [`Scene`], whose numbers
//! are the tracer's `f32`. The schema is documented in `docs/scene-schema.md`.

use std::collections::BTreeMap;
use std::fmt;

use glam::{DVec3, Vec3};
use radiometry::domain::{self, DomainError};
use serde::Deserialize;
use serde_json::Value;

use crate::camera::{Camera, LookAtView};
use crate::geometry::{Object, Plane, Sphere, Tube};

/// The only schema version this crate reads.
pub const SCHEMA_VERSION: u32 = 1;

/// The largest image side accepted, in pixels. 16384 is the largest texture
/// side common GPUs allow and four times a 4K display; a larger image is
/// almost certainly a typo, and 16384² RGB floats are already 3 GiB.
pub const MAX_IMAGE_SIDE: u32 = 16_384;

/// The most pixels accepted: 8192², a 64-megapixel image (768 MiB of
/// `f32` radiance).
pub const MAX_PIXELS: u64 = 8192 * 8192;

/// The most samples per pixel accepted: 2^20. Beyond this the `f32` image
/// cannot resolve the difference a further sample makes.
pub const MAX_SPP: u32 = 1 << 20;

/// The deepest recursion accepted. The course's shaders use 12 and 64.
pub const MAX_DEPTH: u32 = 1024;

/// Why a scene file could not be read, with where in it the problem is.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// The file could not be read.
    #[error("cannot read {path}: {source}")]
    Io {
        /// The file.
        path: String,
        /// The operating system's reason.
        source: std::io::Error,
    },
    /// Not JSON, a wrong type, an unknown or missing field.
    #[error("{path}: {message} (line {line}, column {column})")]
    Syntax {
        /// The JSON path of the bad value (`.` for the whole file).
        path: String,
        /// serde's description.
        message: String,
        /// Where in the text.
        line: usize,
        /// Where in the text.
        column: usize,
    },
    /// Well-formed, but a value is outside its domain.
    #[error(transparent)]
    Domain(#[from] DomainError),
    /// A reference or combination that does not hold together.
    #[error("{path}: {message}")]
    Invalid {
        /// The JSON path of the bad value.
        path: String,
        /// What is wrong and what was expected.
        message: String,
    },
}

impl SceneError {
    fn invalid(path: impl Into<String>, message: impl Into<String>) -> Self {
        SceneError::Invalid {
            path: path.into(),
            message: message.into(),
        }
    }
}

/// A scene file as written, before validation. Numbers are `f64` here so
/// that a value is reported exactly as it was given.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
    /// Must be [`SCHEMA_VERSION`].
    pub version: u32,
    /// The image size.
    pub image: ImageSpec,
    /// How primary rays are made.
    pub camera: CameraSpec,
    /// Radiance of rays that leave the scene, W/(sr·m²) per channel.
    #[serde(default)]
    pub background: [f64; 3],
    /// The course's ambient light, radiance per channel, used by the `local`
    /// and `whitted` integrators (the path tracer computes indirect light
    /// instead).
    #[serde(default)]
    pub ambient: [f64; 3],
    /// Named materials.
    pub materials: BTreeMap<String, MaterialSpec>,
    /// The objects.
    pub objects: Vec<ObjectSpec>,
    /// The delta lights.
    #[serde(default)]
    pub lights: Vec<LightSpec>,
    /// Default render settings; the command line overrides them.
    #[serde(default)]
    pub render: RenderSpec,
}

/// The image size in pixels.
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ImageSpec {
    /// Width, 1 to [`MAX_IMAGE_SIDE`].
    pub width: f64,
    /// Height, 1 to [`MAX_IMAGE_SIDE`].
    pub height: f64,
}

/// A camera, as written.
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum CameraSpec {
    /// The course's pinhole (`000`): eye at (0, 0, −2), image plane z = 0,
    /// `ndc.x` scaled by the aspect ratio.
    CoursePinhole {},
    /// A look-at camera unprojected through the inverse view-projection
    /// matrix, near plane to far plane (`002`).
    LookAt {
        /// Eye position, m.
        eye: [f64; 3],
        /// The point looked at, m.
        target: [f64; 3],
        /// Up direction (any length).
        up: [f64; 3],
        /// Vertical field of view, degrees, in (0, 180).
        fov_y_deg: f64,
        /// Near plane distance, m, > 0.
        near: f64,
        /// Far plane distance, m, > near.
        far: f64,
    },
}

/// A material, as written. Colours are per-channel (R, G, B).
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum MaterialSpec {
    /// Unlit: the pixel shows `radiance` (the course's first red sphere).
    Flat {
        /// Radiance leaving the surface, W/(sr·m²).
        radiance: [f64; 3],
    },
    /// Unlit: the pixel shows the normal as a colour, `n / 2 + 1/2`.
    NormalColour {},
    /// The course's rough model: ambient, diffuse `kd` (1/sr, un-normalised),
    /// Blinn-Phong specular `ks` and shininess.
    CourseRough {
        /// Ambient reflectance `ka`.
        ambient: [f64; 3],
        /// Diffuse coefficient `kd`, 1/sr.
        diffuse: [f64; 3],
        /// Specular coefficient `ks`, 1/sr.
        specular: [f64; 3],
        /// Blinn-Phong exponent.
        shininess: f64,
    },
    /// Normalised Lambert, `f_r = albedo / π`.
    Lambert {
        /// Albedo, each in [0, 1].
        albedo: [f64; 3],
    },
    /// A smooth conductor of complex index `n + iκ` per channel.
    Conductor {
        /// Real part of the index.
        n: [f64; 3],
        /// Extinction coefficient κ.
        kappa: [f64; 3],
    },
    /// A smooth dielectric of relative index `eta = n_inside / n_outside`.
    Dielectric {
        /// Relative index.
        eta: f64,
    },
}

/// An object, as written.
#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum ObjectSpec {
    /// A sphere.
    Sphere {
        /// Centre, m.
        center: [f64; 3],
        /// Radius, m, > 0.
        radius: f64,
        /// Material name.
        material: String,
    },
    /// An infinite plane, visible and reflective from both sides.
    Plane {
        /// A point on the plane, m.
        point: [f64; 3],
        /// The normal (any length): the side called "outside".
        normal: [f64; 3],
        /// Material name.
        material: String,
    },
    /// The homework's kaleidoscope: a regular-polygon tube of mirrors,
    /// infinite along its axis.
    MirrorTube {
        /// A point on the axis, m.
        axis_point: [f64; 3],
        /// The axis direction (any length).
        axis: [f64; 3],
        /// Number of sides, ≥ 3.
        sides: f64,
        /// Circumradius (axis to corner), m, > 0.
        radius: f64,
        /// Material name.
        material: String,
    },
}

/// A light, as written.
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum LightSpec {
    /// Parallel light arriving from `towards` (the direction from the
    /// surface to the light).
    Directional {
        /// Direction towards the light (any length).
        towards: [f64; 3],
        /// Irradiance on a surface facing the light, W/m² per channel.
        irradiance: [f64; 3],
    },
    /// A point light with inverse-square falloff.
    Point {
        /// Position, m.
        position: [f64; 3],
        /// Radiant intensity, W/sr per channel.
        intensity: [f64; 3],
    },
}

/// Render settings a scene may carry; all optional.
#[derive(Clone, Copy, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RenderSpec {
    /// The integrator.
    pub integrator: Option<IntegratorKind>,
    /// Samples per pixel (path tracer), ≥ 1.
    pub spp: Option<f64>,
    /// Maximum number of bounces after the primary hit.
    pub max_depth: Option<f64>,
    /// Fresnel model.
    pub fresnel: Option<FresnelModel>,
    /// Throughput below which a path is cut (whitted) or rouletted (path).
    pub throughput_cutoff: Option<f64>,
    /// Seed of the path tracer's random numbers.
    pub seed: Option<u64>,
    /// How secondary rays leave a surface.
    pub ray_offset: Option<RayOffset>,
}

/// The light transport algorithm: the speed/accuracy ladder of `003`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum IntegratorKind {
    /// Direct light only; mirrors and glass show the background.
    Local,
    /// Recursive specular reflection and refraction, shadow rays.
    Whitted,
    /// Monte Carlo global illumination.
    Path,
    /// What the course's final GLSL shader computes, bugs included.
    Course,
}

impl fmt::Display for IntegratorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            IntegratorKind::Local => "local",
            IntegratorKind::Whitted => "whitted",
            IntegratorKind::Path => "path",
            IntegratorKind::Course => "course",
        })
    }
}

/// Which Fresnel law the smooth materials use.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FresnelModel {
    /// The exact equations (`radiometry::fresnel::conductor_rgb`, `dielectric`).
    Exact,
    /// Schlick's approximation (`radiometry::fresnel::schlick_rgb`, `schlick_dielectric`).
    Schlick,
    /// The course shader's reversed form, `F0 + (1 − F0) cos⁵θ`
    /// (`radiometry::course::fresnel_000_glsl`): isolates that one erratum
    /// in an otherwise physical render.
    Course,
}

/// How a secondary ray's origin is moved off the surface it leaves.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize, serde::Serialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum RayOffset {
    /// Along the normal by the bound on the hit point's rounding error.
    Robust,
    /// Along the normal by a fixed distance in metres (the course: 0.001).
    Fixed(f64),
}

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
    /// The scene's render settings (command-line overrides apply on top).
    pub render: RenderSpec,
}

/// A material in the tracer's `f32`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Material {
    /// See [`MaterialSpec::Flat`].
    Flat {
        /// Radiance, W/(sr·m²).
        radiance: Vec3,
    },
    /// See [`MaterialSpec::NormalColour`].
    NormalColour,
    /// See [`MaterialSpec::CourseRough`].
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
    /// See [`MaterialSpec::Lambert`].
    Lambert {
        /// Albedo.
        albedo: Vec3,
    },
    /// See [`MaterialSpec::Conductor`].
    Conductor {
        /// Real index per channel.
        n: [f32; 3],
        /// Extinction per channel.
        kappa: [f32; 3],
    },
    /// See [`MaterialSpec::Dielectric`].
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
    /// See [`LightSpec::Directional`].
    Directional {
        /// Unit direction towards the light.
        towards: Vec3,
        /// W/m² per channel, on a surface facing the light.
        irradiance: Vec3,
    },
    /// See [`LightSpec::Point`].
    Point {
        /// Position, m.
        position: Vec3,
        /// W/sr per channel.
        intensity: Vec3,
    },
}

/// Reads and validates a scene file.
pub fn load(path: &std::path::Path) -> Result<Scene, SceneError> {
    let text = std::fs::read_to_string(path).map_err(|source| SceneError::Io {
        path: path.display().to_string(),
        source,
    })?;
    parse(&text)
}

/// Parses and validates a scene from JSON text.
pub fn parse(text: &str) -> Result<Scene, SceneError> {
    let de = &mut serde_json::Deserializer::from_str(text);
    let mut value: Value = serde_path_to_error::deserialize(de).map_err(|err| {
        let path = err.path().to_string();
        let inner = err.into_inner();
        let mut message = without_position(&inner);
        if message == "expected value" {
            message.push_str(" (JSON numbers are finite: NaN and Infinity are not numbers)");
        }
        SceneError::Syntax {
            path,
            message,
            line: inner.line(),
            column: inner.column(),
        }
    })?;
    retag(&mut value)?;
    let file: SceneFile = serde_path_to_error::deserialize(value).map_err(|err| {
        let mut path = json_path(err.path());
        let message = without_position(err.inner());
        if message.starts_with("unknown variant") {
            // The kind was the object's "type" before retagging.
            path.push_str(".type");
        }
        SceneError::Invalid { path, message }
    })?;
    file.validate()
}

fn without_position(err: &serde_json::Error) -> String {
    let text = err.to_string();
    match text.find(" at line ") {
        Some(i) => text[..i].to_owned(),
        None => text,
    }
}

/// The path of a value as the file spells it: variant names, which exist
/// only after [`retag`], are left out.
fn json_path(path: &serde_path_to_error::Path) -> String {
    use serde_path_to_error::Segment;
    let mut out = String::new();
    for segment in path.iter() {
        match segment {
            Segment::Seq { index } => out.push_str(&format!("[{index}]")),
            Segment::Map { key } => {
                if !out.is_empty() {
                    out.push('.');
                }
                out.push_str(key);
            }
            Segment::Enum { .. } | Segment::Unknown => {}
        }
    }
    if out.is_empty() {
        ".".to_owned()
    } else {
        out
    }
}

/// Rewrites each `{"type": "sphere", ...}` as `{"sphere": {...}}`, serde's
/// external tagging. Serde's internally tagged enums buffer their content
/// and lose the path of an error inside it; externally tagged ones keep it.
fn retag(scene: &mut Value) -> Result<(), SceneError> {
    let Some(top) = scene.as_object_mut() else {
        return Ok(()); // serde reports the wrong type with its path
    };
    let mut places: Vec<(String, &mut Value)> = Vec::new();
    for (key, value) in top.iter_mut() {
        match (key.as_str(), value) {
            ("camera", v) => places.push(("camera".into(), v)),
            ("materials", Value::Object(m)) => {
                for (name, v) in m.iter_mut() {
                    places.push((format!("materials.{name}"), v));
                }
            }
            ("objects" | "lights", Value::Array(items)) => {
                for (i, v) in items.iter_mut().enumerate() {
                    places.push((format!("{key}[{i}]"), v));
                }
            }
            _ => {}
        }
    }
    for (path, value) in places {
        let Value::Object(fields) = value else {
            continue; // serde reports the wrong type with its path
        };
        let kind = match fields.remove("type") {
            Some(Value::String(kind)) => kind,
            Some(other) => {
                return Err(SceneError::invalid(
                    format!("{path}.type"),
                    format!("must be a string naming the kind, got {other}"),
                ))
            }
            None => {
                return Err(SceneError::invalid(
                    format!("{path}.type"),
                    "missing: every camera, material, object and light names its \"type\"",
                ))
            }
        };
        let body = Value::Object(std::mem::take(fields));
        *value = Value::Object(serde_json::Map::from_iter([(kind, body)]));
    }
    Ok(())
}

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

fn finite3(path: &str, v: [f64; 3]) -> Result<Vec3, DomainError> {
    for (axis, c) in ["[0]", "[1]", "[2]"].into_iter().zip(v) {
        let name = format!("{path}{axis}");
        domain::finite(&name, c)?;
        within_f32(name, c)?;
    }
    Ok(DVec3::from_array(v).as_vec3())
}

fn non_negative3(path: &str, v: [f64; 3]) -> Result<Vec3, DomainError> {
    for (axis, c) in ["[0]", "[1]", "[2]"].into_iter().zip(v) {
        let name = format!("{path}{axis}");
        domain::non_negative(&name, c)?;
        within_f32(name, c)?;
    }
    Ok(DVec3::from_array(v).as_vec3())
}

fn direction(path: &str, v: [f64; 3]) -> Result<Vec3, SceneError> {
    let d = domain::direction(path, DVec3::from_array(v))?;
    // The unit vector must also survive rounding to f32.
    let unit = d.unit.as_vec3();
    if !(unit.length() > 0.5) {
        return Err(SceneError::invalid(
            path,
            "a direction representable in f32",
        ));
    }
    Ok(unit)
}

fn positive(path: &str, value: f64) -> Result<f32, SceneError> {
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

fn count(path: &str, value: f64, min: u32, max: u32) -> Result<u32, SceneError> {
    domain::finite(path, value)?;
    if value.fract() != 0.0 || value < min as f64 || value > max as f64 {
        return Err(SceneError::invalid(
            path,
            format!("must be a whole number from {min} to {max}, got {value}"),
        ));
    }
    Ok(value as u32)
}

/// Validates the settings a scene or a command line gives.
pub fn validate_settings(path: &str, spec: &RenderSpec) -> Result<(), SceneError> {
    if let Some(spp) = spec.spp {
        count(&format!("{path}.spp"), spp, 1, MAX_SPP)?;
    }
    if let Some(depth) = spec.max_depth {
        count(&format!("{path}.max_depth"), depth, 0, MAX_DEPTH)?;
    }
    if let Some(cutoff) = spec.throughput_cutoff {
        domain::fraction(&format!("{path}.throughput_cutoff"), cutoff)?;
    }
    if let Some(RayOffset::Fixed(eps)) = spec.ray_offset {
        positive(&format!("{path}.ray_offset.fixed"), eps)?;
    }
    Ok(())
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

impl SceneFile {
    /// Checks every value against its domain and builds the [`Scene`].
    pub fn validate(&self) -> Result<Scene, SceneError> {
        if self.version != SCHEMA_VERSION {
            return Err(SceneError::invalid(
                "version",
                format!(
                    "this tracer reads scene version {SCHEMA_VERSION}, got {}",
                    self.version
                ),
            ));
        }
        let width = count("image.width", self.image.width, 1, MAX_IMAGE_SIDE)?;
        let height = count("image.height", self.image.height, 1, MAX_IMAGE_SIDE)?;
        if width as u64 * height as u64 > MAX_PIXELS {
            return Err(SceneError::invalid(
                "image",
                format!("{width} × {height} pixels is more than the {MAX_PIXELS} accepted"),
            ));
        }
        let camera = match self.camera {
            CameraSpec::CoursePinhole {} => Camera::course_pinhole(width, height),
            CameraSpec::LookAt {
                eye,
                target,
                up,
                fov_y_deg,
                near,
                far,
            } => {
                let eye_v = finite3("camera.eye", eye)?;
                let target_v = finite3("camera.target", target)?;
                let forward = direction(
                    "camera.target",
                    [target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]],
                )
                .map_err(|_| SceneError::invalid("camera.target", "must differ from camera.eye"))?;
                let up_v = direction("camera.up", up)?;
                if forward.cross(up_v).length() < 1e-6 {
                    return Err(SceneError::invalid(
                        "camera.up",
                        "must not be parallel to the viewing direction",
                    ));
                }
                domain::finite("camera.fov_y_deg", fov_y_deg)?;
                if !(fov_y_deg > 0.0 && fov_y_deg < 180.0) {
                    return Err(SceneError::invalid(
                        "camera.fov_y_deg",
                        format!("must be in (0, 180) degrees, got {fov_y_deg}"),
                    ));
                }
                positive("camera.near", near)?;
                positive("camera.far", far)?;
                if !(far > near) {
                    return Err(SceneError::invalid(
                        "camera.far",
                        format!("must be beyond camera.near ({near}), got {far}"),
                    ));
                }
                Camera::look_at(
                    LookAtView {
                        eye: eye_v.as_dvec3(),
                        target: target_v.as_dvec3(),
                        up: up_v.as_dvec3(),
                        fov_y: fov_y_deg.to_radians(),
                        near,
                        far,
                    },
                    width,
                    height,
                )
            }
        };
        let background = non_negative3("background", self.background)?;
        let ambient = non_negative3("ambient", self.ambient)?;

        let mut material_names = Vec::new();
        let mut materials = Vec::new();
        for (name, spec) in &self.materials {
            let p = format!("materials.{name}");
            materials.push(validate_material(&p, spec)?);
            material_names.push(name.clone());
        }
        let material_index = |path: &str, name: &str| -> Result<u32, SceneError> {
            material_names
                .iter()
                .position(|m| m == name)
                .map(|i| i as u32)
                .ok_or_else(|| {
                    SceneError::invalid(
                        path,
                        format!(
                            "no material named {name:?}; the scene defines {:?}",
                            material_names
                        ),
                    )
                })
        };

        let mut objects = Vec::new();
        for (i, spec) in self.objects.iter().enumerate() {
            let p = format!("objects[{i}]");
            let object = match spec {
                ObjectSpec::Sphere {
                    center,
                    radius,
                    material,
                } => Object::Sphere(Sphere {
                    center: finite3(&format!("{p}.center"), *center)?,
                    radius: positive(&format!("{p}.radius"), *radius)?,
                    material: material_index(&format!("{p}.material"), material)?,
                }),
                ObjectSpec::Plane {
                    point,
                    normal,
                    material,
                } => {
                    let m = material_index(&format!("{p}.material"), material)?;
                    refuse_dielectric(&p, &materials[m as usize])?;
                    Object::Plane(Plane {
                        point: finite3(&format!("{p}.point"), *point)?,
                        normal: direction(&format!("{p}.normal"), *normal)?,
                        material: m,
                    })
                }
                ObjectSpec::MirrorTube {
                    axis_point,
                    axis,
                    sides,
                    radius,
                    material,
                } => {
                    let m = material_index(&format!("{p}.material"), material)?;
                    refuse_dielectric(&p, &materials[m as usize])?;
                    let sides = count(&format!("{p}.sides"), *sides, 3, 64)?;
                    Object::Tube(Tube::new(
                        finite3(&format!("{p}.axis_point"), *axis_point)?,
                        direction(&format!("{p}.axis"), *axis)?,
                        sides,
                        positive(&format!("{p}.radius"), *radius)?,
                        m,
                    ))
                }
            };
            objects.push(object);
        }

        let mut lights = Vec::new();
        for (i, spec) in self.lights.iter().enumerate() {
            let p = format!("lights[{i}]");
            lights.push(match *spec {
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
            });
        }
        validate_settings("render", &self.render)?;

        Ok(Scene {
            width,
            height,
            camera,
            background,
            ambient,
            materials,
            material_names,
            objects,
            lights,
            render: self.render,
        })
    }
}

fn refuse_dielectric(path: &str, material: &Material) -> Result<(), SceneError> {
    if matches!(material, Material::Dielectric { .. }) {
        return Err(SceneError::invalid(
            format!("{path}.material"),
            "a dielectric needs a closed surface with an inside: only spheres may be dielectric",
        ));
    }
    Ok(())
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
            for (axis, (n, k)) in ["[0]", "[1]", "[2]"]
                .into_iter()
                .zip(n.into_iter().zip(kappa))
            {
                domain::INDEX_RANGE_F32.refractive_index(&format!("{p}.n{axis}"), n)?;
                domain::INDEX_RANGE_F32.extinction(&format!("{p}.kappa{axis}"), k)?;
            }
            Material::Conductor {
                n: n.map(|x| x as f32),
                kappa: kappa.map(|x| x as f32),
            }
        }
        MaterialSpec::Dielectric { eta } => Material::Dielectric {
            eta: domain::INDEX_RANGE_F32.refractive_index(&format!("{p}.eta"), eta)? as f32,
        },
    })
}
