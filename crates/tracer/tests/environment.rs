//! The environment (`tracer::environment`): what escaping rays receive,
//! read from the scene, looked up through `techniques::envmap`, reflected
//! by mirrors; and unchanged renders where a scene has none.

mod common;

use std::path::Path;

use common::{parse, radiance_along, LAW_INTEGRATORS};
use glam::Vec3;
use image::ImageEncoder;
use serde_json::{json, Value};
use techniques::envmap::cube::{CubeTexel, Face};
use techniques::envmap::lat_long::LatLong;
use tracer::capture::capture_cube;
use tracer::environment::Environment;
use tracer::geometry::Ray;
use tracer::job::{Overrides, RenderJob};
use tracer::scene::error::{ImageProblem, SizeRule};
use tracer::scene::{self, ErrorKind, IntegratorKind, Settings};

/// An 8-bit PNG of `width × height` pixels of `channels` bytes each.
fn png(width: u32, height: u32, colour: image::ExtendedColorType, bytes: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    image::codecs::png::PngEncoder::new(&mut out)
        .write_image(bytes, width, height, colour)
        .expect("a test PNG encodes");
    out
}

/// An RGB PNG whose texel `(i, j)` has the codes `(i·16, j·16, 255 − i − j)`.
fn ramp_png(width: u32, height: u32) -> Vec<u8> {
    let codes: Vec<u8> = (0..height)
        .flat_map(|j| {
            (0..width).flat_map(move |i| [(i * 16) as u8, (j * 16) as u8, (255 - i - j) as u8])
        })
        .collect();
    png(width, height, image::ExtendedColorType::Rgb8, &codes)
}

fn linear(code: u8) -> f32 {
    radiometry::colour::srgb_decode(f64::from(code) / 255.0) as f32
}

/// A scene with no objects, its environment `environment`, read in `dir`.
fn sky_scene(environment: Value, dir: &Path) -> Result<scene::Scene, scene::SceneError> {
    let file = json!({
        "version": 1, "image": { "width": 4, "height": 3 },
        "camera": { "type": "course_pinhole" }, "materials": {}, "objects": [],
        "environment": environment
    });
    scene::parse_bytes_in(file.to_string().as_bytes(), dir)
}

fn settings(integrator: IntegratorKind) -> Settings {
    Settings {
        integrator,
        ..Settings::default()
    }
}

/// Directions on the axes, the cube's corners and in between.
fn directions() -> Vec<Vec3> {
    let mut out = Vec::new();
    for x in [-1.0, -0.3, 0.0, 0.7, 1.0] {
        for y in [-1.0, 0.0, 0.4, 1.0] {
            for z in [-1.0, -0.2, 0.0, 1.0] {
                let d = Vec3::new(x, y, z);
                if d != Vec3::ZERO {
                    out.push(d.normalize());
                }
            }
        }
    }
    out
}

/// Every integrator built from the laws gives an escaping ray
/// `scale · (d + 1)/2`, to 1e-6 (`f32` rounding of a sum and a product).
#[test]
fn escaping_rays_receive_the_direction_colour_of_their_direction() {
    let scene = sky_scene(
        json!({ "type": "direction_colour", "scale": 2 }),
        Path::new(""),
    )
    .unwrap();
    for integrator in LAW_INTEGRATORS {
        for d in directions() {
            let ray = Ray::new(Vec3::new(0.3, -1.0, 2.0), d);
            let got = radiance_along(&scene, &settings(integrator), &ray);
            let expected = d + Vec3::ONE;
            assert!(
                (got - expected).abs().max_element() < 1e-6,
                "{integrator} {d}: {got}"
            );
        }
    }
}

/// Along the direction of each texel's centre (`LatLong::direction`),
/// the map gives that texel's decoded code times the scale, to 1e-5 (the
/// round trip leaves `u`, `v` within 1e-15 of the centre, where the
/// bilinear weights are 0 and 1).
#[test]
fn a_lat_long_image_is_looked_up_at_the_texel_of_the_direction() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("sky.png"), ramp_png(8, 4)).unwrap();
    let scene = sky_scene(
        json!({ "type": "lat_long", "image": "sky.png", "scale": 0.5 }),
        dir.path(),
    )
    .unwrap();
    let whitted = settings(IntegratorKind::Whitted);
    for j in 0..4u32 {
        for i in 0..8u32 {
            let texel = LatLong::from_uv((i as f64 + 0.5) / 8.0, (j as f64 + 0.5) / 4.0).unwrap();
            let d = texel.direction().get().as_vec3();
            let got = radiance_along(&scene, &whitted, &Ray::new(Vec3::ZERO, d));
            let expected = Vec3::new(
                linear((i * 16) as u8),
                linear((j * 16) as u8),
                linear((255 - i - j) as u8),
            ) * 0.5;
            assert!(
                (got - expected).abs().max_element() < 1e-5,
                "({i}, {j}): {got} vs {expected}"
            );
        }
    }
}

