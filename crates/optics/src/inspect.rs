//! `optics inspect`: what a scene needs.

use crate::Ui;

#[derive(clap::Args, Debug)]
pub struct InspectArgs {
    /// The scene file (JSON).
    pub scene: std::path::PathBuf,
}

pub fn run(_args: &InspectArgs, _ui: &Ui) -> anyhow::Result<()> {
    anyhow::bail!("inspection is not available yet")
}
