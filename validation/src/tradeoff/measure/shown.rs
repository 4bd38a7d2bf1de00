//! The measures of the displayed image: ΔE2000 of each pixel as the PNG
//! shows it, in CIELAB under D65, and ꟻLIP of the 8-bit frame.

use radiometry::colour::{d65_white, delta_e_2000, linear_srgb_to_xyz, srgb_decode, xyz_to_lab};
use tracer::output::{srgb8, to_srgb8};
use tracer::render::Image;

use super::mask::Mask;

/// The measures of the displayed image of the renders `images` of one
/// setting against `truth` over `mask`, each the mean over the renders:
/// ΔE2000's mean and 99th percentile, and ꟻLIP's mean.
pub(super) fn shown(images: &[Image], truth: &Image, mask: &Mask) -> (f64, f64, f64) {
    let n = images.len() as f64;
    let displayed_truth = displayed(truth, mask);
    let shown_truth = srgb8(truth);
    let mut delta_e_mean = 0.0;
    let mut delta_e_p99 = 0.0;
    let mut flip_mean = 0.0;
    for image in images {
        let map = crate::flip::error_map(&shown_truth, &srgb8(image), image.width, image.height);
        flip_mean += crate::flip::mean(&map, Some(&mask.0)) / n;
        let mut de: Vec<f64> = displayed(image, mask)
            .iter()
            .zip(&displayed_truth)
            .map(|(&a, &b)| delta_e_2000(a, b))
            .collect();
        delta_e_mean += de.iter().sum::<f64>() / de.len().max(1) as f64 / n;
        delta_e_p99 += percentile(&mut de, 0.99) / n;
    }
    (delta_e_mean, delta_e_p99, flip_mean)
}

/// The `q`-quantile (0 to 1) of `values`, the nearest rank; 0 for none.
pub fn percentile(values: &mut [f64], q: f64) -> f64 {
    if values.is_empty() {
        return 0.0;
    }
    values.sort_by(f64::total_cmp);
    let rank = (q * values.len() as f64).ceil() as usize;
    values[rank.clamp(1, values.len()) - 1]
}

/// The kept pixels as the PNG displays them, in CIELAB (D65).
fn displayed(image: &Image, mask: &Mask) -> Vec<radiometry::colour::Lab> {
    let white = d65_white();
    mask.kept()
        .map(|i| {
            let shown = image.pixels[i]
                .to_array()
                .map(|c| srgb_decode(f64::from(to_srgb8(c)) / 255.0));
            xyz_to_lab(linear_srgb_to_xyz(shown), white)
        })
        .collect()
}
