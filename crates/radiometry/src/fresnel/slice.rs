//! The exact laws over slices of cosines, for callers that evaluate one
//! material at many angles (a table, a batch of requests, a film row): the
//! scalar law in a loop the compiler vectorises, since the laws compute
//! their general case whatever the input and choose their special cases
//! after it, without branching.
//!
//! # Wider instructions, same bits
//!
//! The loop is compiled three times: for the build's own target (on
//! x86-64 by default SSE2, two `f64` lanes), for AVX2 with FMA (four) and
//! for AVX-512 (eight), and each call takes the widest the CPU has
//! ([`Lanes::widest`]). Every path gives the same bits: the laws use only
//! additions, multiplications, divisions and square roots, each correctly
//! rounded by IEEE 754 whatever the width; Rust never fuses a
//! multiplication and an addition on its own; and where the `f32` tier
//! takes a product's rounding error, an exact number, the wide paths take
//! it by one fused multiply-add and the baseline by Dekker's split, the
//! same value either way (`compensated::exact_error`; the `f64` tier's
//! error-free products choose for the build, not per path). The test
//! `fresnel_slice_paths_agree_bit_for_bit` forces each path the CPU has
//! and compares.

use crate::Real;

/// The width of the instructions a slice law runs on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lanes {
    /// The build's own target (SSE2 on the default x86-64 target).
    Baseline,
    /// AVX2 with FMA (x86-64), four `f64` lanes.
    Avx2,
    /// AVX-512 F/DQ/VL with FMA (x86-64), eight `f64` lanes.
    Avx512,
}

impl Lanes {
    /// Every width, narrowest first.
    pub const ALL: [Lanes; 3] = [Lanes::Baseline, Lanes::Avx2, Lanes::Avx512];

    /// Whether this CPU can run this width.
    pub fn available(self) -> bool {
        match self {
            Lanes::Baseline => true,
            #[cfg(target_arch = "x86_64")]
            Lanes::Avx2 => {
                std::arch::is_x86_feature_detected!("avx2")
                    && std::arch::is_x86_feature_detected!("fma")
            }
            #[cfg(target_arch = "x86_64")]
            Lanes::Avx512 => {
                std::arch::is_x86_feature_detected!("avx512f")
                    && std::arch::is_x86_feature_detected!("avx512dq")
                    && std::arch::is_x86_feature_detected!("avx512vl")
                    && std::arch::is_x86_feature_detected!("fma")
            }
            #[cfg(not(target_arch = "x86_64"))]
            _ => false,
        }
    }

    /// The widest this CPU can run, the one the slice laws take.
    pub fn widest() -> Self {
        Self::ALL
            .into_iter()
            .rev()
            .find(|lanes| lanes.available())
            .unwrap_or(Lanes::Baseline)
    }
}

/// [`super::dielectric`] of each cosine in `cos_i`, written to `out`, on
/// the widest instructions this CPU has.
///
/// ```
/// use radiometry::fresnel::{dielectric, dielectric_slice};
/// let cosines = [1.0_f32, 0.5, -0.5, -0.9];
/// let mut r = [0.0; 4];
/// dielectric_slice(&cosines, 1.5, &mut r);
/// assert_eq!(r, cosines.map(|c| dielectric(c, 1.5)));
/// ```
///
/// # Panics
///
/// If the two slices differ in length.
pub fn dielectric_slice<T: Real>(cos_i: &[T], eta: T, out: &mut [T]) {
    dielectric_slice_on(Lanes::widest(), cos_i, eta, out);
}

/// [`super::conductor`] of each cosine in `cos_i`, written to `out`, on the
/// widest instructions this CPU has.
///
/// # Panics
///
/// If the two slices differ in length.
pub fn conductor_slice<T: Real>(cos_i: &[T], n: T, kappa: T, out: &mut [T]) {
    conductor_slice_on(Lanes::widest(), cos_i, n, kappa, out);
}

/// [`dielectric_slice`] on the given width, or on the baseline where this
/// CPU lacks it: for tests and benchmarks that compare the paths.
///
/// # Panics
///
/// If the two slices differ in length.
pub fn dielectric_slice_on<T: Real>(lanes: Lanes, cos_i: &[T], eta: T, out: &mut [T]) {
    dispatch(lanes, cos_i, out, &Dielectric(eta));
}

