//! Compton scattering: the wavelength shift of a photon scattered by a free
//! electron at rest, in metres.
//!
//! Δλ = (h / (m_e c)) (1 − cos θ), with θ the scattering angle (A. H.
//! Compton, "A quantum theory of the scattering of X-rays by light
//! elements", Phys. Rev. 21, 483, 1923). The shift does not depend on the
//! photon's wavelength, so it matters for X-rays and gamma rays and is negligible
//! for visible light — the reason a renderer may treat scattering by
//! electrons as elastic.
//!
//! ```
//! use radiometry::photon::{compton_shift_m, COMPTON_WAVELENGTH_M};
//!
//! // Back-scattering (θ = π) shifts by twice the Compton wavelength, 4.85 pm,
//! // about 1.3e-5 of the shortest visible wavelength, 380 nm.
//! let back = compton_shift_m(std::f64::consts::PI);
//! assert!((back - 2.0 * COMPTON_WAVELENGTH_M).abs() < 1e-27);
//! assert!((back * 1e12 - 4.852).abs() < 1e-3);
//! assert!(back / 380e-9 < 1.3e-5);
//! // Forward scattering does not shift at all.
//! assert_eq!(compton_shift_m(0.0), 0.0);
//! ```

/// The Planck constant, J s: exact since the SI of 2019.
pub const PLANCK_J_S: f64 = 6.626_070_15e-34;

/// The electron's rest mass, kg (CODATA 2018).
pub const ELECTRON_MASS_KG: f64 = 9.109_383_701_5e-31;

/// The speed of light in vacuum, m/s: exact by the definition of the metre.
pub const LIGHT_SPEED_M_S: f64 = 299_792_458.0;

/// The electron's Compton wavelength h / (m_e c), m (2.426 pm; CODATA 2018
/// gives 2.426 310 238 67e-12 m).
pub const COMPTON_WAVELENGTH_M: f64 = PLANCK_J_S / (ELECTRON_MASS_KG * LIGHT_SPEED_M_S);

/// The increase of a photon's wavelength, in metres, when a free electron at
/// rest scatters it through `theta` radians (0: forward, π: back).
///
/// Never negative for a real angle; NaN for a NaN angle (crate conventions).
/// The largest shift, at `theta = π`, is `2 h / (m_e c)`.
pub fn compton_shift_m(theta: f64) -> f64 {
    COMPTON_WAVELENGTH_M * (1.0 - theta.cos())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compton_wavelength_matches_codata() {
        // CODATA 2018: 2.426 310 238 67(73)e-12 m; the constants above give
        // it to their own ten digits (relative 1e-10).
        let codata = 2.426_310_238_67e-12;
        assert!((COMPTON_WAVELENGTH_M / codata - 1.0).abs() < 1e-10);
    }

    #[test]
    fn compton_shift_grows_from_forward_to_back_scattering() {
        // At 90° the shift is one Compton wavelength (cos 90° rounds to
        // 6e-17, a relative 1e-16 of it).
        let right = compton_shift_m(std::f64::consts::FRAC_PI_2);
        assert!((right / COMPTON_WAVELENGTH_M - 1.0).abs() < 1e-15);
        let angles = [0.0, 0.5, 1.0, 2.0, 3.0, std::f64::consts::PI];
        for pair in angles.windows(2) {
            assert!(compton_shift_m(pair[0]) < compton_shift_m(pair[1]));
        }
        assert!(compton_shift_m(f64::NAN).is_nan());
    }
}
