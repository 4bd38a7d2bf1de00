//! The render job: settings settled once (defaults, then the scene's
//! `render`, then the caller's overrides), each refusal typed and named by
//! its field, the integrator checked by the job itself, and the destination
//! refused before any render.

mod common;

use serde_json::json;
use tracer::job::{Overrides, RenderJob};
use tracer::output::{Destination, OutputError};
use tracer::scene::{
    ErrorKind, FresnelModel, IntegratorKind, PixelFilter, RenderSpec, Scene, Settings,
};

fn glass_scene() -> Scene {
    common::pinhole_scene(
        8,
        6,
        json!({
            "materials": { "glass": { "type": "dielectric", "eta": 1.5 } },
            "objects": [ { "type": "sphere", "center": [0, 0, 4], "radius": 1, "material": "glass" } ],
            "render": { "integrator": "path", "spp": 4, "max_depth": 3 }
        }),
    )
}

#[test]
fn settings_are_the_defaults_under_the_scene_under_the_overrides() {
    let scene = glass_scene();
    // The scene's own, over the defaults.
    assert_eq!(
        scene.settings,
        Settings {
            integrator: IntegratorKind::Path,
            spp: 4,
            max_depth: 3,
            pixel_filter: PixelFilter::Box,
            ..Settings::default()
        }
    );
    let overrides = Overrides {
        render: RenderSpec {
            spp: Some(16.0),
            fresnel: Some(FresnelModel::SchlickRarer.into()),
            seed: Some(7),
            ..RenderSpec::default()
        },
        width: Some(4),
        height: None,
        allow_expensive: false,
    };
    let job = RenderJob::new(scene, &overrides).unwrap();
    assert_eq!(
        *job.settings(),
        Settings {
            integrator: IntegratorKind::Path,
            spp: 16,
            max_depth: 3,
            fresnel: FresnelModel::SchlickRarer,
            seed: 7,
            pixel_filter: PixelFilter::Box,
            ..Settings::default()
        }
    );
    assert_eq!((job.scene().width, job.scene().height), (4, 6));
    // Glass makes every path random: all 16 samples are taken.
    assert_eq!(job.machinery().spp, 16);
}

/// The pixel filter's default is decided once, in `Settings::settle`: the
/// integrator named beside it decides it unless a filter is named too; a
/// stage that names neither keeps the one before. One case per line: the
/// scene's `render`, the overrides, the filter settled and the samples taken.
#[test]
fn the_pixel_filter_follows_the_integrator_named_beside_it_unless_named_itself() {
    use IntegratorKind::{Course, Path, Whitted};
    use PixelFilter::{Box, Center};
    let cases = [
        (json!({}), (None, None), Center, 1),
        (json!({ "integrator": "path" }), (None, None), Box, 16),
        (
            json!({ "integrator": "path" }),
            (Some(Course), None),
            Center,
            1,
        ),
        (
            json!({ "integrator": "path" }),
            (Some(Whitted), None),
            Center,
            1,
        ),
        (
            json!({ "integrator": "whitted" }),
            (Some(Path), None),
            Box,
            16,
        ),
        (
            json!({ "integrator": "path", "pixel_filter": "center" }),
            (None, None),
            Center,
            16,
        ),
        (
            json!({ "integrator": "whitted", "pixel_filter": "box" }),
            (None, None),
            Box,
            16,
        ),
        (
            json!({ "integrator": "path", "pixel_filter": "center" }),
            (Some(Whitted), None),
            Center,
            1,
        ),
        (
            json!({ "integrator": "path" }),
            (Some(Course), Some(Box)),
            Box,
            16,
        ),
        (
            json!({ "integrator": "whitted" }),
            (None, Some(Box)),
            Box,
            16,
        ),
        (
            json!({ "integrator": "path" }),
            (None, Some(Center)),
            Center,
            16,
        ),
    ];
    for (render, (integrator, pixel_filter), filter, spp) in cases {
        let mut render = render;
        render["spp"] = json!(16);
        let scene = common::pinhole_scene(
            4,
            3,
            json!({
                "materials": { "grey": { "type": "lambert", "albedo": [0.5, 0.5, 0.5] } },
                "objects": [ { "type": "sphere", "center": [0, 0, 4], "radius": 1, "material": "grey" } ],
                "lights": [ { "type": "directional", "towards": [0, 1, -1], "irradiance": [1, 1, 1] } ],
                "render": render.clone()
            }),
        );
        let overrides = Overrides {
            render: RenderSpec {
                integrator,
                pixel_filter,
                ..RenderSpec::default()
            },
            ..Overrides::default()
        };
        let job = RenderJob::new(scene, &overrides).unwrap();
        let case = format!("{render} under {integrator:?}, {pixel_filter:?}");
        assert_eq!(job.settings().pixel_filter, filter, "{case}");
        assert_eq!(job.machinery().spp, spp, "{case}");
    }
}