/// [`conductor_slice`] on the given width, or on the baseline where this
/// CPU lacks it.
///
/// # Panics
///
/// If the two slices differ in length.
pub fn conductor_slice_on<T: Real>(lanes: Lanes, cos_i: &[T], n: T, kappa: T, out: &mut [T]) {
    match super::conductor::Conductor::new(n, kappa) {
        // The material's constants once per slice, as for a surface.
        Some(metal) => dispatch(lanes, cos_i, out, &metal),
        None => dispatch(lanes, cos_i, out, &Undefined),
    }
}

/// A law of one material at a cosine, called in a loop: a trait rather
/// than a closure, so that its body is inlined into every width's loop.
trait AtCosine<T>: Sync {
    /// The law at `cos_i`, compiled for a path that fuses a multiply-add
    /// (`FUSED`) or not: the same bits either way.
    fn at<const FUSED: bool>(&self, cos_i: T) -> T;
}

struct Dielectric<T>(T);

impl<T: Real> AtCosine<T> for Dielectric<T> {
    #[inline(always)]
    fn at<const FUSED: bool>(&self, cos_i: T) -> T {
        super::dielectric::polarized_on::<T, FUSED>(cos_i, self.0).reflectance()
    }
}

impl<T: Real> AtCosine<T> for super::conductor::Conductor<T> {
    #[inline(always)]
    fn at<const FUSED: bool>(&self, cos_i: T) -> T {
        self.polarized_on::<FUSED>(cos_i).reflectance()
    }
}

/// Input that describes no material: NaN at every cosine.
struct Undefined;

impl<T: Real> AtCosine<T> for Undefined {
    #[inline(always)]
    fn at<const FUSED: bool>(&self, _: T) -> T {
        T::nan()
    }
}

#[inline(always)]
fn dispatch<T: Real>(lanes: Lanes, cos_i: &[T], out: &mut [T], law: &impl AtCosine<T>) {
    assert_eq!(
        cos_i.len(),
        out.len(),
        "a slice law needs as many outputs as cosines"
    );
    match lanes {
        #[cfg(target_arch = "x86_64")]
        Lanes::Avx512 => wide::avx512(cos_i, out, law),
        #[cfg(target_arch = "x86_64")]
        Lanes::Avx2 => wide::avx2(cos_i, out, law),
        _ => each::<T, false>(cos_i, out, law),
    }
}

/// The loop; `FUSED` where it is compiled for instructions that fuse a
/// multiply-add.
#[inline(always)]
fn each<T: Real, const FUSED: bool>(cos_i: &[T], out: &mut [T], law: &impl AtCosine<T>) {
    for (r, &c) in out.iter_mut().zip(cos_i) {
        *r = law.at::<FUSED>(c);
    }
}

/// The loop compiled for wider instructions. The only `unsafe` of the
/// crate: calling a function compiled for instructions the CPU may lack.
#[cfg(target_arch = "x86_64")]
#[allow(unsafe_code)]
mod wide {
    use super::{each, AtCosine, Lanes};
    use crate::Real;

    #[target_feature(enable = "avx2,fma")]
    fn each_avx2<T: Real>(cos_i: &[T], out: &mut [T], law: &impl AtCosine<T>) {
        each::<T, true>(cos_i, out, law);
    }

    #[target_feature(enable = "avx512f,avx512dq,avx512vl,fma")]
    fn each_avx512<T: Real>(cos_i: &[T], out: &mut [T], law: &impl AtCosine<T>) {
        each::<T, true>(cos_i, out, law);
    }

    /// The loop on AVX2 where this CPU has it, on the baseline otherwise.
    #[inline(always)]
    pub(super) fn avx2<T: Real>(cos_i: &[T], out: &mut [T], law: &impl AtCosine<T>) {
        if Lanes::Avx2.available() {
            // SAFETY: this CPU runs AVX2 and FMA, checked on the line above.
            unsafe { each_avx2(cos_i, out, law) }
        } else {
            each::<T, false>(cos_i, out, law)
        }
    }

    /// The loop on AVX-512 where this CPU has it, on the baseline otherwise.
    #[inline(always)]
    pub(super) fn avx512<T: Real>(cos_i: &[T], out: &mut [T], law: &impl AtCosine<T>) {
        if Lanes::Avx512.available() {
            // SAFETY: this CPU runs AVX-512 F, DQ and VL and FMA, checked on the
            // line above.
            unsafe { each_avx512(cos_i, out, law) }
        } else {
            each::<T, false>(cos_i, out, law)
        }
    }
}
