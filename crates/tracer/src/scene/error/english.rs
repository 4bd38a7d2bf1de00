//! The English text of each [`ErrorKind`]: its `Display`, one arm a kind.

use std::fmt;

use super::kind::ErrorKind;
use crate::kinds::{FresnelModel, IntegratorKind, Precision, MAX_PIXELS, MAX_RAYS, SCHEMA_VERSION};

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
            ErrorKind::RadianceOverflow { bound } => radiance_overflow(f, *bound),
            ErrorKind::LightWithinRounding {
                distance,
                rounding,
                widest,
            } => light_within_rounding(f, *distance, *rounding, *widest),
            ErrorKind::TooExpensive { rays } => too_expensive(f, *rays),
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
            } => precision_not_served(f, *precision, *integrator),
            ErrorKind::Bump(error) => write!(f, "{error}"),
            ErrorKind::BumpOnSmoothSurface => f.write_str(
                "a bump map bends the shading of rough and unlit materials only, \
                 not of a conductor or dielectric",
            ),
            ErrorKind::EnvironmentImage { file, problem } => write!(f, "{file} {problem}"),
            ErrorKind::BackgroundWithEnvironment => f.write_str(
                "the environment replaces the background: give one of background and environment",
            ),
            ErrorKind::SchlickFormUnnamed => schlick_form_unnamed(f),
        }
    }
}

/// The text of [`ErrorKind::SchlickFormUnnamed`].
fn schlick_form_unnamed(f: &mut fmt::Formatter<'_>) -> fmt::Result {
    let [incident, rarer] = FresnelModel::SCHLICK_FORMS;
    write!(
        f,
        "\"schlick\" names neither of Schlick's forms: give \"{incident}\" (the \
         cosine of incidence, as the course writes it; misses total internal \
         reflection) or \"{rarer}\" (the cosine in the rarer medium; total internal \
         reflection right)"
    )
}

/// The text of [`ErrorKind::RadianceOverflow`].
fn radiance_overflow(f: &mut fmt::Formatter<'_>, bound: f64) -> fmt::Result {
    write!(
        f,
        "the scene's numbers together give radiance up to {bound:.3e} W/(sr·m²), \
         beyond f32 ({:.3e}): scale the lights or the coefficients down",
        f32::MAX
    )
}

/// The text of [`ErrorKind::LightWithinRounding`].
fn light_within_rounding(
    f: &mut fmt::Formatter<'_>,
    distance: f64,
    rounding: f64,
    widest: usize,
) -> fmt::Result {
    write!(
        f,
        "a point light {distance:.3e} m from the nearest surface, within the f32 \
         rounding of hit points ({rounding:.3e} m, set by objects[{widest}]'s \
         coordinates): its irradiance has no bound there; move the light away from \
         the surface, or bring objects[{widest}] nearer the origin"
    )
}

/// The text of [`ErrorKind::TooExpensive`].
fn too_expensive(f: &mut fmt::Formatter<'_>, rays: f64) -> fmt::Result {
    write!(
        f,
        "this render may cast up to {rays:.3e} rays, past the {:e} allowed unless an \
         expensive render is allowed: lower max_depth, spp or the size, or raise \
         throughput_cutoff",
        MAX_RAYS
    )
}

/// The text of [`ErrorKind::PrecisionNotServed`].
fn precision_not_served(
    f: &mut fmt::Formatter<'_>,
    precision: Precision,
    integrator: IntegratorKind,
) -> fmt::Result {
    write!(
        f,
        "the {integrator} integrator does not compute in {precision}: \
         precision f64 is for local and whitted; path, photon and course are f32"
    )
}