/// One case per line: the overrides, the field the refusal names, and its
/// kind.
#[test]
fn bad_overrides_are_refused_by_kind_and_field() {
    type Kind = fn(&ErrorKind) -> bool;
    let render = |render: RenderSpec| Overrides {
        render,
        ..Overrides::default()
    };
    let cases: [(&str, Overrides, &str, Kind); 5] = [
        (
            "no samples",
            render(RenderSpec {
                spp: Some(0.0),
                ..RenderSpec::default()
            }),
            "overrides.spp",
            |k| matches!(k, ErrorKind::NotACount { min: 1, value, .. } if *value == 0.0),
        ),
        (
            "too many pixels",
            Overrides {
                width: Some(16_384),
                height: Some(16_384),
                ..Overrides::default()
            },
            "overrides",
            |k| {
                matches!(
                    k,
                    ErrorKind::TooManyPixels {
                        width: 16_384,
                        height: 16_384
                    }
                )
            },
        ),
        (
            "no width",
            Overrides {
                width: Some(0),
                ..Overrides::default()
            },
            "overrides.width",
            |k| matches!(k, ErrorKind::NotACount { min: 1, value, .. } if *value == 0.0),
        ),
        (
            "cutoff above 1",
            render(RenderSpec {
                throughput_cutoff: Some(2.0),
                ..RenderSpec::default()
            }),
            "overrides.throughput_cutoff",
            |k| matches!(k, ErrorKind::Domain(_)),
        ),
        (
            // Only the photons given: the product is refused under their
            // name, with the most the scene's 16 passes allow.
            "photons beyond what 16 passes may hold",
            render(RenderSpec {
                photons: Some(300_000.0),
                ..RenderSpec::default()
            }),
            "overrides.photons",
            |k| matches!(k, ErrorKind::NotACount { max: 262_144, .. }),
        ),
    ];
    for (name, overrides, field, kind) in cases {
        let e = RenderJob::new(glass_scene(), &overrides).expect_err(name);
        assert_eq!(e.field(), field, "{name}: {e}");
        assert!(kind(e.kind()), "{name}: {:?}", e.kind());
    }
}

/// The renderer itself refuses what an integrator cannot render, whoever
/// calls it: the course's shader has no glass.
#[test]
fn the_job_refuses_glass_under_the_course_shader_naming_the_material() {
    let scene = glass_scene();
    let course = Settings {
        integrator: IntegratorKind::Course,
        ..scene.settings
    };
    let e = RenderJob::with_settings(scene.clone(), course).unwrap_err();
    assert_eq!(e.field(), "materials.glass");
    assert!(matches!(e.kind(), ErrorKind::CourseHasNoRefraction));
    let overrides = Overrides {
        render: RenderSpec {
            integrator: Some(IntegratorKind::Course),
            ..RenderSpec::default()
        },
        ..Overrides::default()
    };
    assert!(RenderJob::new(scene, &overrides).is_err());
}

#[test]
fn a_destination_is_refused_before_the_render() {
    let dir = tempfile::tempdir().unwrap();
    let pfm = dir.path().join("out.pfm");
    assert!(matches!(
        Destination::new(&pfm, &[]),
        Err(OutputError::PfmIsPng { .. })
    ));
    // PNG bytes are never written under another format's name.
    for other in ["out.jpg", "out.JPEG", "out.exr"] {
        assert!(matches!(
            Destination::new(&dir.path().join(other), &[]),
            Err(OutputError::NotPng { .. })
        ));
    }
    assert!(Destination::new(&dir.path().join("out.PNG"), &[]).is_ok());
    let nowhere = dir.path().join("no/such/dir/out.png");
    assert!(matches!(
        Destination::new(&nowhere, &[]),
        Err(OutputError::Write(safe_io::WriteError::NoDirectory { .. }))
    ));
    let png = dir.path().join("out.png");
    let destination = Destination::new(&png, &[]).unwrap();
    let job = RenderJob::new(glass_scene(), &Overrides::default()).unwrap();
    let rendered = job.render_to(&destination, Some(1), &|_| {}).unwrap();
    assert_eq!(destination.pfm(), dir.path().join("out.pfm"));
    let pfm = std::fs::read(destination.pfm()).unwrap();
    assert_eq!(tracer::output::read_pfm(&pfm), Some(rendered.image));
    assert!(png.is_file());
}

#[test]
fn first_hits_name_the_object_seen_through_each_pixel_centre() {
    // Two spheres side by side at z = 4 (the course pinhole at z = −2 sees
    // y ∈ [−1, 1] at z = 0, so x ∈ [−3, 3] at z = 4 spans the 8 columns
    // at 0.75 m each): the left one (object 0) covers the centres of
    // columns 2 and 3, the right one (object 1) those of 4 and 5; the
    // corners see the background.
    let scene = common::pinhole_scene(
        8,
        6,
        json!({
            "materials": { "grey": { "type": "lambert", "albedo": [0.5, 0.5, 0.5] } },
            "objects": [
                { "type": "sphere", "center": [-1.1, 0, 4], "radius": 1, "material": "grey" },
                { "type": "sphere", "center": [1.1, 0, 4], "radius": 1, "material": "grey" }
            ]
        }),
    );
    let job = RenderJob::new(scene, &Overrides::default()).unwrap();
    let hits = job.first_hits();
    assert_eq!(hits.len(), 8 * 6);
    let row: Vec<Option<u32>> = hits[2 * 8..3 * 8].to_vec();
    let (n, s0, s1) = (None, Some(0), Some(1));
    assert_eq!(row, [n, n, s0, s0, s1, s1, n, n]);
    assert_eq!(hits[0], None);
}
