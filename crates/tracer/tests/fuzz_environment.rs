//! The fuzz target of environment images: PNGs of hostile sizes (a side
//! of 1, past 8192, neither square nor twice as wide as high, cube faces
//! of several sides) and pixel formats (grey, 16-bit, with alpha), then
//! mutated byte by byte (overwritten, inserted, deleted, truncated), named
//! by a lat-long, cube or cube-cross environment, read through
//! `scene::parse_bytes_in` and, when accepted, rendered at 16 × 12 under a
//! mirror sphere that reflects nearly every direction. The promises checked on every case:
//!
//! - no panic;
//! - a refusal names the field that gave the file (`environment.image`,
//!   `environment.faces[k]`) and is an [`ErrorKind::EnvironmentImage`];
//! - an accepted scene renders finite.
//!
//! `OPTICS_FUZZ_CASES` sets the number of cases (default 256). The
//! test-only fault `EnvironmentSizeUnchecked` (`scene::faults`) accepts
//! images of any size, and the target must then fail.

use std::collections::BTreeMap;
use std::path::Path;
use std::sync::Mutex;

use image::ImageEncoder;
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestError, TestRng, TestRunner};
use serde_json::json;
use tracer::job::{Overrides, RenderJob};
use tracer::scene::error::ImageProblem;
use tracer::scene::faults::{self, Fault};
use tracer::scene::{self, ErrorKind, IntegratorKind, RenderSpec};

/// What the cases reached: each problem (and size rule), and how many
/// scenes were accepted and rendered.
type Coverage = Mutex<BTreeMap<String, usize>>;

fn reached(coverage: &Coverage, what: String) {
    *coverage.lock().unwrap().entry(what).or_default() += 1;
}

/// The sizes a hostile file has.
const SIZES: [(u32, u32); 13] = [
    (1, 1),
    (2, 1),
    (2, 2),
    (3, 3),
    (4, 4),
    (8, 4),
    (3, 7),
    (16, 8),
    (4, 3),
    (8, 6),
    (12, 8),
    (8193, 1),
    (1, 8193),
];

/// One image: its size (an index into [`SIZES`]), its pixel format and
/// its byte mutations.
#[derive(Clone, Debug)]
struct Picture {
    size: usize,
    format: Format,
    mutations: Vec<Mutation>,
}

#[derive(Clone, Copy, Debug)]
enum Format {
    Rgb8,
    Rgba8,
    L8,
    Rgb16,
}

#[derive(Clone, Debug)]
enum Mutation {
    Overwrite(usize, u8),
    Insert(usize, u8),
    Delete(usize),
    Truncate(usize),
}

/// What a case's pictures are.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Map {
    /// One lat-long picture.
    LatLong,
    /// Six cube faces.
    Cube,
    /// One cube cross.
    Cross,
}

/// A case: the map and its pictures.
type Case = (Map, Vec<Picture>);

fn picture(mutated: bool) -> impl Strategy<Value = Picture> {
    let format = prop_oneof![
        6 => Just(Format::Rgb8),
        2 => Just(Format::Rgba8),
        1 => Just(Format::L8),
        1 => Just(Format::Rgb16),
    ];
    let mutation = prop_oneof![
        (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Mutation::Overwrite(i, b)),
        (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Mutation::Insert(i, b)),
        any::<usize>().prop_map(Mutation::Delete),
        any::<usize>().prop_map(Mutation::Truncate),
    ];
    let count = if mutated { 0..3usize } else { 0..1usize };
    (
        0..SIZES.len(),
        format,
        prop::collection::vec(mutation, count),
    )
        .prop_map(|(size, format, mutations)| Picture {
            size,
            format,
            mutations,
        })
}

/// A lat-long picture or a cross, or six faces: most often one good face
/// repeated, some replaced by pictures of their own.
fn case() -> impl Strategy<Value = Case> {
    let lat_long = picture(true).prop_map(|p| (Map::LatLong, vec![p]));
    let cross = picture(true).prop_map(|p| (Map::Cross, vec![p]));
    let good_face = (prop::sample::select(vec![2usize, 3, 4]), Just(Format::Rgb8)).prop_map(
        |(size, format)| Picture {
            size,
            format,
            mutations: Vec::new(),
        },
    );
    let cube = (
        good_face,
        prop::collection::vec(prop::option::weighted(0.25, picture(true)), 6),
    )
        .prop_map(|(good, own)| {
            let faces = own.into_iter().map(|p| p.unwrap_or(good.clone())).collect();
            (Map::Cube, faces)
        });
    prop_oneof![lat_long, cube, cross]
}

/// The bytes of `p`: encoded at its size and format, then mutated.
fn bytes_of(p: &Picture) -> Vec<u8> {
    let (w, h) = SIZES[p.size];
    let (colour, per_pixel) = match p.format {
        Format::Rgb8 => (image::ExtendedColorType::Rgb8, 3),
        Format::Rgba8 => (image::ExtendedColorType::Rgba8, 4),
        Format::L8 => (image::ExtendedColorType::L8, 1),
        Format::Rgb16 => (image::ExtendedColorType::Rgb16, 6),
    };
    let data: Vec<u8> = (0..(w * h) as usize * per_pixel)
        .map(|k| (k * 37 % 256) as u8)
        .collect();
    let mut bytes = Vec::new();
    image::codecs::png::PngEncoder::new(&mut bytes)
        .write_image(&data, w, h, colour)
        .expect("a seed PNG encodes");
    let at = |i: usize, len: usize| i % len.max(1);
    for m in &p.mutations {
        match *m {
            Mutation::Overwrite(i, b) if !bytes.is_empty() => {
                let i = at(i, bytes.len());
                bytes[i] = b;
            }
            Mutation::Insert(i, b) => bytes.insert(at(i, bytes.len() + 1), b),
            Mutation::Delete(i) if !bytes.is_empty() => {
                bytes.remove(at(i, bytes.len()));
            }
            Mutation::Truncate(i) => bytes.truncate(at(i, bytes.len() + 1)),
            _ => {}
        }
    }
    bytes
}

