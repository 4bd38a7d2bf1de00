//! The tracer's renders against Mitsuba 3's: each physically based course
//! scene, by a Whitted integrator written on Mitsuba's own primitives and by
//! Mitsuba's `path` integrator (`python-checks/mitsuba_render.py`, reference
//! `mitsuba_renders.json`), against the tracer's `whitted` and `path`.
//!
//! - **Whitted** renders are deterministic: compared per pixel, away from
//!   edges. A pixel is an edge when a neighbour's Whitted path meets another
//!   object or another shadow (the reference's mask): there a float32
//!   difference in one intersection moves a whole object.
//! - **Path** renders are Monte Carlo: per pixel and channel, Welch's t-test
//!   of the tracer's mean over `n₁` samples against Mitsuba's over `n₂`,
//!   with the per-sample variances of both; the render fails when any p-value
//!   falls below `α / m` for `m` tests (Bonferroni; Holm's step-down rejects
//!   something exactly when this does) and the means differ by more than the
//!   Whitted tolerance, which no number of samples removes. Pixels where
//!   neither side varies are compared as the Whitted ones are. A rejection
//!   that the same test no longer makes once the difference is reduced by
//!   what Mitsuba's own ray offsets move that pixel (measured by the
//!   generator) is a finding about the reference, not a failure.
//!
//! The renderer is a parameter ([`Renderer`]), so a deliberately broken render
//! can be shown to be caught. Radiance is in W/(sr·m²) per channel.

use serde::Deserialize;
use tracer::job::RenderJob;
use tracer::render::Image;
use tracer::scene::{IntegratorKind, Scene, Settings};

use crate::check::Check;
use crate::reference::ReferenceError;
use crate::statistics::{self, Sample};

/// The reference file.
pub const FILE: &str = "mitsuba_renders.json";
/// Its schema.
pub const SCHEMA: &str = "mitsuba-renders/1";

/// Family-wise false-alarm rate of a path comparison: one correct render in
/// a hundred may fail by chance.
pub const ALPHA: f64 = 0.01;

/// Absolute part of the per-pixel tolerance of deterministic pixels,
/// W/(sr·m²): a dark pixel's few float32 roundings of order-one terms.
pub const TOLERANCE_ABSOLUTE: f64 = 1e-5;

/// Relative part of the per-pixel tolerance of deterministic pixels. Both
/// sides compute in float32 with different intersection routines and start
/// secondary rays at different offsets (ours: twice the hit's error bound;
/// the reference: 4 ulps of the hit's largest coordinate), so hit points
/// differ by micrometres after a chain of mirrors. The course's Blinn-Phong
/// lobe `cos^s δ` with `s = 100` multiplies a cosine's relative error by `s`:
/// on the kaleidoscope's five-mirror chains that is up to 2 × 10⁻⁴ (ours is
/// that far from an exact float64 trace there; the reference 3 × 10⁻⁶).
/// 10⁻³ covers it with a margin; a wrong law, light unit or camera is
/// percent-level, ten times beyond.
pub const TOLERANCE_RELATIVE: f64 = 1e-3;

/// `mitsuba_renders.json`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MitsubaRenders {
    /// [`SCHEMA`].
    pub schema: String,
    /// The script that wrote it.
    pub generator: String,
    /// The command that regenerates it.
    pub regenerate: String,
    /// What it holds.
    pub description: String,
    /// Mitsuba's version and variant.
    pub mitsuba: Tool,
    /// Scenes not compared, and why.
    pub excluded: std::collections::BTreeMap<String, String>,
    /// The scenes rendered.
    pub scenes: Vec<SceneRenders>,
}

/// A tool's version.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Tool {
    /// Version.
    pub version: String,
    /// Mitsuba's variant.
    pub variant: String,
}

