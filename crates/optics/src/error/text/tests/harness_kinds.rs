//! One example of every kind of the harness's errors: no checkout, a
//! pipeline that could not run to the end, failed checks.

use super::{named, os_error};
use crate::error::{ErrorKind, HarnessKind};
use safe_io::WriteError;
use tracer::output::OutputError;
use validation::checkout::{CheckoutError, Via, MARKERS};
use validation::pipeline::PipelineError;
use validation::python::{Task, ToolError};
use validation::reference::ReferenceError;
use validation::regenerate::RegenerateError;
use validation::tradeoff::error::BudgetError;

/// The place of a checkout error's kind among the harness slots.
pub fn checkout_slot(error: &CheckoutError) -> usize {
    match error {
        CheckoutError::NotACheckout { .. } => 0,
        CheckoutError::NotFound { .. } => 1,
    }
}

/// The place of a pipeline error's kind among the harness slots (a tool's
/// failure has one slot whichever step ran it).
pub fn pipeline_slot(error: &PipelineError) -> usize {
    let tool = |error: &ToolError| match error {
        ToolError::Start { .. } => 9,
        ToolError::Failed { .. } => 10,
    };
    match error {
        PipelineError::OutNotADirectory { .. } => 2,
        PipelineError::CreateDir { .. } => 3,
        PipelineError::NoRequirements { .. } => 4,
        PipelineError::Write(_) => 5,
        PipelineError::Reference(ReferenceError::Io { .. }) => 6,
        PipelineError::Reference(ReferenceError::Malformed { .. }) => 7,
        PipelineError::Reference(ReferenceError::Schema { .. }) => 8,
        PipelineError::Tool(error) | PipelineError::Regenerate(RegenerateError::Tool(error)) => {
            tool(error)
        }
        PipelineError::Regenerate(RegenerateError::Undecided { .. }) => 11,
    }
}

/// The slot of failed checks.
pub const CHECKS_FAILED: usize = 12;

/// The slot of a black truth (`optics tradeoff`).
pub const TRUTH_IS_BLACK: usize = 13;

/// The slot of a budget no candidate reaches.
pub const BUDGET_UNREACHABLE: usize = 14;

/// The slot of a pilot too noisy to bound the truth's energy.
pub const BUDGET_PILOT_NOISY: usize = 15;

/// The slot of a scene whose rough material gains energy, budgeted
/// without `--lambert`.
pub const BUDGET_ENERGY_GAIN: usize = 16;

/// The slot of a Pareto plot that cannot be drawn (`optics tradeoff`).
pub const PLOT: usize = 17;

/// The slot of a Pareto plot without a Python environment.
pub const NO_PLOT_PYTHON: usize = 18;

/// How many harness slots there are.
pub const SLOTS: usize = 19;

/// An exit status of 3, as a failed tool reports it.
fn exit_status() -> std::process::ExitStatus {
    use std::os::unix::process::ExitStatusExt;
    std::process::ExitStatus::from_raw(3 << 8)
}

fn pipeline(error: PipelineError, quoted: &[&str]) -> (ErrorKind, Vec<String>) {
    (
        ErrorKind::Harness(HarnessKind::Pipeline(error)),
        named(quoted),
    )
}

