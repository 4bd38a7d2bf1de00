//! Helmholtz reciprocity, `f_r(wi, wo) = f_r(wo, wi)`, checked over
//! direction pairs spread over the hemisphere.

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use super::hemisphere::Brdf;
use crate::{Real, Vector3};

/// The worst violation of Helmholtz reciprocity found over a set of
/// direction pairs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReciprocityReport<V: Vector3> {
    /// The largest `|f_r(a, b) − f_r(b, a)|`, in 1/sr.
    pub worst_abs: V::Scalar,
    /// The largest `|f_r(a, b) − f_r(b, a)| / max(f_r(a, b), f_r(b, a))`.
    pub worst_rel: V::Scalar,
    /// The pair `(a, b)` where the relative violation is worst.
    pub worst_pair: (V, V),
    /// How many ordered pairs were compared.
    pub pairs: usize,
}

/// Checks Helmholtz reciprocity, `f_r(a, b) = f_r(b, a)`, over every pair
/// of `directions` at a surface with normal `n`, and reports the worst
/// asymmetry found (zero for a reciprocal BRDF up to rounding).
///
/// ```
/// use glam::DVec3;
/// use radiometry::brdf::{hemisphere_directions, reciprocity, BlinnPhongReciprocal};
/// let dirs = hemisphere_directions::<DVec3>(64);
/// let fixed = BlinnPhongReciprocal { kd: 0.2, ks: 0.5, shine: 20.0 };
/// assert!(reciprocity(&fixed, DVec3::Z, &dirs).worst_rel < 1e-14);
/// ```
pub fn reciprocity<V: Vector3, B: Brdf<V::Scalar>>(
    brdf: &B,
    n: V,
    directions: &[V],
) -> ReciprocityReport<V> {
    let zero = V::Scalar::zero();
    let mut report = ReciprocityReport {
        worst_abs: zero,
        worst_rel: zero,
        worst_pair: (n, n),
        pairs: 0,
    };
    for (i, &a) in directions.iter().enumerate() {
        for &b in &directions[i + 1..] {
            let (ab, ba) = (brdf.eval(n, a, b), brdf.eval(n, b, a));
            report.pairs += 2;
            let diff = (ab - ba).abs();
            let scale = ab.abs().max(ba.abs());
            report.worst_abs = report.worst_abs.max(diff);
            if scale > zero && diff / scale > report.worst_rel {
                report.worst_rel = diff / scale;
                report.worst_pair = (a, b);
            }
        }
    }
    report
}

/// `count` unit directions spread evenly over the hemisphere around +z
/// (a Fibonacci lattice), none exactly at the horizon.
pub fn hemisphere_directions<V: Vector3>(count: usize) -> Vec<V> {
    let golden_angle = V::Scalar::PI() * (V::Scalar::lit(3.0) - V::Scalar::lit(5.0).sqrt());
    (0..count)
        .map(|k| {
            let k = V::Scalar::lit(k as f64);
            let cos_theta =
                V::Scalar::one() - (k + V::Scalar::lit(0.5)) / V::Scalar::lit(count as f64);
            let sin_theta = (V::Scalar::one() - cos_theta * cos_theta).sqrt();
            let phi = golden_angle * k;
            V::new(sin_theta * phi.cos(), sin_theta * phi.sin(), cos_theta)
        })
        .collect()
}
