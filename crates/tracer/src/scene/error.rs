//! Why a scene file or its settings were refused: a typed [`ErrorKind`]
//! and the JSON path of the field it concerns. The English text is only the
//! [`Display`](std::fmt::Display) of the kind, so that a front end can
//! translate every kind with an exhaustive `match`.

use std::fmt;

use radiometry::domain::DomainError;
use techniques::bump::FieldError;

use crate::kinds::{MAX_PIXELS, MAX_RAYS, SCHEMA_VERSION};

/// A refused scene or setting: what is wrong, and where.
#[derive(Debug)]
pub struct SceneError {
    field: String,
    kind: ErrorKind,
}

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
    /// An image with more than [`MAX_PIXELS`] pixels.
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
    /// [`radiance_bound`](super::bound)), is beyond `f32`.
    RadianceOverflow {
        /// The bound, W/(sr·m²), computed in `f64`.
        bound: f64,
    },
    /// A render whose bound on the rays it casts is past
    /// [`MAX_RAYS`], not allowed by the caller.
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
        precision: crate::kinds::Precision,
        /// The integrator settled beside it.
        integrator: super::IntegratorKind,
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
}

/// Why an environment's image file cannot be its map.
#[derive(Debug)]
pub enum ImageProblem {
    /// The file could not be read: the operating system's reason.
    Read(std::io::Error),
    /// Not a PNG the decoder reads: its description (a bad signature or
    /// checksum, data cut short, a header past the decoder's limits).
    Decode(String),
    /// A PNG whose pixels are not 8-bit RGB or RGBA: the colour type.
    Pixels(String),
    /// A size its map cannot have.
    Size {
        /// Width, pixels.
        width: u32,
        /// Height, pixels.
        height: u32,
        /// What the map needs.
        expected: SizeRule,
    },
}

/// What size an environment image must have.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SizeRule {
    /// A latitude–longitude map: width twice the height (360° by 180°).
    TwiceAsWideAsHigh,
    /// A cube face: square.
    Square,
    /// A cube cross: four faces wide and three high, the faces square.
    FourByThreeFaces,
    /// A cube face after the first: the first face's side, pixels.
    SideOfFirstFace(u32),
    /// Any image: each side at most this many pixels.
    AtMost(u32),
}

impl fmt::Display for ImageProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ImageProblem::Read(source) => write!(f, "cannot be read: {source}"),
            ImageProblem::Decode(message) => {
                write!(f, "is not a PNG that can be decoded: {message}")
            }
            ImageProblem::Pixels(format) => {
                write!(
                    f,
                    "has {format} pixels; an environment is 8-bit RGB or RGBA"
                )
            }
            ImageProblem::Size {
                width,
                height,
                expected,
            } => {
                write!(f, "is {width} × {height} pixels; ")?;
                match expected {
                    SizeRule::TwiceAsWideAsHigh => {
                        f.write_str("a lat-long map is twice as wide as high")
                    }
                    SizeRule::Square => f.write_str("a cube face is square"),
                    SizeRule::FourByThreeFaces => {
                        f.write_str("a cube cross is four square faces wide and three high")
                    }
                    SizeRule::SideOfFirstFace(side) => write!(
                        f,
                        "every cube face has the first face's side, {side} pixels"
                    ),
                    SizeRule::AtMost(side) => write!(f, "each side is at most {side} pixels"),
                }
            }
        }
    }
}

/// The types of JSON values, as the schema and the file have them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JsonType {
    /// `null`.
    Null,
    /// `true` or `false`.
    Bool,
    /// A number.
    Number,
    /// A string (in the schema: the name of one of the choices).
    String,
    /// An array.
    Array,
    /// An object.
    Object,
}

impl JsonType {
    /// The type of `value`.
    pub fn of(value: &serde_json::Value) -> Self {
        use serde_json::Value;
        match value {
            Value::Null => JsonType::Null,
            Value::Bool(_) => JsonType::Bool,
            Value::Number(_) => JsonType::Number,
            Value::String(_) => JsonType::String,
            Value::Array(_) => JsonType::Array,
            Value::Object(_) => JsonType::Object,
        }
    }
}

impl fmt::Display for JsonType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            JsonType::Null => "null",
            JsonType::Bool => "boolean",
            JsonType::Number => "number",
            JsonType::String => "string",
            JsonType::Array => "array",
            JsonType::Object => "object",
        })
    }
}

impl SceneError {
    /// An error of `kind` at the JSON path `field`.
    pub fn new(field: impl Into<String>, kind: ErrorKind) -> Self {
        SceneError {
            field: field.into(),
            kind,
        }
    }

    /// The JSON path of the bad value: `.` for the whole file (a file that
    /// cannot be read, text that is not one JSON value, JSON that breaks
    /// off before a value could be named); settings given beside the file
    /// are under `overrides`. A field the schema does not have (an unknown
    /// field, or a syntax error in its value) is named as the file spells it.
    pub fn field(&self) -> &str {
        &self.field
    }

