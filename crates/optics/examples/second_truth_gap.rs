//! Where the sweep's truth and Mitsuba's part on `kaleidoscope_lit`
//! (`docs/tradeoffs.md`, "Mitsuba's renders are a second truth"): the
//! truth's settings ([`validation::tradeoff::sweep::truth_settings`]) varied one
//! at a time (the bounce limit, the caustic photon map's photons and
//! radius, the map left out) and each render held, over the harness's
//! `diffuse` region, against each of Mitsuba's estimates in the reference:
//! the light share `Σx / ΣM` with Mitsuba's standard error
//! ([`validation::tradeoff::mitsuba`], which block-averages the render to
//! the reference's size as the sweep does).
//!
//! ```text
//! cargo run --release -p optics --example second_truth_gap -- [SPP] [RENDERS] [THREADS]
//! ```
//!
//! 160 × 120 with course_rough made Lambert, as `optics tradeoff
//! --lambert` measures the scene; each row `RENDERS` (default 4) renders
//! of `SPP` (default 32) samples per pixel, seeds 0, 1, ..., the same
//! seeds in every row, so the rows differ by the setting more than by the
//! noise; `THREADS` default 2. The region's interior (its pixels whose
//! eight neighbours are in it) and edge are held against the ptracer's
//! per-pixel mean, which carries no passes.

use std::path::Path;

use tracer::job::{Overrides, RenderJob};
use tracer::scene::{IntegratorKind, Settings};
use validation::checkout::{Lookup, ENV};
use validation::full_light::{decode, Estimate, FullLight, Region, RegionMean, FILE};
use validation::tradeoff::mitsuba::{
    box_downsample, light_share, reference_for, region_light, Reference,
};

const SCENE: &str = "kaleidoscope_lit";

/// One row: a name and how it varies the truth's settings.
type Variation = (&'static str, fn(Settings) -> Settings);

const VARIATIONS: [Variation; 7] = [
    ("truth (max_depth 64)", |s| s),
    ("max_depth 16 (the reference's)", |s| Settings {
        max_depth: 16,
        ..s
    }),
    ("max_depth 17 (Mitsuba's 18 as run)", |s| Settings {
        max_depth: 17,
        ..s
    }),
    ("photon radius / 2", |s| Settings {
        photon: tracer::scene::PhotonSettings {
            radius: s.photon.radius / 2.0,
            ..s.photon
        },
        ..s
    }),
    ("photon radius × 2", |s| Settings {
        photon: tracer::scene::PhotonSettings {
            radius: s.photon.radius * 2.0,
            ..s.photon
        },
        ..s
    }),
    ("photons × 4", |s| Settings {
        photon: tracer::scene::PhotonSettings {
            photons: s.photon.photons * 4,
            ..s.photon
        },
        ..s
    }),
    ("path (no caustic map)", |s| Settings {
        integrator: IntegratorKind::Path,
        ..s
    }),
];

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let (spp, renders, threads) = arguments()?;
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../tracer/scenes/{SCENE}.json"));
    let sized = RenderJob::load(
        &file,
        &Overrides {
            width: Some(160),
            height: Some(120),
            ..Overrides::default()
        },
    )?;
    let scene = sized.scene().course_rough_as_lambert();
    let job = RenderJob::with_settings(scene.clone(), *sized.settings())?;
    let truth = validation::tradeoff::sweep::truth_settings(&job, spp);

    let dir = Lookup {
        env: std::env::var_os(ENV),
        cwd: std::env::current_dir()?,
        ..Lookup::default()
    }
    .find()?
    .reference_dir();
    let full = FullLight::load(&dir)?;
    let reference =
        reference_for(&scene, SCENE, &full, &dir.join(FILE)).map_err(|why| why.to_string())?;
    let index = full
        .scenes
        .iter()
        .position(|s| s.name == SCENE)
        .ok_or(SCENE)?;
    let decoded = decode(&dir.join(FILE), index, &full.scenes[index])?;
    let passes = |estimate: Estimate| -> Vec<f64> {
        decoded.passes[&(estimate, Region::Diffuse)]
            .iter()
            .map(|p| p.iter().sum())
            .collect()
    };
    let interior = interior(&reference);
    let edge: Vec<bool> = reference
        .mask
        .iter()
        .zip(&interior)
        .map(|(&m, &i)| m && !i)
        .collect();
    let rows = Rows {
        job: &job,
        truth,
        renders,
        threads,
        reference: &reference,
        masks: [&interior, &edge],
        passes: &passes,
    };
    rows.header(spp);
    for (name, vary) in VARIATIONS {
        rows.print(name, vary)?;
    }
    Ok(())
}

