//! Rendering an image: rows in parallel (rayon), each pixel with its own
//! samples (`crate::sampler`), so the image is bit-identical for any number
//! of threads.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use glam::{DVec3, Vec3};
use rayon::prelude::*;

use crate::filter::sample_point;
use crate::integrator::{Primary, RayCounts, Tracer};
use crate::sampler::{Sample, Sampler};
use radiometry::Vector3;

/// A linear-radiance image, W/(sr·m²) per channel, rows top to bottom.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    /// Width, pixels.
    pub width: u32,
    /// Height, pixels.
    pub height: u32,
    /// `width × height` pixels.
    pub pixels: Vec<Vec3>,
}

impl Image {
    /// The first pixel, in row order, whose radiance is not finite: the
    /// last check before an image is written. The scene's numbers are
    /// bounded at validation (`scene::bound`); this catches what the bound
    /// cannot see, a path's gain.
    pub fn first_not_finite(&self) -> Option<(u32, u32)> {
        let i = self.pixels.iter().position(|p| !p.is_finite())?;
        let width = self.width as usize;
        Some(((i % width) as u32, (i / width) as u32))
    }

    /// The pixel at column `x`, row `y` (0 is the top row).
    pub fn get(&self, x: u32, y: u32) -> Vec3 {
        self.pixels[(y * self.width + x) as usize]
    }

    /// Mean over pixels of the largest channel difference, and the largest.
    pub fn difference(&self, other: &Image) -> (f64, f64) {
        let mut sum = 0.0;
        let mut max = 0.0_f64;
        for (a, b) in self.pixels.iter().zip(&other.pixels) {
            let d = (*a - *b).abs().max_element() as f64;
            sum += d;
            max = max.max(d);
        }
        (sum / self.pixels.len().max(1) as f64, max)
    }
}

/// What a render produced and what it cost.
#[derive(Clone, Debug)]
pub struct Rendered {
    /// The image.
    pub image: Image,
    /// Rays cast, by purpose.
    pub rays: RayCounts,
    /// Wall-clock time of the tracing.
    pub elapsed: Duration,
}

/// Renders with `tracer`, at its tier, on `threads` threads (`None`: all
/// cores). `progress` is called with 0 as the render starts, then with the
/// number of rows finished so far, from any thread.
/// [`RenderJob`](crate::job::RenderJob) is the way in.
pub(crate) fn render<V: Vector3>(
    tracer: &impl Primary<V>,
    threads: Option<usize>,
    progress: &(dyn Fn(usize) + Sync),
) -> Result<Rendered, rayon::ThreadPoolBuildError> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads.unwrap_or(0))
        .build()?;
    let rows_done = AtomicUsize::new(0);
    let start = Instant::now();
    let scene = tracer.tracer().scene;
    let (width, height) = (scene.width, scene.height);
    // Shown before the first row, which may be long in coming.
    progress(0);
    let rows: Vec<(Vec<Vec3>, RayCounts)> = pool.install(|| {
        (0..height)
            .into_par_iter()
            .map(|y| {
                let mut counts = RayCounts::default();
                let row = (0..width)
                    .map(|x| pixel(tracer, x, y, &mut counts))
                    .collect();
                progress(rows_done.fetch_add(1, Ordering::Relaxed) + 1);
                (row, counts)
            })
            .collect()
    });
    let elapsed = start.elapsed();
    let mut rays = RayCounts::default();
    let mut pixels = Vec::with_capacity((width * height) as usize);
    for (row, counts) in rows {
        pixels.extend(row);
        rays.add(&counts);
    }
    Ok(Rendered {
        image: Image {
            width,
            height,
            pixels,
        },
        rays,
        elapsed,
    })
}

/// How many of a pixel's camera rays are made together
/// ([`Camera::rays_in`](crate::camera::Camera::rays_in)).
const CAMERA_BLOCK: u32 = 8;

/// One pixel: the mean of its samples, each through the point of the pixel
/// the filter gives it (`crate::filter`), summed in `f64` so that the mean
/// of many samples keeps `f32` precision, and rounded once to the film's
/// `f32`. The samples' camera rays are made [`CAMERA_BLOCK`] at a time;
/// each sample keeps its own numbers and the sum its order, so the pixel
/// has the bits of one sample made and traced after another.
fn pixel<V: Vector3>(tracer: &impl Primary<V>, x: u32, y: u32, counts: &mut RayCounts) -> Vec3 {
    let Tracer {
        scene,
        settings,
        machinery,
        ..
    } = tracer.tracer();
    let index = y as u64 * scene.width as u64 + x as u64;
    let samples = Sampler::for_pixel(settings.seed, index);
    let spp = machinery.spp.max(1);
    let mut sum = DVec3::ZERO;
    let mut k = 0;
    while spp - k >= CAMERA_BLOCK {
        let mut block: [Sample; CAMERA_BLOCK as usize] =
            std::array::from_fn(|i| samples.sample(k + i as u32));
        let within = block
            .each_mut()
            .map(|sample| sample_point(settings.pixel_filter, sample));
        let rays = scene.camera.rays_in(x, y, within);
        for (ray, sample) in rays.iter().zip(&mut block) {
            sum += tracer.primary(ray, sample, counts).to_f64();
        }
        k += CAMERA_BLOCK;
    }
    for k in k..spp {
        let mut sample = samples.sample(k);
        let within = sample_point(settings.pixel_filter, &mut sample);
        let ray = scene.camera.ray_in(x, y, within);
        sum += tracer.primary(&ray, &mut sample, counts).to_f64();
    }
    (sum / spp as f64).as_vec3()
}
