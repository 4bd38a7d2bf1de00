//! What is wrong with a scene file or a render setting, as a type.

use radiometry::domain::DomainError;
use techniques::bump::FieldError;

use super::image::ImageProblem;
use super::json_type::JsonType;
#[cfg(doc)]
use crate::kinds::FresnelModel;
use crate::kinds::{IntegratorKind, Precision};

/// What is wrong with a scene file or a render setting. Every message the
/// tracer writes about its input is one of these.
#[derive(Debug)]
pub enum ErrorKind {
    /// The file could not be read.
    Read {
        /// The file as given.
        file: String,
        /// The operating system's reason.
        source: std::io::Error,
    },
    /// Not JSON: serde_json's description and where in the text.
    Syntax {
        /// serde_json's description, without its position.
        message: String,
        /// Line of the error, from 1.
        line: usize,
        /// Column of the error, from 1.
        column: usize,
    },
    /// Bytes that are not UTF-8 text (JSON is UTF-8, RFC 8259 §8.1): where
    /// the first bad byte is.
    NotUtf8 {
        /// Line of the bad byte, from 1.
        line: usize,
        /// Column of the bad byte, from 1, counted in characters.
        column: usize,
    },
    /// JSON of one type where the schema has another: an object given as an
    /// array, a choice given as an object.
    WrongShape {
        /// What the schema has there.
        expected: JsonType,
        /// What the file has there.
        got: JsonType,
    },
    /// JSON, but not the schema: a wrong type, an unknown or missing field,
    /// an unknown kind (serde's description).
    Schema {
        /// serde's description.
        message: String,
    },
    /// A camera, material, object or light without its `"type"`.
    TypeMissing,
    /// A `"type"` that is not a string.
    TypeNotString {
        /// The value given, as JSON.
        got: String,
    },
    /// A schema version this tracer does not read.
    Version {
        /// The version given.
        got: u32,
    },
    /// A count (pixels, samples, sides, depth) that is not a whole number
    /// within its bounds.
    NotACount {
        /// The value given.
        value: f64,
        /// The least accepted.
        min: u32,
        /// The most accepted.
        max: u32,
    },
    /// An image with more than [`MAX_PIXELS`](crate::kinds::MAX_PIXELS) pixels.
    TooManyPixels {
        /// Width, pixels.
        width: u32,
        /// Height, pixels.
        height: u32,
    },
    /// A number outside its domain (radiometry's own kinds; the error names
    /// the field itself).
    Domain(DomainError),
    /// A direction whose unit vector does not survive rounding to `f32`.
    DirectionUnrepresentable,
    /// A look-at camera whose target is its eye.
    TargetIsEye,
    /// A look-at camera whose up direction is along its view.
    UpAlongView,
    /// A field of view outside (0, 180) degrees.
    FieldOfView {
        /// The value given, degrees.
        degrees: f64,
    },
    /// A far plane not beyond the near plane.
    FarNotBeyondNear {
        /// The near plane, m.
        near: f64,
        /// The far plane, m.
        far: f64,
    },
    /// An object naming a material the scene does not define.
    UnknownMaterial {
        /// The name given.
        name: String,
        /// The names the scene defines.
        defined: Vec<String>,
    },
    /// Numbers each within `f32` whose product is not: the largest radiance
    /// a surface can send, bounded from the scene's numbers (see
    /// [`radiance_bound`](crate::scene::bound)), is beyond `f32`.
    RadianceOverflow {
        /// The bound, W/(sr·m²), computed in `f64`.
        bound: f64,
    },
    /// A point light within the rounding of a surface's hit points, so
    /// that the irradiance it gives there has no bound in `f32`: the
    /// surface's coordinates, far from the origin, may be the cause.
    LightWithinRounding {
        /// From the light to the nearest surface, m.
        distance: f64,
        /// How far hit points are rounded at the scene's extent, m.
        rounding: f64,
        /// The index of the object whose coordinates set that extent.
        widest: usize,
    },
    /// A render whose bound on the rays it casts is past
    /// [`MAX_RAYS`](crate::kinds::MAX_RAYS), not allowed by the caller.
    TooExpensive {
        /// The bound on the rays cast.
        rays: f64,
    },
    /// A dielectric on a surface without an inside (a plane, the tube).
    DielectricWithoutInside,
    /// A dielectric under the course's shader, which has no refraction.
    CourseHasNoRefraction,
    /// A precision tier the integrator does not compute in (`f64` beyond
    /// `local` and `whitted`).
    PrecisionNotServed {
        /// The tier asked for.
        precision: Precision,
        /// The integrator settled beside it.
        integrator: IntegratorKind,
    },
    /// A bump map's parameter outside its domain (`techniques::bump`'s
    /// own kinds; the error names the parameter's field).
    Bump(FieldError),
    /// A bump map on a mirror or glass, whose lobes follow the geometric
    /// normal here.
    BumpOnSmoothSurface,
    /// An environment's image file that cannot be its map: the file as
    /// the scene names it (joined to the scene's directory), and why.
    EnvironmentImage {
        /// The file.
        file: String,
        /// What is wrong with it.
        problem: ImageProblem,
    },
    /// A `background` given beside an `environment`, which replaces it.
    BackgroundWithEnvironment,
    /// A Fresnel law named by the bare `schlick`, which names neither of
    /// Schlick's forms ([`FresnelModel::SCHLICK_FORMS`]).
    SchlickFormUnnamed,
}