/// One scene's Mitsuba renders.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneRenders {
    /// The scene's name (its file stem).
    pub name: String,
    /// Its file, relative to the repository root.
    pub scene_file: String,
    /// The scene file's text as Mitsuba rendered it.
    pub scene_text: String,
    /// Image width, pixels.
    pub width: u32,
    /// Image height, pixels.
    pub height: u32,
    /// The Whitted render.
    pub whitted: WhittedRender,
    /// Edge mask, one byte per pixel (1: masked), base64.
    pub edges_u8: String,
    /// Mitsuba's path tracer, when compared.
    #[serde(default)]
    pub path: Option<PathRender>,
    /// Why the path tracer is not compared.
    #[serde(default)]
    pub path_skipped: Option<String>,
}

/// A Whitted render.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WhittedRender {
    /// Bounces after the primary hit.
    pub max_depth: u32,
    /// The throughput below which a branch is cut.
    pub throughput_cutoff: f64,
    /// Radiance, float32 little-endian RGB, rows top to bottom, base64.
    pub radiance_f32le: String,
}

/// Mitsuba's path tracer at the pixel centres.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PathRender {
    /// Bounces after the primary hit, the suite's count.
    pub max_depth: u32,
    /// The same as Mitsuba counts it (path segments): `max_depth + 2`.
    pub mitsuba_max_depth: u32,
    /// Samples per pixel.
    pub samples: u32,
    /// Per-pixel mean, float32 RGB, base64.
    pub mean_f32le: String,
    /// Per-pixel unbiased variance of one sample, float32 RGB, base64.
    pub variance_f32le: String,
    /// How far Mitsuba's own ray offsets move each pixel: its Whitted render
    /// with `si.spawn_ray` against the one the Whitted check uses, float32
    /// RGB, base64.
    pub offset_sensitivity_f32le: String,
}

impl MitsubaRenders {
    /// Reads [`FILE`] from `dir`.
    pub fn load(dir: &std::path::Path) -> Result<Self, ReferenceError> {
        crate::reference::load(dir, FILE, SCHEMA)
    }
}

/// A scene's reference decoded: images as `f64` per channel.
#[derive(Clone, Debug)]
pub struct Decoded {
    /// The scene as Mitsuba saw it, at the reference's size.
    pub scene: Scene,
    /// Mitsuba's Whitted radiance, `3 · width · height`.
    pub whitted: Vec<f64>,
    /// Masked pixels, `width · height`.
    pub edges: Vec<bool>,
    /// Mitsuba's path mean and variance, and how far its ray offsets move
    /// each pixel, `3 · width · height` each.
    pub path: Option<PathImages>,
}

/// Mitsuba's path render, decoded.
#[derive(Clone, Debug)]
pub struct PathImages {
    /// Per-pixel mean.
    pub mean: Vec<f64>,
    /// Per-pixel variance of one sample.
    pub variance: Vec<f64>,
    /// Per-pixel sensitivity to Mitsuba's ray offsets.
    pub offset_sensitivity: Vec<f64>,
}

