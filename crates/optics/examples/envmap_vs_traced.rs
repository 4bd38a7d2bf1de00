//! Environment mapping against ray tracing (`docs/techniques.md`,
//! "Environment mapping against ray tracing"): the error of a mirror
//! sphere rendered with the slides' captured cube map against the same
//! mirror traced, as its surroundings move away, and the error of two
//! mirrors side by side, which cannot show each other's reflection of
//! themselves.
//!
//! ```text
//! cargo run --release -p optics --example envmap_vs_traced -- docs/images
//! .venv/bin/python python-checks/plot_envmap_error.py \
//!     docs/images/envmap_vs_traced.json docs/images/envmap_error_vs_distance.png
//! ```
//!
//! Writes `envmap_vs_traced.json` (every number) and the pictures
//! `envmap_*.png` (traced | mapped | 4 × |difference|) into the directory
//! given, and prints the tables as Markdown.

use std::path::{Path, PathBuf};

use image::ImageEncoder;
use serde_json::{json, Map, Value};
use tracer::output::srgb8;
use tracer::render::Image;
use validation::techniques::envmap_vs_traced::{
    log_log_slope, one_sphere, two_spheres, Comparison, Resolution, Surroundings,
};

const RESOLUTION: Resolution = Resolution {
    image: 256,
    cube: 512,
};

const SKY: [f64; 9] = [5.0, 6.0, 8.0, 12.0, 16.0, 24.0, 32.0, 48.0, 64.0];
const OBJECTS: [f64; 11] = [2.0, 3.0, 4.0, 6.0, 8.0, 12.0, 16.0, 24.0, 32.0, 48.0, 64.0];

/// Where self-reflection is measured: far enough that a lone mirror's
/// error is small.
const SELF_REFLECTION_D: f64 = 32.0;

fn main() {
    let out = PathBuf::from(
        std::env::args()
            .nth(1)
            .unwrap_or_else(|| "docs/images".into()),
    );
    let (rows, slopes) = distance_sweep(&out);
    let pairs = self_reflection(&out);
    let record = json!({
        "schema": "optics.envmap_vs_traced",
        "version": 1,
        "command": "cargo run --release -p optics --example envmap_vs_traced -- docs/images",
        "resolution": RESOLUTION,
        "sweep": rows,
        "fitted_exponents": slopes,
        "self_reflection": pairs,
    });
    let path = out.join("envmap_vs_traced.json");
    std::fs::write(&path, serde_json::to_string_pretty(&record).unwrap() + "\n").unwrap();
    println!("wrote {}", path.display());
}

/// One mirror sphere as its surroundings move away: a table row and a
/// JSON row per distance, the pictures of three of them, and the fitted
/// exponents of each kind of surroundings.
fn distance_sweep(out: &Path) -> (Vec<Value>, Map<String, Value>) {
    let mut rows = Vec::new();
    let mut slopes = Map::new();
    println!("| surroundings | d (radii) | rel. RMSE | mean ΔE2000 | p99 ΔE2000 | mean ꟻLIP |");
    println!("|---|---|---|---|---|---|");
    for (kind, distances, name) in [
        (Surroundings::Sky, &SKY[..], "sky"),
        (Surroundings::Objects, &OBJECTS[..], "objects"),
    ] {
        let mut rmse = Vec::new();
        let mut delta_e = Vec::new();
        for &d in distances {
            let c = one_sphere(kind, d, RESOLUTION);
            let e = c.errors;
            println!(
                "| {name} | {d} | {:.4} | {:.3} | {:.2} | {:.4} |",
                e.rel_rmse, e.delta_e_mean, e.delta_e_p99, e.flip_mean
            );
            rmse.push((d, e.rel_rmse));
            delta_e.push((d, e.delta_e_mean));
            rows.push(json!({ "surroundings": kind, "distance": d, "errors": e, "pixels": c.mask.count() }));
            if [
                (Surroundings::Objects, 2.0),
                (Surroundings::Objects, 16.0),
                (Surroundings::Sky, 6.0),
            ]
            .contains(&(kind, d))
            {
                strip(&c, &out.join(format!("envmap_{name}_d{d}.png")));
            }
        }
        // The slope over the far half, where the parallax is small.
        let far = |points: &[(f64, f64)]| {
            points
                .iter()
                .copied()
                .filter(|p| p.0 >= 8.0)
                .collect::<Vec<_>>()
        };
        let fitted = json!({
            "rel_rmse": log_log_slope(&rmse),
            "delta_e_mean": log_log_slope(&delta_e),
            "rel_rmse_d_ge_8": log_log_slope(&far(&rmse)),
            "delta_e_mean_d_ge_8": log_log_slope(&far(&delta_e)),
        });
        println!("\n{name}: fitted exponents {fitted}\n");
        slopes.insert(name.into(), fitted);
    }
    (rows, slopes)
}

