//! The ground truth a sweep is measured against: the scene converged with
//! all the light ([`sweep::truth_settings`]), rendered as two independent
//! halves so that its own noise is known, and cached beside the results
//! under a key of everything it depends on.

use std::path::{Path, PathBuf};

use safe_io::write_all_atomically;
use serde::{Deserialize, Serialize};
use tracer::job::RenderJob;
use tracer::output::read_pfm;
use tracer::render::Image;
use tracer::scene::Settings;

use super::error::TradeoffError;
use super::measure::{Mask, Truth};
use super::render::render;
use super::sweep;

/// The tracer's and the laws' source as this build compiled them (FNV-1a
/// of every `.rs` file under `crates/tracer/src` and `crates/radiometry/src`,
/// by `build.rs`): a truth rendered by other code is of another key.
pub const TRACER_SOURCE: &str = env!("OPTICS_TRACER_SOURCE");

/// What the sweep's JSON says of its truth.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct TruthRecord {
    /// The settings of each half (the second half's seed is one more).
    pub settings: serde_json::Value,
    /// Samples per pixel over both halves.
    pub spp: u32,
    /// Seconds the two halves took to render, when they were rendered.
    pub seconds: f64,
    /// Its noise relative to its energy: the floor under the squared
    /// relative errors measured against it.
    pub noise_relative: f64,
    /// Its variance per surface pixel-channel (mean).
    pub noise: f64,
    /// The standard deviation of its light `Σ t` over the surface
    /// pixel-channels, relative (set by the sweep from the image).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub light_noise_relative: Option<f64>,
    /// Whether it was read from the cache rather than rendered now.
    #[serde(default)]
    pub cached: bool,
    /// Why a cache entry found under its key was not used and the truth
    /// rendered again (the entry unreadable, cut short, of another key or
    /// size, or holding a radiance that is not a number).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub replaced: Option<Stale>,
    /// The cache key: FNV-1a of the scene file, the size, the settings
    /// and the tracer's version.
    pub key: String,
    /// The cached image, a PFM.
    pub file: String,
}

/// What truth a sweep asks for, and where it may be cached.
pub struct Request<'a> {
    /// The scene file, as given (its bytes are part of the key).
    pub scene_file: &'a Path,
    /// Samples per pixel over both halves.
    pub spp: u32,
    /// Whether the scene's course_rough is measured as Lambert.
    pub lambert: bool,
    /// The cache's directory.
    pub dir: &'a Path,
    /// Render again even when the cache holds this truth.
    pub fresh: bool,
}

/// Where the truth a request asks for is cached, under which key.
pub struct Cache {
    /// The settings of the first half (the second's seed is one more).
    pub half: Settings,
    settings_json: serde_json::Value,
    key: String,
    image_path: PathBuf,
    meta_path: PathBuf,
}

impl Cache {
    /// The cache entry of `job`'s truth as `request` asks for it.
    pub fn new(job: &RenderJob, request: &Request<'_>) -> Result<Self, TradeoffError> {
        let half = sweep::truth_settings(job, (request.spp / 2).max(1));
        let scene_bytes = std::fs::read(request.scene_file).unwrap_or_default();
        let settings_json = serde_json::to_value(half).map_err(TradeoffError::Encode)?;
        let key = format!(
            "{:016x}",
            fnv1a(&[
                &scene_bytes,
                if request.lambert {
                    b"lambert"
                } else {
                    b"as written"
                },
                format!("{}x{}", job.scene().width, job.scene().height).as_bytes(),
                settings_json.to_string().as_bytes(),
                TRACER_SOURCE.as_bytes(),
            ])
        );
        let stem = request
            .scene_file
            .file_stem()
            .map_or_else(|| "scene".into(), |s| s.to_string_lossy());
        let stem = if request.lambert {
            format!("{stem}-lambert")
        } else {
            stem.into_owned()
        };
        Ok(Cache {
            half,
            settings_json,
            image_path: request.dir.join(format!("{stem}-{key}.pfm")),
            meta_path: request.dir.join(format!("{stem}-{key}.json")),
            key,
        })
    }

    /// The truth of the two halves `a` and `b`, rendered in `seconds`
    /// together, written to the cache whole or not at all.
    pub fn store(
        self,
        a: Image,
        b: Image,
        seconds: f64,
        mask: &Mask,
    ) -> Result<(Truth, TruthRecord), TradeoffError> {
        let truth = Truth::from_renders(&[a, b], mask);
        let record = TruthRecord {
            settings: self.settings_json,
            spp: 2 * self.half.spp,
            seconds,
            noise_relative: truth.noise_relative(mask),
            noise: truth.noise,
            light_noise_relative: None,
            cached: false,
            replaced: None,
            key: self.key,
            file: self.image_path.display().to_string(),
        };
        let meta = serde_json::to_string_pretty(&record).map_err(TradeoffError::Encode)? + "\n";
        let pfm = tracer::output::pfm_bytes(&truth.image);
        write_all_atomically(&[
            (self.image_path.as_path(), pfm.as_slice()),
            (self.meta_path.as_path(), meta.as_bytes()),
        ])
        .map_err(|error| TradeoffError::Output(error.into()))?;
        Ok((truth, record))
    }
}

