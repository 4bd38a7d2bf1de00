//! The accuracy budget for the measures of the displayed image (ΔE2000
//! mean and 99th percentile, ꟻLIP): no sum of squares bounds them, since
//! the image is clamped, quantised to 8 bits and seen through CIELAB or
//! ꟻLIP's filters, so the final render is *simulated* from the pilot and
//! measured with the sweep's own code ([`measure::errors`]), never a
//! second copy of ΔE or ꟻLIP.
//!
//! # The simulation
//!
//! Per pixel-channel the pilot has the candidate's halves `a_c, b_c` and
//! the truth's settings' `a_r, b_r`, `h` samples each, the pair of each
//! half on one seed. From them, each variance the larger of its own
//! one-degree-of-freedom estimate and the mean over its 3 × 3
//! neighbourhood (a 99th percentile is set by the pixels whose variance
//! one draw underestimates most):
//!
//! - the candidate's mean `m_c`, the truth's settings' `m_r`;
//! - `σ_c² = h (a_c − b_c)² / 2`, the candidate's variance per sample
//!   (0 for a deterministic one), and `σ_r²` alike;
//! - `v_d = ((a_c − a_r) − (b_c − b_r))² / 4`, the variance of the pilot's
//!   estimate `m_c − m_r` of the bias (its two halves share their paths,
//!   so this is less than `v_c + v_r` where the candidate follows the
//!   truth's paths);
//! - `v_r = (a_r − b_r)² / 4`, the variance of `m_r` about the truth.
//!
//! Draw `k` of [`DRAWS`], with standard normal `z` from a fixed generator
//! (the same draws for every candidate and sample count):
//!
//! ```text
//! truth  t_k  = m_r + √v_r z₁
//! render x_k  = t_k + (m_c − m_r) + √(σ_c² / N + σ_r² / N_truth) z₂
//! again  x'_k = x_k + √v_d z₃
//! ```
//!
//! The render's noise at `N` spp is the pilot's per-sample variance over
//! `N`; the ground truth `--verify` measures against has its own at
//! `N_truth` samples and is counted too (ΔE, unlike the RMSE, cannot take
//! it out). The level `m_r` is redrawn (`z₁`) so that clamping and the
//! steep dark end of sRGB see levels as uncertain as the pilot's.
//!
//! # The bound
//!
//! The bound is the largest measure of `x_k` against `t_k` plus [`super::K`]
//! standard deviations of the measures of `x'_k` against `t_k`:
//!
//! - the observed bias `m_c − m_r` carries the pilot's noise (variance
//!   `v_d`). A mean of per-pixel distances only grows with added
//!   zero-mean noise (Jensen: a distance is convex in the offset, where
//!   ΔE is near linear), so in expectation over pilots the measure of
//!   `x_k` errs high;
//! - the one pilot rendered sits somewhere in that spread: each `x'_k`
//!   holds one more realisation of the pilot's noise, the final render's
//!   and the level's, so the deviation of their measures says how far
//!   from its expectation the measure of one pilot can be, and the
//!   margin takes 3 of them.
//!
//! Counting the pilot's noise twice instead (`x'_k` for the value too)
//! would be safe but sets a floor that only more pilot samples lower:
//! with two halves of 2 samples, noise of half-width 0.6 per sample
//! reads as a mean ΔE of 12 where the bias alone shows 1.

use glam::{DVec3, Vec3};
use serde::Serialize;
use tracer::render::Image;

use super::need::Need;
use super::pilot::{ladder, Pilot, K};
use crate::tradeoff::measure::{self, Errors, Mask, Truth};

/// Simulated final renders per prediction.
pub const DRAWS: u64 = 8;

/// A measure of the displayed image the budget can predict.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Shown {
    /// Mean ΔE2000.
    DeltaEMean,
    /// 99th percentile of ΔE2000.
    DeltaEP99,
    /// Mean ꟻLIP.
    FlipMean,
}

impl Shown {
    /// Its value among the sweep's measures.
    pub fn of(self, errors: &Errors) -> f64 {
        match self {
            Shown::DeltaEMean => errors.delta_e_mean,
            Shown::DeltaEP99 => errors.delta_e_p99,
            Shown::FlipMean => errors.flip_mean,
        }
    }
}

/// The truth's settings as the pilot rendered them, shared by every
/// candidate, and the samples of the ground truth predicted against.
pub struct Reference {
    halves: [Image; 2],
    mean: Image,
    /// `v_r`: the variance of `m_r` about the truth.
    level: Vec<Vec3>,
    /// `σ_r²`: the variance per sample.
    per_sample: Vec<Vec3>,
    mask: Mask,
    truth_spp: u32,
}

