//! Normal-incidence reflectance, `F0`, of an interface from a medium of
//! index 1 into one of complex index `n + i·kappa`.

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use crate::Real;

/// Normal-incidence reflectance `F0 = ((n − 1)² + κ²) / ((n + 1)² + κ²)` of
/// an interface from a medium of index 1 into one of index `n + i·kappa`.
///
/// For a dielectric (`kappa = 0`) this is `((η − 1) / (η + 1))²` for either
/// direction of travel. NaN for `n ≤ 0` or `kappa < 0`.
///
/// ```
/// use radiometry::fresnel::{f0, f0_rgb};
/// // Glass: 4 %.
/// assert!((f0(1.5_f64, 0.0) - 0.04).abs() < 1e-16);
/// // The course's gold, n = (0.17, 0.35, 1.5), κ = (3.1, 2.7, 1.9): yellow.
/// let gold = f0_rgb([0.17_f64, 0.35, 1.5], [3.1, 2.7, 1.9]);
/// let expected = [0.938064, 0.846365, 0.391481];
/// for (got, want) in gold.iter().zip(expected) {
///     assert!((got - want).abs() < 1e-6);
/// }
/// ```
#[inline]
pub fn f0<T: Real>(n: T, kappa: T) -> T {
    let k2 = kappa * kappa;
    let below = (n - T::one()) * (n - T::one()) + k2;
    let above = (n + T::one()) * (n + T::one()) + k2;
    // Chosen after the computation, not branched around it, so that loops
    // over the laws that use it vectorise.
    if n > T::zero() && kappa >= T::zero() {
        below / above
    } else {
        T::nan()
    }
}

/// [`f0`] per channel.
#[inline]
pub fn f0_rgb<T: Real>(n: [T; 3], kappa: [T; 3]) -> [T; 3] {
    core::array::from_fn(|ch| f0(n[ch], kappa[ch]))
}
