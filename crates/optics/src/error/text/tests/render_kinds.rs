//! One example of every kind of the tracer's errors: a scene refused, an
//! image not written, the render's threads not started.

use super::{named, os_error};
use crate::error::ErrorKind;
use radiometry::domain::{DomainError, Expected};
use safe_io::WriteError;
use techniques::bump::{FieldError, Parameter};
use tracer::output::OutputError;
use tracer::scene::{ErrorKind as Scene, SceneError};

/// The place of a scene error's kind among the render slots.
pub fn scene_slot(kind: &Scene) -> usize {
    match kind {
        Scene::Read { .. } => 0,
        Scene::Syntax { .. } => 1,
        Scene::Schema { .. } => 2,
        Scene::TypeMissing => 3,
        Scene::TypeNotString { .. } => 4,
        Scene::Version { .. } => 5,
        Scene::NotACount { .. } => 6,
        Scene::TooManyPixels { .. } => 7,
        Scene::Domain(DomainError::NotFinite { .. }) => 8,
        Scene::Domain(DomainError::OutOfRange { .. }) => 9,
        Scene::Domain(DomainError::ZeroVector { .. }) => 10,
        Scene::DirectionUnrepresentable => 11,
        Scene::TargetIsEye => 12,
        Scene::UpAlongView => 13,
        Scene::FieldOfView { .. } => 14,
        Scene::FarNotBeyondNear { .. } => 15,
        Scene::UnknownMaterial { .. } => 16,
        Scene::DielectricWithoutInside => 17,
        Scene::CourseHasNoRefraction => 18,
        Scene::NotUtf8 { .. } => 19,
        Scene::WrongShape { .. } => 20,
        Scene::RadianceOverflow { .. } => 21,
        Scene::LightWithinRounding { .. } => 41,
        Scene::TooExpensive { .. } => 22,
        Scene::Bump(FieldError::NotFinite { .. }) => 23,
        Scene::Bump(FieldError::PeriodTooShort { .. }) => 24,
        Scene::Bump(FieldError::TooSteep { .. }) => 25,
        Scene::BumpOnSmoothSurface => 26,
        Scene::EnvironmentImage { .. } => 36,
        Scene::BackgroundWithEnvironment => 37,
        Scene::PrecisionNotServed { .. } => 38,
        Scene::SchlickFormUnnamed => 40,
    }
}

/// The place of an output error's kind among the render slots.
pub fn output_slot(error: &OutputError) -> usize {
    match error {
        OutputError::Write(WriteError::Io { .. }) => 27,
        OutputError::Write(WriteError::NoDirectory { .. }) => 28,
        OutputError::PfmIsPng { .. } => 29,
        OutputError::NotPng { .. } => 39,
        OutputError::Png { .. } => 30,
        OutputError::Write(WriteError::Unwritable { .. }) => 31,
        OutputError::Write(WriteError::NotARegularFile { .. }) => 32,
        OutputError::Write(WriteError::IsAnInput { .. }) => 33,
    }
}

/// The slot of the threads' failure.
pub const THREADS: usize = 34;

/// The slot of a pixel that left `f32`.
pub const NOT_FINITE: usize = 35;

/// How many render slots there are.
pub const SLOTS: usize = 42;

/// A thread pool that cannot start: its spawner fails.
pub fn thread_pool_error() -> rayon::ThreadPoolBuildError {
    match rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .spawn_handler(|_| Err(os_error()))
        .build()
    {
        Err(error) => error,
        Ok(_) => panic!("a pool whose threads cannot spawn was built"),
    }
}

fn scene(field: &str, kind: Scene, quoted: &[&str]) -> (ErrorKind, Vec<String>) {
    // The whole file's field, `.`, is not shown: the message names the file.
    let mut quoted = named(quoted);
    quoted.extend(named(&["a.json", field]).into_iter().filter(|q| q != "."));
    let error = SceneError::new(field, kind);
    let file = "a.json".into();
    (ErrorKind::Scene { file, error }, quoted)
}

fn domain(error: DomainError) -> (ErrorKind, Vec<String>) {
    let error = SceneError::from(error);
    let quoted = named(&["a.json", error.field()]);
    let file = "a.json".into();
    (ErrorKind::Scene { file, error }, quoted)
}

fn output(error: OutputError, quoted: &[&str]) -> (ErrorKind, Vec<String>) {
    let mut quoted = named(quoted);
    quoted.push("--output".to_owned());
    (ErrorKind::Output(error), quoted)
}