impl Reference {
    /// From the truth's settings' two halves of `half_spp` samples, the
    /// pixels measured, and the ground truth's samples per pixel.
    pub fn new(halves: [&Image; 2], half_spp: u32, mask: &Mask, truth_spp: u32) -> Self {
        let [a, b] = halves;
        let h = f64::from(half_spp);
        let level = variance(a, |i| {
            let d = a.pixels[i].as_dvec3() - b.pixels[i].as_dvec3();
            d * d / 4.0
        });
        let per_sample = level.iter().map(|&v| v * (2.0 * h) as f32).collect();
        Reference {
            halves: [a.clone(), b.clone()],
            mean: mean(a, b),
            level,
            per_sample,
            mask: mask.clone(),
            truth_spp,
        }
    }
}

/// One candidate's pilot, ready to be simulated at any samples.
pub struct Simulation {
    pilot: Pilot,
    mean: Image,
    /// `σ_c²`, zero for a deterministic candidate.
    per_sample: Vec<Vec3>,
    /// `v_d`: the variance of `m_c − m_r`.
    pilot_noise: Vec<Vec3>,
}

/// A candidate's predicted measure at its samples.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Prediction {
    /// Samples per pixel (`None`: a deterministic candidate's own).
    pub spp: Option<u32>,
    /// The largest of the simulated measures.
    pub simulated: f64,
    /// [`K`] standard deviations of the simulated measures.
    pub margin: f64,
    /// The bound: `simulated + margin`.
    pub bound: f64,
    /// Rays one render casts.
    pub rays: f64,
}

impl Simulation {
    /// From the candidate's two halves (`half_spp` samples each, the
    /// seeds of the reference's) and what [`Pilot::measure`] made of them.
    ///
    /// # Panics
    ///
    /// If the images differ in size from the reference's.
    pub fn new(candidate: [&Image; 2], reference: &Reference, half_spp: u32, pilot: Pilot) -> Self {
        let [a, b] = candidate;
        let [ra, rb] = &reference.halves;
        let h = f64::from(half_spp);
        let per_sample = if pilot.samples {
            variance(a, |i| {
                let d = a.pixels[i].as_dvec3() - b.pixels[i].as_dvec3();
                h * d * d / 2.0
            })
        } else {
            vec![Vec3::ZERO; a.pixels.len()]
        };
        let pilot_noise = variance(a, |i| {
            let first = a.pixels[i].as_dvec3() - ra.pixels[i].as_dvec3();
            let second = b.pixels[i].as_dvec3() - rb.pixels[i].as_dvec3();
            (first - second) * (first - second) / 4.0
        });
        Simulation {
            pilot,
            mean: mean(a, b),
            per_sample,
            pilot_noise,
        }
    }

    /// The predicted `measure` at `n` samples per pixel (`f64::INFINITY`:
    /// the floor no samples pass; ignored for a deterministic candidate):
    /// the largest of the draws with the pilot's noise as observed, and
    /// [`K`] standard deviations of the draws with it drawn once more.
    fn at(&self, reference: &Reference, measure: Shown, n: f64) -> (f64, f64) {
        let measured = |truth: Image, render: Image| {
            let truth = Truth::new(truth, 0.0, &reference.mask);
            measure.of(&measure::errors(&[render], &truth, &reference.mask))
        };
        let (mut largest, mut redrawn) = (0.0_f64, Vec::new());
        for k in 0..DRAWS {
            let [truth, render, again] = self.draw(reference, n, k);
            largest = largest.max(measured(truth.clone(), render));
            redrawn.push(measured(truth, again));
        }
        let count = redrawn.len() as f64;
        let mean = redrawn.iter().sum::<f64>() / count;
        let spread = redrawn.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (count - 1.0);
        (largest, K * spread.sqrt())
    }

    /// Draw `k` at `n` spp: the truth `t_k`, the render `x_k`, and `x_k`
    /// with the pilot's noise drawn once more.
    fn draw(&self, reference: &Reference, n: f64, k: u64) -> [Image; 3] {
        let mut normal = Normal::new(k);
        let final_noise = |i: usize| {
            let own = if self.pilot.samples {
                self.per_sample[i] / n as f32
            } else {
                Vec3::ZERO
            };
            own + reference.per_sample[i] / reference.truth_spp as f32
        };
        let (mut truth, mut render, mut again) = (Vec::new(), Vec::new(), Vec::new());
        for i in 0..self.mean.pixels.len() {
            let t = reference.mean.pixels[i] + reference.level[i].powf(0.5) * normal.vec3();
            let bias = self.mean.pixels[i] - reference.mean.pixels[i];
            let x = t + bias + final_noise(i).powf(0.5) * normal.vec3();
            truth.push(t);
            render.push(x);
            again.push(x + self.pilot_noise[i].powf(0.5) * normal.vec3());
        }
        [truth, render, again].map(|pixels| Image {
            width: self.mean.width,
            height: self.mean.height,
            pixels,
        })
    }

    /// The prediction at `spp` samples per pixel (ignored for a
    /// deterministic candidate).
    pub fn predict(&self, reference: &Reference, measure: Shown, spp: u32) -> Prediction {
        let spp = self.pilot.samples.then_some(spp);
        let (simulated, margin) = self.at(reference, measure, f64::from(spp.unwrap_or(1)));
        Prediction {
            spp,
            simulated,
            margin,
            bound: simulated + margin,
            rays: self.pilot.rays.at(spp.unwrap_or(0)),
        }
    }