/// One mirror and two side by side at `SELF_REFLECTION_D`: a table row
/// each, and where two show each other, the error split there.
fn self_reflection(out: &Path) -> Vec<Value> {
    let mut pairs = Vec::new();
    println!("| mirrors | surroundings at d = {SELF_REFLECTION_D} | rel. RMSE | mean ΔE2000 | p99 ΔE2000 | mean ꟻLIP |");
    println!("|---|---|---|---|---|---|");
    for kind in [Surroundings::Sky, Surroundings::Objects] {
        for (mirrors, c) in [
            ("one", one_sphere(kind, SELF_REFLECTION_D, RESOLUTION)),
            ("two", two_spheres(kind, SELF_REFLECTION_D, RESOLUTION)),
        ] {
            let e = c.errors;
            println!(
                "| {mirrors} | {kind:?} | {:.4} | {:.3} | {:.2} | {:.4} |",
                e.rel_rmse, e.delta_e_mean, e.delta_e_p99, e.flip_mean
            );
            if let Some(split) = c.split {
                for (part, e, n) in [
                    (
                        "where it shows the other",
                        split.seeing_a_mirror,
                        split.seeing_a_mirror_pixels,
                    ),
                    ("elsewhere", split.elsewhere, split.elsewhere_pixels),
                ] {
                    println!(
                        "| two, {part} ({n} px) | {kind:?} | {:.4} | {:.3} | {:.2} | {:.4} |",
                        e.rel_rmse, e.delta_e_mean, e.delta_e_p99, e.flip_mean
                    );
                }
                strip(
                    &c,
                    &out.join(format!("envmap_two_spheres_{kind:?}.png").to_lowercase()),
                );
            }
            pairs.push(json!({
                "mirrors": mirrors, "surroundings": kind, "distance": SELF_REFLECTION_D,
                "errors": e, "pixels": c.mask.count(), "split": c.split,
            }));
        }
    }
    pairs
}

/// The traced render, the mapped one and four times their absolute
/// difference, side by side, as the PNG displays them.
fn strip(c: &Comparison, path: &Path) {
    let (w, h) = (c.traced.width, c.traced.height);
    let diff = Image {
        width: w,
        height: h,
        pixels: c
            .traced
            .pixels
            .iter()
            .zip(&c.mapped.pixels)
            .map(|(a, b)| (*a - *b).abs() * 4.0)
            .collect(),
    };
    let tiles = [srgb8(&c.traced), srgb8(&c.mapped), srgb8(&diff)];
    let mut bytes = Vec::with_capacity((9 * w * h) as usize);
    for y in 0..h as usize {
        for tile in &tiles {
            let row = 3 * w as usize;
            bytes.extend_from_slice(&tile[y * row..(y + 1) * row]);
        }
    }
    let file = std::fs::File::create(path).unwrap();
    image::codecs::png::PngEncoder::new(std::io::BufWriter::new(file))
        .write_image(&bytes, 3 * w, h, image::ExtendedColorType::Rgb8)
        .unwrap();
}
