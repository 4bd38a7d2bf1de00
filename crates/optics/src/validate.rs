//! `optics validate`: the cross-check harness's command.

use crate::Ui;

#[derive(clap::Args, Debug)]
pub struct ValidateArgs {
    /// Run the reduced set of checks.
    #[arg(long)]
    pub quick: bool,
}

pub fn run(_args: &ValidateArgs, _ui: &Ui) -> anyhow::Result<()> {
    anyhow::bail!("validation is not available yet")
}
