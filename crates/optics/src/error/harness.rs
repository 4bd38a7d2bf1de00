//! The harness's errors as `optics validate` reports them: each kind's
//! stable name, the flag (or variable) that sets what it concerns, and the
//! advice about a missing checkout that the reporting command accepts.

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