/// Six one-colour faces, in the file's order `+X, −X, +Y, −Y, +Z, −Z`:
/// each axis direction sees its own face's colour, exactly.
#[test]
fn cube_faces_are_read_in_opengls_order() {
    let dir = tempfile::tempdir().unwrap();
    let codes = [
        [255, 0, 0],
        [0, 255, 0],
        [0, 0, 255],
        [255, 255, 0],
        [0, 255, 255],
        [255, 0, 255],
    ];
    let mut faces = Vec::new();
    for (k, code) in codes.iter().enumerate() {
        let name = format!("face{k}.png");
        let bytes: Vec<u8> = code.iter().copied().cycle().take(3 * 4).collect();
        std::fs::write(
            dir.path().join(&name),
            png(2, 2, image::ExtendedColorType::Rgb8, &bytes),
        )
        .unwrap();
        faces.push(name);
    }
    let scene = sky_scene(json!({ "type": "cube", "faces": faces }), dir.path()).unwrap();
    for (face, code) in Face::ALL.into_iter().zip(codes) {
        let axis = CubeTexel::from_uv(face, 0.5, 0.5)
            .unwrap()
            .direction()
            .get()
            .as_vec3();
        let got = radiance_along(
            &scene,
            &settings(IntegratorKind::Whitted),
            &Ray::new(Vec3::ZERO, axis),
        );
        assert_eq!(got, Vec3::from_array(code.map(linear)), "{face:?}");
    }
}

/// The same six colours as one horizontal cross (`environment::CROSS`):
/// each axis direction sees its own face's colour, exactly, and a cross
/// whose texels hold the direction-colour sky of their own directions
/// gives that sky back in every direction (to 0.02: 8-bit codes, 1/255
/// of the range, and the filter at a face's edge, at 32 texels a side).
#[test]
fn a_cube_cross_is_cut_into_its_faces() {
    let dir = tempfile::tempdir().unwrap();
    let codes = [
        [255, 0, 0],
        [0, 255, 0],
        [0, 0, 255],
        [255, 255, 0],
        [0, 255, 255],
        [255, 0, 255],
    ];
    let side = 32u32;
    let mut one = vec![0u8; (3 * 4 * side * 3 * side) as usize];
    let mut sky = one.clone();
    // The layout as docs/scene-schema.md draws it, written out here apart
    // from `environment::CROSS`: +X, −X, +Y, −Y, +Z, −Z at (column, row).
    let drawn = [(2, 1), (0, 1), (1, 0), (1, 2), (1, 1), (3, 1)];
    for (k, &(column, row)) in drawn.iter().enumerate() {
        for j in 0..side {
            for i in 0..side {
                let (x, y) = (column * side + i, row * side + j);
                let at = (3 * (y * 4 * side + x)) as usize;
                one[at..at + 3].copy_from_slice(&codes[k]);
            }
        }
    }
    for (k, &(column, row)) in tracer::environment::CROSS.iter().enumerate() {
        for j in 0..side {
            for i in 0..side {
                let (x, y) = (column * side + i, row * side + j);
                let at = (3 * (y * 4 * side + x)) as usize;
                let (u, v) = (
                    (i as f64 + 0.5) / side as f64,
                    (j as f64 + 0.5) / side as f64,
                );
                let d = CubeTexel::from_uv(Face::ALL[k], u, v)
                    .unwrap()
                    .direction()
                    .get();
                let colour = (d + 1.0) / 2.0;
                let code = |c: f64| (radiometry::colour::srgb_encode(c) * 255.0).round() as u8;
                sky[at..at + 3].copy_from_slice(&colour.to_array().map(code));
            }
        }
    }
    let rgb = image::ExtendedColorType::Rgb8;
    std::fs::write(
        dir.path().join("one.png"),
        png(4 * side, 3 * side, rgb, &one),
    )
    .unwrap();
    std::fs::write(
        dir.path().join("sky.png"),
        png(4 * side, 3 * side, rgb, &sky),
    )
    .unwrap();
    let whitted = settings(IntegratorKind::Whitted);
    let scene = sky_scene(
        json!({ "type": "cube_cross", "image": "one.png" }),
        dir.path(),
    )
    .unwrap();
    for (face, code) in Face::ALL.into_iter().zip(codes) {
        let axis = CubeTexel::from_uv(face, 0.5, 0.5)
            .unwrap()
            .direction()
            .get()
            .as_vec3();
        let got = radiance_along(&scene, &whitted, &Ray::new(Vec3::ZERO, axis));
        assert_eq!(got, Vec3::from_array(code.map(linear)), "{face:?}");
    }
    let scene = sky_scene(
        json!({ "type": "cube_cross", "image": "sky.png" }),
        dir.path(),
    )
    .unwrap();
    for d in directions() {
        let got = radiance_along(&scene, &whitted, &Ray::new(Vec3::ZERO, d));
        let expected = (d + Vec3::ONE) * 0.5;
        assert!(
            (got - expected).abs().max_element() < 0.02,
            "{d}: {got} vs {expected}"
        );
    }
}

