//! The cost side of "three wavelengths instead of a spectrum": time per
//! metal colour by each method, measured with the wall clock on the machine
//! that runs the report. These are measurements, never assertions; the
//! criterion bench `cargo bench -p validation --bench metal_colour` measures
//! the same two paths with statistics.

use std::hint::black_box;
use std::time::Instant;

use radiometry::colour;
use radiometry::spectrum::{self, SAMPLES};
use serde::Serialize;

use crate::metals::{Metal, MetalLaws};
use radiometry::course::{GOLD_000_KAPPA, GOLD_000_N};

/// One timed method.
#[derive(Clone, Debug, Serialize)]
pub struct Timing {
    /// What was timed.
    pub method: String,
    /// Mean wall-clock time per colour, nanoseconds.
    pub ns_per_colour: f64,
    /// How many colours were timed.
    pub iterations: u64,
    /// Whether the code was compiled with optimisations (times from an
    /// unoptimised build say little about the trade).
    pub optimised: bool,
}

/// The CIELAB colour of a metal at `cos_i` from its full spectrum: 85
/// conductor evaluations, the CIE integral, the Lab transform.
pub fn spectral_lab(laws: &MetalLaws, index: &[(f64, f64); SAMPLES], cos_i: f64) -> colour::Lab {
    let xyz = spectrum::reflectance_to_xyz(&laws.spectrum(index, cos_i));
    colour::xyz_to_lab(xyz, colour::d65_white())
}

/// The CIELAB colour from three per-channel conductor evaluations.
pub fn rgb_lab(laws: &MetalLaws, n: [f64; 3], kappa: [f64; 3], cos_i: f64) -> colour::Lab {
    let rgb: [f64; 3] = core::array::from_fn(|ch| (laws.conductor)(cos_i, n[ch], kappa[ch]));
    colour::xyz_to_lab(colour::linear_srgb_to_xyz(rgb), colour::d65_white())
}

fn time(method: &str, iterations: u64, mut f: impl FnMut(f64) -> colour::Lab) -> Timing {
    let start = Instant::now();
    for i in 0..iterations {
        // Vary the angle so that nothing is hoisted out of the loop.
        let cos_i = 0.5 + 0.5 * (i % 1000) as f64 / 1000.0;
        black_box(f(black_box(cos_i)));
    }
    Timing {
        method: method.to_owned(),
        ns_per_colour: start.elapsed().as_nanos() as f64 / iterations as f64,
        iterations,
        optimised: !cfg!(debug_assertions),
    }
}

/// Times the spectral colour of `gold` against the course's three-wavelength
/// colour, `iterations` colours each.
pub fn time_gold(laws: &MetalLaws, gold: &Metal, iterations: u64) -> Option<[Timing; 2]> {
    let index = gold.index_on_grid()?;
    Some([
        time(
            "spectral: 85 wavelengths, CIE integral, Lab",
            iterations,
            |c| spectral_lab(laws, &index, c),
        ),
        time("course RGB: 3 wavelengths, matrix, Lab", iterations, |c| {
            rgb_lab(laws, GOLD_000_N, GOLD_000_KAPPA, c)
        }),
    ])
}
