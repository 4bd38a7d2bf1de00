//! `optics validate`: the cross-check harness's command, a front over
//! [`validation::pipeline`]: the flags become its options, its steps
//! progress messages, its outcome the output and the exit status.

use std::io::IsTerminal;
use std::path::PathBuf;
use std::process::ExitCode;

use indicatif::{ProgressBar, ProgressStyle};
use validation::pipeline::{self, Options, Outcome, PythonOptions, Step};
use validation::python::SetUp;

use crate::error::{self, ErrorKind, HarnessKind};
use crate::ui::Ui;
use record::{say, Lang};
use record::{Answer, Record};

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:
  optics validate                      regenerate the references with the pinned tools, check
  optics validate --quick              the committed references, no regeneration (CI runs this)
  optics validate --quick --no-python  no Python at all: no set-up, no figures
  optics --json validate --quick --out /tmp/validation
  optics validate --quick --checkout ~/src/optics

Reads the suite's checkout: --checkout, else $OPTICS_CHECKOUT, else the
checkout containing the working directory. Writes report.json, report.html
and figures/*.png into --out. On first use the Python environment (--venv,
pinned by python-checks/requirements.txt) is created; that downloads
Mitsuba 3, colour-science and matplotlib once. Exit status 1 when any check
fails.")]
#[derive(serde::Serialize)]
pub struct ValidateArgs {
    /// Run the reduced set: check against the committed references instead of
    /// regenerating them.
    #[arg(long)]
    pub quick: bool,
    /// The suite's checkout (holding validation/reference/ and
    /// python-checks/) [default: $OPTICS_CHECKOUT, else the checkout
    /// containing the working directory].
    #[arg(long, value_name = "DIR")]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub checkout: Option<PathBuf>,
    /// Directory for report.json, report.html and figures/ (created if
    /// missing) [default: validation/out in the checkout].
    #[arg(long, value_name = "DIR")]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub out: Option<PathBuf>,
    /// The Python virtual environment, created if missing [default: .venv in
    /// the checkout].
    #[arg(long, value_name = "DIR")]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub venv: Option<PathBuf>,
    /// The Python 3 interpreter that creates the environment.
    #[arg(long, value_name = "PATH", default_value = "python3")]
    pub python: PathBuf,
    /// Use no Python: check against the committed references, draw no figures.
    #[arg(long)]
    pub no_python: bool,
    /// Seed of the random cases evaluated by Mitsuba.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
}

impl ValidateArgs {
    /// The pipeline's options: the checkout found, the flags as they are.
    fn options(&self, lang: Lang) -> error::Result<Options> {
        let checkout = crate::checkout::lookup(self.checkout.as_deref())
            .find()
            .map_err(HarnessKind::CheckoutWithFlag)?;
        // The command as typed, by the program's name rather than its build path.
        let command = std::iter::once("optics".to_owned())
            .chain(std::env::args().skip(1))
            .collect::<Vec<_>>()
            .join(" ");
        Ok(Options {
            checkout,
            quick: self.quick,
            out: self.out.clone(),
            python: (!self.no_python).then(|| PythonOptions {
                base: self.python.clone(),
                venv: self.venv.clone(),
            }),
            seed: self.seed,
            command,
            lang,
        })
    }
}

/// Runs the harness; the exit status says whether every check passed (with
/// `--json` the record is the whole answer, without it a failure is also
/// reported as an error).
pub fn run(args: &ValidateArgs, ui: &Ui) -> error::Result<ExitCode> {
    let options = args.options(ui.lang)?;
    let bar = (std::io::stderr().is_terminal() && !ui.json).then(|| {
        let bar = ProgressBar::new(0);
        bar.set_style(
            ProgressStyle::with_template("{bar:30} {pos}/{len} {msg}")
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
        );
        bar
    });
    let outcome = pipeline::run(&options, |step| progress(ui, bar.as_ref(), step));
    if let Some(bar) = &bar {
        bar.finish_and_clear();
    }
    let outcome = outcome.map_err(HarnessKind::Pipeline)?;
    ui.show_steps(&record(args, &outcome, ui.lang))?;
    let s = &outcome.report.summary;
    match (outcome.passed(), ui.json) {
        (true, _) => Ok(ExitCode::SUCCESS),
        (false, true) => Ok(ExitCode::FAILURE),
        (false, false) => Err(ErrorKind::Harness(HarnessKind::ChecksFailed {
            failed: s.failed,
            checks: s.checks,
        })
        .into()),
    }
}

/// One step's progress message on stderr (never on stdout, which carries
/// the result), or the progress bar's position.
fn progress(ui: &Ui, bar: Option<&ProgressBar>, step: Step) {
    let lang = ui.lang;
    let message = match step {
        Step::Python(SetUp::Creating { venv }) => say!(lang,
            "setting up the Python environment in {} (first run: installs Mitsuba 3, colour-science, matplotlib, mpmath; a few minutes)",
            "a Python-környezet létrehozása itt: {} (első futás: Mitsuba 3, colour-science, matplotlib, mpmath telepítése; néhány perc)",
            venv.display()),
        Step::Python(SetUp::Installing { requirements }) => say!(
            lang,
            "installing the pinned requirements ({})",
            "a rögzített csomagok telepítése ({})",
            requirements.display()
        ),
        Step::Regenerating => say!(
            lang,
            "regenerating the references with the pinned tools",
            "a referenciák újragenerálása a rögzített eszközökkel"
        ),
        Step::Checks {
            index,
            total,
            names: [name, name_hu],
        } => match bar {
            Some(bar) => {
                bar.set_length(total as u64);
                bar.set_position(index as u64);
                bar.set_message(lang.pick(name, name_hu).to_owned());
                return;
            }
            None => format!("[{}/{total}] {}", index + 1, lang.pick(name, name_hu)),
        },
        Step::ChecksDone => {
            if let Some(bar) = bar {
                bar.finish_and_clear();
            }
            return;
        }
        Step::RandomCases { cases } => say!(
            lang,
            "evaluating {} random cases with Mitsuba",
            "{} véletlen eset kiértékelése a Mitsubával",
            cases
        ),
        Step::DrawingFigures => say!(lang, "drawing the figures", "az ábrák rajzolása"),
    };
    if ui.json {
        return;
    }
    // The Python steps start beside the checks: above the bar while it runs.
    match bar {
        Some(bar) if !bar.is_finished() && !bar.is_hidden() => {
            bar.println(format!("optics validate: {message}"));
        }
        _ => crate::ui::print_err(&format!("optics validate: {message}\n")),
    }
}

/// The run's record: the verdict as the answer, one step per check (and
/// its first failures), the speed and the summary lines.
fn record(args: &ValidateArgs, outcome: &Outcome, lang: Lang) -> Record {
    let report = &outcome.report;
    let mut record = Record::new("validate", String::new(), "");
    record
        .inputs_from(args)
        .set_answer(Answer::Verdict(outcome.passed()), None);
    for check in &report.checks {
        let mark = match (check.passed(), lang) {
            (true, Lang::En) => "pass",
            (false, Lang::En) => "FAIL",
            (true, Lang::Hu) => "jó  ",
            (false, Lang::Hu) => "HIBA",
        };
        record.step(|| {
            say!(
                lang,
                "{}  {} ({} cases, {} findings)",
                "{}  {} ({} eset, {} megállapítás)",
                mark,
                check.id,
                check.cases,
                check.findings.len()
            )
        });
        for failure in check.failures.iter().take(5) {
            record.step(|| format!("      {failure}"));
        }
    }
    if let [spectral, rgb] = report.speed.as_slice() {
        record.step(|| {
            say!(
                lang,
                "gold's colour: {:.2} µs from 85 wavelengths, {:.2} µs from three ({:.1}×{})",
                "az arany színe: {:.2} µs 85 hullámhosszból, {:.2} µs háromból ({:.1}×{})",
                spectral.ns_per_colour / 1e3,
                rgb.ns_per_colour / 1e3,
                spectral.ns_per_colour / rgb.ns_per_colour,
                if spectral.optimised {
                    ""
                } else {
                    lang.pick(", unoptimised build", ", optimalizálatlan fordítás")
                }
            )
        });
    }
    let s = &report.summary;
    record.step(|| {
        say!(
        lang,
        "{} checks: {} passed, {} failed; {} findings about the references. Report: {}",
        "{} ellenőrzés: {} sikeres, {} sikertelen; {} megállapítás a referenciákról. Jelentés: {}",
        s.checks,
        s.passed,
        s.failed,
        s.findings,
        outcome.report_html().display()
    )
    });
    let failed: Vec<&String> = report
        .checks
        .iter()
        .filter(|c| !c.passed())
        .map(|c| &c.id)
        .collect();
    record
        .detail("summary", &report.summary)
        .detail("report_json", outcome.report_json())
        .detail("report_html", outcome.report_html())
        .detail("figures", &outcome.figures)
        .detail("failed_checks", failed);
    record
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_checkout_flag_is_read_before_the_variable_and_the_search() {
        let args = ValidateArgs {
            quick: true,
            checkout: Some(PathBuf::from("/nonexistent/checkout")),
            out: None,
            venv: None,
            python: PathBuf::from("python3"),
            no_python: true,
            seed: 1,
        };
        let message = args.options(Lang::En).unwrap_err().to_string();
        assert!(
            message.starts_with("--checkout /nonexistent/checkout: not a checkout"),
            "{message}"
        );
    }
}