/// Decodes one scene of the reference; errors name the field.
pub fn decode(
    file: &std::path::Path,
    index: usize,
    s: &SceneRenders,
) -> Result<Decoded, ReferenceError> {
    let malformed = |field: &str, message: String| ReferenceError::Malformed {
        path: file.to_owned(),
        field: format!("scenes[{index}].{field}"),
        message,
    };
    // The reference images are small (64 × 48); anything beyond the tracer's
    // own cap is a malformed file, refused before any allocation.
    let side = 1..=tracer::scene::MAX_IMAGE_SIDE;
    if !side.contains(&s.width) || !side.contains(&s.height) {
        return Err(malformed(
            "width",
            format!(
                "image {} × {} outside 1..={} per side",
                s.width,
                s.height,
                tracer::scene::MAX_IMAGE_SIDE
            ),
        ));
    }
    if let Some(p) = &s.path {
        if p.samples < 2 {
            return Err(malformed(
                "path.samples",
                format!("a variance needs at least 2 samples, got {}", p.samples),
            ));
        }
    }
    let scene = tracer::scene::parse(&s.scene_text)
        .map_err(|e| malformed("scene_text", e.to_string()))?
        .resized(s.width, s.height);
    let pixels = s.width as usize * s.height as usize;
    let floats = |field: &str, text: &str| {
        let bytes = base64_decode(text).map_err(|m| malformed(field, m))?;
        if bytes.len() != 12 * pixels {
            return Err(malformed(
                field,
                format!(
                    "expected {} float32 RGB pixels ({} bytes), got {} bytes",
                    pixels,
                    12 * pixels,
                    bytes.len()
                ),
            ));
        }
        Ok(bytes
            .chunks_exact(4)
            .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64)
            .collect::<Vec<f64>>())
    };
    let whitted = floats("whitted.radiance_f32le", &s.whitted.radiance_f32le)?;
    let edges = base64_decode(&s.edges_u8).map_err(|m| malformed("edges_u8", m))?;
    if edges.len() != pixels {
        return Err(malformed(
            "edges_u8",
            format!("expected {pixels} bytes, got {}", edges.len()),
        ));
    }
    let path = match &s.path {
        Some(p) => Some(PathImages {
            mean: floats("path.mean_f32le", &p.mean_f32le)?,
            variance: floats("path.variance_f32le", &p.variance_f32le)?,
            offset_sensitivity: floats(
                "path.offset_sensitivity_f32le",
                &p.offset_sensitivity_f32le,
            )?,
        }),
        None => None,
    };
    Ok(Decoded {
        scene,
        whitted,
        edges: edges.iter().map(|&b| b != 0).collect(),
        path,
    })
}

/// Standard base64 (RFC 4648, with padding).
fn base64_decode(text: &str) -> Result<Vec<u8>, String> {
    let value = |c: u8| -> Result<u32, String> {
        Ok(match c {
            b'A'..=b'Z' => c - b'A',
            b'a'..=b'z' => c - b'a' + 26,
            b'0'..=b'9' => c - b'0' + 52,
            b'+' => 62,
            b'/' => 63,
            _ => return Err(format!("not base64: byte {c:#04x}")),
        } as u32)
    };
    let bytes = text.as_bytes();
    if bytes.len() % 4 != 0 {
        return Err(format!(
            "base64 length {} is not a multiple of 4",
            bytes.len()
        ));
    }
    let mut out = Vec::with_capacity(bytes.len() / 4 * 3);
    for chunk in bytes.chunks_exact(4) {
        let pad = chunk.iter().rev().take_while(|&&c| c == b'=').count();
        let mut n = 0u32;
        for &c in &chunk[..4 - pad] {
            n = n << 6 | value(c)?;
        }
        n <<= 6 * pad as u32;
        out.extend_from_slice(&n.to_be_bytes()[1..4 - pad]);
    }
    Ok(out)
}

/// Renders a scene with settings; the tracer, or a deliberately broken one.
pub type Renderer = fn(&Scene, &Settings) -> Result<Image, String>;

/// The tracer as `optics render` runs it: the scene's needs decide the
/// machinery, all cores.
pub fn tracer_render(scene: &Scene, settings: &Settings) -> Result<Image, String> {
    RenderJob::with_settings(scene.clone(), *settings)
        .map_err(|e| e.to_string())?
        .render(None, &|_| {})
        .map(|r| r.image)
        .map_err(|e| e.to_string())
}

/// A triptych for the report: ours | Mitsuba | the difference in units of
/// the tolerance, each panel enlarged.
#[derive(Clone, Debug)]
pub struct RenderFigure {
    /// File name under `figures/`.
    pub file: String,
    /// Linear radiance to be written as sRGB PNG.
    pub image: Image,
}

/// Outcome of one scene's comparison.
pub struct Compared {
    /// The check.
    pub check: Check,
    /// Its figure.
    pub figure: RenderFigure,
}

fn tolerance(mitsuba: f64) -> f64 {
    TOLERANCE_ABSOLUTE + TOLERANCE_RELATIVE * mitsuba.abs()
}

fn pixel_label(width: u32, i: usize) -> String {
    const CHANNEL: [&str; 3] = ["R", "G", "B"];
    let pixel = i / 3;
    format!(
        "pixel ({}, {}) {}",
        pixel as u32 % width,
        pixel as u32 / width,
        CHANNEL[i % 3]
    )
}

