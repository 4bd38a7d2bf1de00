//! The accuracy budget's prediction: from a cheap pilot pass, an upper
//! bound on the relative RMSE of linear radiance ([`super::measure`]) that
//! a render at given settings reaches against the ground truth, and the
//! cheapest settings, in rays, whose bound stays under a tolerance
//! ([`choose_among`], for any metric). The displayed image's measures are
//! bounded by simulated renders in [`displayed`].
//!
//! # The bound
//!
//! A render `x` of the surface pixel-channels `i` at `N` samples per pixel
//! differs from the truth `t` by a bias and a noise:
//! `x_i − t_i = b_i + ε_i`, `E[ε_i] = 0`, `Var ε_i = σ_i² / N`, so the
//! squared error the measure takes has the expectation
//! `Σ b_i² + Σ σ_i² / N` and the spread of a sum of independent terms.
//!
//! The pilot renders each candidate and the *pilot reference* (the truth's
//! settings) as two halves of `h` samples each, seeds `s` and `s + 1`:
//!
//! - **bias**: `B = Σ (m_c − m_r)²` of the two means. Its expectation is
//!   `Σ b_i²` *plus* the variance of the difference, never less: the
//!   pilot's noise can only make the bias look larger. Everything a
//!   setting leaves out (the light past `max_depth`, Schlick's error at
//!   the angles this scene produces, the light an integrator misses, the
//!   centre instead of the box filter) is in it, measured at the
//!   render's own size and pixels.
//! - **noise**: `S = Σ h (a_c − b_c)² / 2`, an unbiased estimate of
//!   `Σ σ_i²` per sample; stratified samples only lower `σ²` as `N` grows,
//!   so `S / N` is conservative too.
//! - **energy**: `Σ m_r² − Σ (a_r − b_r)² / 4`, unbiased for `Σ t_i²`.
//!
//! Each sum is one of independent terms, whose standard deviation is
//! estimated by `√(2 Σ w²)` for terms `w` (a weighted χ² with one degree of
//! freedom each: mean `Σ w`, variance `2 Σ w²`; the single draws
//! overestimate `Σ w²` threefold, on the safe side). The prediction takes
//! each at [`K`] standard deviations on its unsafe side, the final render's
//! own noise fluctuation and the bias–noise cross term `2 Σ b ε` as well:
//!
//! ```text
//! squared = B + K √(2 Σ d⁴)  +  (S + 2 K √(2 Σ w²)) / N  +  2 K √(Σ d² w / N)
//! rel_rmse ≤ √(squared / (E − K √(Σ 4 m_r² v_r)))
//! ```
//!
//! A deterministic setting has no noise term: its two halves agree.

use serde::Serialize;
use tracer::render::Image;

use super::measure::Mask;

pub mod displayed;
mod tolerance;
pub use tolerance::written;

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

/// The predicted error of one candidate at its samples.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Prediction {
    /// Samples per pixel (`None`: a deterministic candidate's own).
    pub spp: Option<u32>,
    /// The bias part, relative: `√(B_up / E)`.
    pub bias: f64,
    /// The noise part at `spp` with the cross term, relative.
    pub noise: f64,
    /// The bound on the relative RMSE: `√(bias² + noise²)`.
    pub rel_rmse: f64,
    /// Rays one render casts.
    pub rays: f64,
}

/// `pilot`'s predicted error at `spp` samples per pixel (ignored for a
/// deterministic candidate) against a truth of energy `energy`.
pub fn predict(pilot: &Pilot, energy: f64, spp: u32) -> Prediction {
    let bias_squared = pilot.bias.upper();
    let (spp, noise_squared) = if pilot.samples {
        (Some(spp), noise_squared(pilot, f64::from(spp)))
    } else {
        (None, 0.0)
    };
    let bias = (bias_squared / energy).sqrt();
    let noise = (noise_squared / energy).sqrt();
    Prediction {
        spp,
        bias,
        noise,
        rel_rmse: bias.hypot(noise),
        rays: pilot.rays.at(spp.unwrap_or(0)),
    }
}

/// The squared noise bound of a sampling `pilot` at `n` samples per
/// pixel, with the bias–noise cross term.
fn noise_squared(pilot: &Pilot, n: f64) -> f64 {
    let noise = pilot.noise.sum + 2.0 * K * (2.0 * pilot.noise.squares).sqrt();
    let cross = 2.0 * K * (pilot.cross / n).sqrt();
    noise / n + cross
}

