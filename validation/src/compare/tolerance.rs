//! Deterministic tests: an image's radiance, or its 8-bit sRGB codes,
//! within a stated tolerance of the reference's, the tolerance widened by
//! the reference's own noise where it has any.
//!
//! **The reference's noise.** A Monte Carlo reference's mean is off the
//! exact value by its standard error `σ/√n` per pixel-channel. The
//! allowance adds `z · σ/√n`, with `z` the two-sided Student-t quantile at
//! `α/m` for the `m` noisy pixel-channels (Bonferroni): a noise-free image
//! of the exact values disagrees somewhere by the reference's noise alone
//! at most once in `1/α` comparisons.
//!
//! **8-bit codes.** A PNG holds `to_srgb8` of each channel
//! ([`tracer::output::to_srgb8`]: clamped to `[0, 1]`, sRGB-encoded,
//! rounded). The codes allowed are those of the radiance interval
//! `reference ± allowance`, widened by one code on either side: a renderer
//! that rounds the same radiance another way (truncating, a GPU's unorm
//! conversion, a float32 encoding landing on the other side of a half
//! code, dithering by one code) is at most one code off. Radiance at or
//! beyond full white is code 255 whatever its value: a PNG cannot show it.

use tracer::output::to_srgb8;

use super::estimate::Estimate;
use super::tolerance_bounds::Tolerance;
use super::verdicts::{masked, Verdicts};
use crate::statistics::student_t_critical;

/// `z` of the reference's noise and what it allows at each pixel-channel:
/// `tolerance.at(reference) + z · σ/√n` (without noise, the tolerance alone).
fn allowances(
    reference: &[f64],
    noise: Option<&Estimate>,
    tolerance: Tolerance,
    alpha: f64,
    mask: Option<&[bool]>,
) -> (Option<f64>, Vec<f64>) {
    let z = noise.and_then(|noise| {
        let noisy = (0..reference.len())
            .filter(|&i| !masked(mask, i) && noise.variance[i] > 0.0)
            .count();
        (noisy > 0)
            .then(|| student_t_critical(alpha / noisy as f64, f64::from(noise.samples) - 1.0))
            .flatten()
    });
    let allowed = (0..reference.len())
        .map(|i| {
            let spread = match (noise, z) {
                (Some(noise), Some(z)) => z * noise.standard_error(i),
                _ => 0.0,
            };
            tolerance.at(reference[i]) + spread
        })
        .collect();
    (z, allowed)
}

/// The test's description: the tolerance, and the noise's `z` if any.
fn describe(what: &str, tolerance: Tolerance, z: Option<f64>, alpha: f64) -> String {
    let noise = z.map_or(String::new(), |z| {
        format!(" + {z:.2} × the reference's standard error (its noise, Bonferroni at α = {alpha})")
    });
    format!(
        "{what} ≤ {:e} + {:e} · |reference|{noise}",
        tolerance.absolute, tolerance.relative
    )
}

/// Radiance against radiance: pixel-channel `i` agrees when
/// `|image[i] − reference[i]|` is within the allowance; the score is the
/// difference over it.
pub fn radiance(
    image: &[f64],
    reference: &[f64],
    noise: Option<&Estimate>,
    tolerance: Tolerance,
    alpha: f64,
    mask: Option<&[bool]>,
) -> Verdicts {
    let (z, allowed) = allowances(reference, noise, tolerance, alpha, mask);
    let test = describe("|image − reference|", tolerance, z, alpha);
    let mut verdicts = Verdicts::new(reference.len(), "W/(sr m²)", test);
    for (i, (&a, &b)) in image.iter().zip(reference).enumerate() {
        if masked(mask, i) {
            continue;
        }
        verdicts.compared[i] = true;
        verdicts.difference[i] = a - b;
        verdicts.score[i] = (a - b).abs() / allowed[i];
    }
    verdicts
}

/// The codes allowed at a radiance and its allowance: those of the
/// interval, one more on either side.
pub fn allowed_codes(reference: f64, allowance: f64) -> (u8, u8) {
    let code = |x: f64| to_srgb8(x as f32);
    (
        code(reference - allowance).saturating_sub(1),
        code(reference + allowance).saturating_add(1),
    )
}