/// Whitted against Whitted, per pixel away from edges.
pub fn compare_whitted(name: &str, reference: &Decoded, ours: &Image) -> Compared {
    let scene = &reference.scene;
    let mut check = Check::new(
        &format!("renders.mitsuba.{name}.whitted"),
        &format!("{name}: the tracer's whitted against a Whitted integrator on Mitsuba's primitives, per pixel"),
        "Mitsuba 3 (scalar_rgb, float32): ray_intersect, fresnel_conductor, reflect (mitsuba_renders.json)",
        &format!(
            "|ours − Mitsuba| ≤ {TOLERANCE_ABSOLUTE:e} + {TOLERANCE_RELATIVE:e} · |Mitsuba| per channel, \
             edge pixels masked: both float32, different intersections and ray offsets; the s = 100 lobe \
             and mirror chains amplify them"
        ),
    );
    let ours = flatten(ours);
    if ours.len() != reference.whitted.len() {
        check.fail(format!(
            "the render has {} values, the reference {}",
            ours.len(),
            reference.whitted.len()
        ));
    }
    let mut heat = vec![f64::NAN; ours.len()];
    let (mut sum, mut compared) = (0.0, 0usize);
    let masked = reference.edges.iter().filter(|&&e| e).count();
    for (i, (&a, &b)) in ours.iter().zip(&reference.whitted).enumerate() {
        if reference.edges[i / 3] {
            continue;
        }
        let d = (a - b).abs();
        heat[i] = d / tolerance(b);
        sum += d;
        compared += 1;
        let at = pixel_label(scene.width, i);
        check.measure("|ours − Mitsuba|, W/(sr m²)", d, &at);
        check.measure("|ours − Mitsuba| / tolerance", heat[i], &at);
        if !(d <= tolerance(b)) {
            check.fail(format!(
                "{at}: ours {a:.7}, Mitsuba {b:.7}, difference {d:.3e}"
            ));
        }
    }
    check.cases = compared / 3;
    check.measure("masked edge pixels", masked as f64, "");
    check.measure(
        "mean |ours − Mitsuba|, W/(sr m²)",
        sum / compared.max(1) as f64,
        "",
    );
    summarise_failures(&mut check);
    let figure = triptych(name, "whitted", scene, &ours, &reference.whitted, &heat);
    Compared { check, figure }
}

/// The tracer's path samples: per-pixel mean and unbiased variance of one
/// sample, from `samples` renders at 1 sample per pixel with seeds `0..samples`.
pub fn path_statistics(
    render: Renderer,
    scene: &Scene,
    max_depth: u32,
    samples: u32,
) -> Result<(Vec<f64>, Vec<f64>), String> {
    let mut settings = scene.settings;
    settings.integrator = IntegratorKind::Path;
    settings.max_depth = max_depth;
    settings.spp = 1;
    let n = (3 * scene.width * scene.height) as usize;
    // Welford's running mean and sum of squared deviations: exact zero
    // variance where every sample is the same, no cancellation elsewhere.
    let (mut mean, mut squares) = (vec![0.0; n], vec![0.0; n]);
    for seed in 0..samples as u64 {
        settings.seed = seed;
        let image = flatten(&render(scene, &settings)?);
        let count = (seed + 1) as f64;
        for (i, v) in image.into_iter().enumerate() {
            let delta = v - mean[i];
            mean[i] += delta / count;
            squares[i] += delta * (v - mean[i]);
        }
    }
    let variance = squares.iter().map(|q| q / (samples as f64 - 1.0)).collect();
    Ok((mean, variance))
}

