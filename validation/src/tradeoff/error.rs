//! Why a sweep, a budget or one of their renders could not run: the
//! library's kinds, each naming the value that was wrong and never a
//! command-line flag (the front end that took the value adds its name).

use std::path::PathBuf;

use tracer::job::RenderError;
use tracer::output::OutputError;
use tracer::scene::SceneError;

/// A failure of the trade-off library.
#[derive(Debug, thiserror::Error)]
pub enum TradeoffError {
    /// The scene, or a setting a sweep gives it, that the tracer refused.
    #[error("scene {}: {error}", file.display())]
    Scene {
        /// The scene file, as given.
        file: PathBuf,
        /// The tracer's error.
        error: SceneError,
    },
    /// A render that could not run or finish.
    #[error(transparent)]
    Render(#[from] RenderError),
    /// A file (a cached truth, a record) that could not be written.
    #[error(transparent)]
    Output(OutputError),
    /// A record that could not be written as JSON; serde's message.
    #[error(transparent)]
    Encode(serde_json::Error),
}
