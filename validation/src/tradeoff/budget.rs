//! The accuracy budget's prediction: from a cheap pilot pass, an upper
//! bound on the relative RMSE of linear radiance ([`super::measure`]) that
//! a render at given settings reaches against the ground truth, and the
//! cheapest settings, in rays, whose bound stays under a tolerance
//! ([`choose_among`], for any metric). The displayed image's measures are
//! bounded by simulated renders in [`displayed`].
//!
//! # The bound
//!
//! A render `x` of the surface pixel-channels `i` at `N` samples per pixel
//! differs from the truth `t` by a bias and a noise:
//! `x_i − t_i = b_i + ε_i`, `E[ε_i] = 0`, `Var ε_i = σ_i² / N`, so the
//! squared error the measure takes has the expectation
//! `Σ b_i² + Σ σ_i² / N` and the spread of a sum of independent terms.
//!
//! The pilot renders each candidate and the *pilot reference* (the truth's
//! settings) as two halves of `h` samples each, seeds `s` and `s + 1`:
//!
//! - **bias**: `B = Σ (m_c − m_r)²` of the two means. Its expectation is
//!   `Σ b_i²` *plus* the variance of the difference, never less: the
//!   pilot's noise can only make the bias look larger. Everything a
//!   setting leaves out (the light past `max_depth`, Schlick's error at
//!   the angles this scene produces, the light an integrator misses, the
//!   centre instead of the box filter) is in it, measured at the
//!   render's own size and pixels.
//! - **noise**: `S = Σ h (a_c − b_c)² / 2`, an unbiased estimate of
//!   `Σ σ_i²` per sample; stratified samples only lower `σ²` as `N` grows,
//!   so `S / N` is conservative too.
//! - **energy**: `Σ m_r² − Σ (a_r − b_r)² / 4`, unbiased for `Σ t_i²`.
//!
//! Each sum is one of independent terms, whose standard deviation is
//! estimated by `√(2 Σ w²)` for terms `w` (a weighted χ² with one degree of
//! freedom each: mean `Σ w`, variance `2 Σ w²`; the single draws
//! overestimate `Σ w²` threefold, on the safe side). The prediction takes
//! each at [`K`] standard deviations on its unsafe side, the final render's
//! own noise fluctuation and the bias–noise cross term `2 Σ b ε` as well:
//!
//! ```text
//! squared = B + K √(2 Σ d⁴)  +  (S + 2 K √(2 Σ w²)) / N  +  2 K √(Σ d² w / N)
//! rel_rmse ≤ √(squared / (E − K √(Σ 4 m_r² v_r)))
//! ```
//!
//! A deterministic setting has no noise term: its two halves agree.

mod choice;
pub mod displayed;
mod linear;
mod need;
mod pilot;
mod tolerance;

pub use choice::{choose, choose_among, Bound, Choice};
pub use linear::{cheapest, need, predict, Prediction};
pub use need::Need;
pub use pilot::{energy, top_spp, Pilot, Rays, Sum, K};
pub use tolerance::written;

#[cfg(test)]
mod tests;
