//! The suite's command line, `optics`, as a library: the binary is a thin
//! `main` over [`main_entry`], and benches drive [`batch`] directly. It
//! parses, calls, and prints through [`ui`]; the features it fronts live in
//! the library crates below it.
//!
//! Every subcommand prints a record (the working and the answer) as text, or
//! with `--json` as one JSON object whose fields `docs/cli.md` documents
//! ("The JSON record").
//! Errors are typed ([`Error`], [`ErrorKind`]), name the argument that was
//! wrong, come in the chosen language (with `--json` also as the object
//! [`Error::to_json`] writes), and exit with status 1 (2 for command-line
//! syntax, as reported by the argument parser).

//!
//! A law from a library: the arguments read as a batch request would give
//! them, evaluated, the record's answer.
//!
//! ```
//! use optics::input::Via;
//! use optics::law_table::Law;
//! use optics::Lang;
//! use record::Steps;
//!
//! let fields = serde_json::json!({"n": 1.5});
//! let law = Law::read("f0", &fields).expect("a law").expect("its fields");
//! let record = law.solve(Via::Json, Lang::En, Steps::Wanted).unwrap();
//! assert_eq!(serde_json::to_value(&record).unwrap()["answer"], 0.04);
//! ```

#![warn(missing_docs)]

pub mod batch;
#[cfg(feature = "harness")]
pub mod budget;
#[cfg(feature = "harness")]
mod checkout;
#[cfg(feature = "harness")]
mod compare;
mod envmap;
mod errata;
pub mod error;
#[cfg(test)]
mod fuzz;
mod help_example;
mod image_size;
pub mod input;
mod inspect;
pub mod lang;
pub mod law_table;
pub mod laws;
mod missing_light;
mod planar;
pub mod quiz;
pub(crate) mod render;
#[cfg(feature = "harness")]
pub mod tradeoff;
pub mod ui;
#[cfg(feature = "harness")]
mod validate;

pub use error::{Error, ErrorKind};
pub use record::Lang;
pub use ui::Ui;
use ui::{print_err, print_out, reader_gone};

use clap::{Parser, Subcommand};
use input::Via;
use record::{Record, Steps};
use std::process::ExitCode;

#[derive(Parser, Debug)]
#[command(
    name = "optics",
    version,
    about = "Optics laws, the course's quiz, and the course's ray tracers, cross-checked.",
    after_help = "Examples:
  optics quiz seed
  optics fresnel --eta 1.5 --theta-i-deg 60
  optics --json refract --wi 0,0.6,0.8 --normal 0,0,1 --eta 1.5
  optics envmap --dir -3.2,5.1,-8.4 --map cube
  optics --lang hu quiz f0 --n 1.4"
)]
struct Cli {
    /// Print one JSON object instead of text.
    #[arg(long, global = true)]
    json: bool,
    /// Language of the text output: en (English) or hu (magyar).
    #[arg(long, global = true, value_enum, default_value = "en")]
    lang: Lang,
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Worked exercises of the course's quiz, with the steps.
    Quiz(QuizArgs),
    /// The laws, each a subcommand of its own (`law_table`).
    #[command(flatten)]
    Law(law_table::LawCommand),
    /// Evaluate JSON Lines requests from stdin, one JSON result per line.
    Batch(batch::BatchArgs),
    /// Render a scene file to PNG and a float image.
    Render(render::RenderArgs),
    /// Report which effects a scene needs and what the renderer skips.
    Inspect(inspect::InspectArgs),
    /// The errata of the course texts, ranked by class, or one by its id.
    Errata(errata::ErrataArgs),
    /// Cross-check the laws, spectra and renders against the references.
    #[cfg(feature = "harness")]
    Validate(validate::ValidateArgs),
    /// Check a render of a scene (PNG or PFM) against the tracer's reference.
    #[cfg(feature = "harness")]
    Compare(compare::CompareArgs),
    /// Measure what each shortcut a scene allows costs in accuracy and buys in time.
    #[cfg(feature = "harness")]
    Tradeoff(tradeoff::TradeoffArgs),
    /// Run one job of a sweep planned with `optics tradeoff --plan`.
    #[cfg(feature = "harness")]
    TradeoffJob(tradeoff::TradeoffJobArgs),
}

#[derive(clap::Args, Debug)]
#[command(
    allow_negative_numbers = true,
    after_help = "Examples:
  optics quiz                 (lists the exercises)
  optics quiz seed            (works every question of the course's quiz)
  optics quiz f0 --n 1.4
  optics --lang hu quiz seed"
)]
struct QuizArgs {
    #[command(subcommand)]
    exercise: Option<Exercise>,
}

