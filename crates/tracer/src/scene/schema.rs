//! The scene file as written (schema version 1, `docs/scene-schema.md`),
//! before validation. Numbers are `f64` here so that a value is reported
//! exactly as it was given; [`SceneFile::validate`] turns it into a
//! [`Scene`](super::Scene).

use std::collections::BTreeMap;

use serde::Deserialize;

use super::settings::RenderSpec;

/// A scene file as written, before validation.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
    /// Must be [`SCHEMA_VERSION`](super::SCHEMA_VERSION).
    pub version: u32,
    /// The image size.
    pub image: ImageSpec,
    /// How primary rays are made.
    pub camera: CameraSpec,
    /// Radiance of rays that leave the scene, W/(sr·m²) per channel
    /// (black when not given; not given with an `environment`).
    #[serde(default)]
    pub background: Option<[f64; 3]>,
    /// What rays that leave the scene receive, by direction: replaces
    /// `background`.
    #[serde(default)]
    pub environment: Option<EnvironmentSpec>,
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
    /// Width, 1 to [`MAX_IMAGE_SIDE`](crate::kinds::MAX_IMAGE_SIDE).
    pub width: f64,
    /// Height, 1 to [`MAX_IMAGE_SIDE`](crate::kinds::MAX_IMAGE_SIDE).
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
        /// A bump map over the sphere's `(φ / 2π, θ / π)`: it bends the
        /// shading normal only.
        #[serde(default)]
        bump: Option<BumpSpec>,
    },
    /// An infinite plane, visible and reflective from both sides.
    Plane {
        /// A point on the plane, m.
        point: [f64; 3],
        /// The normal (any length): the side called "outside".
        normal: [f64; 3],
        /// Material name.
        material: String,
        /// A bump map over the plane's `(u, v)`, metres along its tangents:
        /// it bends the shading normal only.
        #[serde(default)]
        bump: Option<BumpSpec>,
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

/// A bump map's height field, as written (`techniques::bump::HeightField`):
/// heights in metres over the object's `(u, v)`.
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum BumpSpec {
    /// No height: the object as it is.
    Flat {},
    /// `h = du · u + dv · v`: a constant tilt.
    Slope {
        /// `∂h/∂u`, m per unit of `u`, `|du| ≤ 1e6`.
        du: f64,
        /// `∂h/∂v`, m per unit of `v`, `|dv| ≤ 1e6`.
        dv: f64,
    },
    /// `h = amplitude · sin(2π u / period) · sin(2π v / period)`.
    Sine {
        /// Height of a bump, m.
        amplitude: f64,
        /// Period in `u` and `v`, at least 1/256; `2π |amplitude| / period
        /// ≤ 1e6`.
        period: f64,
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

/// An environment, as written: what rays that leave the scene receive, by
/// direction (`crate::environment`). Image files are PNG, 8-bit RGB or
/// RGBA (alpha ignored), sRGB-encoded, named relative to the scene file's
/// directory.
#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum EnvironmentSpec {
    /// `scale · (d + 1) / 2` along the unit direction `d`: procedural.
    DirectionColour {
        /// Multiplies the colour, ≥ 0 (default 1).
        scale: Option<f64>,
    },
    /// A latitude–longitude image, twice as wide as high.
    LatLong {
        /// The PNG file.
        image: String,
        /// Multiplies every texel's linear value, ≥ 0 (default 1).
        scale: Option<f64>,
    },
    /// A cube map in one PNG: the horizontal cross, four faces wide and
    /// three high (see `crate::environment::CROSS`).
    CubeCross {
        /// The PNG file.
        image: String,
        /// Multiplies every texel's linear value, ≥ 0 (default 1).
        scale: Option<f64>,
    },
    /// A cube map: six square PNGs of one side.
    Cube {
        /// The faces' files in OpenGL's order: `+X, −X, +Y, −Y, +Z, −Z`.
        faces: [String; 6],
        /// Multiplies every texel's linear value, ≥ 0 (default 1).
        scale: Option<f64>,
    },
}
