//! The difference map: each pixel's largest score as a colour, on the
//! scale of the report's render figures.
//!
//! **Scale** (linear values, shown through the PNG's sRGB encoding):
//! a score `s` in `[0, 1]` is `(√s, s², 0)`, black at 0 through red to
//! yellow at 1 (at what the test allows); above 1, disagreeing, magenta
//! `(1, 0, 1)`; a pixel not compared (masked) dark blue `(0, 0, 0.08)`.

use glam::Vec3;
use tracer::render::Image;

use super::verdicts::Verdicts;

/// The scale in words, for the reports beside the map.
pub const LEGEND: &str =
    "each pixel's largest score over its channels (|difference| over what the \
    test allows): black 0, through red, to yellow at 1; magenta above 1 (disagrees); dark blue \
    not compared (masked)";

/// [`LEGEND`] in Hungarian.
pub const LEGEND_HU: &str =
    "minden képpont legnagyobb értéke a csatornái közül (|eltérés| a teszt által megengedetthez \
    képest): fekete 0, vörösön át sárga 1-nél; bíbor 1 fölött (nem egyezik); sötétkék: nincs \
    összehasonlítva (maszkolt)";

/// The colour of a pixel whose channels have `scores` (NaN: not compared).
pub fn heat_colour(scores: &[f64]) -> Vec3 {
    let compared: Vec<f64> = scores.iter().copied().filter(|s| !s.is_nan()).collect();
    if compared.is_empty() {
        return Vec3::new(0.0, 0.0, 0.08);
    }
    let worst = compared.iter().copied().fold(0.0, f64::max);
    if !(worst <= 1.0) {
        Vec3::new(1.0, 0.0, 1.0)
    } else {
        let t = worst as f32;
        Vec3::new(t.sqrt(), t * t, 0.0)
    }
}

/// The map of `verdicts` over a `width × height` image. A pixel whose
/// every channel was compared but whose score is NaN (a value that is not
/// a number) disagrees: magenta.
pub fn difference_map(verdicts: &Verdicts, width: u32, height: u32) -> Image {
    let pixels = (0..(width * height) as usize)
        .map(|p| {
            let channels = 3 * p..3 * p + 3;
            if channels.clone().any(|i| verdicts.disagrees(i)) {
                Vec3::new(1.0, 0.0, 1.0)
            } else {
                heat_colour(&verdicts.score[channels])
            }
        })
        .collect();
    Image {
        width,
        height,
        pixels,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_scale_runs_black_red_yellow_then_magenta() {
        assert_eq!(heat_colour(&[0.0, 0.0, 0.0]), Vec3::ZERO);
        assert_eq!(
            heat_colour(&[0.25, 0.0, f64::NAN]),
            Vec3::new(0.5, 0.0625, 0.0)
        );
        assert_eq!(heat_colour(&[1.0, 0.5, 0.0]), Vec3::new(1.0, 1.0, 0.0));
        assert_eq!(heat_colour(&[1.01, 0.0, 0.0]), Vec3::new(1.0, 0.0, 1.0));
        assert_eq!(heat_colour(&[f64::NAN; 3]), Vec3::new(0.0, 0.0, 0.08));
    }
}
