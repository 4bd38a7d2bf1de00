//! The report's render figures: ours | Mitsuba | the difference.

use tracer::render::Image;
use tracer::scene::Scene;

use crate::compare::map::heat_colour;

/// The white columns between a triptych's panels, pixels.
pub const TRIPTYCH_GAP: u32 = 4;

/// A triptych for the report: ours | Mitsuba | the difference in units of
/// the tolerance, each panel enlarged.
#[derive(Clone, Debug)]
pub struct RenderFigure {
    /// File name under `figures/`.
    pub file: String,
    /// Linear radiance to be written as sRGB PNG.
    pub image: Image,
}

/// Ours | Mitsuba | heat map, each panel enlarged 4×. The heat map shows a
/// pixel's largest channel in units of its tolerance on the scale of
/// [`crate::compare::map`]: black (0) through red to yellow (1, at
/// tolerance), magenta beyond; masked pixels dark blue.
pub(super) fn triptych(
    name: &str,
    integrator: &str,
    scene: &Scene,
    ours: &[f64],
    mitsuba: &[f64],
    heat: &[f64],
) -> RenderFigure {
    const SCALE: u32 = 4;
    const GAP: u32 = TRIPTYCH_GAP;
    let (w, h) = (scene.width, scene.height);
    let width = 3 * w * SCALE + 2 * GAP;
    let height = h * SCALE;
    let mut pixels = vec![glam::Vec3::ONE; (width * height) as usize];
    let rgb = |v: &[f64], p: usize| {
        glam::Vec3::new(v[3 * p] as f32, v[3 * p + 1] as f32, v[3 * p + 2] as f32)
    };
    for y in 0..height {
        for x in 0..3 * w * SCALE + 2 * GAP {
            let panel = x / (w * SCALE + GAP);
            let px = x % (w * SCALE + GAP);
            if px >= w * SCALE {
                continue;
            }
            let p = ((y / SCALE) * w + px / SCALE) as usize;
            pixels[(y * width + x) as usize] = match panel {
                0 => rgb(ours, p),
                1 => rgb(mitsuba, p),
                _ => heat_colour(&heat[3 * p..3 * p + 3]),
            };
        }
    }
    RenderFigure {
        file: format!("render_{name}_{integrator}.png"),
        image: Image {
            width,
            height,
            pixels,
        },
    }
}