/// One example of each kind, with the text it quotes verbatim.
pub fn examples() -> Vec<(ErrorKind, Vec<String>)> {
    let os = os_error().to_string();
    let serde = "unknown field `zoom`, expected one of `eye`, `target`";
    let png = || image::ImageError::IoError(os_error());
    let threads = thread_pool_error();
    let threads_text = threads.to_string();
    vec![
        scene(
            ".",
            Scene::Read {
                file: "a.json".into(),
                source: os_error(),
            },
            &[&os],
        ),
        scene(
            "?",
            Scene::Syntax {
                message: "EOF while parsing an object".into(),
                line: 1,
                column: 14,
            },
            &["EOF while parsing an object"],
        ),
        scene(
            "camera.zoom",
            Scene::Schema {
                message: serde.into(),
            },
            &[serde],
        ),
        scene("objects[0]", Scene::TypeMissing, &["\"type\""]),
        scene(
            "objects[0].type",
            Scene::TypeNotString { got: "3".into() },
            &[],
        ),
        scene("version", Scene::Version { got: 2 }, &[]),
        scene(
            "render.spp",
            Scene::NotACount {
                value: 0.5,
                min: 1,
                max: 65536,
            },
            &[],
        ),
        scene(
            "image",
            Scene::TooManyPixels {
                width: 16384,
                height: 16384,
            },
            &[],
        ),
        domain(DomainError::NotFinite {
            name: "lights[0].towards".into(),
            value: f64::NAN,
        }),
        domain(DomainError::OutOfRange {
            name: "objects[0].radius".into(),
            value: -1.0,
            expected: Expected::PositiveF32,
        }),
        domain(DomainError::ZeroVector {
            name: "lights[0].towards".into(),
            x: 0.0,
            y: 0.0,
            z: 0.0,
        }),
        scene("camera.up", Scene::DirectionUnrepresentable, &[]),
        scene("camera.target", Scene::TargetIsEye, &["camera.eye"]),
        scene("camera.up", Scene::UpAlongView, &[]),
        scene(
            "camera.fov_y_deg",
            Scene::FieldOfView { degrees: 190.0 },
            &[],
        ),
        scene(
            "camera.far",
            Scene::FarNotBeyondNear {
                near: 1.0,
                far: 0.5,
            },
            &["camera.near"],
        ),
        scene(
            "objects[1].material",
            Scene::UnknownMaterial {
                name: "gold".into(),
                defined: vec!["glass".into()],
            },
            &["gold", "glass"],
        ),
        scene("objects[2].material", Scene::DielectricWithoutInside, &[]),
        scene(
            "environment.faces[1]",
            Scene::EnvironmentImage {
                file: "sky/nx.png".into(),
                problem: tracer::scene::error::ImageProblem::Size {
                    width: 64,
                    height: 32,
                    expected: tracer::scene::error::SizeRule::SideOfFirstFace(32),
                },
            },
            &["sky/nx.png"],
        ),
        scene(
            "background",
            Scene::BackgroundWithEnvironment,
            &["environment"],
        ),
        scene(
            "materials.glass",
            Scene::CourseHasNoRefraction,
            // The flag, the commands that take it and the scene field are
            // names, the same in both languages.
            &[
                "--integrator",
                "render.integrator",
                "render",
                "inspect",
                "compare",
                "whitted",
                "path",
            ],
        ),
        scene(
            "render.fresnel",
            Scene::SchlickFormUnnamed,
            // The longer names first: each is taken out before the next.
            &["schlick-incident", "schlick-rarer", "schlick"],
        ),
        scene(
            "overrides.precision",
            Scene::PrecisionNotServed {
                precision: tracer::scene::Precision::F64,
                integrator: tracer::scene::IntegratorKind::Path,
            },
            &["path", "f64", "local", "whitted", "photon", "course", "f32"],
        ),
        scene(
            "objects[0].bump.du",
            Scene::Bump(FieldError::NotFinite {
                parameter: Parameter::Du,
                value: f64::INFINITY,
            }),
            &[],
        ),
        scene(
            "objects[0].bump.period",
            Scene::Bump(FieldError::PeriodTooShort { period: 0.001 }),
            &["0.001"],
        ),
        scene(
            "objects[0].bump.amplitude",
            Scene::Bump(FieldError::TooSteep {
                parameter: Parameter::Amplitude,
                slope: 6.283e7,
            }),
            &["6.283e7"],
        ),
        scene("objects[0].bump", Scene::BumpOnSmoothSurface, &[]),
        output(
            OutputError::Write(WriteError::Io {
                path: "out/a.png".into(),
                source: os_error(),
            }),
            &["out/a.png", &os],
        ),
        output(
            OutputError::Write(WriteError::NoDirectory {
                path: "nowhere/a.png".into(),
                dir: "nowhere".into(),
            }),
            &["nowhere/a.png", "nowhere"],
        ),
        output(
            OutputError::Write(WriteError::Unwritable {
                dir: "/sys".into(),
                source: os_error(),
            }),
            &["/sys", &os],
        ),
        output(
            OutputError::Write(WriteError::NotARegularFile {
                path: "/dev/null".into(),
            }),
            &["/dev/null"],
        ),
        output(
            OutputError::Write(WriteError::IsAnInput {
                path: "./scene.json".into(),
                input: "scene.json".into(),
            }),
            &["./scene.json", "scene.json"],
        ),
        output(
            OutputError::PfmIsPng {
                path: "a.pfm".into(),
            },
            &["a.pfm"],
        ),
        output(
            OutputError::NotPng {
                path: "a.jpg".into(),
            },
            &["a.jpg", ".png", "PNG", "PFM"],
        ),
        output(
            OutputError::Png {
                path: "a.png".into(),
                source: png(),
            },
            &["a.png", &png().to_string()],
        ),
        (ErrorKind::Threads(threads), vec![threads_text]),
        scene(".", Scene::NotUtf8 { line: 3, column: 7 }, &[]),
        scene(
            "image",
            Scene::WrongShape {
                expected: tracer::scene::error::JsonType::Object,
                got: tracer::scene::error::JsonType::Array,
            },
            &[],
        ),
        scene(
            "materials.red",
            Scene::RadianceOverflow { bound: 1e40 },
            &[],
        ),
        scene(
            "lights[0]",
            Scene::LightWithinRounding {
                distance: 1.2,
                rounding: 9.5e12,
                widest: 3,
            },
            &[],
        ),
        scene(
            ".",
            Scene::TooExpensive { rays: 1e13 },
            &[
                "--allow-expensive",
                "max_depth",
                "throughput_cutoff",
                "optics render",
                "inspect",
            ],
        ),
        (ErrorKind::RadianceNotFinite { x: 3, y: 4 }, vec![]),
    ]
}
