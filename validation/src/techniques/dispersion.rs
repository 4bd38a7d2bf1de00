//! A glass sphere with dispersion, rendered: the slides' three-eta trick
//! (one index per RGB channel) and a single index, each against the
//! spectral answer.
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
//! Measured over the pixels that see the sphere by the suite's fixed
//! measures ([`crate::tradeoff::measure`], those of `optics tradeoff`):
//! ΔE2000 of the displayed images against the spectral one, mean and 99th
//! percentile, and the relative RMSE of linear radiance.

use std::path::Path;

use glam::Vec3;
use radiometry::colour::xyz_to_linear_srgb;
use radiometry::spectrum::{self, SAMPLES};
use techniques::dispersion::{fraunhofer_nm, CIE_RGB_PRIMARIES_NM, SELLMEIER_N_BK7};
use tracer::job::RenderJob;
use tracer::render::Image;
use tracer::scene::{self, Material, Scene};

use crate::tradeoff::measure::{errors, Errors, Mask, Truth};

/// The scene with the sphere's glass at index `n`.
pub fn at_index(scene: &Scene, n: f64) -> Scene {
    let mut scene = scene.clone();
    for material in &mut scene.materials {
        if let Material::Dielectric { eta } = material {
            *eta = n as f32;
        }
    }
    scene
}

/// The scene rendered under its own settings.
pub fn render(scene: &Scene) -> Image {
    RenderJob::with_settings(scene.clone(), scene.settings)
        .expect("renderable")
        .render(None, &|_| {})
        .expect("thread pool")
        .image
}

/// N-BK7's index at `nm` nanometres.
pub fn index(nm: f64) -> f64 {
    SELLMEIER_N_BK7
        .index_at(nm)
        .expect("N-BK7 is tabulated over the CIE grid")
}

/// Each pixel's spectrum (the grey renders' green channel at each λ) as
/// linear sRGB under D65.
pub fn spectral(scene: &Scene) -> Image {
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
pub fn three_etas(scene: &Scene) -> Image {
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

/// `image` against the spectral render by the suite's fixed measures
/// ([`crate::tradeoff::measure`]: relative RMSE of radiance, ΔE2000 of the
/// displayed image, ꟻLIP) over the pixels that see the sphere.
pub fn measures(image: &Image, r: &Renders) -> Errors {
    let mask = Mask::from_hits(&r.sphere);
    errors(
        std::slice::from_ref(image),
        &Truth::new(r.spectral.clone(), 0.0, &mask),
        &mask,
    )
}

/// The three renders compared, and where the sphere is.
pub struct Renders {
    /// The spectral answer.
    pub spectral: Image,
    /// The three etas.
    pub three: Image,
    /// One index, `n_d`.
    pub single: Image,
    /// Each pixel's first hit where it is the sphere, `None` elsewhere.
    pub sphere: Vec<Option<u32>>,
}

/// The dispersion scene rendered the three ways.
pub fn renders() -> Renders {
    renders_with(three_etas)
}

/// [`renders`] with the three-eta render made by `three` (a parameter, so
/// that a wrong one can be shown to be caught).
pub fn renders_with(three: fn(&Scene) -> Image) -> Renders {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../crates/techniques/scenes/dispersion_sphere.json");
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
        .map(|hit| hit.filter(|&object| scene.objects[object as usize].material() == glass as u32))
        .collect();
    Renders {
        spectral: spectral(&scene),
        three: three(&scene),
        single: render(&at_index(&scene, index(fraunhofer_nm::D))),
        sphere,
    }
}
