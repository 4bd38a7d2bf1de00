//! Where an image disagrees: per region (a label per pixel, such as the
//! object the camera sees there), the pixels compared and disagreeing and
//! the mean and worst difference; and the regions' silhouettes, where a
//! pixel's neighbours see another region and a float32 difference in one
//! intersection moves a whole object.

use serde::Serialize;

use super::verdicts::Verdicts;

/// One region's summary. A pixel disagrees when any of its channels does.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Region {
    /// The region's label index.
    pub region: usize,
    /// Pixels compared.
    pub pixels: usize,
    /// Pixels masked (not compared).
    pub masked: usize,
    /// Pixels that disagree.
    pub disagreeing: usize,
    /// Mean of image − reference over the compared pixel-channels.
    pub mean_difference: f64,
    /// Mean of |image − reference| over them.
    pub mean_abs_difference: f64,
    /// `Σ (image − reference) / Σ |reference|` over them: how much
    /// brighter (> 0) or darker the region is, as a fraction.
    pub relative_difference: f64,
    /// The difference of largest magnitude (signed).
    pub worst_difference: f64,
    /// Its score (in units of what the test allows).
    pub worst_score: f64,
    /// Where: column, row, channel (`R`, `G`, `B`).
    pub worst_at: Option<(u32, u32, char)>,
}

/// The whole image's summary and each region's.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Summary {
    /// Pixels compared.
    pub pixels: usize,
    /// Pixels that disagree.
    pub disagreeing: usize,
    /// `disagreeing / pixels` (0 when none is compared).
    pub fraction: f64,
    /// Each region that has pixels, in label order.
    pub regions: Vec<Region>,
}

impl Summary {
    /// Whether every compared pixel agrees.
    pub fn agrees(&self) -> bool {
        self.disagreeing == 0
    }
}

/// Summarises `verdicts` (a flat RGB image `width` wide) over `labels`,
/// one per pixel below `count`; `reference` is in the verdicts' unit.
pub fn summarise(
    verdicts: &Verdicts,
    labels: &[usize],
    count: usize,
    width: u32,
    reference: &[f64],
) -> Summary {
    let mut regions: Vec<Region> = (0..count)
        .map(|region| Region {
            region,
            pixels: 0,
            masked: 0,
            disagreeing: 0,
            mean_difference: 0.0,
            mean_abs_difference: 0.0,
            relative_difference: 0.0,
            worst_difference: 0.0,
            worst_score: 0.0,
            worst_at: None,
        })
        .collect();
    let mut reference_sum = vec![0.0; count];
    for (pixel, &label) in labels.iter().enumerate() {
        let r = &mut regions[label];
        if !verdicts.compared[3 * pixel] {
            r.masked += 1;
            continue;
        }
        r.pixels += 1;
        r.disagreeing += usize::from((0..3).any(|c| verdicts.disagrees(3 * pixel + c)));
        for c in 0..3 {
            let i = 3 * pixel + c;
            let d = verdicts.difference[i];
            r.mean_difference += d;
            r.mean_abs_difference += d.abs();
            reference_sum[label] += reference[i].abs();
            if r.worst_at.is_none() || !(d.abs() <= r.worst_difference.abs()) {
                r.worst_difference = d;
                r.worst_score = verdicts.score[i];
                let (x, y) = (pixel as u32 % width, pixel as u32 / width);
                r.worst_at = Some((x, y, ['R', 'G', 'B'][c]));
            }
        }
    }
    for (r, sum) in regions.iter_mut().zip(reference_sum) {
        r.relative_difference = r.mean_difference / sum;
        let channels = (3 * r.pixels).max(1) as f64;
        r.mean_difference /= channels;
        r.mean_abs_difference /= channels;
    }
    let pixels = regions.iter().map(|r| r.pixels).sum();
    let disagreeing = regions.iter().map(|r| r.disagreeing).sum();
    Summary {
        pixels,
        disagreeing,
        fraction: disagreeing as f64 / (pixels as f64).max(1.0),
        regions: regions
            .into_iter()
            .filter(|r| r.pixels + r.masked > 0)
            .collect(),
    }
}

/// The pixels of a `width × height` label map one of whose eight
/// neighbours has another label.
pub fn silhouettes(labels: &[usize], width: u32, height: u32) -> Vec<bool> {
    let (w, h) = (width as i64, height as i64);
    (0..labels.len())
        .map(|p| {
            let (x, y) = (p as i64 % w, p as i64 / w);
            (-1..=1).any(|dy| {
                (-1..=1).any(|dx| {
                    let (nx, ny) = (x + dx, y + dy);
                    (0..w).contains(&nx)
                        && (0..h).contains(&ny)
                        && labels[(ny * w + nx) as usize] != labels[p]
                })
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compare::{tolerance, Tolerance};

    #[test]
    fn a_brighter_region_is_found_and_measured() {
        // Two pixels of region 0, two of region 1; region 1 is 3 % brighter.
        let reference = vec![0.5; 12];
        let mut image = reference.clone();
        for v in &mut image[6..] {
            *v *= 1.03;
        }
        let v = tolerance::radiance(&image, &reference, None, Tolerance::RENDERS, 0.01, None);
        let summary = summarise(&v, &[0, 0, 1, 1], 2, 2, &reference);
        assert_eq!(
            (summary.pixels, summary.disagreeing, summary.fraction),
            (4, 2, 0.5)
        );
        let [quiet, bright] = summary.regions.as_slice() else {
            panic!("{summary:?}")
        };
        assert_eq!((quiet.disagreeing, bright.disagreeing), (0, 2));
        // 3 % of 0.5, within a few roundings.
        assert!(
            (bright.relative_difference - 0.03).abs() < 1e-12,
            "{bright:?}"
        );
        assert!((bright.mean_difference - 0.015).abs() < 1e-12);
        assert_eq!(bright.worst_at, Some((0, 1, 'R')));
        assert_eq!(quiet.mean_abs_difference, 0.0);
    }

    #[test]
    fn silhouettes_are_the_pixels_beside_another_label() {
        // 4 × 3, a one-pixel object at (1, 1): it and its eight neighbours.
        let mut labels = vec![0; 12];
        labels[5] = 1;
        let edges = silhouettes(&labels, 4, 3);
        let expected: Vec<bool> = (0..12).map(|p| p % 4 <= 2).collect();
        assert_eq!(edges, expected);
    }
}
