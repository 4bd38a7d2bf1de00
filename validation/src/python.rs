//! The Python side of the harness: the virtual environment the references
//! come from, pinned by `python-checks/requirements.txt`, and running its
//! scripts with their failures named.

use std::fmt;
use std::path::{Path, PathBuf};
use std::process::Command;

/// What a tool was run for, as its errors name it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Task {
    /// Creating the virtual environment with `base -m venv`.
    CreateEnvironment {
        /// The Python 3 interpreter that creates it.
        base: PathBuf,
    },
    /// Installing the pinned requirements with pip.
    InstallRequirements,
    /// Checking the installed packages against the pins.
    CheckPins,
    /// Running one of the suite's scripts: its path in the checkout
    /// (`python-checks/plot_report.py`).
    Script(String),
}

impl fmt::Display for Task {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Task::CreateEnvironment { base } => write!(
                f,
                "creating the virtual environment with `{} -m venv` (is Python 3 installed?)",
                base.display()
            ),
            Task::InstallRequirements => {
                f.write_str("installing python-checks/requirements.txt with pip")
            }
            Task::CheckPins => f.write_str("checking the installed Python packages"),
            Task::Script(script) => f.write_str(script),
        }
    }
}

/// Why a Python tool could not be used.
#[derive(Debug, thiserror::Error)]
pub enum ToolError {
    /// The program could not be started.
    #[error("{what}: cannot run {program}: {source}")]
    Start {
        /// What was being done.
        what: Task,
        /// The program.
        program: String,
        /// The cause.
        source: std::io::Error,
    },
    /// The program ran and failed.
    #[error("{what} failed ({status}):\n{stderr_tail}")]
    Failed {
        /// What was being done.
        what: Task,
        /// Its exit status.
        status: std::process::ExitStatus,
        /// The last lines of its standard error.
        stderr_tail: String,
    },
}

/// A step of setting the environment up, for progress messages.
#[derive(Clone, Copy, Debug)]
pub enum SetUp<'a> {
    /// Creating the environment (the first run: downloads the tools).
    Creating {
        /// The environment's directory.
        venv: &'a Path,
    },
    /// Installing the pinned requirements.
    Installing {
        /// The requirements file.
        requirements: &'a Path,
    },
}

/// Runs `command`, naming it (`what`) in the error if it cannot start or
/// fails; its standard output.
pub fn run_tool(mut command: Command, what: Task) -> Result<String, ToolError> {
    let output = match command.output() {
        Ok(output) => output,
        Err(source) => {
            return Err(ToolError::Start {
                what,
                program: format!("{:?}", command.get_program()),
                source,
            })
        }
    };
    if !output.status.success() {
        let stderr = String::from_utf8_lossy(&output.stderr);
        let tail: Vec<_> = stderr.lines().rev().take(8).collect();
        return Err(ToolError::Failed {
            what,

            status: output.status,
            stderr_tail: tail.into_iter().rev().collect::<Vec<_>>().join("\n"),
        });
    }
    Ok(String::from_utf8_lossy(&output.stdout).into_owned())
}

/// The environment `venv`'s interpreter, after creating the environment
/// with `base` (a Python 3 interpreter) and installing the pinned
/// `requirements` if needed; `progress` hears of each step taken.
pub fn ensure_environment(
    base: &Path,
    venv: &Path,
    requirements: &Path,
    mut progress: impl FnMut(SetUp),
) -> Result<PathBuf, ToolError> {
    let interpreter = venv.join("bin/python");
    if !interpreter.is_file() {
        progress(SetUp::Creating { venv });
        let mut create = Command::new(base);
        create.arg("-m").arg("venv").arg(venv);
        run_tool(
            create,
            Task::CreateEnvironment {
                base: base.to_owned(),
            },
        )?;
    } else if pins_satisfied(&interpreter, requirements)? {
        return Ok(interpreter);
    }
    progress(SetUp::Installing { requirements });
    let mut install = Command::new(&interpreter);
    install
        .args([
            "-m",
            "pip",
            "install",
            "--quiet",
            "--disable-pip-version-check",
            "-r",
        ])
        .arg(requirements);
    run_tool(install, Task::InstallRequirements)?;
    Ok(interpreter)
}

/// Whether every `name==version` pin is installed at that version.
fn pins_satisfied(interpreter: &Path, requirements: &Path) -> Result<bool, ToolError> {
    const CHECK: &str = "import sys, importlib.metadata as m\n\
        bad = []\n\
        for line in open(sys.argv[1], encoding='utf-8'):\n\
        \x20   line = line.split('#')[0].strip()\n\
        \x20   if '==' in line:\n\
        \x20       name, want = line.split('==')\n\
        \x20       try:\n\
        \x20           have = m.version(name)\n\
        \x20       except m.PackageNotFoundError:\n\
        \x20           have = None\n\
        \x20       if have != want:\n\
        \x20           bad.append(f'{name} {have} (pinned {want})')\n\
        print('\\n'.join(bad))\n";
    let mut check = Command::new(interpreter);
    check.arg("-c").arg(CHECK).arg(requirements);
    Ok(run_tool(check, Task::CheckPins)?.trim().is_empty())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_program_that_cannot_start_is_named() {
        let base = PathBuf::from("/nonexistent/python3");
        let error = run_tool(
            Command::new(&base),
            Task::CreateEnvironment { base: base.clone() },
        )
        .unwrap_err();
        let message = error.to_string();
        assert!(
            matches!(&error, ToolError::Start { what, .. } if *what == Task::CreateEnvironment { base })
                && message.contains("creating the virtual environment")
                && message.contains("/nonexistent/python3"),
            "{message}"
        );
    }

    #[cfg(unix)]
    #[test]
    fn a_failing_program_reports_the_end_of_its_stderr() {
        let mut command = Command::new("sh");
        command
            .arg("-c")
            .arg("for i in 1 2 3 4 5 6 7 8 9 10; do echo line$i >&2; done; exit 3");
        let message = run_tool(command, Task::Script("the script".into()))
            .unwrap_err()
            .to_string();
        assert!(message.starts_with("the script failed"), "{message}");
        assert!(
            message.contains("line3") && message.contains("line10") && !message.contains("line2\n"),
            "the last eight lines: {message}"
        );
    }
}