/// The samples per pixel the budget renders `pilot` at, from its
/// `fewest_spp` up to `max_spp` (and its `most_spp`): the powers of two,
/// `[1]` for a deterministic candidate.
fn ladder(pilot: &Pilot, max_spp: u32) -> Vec<u32> {
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

/// What would bring a candidate within a tolerance it misses at the
/// samples the budget allows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(tag = "need", rename_all = "snake_case")]
pub enum Need {
    /// More samples: the fewest per pixel, a power of two as the budget
    /// renders them, at which its prediction is within the tolerance.
    Samples {
        /// That power of two.
        spp: u64,
    },
    /// No samples: its bias alone is predicted above the tolerance (or it
    /// is deterministic).
    Never,
    /// No samples: the floor of a displayed measure, simulated with no
    /// noise of the candidate's own (its bias, the pilot's noise and the
    /// ground truth's), is predicted above the tolerance.
    Floor,
    /// None it can take: its noise stops falling past these samples per
    /// pixel (a caustic map at its most photons).
    Capped {
        /// The pilot's `most_spp`.
        spp: u32,
    },
}

/// The fewest samples per pixel, a power of two with no cap, at which
/// `pilot` is predicted within `tolerance`; or why none is.
pub fn need(pilot: &Pilot, energy: f64, tolerance: f64) -> Need {
    let bias_squared = pilot.bias.upper() / energy;
    let room = tolerance * tolerance - bias_squared;
    if !pilot.samples || room <= 0.0 {
        return Need::Never;
    }
    if pilot.most_spp < u32::MAX {
        return Need::Capped {
            spp: pilot.most_spp,
        };
    }
    (0..64)
        .map(|k| 1u64 << k)
        .filter(|&n| n >= u64::from(pilot.fewest_spp))
        .find(|&n| noise_squared(pilot, n as f64) / energy <= room)
        .map_or(Need::Never, |spp| Need::Samples { spp })
}

/// The fewest samples per pixel, a power of two up to `max_spp` (and the
/// pilot's `most_spp`), at which
/// `pilot` is predicted within `tolerance`; a deterministic candidate
/// within it as it is; `None` where neither is.
pub fn cheapest(pilot: &Pilot, energy: f64, tolerance: f64, max_spp: u32) -> Option<Prediction> {
    ladder(pilot, max_spp)
        .into_iter()
        .map(|n| predict(pilot, energy, n))
        .find(|p| p.rel_rmse <= tolerance)
}

/// A prediction of one candidate at its samples, whatever its metric:
/// the bound it puts on the metric and what the render costs.
pub trait Bound: Copy {
    /// The bound on the metric.
    fn bound(&self) -> f64;
    /// Rays one render casts.
    fn rays(&self) -> f64;
}

impl Bound for Prediction {
    fn bound(&self) -> f64 {
        self.rel_rmse
    }

    fn rays(&self) -> f64 {
        self.rays
    }
}

impl Bound for displayed::Prediction {
    fn bound(&self) -> f64 {
        self.bound
    }

    fn rays(&self) -> f64 {
        self.rays
    }
}

/// What the budget decides among candidates.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(tag = "outcome", rename_all = "snake_case")]
pub enum Choice<P = Prediction> {
    /// The candidate (its index) that costs the fewest rays within the
    /// tolerance, at its samples.
    Chosen {
        /// Its index among the candidates.
        index: usize,
        /// Its prediction.
        prediction: P,
    },
    /// No candidate is predicted within the tolerance: the one with the
    /// smallest prediction, at the most samples the budget would render
    /// it at (a power of two).
    Unreachable {
        /// Its index among the candidates.
        index: usize,
        /// Its prediction.
        prediction: P,
        /// What it would need to reach the tolerance.
        need: Need,
    },
}

/// The cheapest of `pilots` within `tolerance` (ties: the smaller
/// prediction, then the earlier candidate), or the best of them when none
/// is; `None` only for no candidates.
pub fn choose(pilots: &[Pilot], energy: f64, tolerance: f64, max_spp: u32) -> Option<Choice> {
    choose_among(
        pilots.len(),
        |i| cheapest(&pilots[i], energy, tolerance, max_spp),
        |i| predict(&pilots[i], energy, top_spp(&pilots[i], max_spp)),
        |i| need(&pilots[i], energy, tolerance),
    )
}

/// The choice among `count` candidates, of any metric: the cheapest in
/// rays of those `cheapest` finds within the tolerance (ties: the smaller
/// bound, then the earlier candidate), or else the smallest `best` (each
/// at the most samples the budget renders it at) with its `need`; `None`
/// only for no candidates.
pub fn choose_among<P: Bound>(
    count: usize,
    cheapest: impl Fn(usize) -> Option<P>,
    best: impl Fn(usize) -> P,
    need: impl Fn(usize) -> Need,
) -> Option<Choice<P>> {
    let within = (0..count)
        .filter_map(|i| cheapest(i).map(|q| (i, q)))
        .min_by(|(_, a), (_, b)| {
            a.rays()
                .total_cmp(&b.rays())
                .then(a.bound().total_cmp(&b.bound()))
        });
    if let Some((index, prediction)) = within {
        return Some(Choice::Chosen { index, prediction });
    }
    (0..count)
        .map(|i| (i, best(i)))
        .min_by(|(_, a), (_, b)| a.bound().total_cmp(&b.bound()))
        .map(|(index, prediction)| Choice::Unreachable {
            index,
            prediction,
            need: need(index),
        })
}

#[cfg(test)]
mod tests;
