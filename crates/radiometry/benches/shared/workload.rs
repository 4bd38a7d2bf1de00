//! What the Fresnel laws are timed over, one copy for `benches/fresnel.rs`
//! and the example `fresnel_alternating`: the same cosines and materials,
//! and the loop a caller writes.

use std::hint::black_box;

use radiometry::Real;

/// Cosines per pass.
pub const COSINES: usize = 4096;

/// Glass.
const ETA: f64 = 1.5;
/// The course's gold (red channel): `n`, `κ`.
const GOLD: (f64, f64) = (0.17, 3.1);

/// One tier's workload: the cosines of each side and the materials'
/// constants, fixed for the slice as they are for a surface, each hidden
/// from the optimiser so that no law is folded into a constant.
pub struct Workload<T> {
    /// Cosines over `[-1, 1]`: both sides of a dielectric.
    pub both_sides: Vec<T>,
    /// Cosines over `[0, 1]`: the outside of a conductor.
    pub outside: Vec<T>,
    /// Glass's relative index.
    pub eta: T,
    /// `1 / η²`, which the textbook dielectric takes precomputed.
    pub inv_eta2: T,
    /// Gold's `n`.
    pub n: T,
    /// Gold's `κ`.
    pub kappa: T,
}

impl<T: Real> Workload<T> {
    /// The workload of tier `T`.
    pub fn new() -> Self {
        let eta = black_box(T::lit(ETA));
        let (n, kappa) = black_box((T::lit(GOLD.0), T::lit(GOLD.1)));
        Self {
            both_sides: cosines(-1.0),
            outside: cosines(0.0),
            eta,
            inv_eta2: T::one() / (eta * eta),
            n,
            kappa,
        }
    }
}

/// [`COSINES`] cosines spread evenly over `[low, 1]`.
fn cosines<T: Real>(low: f64) -> Vec<T> {
    let step = (1.0 - low) / COSINES as f64;
    (0..COSINES)
        .map(|k| T::lit(low + step * (k as f64 + 0.5)))
        .collect()
}

/// `law` over `cosines` into `out`, inlined: the loop a caller writes.
#[inline(always)]
pub fn over<T: Real>(cosines: &[T], out: &mut [T], law: impl Fn(T) -> T) {
    for (r, &c) in out.iter_mut().zip(cosines) {
        *r = law(c);
    }
}