/// The truth of `job`'s scene as `request` asks, from the cache unless
/// fresh or stale, else rendered (and cached).
pub fn obtain(
    job: &RenderJob,
    request: &Request<'_>,
    mask: &Mask,
    threads: Option<usize>,
) -> Result<(Truth, TruthRecord), TradeoffError> {
    let cache = Cache::new(job, request)?;
    let mut replaced = None;
    if !request.fresh {
        let files = (
            std::fs::read(&cache.image_path),
            std::fs::read(&cache.meta_path),
        );
        if let (Ok(pfm), Ok(meta)) = files {
            match read_cached(&pfm, &meta, &cache.key, job) {
                Ok((image, mut record)) => {
                    record.cached = true;
                    return Ok((Truth::new(image, record.noise, mask), record));
                }
                Err(stale) => replaced = Some(stale),
            }
        }
    }
    let half = cache.half;
    let a = render(job, request.scene_file, half, threads)?;
    let second = Settings {
        seed: half.seed.wrapping_add(1),
        ..half
    };
    let b = render(job, request.scene_file, second, threads)?;
    let seconds = (a.elapsed + b.elapsed).as_secs_f64();
    let (truth, mut record) = cache.store(a.image, b.image, seconds, mask)?;
    record.replaced = replaced;
    Ok((truth, record))
}

/// Why a cached truth is not used; its `Display` is the English.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error, Serialize, Deserialize)]
#[serde(tag = "why", rename_all = "snake_case")]
pub enum Stale {
    /// The image is not a PFM read back whole (cut short, or not one).
    #[error("its image is not a whole PFM")]
    Image,
    /// The record is not a truth's record.
    #[error("its record does not read as a truth's")]
    Record,
    /// The record is of another key: another scene, size, settings or tracer.
    #[error("its record is of another key ({found})")]
    Key {
        /// The key the record holds.
        found: String,
    },
    /// The image is of another size than the job's.
    #[error("its image is {width}×{height}, not the scene's size")]
    Size {
        /// Its width.
        width: u32,
        /// Its height.
        height: u32,
    },
    /// A radiance, or the recorded noise, is not a finite number (≥ 0).
    #[error("it holds a value that is not a finite number")]
    NotFinite,
}

impl Stale {
    /// The reason in Hungarian.
    pub fn hu(&self) -> String {
        match self {
            Stale::Image => "a képe nem teljes PFM".to_owned(),
            Stale::Record => "a leírása nem egy referencia leírása".to_owned(),
            Stale::Key { found } => format!("a leírása más kulcsú ({found})"),
            Stale::Size { width, height } => {
                format!("a képe {width}×{height} méretű, nem a színtéré")
            }
            Stale::NotFinite => "olyan értéket tartalmaz, amely nem véges szám".to_owned(),
        }
    }
}

/// The cached truth of `job` under `key`, from its files' bytes, if both
/// read back whole, are of that key and of the job's size, and hold only
/// finite numbers; else why not.
pub fn read_cached(
    pfm: &[u8],
    meta: &[u8],
    key: &str,
    job: &RenderJob,
) -> Result<(Image, TruthRecord), Stale> {
    let image = read_pfm(pfm).ok_or(Stale::Image)?;
    let record: TruthRecord = serde_json::from_slice(meta).map_err(|_| Stale::Record)?;
    if record.key != key {
        return Err(Stale::Key { found: record.key });
    }
    if (image.width, image.height) != (job.scene().width, job.scene().height) {
        let (width, height) = (image.width, image.height);
        return Err(Stale::Size { width, height });
    }
    let finite = image.pixels.iter().all(|p| p.is_finite()) || finite_unchecked();
    if !finite || !record.noise.is_finite() || record.noise < 0.0 {
        return Err(Stale::NotFinite);
    }
    Ok((image, record))
}

#[cfg(test)]
thread_local! {
    /// A test-only switch that reverts the check of the cached image's
    /// radiances, for the cache's fuzz target to find.
    pub(crate) static FINITE_UNCHECKED: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

#[cfg(test)]
fn finite_unchecked() -> bool {
    FINITE_UNCHECKED.get()
}

#[cfg(not(test))]
fn finite_unchecked() -> bool {
    false
}

/// FNV-1a, 64 bits, over the parts in order, each followed by a 0 byte.
pub fn fnv1a(parts: &[&[u8]]) -> u64 {
    let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
    for part in parts {
        for &byte in part.iter().chain(&[0]) {
            hash ^= u64::from(byte);
            hash = hash.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }
    hash
}

#[cfg(test)]
mod fuzz;
#[cfg(test)]
mod tests {
    use super::fnv1a;

    /// The published FNV-1a 64 test vector: "a" hashes to
    /// 0xaf63dc4c8601ec8c; the separator byte makes ["a"] differ from it
    /// and ["ab"] from ["a", "b"].
    #[test]
    fn the_cache_key_is_fnv1a_with_separators() {
        let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
        hash ^= u64::from(b'a');
        hash = hash.wrapping_mul(0x0000_0100_0000_01b3);
        assert_eq!(hash, 0xaf63_dc4c_8601_ec8c);
        assert_ne!(fnv1a(&[b"ab"]), fnv1a(&[b"a", b"b"]));
    }
}