/// The scene of a case, its pictures written into `dir`.
fn scene_file(case: &Case, dir: &Path) -> Vec<u8> {
    let (map, pictures) = case;
    let mut names = Vec::new();
    for (k, p) in pictures.iter().enumerate() {
        let name = format!("{k}.png");
        std::fs::write(dir.join(&name), bytes_of(p)).unwrap();
        names.push(name);
    }
    let environment = match map {
        Map::LatLong => json!({ "type": "lat_long", "image": names[0] }),
        Map::Cross => json!({ "type": "cube_cross", "image": names[0] }),
        Map::Cube => json!({ "type": "cube", "faces": names }),
    };
    json!({
        "version": 1, "image": { "width": 16, "height": 12 },
        "camera": { "type": "course_pinhole" },
        "materials": { "mirror": { "type": "conductor", "n": [0.2, 0.2, 0.2], "kappa": [3, 3, 3] } },
        "objects": [ { "type": "sphere", "center": [0, 0, 2], "radius": 1.6, "material": "mirror" } ],
        "environment": environment
    })
    .to_string()
    .into_bytes()
}

fn check(case: &Case, coverage: &Coverage) -> Result<(), TestCaseError> {
    let dir = tempfile::tempdir().unwrap();
    let file = scene_file(case, dir.path());
    let scene = match scene::parse_bytes_in(&file, dir.path()) {
        Err(error) => {
            let field = error.field();
            let named = field == "environment.image"
                || (0..6).any(|k| field == format!("environment.faces[{k}]"));
            prop_assert!(named, "{error:?} names {field:?}");
            let ErrorKind::EnvironmentImage { problem, .. } = error.kind() else {
                return Err(TestCaseError::fail(format!("{error:?}")));
            };
            let what = match problem {
                ImageProblem::Read(_) => "read".to_owned(),
                ImageProblem::Decode(_) => "decode".to_owned(),
                ImageProblem::Pixels(_) => "pixels".to_owned(),
                ImageProblem::Size { expected, .. } => format!("size {expected:?}"),
            };
            reached(coverage, what);
            return Ok(());
        }
        Ok(scene) => scene,
    };
    for integrator in [IntegratorKind::Whitted, IntegratorKind::Path] {
        let overrides = Overrides {
            render: RenderSpec {
                integrator: Some(integrator),
                spp: Some(2.0),
                ..RenderSpec::default()
            },
            ..Overrides::default()
        };
        let job = RenderJob::new(scene.clone(), &overrides).expect("renderable");
        let image = job.render(Some(1), &|_| {}).expect("rendered").image;
        prop_assert!(image.pixels.iter().all(|p| p.is_finite()), "not finite");
    }
    reached(coverage, "accepted and rendered".to_owned());
    Ok(())
}

fn cases() -> u32 {
    std::env::var("OPTICS_FUZZ_CASES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(256)
}

fn run(cases: u32, coverage: &Coverage) -> Result<(), TestError<Case>> {
    let config = Config {
        cases,
        failure_persistence: None,
        max_shrink_iters: 64,
        ..Config::default()
    };
    let rng = TestRng::deterministic_rng(RngAlgorithm::ChaCha);
    TestRunner::new_with_rng(config, rng).run(&case(), |case| check(&case, coverage))
}

#[test]
fn hostile_environment_images_keep_the_readers_promises() {
    let coverage = Coverage::default();
    if let Err(error) = run(cases(), &coverage) {
        panic!("{error}");
    }
    let reached = coverage.into_inner().unwrap();
    println!("environment fuzz: {} cases, reached {reached:?}", cases());
    // Every refusal a hostile file can earn (a file always exists here,
    // so never `read`), and acceptances rendered.
    for what in [
        "decode",
        "pixels",
        "size AtMost(8192)",
        "size TwiceAsWideAsHigh",
        "size Square",
        "size FourByThreeFaces",
        "accepted and rendered",
    ] {
        assert!(reached.contains_key(what), "a timid generator: {reached:?}");
    }
}

/// With the size checks undone, a cube whose faces differ in side is read
/// by its first face's side, and a lookup on a smaller face runs past its
/// texels: the target finds the panic.
#[test]
fn the_fuzz_target_finds_environment_sizes_unchecked() {
    let coverage = Coverage::default();
    let found = faults::with(Fault::EnvironmentSizeUnchecked, || run(cases(), &coverage));
    match found {
        Err(TestError::Fail(reason, case)) => {
            assert!(reason.message().contains("index out of bounds"), "{reason}");
            println!("EnvironmentSizeUnchecked found: {reason} ({case:?})");
        }
        other => panic!("EnvironmentSizeUnchecked not found: {other:?}"),
    }
}
