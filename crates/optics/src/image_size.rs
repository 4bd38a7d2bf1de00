//! `--width` and `--height`, declared once for the commands that render a
//! scene at another size than its own (`render`, `tradeoff`).

use serde::Serialize;
use tracer::scene::MAX_IMAGE_SIDE;

/// The image's size in pixels, where it overrides the scene's.
#[derive(clap::Args, Clone, Copy, Debug, Default, Serialize)]
pub struct ImageSize {
    /// Image width in pixels (default: the scene's); the camera keeps its view.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=MAX_IMAGE_SIDE as i64))]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub width: Option<u32>,
    /// Image height in pixels (default: the scene's).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=MAX_IMAGE_SIDE as i64))]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub height: Option<u32>,
}
