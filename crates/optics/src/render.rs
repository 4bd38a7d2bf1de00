//! `optics render`: the tracer's command.

use crate::Ui;

#[derive(clap::Args, Debug)]
pub struct RenderArgs {
    /// The scene file (JSON).
    pub scene: std::path::PathBuf,
}

pub fn run(_args: &RenderArgs, _ui: &Ui) -> anyhow::Result<()> {
    anyhow::bail!("rendering is not available yet")
}
