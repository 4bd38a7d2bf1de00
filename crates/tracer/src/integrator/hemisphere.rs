//! Directions drawn on the hemisphere around a normal.

use glam::Vec3;

/// A direction on the hemisphere around `n` with density `cos θ / π`
/// (Malley's method: a uniform point on the unit disc lifted to the
/// hemisphere; Pharr, Jakob and Humphreys, *pbrt* 4th ed., §A.5.3), from two
/// uniform numbers in `[0, 1)`.
pub fn cosine_sample(n: Vec3, u1: f32, u2: f32) -> Vec3 {
    let r = u1.sqrt();
    let phi = std::f32::consts::TAU * u2;
    let (x, y) = (r * phi.cos(), r * phi.sin());
    let z = (1.0 - u1).max(0.0).sqrt();
    let (t, b) = n.any_orthonormal_pair();
    (t * x + b * y + n * z).normalize()
}