/// `SPP`, `RENDERS` and `THREADS` from the command line, or their defaults.
fn arguments() -> Result<(u32, u64, usize), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let mut next = |name: &str, default: u64| -> Result<u64, String> {
        args.next().map_or(Ok(default), |a| {
            a.parse().map_err(|e| format!("{name}: {a:?}: {e}"))
        })
    };
    let spp = u32::try_from(next("SPP", 32)?).map_err(|e| format!("SPP: {e}"))?;
    let renders = next("RENDERS", 4)?;
    let threads = usize::try_from(next("THREADS", 2)?).map_err(|e| format!("THREADS: {e}"))?;
    if spp == 0 || renders < 2 {
        return Err("SPP must be at least 1 and RENDERS at least 2".into());
    }
    Ok((spp, renders, threads))
}

/// Mitsuba's estimates the renders are held against, in the table's order.
const ESTIMATES: [Estimate; 3] = [Estimate::Ptracer, Estimate::Area, Estimate::Path];

/// What every row of the table is rendered and held against.
struct Rows<'a> {
    job: &'a RenderJob,
    truth: Settings,
    renders: u64,
    threads: usize,
    reference: &'a Reference,
    /// The region's interior and its edge.
    masks: [&'a [bool]; 2],
    /// The sums of an estimate's passes over the region.
    passes: &'a dyn Fn(Estimate) -> Vec<f64>,
}

impl Rows<'_> {
    /// The scene, the region and Mitsuba's own spread, then the table's
    /// head.
    fn header(&self, spp: u32) {
        let (reference, renders, passes) = (self.reference, self.renders, self.passes);
        println!(
            "{SCENE}, 160×120 Lambert, {renders} renders of {spp} spp (seeds 0 to {}); `diffuse` at {}×{}: {} pixels ({} interior); \
             Mitsuba {} passes of {} spp, max_depth {}",
            renders - 1,
            reference.width,
            reference.height,
            reference.mask.iter().filter(|&&m| m).count(),
            self.masks[0].iter().filter(|&&m| m).count(),
            reference.passes.len(),
            reference.spp,
            reference.max_depth,
        );
        println!();
        println!(
            "Mitsuba's estimates against its ptracer (share ± standard error of both estimates' passes):"
        );
        for estimate in [Estimate::Area, Estimate::Path] {
            let theirs = RegionMean::from_passes(passes(estimate));
            let (share, se) = light_share(theirs.0.mean, &passes(Estimate::Ptracer));
            let own = share * theirs.standard_error() / theirs.0.mean;
            println!("- {}: {share:.4} ± {:.4}", estimate.name(), se.hypot(own));
        }
        println!();
        println!(
            "Each cell: the mean over the renders ± the standard error of their spread and, \
             against an estimate's passes, of Mitsuba's passes too."
        );
        println!();
        println!("| setting | seconds | vs ptracer | vs area | vs path | vs ptracer mean, interior | vs ptracer mean, edge |");
        println!("|---|---:|---:|---:|---:|---:|---:|");
    }

    /// One row: the truth's settings varied by `vary`, rendered with each
    /// seed, and each column's mean with its standard error.
    fn print(
        &self,
        name: &str,
        vary: fn(Settings) -> Settings,
    ) -> Result<(), Box<dyn std::error::Error>> {
        let (reference, passes) = (self.reference, self.passes);
        let mut seconds = 0.0;
        let mut rows = Vec::new();
        for seed in 0..self.renders {
            let settings = Settings {
                seed,
                ..vary(self.truth)
            };
            let rendered = RenderJob::with_settings(self.job.scene().clone(), settings)?
                .render(Some(self.threads), &|_| {})?;
            seconds += rendered.elapsed.as_secs_f64();
            let small = box_downsample(&rendered.image, reference.factor);
            let ours = region_light(&small, &reference.mask);
            let mut row: Vec<f64> = ESTIMATES
                .iter()
                .map(|&e| light_share(ours, &passes(e)).0)
                .collect();
            row.extend(
                self.masks
                    .map(|mask| region_light(&small, mask) / region_light(&reference.mean, mask)),
            );
            rows.push(row);
        }
        let cells: Vec<String> = (0..rows[0].len())
            .map(|k| {
                let column = RegionMean::from_passes(rows.iter().map(|r| r[k]));
                let theirs = ESTIMATES.get(k).map_or(0.0, |&e| {
                    let (share, se) = light_share(column.0.mean, &passes(e));
                    se / share * column.0.mean
                });
                let se = (column.standard_error().powi(2) + theirs.powi(2)).sqrt();
                format!("{:.4} ± {se:.4}", column.0.mean)
            })
            .collect();
        println!("| {name} | {seconds:.1} | {} |", cells.join(" | "));
        Ok(())
    }
}

/// The region's pixels whose eight neighbours are in the region too.
fn interior(reference: &Reference) -> Vec<bool> {
    let (w, h) = (reference.width as i64, reference.height as i64);
    let inside = |x: i64, y: i64| {
        (0..w).contains(&x) && (0..h).contains(&y) && reference.mask[(y * w + x) as usize]
    };
    (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| (-1..=1).all(|j| (-1..=1).all(|i| inside(x + i, y + j))))
        .collect()
}
