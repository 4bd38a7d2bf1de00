//! How a sweep in one run renders its points: in rounds, each point at
//! least `--repeats` times and until its renders add up to
//! `--min-seconds`; the rule a job of a planned sweep follows too.

use std::path::Path;

use tracer::render::Image;
use tracer::scene::Settings;

use validation::tradeoff::render::render;

use super::{jobs, truth, Provenance, Renders, Setup, TradeoffArgs};
use crate::error::{self, ErrorKind};

/// The sweep rendered here: the truth (from the cache when it holds it),
/// then every point in rounds, with a progress bar on a terminal.
pub(crate) fn render_here(
    setup: &Setup,
    args: &TradeoffArgs,
    request: &truth::Request<'_>,
) -> error::Result<Renders> {
    let threads = args.threads.map(|t| t as usize);
    let bar = crate::render::progress_bar(setup.plan.points.len() as u64 + 1).inspect(|bar| {
        bar.set_style(
            indicatif::ProgressStyle::with_template(
                "{bar:40} {pos}/{len} settings, {eta} left: {msg}",
            )
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        bar.set_message("ground truth");
    });
    let tick = |message: &str| {
        if let Some(bar) = &bar {
            bar.inc(1);
            bar.set_message(message.to_owned());
        }
    };
    let (truth, record) = truth::obtain(&setup.job, request, &setup.mask, threads)?;
    if truth.is_black() {
        return Err(ErrorKind::TruthIsBlack {
            file: args.scene.clone(),
        }
        .into());
    }
    let timed = time_points(setup, &args.scene, args, threads, &tick)?;
    if let Some(bar) = &bar {
        bar.finish_and_clear();
    }
    let provenance = Provenance {
        machine: results::machine(),
        date: results::today(),
        load: results::load(),
        collected: None,
    };
    Ok((truth, record, timed, provenance))
}

/// The most renders of one setting that `--min-seconds` asks for.
pub(crate) const MAX_RENDERS: usize = 64;

/// One point's renders: the images measured, the times.
pub(crate) struct Timed {
    /// One image for a deterministic setting; the first
    /// [`jobs::MAX_KEPT`] seeds' for a Monte Carlo one.
    pub images: Vec<Image>,
    /// Every render's time, s.
    pub seconds: Vec<f64>,
    /// Rays over all the renders.
    pub rays: f64,
}

/// How many renders a point takes whose first took `first` seconds: at
/// least `--repeats`, and enough to add up to `--min-seconds`, at most
/// [`MAX_RENDERS`].
pub(crate) fn renders_wanted(first: f64, repeats: u32, min_seconds: f64) -> usize {
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
    args: &TradeoffArgs,
    threads: Option<usize>,
    tick: &dyn Fn(&str),
) -> error::Result<Vec<Timed>> {
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
