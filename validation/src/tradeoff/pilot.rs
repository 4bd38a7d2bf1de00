//! The budget's candidates and their pilot pass: the settings it may
//! choose, in the sweep's vocabulary (`RenderSpec` settled over the
//! truth's settings), each rendered as two cheap halves beside the
//! truth's settings at the same samples and seeds.

use std::path::Path;

use super::budget::{Pilot, Rays};
use super::error::TradeoffError;
use super::measure::Mask;
use super::render::render;
use super::sweep;
use serde::Serialize;
use tracer::job::RenderJob;
use tracer::render::Rendered;
use tracer::scene::{FresnelModel, IntegratorKind, PixelFilter, RenderSpec, Settings};

use super::sweep::SCHLICK_SWEPT;

/// The bounce limits a candidate may take, up to the truth's.
const DEPTHS: [u32; 6] = [1, 2, 4, 8, 16, 32];

/// The throughput cutoffs a candidate may take, above the truth's: the
/// path tracer's Russian roulette below them, unbiased, so a cutoff buys
/// fewer rays per sample for more noise per sample, both of which the
/// pilot measures.
const CUTOFFS: [f32; 2] = [1e-2, 1e-1];

/// What a candidate leaves out of the truth's settings: the terms of its
/// bias, each measured alone by the pilot where the candidate has one.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Shortcut {
    /// The scene's own settings, whatever they leave out.
    Scene,
    /// The truth's settings (only the samples differ).
    None,
    /// A bounce limit below the truth's: the light past it.
    MaxDepth,
    /// Schlick's law for the exact one, at the angles this scene produces.
    Schlick,
    /// Both of the above.
    MaxDepthAndSchlick,
    /// A cheaper integrator (with its own pixel filter): the light it
    /// misses.
    Integrator,
    /// A throughput cutoff above the truth's: Russian roulette ends more
    /// paths (no bias in expectation; fewer rays, more noise).
    Cutoff,
}

/// One setting the budget may choose.
#[derive(Clone, Debug, Serialize)]
pub struct Candidate {
    /// What it leaves out.
    pub shortcut: Shortcut,
    /// Its settings, `spp` the pilot's half for a sampling candidate.
    pub settings: Settings,
}

impl Candidate {
    /// Whether its error falls with the samples (random paths, or a box
    /// filter's jittered rays).
    pub fn samples(&self) -> bool {
        self.settings.integrator.samples() || self.settings.pixel_filter == PixelFilter::Box
    }
}

/// The candidates for `job`'s scene against the truth's settings
/// `truth`: the scene's own first, then the truth's with each bounce limit
/// and (where the scene has mirrors or glass) Schlick's law, then
/// `whitted` and `local` where they can render it; no two alike.
pub fn candidates(job: &RenderJob, truth: &Settings) -> Vec<Candidate> {
    let mut list: Vec<Candidate> = vec![Candidate {
        shortcut: Shortcut::Scene,
        settings: *job.settings(),
    }];
    let mut add = |shortcut: Shortcut, spec: RenderSpec| {
        let Ok(settings) = truth.settle("budget", &spec) else {
            return;
        };
        let renderable = RenderJob::with_settings(job.scene().clone(), settings).is_ok();
        let new = !list.iter().any(|c| same_but_spp(&c.settings, &settings));
        if renderable && new {
            list.push(Candidate { shortcut, settings });
        }
    };
    let smooth = job.needs().conductors || job.needs().refraction;
    let laws: &[FresnelModel] = if smooth {
        &[FresnelModel::Exact, SCHLICK_SWEPT]
    } else {
        &[FresnelModel::Exact]
    };
    let depths = DEPTHS.iter().copied().filter(|&d| d < truth.max_depth);
    for depth in depths.map(Some).chain([None]) {
        for &fresnel in laws {
            let shortcut = match (depth.is_some(), fresnel == SCHLICK_SWEPT) {
                (false, false) => Shortcut::None,
                (true, false) => Shortcut::MaxDepth,
                (false, true) => Shortcut::Schlick,
                (true, true) => Shortcut::MaxDepthAndSchlick,
            };
            let spec = RenderSpec {
                max_depth: depth.map(f64::from),
                fresnel: Some(fresnel.into()),
                ..RenderSpec::default()
            };
            add(shortcut, spec);
        }
    }
    let cutoffs = CUTOFFS.iter().filter(|&&c| c > truth.throughput_cutoff);
    for &cutoff in cutoffs {
        let spec = RenderSpec {
            throughput_cutoff: Some(f64::from(cutoff)),
            ..RenderSpec::default()
        };
        add(Shortcut::Cutoff, spec);
    }
    for integrator in [IntegratorKind::Whitted, IntegratorKind::Local] {
        let spec = RenderSpec {
            integrator: Some(integrator),
            // The integrator's own filter, the pixel centre.
            pixel_filter: Some(PixelFilter::default_for(integrator)),
            spp: Some(1.0),
            ..RenderSpec::default()
        };
        add(Shortcut::Integrator, spec);
    }
    list
}

/// Whether two settings differ at most in their samples.
pub fn same_but_spp(a: &Settings, b: &Settings) -> bool {
    Settings { spp: b.spp, ..*a } == *b
}

