//! The result line a job writes (`optics.tradeoff-result`): its times,
//! its rays and the images the measures read, every `f32` as rendered.

use base64::Engine as _;
use serde::{Deserialize, Serialize};
use tracer::output::{pfm_bytes, read_pfm};
use tracer::render::Image;

use super::error::{ImageProblem, JobError, Place};

/// The fields of a result line, by name, in the order [`JobResult`]
/// declares them.
pub const RESULT_FIELDS: [&str; 14] = [
    "schema",
    "version",
    "plan",
    "planned_as",
    "scene_fnv1a",
    "job",
    "jobs",
    "label",
    "seconds",
    "rays",
    "machine",
    "date",
    "load",
    "images",
];

/// What a job rendered: one line of `optics.tradeoff-result`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct JobResult {
    /// `optics.tradeoff-result`.
    pub schema: String,
    /// [`super::VERSION`].
    pub version: u32,
    /// The plan's id.
    pub plan: String,
    /// The command that plans it (with `--plan`), or renders the same
    /// sweep in one run: what `--collect` is to be given.
    pub planned_as: String,
    /// FNV-1a of the scene file the job rendered.
    pub scene_fnv1a: String,
    /// The job, from 0.
    pub job: usize,
    /// The plan's jobs.
    pub jobs: usize,
    /// The job's label.
    pub label: String,
    /// Every render's time, s, in the order taken (after one untimed
    /// warm-up render of a point).
    pub seconds: Vec<f64>,
    /// Rays cast over all the renders.
    pub rays: f64,
    /// The machine the times were taken on.
    pub machine: String,
    /// `YYYY-MM-DD`, UTC.
    pub date: String,
    /// The load average as the job ended.
    pub load: Option<String>,
    /// The images kept ([`super::Planned::kept`]), each its PFM file in base64,
    /// in the order of their seeds.
    pub images: Vec<String>,
}

impl JobResult {
    /// Checks the result's numbers and decodes its images, `kept` of them
    /// of `width` × `height` pixels.
    pub fn images(
        &self,
        at: &Place,
        kept: usize,
        (width, height): (u32, u32),
    ) -> Result<Vec<Image>, JobError> {
        let times = |field| JobError::Times {
            at: at.clone(),
            field,
        };
        let renders = self.seconds.len();
        if !(1..=64).contains(&renders) || !self.seconds.iter().all(|s| *s >= 0.0 && s.is_finite())
        {
            return Err(times("seconds"));
        }
        if !(self.rays >= 0.0 && self.rays.is_finite()) {
            return Err(times("rays"));
        }
        if self.images.len() != kept {
            let problem = ImageProblem::Count {
                got: self.images.len(),
                expected: kept,
            };
            return Err(image_error(at, problem));
        }
        self.images
            .iter()
            .enumerate()
            .map(|(index, text)| {
                let image = base64::engine::general_purpose::STANDARD
                    .decode(text)
                    .ok()
                    .and_then(|bytes| read_pfm(&bytes))
                    .ok_or_else(|| image_error(at, ImageProblem::Encoding { index }))?;
                if (image.width, image.height) != (width, height) {
                    let problem = ImageProblem::Size {
                        index,
                        got: (image.width, image.height),
                        expected: (width, height),
                    };
                    return Err(image_error(at, problem));
                }
                Ok(image)
            })
            .collect()
    }
}

fn image_error(at: &Place, problem: ImageProblem) -> JobError {
    JobError::Image {
        at: at.clone(),
        problem,
    }
}

/// An image as a result line carries it: its PFM file in base64, every
/// `f32` as rendered.
pub fn encode(image: &Image) -> String {
    base64::engine::general_purpose::STANDARD.encode(pfm_bytes(image))
}
