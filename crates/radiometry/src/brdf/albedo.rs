//! Energy conservation: the directional albedo
//! `ρ(wi) = ∫ f_r(wi, wo) cos θ_o dω_o`, by quadrature with its error.

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use super::hemisphere::Brdf;
use crate::{Real, Vector3};

/// A directional albedo with the estimated error of its quadrature.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AlbedoEstimate<T> {
    /// `ρ(wi) = ∫ f_r(wi, wo) cos θ_o dω_o` over the hemisphere, unitless.
    pub albedo: T,
    /// `|ρ_2N − ρ_N|`, the change from halving the quadrature step: an
    /// estimate of the quadrature error of `ρ_N`, so a conservative one of
    /// `albedo` (which is `ρ_2N`).
    pub error_estimate: T,
    /// How many BRDF evaluations the estimate took.
    pub evaluations: usize,
}

/// The directional albedo `ρ(wi) = ∫_H f_r(wi, wo) cos θ_o dω_o`, the
/// fraction of the power arriving from `wi` that the surface reflects into
/// the hemisphere; energy conservation requires `ρ ≤ 1` for every `wi`.
///
/// The integral is over the outgoing directions `wo`, whatever the BRDF: a
/// BRDF that is not reciprocal (the course's Phong-Blinn, which divides by
/// `cos θ_i`) can send a grazing `wi` more power than it received while
/// every integral over incoming directions stays below 1. For a reciprocal
/// BRDF the two integrals are the same.
///
/// Integrated with the midpoint rule in `(cos θ_o, φ_o)`, where
/// `dω = d(cos θ) dφ`, on an `n × 4n` grid and again on a `2n × 8n` grid;
/// the finer result is returned with their difference as its error
/// estimate. The midpoint rule is exact for an integrand linear in
/// `cos θ_o`, so Lambertian albedos come out exact to rounding.
pub fn directional_albedo<V: Vector3, B: Brdf<V::Scalar>>(
    brdf: &B,
    n: V,
    wi: V,
    resolution: usize,
) -> AlbedoEstimate<V::Scalar> {
    let resolution = resolution.max(1);
    let coarse = midpoint_albedo(brdf, n, wi, resolution);
    let fine = midpoint_albedo(brdf, n, wi, 2 * resolution);
    AlbedoEstimate {
        albedo: fine,
        error_estimate: (fine - coarse).abs(),
        evaluations: 4 * resolution * resolution + 16 * resolution * resolution,
    }
}

fn midpoint_albedo<V: Vector3, B: Brdf<V::Scalar>>(
    brdf: &B,
    n: V,
    wi: V,
    rows: usize,
) -> V::Scalar {
    let (t, b) = orthonormal_frame(n);
    let one = V::Scalar::one();
    let half = V::Scalar::lit(0.5);
    let columns = 4 * rows;
    let d_mu = one / V::Scalar::lit(rows as f64);
    let d_phi = V::Scalar::TAU() / V::Scalar::lit(columns as f64);
    let mut total = V::Scalar::zero();
    for row in 0..rows {
        let mu = (V::Scalar::lit(row as f64) + half) * d_mu;
        let sin_theta = (one - mu * mu).sqrt();
        let mut ring = V::Scalar::zero();
        for column in 0..columns {
            let phi = (V::Scalar::lit(column as f64) + half) * d_phi;
            let wo = t * (sin_theta * phi.cos()) + b * (sin_theta * phi.sin()) + n * mu;
            ring = ring + brdf.eval(n, wi, wo) * mu;
        }
        total = total + ring;
    }
    total * d_mu * d_phi
}

/// Two unit tangents completing the unit normal `n` to a right-handed
/// orthonormal frame (Duff et al., "Building an orthonormal basis,
/// revisited", JCGT 6(1), 2017).
fn orthonormal_frame<V: Vector3>(n: V) -> (V, V) {
    let [x, y, z] = n.to_array();
    let one = V::Scalar::one();
    let sign = one.copysign(z);
    let a = -one / (sign + z);
    let b = x * y * a;
    (
        V::new(one + sign * x * x * a, sign * b, -sign * x),
        V::new(b, sign + y * y * a, -y),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::brdf::hemisphere_directions;
    use glam::DVec3;

    #[test]
    fn orthonormal_frame_is_orthonormal() {
        for n in
            hemisphere_directions::<DVec3>(50)
                .into_iter()
                .chain([DVec3::Z, -DVec3::Z, DVec3::X])
        {
            let (t, b) = orthonormal_frame(n);
            for (u, v) in [(t, b), (t, n), (b, n)] {
                assert!(u.dot(v).abs() < 1e-15, "{u} · {v}");
            }
            for u in [t, b] {
                assert!((u.length() - 1.0).abs() < 1e-15);
            }
        }
    }
}