#[derive(Subcommand, Debug)]
enum Exercise {
    /// Every question of the course's quiz, with the printed answers checked.
    #[command(after_help = "Examples:
  optics quiz seed
  optics --lang hu quiz seed          (in the course's language)
  optics --json quiz seed             (one JSON object; the questions under details.questions)")]
    Seed,
    /// The exercises one can pose with other numbers (`law_table`).
    #[command(flatten)]
    Law(law_table::QuizLaw),
}

/// The record of a command that evaluates one law with its flags; `None`
/// for the others.
fn law_record(command: &Command, lang: Lang) -> Option<error::Result<Record>> {
    let (via, steps) = (Via::Flags, Steps::Wanted);
    Some(match command {
        Command::Law(law) => law.solve(via, lang, steps),
        Command::Quiz(args) => match args.exercise.as_ref()? {
            Exercise::Law(law) => law.solve(via, lang, steps),
            Exercise::Seed => return None,
        },
        _ => return None,
    })
}

fn run(command: &Command, ui: &Ui) -> error::Result<ExitCode> {
    let lang = ui.lang;
    if let Some(record) = law_record(command, lang) {
        ui.show(&record?)?;
        return Ok(ExitCode::SUCCESS);
    }
    match command {
        Command::Quiz(args) => match &args.exercise {
            Some(Exercise::Seed) if ui.json => ui.show(&quiz::seed_record(lang)?)?,
            Some(Exercise::Seed) => {
                for (i, question) in quiz::seed(lang)?.iter().enumerate() {
                    if i > 0 {
                        print_out("\n")?;
                    }
                    ui.show(question)?;
                }
            }
            _ => {
                let command = parser_command(lang);
                let quiz = command
                    .find_subcommand("quiz")
                    .expect("the command line has quiz");
                ui.show(&quiz::list(lang, quiz))?
            }
        },
        Command::Batch(args) => {
            let stdin = std::io::stdin().lock();
            let stdout = std::io::BufWriter::with_capacity(1 << 16, std::io::stdout().lock());
            let (read, failed) = batch::run(args, stdin, stdout, lang)?;
            if failed > 0 {
                let summary = record::say!(
                    lang,
                    "optics batch: {failed} of {read} lines gave errors",
                    "optics batch: {read} sorból {failed} hibás"
                );
                print_err(&format!("{summary}\n"));
                return Ok(ExitCode::FAILURE);
            }
        }
        Command::Render(args) => render::run(args, ui)?,
        Command::Inspect(args) => inspect::run(args, ui)?,
        Command::Errata(args) => errata::run(args, ui)?,
        #[cfg(feature = "harness")]
        Command::Validate(args) => return validate::run(args, ui),
        #[cfg(feature = "harness")]
        Command::Compare(args) => return compare::run(args, ui),
        #[cfg(feature = "harness")]
        Command::Tradeoff(args) => tradeoff::run(args, ui)?,
        #[cfg(feature = "harness")]
        Command::TradeoffJob(args) => tradeoff::run_job(args, ui)?,
        // Evaluated by `law_record` above.
        Command::Law(_) => {}
    }
    Ok(ExitCode::SUCCESS)
}

/// Parses the command line, runs the command, prints any error; the exit status.
pub fn main_entry() -> ExitCode {
    let args: Vec<std::ffi::OsString> = std::env::args_os().collect();
    // The form asked for, read before parsing: a help page or a syntax
    // error is already in it.
    let asked = Ui::from_raw_args(args.iter().cloned());
    let cli = match parse(args, asked.lang) {
        Ok(cli) => cli,
        Err(usage) => return usage_failure(usage, &asked),
    };
    let ui = Ui {
        json: cli.json,
        lang: cli.lang,
    };
    match run(&cli.command, &ui) {
        Ok(code) => code,
        Err(error) if reader_gone(&error) => ExitCode::SUCCESS,
        Err(error) => {
            ui.report(&error);
            ExitCode::FAILURE
        }
    }
}

/// The parser's command, its help in `lang`.
fn parser_command(lang: Lang) -> clap::Command {
    use clap::CommandFactory;
    match lang {
        Lang::En => Cli::command(),
        Lang::Hu => lang::help::hungarian(Cli::command()),
    }
}

/// The command line parsed by the parser whose help speaks `lang`.
fn parse(args: Vec<std::ffi::OsString>, lang: Lang) -> Result<Cli, clap::Error> {
    use clap::FromArgMatches;
    let mut command = parser_command(lang);
    let mut matches = command.try_get_matches_from_mut(args)?;
    Cli::from_arg_matches_mut(&mut matches).map_err(|error| error.format(&mut command))
}

/// A command line that did not parse, or asked for help or the version.
fn usage_failure(usage: clap::Error, ui: &Ui) -> ExitCode {
    use clap::error::ErrorKind as Clap;
    let code = ExitCode::from(u8::try_from(usage.exit_code()).unwrap_or(2));
    match usage.kind() {
        Clap::DisplayHelp
        | Clap::DisplayVersion
        | Clap::DisplayHelpOnMissingArgumentOrSubcommand => {
            // Help is what was asked for, not a failure to report.
            let _ = usage.print();
        }
        _ => ui.report(&ErrorKind::Usage(usage).into()),
    }
    code
}
