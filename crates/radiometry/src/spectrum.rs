//! Sampled spectra and their CIE 1931 tristimulus values `X, Y, Z` under
//! illuminant D65: wavelengths in nanometres, tristimulus values unitless,
//! scaled so that a perfect reflector has `Y = 1`.
//!
//! Spectra are sampled on the CIE grid, 360–780 nm every 5 nm ([`SAMPLES`]
//! values), where the CIE tabulates both the 2° colour-matching functions and
//! D65 (CIE 15:2004, tables T.1 and T.4). The tables are compiled in as
//! constants, generated from colour-science's copies by
//! `python-checks/colorimetry.py`; the workspace tests check them, and the
//! colours computed from them, against colour-science.
//!
//! The tristimulus integral is the CIE's sum over the grid (CIE 15:2004
//! §7.1): `X = Σ R(λ) S(λ) x̄(λ) / Σ S(λ) ȳ(λ)`, likewise `Y` and `Z`, with
//! `S` the illuminant and `R` the reflectance.
//!
//! ```
//! use radiometry::spectrum;
//! // A perfect reflector under D65 is the D65 white, Y = 1.
//! let white = spectrum::reflectance_to_xyz(&[1.0; spectrum::SAMPLES]);
//! assert!((white.y - 1.0).abs() < 1e-15);
//! assert!((white.x - 0.9505).abs() < 1e-4 && (white.z - 1.0890).abs() < 1e-4);
//! ```

pub use crate::cie_tables::{CMF_XYZ, D65, SAMPLES, START_NM, STEP_NM};
use crate::colour::Xyz;

/// One wavelength per RGB channel, red first, in nanometres: where a
/// three-wavelength renderer reads a measured index for its red, green and
/// blue (the course texts name none; these are a common choice).
pub const RGB_WAVELENGTHS_NM: [f64; 3] = [650.0, 550.0, 450.0];

/// The wavelength of sample `i`, in nanometres.
#[inline]
pub fn wavelength_nm(i: usize) -> f64 {
    START_NM + STEP_NM * i as f64
}

/// Samples `f(wavelength_nm)` on the CIE grid.
pub fn sample(mut f: impl FnMut(f64) -> f64) -> [f64; SAMPLES] {
    core::array::from_fn(|i| f(wavelength_nm(i)))
}

/// The value at `at_nm` of a tabulated function, interpolated linearly
/// between the two neighbouring samples.
///
/// `wavelengths_nm` must be increasing and as long as `values`. Returns `None`
/// outside the tabulated range, for mismatched or empty tables, and for NaN.
///
/// ```
/// use radiometry::spectrum::interpolate_linear;
/// let w = [400.0, 500.0, 600.0];
/// let v = [1.0, 3.0, 2.0];
/// assert_eq!(interpolate_linear(&w, &v, 450.0), Some(2.0));
/// assert_eq!(interpolate_linear(&w, &v, 600.0), Some(2.0));
/// assert_eq!(interpolate_linear(&w, &v, 650.0), None);
/// ```
pub fn interpolate_linear(wavelengths_nm: &[f64], values: &[f64], at_nm: f64) -> Option<f64> {
    if wavelengths_nm.len() != values.len() || wavelengths_nm.is_empty() {
        return None;
    }
    let (first, last) = (wavelengths_nm[0], wavelengths_nm[wavelengths_nm.len() - 1]);
    if !(at_nm >= first && at_nm <= last) {
        return None;
    }
    // The first sample at or beyond `at_nm`.
    let upper = wavelengths_nm.partition_point(|&w| w < at_nm);
    if wavelengths_nm[upper] == at_nm {
        return Some(values[upper]);
    }
    let (w0, w1) = (wavelengths_nm[upper - 1], wavelengths_nm[upper]);
    let t = (at_nm - w0) / (w1 - w0);
    Some(values[upper - 1] + t * (values[upper] - values[upper - 1]))
}

/// The CIE 1931 tristimulus values of a reflectance sampled on the CIE grid,
/// under D65, with `Y = 1` for a perfect reflector.
pub fn reflectance_to_xyz(reflectance: &[f64; SAMPLES]) -> Xyz {
    let (mut x, mut y, mut z, mut white) = (0.0, 0.0, 0.0, 0.0);
    for ((r, [xb, yb, zb]), s) in reflectance.iter().zip(CMF_XYZ).zip(D65) {
        let power = r * s;
        x += power * xb;
        y += power * yb;
        z += power * zb;
        white += s * yb;
    }
    Xyz {
        x: x / white,
        y: y / white,
        z: z / white,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_spans_360_to_780_nm() {
        assert_eq!(wavelength_nm(0), 360.0);
        assert_eq!(wavelength_nm(SAMPLES - 1), 780.0);
    }

    #[test]
    fn tables_peak_where_the_cie_says() {
        // ȳ peaks at 555 nm with the value 1 (CIE 15:2004, table T.4), D65 is 100 at 560 nm.
        // colour-science's copy carries one rounding of its own (0.9999999999999999).
        let peak = (0..SAMPLES).max_by(|&a, &b| CMF_XYZ[a][1].total_cmp(&CMF_XYZ[b][1]));
        assert_eq!(peak.map(wavelength_nm), Some(555.0));
        assert!((CMF_XYZ[39][1] - 1.0).abs() <= f64::EPSILON);
        assert_eq!(D65[40], 100.0);
    }

    #[test]
    fn interpolation_refuses_bad_tables() {
        assert_eq!(interpolate_linear(&[], &[], 500.0), None);
        assert_eq!(interpolate_linear(&[400.0, 500.0], &[1.0], 450.0), None);
        assert_eq!(
            interpolate_linear(&[400.0, 500.0], &[1.0, 2.0], f64::NAN),
            None
        );
    }

    #[test]
    fn xyz_is_linear_in_reflectance() {
        let half = reflectance_to_xyz(&[0.5; SAMPLES]);
        let one = reflectance_to_xyz(&[1.0; SAMPLES]);
        // Halving every sample halves every sum exactly (a power of two).
        assert_eq!(
            (half.x * 2.0, half.y * 2.0, half.z * 2.0),
            (one.x, one.y, one.z)
        );
    }
}
