//! Texels given back to a map, checked once, where they enter.

/// Why a texel given back is not one of a map's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TexelError {
    /// `u` is not a finite number in `[0, 1]`; the value given.
    U(f64),
    /// `v` is not a finite number in `[0, 1]`; the value given.
    V(f64),
    /// `(u, v)` lies outside the sphere map's disc
    /// `(2u − 1)² + (2v − 1)² ≤ 1`.
    OutsideDisc {
        /// `u` given.
        u: f64,
        /// `v` given.
        v: f64,
    },
}

/// `(u, v)` checked to lie in the unit square, once, for every map.
pub(super) fn unit_square(u: f64, v: f64) -> Result<(f64, f64), TexelError> {
    if !(0.0..=1.0).contains(&u) {
        return Err(TexelError::U(u));
    }
    if !(0.0..=1.0).contains(&v) {
        return Err(TexelError::V(v));
    }
    Ok((u, v))
}
