//! The harness's errors as the commands of the `harness` feature report
//! them ([`HarnessKind`]): each kind's stable name, the flag (or variable)
//! that sets what it concerns, and the advice about a missing checkout that
//! the reporting command accepts.

use std::path::PathBuf;

use validation::checkout::{CheckoutError, Via, ENV};
use validation::pipeline::PipelineError;
use validation::python::ToolError;
use validation::reference::ReferenceError;
use validation::regenerate::RegenerateError;
use validation::tradeoff::error::BudgetError;

/// The flag an English and a Hungarian message start with, where the
/// harness's own message does not say which flag sets what it concerns.
#[derive(Clone, Copy, Debug)]
pub struct Lead {
    /// In English.
    pub en: &'static str,
    /// In Hungarian.
    pub hu: &'static str,
}

/// The flag `optics validate` names the checkout with; the other commands
/// that need a checkout have none.
pub const CHECKOUT_FLAG: &str = "--checkout";

/// A checkout error in English, for a command whose checkout flag is
/// `flag` (`None`: the command has none): the flag leads the message of a
/// directory it named, and the advice after a missing checkout names only
/// what the command accepts.
pub fn checkout_en(error: &CheckoutError, flag: Option<&str>) -> String {
    match (error, flag) {
        (
            CheckoutError::NotACheckout {
                via: Via::Explicit,
                path,
                marker,
            },
            Some(flag),
        ) => format!(
            "{flag} {}: not a checkout of the suite (it has no {marker})",
            path.display()
        ),
        (CheckoutError::NotACheckout { .. }, _) => error.to_string(),
        (CheckoutError::NotFound { .. }, Some(flag)) => {
            format!("{error}; pass {flag} DIR, set {ENV}=DIR, or run from inside a checkout")
        }
        (CheckoutError::NotFound { .. }, None) => {
            format!("{error}; set {ENV}=DIR, or run from inside a checkout")
        }
    }
}

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

/// The flag a pipeline error's message is led by, where the harness's own
/// message names a path or a program but not the flag that set it.
pub fn pipeline_lead(error: &PipelineError) -> Option<Lead> {
    match error {
        PipelineError::OutNotADirectory { .. } => Some(Lead {
            en: "--out",
            hu: "--out",
        }),
        PipelineError::NoRequirements { .. } => Some(Lead {
            en: "--checkout (or --no-python)",
            hu: "--checkout (vagy --no-python)",
        }),
        PipelineError::Tool(ToolError::Start { .. }) => Some(Lead {
            en: "--python (or --no-python)",
            hu: "--python (vagy --no-python)",
        }),
        PipelineError::CreateDir { .. }
        | PipelineError::Write(_)
        | PipelineError::Reference(_)
        | PipelineError::Tool(ToolError::Failed { .. })
        | PipelineError::Regenerate(_) => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn not_found() -> CheckoutError {
        CheckoutError::NotFound {
            start: "/tmp/work".into(),
        }
    }

    #[test]
    fn a_command_without_the_flag_is_not_advised_to_pass_it() {
        let message = checkout_en(&not_found(), None);
        assert!(!message.contains("--"), "{message}");
        assert!(message.contains(&format!("set {ENV}=DIR")), "{message}");
        assert_eq!(checkout_field(&not_found(), None), ENV);
    }

    #[test]
    fn a_command_with_the_flag_is_advised_to_pass_it() {
        let message = checkout_en(&not_found(), Some(CHECKOUT_FLAG));
        for way in [
            "--checkout DIR",
            &format!("{ENV}=DIR"),
            "from inside a checkout",
        ] {
            assert!(message.contains(way), "{message}");
        }
        assert_eq!(
            checkout_field(&not_found(), Some(CHECKOUT_FLAG)),
            CHECKOUT_FLAG
        );
    }
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
