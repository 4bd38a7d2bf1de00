//! A second front end over the trade-off library: a sweep, an accuracy
//! budget and the same sweep spread over jobs, on a tiny scene, through
//! `validation` and `tracer` alone (no `optics`; `cargo tree -p
//! validation` shows none).
//!
//! `cargo run -p validation --example second_front_end`
//!
//! The sweep is settled once ([`engine::Setup::new`]), rendered here
//! ([`engine::render_here`], its progress told to a callback), measured
//! against its converged truth ([`engine::measure_points`]) and written
//! ([`engine::write_sweep`]). The budget renders the scene at the
//! cheapest settings predicted within a relative RMSE of 0.5
//! ([`engine::render_within`]). The jobs are planned
//! ([`engine::plan_jobs`]), each run ([`engine::run_job`]) and their
//! results collected ([`engine::collect`]) into a record whose every
//! error is the sweep's in one run: rendering is deterministic per seed,
//! wherever it runs. `cargo test` runs it and holds it to that.

use std::cell::Cell;
use std::error::Error;
use std::path::{Path, PathBuf};

use tracer::output::Destination;
use validation::checkout::Lookup;
use validation::tradeoff::engine::{self, Budget, BudgetRequest, Metric, Setup, SweepRequest};
use validation::tradeoff::jobs::Place;

/// The scene, at a size that renders in a moment.
fn scene() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../crates/tracer/scenes/shadow.json")
}

/// The sweep, as a front end would ask for it, writing into `out`.
fn request(out: &Path) -> SweepRequest {
    SweepRequest {
        scene: scene(),
        width: Some(16),
        height: Some(12),
        spp: 4,
        truth_spp: 16,
        repeats: 2,
        min_seconds: 0.0,
        out: out.to_owned(),
        lambert: true,
        fresh: false,
        threads: Some(2),
        checkout: Lookup {
            explicit: Some(Path::new(env!("CARGO_MANIFEST_DIR")).join("..")),
            ..Lookup::default()
        },
    }
}

/// What the three features gave.
struct Ran {
    /// The sweep rendered here.
    here: engine::Sweep,
    /// The progress steps told.
    steps: usize,
    /// The budget's choice.
    budget: engine::Outcome,
    /// The same sweep, from its jobs.
    collected: engine::Sweep,
}

fn run(dir: &Path) -> Result<Ran, Box<dyn Error>> {
    let asked = request(&dir.join("here"));
    let setup = Setup::new(&asked)?;
    setup.files.prepare(&asked.scene)?;
    let truth_dir = setup.files.truth_dir();
    let truth = setup.truth_request(&asked, &truth_dir);
    let steps = Cell::new(0);
    let renders = engine::render_here(&setup, &asked, &truth, &|_| steps.set(steps.get() + 1))?;
    let here = engine::measure_points(setup, &asked, renders)?;
    engine::write_sweep(&here, None)?;

    let job = Setup::new(&asked)?.job;
    let png = dir.join("budget.png");
    let destination = Destination::new(&png, &[&asked.scene])?;
    let budget = engine::render_within(
        &job,
        &BudgetRequest {
            scene: &asked.scene,
            budget: Budget {
                tolerance: 0.5,
                metric: Metric::RelRmse,
            },
            pilot_spp: 8,
            lambert: true,
            truth_spp: asked.truth_spp,
            verify: Some(&truth_dir),
            threads: asked.threads,
        },
        &destination,
    )?;

    let collected = jobs(dir)?;
    Ok(Ran {
        here,
        steps: steps.get(),
        budget,
        collected,
    })
}

/// The sweep planned as jobs, each run, the results collected.
fn jobs(dir: &Path) -> Result<engine::Sweep, Box<dyn Error>> {
    let asked = request(&dir.join("collected"));
    let setup = Setup::new(&asked)?;
    let plan = dir.join("jobs.jsonl");
    let written = engine::plan_jobs(&setup, &asked, &plan)?;
    let text = std::fs::read_to_string(&plan)?;
    let results = dir.join("results");
    for index in 0..written.jobs {
        let (line, at): (String, Place) = engine::job_line(&text, &plan, Some(index))?;
        engine::run_job(&line, at, &results, asked.threads)?;
    }
    setup.files.prepare(&asked.scene)?;
    let truth_dir = setup.files.truth_dir();
    let truth = setup.truth_request(&asked, &truth_dir);
    let renders = engine::collect(&setup, &truth, &[results])?;
    Ok(engine::measure_points(setup, &asked, renders)?)
}

fn main() -> Result<(), Box<dyn Error>> {
    let dir = tempfile::tempdir()?;
    let ran = run(dir.path())?;
    println!(
        "sweep: {} points, truth {} spp, {} progress steps",
        ran.here.points.len(),
        ran.here.truth.spp,
        ran.steps
    );
    for p in &ran.here.points {
        println!(
            "  {:<40} rel_rmse {:.4}  front {}",
            p.point.label,
            p.errors.rel_rmse,
            engine::front_marks(p)
        );
    }
    println!(
        "budget: {} within rel_rmse {}",
        engine::describe(&ran.budget.chosen),
        ran.budget.tolerance
    );
    println!(
        "jobs: {} points collected from {} jobs",
        ran.collected.points.len(),
        ran.collected.collected.as_ref().map_or(0, |c| c.jobs)
    );
    Ok(())
}

/// The sweep's points each once on the progress callback (and the truth
/// and the end), the budget's render within its tolerance, and every
/// point's errors the same whether rendered here or as jobs: the images
/// are the same bits wherever a seed is rendered.
#[test]
fn a_sweep_a_budget_and_its_jobs_run_through_the_library_alone() {
    let dir = tempfile::tempdir().unwrap();
    let ran = run(dir.path()).unwrap();
    assert!(
        ran.here.points.len() > 2,
        "{} points",
        ran.here.points.len()
    );
    assert_eq!(ran.steps, ran.here.points.len() + 2);
    let verified = ran.budget.verified.as_ref().expect("verified");
    assert!(
        verified.rel_rmse <= ran.budget.tolerance,
        "{} over {}",
        verified.rel_rmse,
        ran.budget.tolerance
    );
    let labels = |s: &engine::Sweep| -> Vec<String> {
        s.points.iter().map(|p| p.point.label.clone()).collect()
    };
    assert_eq!(labels(&ran.here), labels(&ran.collected));
    for (a, b) in ran.here.points.iter().zip(&ran.collected.points) {
        assert_eq!(
            a.errors.rel_rmse.to_bits(),
            b.errors.rel_rmse.to_bits(),
            "{}",
            a.point.label
        );
        assert_eq!(
            a.errors.delta_e_p99.to_bits(),
            b.errors.delta_e_p99.to_bits()
        );
    }
    assert!(ran.collected.collected.is_some());
}
