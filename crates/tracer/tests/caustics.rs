//! The `photon` integrator against the method of images: a point light
//! beside a planar mirror, over a Lambert floor, lights the floor twice,
//! directly and as its mirror image, a second point light of intensity
//! `R(θ) I` behind the mirror (`R` the mirror's Fresnel reflectance where
//! the image's ray crosses it). The path tracer finds only the first
//! (no camera path can aim at the light through the mirror); the photon
//! integrator must find both. Also: a directional light's photons off a
//! mirror ball carry the Fresnel-weighted flux of the ball's outer ring,
//! the image does not depend on the thread count, without mirrors the
//! photon integrator is the path tracer, and each photon law left out is
//! caught.

mod common;

use common::{job, parse};
use glam::DVec3;
use radiometry::fresnel;
use serde_json::json;
use tracer::integrator::photon;
use tracer::render::Image;
use tracer::scene::faults::{self, Fault};
use tracer::scene::{IntegratorKind, PhotonSettings, Scene, Settings};

const LIGHT: [f64; 3] = [-0.5, 1.0, 0.0];
const INTENSITY: f64 = 10.0;
const ALBEDO: [f64; 3] = [0.8, 0.6, 0.4];
/// A conductor whose reflectance differs per channel (0.92, 0.47 and 0.13
/// at normal incidence), so a factor lost per channel shows.
const MIRROR_N: [f64; 3] = [0.2, 0.9, 1.4];
const MIRROR_KAPPA: [f64; 3] = [3.0, 1.8, 0.8];
const WIDTH: u32 = 64;
const HEIGHT: u32 = 48;
/// Regions of `BLOCK × BLOCK` pixels are compared.
const BLOCK: u32 = 8;

