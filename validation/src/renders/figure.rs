//! The report's render figures: ours | Mitsuba | ꟻLIP | the difference,
//! and the mask of the pixels not compared where there are any.

use glam::Vec3;
use tracer::render::Image;
use tracer::scene::Scene;

use crate::compare::map::heat_colour;
use crate::flip;

/// The white columns between a figure's panels, pixels.
pub const TRIPTYCH_GAP: u32 = 4;

/// How much each panel is enlarged.
const SCALE: u32 = 4;

/// A render compared, for the report: its panels side by side, each
/// enlarged, ours first and Mitsuba's second.
#[derive(Clone, Debug)]
pub struct RenderFigure {
    /// File name under `figures/`.
    pub file: String,
    /// Linear radiance to be written as sRGB PNG.
    pub image: Image,
    /// How many panels stand side by side, [`TRIPTYCH_GAP`] apart.
    pub panels: u32,
}

/// Ours | Mitsuba | ꟻLIP | heat map \[| mask\], each panel enlarged 4×.
///
/// - ꟻLIP: the LDR ꟻLIP error map of ours against Mitsuba's (both as their
///   PNGs display them) on ꟻLIP's own magma scale, 0 black to 1 pale
///   yellow ([`flip::magma`]);
/// - the heat map: a pixel's largest channel in units of its tolerance on
///   the scale of [`crate::compare::map`] (black 0, red, yellow at the
///   tolerance, magenta beyond; dark blue not compared);
/// - the mask, only where some pixel was not compared (`heat` NaN in every
///   channel: a Whitted check's edge pixels): white where masked.
pub(super) fn triptych(
    name: &str,
    integrator: &str,
    scene: &Scene,
    ours: &[f64],
    mitsuba: &[f64],
    heat: &[f64],
) -> RenderFigure {
    let (w, h) = (scene.width, scene.height);
    let rgb =
        |v: &[f64], p: usize| Vec3::new(v[3 * p] as f32, v[3 * p + 1] as f32, v[3 * p + 2] as f32);
    let image = |v: &[f64]| Image {
        width: w,
        height: h,
        pixels: (0..(w * h) as usize).map(|p| rgb(v, p)).collect(),
    };
    let ldr = |v: &[f64]| tracer::output::srgb8(&image(v));
    let flip_map = flip::error_map(&ldr(mitsuba), &ldr(ours), w, h);
    let masked = |p: usize| heat[3 * p..3 * p + 3].iter().all(|s| s.is_nan());
    let any_masked = (0..(w * h) as usize).any(masked);
    let panels = if any_masked { 5 } else { 4 };
    // Each panel's colours once per pixel, then enlarged.
    let colours: Vec<Vec<Vec3>> = (0..panels)
        .map(|k| {
            (0..(w * h) as usize)
                .map(|p| match k {
                    0 => rgb(ours, p),
                    1 => rgb(mitsuba, p),
                    2 => flip::magma(flip_map[p]),
                    3 => heat_colour(&heat[3 * p..3 * p + 3]),
                    _ => Vec3::splat(if masked(p) { 1.0 } else { 0.0 }),
                })
                .collect()
        })
        .collect();
    let panel = |k: u32, p: usize| colours[k as usize][p];
    let width = panels * w * SCALE + (panels - 1) * TRIPTYCH_GAP;
    let height = h * SCALE;
    let mut pixels = vec![Vec3::ONE; (width * height) as usize];
    for y in 0..height {
        for x in 0..width {
            let (k, px) = (
                x / (w * SCALE + TRIPTYCH_GAP),
                x % (w * SCALE + TRIPTYCH_GAP),
            );
            if px < w * SCALE {
                let p = ((y / SCALE) * w + px / SCALE) as usize;
                pixels[(y * width + x) as usize] = panel(k, p);
            }
        }
    }
    RenderFigure {
        file: format!("render_{name}_{integrator}.png"),
        image: Image {
            width,
            height,
            pixels,
        },
        panels,
    }
}
