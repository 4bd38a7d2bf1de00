//! A glass sphere with dispersion: the slides' three-eta trick (one index
//! per RGB channel) and a single index, each against the spectral answer,
//! rendered and measured.
//!
//! `cargo run --release -p techniques --example dispersion`
//!
//! The scene (`crates/techniques/scenes/dispersion_sphere.json`) is grey:
//! a white sky, a dark floor, black beads behind a sphere of N-BK7, one
//! white point light; so every render at one index is grey, and colour
//! comes from dispersion alone. The spectral answer renders the scene
//! (Whitted) once per sample of the CIE grid (360–780 nm every 5 nm) with
//! the sphere's index `n(λ)` by Sellmeier, takes each pixel's values over
//! λ as its spectrum under the light's D65, and converts it to linear sRGB
//! by the suite's CIE tables (`radiometry::spectrum`): a pixel the same at
//! every λ comes out grey, as in the other renders. The three-eta render
//! takes channel c from a render at `n(λ_c)`, `λ_c` the CIE RGB primaries
//! (700, 546.1, 435.8 nm); the single index is `n_d` (587.56 nm).
//!
//! Measured over the pixels that see the sphere: ΔE2000 of the displayed
//! images (8-bit sRGB, CIELAB under D65) against the spectral one, mean
//! and 99th percentile, and the relative RMSE of linear radiance. The table
//! is the section `dispersion` of `docs/results.md`; the pictures are
//! written to `docs/images/dispersion-*.png` by `main` only.

use std::path::Path;

use glam::Vec3;
use radiometry::colour::{
    d65_white, delta_e_2000, linear_srgb_to_xyz, srgb_decode, xyz_to_lab, xyz_to_linear_srgb, Lab,
};
use radiometry::spectrum::{self, SAMPLES};
use techniques::dispersion::{fraunhofer_nm, CIE_RGB_PRIMARIES_NM, SELLMEIER_N_BK7};
use tracer::job::RenderJob;
use tracer::output::{to_srgb8, write_png};
use tracer::render::Image;
use tracer::scene::{self, Material, Scene};

/// The scene with the sphere's glass at index `n`.
fn at_index(scene: &Scene, n: f64) -> Scene {
    let mut scene = scene.clone();
    for material in &mut scene.materials {
        if let Material::Dielectric { eta } = material {
            *eta = n as f32;
        }
    }
    scene
}

fn render(scene: &Scene) -> Image {
    RenderJob::with_settings(scene.clone(), scene.settings)
        .expect("renderable")
        .render(None, &|_| {})
        .expect("thread pool")
        .image
}

fn index(nm: f64) -> f64 {
    SELLMEIER_N_BK7
        .index_at(nm)
        .expect("N-BK7 is tabulated over the CIE grid")
}

/// Each pixel's spectrum (the grey renders' green channel at each λ) as
/// linear sRGB under D65.
fn spectral(scene: &Scene) -> Image {
    let renders: Vec<Image> = (0..SAMPLES)
        .map(|i| render(&at_index(scene, index(spectrum::wavelength_nm(i)))))
        .collect();
    let pixels = (0..renders[0].pixels.len())
        .map(|p| {
            let response: [f64; SAMPLES] =
                std::array::from_fn(|i| f64::from(renders[i].pixels[p].y));
            let [r, g, b] = xyz_to_linear_srgb(spectrum::reflectance_to_xyz(&response));
            Vec3::new(r as f32, g as f32, b as f32)
        })
        .collect();
    Image {
        width: renders[0].width,
        height: renders[0].height,
        pixels,
    }
}

/// Channel c from a render at `n(λ_c)`.
fn three_etas(scene: &Scene) -> Image {
    let [r, g, b] = CIE_RGB_PRIMARIES_NM.map(|nm| render(&at_index(scene, index(nm))));
    let pixels = (0..r.pixels.len())
        .map(|p| Vec3::new(r.pixels[p].x, g.pixels[p].y, b.pixels[p].z))
        .collect();
    Image {
        width: r.width,
        height: r.height,
        pixels,
    }
}

