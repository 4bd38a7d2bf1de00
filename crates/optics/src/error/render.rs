//! The errors of `render` and `inspect`, the tracer's, as the command
//! reports them: each kind's stable name. Their fields are the tracer's
//! own (the JSON path of a scene error), or `--output` for an image.

use radiometry::domain::DomainError;
use safe_io::WriteError;
use techniques::bump::FieldError;
use tracer::output::OutputError;
use tracer::scene::ErrorKind as Scene;

/// The name of a scene error's kind: `scene.` and the tracer's kind.
pub fn scene_name(kind: &Scene) -> &'static str {
    match kind {
        Scene::Read { .. } => "scene.read",
        Scene::Syntax { .. } => "scene.syntax",
        Scene::NotUtf8 { .. } => "scene.not_utf8",
        Scene::WrongShape { .. } => "scene.wrong_shape",
        Scene::Schema { .. } => "scene.schema",
        Scene::TypeMissing => "scene.type_missing",
        Scene::TypeNotString { .. } => "scene.type_not_a_string",
        Scene::Version { .. } => "scene.version",
        Scene::NotACount { .. } => "scene.not_a_count",
        Scene::TooManyPixels { .. } => "scene.too_many_pixels",
        Scene::Domain(DomainError::NotFinite { .. }) => "scene.domain.not_finite",
        Scene::Domain(DomainError::OutOfRange { .. }) => "scene.domain.out_of_range",
        Scene::Domain(DomainError::ZeroVector { .. }) => "scene.domain.zero_vector",
        Scene::DirectionUnrepresentable => "scene.direction_unrepresentable",
        Scene::TargetIsEye => "scene.target_is_eye",
        Scene::UpAlongView => "scene.up_along_view",
        Scene::FieldOfView { .. } => "scene.field_of_view",
        Scene::FarNotBeyondNear { .. } => "scene.far_not_beyond_near",
        Scene::UnknownMaterial { .. } => "scene.unknown_material",
        Scene::RadianceOverflow { .. } => "scene.radiance_overflow",
        Scene::LightWithinRounding { .. } => "scene.light_within_rounding",
        Scene::TooExpensive { .. } => "scene.too_expensive",
        Scene::DielectricWithoutInside => "scene.dielectric_without_inside",
        Scene::CourseHasNoRefraction => "scene.course_has_no_refraction",
        Scene::PrecisionNotServed { .. } => "scene.precision_not_served",
        Scene::Bump(FieldError::NotFinite { .. }) => "scene.bump.not_finite",
        Scene::Bump(FieldError::PeriodTooShort { .. }) => "scene.bump.period_too_short",
        Scene::Bump(FieldError::TooSteep { .. }) => "scene.bump.too_steep",
        Scene::BumpOnSmoothSurface => "scene.bump_on_smooth_surface",
        Scene::EnvironmentImage { .. } => "scene.environment_image",
        Scene::BackgroundWithEnvironment => "scene.background_with_environment",
        Scene::SchlickFormUnnamed => "scene.schlick_form_unnamed",
    }
}

/// The name of an image-writing error's kind: `output.` and the kind.
pub fn output_name(error: &OutputError) -> &'static str {
    match error {
        OutputError::Write(WriteError::Io { .. }) => "output.io",
        OutputError::Write(WriteError::NoDirectory { .. }) => "output.no_directory",
        OutputError::Write(WriteError::Unwritable { .. }) => "output.unwritable",
        OutputError::Write(WriteError::NotARegularFile { .. }) => "output.not_a_regular_file",
        OutputError::Write(WriteError::IsAnInput { .. }) => "output.is_an_input",
        OutputError::PfmIsPng { .. } => "output.pfm_is_png",
        OutputError::NotPng { .. } => "output.not_png",
        OutputError::Png { .. } => "output.png",
    }
}
