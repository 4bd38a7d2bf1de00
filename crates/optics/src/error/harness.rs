//! The harness's errors as the commands of the `harness` feature report
//! them ([`HarnessKind`]): each kind's stable name and the flag (or
//! variable) that sets what it concerns.

use std::path::PathBuf;

use validation::checkout::{CheckoutError, Via, ENV};
use validation::pipeline::PipelineError;
use validation::python::ToolError;
use validation::reference::ReferenceError;
use validation::regenerate::RegenerateError;
use validation::tradeoff::error::BudgetError;

/// The flag `optics validate` names the checkout with; the other commands
/// that need a checkout have none.
pub const CHECKOUT_FLAG: &str = "--checkout";

/// The name of a checkout error's kind.
pub fn checkout_name(error: &CheckoutError) -> &'static str {
    match error {
        CheckoutError::NotACheckout { .. } => "checkout.not_a_checkout",
        CheckoutError::NotFound { .. } => "checkout.not_found",
    }
}

/// What named the checkout, or would name it: the command's `flag`
/// where it has one, else the environment variable.
pub fn checkout_field(error: &CheckoutError, flag: Option<&'static str>) -> &'static str {
    match error {
        CheckoutError::NotACheckout {
            via: Via::Environment,
            ..
        } => ENV,
        CheckoutError::NotACheckout {
            via: Via::Explicit | Via::Search | Via::BuildTime,
            ..
        }
        | CheckoutError::NotFound { .. } => flag.unwrap_or(ENV),
    }
}

/// The name of a pipeline error's kind: `harness.` and the kind (a tool's
/// failure is named the same whichever step ran it).
pub fn pipeline_name(error: &PipelineError) -> &'static str {
    match error {
        PipelineError::OutNotADirectory { .. } => "harness.out_not_a_directory",
        PipelineError::CreateDir { .. } => "harness.create_dir",
        PipelineError::NoRequirements { .. } => "harness.no_requirements",
        PipelineError::Write(_) => "harness.write",
        PipelineError::Reference(ReferenceError::Io { .. }) => "harness.reference.io",
        PipelineError::Reference(ReferenceError::Malformed { .. }) => "harness.reference.malformed",
        PipelineError::Reference(ReferenceError::Schema { .. }) => "harness.reference.schema",
        PipelineError::Tool(error) | PipelineError::Regenerate(RegenerateError::Tool(error)) => {
            tool_name(error)
        }
        PipelineError::Regenerate(RegenerateError::Undecided { .. }) => {
            "harness.regenerate.undecided"
        }
    }
}

fn tool_name(error: &ToolError) -> &'static str {
    match error {
        ToolError::Start { .. } => "harness.tool.start",
        ToolError::Failed { .. } => "harness.tool.failed",
    }
}

/// The flag that sets what a pipeline error concerns, or the field of a
/// malformed reference.
pub fn pipeline_field(error: &PipelineError) -> Option<String> {
    let flag = match error {
        PipelineError::OutNotADirectory { .. }
        | PipelineError::CreateDir { .. }
        | PipelineError::Write(_) => "--out",
        PipelineError::NoRequirements { .. } => "--checkout",
        PipelineError::Tool(ToolError::Start { .. }) => "--python",
        PipelineError::Reference(ReferenceError::Malformed { field, .. }) => {
            return Some(field.clone())
        }
        PipelineError::Reference(ReferenceError::Io { .. } | ReferenceError::Schema { .. })
        | PipelineError::Tool(ToolError::Failed { .. })
        | PipelineError::Regenerate(_) => return None,
    };
    Some(flag.to_owned())
}

/// The failures of the commands the `harness` feature adds: the
/// cross-check harness, `compare`, the trade-off sweep and its jobs, and
/// the accuracy budget.
#[derive(Debug)]
pub enum HarnessKind {
    /// No usable checkout of the suite, for a command without `--checkout`
    /// (`OPTICS_CHECKOUT`, or the working directory's).
    Checkout(validation::checkout::CheckoutError),
    /// No usable checkout, for a command that takes `--checkout`.
    CheckoutWithFlag(validation::checkout::CheckoutError),
    /// The harness could not run to the end.
    Pipeline(validation::pipeline::PipelineError),
    /// The harness ran to the end and some of its checks failed.
    ChecksFailed {
        /// The checks that failed.
        failed: usize,
        /// All checks run.
        checks: usize,
    },
    /// `optics compare` could not compare, or found the image different.
    Compare(super::compare::CompareError),
    /// `optics tradeoff` on a scene whose physical render is black (no
    /// light reaches the camera): there is no light transport to trade.
    TruthIsBlack {
        /// The scene file, as given.
        file: PathBuf,
    },
    /// `optics render --tolerance` that cannot render within its
    /// tolerance: unreachable, a pilot too noisy, a material that gains
    /// energy.
    Budget(BudgetError),
    /// `optics tradeoff`'s Pareto plot has no Python environment to be
    /// drawn with: nothing was written.
    NoPlotPython {
        /// The interpreter looked for.
        python: PathBuf,
    },
    /// `optics tradeoff`'s Pareto plot could not be drawn (its script
    /// failed): nothing was written.
    Plot(ToolError),
    /// A sweep spread over machines: a job or result line refused, a job
    /// not in the plan, results missing or given twice.
    Jobs(super::jobs::JobError),
}

impl HarnessKind {
    /// The kind's stable name, the `kind` of the JSON error object.
    pub fn name(&self) -> &'static str {
        match self {
            HarnessKind::Checkout(error) | HarnessKind::CheckoutWithFlag(error) => {
                checkout_name(error)
            }
            HarnessKind::Pipeline(error) => pipeline_name(error),
            HarnessKind::ChecksFailed { .. } => "harness.checks_failed",
            HarnessKind::Compare(error) => error.name(),
            HarnessKind::TruthIsBlack { .. } => "tradeoff.truth_is_black",
            HarnessKind::NoPlotPython { .. } => "tradeoff.no_python",
            HarnessKind::Plot(_) => "tradeoff.plot",
            HarnessKind::Budget(BudgetError::Unreachable { .. }) => "budget.unreachable",
            HarnessKind::Budget(BudgetError::PilotNoisy { .. }) => "budget.pilot_noisy",
            HarnessKind::Budget(BudgetError::EnergyGain { .. }) => "budget.energy_gain",
            HarnessKind::Jobs(error) => error.name(),
        }
    }

    /// The argument, flag or field the failure concerns.
    pub(crate) fn field(&self) -> Option<String> {
        match self {
            HarnessKind::Checkout(error) => Some(checkout_field(error, None).to_owned()),
            HarnessKind::CheckoutWithFlag(error) => {
                Some(checkout_field(error, Some(CHECKOUT_FLAG)).to_owned())
            }
            HarnessKind::Pipeline(error) => pipeline_field(error),
            HarnessKind::ChecksFailed { .. } => None,
            HarnessKind::Compare(error) => super::compare::field(error),
            HarnessKind::TruthIsBlack { .. } => Some("SCENE".to_owned()),
            HarnessKind::NoPlotPython { .. } | HarnessKind::Plot(_) => Some("--no-plot".to_owned()),
            HarnessKind::Budget(BudgetError::Unreachable { .. }) => Some("--tolerance".to_owned()),
            HarnessKind::Budget(BudgetError::PilotNoisy { .. }) => Some("--pilot-spp".to_owned()),
            HarnessKind::Budget(BudgetError::EnergyGain { .. }) => Some("--lambert".to_owned()),
            HarnessKind::Jobs(error) => error.field(super::jobs::flag),
        }
    }
}
