//! `optics render`: a scene file to a PNG for people and a PFM for
//! comparison, with a one-line summary of what it cost.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};

use anyhow::Context;
use serde_json::json;
use tracer::integrator::Settings;
use tracer::scene::{FresnelModel, IntegratorKind, MAX_DEPTH, MAX_IMAGE_SIDE, MAX_SPP};
use tracer::{needs, output, render, scene};

use crate::lang::say;
use crate::Ui;

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:
  optics render validation/scenes/kaleidoscope.json -o kaleidoscope.png
  optics render validation/scenes/gold_spheres.json -o gold.png --integrator course
  optics --json render scene.json -o out.png --integrator path --spp 64 --seed 7 --threads 2

Writes the PNG (sRGB, radiance clamped to [0, 1]: see docs/scene-schema.md)
and, beside it, the linear radiance as a PFM with the same name.")]
pub struct RenderArgs {
    /// The scene file (JSON, see docs/scene-schema.md).
    pub scene: PathBuf,
    /// The PNG to write; the PFM goes beside it with the extension .pfm.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Light transport: local, whitted, path, or course (the course's shader).
    #[arg(long, value_enum)]
    pub integrator: Option<Integrator>,
    /// Samples per pixel (the path tracer's; the others are deterministic).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=MAX_SPP as i64))]
    pub spp: Option<u32>,
    /// Bounces allowed after the primary hit.
    #[arg(long, value_parser = clap::value_parser!(u32).range(0..=MAX_DEPTH as i64))]
    pub max_depth: Option<u32>,
    /// Fresnel law of mirrors and glass.
    #[arg(long, value_enum)]
    pub fresnel: Option<Fresnel>,
    /// Worker threads (default: all cores). The image does not depend on it.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    pub threads: Option<u32>,
    /// Seed of the path tracer's random numbers.
    #[arg(long)]
    pub seed: Option<u64>,
    /// Image width in pixels, overriding the scene's (the camera keeps its view).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=MAX_IMAGE_SIDE as i64))]
    pub width: Option<u32>,
    /// Image height in pixels, overriding the scene's.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=MAX_IMAGE_SIDE as i64))]
    pub height: Option<u32>,
}

#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum Integrator {
    Local,
    Whitted,
    Path,
    Course,
}

impl From<Integrator> for IntegratorKind {
    fn from(integrator: Integrator) -> Self {
        match integrator {
            Integrator::Local => IntegratorKind::Local,
            Integrator::Whitted => IntegratorKind::Whitted,
            Integrator::Path => IntegratorKind::Path,
            Integrator::Course => IntegratorKind::Course,
        }
    }
}

#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum Fresnel {
    Exact,
    Schlick,
    /// The course shader's reversed form, for measuring that erratum alone.
    Course,
}

/// Loads the scene and settles the settings: flags over the scene's own.
pub(crate) fn prepare(
    path: &Path,
    width: Option<u32>,
    height: Option<u32>,
) -> anyhow::Result<(scene::Scene, Settings)> {
    let mut scene = scene::load(path).with_context(|| format!("scene {}", path.display()))?;
    if width.is_some() || height.is_some() {
        let (w, h) = (width.unwrap_or(scene.width), height.unwrap_or(scene.height));
        if w as u64 * h as u64 > scene::MAX_PIXELS {
            anyhow::bail!(
                "--width × --height: {w} × {h} pixels is more than the {} accepted",
                scene::MAX_PIXELS
            );
        }
        scene = scene.resized(w, h);
    }
    let settings = Settings::from_scene(&scene);
    Ok((scene, settings))
}