/// The floor y = 0 (Lambert), the mirror x = 0 (a conductor), the light
/// at x = −0.5 between them, a black sky. A ray leaving the floor upwards
/// keeps going up after the vertical mirror, so nothing reaches the floor
/// but the two point lights (no interreflection to add).
fn mirror_scene() -> Scene {
    parse(json!({
        "version": 1,
        "image": { "width": WIDTH, "height": HEIGHT },
        "camera": { "type": "look_at", "eye": [-2.2, 2.2, 2.2], "target": [-0.6, 0, 0],
                    "up": [0, 1, 0], "fov_y_deg": 45, "near": 0.1, "far": 100 },
        "materials": {
            "floor": { "type": "lambert", "albedo": ALBEDO },
            "mirror": { "type": "conductor", "n": MIRROR_N, "kappa": MIRROR_KAPPA }
        },
        "objects": [
            { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor" },
            { "type": "plane", "point": [0, 0, 0], "normal": [1, 0, 0], "material": "mirror" }
        ],
        "lights": [ { "type": "point", "position": LIGHT, "intensity": [INTENSITY, INTENSITY, INTENSITY] } ]
    }))
}

/// The settings of the comparison: 64 camera paths a pixel, 8 passes of
/// 100 000 photons from a 6 cm radius.
fn settings(integrator: IntegratorKind, seed: u64) -> Settings {
    Settings {
        integrator,
        spp: 64,
        seed,
        photon: PhotonSettings {
            photons: 100_000,
            passes: 8,
            radius: 0.06,
        },
        ..Settings::default()
    }
}

/// A point light's irradiance on the floor at `x`, W/m².
fn irradiance(light: DVec3, x: DVec3) -> f64 {
    let to = light - x;
    (INTENSITY * to.y / to.length().powi(3)).max(0.0)
}

/// The mirror image's irradiance on the floor at `x`, times the mirror's
/// reflectance per channel where the image's ray crosses the mirror; none
/// behind the mirror (x > 0).
fn mirrored(x: DVec3) -> DVec3 {
    if x.x > 0.0 {
        return DVec3::ZERO;
    }
    let image = DVec3::from_array(LIGHT) * DVec3::new(-1.0, 1.0, 1.0);
    let cos_at_mirror = ((image - x).normalize().x).abs();
    let r = fresnel::conductor_rgb(cos_at_mirror, MIRROR_N, MIRROR_KAPPA);
    DVec3::from_array(r) * irradiance(image, x)
}

/// The floor's radiance at `x` by the method of images, `ρ/π (E + R E')`,
/// and what the estimator converges to at the settings' radii: the image's
/// irradiance averaged over each pass's disc (midpoint quadrature, 8 rings
/// of 16), then over the passes.
fn closed_form(x: DVec3, radii: &[f32]) -> (DVec3, DVec3) {
    let rho = DVec3::from_array(ALBEDO) / std::f64::consts::PI;
    let direct = DVec3::splat(irradiance(DVec3::from_array(LIGHT), x));
    let mut smoothed = DVec3::ZERO;
    for r in radii {
        let mut disc = DVec3::ZERO;
        for ring in 0..8 {
            // Equal-area rings, each point at its ring's mean radius.
            let rho_ring = *r as f64 * ((ring as f64 + 0.5) / 8.0).sqrt();
            for k in 0..16 {
                let phi = std::f64::consts::TAU * (k as f64 + 0.5) / 16.0;
                disc += mirrored(x + DVec3::new(phi.cos(), 0.0, phi.sin()) * rho_ring);
            }
        }
        smoothed += disc / 128.0;
    }
    smoothed /= radii.len() as f64;
    (rho * (direct + mirrored(x)), rho * (direct + smoothed))
}

/// One region wholly on the floor: the closed form, what the kernel
/// converges to, and each render's mean, per channel.
struct Region {
    exact: DVec3,
    kernel: DVec3,
    renders: Vec<DVec3>,
}

fn regions(scene: &Scene, images: &[Image]) -> Vec<Region> {
    let s = settings(IntegratorKind::Photon, 0);
    let radii = photon::radii(s.photon.radius, s.photon.passes);
    let hits = job(scene, &s).first_hits();
    let mut out = Vec::new();
    for by in 0..HEIGHT / BLOCK {
        for bx in 0..WIDTH / BLOCK {
            let mut region = Region {
                exact: DVec3::ZERO,
                kernel: DVec3::ZERO,
                renders: vec![DVec3::ZERO; images.len()],
            };
            let mut floor = true;
            for y in by * BLOCK..(by + 1) * BLOCK {
                for x in bx * BLOCK..(bx + 1) * BLOCK {
                    floor &= hits[(y * WIDTH + x) as usize] == Some(0);
                    let ray = scene.camera.ray(x, y);
                    let (o, d) = (ray.origin.as_dvec3(), ray.direction.as_dvec3());
                    let (exact, kernel) = closed_form(o + d * (-o.y / d.y), &radii);
                    region.exact += exact;
                    region.kernel += kernel;
                    for (sum, image) in region.renders.iter_mut().zip(images) {
                        *sum += image.get(x, y).as_dvec3();
                    }
                }
            }
            if floor {
                out.push(region);
            }
        }
    }
    out
}

/// Renders under `SEEDS` seeds.
fn renders(scene: &Scene, integrator: IntegratorKind) -> Vec<Image> {
    (0..SEEDS)
        .map(|seed| {
            job(scene, &settings(integrator, seed))
                .render(None, &|_| {})
                .unwrap()
                .image
        })
        .collect()
}

/// Renders under this many seeds give each region's noise.
const SEEDS: u64 = 8;

/// Student's t for 7 degrees of freedom at two-sided 99.9 %: 5.41; with
/// some 30 regions of 3 channels, 6.
const T: f64 = 6.0;

/// Each region's mean over the seeds against the method of images, per
/// channel: within `T` standard errors (from the seeds' spread) plus the
/// kernel's bias at these radii (the smoothed closed form's distance from
/// the exact one; it is largest beside the mirror, where the disc reaches
/// the dark floor behind it), plus 2·10⁻⁴ for the `f32` image. The worst
/// errors are returned; a refusal names the region.
fn check(images: &[Image]) -> Result<Summary, String> {
    let scene = mirror_scene();
    let regions = regions(&scene, images);
    assert!(
        regions.len() >= 20,
        "{} regions on the floor",
        regions.len()
    );
    let mut summary = Summary::default();
    for (i, r) in regions.iter().enumerate() {
        let n = r.renders.len() as f64;
        let mean = r.renders.iter().sum::<DVec3>() / n;
        let var = r
            .renders
            .iter()
            .map(|m| (*m - mean).powf(2.0))
            .sum::<DVec3>()
            / (n - 1.0);
        let se = (var / n).powf(0.5);
        for c in 0..3 {
            let bias = (r.kernel[c] - r.exact[c]).abs();
            let allowed = T * se[c] + bias + 2e-4 * r.exact[c];
            let error = (mean[c] - r.exact[c]).abs();
            let beyond = (error - bias).max(0.0) / se[c].max(1e-12);
            summary.standard_errors = summary.standard_errors.max(beyond);
            summary.relative = summary.relative.max(error / r.exact[c]);
            summary.bias = summary.bias.max(bias / r.exact[c]);
            if error > allowed || error.is_nan() {
                return Err(format!(
                    "region {i} channel {c}: mean {:.5} vs the method of images' {:.5} \
                     (relative {:+.4}), allowed {:.5} ({T} × standard error {:.5} + kernel bias {:.5})",
                    mean[c] / 64.0,
                    r.exact[c] / 64.0,
                    mean[c] / r.exact[c] - 1.0,
                    allowed / 64.0,
                    se[c] / 64.0,
                    bias / 64.0
                ));
            }
        }
    }
    Ok(summary)
}

/// The worst of the regions and channels of a check that passed.
#[derive(Debug, Default)]
struct Summary {
    /// The error beyond the kernel's bias, in standard errors.
    standard_errors: f64,
    /// The error relative to the method of images.
    relative: f64,
    /// The kernel's bias relative to the method of images.
    bias: f64,
}

#[test]
fn photon_integrator_matches_the_method_of_images_within_its_noise_and_kernel_bias() {
    let images = renders(&mirror_scene(), IntegratorKind::Photon);
    let worst = check(&images).unwrap();
    eprintln!(
        "worst region and channel: {:.2} standard errors beyond the kernel's bias, \
         relative error {:.4}, kernel bias {:.4}",
        worst.standard_errors, worst.relative, worst.bias
    );
}

/// The same check fails for the path tracer: the mirror image's light is
/// not in it.
#[test]
fn path_tracer_misses_the_mirror_image_and_fails_the_same_check() {
    let images = renders(&mirror_scene(), IntegratorKind::Path);
    let refused = check(&images).expect_err("the path tracer cannot see the image light");
    eprintln!("{refused}");
}

/// Each photon law left out is caught: the mirror's Fresnel factor (the
/// image at intensity `I`, not `R I`), and photons stored without a
/// mirror (the direct light counted twice).
#[test]
fn photon_faults_fail_the_method_of_images() {
    for fault in [
        Fault::PhotonsUnweightedAtMirrors,
        Fault::PhotonsStoredBeforeAnyMirror,
    ] {
        let images = faults::with(fault, || renders(&mirror_scene(), IntegratorKind::Photon));
        let refused = check(&images).expect_err(&format!("{fault:?} is caught"));
        eprintln!("{fault:?}: {refused}");
    }
}

/// The photon pass and the camera paths give the same bits on 1 and on
/// several threads.
#[test]
fn photon_render_is_identical_on_one_and_several_threads() {
    let scene = mirror_scene();
    let s = settings(IntegratorKind::Photon, 5);
    let one = job(&scene, &s).render(Some(1), &|_| {}).unwrap().image;
    for threads in [2, 5] {
        let many = job(&scene, &s)
            .render(Some(threads), &|_| {})
            .unwrap()
            .image;
        let bits = |i: &Image| -> Vec<[u32; 3]> {
            i.pixels
                .iter()
                .map(|p| p.to_array().map(f32::to_bits))
                .collect()
        };
        assert_eq!(bits(&one), bits(&many), "{threads} threads");
    }
}

/// Where no mirror or glass can start a caustic, the photon integrator is
/// the path tracer, bit for bit: nothing is added, and no random number
/// is drawn for a pass.
#[test]
fn without_mirrors_or_glass_the_photon_integrator_is_the_path_tracer() {
    let scene = common::course_scene("shadow", 40, 30);
    let image = |integrator| {
        let s = Settings {
            spp: 4,
            ..settings(integrator, 1)
        };
        job(&scene, &s).render(Some(2), &|_| {}).unwrap().image
    };
    let (photon, path) = (image(IntegratorKind::Photon), image(IntegratorKind::Path));
    let differ = photon
        .pixels
        .iter()
        .zip(&path.pixels)
        .position(|(a, b)| a != b);
    assert_eq!(
        differ,
        None,
        "{:?}",
        differ.map(|i| (photon.pixels[i], path.pixels[i]))
    );
}

/// A directional light straight down on a mirror ball of radius `a` over
/// a Lambert floor: the light meeting the ball at `θ > 45°` from its top
/// reflects downwards and lands on the floor (a convex mirror never sees
/// itself), so the photons landing there carry `E ∫ R(θ) dA` over that
/// part of the ball's shadow disc, `dA = 2π a² sin θ cos θ dθ` (midpoint
/// rule, 20 000 steps): the flux the disc emission, its escape test and
/// the Fresnel weight give together, within 1.5 % (the sum of 200 000
/// photons varies by about 0.3 %). Photons kept at full flux at the
/// mirror fail it.
#[test]
fn a_mirror_ball_under_the_sun_sends_the_fresnel_weighted_flux_of_its_outer_ring_down() {
    let error = sun_on_a_mirror_ball();
    assert!(error < 0.015, "{error}");
    let unweighted = faults::with(Fault::PhotonsUnweightedAtMirrors, sun_on_a_mirror_ball);
    assert!(unweighted > 0.015, "the fault is caught: {unweighted}");
}

/// The largest relative error, per channel, of the flux landed on the
/// floor against the integral.
fn sun_on_a_mirror_ball() -> f64 {
    let (e, a) = (2.0_f64, 0.5_f64);
    let scene = parse(json!({
        "version": 1,
        "image": { "width": 4, "height": 3 },
        "camera": { "type": "course_pinhole" },
        "materials": {
            "floor": { "type": "lambert", "albedo": ALBEDO },
            "mirror": { "type": "conductor", "n": MIRROR_N, "kappa": MIRROR_KAPPA }
        },
        "objects": [
            { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor" },
            { "type": "sphere", "center": [0, 2, 0], "radius": a, "material": "mirror" }
        ],
        "lights": [ { "type": "directional", "towards": [0, 1, 0], "irradiance": [e, e, e] } ]
    }));
    let s = Settings {
        photon: PhotonSettings {
            photons: 200_000,
            passes: 1,
            radius: 0.05,
        },
        ..settings(IntegratorKind::Photon, 2)
    };
    let tracer = common::tracer(&scene, s).with_caustics();
    let caustics = tracer.caustics.as_ref().unwrap();
    let landed: DVec3 = caustics.passes[0]
        .map
        .photons()
        .iter()
        .map(|p| p.flux.as_dvec3())
        .sum();
    let steps = 20_000;
    let h = std::f64::consts::FRAC_PI_4 / steps as f64;
    let want: DVec3 = (0..steps)
        .map(|i| {
            let theta = std::f64::consts::FRAC_PI_4 + (i as f64 + 0.5) * h;
            let r = fresnel::conductor_rgb(theta.cos(), MIRROR_N, MIRROR_KAPPA);
            DVec3::from_array(r) * (std::f64::consts::TAU * a * a * theta.sin() * theta.cos() * h)
        })
        .sum::<DVec3>()
        * e;
    let error = (landed / want - DVec3::ONE).abs().max_element();
    eprintln!("landed {landed:.5} vs {want:.5}: {error:.4}");
    error
}
