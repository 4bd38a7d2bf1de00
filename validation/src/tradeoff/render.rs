//! One render of a sweep's point, a truth's half or a budget's pilot.

use std::path::Path;

use tracer::job::RenderJob;
use tracer::render::Rendered;
use tracer::scene::Settings;

use super::error::TradeoffError;

/// Renders `job`'s scene (read from `file`) with `settings`.
pub fn render(
    job: &RenderJob,
    file: &Path,
    settings: Settings,
    threads: Option<usize>,
) -> Result<Rendered, TradeoffError> {
    let job = RenderJob::with_settings(job.scene().clone(), settings).map_err(|error| {
        TradeoffError::Scene {
            file: file.to_owned(),
            error,
        }
    })?;
    Ok(job.render(threads, &|_| {})?)
}
