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
//! cheapest predicted within a tolerance ([`budget::choose`]). The same
//! sweep spread over machines is planned as job lines ([`jobs::Planned`]);
//! one job is read back, checked against the plan, rendered, and its
//! result line read back and decoded as a collector reads it.

use std::error::Error;
use std::path::Path;

use tracer::job::{Overrides, RenderJob};
use validation::tradeoff::jobs::{self, Job, JobResult, LineKind, Place};
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
    jobs_summary(&job, file)?;
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

/// Plans the sweep as jobs, runs the first point's job and reads its
/// result back as a collector does.
fn jobs_summary(job: &RenderJob, file: &Path) -> Result<(), Box<dyn Error>> {
    let key = jobs::PlanKey {
        scene: file.display().to_string(),
        scene_fnv1a: jobs::scene_fnv1a(&std::fs::read(file)?),
        lambert: false,
        width: 32,
        height: 24,
        spp: 4,
        truth_spp: 16,
        repeats: 1,
        min_seconds: 0.0,
    };
    let planned = jobs::Planned::new(&key, job, &sweep::plan(job, key.spp));
    let at = Place {
        path: "jobs.jsonl".into(),
        line: jobs::TRUTH_JOBS + 1,
    };
    let text = serde_json::to_string(&planned.jobs[jobs::TRUTH_JOBS])?;
    let line: Job = jobs::read_line(&text, LineKind::Job, &at)?;
    let index = planned.check(&line, &at)?;
    let rendered = render(job, file, planned.settings[index], None)?;
    let result = JobResult {
        schema: LineKind::Result.schema().to_owned(),
        version: jobs::VERSION,
        plan: key.id(),
        planned_as: format!("plan of {}", key.scene),
        scene_fnv1a: key.scene_fnv1a.clone(),
        job: index,
        jobs: planned.jobs.len(),
        label: line.label.clone(),
        seconds: vec![rendered.elapsed.as_secs_f64()],
        rays: rendered.rays.total() as f64,
        machine: "here".to_owned(),
        date: "today".to_owned(),
        load: None,
        images: vec![jobs::encode(&rendered.image)],
    };
    let text = serde_json::to_string(&result)?;
    let back: JobResult = jobs::read_line(&text, LineKind::Result, &at)?;
    let images = back.images(&at, planned.kept(index, 1), (key.width, key.height))?;
    println!(
        "jobs: {} planned (plan {}); job {index} ({}) rendered, {} image read back",
        planned.jobs.len(),
        key.id(),
        back.label,
        images.len()
    );
    Ok(())
}
