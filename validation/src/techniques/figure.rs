//! The techniques' pictures: the shortcut, the traced truth and their
//! difference side by side, as the report and `docs/images` show them.

use glam::Vec3;
use tracer::render::Image;

use crate::renders::{RenderFigure, TRIPTYCH_GAP};

/// How much the difference panel is amplified: a tenth of the radiance
/// range shows at about 40 % grey.
pub const DIFFERENCE_GAIN: f32 = 4.0;

/// `DIFFERENCE_GAIN × |a − b|`, per channel.
pub fn difference(a: &Image, b: &Image) -> Image {
    Image {
        width: a.width,
        height: a.height,
        pixels: a
            .pixels
            .iter()
            .zip(&b.pixels)
            .map(|(p, q)| (*p - *q).abs() * DIFFERENCE_GAIN)
            .collect(),
    }
}

/// `shortcut | truth | DIFFERENCE_GAIN × |shortcut − truth|`, each panel
/// enlarged `scale` times without smoothing, [`TRIPTYCH_GAP`] white
/// columns apart, named `file` under the report's `figures/`.
pub fn strip(file: &str, shortcut: &Image, truth: &Image, scale: u32) -> RenderFigure {
    let panels = [shortcut, truth, &difference(shortcut, truth)];
    let (w, h) = (truth.width * scale, truth.height * scale);
    let count = panels.len() as u32;
    let width = count * w + (count - 1) * TRIPTYCH_GAP;
    let mut pixels = vec![Vec3::ONE; (width * h) as usize];
    for y in 0..h {
        for x in 0..width {
            let (k, px) = (x / (w + TRIPTYCH_GAP), x % (w + TRIPTYCH_GAP));
            if px < w {
                let p = ((y / scale) * truth.width + px / scale) as usize;
                pixels[(y * width + x) as usize] = panels[k as usize].pixels[p];
            }
        }
    }
    RenderFigure {
        file: file.to_owned(),
        image: Image {
            width,
            height: h,
            pixels,
        },
        panels: count,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each panel holds its image's pixel at every enlarged position, and
    /// the gaps are white.
    #[test]
    fn the_strip_places_each_panel_enlarged() {
        let image = |v: f32| Image {
            width: 2,
            height: 1,
            pixels: vec![Vec3::splat(v), Vec3::splat(v / 2.0)],
        };
        let f = strip("t.png", &image(0.5), &image(0.25), 3);
        assert_eq!(
            (f.image.width, f.image.height),
            (3 * 6 + 2 * TRIPTYCH_GAP, 3)
        );
        assert_eq!(f.image.pixels[0], Vec3::splat(0.5));
        assert_eq!(f.image.pixels[3], Vec3::splat(0.25));
        assert_eq!(f.image.pixels[6], Vec3::ONE);
        let third = (2 * (6 + TRIPTYCH_GAP)) as usize;
        assert_eq!(f.image.pixels[third], Vec3::splat(0.25 * DIFFERENCE_GAIN));
    }
}
