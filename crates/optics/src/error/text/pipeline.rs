//! The cross-check harness's pipeline that could not run to the end, in
//! both languages: the flag that sets what it concerns leads the message,
//! side by side in one `match`; the message is the harness's English, or
//! an exhaustive `match` over its kinds in Hungarian.

use record::Lang;
use validation::pipeline::PipelineError;
use validation::python::{Task, ToolError};
use validation::reference::ReferenceError;
use validation::regenerate::RegenerateError;

use super::output::output;

/// A pipeline that could not run to the end, in `lang`, led by the flag
/// that sets what it concerns.
pub(super) fn pipeline(error: &PipelineError, lang: Lang) -> String {
    let message = match lang {
        Lang::En => error.to_string(),
        Lang::Hu => pipeline_hu(error),
    };
    match lead(error, lang) {
        Some(lead) => format!("{lead}: {message}"),
        None => message,
    }
}

/// The flag a pipeline error's message is led by, where the harness's own
/// message names a path or a program but not the flag that set it.
fn lead(error: &PipelineError, lang: Lang) -> Option<&'static str> {
    match error {
        PipelineError::OutNotADirectory { .. } => Some("--out"),
        PipelineError::NoRequirements { .. } => Some(lang.pick(
            "--checkout (or --no-python)",
            "--checkout (vagy --no-python)",
        )),
        PipelineError::Tool(ToolError::Start { .. }) => {
            Some(lang.pick("--python (or --no-python)", "--python (vagy --no-python)"))
        }
        PipelineError::CreateDir { .. }
        | PipelineError::Write(_)
        | PipelineError::Reference(_)
        | PipelineError::Tool(ToolError::Failed { .. })
        | PipelineError::Regenerate(_) => None,
    }
}

/// What stopped the pipeline, in Hungarian.
fn pipeline_hu(error: &PipelineError) -> String {
    match error {
        PipelineError::OutNotADirectory { path } => format!(
            "a(z) {} kimeneti könyvtár létezik, de nem könyvtár",
            path.display()
        ),
        PipelineError::CreateDir { path, source } => format!(
            "a(z) {} könyvtár nem hozható létre: {source}",
            path.display()
        ),
        PipelineError::NoRequirements { path } => format!(
            "{} nem található: a Python-oldal a programcsomag munkapéldányából fut",
            path.display()
        ),
        PipelineError::Write(error) => output(error, Lang::Hu),
        PipelineError::Reference(error) => reference_hu(error),
        PipelineError::Tool(error) | PipelineError::Regenerate(RegenerateError::Tool(error)) => {
            tool_hu(error)
        }
        PipelineError::Regenerate(RegenerateError::Undecided {
            file,
            status,
            stderr,
        }) => format!(
            "a python-checks/reproduce.py nem tudta eldönteni, egyezik-e {file} ({status}): \
             {stderr}"
        ),
    }
}

fn reference_hu(error: &ReferenceError) -> String {
    match error {
        ReferenceError::Io { path, source } => {
            format!("a(z) {} referencia nem olvasható: {source}", path.display())
        }
        ReferenceError::Malformed {
            path,
            field,
            message,
        } => format!(
            "a(z) {} referencia hibás itt: `{field}`: {message}",
            path.display()
        ),
        ReferenceError::Schema {
            path,
            found,
            expected,
        } => format!(
            "a(z) {} referencia sémája `{found}`, a várt séma `{expected}`",
            path.display()
        ),
    }
}

/// A tool that could not start or failed, in `lang`.
pub(super) fn tool(error: &ToolError, lang: Lang) -> String {
    match lang {
        Lang::En => error.to_string(),
        Lang::Hu => tool_hu(error),
    }
}

fn tool_hu(error: &ToolError) -> String {
    match error {
        ToolError::Start {
            what,
            program,
            source,
        } => format!("{}: a(z) {program} nem indítható: {source}", task_hu(what)),
        ToolError::Failed {
            what,
            status,
            stderr_tail,
        } => format!("{}: sikertelen ({status}):\n{stderr_tail}", task_hu(what)),
    }
}

fn task_hu(task: &Task) -> String {
    match task {
        Task::CreateEnvironment { base } => format!(
            "a virtuális környezet létrehozása a(z) `{} -m venv` paranccsal (telepítve van a Python 3?)",
            base.display()
        ),
        Task::InstallRequirements => {
            "a python-checks/requirements.txt telepítése pip-pel".to_owned()
        }
        Task::CheckPins => "a telepített Python-csomagok ellenőrzése".to_owned(),
        Task::Script(script) => script.clone(),
    }
}
