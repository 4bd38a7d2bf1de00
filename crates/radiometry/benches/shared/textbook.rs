//! The exact Fresnel laws as shaders write them: the baselines the crate's
//! laws are timed against (`benches/fresnel.rs` and the example
//! `fresnel_alternating`), one copy for both.

use radiometry::Real;

/// The exact dielectric law as shaders write it, from the outside.
#[inline(always)]
pub fn dielectric_textbook<T: Real>(cos_i: T, eta: T, inv_eta2: T) -> T {
    let c = cos_i.abs();
    let sin2_t = (T::one() - c * c) * inv_eta2;
    let cos_t = (T::one() - sin2_t).max(T::zero()).sqrt();
    let r_s = (c - eta * cos_t) / (c + eta * cos_t);
    let r_p = (eta * c - cos_t) / (eta * c + cos_t);
    (r_s * r_s + r_p * r_p) * T::lit(0.5)
}

/// The exact conductor law in the `a² + b²` form shaders use.
#[inline(always)]
pub fn conductor_textbook<T: Real>(cos_i: T, n: T, kappa: T) -> T {
    let c2 = cos_i * cos_i;
    let s2 = T::one() - c2;
    let t0 = n * n - kappa * kappa - s2;
    let a2b2 = (t0 * t0 + T::lit(4.0) * n * n * kappa * kappa).sqrt();
    let a = ((a2b2 + t0) * T::lit(0.5)).max(T::zero()).sqrt();
    let t1 = a2b2 + c2;
    let t2 = T::lit(2.0) * a * cos_i;
    let r_s = (t1 - t2) / (t1 + t2);
    let t3 = c2 * a2b2 + s2 * s2;
    let t4 = t2 * s2;
    let r_p = r_s * (t3 - t4) / (t3 + t4);
    (r_s + r_p) * T::lit(0.5)
}
