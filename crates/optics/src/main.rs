//! `optics`: the suite's command line.

mod inspect;
mod render;
mod validate;

use clap::{Parser, Subcommand, ValueEnum};
use std::process::ExitCode;

/// How results are shown: plain text or one JSON object, in English or Hungarian.
#[derive(Debug, Clone, Copy)]
pub struct Ui {
    pub json: bool,
    pub lang: Lang,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Lang {
    En,
    Hu,
}

#[derive(Parser, Debug)]
#[command(name = "optics", version, about)]
struct Cli {
    /// Print one JSON object instead of text.
    #[arg(long, global = true)]
    json: bool,
    /// Language of the text output.
    #[arg(long, global = true, value_enum, default_value_t = Lang::En)]
    lang: Lang,
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Render a scene file to PNG and a float image.
    Render(render::RenderArgs),
    /// Report which effects a scene needs and what the renderer skips.
    Inspect(inspect::InspectArgs),
    /// Cross-check the laws, spectra and renders against the references.
    Validate(validate::ValidateArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let ui = Ui { json: cli.json, lang: cli.lang };
    let result = match &cli.command {
        Command::Render(args) => render::run(args, &ui),
        Command::Inspect(args) => inspect::run(args, &ui),
        Command::Validate(args) => validate::run(args, &ui),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("error: {error:#}");
            ExitCode::FAILURE
        }
    }
}