    /// What is wrong.
    pub fn kind(&self) -> &ErrorKind {
        &self.kind
    }
}

impl From<DomainError> for SceneError {
    fn from(error: DomainError) -> Self {
        let field = match &error {
            DomainError::NotFinite { name, .. }
            | DomainError::OutOfRange { name, .. }
            | DomainError::ZeroVector { name, .. } => name.clone(),
        };
        SceneError::new(field, ErrorKind::Domain(error))
    }
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.kind {
            // These name their subject themselves.
            ErrorKind::Read { .. } | ErrorKind::Domain(_) => write!(f, "{}", self.kind),
            // The whole file is the file the caller names.
            kind if self.field == "." => write!(f, "{kind}"),
            kind => write!(f, "{}: {kind}", self.field),
        }
    }
}

impl fmt::Display for ErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            // The file is named by whoever names the scene; the kind keeps it.
            ErrorKind::Read { source, .. } => write!(f, "cannot be read: {source}"),
            ErrorKind::Syntax {
                message,
                line,
                column,
            } => write!(f, "{message} (line {line}, column {column})"),
            ErrorKind::NotUtf8 { line, column } => write!(
                f,
                "not UTF-8 text: a byte that is not UTF-8 at line {line}, column {column}"
            ),
            ErrorKind::WrongShape { expected, got } => {
                write!(f, "must be a JSON {expected}, got a JSON {got}")
            }
            ErrorKind::Schema { message } => f.write_str(message),
            ErrorKind::TypeMissing => f.write_str(
                "missing: every camera, material, object and light names its \"type\"",
            ),
            ErrorKind::TypeNotString { got } => {
                write!(f, "must be a string naming the kind, got {got}")
            }
            ErrorKind::Version { got } => write!(
                f,
                "this tracer reads scene version {SCHEMA_VERSION}, got {got}"
            ),
            ErrorKind::NotACount { value, min, max } => {
                write!(f, "must be a whole number from {min} to {max}, got {value}")
            }
            ErrorKind::TooManyPixels { width, height } => write!(
                f,
                "{width} × {height} pixels is more than the {MAX_PIXELS} accepted"
            ),
            ErrorKind::Domain(error) => write!(f, "{error}"),
            ErrorKind::DirectionUnrepresentable => f.write_str("a direction representable in f32"),
            ErrorKind::TargetIsEye => f.write_str("must differ from camera.eye"),
            ErrorKind::UpAlongView => f.write_str("must not be parallel to the viewing direction"),
            ErrorKind::FieldOfView { degrees } => {
                write!(f, "must be in (0, 180) degrees, got {degrees}")
            }
            ErrorKind::FarNotBeyondNear { near, far } => {
                write!(f, "must be beyond camera.near ({near}), got {far}")
            }
            ErrorKind::UnknownMaterial { name, defined } => write!(
                f,
                "no material named {name:?}; the scene defines {defined:?}"
            ),
            ErrorKind::RadianceOverflow { bound } => write!(
                f,
                "the scene's numbers together give radiance up to {bound:.3e} W/(sr·m²), \
                 beyond f32 ({:.3e}): scale the lights or the coefficients down",
                f32::MAX
            ),
            ErrorKind::TooExpensive { rays } => write!(
                f,
                "this render may cast up to {rays:.3e} rays, past the {:e} allowed unless an \
                 expensive render is allowed: lower max_depth, spp or the size, or raise \
                 throughput_cutoff",
                MAX_RAYS
            ),
            ErrorKind::DielectricWithoutInside => f.write_str(
                "a dielectric needs a closed surface with an inside: only spheres may be dielectric",
            ),
            ErrorKind::CourseHasNoRefraction => f.write_str(
                "the course's shader has no refraction: dielectrics are rendered by the \
                 integrators whitted and path",
            ),
            ErrorKind::PrecisionNotServed {
                precision,
                integrator,
            } => write!(
                f,
                "the {integrator} integrator does not compute in {precision}: \
                 precision f64 is for local and whitted; path, photon and course are f32"
            ),
            ErrorKind::Bump(error) => write!(f, "{error}"),
            ErrorKind::BumpOnSmoothSurface => f.write_str(
                "a bump map bends the shading of rough and unlit materials only, \
                 not of a conductor or dielectric",
            ),
            ErrorKind::EnvironmentImage { file, problem } => write!(f, "{file} {problem}"),
            ErrorKind::BackgroundWithEnvironment => f.write_str(
                "the environment replaces the background: give one of background and environment",
            ),
        }
    }
}

// No `source`: the operating system's reason is part of the message, and
// a reporter that also printed the chain would print it twice.
impl std::error::Error for SceneError {}