    /// The fewest samples per pixel, a power of two up to `max_spp` (and
    /// the pilot's `most_spp`), predicted within `tolerance`, found by
    /// bisection over the powers of two (the simulated noise shrinks with
    /// the samples, draw by draw); `None` where none is.
    pub fn cheapest(
        &self,
        reference: &Reference,
        measure: Shown,
        tolerance: f64,
        max_spp: u32,
    ) -> Option<Prediction> {
        let ladder = ladder(&self.pilot, max_spp);
        let within =
            |spp: u32| Some(self.predict(reference, measure, spp)).filter(|p| p.bound <= tolerance);
        let top = within(*ladder.last()?)?;
        let (mut low, mut high, mut best) = (0, ladder.len() - 1, top);
        // Invariant: ladder[high] is within (its prediction `best`).
        while low < high {
            let middle = (low + high) / 2;
            match within(ladder[middle]) {
                Some(p) => (high, best) = (middle, p),
                None => low = middle + 1,
            }
        }
        Some(best)
    }

    /// The fewest samples per pixel, a power of two with no cap, at which
    /// the candidate is predicted within `tolerance`; or why none is.
    pub fn need(&self, reference: &Reference, measure: Shown, tolerance: f64) -> Need {
        let within = |n: f64| {
            let (simulated, margin) = self.at(reference, measure, n);
            simulated + margin <= tolerance
        };
        if !self.pilot.samples || self.floor(reference, measure) > tolerance {
            return Need::Floor;
        }
        if self.pilot.most_spp < u32::MAX {
            return Need::Capped {
                spp: self.pilot.most_spp,
            };
        }
        let fewest = self.pilot.fewest_spp.next_power_of_two().trailing_zeros();
        let (mut low, mut high) = (fewest.min(40), 40u32);
        if !within((1u64 << high) as f64) {
            return Need::Floor;
        }
        while low < high {
            let middle = (low + high) / 2;
            if within((1u64 << middle) as f64) {
                high = middle;
            } else {
                low = middle + 1;
            }
        }
        Need::Samples { spp: 1 << high }
    }

    /// The bound with no noise of the candidate's own (its bias, the
    /// pilot's noise, the truth's): what no samples pass.
    pub fn floor(&self, reference: &Reference, measure: Shown) -> f64 {
        let (simulated, margin) = self.at(reference, measure, f64::INFINITY);
        simulated + margin
    }

    /// The pilot it was made from.
    pub fn pilot(&self) -> &Pilot {
        &self.pilot
    }
}

/// The mean of two images.
fn mean(a: &Image, b: &Image) -> Image {
    Image {
        width: a.width,
        height: a.height,
        pixels: a
            .pixels
            .iter()
            .zip(&b.pixels)
            .map(|(p, q)| (*p + *q) / 2.0)
            .collect(),
    }
}

/// A variance map of `like`'s size from its per-pixel estimate `raw`, each
/// pixel-channel the larger of its own and its 3 × 3 neighbourhood's mean:
/// one degree of freedom alone reads zero for a fifth of the pixels
/// (P(χ²₁ < 0.064) = 0.2), nine pooled rarely below half the variance.
fn variance(like: &Image, raw: impl Fn(usize) -> DVec3) -> Vec<Vec3> {
    let (w, h) = (like.width as i64, like.height as i64);
    let raw: Vec<DVec3> = (0..like.pixels.len()).map(raw).collect();
    (0..like.pixels.len())
        .map(|i| {
            let (x, y) = (i as i64 % w, i as i64 / w);
            let (mut sum, mut count) = (DVec3::ZERO, 0.0);
            for (dx, dy) in (-1..=1).flat_map(|dx| (-1..=1).map(move |dy| (dx, dy))) {
                let (u, v) = (x + dx, y + dy);
                if (0..w).contains(&u) && (0..h).contains(&v) {
                    sum += raw[(v * w + u) as usize];
                    count += 1.0;
                }
            }
            raw[i].max(sum / count).as_vec3()
        })
        .collect()
}

/// Standard normal numbers from a fixed xorshift generator and the
/// Box–Muller transform: draw `k` is the same for every candidate.
struct Normal(u64);

impl Normal {
    fn new(k: u64) -> Self {
        Normal(0x9e37_79b9_7f4a_7c15 ^ (k + 1).wrapping_mul(0xbf58_476d_1ce4_e5b9))
    }

    /// Uniform on (0, 1].
    fn uniform(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        ((self.0 >> 11) + 1) as f64 / (1u64 << 53) as f64
    }

    fn vec3(&mut self) -> Vec3 {
        Vec3::from_array([(); 3].map(|()| {
            let (u, v) = (self.uniform(), self.uniform());
            ((-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()) as f32
        }))
    }
}

#[cfg(test)]
mod tests;