/// One example of each kind, with the text it quotes verbatim.
pub fn examples() -> Vec<(ErrorKind, Vec<String>)> {
    let os = os_error().to_string();
    let status = exit_status().to_string();
    let reference = "validation/reference/metals.json";
    let mut kinds = vec![
        (
            ErrorKind::Harness(HarnessKind::Checkout(CheckoutError::NotACheckout {
                via: Via::Environment,
                path: "/srv/elsewhere".into(),
                marker: MARKERS[1],
            })),
            named(&["OPTICS_CHECKOUT", "/srv/elsewhere", MARKERS[1]]),
        ),
        (
            ErrorKind::Harness(HarnessKind::Checkout(CheckoutError::NotFound {
                start: "/tmp/work".into(),
            })),
            named(&[
                "OPTICS_CHECKOUT=DIR",
                "OPTICS_CHECKOUT",
                "/tmp/work",
                MARKERS[0],
                MARKERS[1],
            ]),
        ),
        (
            ErrorKind::Harness(HarnessKind::CheckoutWithFlag(CheckoutError::NotFound {
                start: "/tmp/work".into(),
            })),
            named(&[
                "--checkout DIR",
                "OPTICS_CHECKOUT=DIR",
                "OPTICS_CHECKOUT",
                "/tmp/work",
                MARKERS[0],
                MARKERS[1],
            ]),
        ),
        (
            ErrorKind::Harness(HarnessKind::CheckoutWithFlag(CheckoutError::NotACheckout {
                via: Via::Explicit,
                path: "/srv/elsewhere".into(),
                marker: MARKERS[0],
            })),
            named(&["--checkout /srv/elsewhere", MARKERS[0]]),
        ),
        pipeline(
            PipelineError::OutNotADirectory {
                path: "/tmp/taken".into(),
            },
            &["--out", "/tmp/taken"],
        ),
        pipeline(
            PipelineError::CreateDir {
                path: "/tmp/out/figures".into(),
                source: os_error(),
            },
            &["/tmp/out/figures", &os],
        ),
        pipeline(
            PipelineError::NoRequirements {
                path: "/c/python-checks/requirements.txt".into(),
            },
            &[
                "/c/python-checks/requirements.txt",
                "--checkout",
                "--no-python",
                "Python",
            ],
        ),
        pipeline(
            PipelineError::Write(OutputError::Write(WriteError::Io {
                path: "/tmp/out/report.json".into(),
                source: os_error(),
            })),
            &["/tmp/out/report.json", &os],
        ),
        pipeline(
            PipelineError::Reference(ReferenceError::Io {
                path: reference.into(),
                source: os_error(),
            }),
            &[reference, &os],
        ),
        pipeline(
            PipelineError::Reference(ReferenceError::Malformed {
                path: reference.into(),
                field: "dielectric[3].mitsuba.f".into(),
                message: "invalid type: string".into(),
            }),
            &[reference, "dielectric[3].mitsuba.f", "invalid type: string"],
        ),
        pipeline(
            PipelineError::Reference(ReferenceError::Schema {
                path: reference.into(),
                found: "metals/0".into(),
                expected: "metals/1",
            }),
            &[reference, "metals/0", "metals/1"],
        ),
        pipeline(
            PipelineError::Tool(ToolError::Start {
                what: Task::CreateEnvironment {
                    base: "python3".into(),
                },
                program: "\"python3\"".into(),
                source: os_error(),
            }),
            &[
                "--python",
                "--no-python",
                "python3 -m venv",
                "\"python3\"",
                "Python",
                &os,
            ],
        ),
        pipeline(
            PipelineError::Regenerate(RegenerateError::Tool(ToolError::Failed {
                what: Task::Script("python-checks/metals.py".into()),
                status: exit_status(),
                stderr_tail: "Traceback (most recent call last)".into(),
            })),
            &[
                "python-checks/metals.py",
                &status,
                "Traceback (most recent call last)",
            ],
        ),
        pipeline(
            PipelineError::Regenerate(RegenerateError::Undecided {
                file: reference.into(),
                status: status.clone(),
                stderr: "no such file".into(),
            }),
            &[
                "python-checks/reproduce.py",
                reference,
                &status,
                "no such file",
            ],
        ),
        (
            ErrorKind::Harness(HarnessKind::ChecksFailed {
                failed: 2,
                checks: 40,
            }),
            vec![],
        ),
        (
            ErrorKind::Harness(HarnessKind::NoPlotPython {
                python: "/work/.venv/bin/python".into(),
            }),
            named(&[
                "--no-plot",
                "/work/.venv/bin/python",
                "`optics validate`",
                "Pareto",
                "Python",
            ]),
        ),
        (
            ErrorKind::Harness(HarnessKind::Plot(ToolError::Failed {
                what: Task::Script("python-checks/plot_tradeoff.py".into()),
                status: exit_status(),
                stderr_tail: "Traceback (most recent call last)".into(),
            })),
            named(&[
                "--no-plot",
                "python-checks/plot_tradeoff.py",
                "Traceback (most recent call last)",
                &status,
                "Pareto",
            ]),
        ),
        (
            ErrorKind::Harness(HarnessKind::TruthIsBlack {
                file: "scenes/kaleidoscope.json".into(),
            }),
            named(&["SCENE", "scenes/kaleidoscope.json"]),
        ),
        (
            ErrorKind::Harness(HarnessKind::Budget(BudgetError::Unreachable {
                metric: "rel_rmse",
                tolerance: 1e-7,
                best: 0.0123,
                settings: "path, 65536 spp, max_depth 64, fresnel exact".into(),
                top_spp: Some(65536),
                need: validation::tradeoff::budget::Need::Samples { spp: 1 << 20 },
            })),
            named(&[
                "--tolerance 1e-7",
                "rel_rmse",
                "path, 65536 spp, max_depth 64, fresnel exact",
                "1048576",
            ]),
        ),
        (
            ErrorKind::Harness(HarnessKind::Budget(BudgetError::Unreachable {
                metric: "delta_e_p99",
                tolerance: 0.5,
                best: 14.6475,
                settings: "path, 65536 spp, max_depth 1, fresnel exact".into(),
                top_spp: Some(65536),
                need: validation::tradeoff::budget::Need::Floor,
            })),
            named(&[
                "--tolerance 0.5",
                "delta_e_p99",
                "path, 65536 spp, max_depth 1, fresnel exact",
                "--pilot-spp",
            ]),
        ),
        (
            ErrorKind::Harness(HarnessKind::Budget(BudgetError::Unreachable {
                metric: "rel_rmse",
                tolerance: 1e-3,
                best: 0.0612,
                settings: "whitted, max_depth 64, fresnel exact".into(),
                top_spp: None,
                need: validation::tradeoff::budget::Need::Never,
            })),
            named(&[
                "--tolerance 1e-3",
                "rel_rmse",
                "whitted, max_depth 64, fresnel exact",
            ]),
        ),
        (
            ErrorKind::Harness(HarnessKind::Budget(BudgetError::Unreachable {
                metric: "rel_rmse",
                tolerance: 1e-3,
                best: 0.0123,
                settings: "photon, 4096 spp, max_depth 16, fresnel exact".into(),
                top_spp: Some(4096),
                need: validation::tradeoff::budget::Need::Capped { spp: 4096 },
            })),
            named(&[
                "--tolerance 1e-3",
                "rel_rmse",
                "photon, 4096 spp, max_depth 16, fresnel exact",
                "4096",
            ]),
        ),
        (
            ErrorKind::Harness(HarnessKind::Budget(BudgetError::EnergyGain {
                material: "green".to_owned(),
                gain: 2.51,
            })),
            named(&[
                "`optics tradeoff --lambert`",
                "--lambert",
                "course_rough",
                "\"green\"",
                "2.51",
            ]),
        ),
        (
            ErrorKind::Harness(HarnessKind::Budget(BudgetError::PilotNoisy {
                pilot_spp: 8,
            })),
            named(&[
                "--pilot-spp 8",
                "course_rough",
                "`optics tradeoff --lambert`",
                "--lambert",
            ]),
        ),
    ];
    // The other tasks a tool runs for, each translated.
    let tail = "ERROR: No matching distribution";
    for (what, name) in [
        (Task::InstallRequirements, "python-checks/requirements.txt"),
        (Task::CheckPins, "Python"),
    ] {
        kinds.push(pipeline(
            PipelineError::Tool(ToolError::Failed {
                what,
                status: exit_status(),
                stderr_tail: tail.into(),
            }),
            &[name, &status, tail],
        ));
    }
    kinds
}