/// Path against path: Welch's t per pixel and channel, Bonferroni-corrected.
pub fn compare_path(
    name: &str,
    reference: &Decoded,
    mitsuba_samples: u32,
    ours: (&[f64], &[f64]),
    our_samples: u32,
) -> Option<Compared> {
    let PathImages {
        mean: m_mean,
        variance: m_var,
        offset_sensitivity,
    } = reference.path.as_ref()?;
    let scene = &reference.scene;
    let mut check = Check::new(
        &format!("renders.mitsuba.{name}.path"),
        &format!("{name}: the tracer's path against Mitsuba's path integrator, per-pixel Welch t-test"),
        "Mitsuba 3 path integrator (scalar_rgb), pixel centres (mitsuba_renders.json)",
        &format!(
            "a pixel-channel fails when p < α/m, α = {ALPHA} over the m t-tests (Bonferroni: one correct \
             render in {:.0} fails by chance), and its means differ by more than the Whitted tolerance \
             {TOLERANCE_ABSOLUTE:e} + {TOLERANCE_RELATIVE:e} · |Mitsuba| (float32 differences, which no \
             number of samples removes); edges masked",
            1.0 / ALPHA
        ),
    );
    let mut tests = Vec::new();
    let mut deterministic = Vec::new();
    let (mut sum, mut compared) = (0.0, 0usize);
    for i in 0..m_mean.len() {
        if reference.edges[i / 3] {
            continue;
        }
        compared += 1;
        let (a, b) = (ours.0[i], m_mean[i]);
        sum += (a - b).abs();
        check.measure(
            "|mean ours − mean Mitsuba|, W/(sr m²)",
            (a - b).abs(),
            &pixel_label(scene.width, i),
        );
        let side = |mean, variance, count: u32| Sample {
            mean,
            variance,
            count: count as f64,
        };
        match statistics::welch(
            side(a, ours.1[i], our_samples),
            side(b, m_var[i], mitsuba_samples),
        ) {
            Some(w) => tests.push((i, w)),
            None => deterministic.push(i),
        }
    }
    let m = tests.len().max(1) as f64;
    let threshold = ALPHA / m;
    let mut heat = vec![f64::NAN; m_mean.len()];
    let (mut rejected, mut offset_findings) = (0, 0);
    let mut offset_example = None;
    for &(i, w) in &tests {
        // In units of the threshold's −log: 1 at the threshold.
        heat[i] = w.p.max(1e-300).ln() / threshold.ln();
        check.measure("|t|", w.t.abs(), &pixel_label(scene.width, i));
        let difference = (ours.0[i] - m_mean[i]).abs();
        if w.p >= threshold || difference <= tolerance(m_mean[i]) {
            continue;
        }
        // The same test of |difference| ≤ what Mitsuba's own ray offsets
        // move this pixel by: passing it, the disagreement is the reference's.
        let allowance = tolerance(m_mean[i]) + offset_sensitivity[i];
        let standard_error = difference / w.t.abs();
        let shifted = (difference - allowance).max(0.0) / standard_error;
        let p_shifted = statistics::student_t_two_sided(shifted.abs(), w.dof);
        let message = format!(
            "{}: ours {:.6} (n = {our_samples}), Mitsuba {:.6} (n = {mitsuba_samples}), t = {:.2}, p = {:.2e} < {threshold:.2e}",
            pixel_label(scene.width, i),
            ours.0[i],
            m_mean[i],
            w.t,
            w.p
        );
        if p_shifted >= threshold {
            offset_findings += 1;
            if offset_example.is_none() {
                offset_example = Some(format!(
                    "{message}, within the {:.2e} that Mitsuba's ray offsets move this pixel",
                    offset_sensitivity[i]
                ));
            }
        } else {
            rejected += 1;
            check.fail(message);
        }
    }
    for &i in &deterministic {
        let d = (ours.0[i] - m_mean[i]).abs();
        heat[i] = d / tolerance(m_mean[i]);
        if !(d <= tolerance(m_mean[i])) {
            check.fail(format!(
                "{}: neither side varies; ours {:.7}, Mitsuba {:.7}",
                pixel_label(scene.width, i),
                ours.0[i],
                m_mean[i]
            ));
        }
    }
    let smallest = tests.iter().map(|(_, w)| w.p).fold(1.0, f64::min);
    let p_at = tests
        .iter()
        .find(|(_, w)| w.p == smallest)
        .map_or(String::new(), |(i, _)| pixel_label(scene.width, *i));
    check.cases = compared / 3;
    // Smaller p is worse: recorded as −log10 p beside the threshold's.
    // A p-value that underflows to 0 is shown as 10⁻³⁰⁰.
    check.measure(
        "−log10 smallest p",
        0.0 - smallest.max(1e-300).log10(),
        &p_at,
    );
    check.measure("−log10 (α/m), the threshold", -threshold.log10(), "");
    check.measure("pixel-channel t-tests m", tests.len() as f64, "");
    check.measure("tests rejected", rejected as f64, "");
    check.measure(
        "rejected within Mitsuba's ray-offset sensitivity (findings)",
        offset_findings as f64,
        "",
    );
    check.measure(
        "pixel-channels where neither side varies",
        deterministic.len() as f64,
        "",
    );
    check.measure(
        "masked edge pixels",
        reference.edges.iter().filter(|&&e| e).count() as f64,
        "",
    );
    check.measure(
        "mean |mean ours − mean Mitsuba|, W/(sr m²)",
        sum / compared.max(1) as f64,
        "",
    );
    if let Some(example) = offset_example {
        check.find(format!(
            "{offset_findings} pixel-channels differ significantly from Mitsuba's path integrator, each by \
             less than Mitsuba's own ray offsets (RayEpsilon ≈ 8.9e-5 relative) move it; e.g. {example}"
        ));
    }
    summarise_failures(&mut check);
    let figure = triptych(name, "path", scene, ours.0, m_mean, &heat);
    Some(Compared { check, figure })
}