/// One case per line: the environment, the files in the directory, the
/// field refused and what is wrong there.
#[test]
fn environment_images_are_refused_by_field() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, bytes: Vec<u8>| std::fs::write(dir.path().join(name), bytes).unwrap();
    write("wide.png", ramp_png(8, 4));
    write("square.png", ramp_png(4, 4));
    write("small.png", ramp_png(2, 2));
    write("tall.png", ramp_png(4, 8));
    write(
        "grey.png",
        png(2, 1, image::ExtendedColorType::L8, &[0, 255]),
    );
    write(
        "huge.png",
        png(8193, 1, image::ExtendedColorType::Rgb8, &[7; 3 * 8193]),
    );
    let cut = ramp_png(8, 4);
    write("cut.png", cut[..cut.len() - 20].to_vec());
    write("text.png", b"not a PNG".to_vec());
    let cube = |faces: [&str; 6]| json!({ "type": "cube", "faces": faces });
    let s = "square.png";
    let size = |expected| move |p: &ImageProblem| matches!(p, ImageProblem::Size { expected: e, .. } if *e == expected);
    type Check = Box<dyn Fn(&ImageProblem) -> bool>;
    let cases: Vec<(Value, &str, Check)> = vec![
        (
            json!({ "type": "cube_cross", "image": "wide.png" }),
            "environment.image",
            Box::new(size(SizeRule::FourByThreeFaces)),
        ),
        (
            json!({ "type": "lat_long", "image": "missing.png" }),
            "environment.image",
            Box::new(|p| matches!(p, ImageProblem::Read(_))),
        ),
        (
            json!({ "type": "lat_long", "image": "square.png" }),
            "environment.image",
            Box::new(size(SizeRule::TwiceAsWideAsHigh)),
        ),
        (
            json!({ "type": "lat_long", "image": "huge.png" }),
            "environment.image",
            Box::new(size(SizeRule::AtMost(8192))),
        ),
        (
            json!({ "type": "lat_long", "image": "grey.png" }),
            "environment.image",
            Box::new(|p| matches!(p, ImageProblem::Pixels(_))),
        ),
        (
            json!({ "type": "lat_long", "image": "cut.png" }),
            "environment.image",
            Box::new(|p| matches!(p, ImageProblem::Decode(_))),
        ),
        (
            json!({ "type": "lat_long", "image": "text.png" }),
            "environment.image",
            Box::new(|p| matches!(p, ImageProblem::Decode(_))),
        ),
        (
            cube([s, s, "tall.png", s, s, s]),
            "environment.faces[2]",
            Box::new(size(SizeRule::Square)),
        ),
        (
            cube([s, s, s, s, s, "small.png"]),
            "environment.faces[5]",
            Box::new(size(SizeRule::SideOfFirstFace(4))),
        ),
        (
            cube([s, "missing.png", s, s, s, s]),
            "environment.faces[1]",
            Box::new(|p| matches!(p, ImageProblem::Read(_))),
        ),
    ];
    for (environment, field, check) in cases {
        let error = sky_scene(environment.clone(), dir.path()).expect_err(&environment.to_string());
        assert_eq!(error.field(), field, "{error}");
        match error.kind() {
            ErrorKind::EnvironmentImage { problem, .. } => {
                assert!(check(problem), "{environment}: {error}")
            }
            other => panic!("{environment}: {other:?}"),
        }
    }
}