pub fn run(args: &RenderArgs, ui: &Ui) -> anyhow::Result<()> {
    let (scene, mut settings) = prepare(&args.scene, args.width, args.height)?;
    if let Some(i) = args.integrator {
        settings.integrator = i.into();
    }
    if let Some(f) = args.fresnel {
        settings.fresnel = match f {
            Fresnel::Exact => FresnelModel::Exact,
            Fresnel::Schlick => FresnelModel::Schlick,
            Fresnel::Course => FresnelModel::Course,
        };
    }
    settings.spp = args.spp.unwrap_or(settings.spp);
    settings.max_depth = args.max_depth.unwrap_or(settings.max_depth);
    settings.seed = args.seed.unwrap_or(settings.seed);
    needs::check_integrator(&scene, &settings)
        .with_context(|| format!("scene {}", args.scene.display()))?;
    let needs = needs::analyse(&scene, &settings);
    let machinery = needs.machinery(&settings);

    let png = args.output.clone();
    let pfm = png.with_extension("pfm");
    if pfm == png {
        anyhow::bail!(
            "--output {}: give the PNG's name (the PFM is written beside it)",
            png.display()
        );
    }

    // Refuse an unwritable destination before spending the render on it.
    let dir = match png.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    if !dir.is_dir() {
        anyhow::bail!(
            "--output {}: the directory {} does not exist",
            png.display(),
            dir.display()
        );
    }

    let bar = std::io::stderr().is_terminal().then(|| {
        let bar = indicatif::ProgressBar::new(scene.height as u64);
        bar.set_style(
            indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} rows, {eta} left")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        bar
    });
    let progress = |rows: usize| {
        if let Some(bar) = &bar {
            bar.set_position(rows as u64);
        }
    };
    let rendered = render::render(
        &scene,
        &settings,
        &machinery,
        args.threads.map(|t| t as usize),
        &progress,
    )?;
    if let Some(bar) = &bar {
        bar.finish_and_clear();
    }
    output::write_png(&png, &rendered.image)?;
    output::write_pfm(&pfm, &rendered.image)?;

    let seconds = rendered.elapsed.as_secs_f64();
    let rays = rendered.rays.total();
    let rate = rays as f64 / seconds.max(1e-9);
    let lang = ui.lang;
    let summary = say!(
        lang,
        "{}×{} {} in {:.3} s: {} rays, {:.2} M rays/s → {}, {}",
        "{}×{} {} {:.3} s alatt: {} sugár, {:.2} M sugár/s → {}, {}",
        scene.width,
        scene.height,
        settings.integrator,
        seconds,
        rays,
        rate / 1e6,
        png.display(),
        pfm.display()
    );
    if ui.json {
        let record = json!({
            "command": "render",
            "inputs": {
                "scene": args.scene.display().to_string(),
                "width": scene.width,
                "height": scene.height,
                "settings": settings,
                "threads": args.threads,
            },
            "answer": {
                "png": png.display().to_string(),
                "pfm": pfm.display().to_string(),
                "seconds": seconds,
                "rays": rendered.rays,
                "rays_total": rays,
                "rays_per_second": rate,
                "samples_per_pixel_taken": machinery.spp,
                "shadow_rays": machinery.shadow_rays,
            },
            "unit": "rays/s",
            "steps": steps(&needs, &machinery, &settings, lang),
        });
        println!("{record}");
    } else {
        println!("{summary}");
    }
    Ok(())
}

/// What the renderer switched off and why, one line each.
pub(crate) fn steps(
    needs: &needs::Needs,
    machinery: &tracer::integrator::Machinery,
    settings: &Settings,
    lang: crate::Lang,
) -> Vec<String> {
    let mut steps = Vec::new();
    if !machinery.shadow_rays {
        steps.push(if needs.lights.iter().any(|l| l.used) {
            say!(
                lang,
                "shadow rays skipped: no object can block a light",
                "árnyéksugarak kihagyva: semmi sem takarhatja el a fényt"
            )
        } else {
            say!(
                lang,
                "shadow rays skipped: no light is used",
                "árnyéksugarak kihagyva: nincs használt fény"
            )
        });
    }
    for light in needs.lights.iter().filter(|l| !l.used) {
        steps.push(say!(
            lang,
            "light {} ({}) skipped: {}",
            "{}. fény ({}) kihagyva: {}",
            light.index,
            light.kind,
            light.reason.unwrap_or_default()
        ));
    }
    if machinery.spp < settings.spp {
        steps.push(if settings.integrator == IntegratorKind::Path {
            say!(
                lang,
                "{} samples per pixel reduced to 1: every path is deterministic",
                "{} minta pixelenként 1-re csökkentve: minden út determinisztikus",
                settings.spp
            )
        } else {
            say!(
                lang,
                "{} samples per pixel reduced to 1: the {} integrator is deterministic",
                "{} minta pixelenként 1-re csökkentve: a(z) {} integrátor determinisztikus",
                settings.spp,
                settings.integrator
            )
        });
    }
    steps
}
