//! The exact laws over slices of cosines, for callers that evaluate one
//! material at many angles (a table, a batch of requests, a film row): the
//! scalar law in a loop the compiler can vectorise, since the laws choose
//! their special cases without branching.

use crate::Real;

/// [`super::dielectric`] of each cosine in `cos_i`, written to `out`.
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
    each(cos_i, out, |c| super::dielectric(c, eta));
}

/// [`super::conductor`] of each cosine in `cos_i`, written to `out`.
///
/// # Panics
///
/// If the two slices differ in length.
pub fn conductor_slice<T: Real>(cos_i: &[T], n: T, kappa: T, out: &mut [T]) {
    each(cos_i, out, |c| super::conductor(c, n, kappa));
}

#[inline(always)]
fn each<T: Real>(cos_i: &[T], out: &mut [T], law: impl Fn(T) -> T) {
    assert_eq!(
        cos_i.len(),
        out.len(),
        "a slice law needs as many outputs as cosines"
    );
    for (r, &c) in out.iter_mut().zip(cos_i) {
        *r = law(c);
    }
}