/// A pixel as its PNG displays it, in CIELAB.
fn displayed(pixel: Vec3) -> Lab {
    let shown = pixel
        .to_array()
        .map(|c| srgb_decode(f64::from(to_srgb8(c)) / 255.0));
    xyz_to_lab(linear_srgb_to_xyz(shown), d65_white())
}

/// ΔE2000 mean and 99th percentile, and the relative RMSE, of `image`
/// against `truth` over the pixels `keep` says.
fn measures(image: &Image, truth: &Image, keep: &[bool]) -> (f64, f64, f64) {
    let mut delta_e: Vec<f64> = Vec::new();
    let (mut error, mut total) = (0.0, 0.0);
    for (p, _) in keep.iter().enumerate().filter(|(_, k)| **k) {
        let (a, t) = (image.pixels[p].as_dvec3(), truth.pixels[p].as_dvec3());
        delta_e.push(delta_e_2000(
            displayed(image.pixels[p]),
            displayed(truth.pixels[p]),
        ));
        error += (a - t).length_squared();
        total += t.length_squared();
    }
    delta_e.sort_by(f64::total_cmp);
    let mean = delta_e.iter().sum::<f64>() / delta_e.len() as f64;
    let p99 = delta_e[((0.99 * delta_e.len() as f64).ceil() as usize).clamp(1, delta_e.len()) - 1];
    (mean, p99, (error / total).sqrt())
}

struct Renders {
    spectral: Image,
    three: Image,
    single: Image,
    sphere: Vec<bool>,
}

fn renders() -> Renders {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/dispersion_sphere.json");
    let scene = scene::load(&path).expect("the dispersion scene");
    let job = RenderJob::with_settings(scene.clone(), scene.settings).expect("renderable");
    let glass = scene
        .materials
        .iter()
        .position(|m| matches!(m, Material::Dielectric { .. }))
        .expect("a glass");
    let sphere = job
        .first_hits()
        .iter()
        .map(|hit| {
            hit.is_some_and(|object| scene.objects[object as usize].material() == glass as u32)
        })
        .collect();
    Renders {
        spectral: spectral(&scene),
        three: three_etas(&scene),
        single: render(&at_index(&scene, index(fraunhofer_nm::D))),
        sphere,
    }
}

fn table() -> String {
    let r = renders();
    let mut t = String::from(
        "| the sphere's index | ΔE2000 mean | ΔE2000 p99 | relative RMSE |\n|---|---:|---:|---:|\n",
    );
    let [nr, ng, nb] = CIE_RGB_PRIMARIES_NM.map(index);
    for (what, image) in [
        (
            format!("three etas ({nr:.5}, {ng:.5}, {nb:.5} at 700, 546.1, 435.8 nm)"),
            &r.three,
        ),
        (
            format!("one index, n_d = {:.5}", index(fraunhofer_nm::D)),
            &r.single,
        ),
    ] {
        let (mean, p99, rmse) = measures(image, &r.spectral, &r.sphere);
        t.push_str(&format!("| {what} | {mean:.2} | {p99:.2} | {rmse:.4} |\n"));
    }
    t.push_str(&format!(
        "\n{} of {} pixels see the sphere; the spectral answer renders it at {SAMPLES} wavelengths.\n",
        r.sphere.iter().filter(|k| **k).count(),
        r.sphere.len()
    ));
    t
}

fn pictures() {
    let r = renders();
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/images");
    for (name, image) in [
        ("spectral", &r.spectral),
        ("three-etas", &r.three),
        ("single-index", &r.single),
    ] {
        write_png(&dir.join(format!("dispersion-{name}.png")), image).expect("docs/images");
    }
}

fn main() {
    let table = table();
    println!("{table}");
    results::assert_settled(&results::Section::deterministic(
        "dispersion",
        "cargo run --release -p techniques --example dispersion",
        &table,
    ));
    pictures();
}

#[test]
fn committed_table_is_current() {
    results::assert_settled(&results::Section::deterministic(
        "dispersion",
        "cargo run --release -p techniques --example dispersion",
        &table(),
    ));
}
