//! The harness's errors as `optics validate` reports them: each kind's
//! stable name, and the flag (or variable) that sets what it concerns.

use validation::checkout::{CheckoutError, Via, ENV};
use validation::pipeline::PipelineError;
use validation::python::ToolError;
use validation::reference::ReferenceError;
use validation::regenerate::RegenerateError;

/// The flag an English and a Hungarian message start with, where the
/// harness's own message does not say which flag sets what it concerns.
#[derive(Clone, Copy, Debug)]
pub struct Lead {
    /// In English.
    pub en: &'static str,
    /// In Hungarian.
    pub hu: &'static str,
}

/// The name of a checkout error's kind.
pub fn checkout_name(error: &CheckoutError) -> &'static str {
    match error {
        CheckoutError::NotACheckout { .. } => "checkout.not_a_checkout",
        CheckoutError::NotFound { .. } => "checkout.not_found",
    }
}

/// What named the checkout: `--checkout`, or the environment variable.
pub fn checkout_field(error: &CheckoutError) -> &'static str {
    match error {
        CheckoutError::NotACheckout {
            via: Via::Environment,
            ..
        } => ENV,
        CheckoutError::NotACheckout {
            via: Via::Explicit | Via::Search | Via::BuildTime,
            ..
        }
        | CheckoutError::NotFound { .. } => "--checkout",
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