#[test]
fn an_environments_numbers_and_shape_are_refused_by_field() {
    let dir = Path::new("");
    for (environment, field) in [
        (
            json!({ "type": "direction_colour", "scale": -1 }),
            "environment.scale",
        ),
        (
            json!({ "type": "direction_colour", "scale": 1e39 }),
            "environment.scale",
        ),
        (json!({ "type": "lat_long" }), "environment"),
        (
            json!({ "type": "cube", "faces": ["a.png"] }),
            "environment.faces",
        ),
        (
            json!({ "type": "sphere_map", "image": "a.png" }),
            "environment.type",
        ),
        (json!({ "image": "a.png" }), "environment.type"),
        (
            json!({ "type": "direction_colour", "zoom": 1 }),
            "environment.zoom",
        ),
    ] {
        let error = sky_scene(environment.clone(), dir).expect_err(&environment.to_string());
        assert_eq!(error.field(), field, "{environment}: {error}");
    }
    let mut file: Value = serde_json::from_str(&common_file("shadow")).unwrap();
    file["environment"] = json!({ "type": "direction_colour" });
    let error = scene::parse(&file.to_string()).unwrap_err();
    assert_eq!(error.field(), "background", "{error}");
    assert!(matches!(error.kind(), ErrorKind::BackgroundWithEnvironment));
}

fn common_file(name: &str) -> String {
    std::fs::read_to_string(format!("{}/scenes/{name}.json", env!("CARGO_MANIFEST_DIR"))).unwrap()
}

/// Without an environment a course scene renders as it did before there
/// were environments: byte for byte the PNG that `scenes/render-all`
/// wrote at 320 × 240 (`scenes/images/`), background included
/// (`gold_spheres` has a blue-grey one).
#[test]
fn course_scenes_without_an_environment_render_as_before() {
    for name in ["gold_spheres", "kaleidoscope_lit"] {
        let path = format!("{}/scenes/{name}.json", env!("CARGO_MANIFEST_DIR"));
        let overrides = Overrides {
            width: Some(320),
            height: Some(240),
            ..Overrides::default()
        };
        let job = RenderJob::load(Path::new(&path), &overrides).unwrap();
        let image = job.render(None, &|_| {}).unwrap().image;
        let stored = format!("{}/scenes/images/{name}.png", env!("CARGO_MANIFEST_DIR"));
        let stored = image::open(stored).unwrap().to_rgb8().into_raw();
        assert!(
            tracer::output::srgb8(&image) == stored,
            "{name} differs from its stored render"
        );
    }
}

/// A sanity check, true by construction: the slides' environment map of
/// an environment that *is* at infinity (the direction-colour sky),
/// captured from the mirror sphere's centre (`capture_cube`, 64 texels a
/// side) and looked up along each reflected ray, gives the mirror the
/// ray tracer gives it, to 5e-3 of the sky's range (the bilinear filter's
/// error at a face's edge, `environment::tests`). It shows the capture and
/// the lookup agree on every direction; it says nothing of finite distances.
#[test]
fn a_mirror_under_an_environment_at_infinity_matches_its_captured_map() {
    let body = |environment: Value| {
        json!({
            "version": 1, "image": { "width": 32, "height": 32 },
            "camera": { "type": "look_at", "eye": [0, 0, -4], "target": [0, 0, 0], "up": [0, 1, 0],
                        "fov_y_deg": 32, "near": 0.1, "far": 100 },
            "materials": { "mirror": common::gold() },
            "objects": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "mirror" } ],
            "environment": environment
        })
    };
    let traced = parse(body(json!({ "type": "direction_colour" })));
    let mut empty = traced.clone();
    empty.objects.clear();
    let map = capture_cube(&empty, traced.settings, Vec3::ZERO, 64);
    let mut mapped = traced.clone();
    mapped.environment = Some(std::sync::Arc::new(Environment::Cube { map, scale: 1.0 }));
    let render = |scene: &scene::Scene| common::render_with(scene, &scene.settings, Some(1));
    let (a, b) = (render(&traced), render(&mapped));
    let worst = a
        .pixels
        .iter()
        .zip(&b.pixels)
        .map(|(p, q)| (*p - *q).abs().max_element())
        .fold(0.0, f32::max);
    assert!(worst < 5e-3, "{worst}");
    // The sphere fills the middle: the check is of reflected rays.
    assert!(a.get(16, 16).max_element() > 0.0);
}
