//! A second front end over the trade-off library: a small sweep and an
//! accuracy budget on a tiny scene, through `validation` and `tracer`
//! alone (no `optics`).
//!
//! `cargo run -p validation --example second_front_end`
//!
//! The sweep plans its points ([`sweep::plan`]), measures each render
//! against a converged truth ([`truth::obtain`], cached in a temporary
//! directory) and marks the Pareto front of time against relative RMSE;
//! the budget pilots its candidates ([`pilot::run`]) and chooses the
//! cheapest predicted within a tolerance ([`budget::choose`]).

use std::error::Error;
use std::path::Path;

use tracer::job::{Overrides, RenderJob};
use validation::tradeoff::render::render;
use validation::tradeoff::{budget, measure, pareto, pilot, sweep, truth};

/// The scene, at a size that renders in a moment.
const SCENE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../crates/tracer/scenes/shadow.json"
);

fn main() -> Result<(), Box<dyn Error>> {
    let file = Path::new(SCENE);
    let overrides = Overrides {
        width: Some(32),
        height: Some(24),
        ..Overrides::default()
    };
    let job = RenderJob::load(file, &overrides)?;
    let mask = measure::Mask::from_hits(&job.first_hits());
    sweep_summary(&job, file, &mask)?;
    budget_summary(&job, file, &mask)?;
    Ok(())
}

/// Renders every point of the sweep once and prints its error and time.
fn sweep_summary(job: &RenderJob, file: &Path, mask: &measure::Mask) -> Result<(), Box<dyn Error>> {
    let plan = sweep::plan(job, 4);
    let cache = tempfile::tempdir()?;
    let request = truth::Request {
        scene_file: file,
        spp: 16,
        lambert: false,
        dir: cache.path(),
        fresh: true,
    };
    let (truth, record) = truth::obtain(job, &request, mask, None)?;
    println!(
        "sweep: {} points, truth {} spp",
        plan.points.len(),
        record.spp
    );
    let mut xy = Vec::with_capacity(plan.points.len());
    for point in &plan.points {
        let rendered = render(job, file, point.settings, None)?;
        let errors = measure::errors(std::slice::from_ref(&rendered.image), &truth, mask);
        let seconds = rendered.elapsed.as_secs_f64();
        println!("  {:<28} rel_rmse {:.4}", point.label, errors.rel_rmse);
        xy.push((seconds, errors.rel_rmse));
    }
    let front: Vec<&str> = pareto::front(&xy)
        .into_iter()
        .map(|i| plan.points[i].label.as_str())
        .collect();
    println!(
        "  on the front of time against rel_rmse: {}",
        front.join(", ")
    );
    Ok(())
}

/// Pilots the budget's candidates and prints the cheapest within 10 %.
fn budget_summary(
    job: &RenderJob,
    file: &Path,
    mask: &measure::Mask,
) -> Result<(), Box<dyn Error>> {
    let half = 2;
    let truth = pilot::truth_settings(job, half);
    let candidates = pilot::candidates(job, &truth);
    let pass = pilot::run(job, file, (&truth, &candidates), (half, mask, false), None)?;
    let [a, b] = &pass.reference;
    let Some(energy) = budget::energy([a, b], mask) else {
        println!("budget: the pilot cannot bound the truth's light at {half} spp");
        return Ok(());
    };
    let tolerance = 0.1;
    match budget::choose(&pass.pilots, energy, tolerance, 1024) {
        Some(budget::Choice::Chosen { index, prediction }) => println!(
            "budget: {} candidates; within rel_rmse {tolerance}: {} at {:?} spp",
            candidates.len(),
            sweep::describe(&candidates[index].settings),
            prediction.spp
        ),
        Some(budget::Choice::Unreachable { index, .. }) => println!(
            "budget: no candidate within {tolerance}; nearest {}",
            sweep::describe(&candidates[index].settings)
        ),
        None => println!("budget: no candidates"),
    }
    Ok(())
}
