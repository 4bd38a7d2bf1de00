//! Chromatic dispersion: the refractive index of a glass as a function of
//! wavelength (nanometres), by the Sellmeier equation, and the slides'
//! per-channel "three eta" trick beside it; the prism in [`prism`].
//!
//! The slides (`001`, "Fénytörés mértéke függ még a bejövő fény
//! hullámhosszától", lines 473–477, and `C7E5v_dispersion`) refract each of
//! R, G and B with its own `etaRatio`, a `uniform float3` whose values they
//! do not give. In the Cg `refract(I, N, etaRatio)` that ratio is
//! `n₁/n₂`, the index the light leaves over the index it enters: entering
//! glass from air, `1/n(λ)`. [`eta_ratios`] gives the three ratios
//! [`SELLMEIER_N_BK7`] implies at the wavelengths chosen to stand for the
//! channels ([`CIE_RGB_PRIMARIES_NM`]).
//!
//! The slides' "red light bends more than blue" (line 474) is an erratum:
//! glass and water disperse normally in the visible, their index falling
//! with wavelength, so blue bends more (`docs/errata.md`).

pub mod prism;

/// The Sellmeier equation with three terms,
/// `n²(λ) = 1 + Σ Bᵢ λ² / (λ² − Cᵢ)`, `λ` in micrometres, `Cᵢ` in µm².
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sellmeier {
    /// The oscillator strengths `B₁, B₂, B₃` (unitless).
    pub b: [f64; 3],
    /// The squared resonance wavelengths `C₁, C₂, C₃`, in µm².
    pub c_um2: [f64; 3],
    /// The wavelengths (nm) the coefficients were fitted over, both ends
    /// included: outside them the formula is an extrapolation.
    pub valid_nm: (f64, f64),
}

/// Schott N-BK7, the coefficients of Schott's optical glass data sheet
/// (SCHOTT AG, *Optical Glass Data Sheets*, N-BK7, glass code 517642.251),
/// fitted there to indices measured from the near ultraviolet to the near
/// infrared. Answered here from 300 to 2500 nm (the visible with wide
/// margins); nothing beyond is extrapolated.
pub const SELLMEIER_N_BK7: Sellmeier = Sellmeier {
    b: [1.039_612_12, 0.231_792_344, 1.010_469_45],
    c_um2: [0.006_000_698_67, 0.020_017_914_4, 103.560_653],
    valid_nm: (300.0, 2500.0),
};

impl Sellmeier {
    /// The refractive index at `wavelength_nm` (vacuum wavelength,
    /// nanometres); `None` outside [`Sellmeier::valid_nm`] (and for NaN).
    ///
    /// ```
    /// use techniques::dispersion::{fraunhofer_nm, SELLMEIER_N_BK7};
    /// // Schott's data sheet: n_F = 1.52238 for N-BK7.
    /// let n_f = SELLMEIER_N_BK7.index_at(fraunhofer_nm::F).unwrap();
    /// assert!((n_f - 1.52238).abs() < 5e-6);
    /// assert_eq!(SELLMEIER_N_BK7.index_at(3000.0), None);
    /// ```
    pub fn index_at(&self, wavelength_nm: f64) -> Option<f64> {
        let (shortest, longest) = self.valid_nm;
        if !(shortest..=longest).contains(&wavelength_nm) {
            return None;
        }
        let lambda_um = wavelength_nm / 1000.0;
        let lambda2 = lambda_um * lambda_um;
        let n2 = 1.0
            + self
                .b
                .iter()
                .zip(self.c_um2)
                .map(|(b, c)| b * lambda2 / (lambda2 - c))
                .sum::<f64>();
        Some(n2.sqrt())
    }
}

/// The Fraunhofer lines the data sheets quote indices at, vacuum
/// wavelengths in nm: d (helium), F and C (hydrogen), e (mercury).
pub mod fraunhofer_nm {
    /// The helium d line, 587.5618 nm.
    pub const D: f64 = 587.5618;
    /// The hydrogen F line, 486.1327 nm.
    pub const F: f64 = 486.1327;
    /// The hydrogen C line, 656.2725 nm.
    pub const C: f64 = 656.2725;
    /// The mercury e line, 546.0740 nm.
    pub const E: f64 = 546.0740;
}

/// The Abbe number `ν_d = (n_d − 1) / (n_F − n_C)`: how little the glass
/// disperses (larger is less).
pub fn abbe_number(glass: &Sellmeier) -> Option<f64> {
    let index = |nm| glass.index_at(nm);
    let (d, f, c) = (
        index(fraunhofer_nm::D)?,
        index(fraunhofer_nm::F)?,
        index(fraunhofer_nm::C)?,
    );
    Some((d - 1.0) / (f - c))
}

/// The wavelengths (nm) chosen here to stand for the R, G and B channels:
/// the CIE 1931 RGB primaries, 700, 546.1 and 435.8 nm, the monochromatic
/// lights the colour-matching functions were measured with. (A channel of
/// a display is a band, not a line; any such choice is a convention.)
pub const CIE_RGB_PRIMARIES_NM: [f64; 3] = [700.0, 546.1, 435.8];

/// The per-channel `etaRatio` of the slides' Cg program for light entering
/// `glass` from air (index 1): `1 / n(λ)` at each of `wavelengths_nm`.
pub fn eta_ratios(glass: &Sellmeier, wavelengths_nm: [f64; 3]) -> Option<[f64; 3]> {
    let mut ratios = [0.0; 3];
    for (ratio, nm) in ratios.iter_mut().zip(wavelengths_nm) {
        *ratio = 1.0 / glass.index_at(nm)?;
    }
    Some(ratios)
}

#[cfg(test)]
mod tests;