/// 8-bit sRGB codes against radiance: pixel-channel `i` agrees when
/// `codes[i]` is among [`allowed_codes`]; the difference is in codes from
/// the reference's own code, the score that over the allowed codes on its
/// side.
pub fn codes(
    codes: &[u8],
    reference: &[f64],
    noise: Option<&Estimate>,
    tolerance: Tolerance,
    alpha: f64,
    mask: Option<&[bool]>,
) -> Verdicts {
    let (z, allowed) = allowances(reference, noise, tolerance, alpha, mask);
    let test = format!(
        "8-bit sRGB codes within those of {}, one code more either side (rounding)",
        describe(
            "the radiance interval |image − reference|",
            tolerance,
            z,
            alpha
        )
    );
    let mut verdicts = Verdicts::new(reference.len(), "8-bit codes", test);
    for (i, (&u, &b)) in codes.iter().zip(reference).enumerate() {
        if masked(mask, i) {
            continue;
        }
        let (low, high) = allowed_codes(b, allowed[i]);
        let own = to_srgb8(b as f32);
        let d = f64::from(u) - f64::from(own);
        let room = if u >= own { high - own } else { own - low };
        verdicts.compared[i] = true;
        verdicts.difference[i] = d;
        verdicts.score[i] = if d == 0.0 {
            0.0
        } else {
            d.abs() / f64::from(room)
        };
    }
    verdicts
}

#[cfg(test)]
mod tests {
    use super::*;

    const ALPHA: f64 = 0.01;

    #[test]
    fn radiance_within_the_renders_tolerance_agrees_and_beyond_it_disagrees() {
        // Tolerance at 0.5: 1e-5 + 1e-3 · 0.5 = 5.1e-4.
        let reference = [0.5, 0.5, 0.5];
        let image = [0.5 + 5.0e-4, 0.5 - 5.0e-4, 0.5 + 5.2e-4];
        let v = radiance(&image, &reference, None, Tolerance::RENDERS, ALPHA, None);
        assert!(
            !v.disagrees(0) && !v.disagrees(1) && v.disagrees(2),
            "{v:?}"
        );
        assert!((v.score[2] - 5.2e-4 / 5.1e-4).abs() < 1e-9);
    }

    #[test]
    fn a_masked_pixel_is_not_compared_and_nan_disagrees() {
        let reference = [0.2; 6];
        let image = [f64::NAN, 0.2, 0.2, 9.0, 9.0, 9.0];
        let mask = [false, true];
        let v = radiance(
            &image,
            &reference,
            None,
            Tolerance::RENDERS,
            ALPHA,
            Some(&mask),
        );
        assert!(v.disagrees(0) && !v.disagrees(3));
        assert_eq!((v.compared_count(), v.disagreeing_count()), (3, 1));
    }

    #[test]
    fn the_reference_noise_widens_the_tolerance_by_its_bonferroni_quantile() {
        // One noisy channel, n = 100, σ² = 1: z = t(0.01, 99) = 2.626
        // (printed tables, to 3 decimals), σ/√n = 0.1.
        let reference = [1.0, 1.0, 1.0];
        let variance = [1.0, 0.0, 0.0];
        let noise = Estimate {
            mean: &reference,
            variance: &variance,
            samples: 100,
        };
        let image = [1.26, 1.0, 1.0];
        let v = radiance(
            &image,
            &reference,
            Some(&noise),
            Tolerance::RENDERS,
            ALPHA,
            None,
        );
        let allowed = 1e-5 + 1e-3 + 2.626 * 0.1;
        assert!((v.score[0] - 0.26 / allowed).abs() < 1e-3, "{}", v.score[0]);
        assert!(!v.disagrees(0));
        let image = [1.27, 1.0, 1.0];
        let v = radiance(
            &image,
            &reference,
            Some(&noise),
            Tolerance::RENDERS,
            ALPHA,
            None,
        );
        assert!(v.disagrees(0), "{}", v.score[0]);
    }

    #[test]
    fn codes_allow_one_code_of_rounding_and_no_more() {
        // 0.3 linear encodes to 148.877 of 255 (IEC 61966-2-1), code 149;
        // the tolerance 3.1e-4 moves it by 0.07 code, so 148..=150 are allowed.
        assert_eq!(allowed_codes(0.3, Tolerance::RENDERS.at(0.3)), (148, 150));
        let reference = [0.3, 0.3, 0.3];
        let v = codes(
            &[148, 150, 151],
            &reference,
            None,
            Tolerance::RENDERS,
            ALPHA,
            None,
        );
        assert!(
            !v.disagrees(0) && !v.disagrees(1) && v.disagrees(2),
            "{v:?}"
        );
        assert_eq!(v.difference[2], 2.0);
    }

    #[test]
    fn codes_beyond_full_white_are_255_and_black_is_0() {
        let reference = [3.0, 0.0, 1.0];
        let v = codes(
            &[255, 0, 254],
            &reference,
            None,
            Tolerance::RENDERS,
            ALPHA,
            None,
        );
        assert_eq!(v.disagreeing_count(), 0, "{v:?}");
        let v = codes(
            &[253, 2, 255],
            &reference,
            None,
            Tolerance::RENDERS,
            ALPHA,
            None,
        );
        assert_eq!(v.disagreeing_count(), 2, "{v:?}");
    }
}