/// Keeps the first failures and counts the rest.
fn summarise_failures(check: &mut Check) {
    const SHOWN: usize = 10;
    if check.failures.len() > SHOWN {
        let rest = check.failures.len() - SHOWN;
        check.failures.truncate(SHOWN);
        check.failures.push(format!("… and {rest} more"));
    }
}

fn flatten(image: &Image) -> Vec<f64> {
    image
        .pixels
        .iter()
        .flat_map(|p| p.to_array())
        .map(f64::from)
        .collect()
}

/// Ours | Mitsuba | heat map, each panel enlarged 4×. The heat map shows a
/// pixel's largest channel in units of its tolerance: black (0) through red
/// to yellow (1, at tolerance), magenta beyond; masked pixels dark blue.
fn triptych(
    name: &str,
    integrator: &str,
    scene: &Scene,
    ours: &[f64],
    mitsuba: &[f64],
    heat: &[f64],
) -> RenderFigure {
    const SCALE: u32 = 4;
    const GAP: u32 = 4;
    let (w, h) = (scene.width, scene.height);
    let width = 3 * w * SCALE + 2 * GAP;
    let height = h * SCALE;
    let mut pixels = vec![glam::Vec3::ONE; (width * height) as usize];
    let rgb = |v: &[f64], p: usize| {
        glam::Vec3::new(v[3 * p] as f32, v[3 * p + 1] as f32, v[3 * p + 2] as f32)
    };
    for y in 0..height {
        for x in 0..3 * w * SCALE + 2 * GAP {
            let panel = x / (w * SCALE + GAP);
            let px = x % (w * SCALE + GAP);
            if px >= w * SCALE {
                continue;
            }
            let p = ((y / SCALE) * w + px / SCALE) as usize;
            pixels[(y * width + x) as usize] = match panel {
                0 => rgb(ours, p),
                1 => rgb(mitsuba, p),
                _ => {
                    let worst = heat[3 * p..3 * p + 3]
                        .iter()
                        .copied()
                        .fold(f64::NAN, f64::max);
                    if worst.is_nan() {
                        glam::Vec3::new(0.0, 0.0, 0.08)
                    } else if worst > 1.0 {
                        glam::Vec3::new(1.0, 0.0, 1.0)
                    } else {
                        let t = worst as f32;
                        glam::Vec3::new(t.sqrt(), t * t, 0.0)
                    }
                }
            };
        }
    }
    RenderFigure {
        file: format!("render_{name}_{integrator}.png"),
        image: Image {
            width,
            height,
            pixels,
        },
    }
}

