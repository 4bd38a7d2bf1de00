//! The integrators against known answers: an analytic Lambert plane, a
//! point light's inverse square and its shadow ray stopping at the light,
//! the path tracer converging to Whitted's answer, images independent of the
//! thread count, robust ray offsets where a fixed epsilon fails, and glass
//! in a uniform sky, invisible from outside and `η²` times the sky from
//! inside (what a scene needs and what the renderer skips: `machinery.rs`).

mod common;

use common::{
    course_scene, gold, parse, pinhole_scene, radiance_along, render_with, tracer, GOLD_KAPPA,
    GOLD_N,
};
use glam::Vec3;
use serde_json::{json, Value};
use tracer::geometry::Ray;
use tracer::integrator::RayCounts;
use tracer::sampler::Sampler;
use tracer::scene::faults::{self, Fault};
use tracer::scene::{FresnelModel, IntegratorKind, PixelFilter, RayOffset, Scene, Settings};

fn settings(integrator: IntegratorKind) -> Settings {
    Settings {
        integrator,
        ..Settings::default()
    }
}

/// A Lambert floor (albedo 0.5, 0.25, 0.75) under a directional light of
/// E⊥ = 2 W/m² from 60° off the normal, seen from above: `L = albedo/π · E⊥
/// cos 60°` at every pixel that sees the floor, for all three integrators
/// (the path tracer's bounces escape to a black sky, so it adds nothing).
#[test]
fn lambert_plane_under_a_directional_light_matches_kd_over_pi_e_cos_for_every_integrator() {
    let theta = 60_f64.to_radians();
    let scene = parse(json!({
        "version": 1,
        "image": { "width": 16, "height": 12 },
        "camera": { "type": "look_at", "eye": [0, 3, 3], "target": [0, 0, 0], "up": [0, 1, 0],
                    "fov_y_deg": 40, "near": 0.1, "far": 100 },
        "materials": { "floor": { "type": "lambert", "albedo": [0.5, 0.25, 0.75] } },
        "objects": [ { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor" } ],
        "lights": [ { "type": "directional", "towards": [theta.sin(), theta.cos(), 0], "irradiance": [2, 2, 2] } ]
    }));
    let expected = Vec3::new(0.5, 0.25, 0.75) / std::f32::consts::PI * 2.0 * 0.5;
    for integrator in common::LAW_INTEGRATORS {
        let s = Settings {
            spp: 8,
            ..settings(integrator)
        };
        let image = render_with(&scene, &s, Some(1));
        for (i, p) in image.pixels.iter().enumerate() {
            // A dozen f32 roundings (normalising the light, the cosine, the
            // BRDF, the product): relative 2e-6 would do; 1e-5 is stated.
            let err = ((*p - expected).abs() / expected).max_element();
            assert!(
                err < 1e-5,
                "{integrator}: pixel {i} is {p}, expected {expected}"
            );
        }
    }
}

fn lit_floor(occluder: Option<([f64; 3], f64)>, light_height: f64) -> Scene {
    let mut objects = vec![
        json!({ "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor" }),
    ];
    if let Some((center, radius)) = occluder {
        objects.push(
            json!({ "type": "sphere", "center": center, "radius": radius, "material": "floor" }),
        );
    }
    pinhole_scene(
        4,
        4,
        json!({
            "materials": { "floor": { "type": "lambert", "albedo": [0.6, 0.6, 0.6] } },
            "objects": objects,
            "lights": [ { "type": "point", "position": [0, light_height, 0], "intensity": [10, 10, 10] } ]
        }),
    )
}

/// The floor's origin seen along the diagonal from (3, 3, 0).
fn to_origin() -> Ray {
    Ray::new(
        Vec3::new(3.0, 3.0, 0.0),
        Vec3::new(-1.0, -1.0, 0.0).normalize(),
    )
}

#[test]
fn point_light_falls_off_with_the_inverse_square_of_distance() {
    let s = settings(IntegratorKind::Whitted);
    // L = albedo/π · I cos θ / r² with θ = 0 straight below the light.
    for height in [1.0, 2.0] {
        let l = radiance_along(&lit_floor(None, height), &s, &to_origin());
        let expected = 0.6 / std::f32::consts::PI * 10.0 / (height * height) as f32;
        assert!(
            (l.x - expected).abs() < 1e-5 * expected,
            "h = {height}: {l} vs {expected}"
        );
    }
}

#[test]
fn shadow_ray_stops_at_the_point_light() {
    let s = settings(IntegratorKind::Whitted);
    let unshadowed = radiance_along(&lit_floor(None, 1.0), &s, &to_origin());
    // A sphere beyond the light, on the same line: it must not shadow.
    let beyond = radiance_along(
        &lit_floor(Some(([0.0, 3.0, 0.0], 0.5)), 1.0),
        &s,
        &to_origin(),
    );
    assert_eq!(beyond, unshadowed);
    // The same sphere between the floor and the light: full shadow.
    let between = radiance_along(
        &lit_floor(Some(([0.0, 0.5, 0.0], 0.2)), 1.0),
        &s,
        &to_origin(),
    );
    assert_eq!(between, Vec3::ZERO);
}

/// Only specular surfaces scatter (a gold sphere, a glass sphere), lit by an
/// unlit emitter panel and the sky; the delta light reaches no rough
/// surface. Whitted's recursion, cut nowhere, is then the exact answer, and
/// the path tracer, which picks reflection or refraction at the glass with
/// the Fresnel probability, is an unbiased estimate of it: its mean over 256
/// independent seeds must lie within 5 standard errors of Whitted at every
/// pixel and channel (a false alarm in 1.7 million per value).
#[test]
fn path_converges_to_whitted_where_only_mirrors_and_glass_scatter() {
    let scene = gold_and_glass_over_a_panel(
        json!([
            { "type": "sphere", "center": [0.6, 0, 4], "radius": 0.8, "material": "gold" },
            { "type": "sphere", "center": [-0.7, 0, 3.5], "radius": 0.7, "material": "glass" },
            { "type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0], "material": "panel" }
        ]),
        json!([ { "type": "directional", "towards": [0, 1, 0], "irradiance": [1, 1, 1] } ]),
    );
    let noisy = path_mean_within_five_standard_errors_of_whitted(&scene, FresnelModel::Exact);
    assert!(
        noisy > 50,
        "the glass must make some pixels random, got {noisy}"
    );
}

/// The same convergence where light is totally reflected inside glass, with
/// the course's Fresnel formula, which (unlike the exact law) gives R < 1
/// there: the camera sits inside a large glass sphere, near its wall, and
/// sees the wall beyond the critical angle over much of the image. The path
/// tracer's certain mirror branch must carry R, as Whitted's does.
#[test]
fn path_converges_to_whitted_under_total_internal_reflection_with_the_course_fresnel() {
    let scene = gold_and_glass_over_a_panel(
        json!([
            { "type": "sphere", "center": [0, 10, 4], "radius": 12, "material": "glass" },
            { "type": "sphere", "center": [0.5, -0.4, 4], "radius": 0.5, "material": "gold" },
            { "type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0], "material": "panel" }
        ]),
        json!([]),
    );
    // Check that the scene does what it is for: somewhere the course's R
    // under total internal reflection is below 1.
    let tir_r = radiometry::course::fresnel_000_glsl(radiometry::fresnel::f0(1.5f32, 0.0), 0.3);
    assert!(tir_r < 0.9, "{tir_r}");
    path_mean_within_five_standard_errors_of_whitted(&scene, FresnelModel::Course);
}

/// The two convergence tests' scene: course gold, glass and an unlit
/// emitter panel under a blue-grey sky, with their own `objects` and `lights`.
fn gold_and_glass_over_a_panel(objects: Value, lights: Value) -> Scene {
    pinhole_scene(
        24,
        18,
        json!({
            "background": [0.2, 0.3, 0.5],
            "materials": {
                "gold": gold(),
                "glass": { "type": "dielectric", "eta": 1.5 },
                "panel": { "type": "flat", "radiance": [1.0, 0.9, 0.7] }
            },
            "objects": objects,
            "lights": lights
        }),
    )
}

/// Renders Whitted once and the path tracer with 256 seeds, both with
/// `fresnel`, six bounces and no throughput cutoff (so that Whitted's
/// recursion is exact), and asserts the path mean within 5 standard errors
/// (plus f32 rounding) of Whitted at every pixel and channel. Returns how
/// many values were random at all.
fn path_mean_within_five_standard_errors_of_whitted(scene: &Scene, fresnel: FresnelModel) -> usize {
    let base = Settings {
        max_depth: 6,
        throughput_cutoff: 0.0,
        fresnel,
        ..Settings::default()
    };
    let whitted = render_with(
        scene,
        &Settings {
            integrator: IntegratorKind::Whitted,
            ..base
        },
        Some(1),
    );
    let n = 256;
    let mut sum = vec![[0.0_f64; 3]; whitted.pixels.len()];
    let mut sum2 = sum.clone();
    for seed in 0..n {
        let s = Settings {
            integrator: IntegratorKind::Path,
            seed,
            ..base
        };
        let image = render_with(scene, &s, None);
        for (i, p) in image.pixels.iter().enumerate() {
            for c in 0..3 {
                sum[i][c] += p[c] as f64;
                sum2[i][c] += (p[c] as f64).powi(2);
            }
        }
    }
    let mut noisy = 0;
    for (i, w) in whitted.pixels.iter().enumerate() {
        for c in 0..3 {
            let mean = sum[i][c] / n as f64;
            let var = (sum2[i][c] / n as f64 - mean * mean).max(0.0) * n as f64 / (n - 1) as f64;
            let standard_error = (var / n as f64).sqrt();
            if standard_error > 0.0 {
                noisy += 1;
            }
            // Plus f32 rounding of sums of a few dozen terms of order 1.
            let allowed = 5.0 * standard_error + 1e-5;
            assert!(
                (mean - w[c] as f64).abs() <= allowed,
                "pixel {i} channel {c}: path mean {mean} vs whitted {} (allowed {allowed})",
                w[c]
            );
        }
    }
    noisy
}

#[test]
fn image_is_identical_for_any_thread_count() {
    let scene = course_scene("kaleidoscope_lit", 32, 24);
    // Both filters: the box's points come from the pixel's own samples too.
    for (integrator, pixel_filter) in [
        (IntegratorKind::Whitted, PixelFilter::Center),
        (IntegratorKind::Whitted, PixelFilter::Box),
        (IntegratorKind::Path, PixelFilter::Center),
        (IntegratorKind::Path, PixelFilter::Box),
    ] {
        let s = Settings {
            spp: 3,
            seed: 11,
            pixel_filter,
            ..settings(integrator)
        };
        let one = render_with(&scene, &s, Some(1));
        for threads in [2, 3, 8] {
            assert!(
                one == render_with(&scene, &s, Some(threads)),
                "{integrator}, {pixel_filter} filter, with {threads} threads"
            );
        }
    }
}

/// A matte sphere 100 km from the origin, lit from the camera's side, with
/// a second sphere so that shadow rays are cast. A convex sphere cannot
/// shadow its own lit side, so every lit pixel must be lit. At 10⁵ m one f32
/// ulp is 7.8 mm: the course's fixed 1 mm offset rounds back onto the
/// surface and the shadow rays find it again (shadow acne).
#[test]
fn fixed_epsilon_shadows_acne_far_from_the_origin_where_the_error_bound_offset_holds() {
    let far = 1.0e5;
    let scene = parse(json!({
        "version": 1,
        "image": { "width": 32, "height": 24 },
        "camera": { "type": "look_at", "eye": [far, 0, far - 4.0], "target": [far, 0, far], "up": [0, 1, 0],
                    "fov_y_deg": 40, "near": 0.1, "far": 100 },
        "materials": { "matte": { "type": "lambert", "albedo": [0.8, 0.8, 0.8] } },
        "objects": [
            { "type": "sphere", "center": [far, 0, far], "radius": 1, "material": "matte" },
            { "type": "sphere", "center": [far + 50.0, 50, far + 50.0], "radius": 1, "material": "matte" }
        ],
        "lights": [ { "type": "directional", "towards": [0.3, 0.4, -1], "irradiance": [1, 1, 1] } ]
    }));
    let dark_lit_pixels = |offset: RayOffset| {
        let s = Settings {
            ray_offset: offset,
            ..settings(IntegratorKind::Whitted)
        };
        let tracer = tracer(&scene, s);
        let (mut lit, mut dark) = (0, 0);
        for y in 0..scene.height {
            for x in 0..scene.width {
                let ray = scene.camera.ray(x, y);
                let Some(hit) = tracer.intersect(&ray) else {
                    continue;
                };
                if hit.normal.dot(Vec3::new(0.3, 0.4, -1.0).normalize()) > 0.05 {
                    lit += 1;
                    let l = tracer.radiance(
                        &ray,
                        &mut Sampler::for_pixel(0, 0).sample(0),
                        &mut RayCounts::default(),
                    );
                    if l == Vec3::ZERO {
                        dark += 1;
                    }
                }
            }
        }
        assert!(lit > 50, "the test must see the lit side, saw {lit} pixels");
        dark as f64 / lit as f64
    };
    let robust = dark_lit_pixels(RayOffset::Robust);
    let fixed = dark_lit_pixels(RayOffset::Fixed(0.001));
    eprintln!(
        "lit pixels shadowed by their own surface: robust {robust:.3}, fixed 1 mm {fixed:.3}"
    );
    assert_eq!(robust, 0.0, "error-bound offsets: no acne");
    assert!(
        fixed > 0.2,
        "the course's fixed epsilon was expected to fail here: {fixed}"
    );
}

/// The course's Fresnel (`pow(cos θ, 5)` for `pow(1 − cos θ, 5)`) makes a
/// mirror reflect everything head-on; the exact law gives gold's F0 there.
#[test]
fn course_integrator_uses_the_course_fresnel_and_whitted_the_exact_law() {
    let scene = pinhole_scene(
        4,
        4,
        json!({
            "materials": {
                "gold": gold(),
                "white": { "type": "flat", "radiance": [1, 1, 1] }
            },
            "objects": [
                { "type": "sphere", "center": [0, 0, 4], "radius": 1, "material": "gold" },
                { "type": "sphere", "center": [0, 0, -20], "radius": 10, "material": "white" }
            ]
        }),
    );
    let head_on = Ray::new(Vec3::new(0.0, 0.0, -2.0), Vec3::Z);
    let course = radiance_along(&scene, &settings(IntegratorKind::Course), &head_on);
    assert!((course - Vec3::ONE).abs().max_element() < 1e-6, "{course}");
    let exact = radiance_along(&scene, &settings(IntegratorKind::Whitted), &head_on);
    let f0 = radiometry::fresnel::f0_rgb(GOLD_N.map(|n| n as f32), GOLD_KAPPA.map(|k| k as f32));
    assert!(
        (exact - Vec3::from_array(f0)).abs().max_element() < 1e-6,
        "{exact}"
    );
    let schlick = radiance_along(
        &scene,
        &Settings {
            fresnel: FresnelModel::SchlickRarer,
            ..settings(IntegratorKind::Whitted)
        },
        &head_on,
    );
    assert!(
        (schlick - Vec3::from_array(f0)).abs().max_element() < 1e-6,
        "Schlick is exact head-on"
    );
}

/// A glass sphere in a uniform sky (a "white furnace"): it neither absorbs
/// nor emits, so every pixel must show the sky. The path tracer's weights
/// are exactly 1 per path (the Fresnel choice cancels R and T; `1/η²` in and
/// `η²` out cancel), so it matches up to f32 rounding; Whitted's branches
/// sum to the sky less what falls past `max_depth` or under the cutoff.
#[test]
fn glass_sphere_in_a_uniform_sky_is_invisible() {
    let scene = pinhole_scene(
        24,
        18,
        json!({
            "background": [0.5, 0.5, 0.5],
            "materials": { "glass": { "type": "dielectric", "eta": 1.5 } },
            "objects": [ { "type": "sphere", "center": [0, 0, 3], "radius": 1.2, "material": "glass" } ]
        }),
    );
    for fresnel in [FresnelModel::Exact, FresnelModel::SchlickRarer] {
        let path = Settings {
            spp: 4,
            max_depth: 64,
            fresnel,
            ..settings(IntegratorKind::Path)
        };
        for p in render_with(&scene, &path, None).pixels {
            // A few dozen f32 products along a path: relative 1e-5.
            assert!(
                (p - Vec3::splat(0.5)).abs().max_element() < 5e-6,
                "{fresnel:?} path: {p}"
            );
        }
        let whitted = Settings {
            max_depth: 12,
            throughput_cutoff: 1e-4,
            fresnel,
            ..settings(IntegratorKind::Whitted)
        };
        for p in render_with(&scene, &whitted, None).pixels {
            // Lost: branches under 1e-4 of weight and past 12 bounces; a
            // sphere traps no light, so well under 1 %.
            assert!(
                p.max_element() <= 0.5 + 5e-6 && p.min_element() > 0.495,
                "{fresnel:?} whitted: {p}"
            );
        }
    }
}

/// A camera inside a glass sphere in a uniform sky of radiance L: in a
/// lossless medium of index n in equilibrium with the sky the radiance is
/// `n² L` (`L/n²` is conserved along a path), so every pixel shows
/// `2.25 L`. The path tracer's samples are exactly that (a reflection inside
/// weighs 1, the way out `η²`); Whitted's branches sum to it less what falls
/// under the cutoff or past `max_depth`. Without the `η²` the image would
/// show the sky itself.
#[test]
fn a_camera_inside_glass_in_a_uniform_sky_sees_eta_squared_times_the_sky() {
    let scene = pinhole_scene(
        24,
        18,
        json!({
            "background": [0.5, 0.5, 0.5],
            "materials": { "glass": { "type": "dielectric", "eta": 1.5 } },
            "objects": [ { "type": "sphere", "center": [0, 0, -1.5], "radius": 3, "material": "glass" } ]
        }),
    );
    let expected = 0.5 * 2.25;
    let path = Settings {
        spp: 4,
        max_depth: 64,
        ..settings(IntegratorKind::Path)
    };
    for p in render_with(&scene, &path, None).pixels {
        // A few dozen f32 products along a path: relative 1e-5.
        assert!(
            (p - Vec3::splat(expected)).abs().max_element() < expected * 1e-5,
            "path: {p}"
        );
    }
    let whitted = Settings {
        max_depth: 12,
        throughput_cutoff: 1e-4,
        ..settings(IntegratorKind::Whitted)
    };
    for p in render_with(&scene, &whitted, None).pixels {
        // Lost: branches under 1e-4 of weight and past 12 bounces, R ≈ 0.04
        // each time a branch stays inside: well under 1 %.
        assert!(
            p.max_element() <= expected * (1.0 + 1e-5) && p.min_element() > expected * 0.99,
            "whitted: {p}"
        );
    }
    // The η² left out (a test-only switch): the sky, not its η² times.
    let unscaled = faults::with(Fault::RadianceNotScaledAcrossInterfaces, || {
        render_with(&scene, &path, None)
    });
    for p in unscaled.pixels {
        assert!((p - Vec3::splat(0.5)).abs().max_element() < 5e-6, "{p}");
    }
}

#[test]
fn path_tracer_is_deterministic_per_seed() {
    let scene = course_scene("webgl_seven_spheres", 24, 18);
    let with_seed = |seed| Settings {
        spp: 2,
        seed,
        ..settings(IntegratorKind::Path)
    };
    let a = render_with(&scene, &with_seed(1), None);
    assert!(
        a == render_with(&scene, &with_seed(1), None),
        "same seed, same image"
    );
    assert!(
        a != render_with(&scene, &with_seed(2), None),
        "another seed, other noise"
    );
}

/// A Lambert sphere under a uniform sky of radiance L (a white furnace): a
/// convex surface sees only sky, so it reflects `albedo · L`. The path
/// tracer finds this by sampling (each cosine-sampled bounce carries exactly
/// `π · albedo/π`, so there is no noise); `local` and `whitted` get it from
/// the ambient term when the ambient radiance is that same sky.
#[test]
fn lambert_sphere_in_a_uniform_sky_reflects_albedo_times_the_sky() {
    let scene = pinhole_scene(
        24,
        18,
        json!({
            "background": [0.4, 0.4, 0.4],
            "ambient": [0.4, 0.4, 0.4],
            "materials": { "clay": { "type": "lambert", "albedo": [0.9, 0.5, 0.1] } },
            "objects": [ { "type": "sphere", "center": [0, 0, 3], "radius": 1.2, "material": "clay" } ]
        }),
    );
    let expected = Vec3::new(0.9, 0.5, 0.1) * 0.4;
    for integrator in common::LAW_INTEGRATORS {
        let s = Settings {
            spp: 4,
            ..settings(integrator)
        };
        let image = render_with(&scene, &s, None);
        let on_sphere: Vec<Vec3> = image
            .pixels
            .into_iter()
            .filter(|p| *p != Vec3::splat(0.4))
            .collect();
        assert!(
            on_sphere.len() > 50,
            "{integrator}: the sphere covers the image's centre"
        );
        for p in on_sphere {
            // π · (albedo/π) and a product: a few f32 roundings.
            assert!(
                (p - expected).abs().max_element() < 1e-6,
                "{integrator}: {p} vs {expected}"
            );
        }
    }
}
