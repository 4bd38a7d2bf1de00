//! What the pilot measures of each candidate against the pilot reference
//! (the bias, the noise per sample and their cross term, with the spread
//! of each sum), the truth's energy, and the samples per pixel the budget
//! renders a candidate at.

use serde::Serialize;
use tracer::render::Image;

use crate::tradeoff::measure::Mask;

/// Standard deviations taken on the unsafe side of each estimated sum:
/// 3, a one-sided 99.87 % bound for each where the sums are near normal.
pub const K: f64 = 3.0;

/// A sum of independent non-negative terms, with what its spread needs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Sum {
    /// `Σ w`.
    pub sum: f64,
    /// `Σ w²`.
    pub squares: f64,
}

impl Sum {
    fn add(&mut self, w: f64) {
        self.sum += w;
        self.squares += w * w;
    }

    /// `Σ w + K √(2 Σ w²)`: the sum at [`K`] standard deviations up.
    pub fn upper(&self) -> f64 {
        self.sum + K * (2.0 * self.squares).sqrt()
    }
}

/// The rays one render of a candidate casts: a part that does not grow
/// with the samples (the photon map) and one per sample per pixel.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Rays {
    /// Rays cast once per render, whatever the samples.
    pub fixed: f64,
    /// Rays per sample per pixel, over the whole image.
    pub per_sample: f64,
}

impl Rays {
    /// The rays of a render at `spp` samples per pixel.
    pub fn at(&self, spp: u32) -> f64 {
        self.fixed + self.per_sample * f64::from(spp)
    }
}

/// What the pilot measured of one candidate against the pilot reference.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Pilot {
    /// `Σ (m_c − m_r)²` over the surface pixel-channels.
    pub bias: Sum,
    /// `Σ σ²` per sample, `h (a_c − b_c)² / 2` per pixel-channel; zero for
    /// a deterministic candidate.
    pub noise: Sum,
    /// `Σ d² w`, for the bias–noise cross term.
    pub cross: f64,
    /// Whether the candidate takes random samples (its error falls with
    /// `N`); a deterministic one renders its own settings only.
    pub samples: bool,
    /// What one render costs.
    pub rays: Rays,
    /// The most samples per pixel at which the noise still falls as
    /// `1 / N` (a caustic map that cannot grow with the samples past its
    /// cap); `u32::MAX` where nothing caps it.
    pub most_spp: u32,
    /// The fewest samples per pixel it is predicted at: a half's. Its
    /// variance per sample is measured on means of that many samples;
    /// fewer have heavier tails than the halves show (gold_spheres at
    /// 16×12, T 0.2, seed 2 predicted ≤ 0.1908 at 1 spp from halves of 4
    /// and reached 0.2135), so the bound is not taken below it.
    pub fewest_spp: u32,
}

impl Pilot {
    /// The pilot of a candidate from its two halves `candidate` and the
    /// reference's `reference` (each pair seeds `s` and `s + 1`), rendered
    /// at `half_spp` samples per pixel each, over `mask`.
    ///
    /// # Panics
    ///
    /// If the images differ in size: the pilot renders all at one size.
    pub fn measure(
        candidate: [&Image; 2],
        reference: [&Image; 2],
        mask: &Mask,
        half_spp: u32,
        samples: bool,
        rays: Rays,
    ) -> Self {
        let (mut bias, mut noise, mut cross) = (Sum::default(), Sum::default(), 0.0);
        for i in mask.kept() {
            let [a_c, b_c] = candidate.map(|im| im.pixels[i].as_dvec3());
            let [a_r, b_r] = reference.map(|im| im.pixels[i].as_dvec3());
            let d = (a_c + b_c) / 2.0 - (a_r + b_r) / 2.0;
            let w = f64::from(half_spp) * (a_c - b_c) * (a_c - b_c) / 2.0;
            for (d, w) in d.to_array().into_iter().zip(w.to_array()) {
                bias.add(d * d);
                noise.add(w);
                cross += d * d * w;
            }
        }
        Pilot {
            bias,
            noise,
            cross,
            samples,
            rays,
            most_spp: u32::MAX,
            fewest_spp: half_spp.max(1),
        }
    }
}

/// The truth's energy `Σ t²`, estimated from the reference's two halves
/// at [`K`] standard deviations down; `None` where that is not above 0
/// (no light the pilot can see: a relative error is not defined).
pub fn energy(reference: [&Image; 2], mask: &Mask) -> Option<f64> {
    let (mut sum, mut spread) = (0.0, 0.0);
    for i in mask.kept() {
        let [a, b] = reference.map(|im| im.pixels[i].as_dvec3());
        let m = (a + b) / 2.0;
        let v = (a - b) * (a - b) / 4.0;
        sum += (m * m - v).element_sum();
        spread += (4.0 * m * m * v).element_sum();
    }
    let low = sum - K * spread.sqrt();
    (low > 0.0).then_some(low)
}

/// The samples per pixel the budget renders `pilot` at, from its
/// `fewest_spp` up to `max_spp` (and its `most_spp`): the powers of two,
/// `[1]` for a deterministic candidate.
pub(super) fn ladder(pilot: &Pilot, max_spp: u32) -> Vec<u32> {
    let max_spp = max_spp.min(pilot.most_spp);
    if !pilot.samples {
        return vec![1];
    }
    std::iter::successors(Some(1u32), |&n| n.checked_mul(2))
        .take_while(|&n| n <= max_spp)
        .filter(|&n| n >= pilot.fewest_spp)
        .collect()
}

/// The most samples per pixel the budget would render `pilot` at: the
/// largest power of two within `max_spp` and the pilot's `most_spp`.
pub fn top_spp(pilot: &Pilot, max_spp: u32) -> u32 {
    ladder(pilot, max_spp).last().copied().unwrap_or(1)
}
