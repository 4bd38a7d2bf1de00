//! How a sweep in one run renders its points: in rounds, each point at
//! least `repeats` times and until its renders add up to `min_seconds`;
//! the rule a job of a planned sweep follows too.

use std::path::Path;

use tracer::scene::Settings;

use super::renders::{Provenance, Renders, Timed};
use super::request::SweepRequest;
use super::setup::Setup;
use crate::tradeoff::error::TradeoffError;
use crate::tradeoff::render::render;
use crate::tradeoff::{jobs, truth};

/// How far a sweep rendered here has come: told before each step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Progress<'a> {
    /// The ground truth is being obtained (rendered, or read from its
    /// cache).
    Truth,
    /// The first round reached the point of this label.
    Point(&'a str),
    /// Every point is rendered.
    Done,
}

/// The sweep rendered here: the truth (from the cache when it holds it),
/// then every point in rounds, each step told to `progress` (of
/// `setup.plan.points.len() + 1` steps).
pub fn render_here(
    setup: &Setup,
    args: &SweepRequest,
    request: &truth::Request<'_>,
    progress: &dyn Fn(Progress<'_>),
) -> Result<Renders, TradeoffError> {
    let threads = args.threads;
    progress(Progress::Truth);
    let (truth, record) = truth::obtain(&setup.job, request, &setup.mask, threads)?;
    if truth.is_black() {
        return Err(TradeoffError::TruthIsBlack {
            file: args.scene.clone(),
        });
    }
    let tick = |label: &str| progress(Progress::Point(label));
    let timed = time_points(setup, &args.scene, args, threads, &tick)?;
    progress(Progress::Done);
    let provenance = Provenance {
        machine: results::machine(),
        date: results::today(),
        load: results::load(),
        collected: None,
    };
    Ok((truth, record, timed, provenance))
}

/// The most renders of one setting that `min_seconds` asks for.
pub const MAX_RENDERS: usize = 64;

/// How many renders a point takes whose first took `first` seconds: at
/// least `repeats`, and enough to add up to `min_seconds`, at most
/// [`MAX_RENDERS`].
pub fn renders_wanted(first: f64, repeats: u32, min_seconds: f64) -> usize {
    let enough = (min_seconds / first.max(1e-6)).ceil() as usize;
    enough.clamp(repeats as usize, MAX_RENDERS)
}

/// Renders every point in rounds, each round every point once, so that a
/// drift of the machine's speed falls on all of them alike (A B C … A B C):
/// after one untimed warm-up render, the first round, then as many more as
/// each point needs ([`renders_wanted`]). Monte Carlo points take a new
/// seed each time.
fn time_points(
    setup: &Setup,
    file: &Path,
    args: &SweepRequest,
    threads: Option<usize>,
    tick: &dyn Fn(&str),
) -> Result<Vec<Timed>, TradeoffError> {
    let (job, points) = (&setup.job, &setup.plan.points);
    if let Some(first) = points.first() {
        render(job, file, first.settings, threads)?;
    }
    let mut timed: Vec<Timed> = points
        .iter()
        .map(|_| Timed {
            images: Vec::new(),
            seconds: Vec::new(),
            rays: 0.0,
        })
        .collect();
    let mut wanted = vec![args.repeats as usize; points.len()];
    for round in 0..MAX_RENDERS {
        let mut rendered_any = false;
        for (i, point) in points.iter().enumerate() {
            if timed[i].seconds.len() >= wanted[i] {
                continue;
            }
            if round == 0 {
                tick(&point.label);
            }
            let settings = Settings {
                seed: point.settings.seed.wrapping_add(round as u64),
                ..point.settings
            };
            let rendered = render(job, file, settings, threads)?;
            let t = &mut timed[i];
            t.seconds.push(rendered.elapsed.as_secs_f64());
            t.rays += rendered.rays.total() as f64;
            // A deterministic setting renders the same image each time.
            let keep = if settings.integrator.samples() {
                jobs::MAX_KEPT
            } else {
                1
            };
            if t.images.len() < keep {
                t.images.push(rendered.image);
            }
            if round == 0 {
                wanted[i] = renders_wanted(t.seconds[0], args.repeats, args.min_seconds);
            }
            rendered_any = true;
        }
        if !rendered_any {
            break;
        }
    }
    Ok(timed)
}