/// The renders against Mitsuba, by a renderer under test.
pub struct RenderChecks {
    /// The renderer.
    pub render: Renderer,
}

impl RenderChecks {
    /// The tracer.
    pub fn tracer() -> Self {
        Self {
            render: tracer_render,
        }
    }

    /// Samples per pixel of the tracer's path renders: 256 with `--quick`
    /// (a few seconds), 1024 otherwise.
    pub fn samples(quick: bool) -> u32 {
        if quick {
            256
        } else {
            1024
        }
    }

    /// Every scene of `reference`, appended to `checks` and `figures`.
    pub fn run_all(
        &self,
        file: &std::path::Path,
        reference: &MitsubaRenders,
        quick: bool,
        checks: &mut Vec<Check>,
        figures: &mut Vec<RenderFigure>,
    ) -> Result<(), ReferenceError> {
        for (index, s) in reference.scenes.iter().enumerate() {
            let decoded = decode(file, index, s)?;
            let mut stale = None;
            let on_disk = crate::repo_root().join(&s.scene_file);
            if let Ok(text) = std::fs::read_to_string(&on_disk) {
                if text != s.scene_text {
                    stale = Some(format!(
                        "{} differs from the scene Mitsuba rendered: regenerate with `{}`",
                        s.scene_file, reference.regenerate
                    ));
                }
            }
            let mut settings = decoded.scene.settings;
            settings.integrator = IntegratorKind::Whitted;
            settings.max_depth = s.whitted.max_depth;
            settings.throughput_cutoff = s.whitted.throughput_cutoff as f32;
            let mut compared = match (self.render)(&decoded.scene, &settings) {
                Ok(ours) => compare_whitted(&s.name, &decoded, &ours),
                Err(e) => failed_render(&s.name, "whitted", e),
            };
            if let Some(stale) = &stale {
                compared.check.fail(stale.clone());
            }
            checks.push(compared.check);
            figures.push(compared.figure);
            if let Some(p) = &s.path {
                let samples = Self::samples(quick);
                let compared =
                    match path_statistics(self.render, &decoded.scene, p.max_depth, samples) {
                        Ok((mean, variance)) => {
                            compare_path(&s.name, &decoded, p.samples, (&mean, &variance), samples)
                        }
                        Err(e) => Some(failed_render(&s.name, "path", e)),
                    };
                if let Some(mut compared) = compared {
                    if let Some(stale) = &stale {
                        compared.check.fail(stale.clone());
                    }
                    checks.push(compared.check);
                    figures.push(compared.figure);
                }
            }
        }
        Ok(())
    }
}

fn failed_render(name: &str, integrator: &str, error: String) -> Compared {
    let mut check = Check::new(
        &format!("renders.mitsuba.{name}.{integrator}"),
        &format!("{name}: the tracer's {integrator} render"),
        "Mitsuba 3 (mitsuba_renders.json)",
        "the render succeeds",
    );
    check.cases = 1;
    check.fail(format!("the render failed: {error}"));
    Compared {
        check,
        figure: RenderFigure {
            file: format!("render_{name}_{integrator}.png"),
            image: Image {
                width: 1,
                height: 1,
                pixels: vec![glam::Vec3::ZERO],
            },
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_decodes_rfc4648_test_vectors() {
        // RFC 4648 §10.
        for (text, bytes) in [
            ("", ""),
            ("Zg==", "f"),
            ("Zm8=", "fo"),
            ("Zm9v", "foo"),
            ("Zm9vYg==", "foob"),
            ("Zm9vYmE=", "fooba"),
            ("Zm9vYmFy", "foobar"),
        ] {
            assert_eq!(base64_decode(text).unwrap(), bytes.as_bytes(), "{text}");
        }
        assert!(base64_decode("Zm9").is_err());
        assert!(base64_decode("Zm9*").is_err());
    }
}