/// The pilot pass: its pilots, the reference's two halves, what it cast.
pub struct Pass {
    /// One per candidate, in order.
    pub pilots: Vec<Pilot>,
    /// Each candidate's two halves, in order, where they were kept (a
    /// displayed measure's simulation needs them); empty otherwise.
    pub halves: Vec<[tracer::render::Image; 2]>,
    /// The truth's settings' two halves.
    pub reference: [tracer::render::Image; 2],
    /// Rays cast by the whole pass.
    pub rays: u64,
}

/// Renders the truth's settings and every candidate as two halves of
/// `half_spp` samples (seeds `seed` and `seed + 1`; a candidate that does
/// not sample at its own) and measures each against the truth's; each
/// candidate's halves are kept where `keep` says so.
pub fn run(
    job: &RenderJob,
    file: &Path,
    (truth, candidates): (&Settings, &[Candidate]),
    (half_spp, mask, keep): (u32, &Mask, bool),
    threads: Option<usize>,
) -> Result<Pass, TradeoffError> {
    let mut rays = 0;
    let mut halves = |settings: &Settings, samples: bool| -> Result<[Rendered; 2], TradeoffError> {
        let at = |seed: u64| Settings {
            spp: if samples { half_spp } else { settings.spp },
            seed,
            ..*settings
        };
        let first = render(job, file, at(settings.seed), threads)?;
        let second = render(job, file, at(settings.seed.wrapping_add(1)), threads)?;
        rays += first.rays.total() + second.rays.total();
        Ok([first, second])
    };
    let [a, b] = halves(truth, true)?;
    let reference = [a.image, b.image];
    let mut pilots = Vec::with_capacity(candidates.len());
    let mut images = Vec::with_capacity(candidates.len());
    for candidate in candidates {
        let samples = candidate.samples();
        let [a, b] = halves(&candidate.settings, samples)?;
        let total = a.rays.total() as f64;
        // The caustic map's photons grow with the samples (see
        // `scaled_photons`), so its rays count per sample too.
        let cost = if samples {
            Rays {
                fixed: 0.0,
                per_sample: total / f64::from(half_spp),
            }
        } else {
            Rays {
                fixed: total,
                per_sample: 0.0,
            }
        };
        let mut pilot = Pilot::measure(
            [&a.image, &b.image],
            [&reference[0], &reference[1]],
            mask,
            half_spp,
            samples,
            cost,
        );
        if samples && candidate.settings.integrator == IntegratorKind::Photon {
            let p = &candidate.settings.photon;
            let most = tracer::scene::MAX_PHOTONS / p.passes.max(1);
            let spp = u64::from(half_spp) * u64::from(most) / u64::from(p.photons.max(1));
            pilot.most_spp = spp.min(u64::from(u32::MAX)) as u32;
        }
        pilots.push(pilot);
        if keep {
            images.push([a.image, b.image]);
        }
    }
    Ok(Pass {
        pilots,
        halves: images,
        reference,
        rays,
    })
}

/// The settings of a sampling candidate piloted at `half_spp` and
/// rendered at `spp`: the caustic map's photons per pass scaled by
/// `spp / half_spp` (at least 1, at most what the passes allow), so that
/// its noise, like the paths', falls as 1 / spp and the pilot's
/// per-sample variance holds for both: a map of fixed size would keep
/// its noise at any spp. Its radii, and so its bias, stay the truth's.
pub fn scaled_photons(settings: &Settings, half_spp: u32, spp: u32) -> Settings {
    if settings.integrator != IntegratorKind::Photon {
        return Settings { spp, ..*settings };
    }
    let most = tracer::scene::MAX_PHOTONS / settings.photon.passes.max(1);
    let photons = u64::from(settings.photon.photons) * u64::from(spp) / u64::from(half_spp);
    let mut scaled = Settings { spp, ..*settings };
    scaled.photon.photons = (photons.clamp(1, u64::from(most))) as u32;
    scaled
}

/// The truth's settings for `job`: the sweep's ground truth at `spp`.
pub fn truth_settings(job: &RenderJob, spp: u32) -> Settings {
    sweep::truth_settings(job, spp)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tradeoff::sweep::tests::job;

    fn cutoffs(truth: &Settings, job: &RenderJob) -> Vec<f32> {
        candidates(job, truth)
            .iter()
            .filter(|c| c.shortcut == Shortcut::Cutoff)
            .map(|c| c.settings.throughput_cutoff)
            .collect()
    }

    #[test]
    fn the_roulette_cutoffs_above_the_truths_are_candidates_and_none_below() {
        let job = job("glass_spheres");
        let truth = truth_settings(&job, 4);
        assert_eq!(truth.throughput_cutoff, 1e-3);
        assert_eq!(cutoffs(&truth, &job), CUTOFFS.to_vec());
        // Each differs from the truth in its cutoff alone (and its samples).
        for c in candidates(&job, &truth) {
            if c.shortcut == Shortcut::Cutoff {
                let same = Settings {
                    throughput_cutoff: truth.throughput_cutoff,
                    ..c.settings
                };
                assert!(same_but_spp(&same, &truth), "{:?}", c.settings);
            }
        }
        // A truth already at the larger cutoff offers none at or below it.
        let coarse = Settings {
            throughput_cutoff: 1e-1,
            ..truth
        };
        assert!(cutoffs(&coarse, &job).is_empty());
    }
}
