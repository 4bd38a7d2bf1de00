//! Error-free transformations for the few sums where the laws cancel.
//!
//! Near the critical angle `n_t² − n_i² sin²θ` is a difference of nearly equal
//! numbers, and near Brewster's angle so is `cos²θ (n_t² + n_i²) − n_i²`. Evaluated
//! naively each loses as many digits as cancel (all of them within 1e-12 rad
//! of the critical angle). Here every product is split exactly into a rounded
//! value and its rounding error (`two_prod`, via a fused multiply-add) and
//! the terms are summed with their errors carried along (`two_sum`), so the
//! result is as accurate as if it had been computed in twice the working
//! precision and rounded once.
//!
//! The Fresnel laws evaluate in the tier's wide precision ([`Real::Wide`](crate::Real::Wide),
//! `f64` for both tiers) and round once at the end, so the `f32` tier's
//! results are limited only by that rounding. Its products are exact in
//! `f64` ([`Real::PRODUCTS_EXACT_IN_WIDE`](crate::Real::PRODUCTS_EXACT_IN_WIDE)): their error terms are zero and
//! are neither computed nor summed, and what is left to compensate is the
//! square of a product of two of them (96 bits), split by Dekker's method.
//! The sums still cancel there: summed plainly in `f64`, R near the
//! critical angle and R_p near Brewster's angle miss by 10 to 25 `f32`
//! ulps (`cargo test -p radiometry --test precision_tiers`, which scans the
//! `f32` cosines around both angles).
//!
//! `two_prod` takes a product's rounding error by a fused multiply-add where
//! the target has the instruction, and by Dekker's splitting otherwise: the
//! default x86-64 target has no FMA, so `mul_add` would be a call into libm
//! for every product, the cost of the whole law. Both give the exact error
//! (Dekker's for operands below `2^995` in magnitude, whose splitting cannot
//! overflow; larger ones are split scaled down by a power of two), so the
//! results are the same bits on every target. No branch is taken on the
//! way, so loops over the laws vectorise.
//!
//! Reference: T. Ogita, S. M. Rump, S. Oishi, "Accurate sum and dot product",
//! SIAM J. Sci. Comput. 26(6), 2005 (algorithms TwoSum, TwoProduct, Sum2).

mod conductor;
mod dielectric;
mod error_free;

pub(crate) use conductor::{brewster_from, discriminant_from, squares_plus};
pub(crate) use dielectric::{
    brewster_factor, snell_discriminant, snell_discriminant_from_sine, IndexSquares,
};
pub(crate) use error_free::TwoPart;

#[cfg(test)]
mod tests;
