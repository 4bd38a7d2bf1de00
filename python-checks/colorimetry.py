"""CIE 1931 colorimetry tables and colour-science reference values.

Regenerate (from the repository root; the Rust tables are byte-for-byte stable,
the JSON up to the last bits of BLAS rounding, see ``reproduce.py``):

    .venv/bin/python python-checks/colorimetry.py

writes

- ``crates/radiometry/src/cie_tables.rs``: the CIE 1931 2-degree colour-matching
  functions and the CIE D65 relative spectral power, 360-780 nm every 5 nm, as
  Rust constants (the radiometry crate stays free of I/O and of a JSON parser);
- ``validation/reference/colorimetry.json`` (schema ``colorimetry/1``): the same
  tables, and what colour-science computes from them: XYZ, linear sRGB, sRGB and
  CIELAB of test reflectance spectra under D65, and CIEDE2000 of the Sharma,
  Wu & Dalal (2005) test pairs.

The tables are colour-science's ``MSDS_CMFS['CIE 1931 2 Degree Standard
Observer']`` and ``SDS_ILLUMINANTS['D65']`` read at their own tabulated
wavelengths (no interpolation). 360-780 nm at 5 nm is where both are tabulated;
the colour-matching functions beyond 780 nm are below 1.5e-4 of their peak.

Conventions of the reference values: ``sd_to_XYZ(method="Integration")`` with
D65, scaled so that a perfect reflector has Y = 1 (colour-science's Y = 100,
divided by 100); sRGB is IEC 61966-2-1 (colour-science's ``XYZ_to_sRGB``, whose
matrix is the standard's four-decimal one); CIELAB is relative to the D65
white point of chromaticity (0.3127, 0.3290), Y = 1.
"""
import os
import sys

import numpy as np
import colour
from atomic_write import write_json, write_text

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_JSON = os.path.join(ROOT, "validation", "reference", "colorimetry.json")
DEFAULT_RUST = os.path.join(ROOT, "crates", "radiometry", "src", "cie_tables.rs")
REGENERATE = ".venv/bin/python python-checks/colorimetry.py"

START_NM, STEP_NM, END_NM = 360, 5, 780
WAVELENGTHS = np.arange(START_NM, END_NM + 1, STEP_NM, dtype=float)
D65_XY = colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["D65"]

# CIEDE2000 test data: G. Sharma, W. Wu, E. N. Dalal, "The CIEDE2000
# color-difference formula: implementation notes, supplementary test data, and
# mathematical observations", Color Research & Application 30(1), 2005, Table 1:
# (L1, a1, b1, L2, a2, b2, Delta E00 as printed, four decimals).
SHARMA_2005 = [
    (50.0000, 2.6772, -79.7751, 50.0000, 0.0000, -82.7485, 2.0425),
    (50.0000, 3.1571, -77.2803, 50.0000, 0.0000, -82.7485, 2.8615),
    (50.0000, 2.8361, -74.0200, 50.0000, 0.0000, -82.7485, 3.4412),
    (50.0000, -1.3802, -84.2814, 50.0000, 0.0000, -82.7485, 1.0000),
    (50.0000, -1.1848, -84.8006, 50.0000, 0.0000, -82.7485, 1.0000),
    (50.0000, -0.9009, -85.5211, 50.0000, 0.0000, -82.7485, 1.0000),
    (50.0000, 0.0000, 0.0000, 50.0000, -1.0000, 2.0000, 2.3669),
    (50.0000, -1.0000, 2.0000, 50.0000, 0.0000, 0.0000, 2.3669),
    (50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0009, 7.1792),
    (50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0010, 7.1792),
    (50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0011, 7.2195),
    (50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0012, 7.2195),
    (50.0000, -0.0010, 2.4900, 50.0000, 0.0009, -2.4900, 4.8045),
    (50.0000, -0.0010, 2.4900, 50.0000, 0.0010, -2.4900, 4.8045),
    (50.0000, -0.0010, 2.4900, 50.0000, 0.0011, -2.4900, 4.7461),
    (50.0000, 2.5000, 0.0000, 50.0000, 0.0000, -2.5000, 4.3065),
    (50.0000, 2.5000, 0.0000, 73.0000, 25.0000, -18.0000, 27.1492),
    (50.0000, 2.5000, 0.0000, 61.0000, -5.0000, 29.0000, 22.8977),
    (50.0000, 2.5000, 0.0000, 56.0000, -27.0000, -3.0000, 31.9030),
    (50.0000, 2.5000, 0.0000, 58.0000, 24.0000, 15.0000, 19.4535),
    (50.0000, 2.5000, 0.0000, 50.0000, 3.1736, 0.5854, 1.0000),
    (50.0000, 2.5000, 0.0000, 50.0000, 3.2972, 0.0000, 1.0000),
    (50.0000, 2.5000, 0.0000, 50.0000, 1.8634, 0.5757, 1.0000),
    (50.0000, 2.5000, 0.0000, 50.0000, 3.2592, 0.3350, 1.0000),
    (60.2574, -34.0099, 36.2677, 60.4626, -34.1751, 39.4387, 1.2644),
    (63.0109, -31.0961, -5.8663, 62.8187, -29.7946, -4.0864, 1.2630),
    (61.2901, 3.7196, -5.3901, 61.4292, 2.2480, -4.9620, 1.8731),
    (35.0831, -44.1164, 3.7933, 35.0232, -40.0716, 1.5901, 1.8645),
    (22.7233, 20.0904, -46.6940, 23.0331, 14.9730, -42.5619, 2.0373),
    (36.4612, 47.8580, 18.3852, 36.2715, 50.5065, 21.2231, 1.4146),
    (90.8027, -2.0831, 1.4410, 91.1528, -1.6435, 0.0447, 1.4441),
    (90.9257, -0.5406, -0.9208, 88.6381, -0.8985, -0.7239, 1.5381),
    (6.7747, -0.2908, -2.4247, 5.8714, -0.0985, -2.2286, 0.6377),
    (2.0776, 0.0795, -1.1350, 0.9033, -0.0636, -0.5514, 0.9082),
]


def tables():
    """(cmf [85 x 3], d65 [85]) at WAVELENGTHS, read at tabulated wavelengths."""
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"]
    d65 = colour.SDS_ILLUMINANTS["D65"]
    assert set(WAVELENGTHS) <= set(cmfs.wavelengths) and set(WAVELENGTHS) <= set(d65.wavelengths)
    return np.asarray(cmfs[WAVELENGTHS]), np.asarray(d65[WAVELENGTHS])


def colour_of(reflectance):
    """colour-science's XYZ (Y = 1 white), linear sRGB, sRGB and Lab of a reflectance on WAVELENGTHS."""
    cmf, d65 = tables()
    shape = colour.SpectralShape(START_NM, END_NM, STEP_NM)
    cmfs = colour.MultiSpectralDistributions(dict(zip(WAVELENGTHS, cmf)), name="CIE 1931 2 deg")
    illuminant = colour.SpectralDistribution(dict(zip(WAVELENGTHS, d65)), name="D65")
    sd = colour.SpectralDistribution(dict(zip(WAVELENGTHS, reflectance)), name="sample")
    assert sd.shape == shape
    XYZ = colour.sd_to_XYZ(sd, cmfs, illuminant, method="Integration") / 100
    linear = colour.XYZ_to_sRGB(XYZ, apply_cctf_encoding=False)
    encoded = colour.cctf_encoding(np.clip(linear, 0, 1), function="sRGB")
    lab = colour.XYZ_to_Lab(XYZ, illuminant=D65_XY)
    return {"xyz": XYZ.tolist(), "linear_srgb": linear.tolist(), "srgb": encoded.tolist(), "lab": lab.tolist()}


def test_spectra():
    """[(label, reflectance on WAVELENGTHS)]: flat, smooth and the 24 ColorChecker patches."""
    w = WAVELENGTHS
    out = [("perfect white", np.ones_like(w)), ("flat 18 %", np.full_like(w, 0.18)),
           ("linear ramp", (w - START_NM) / (END_NM - START_NM)),
           ("gaussian at 550 nm", np.exp(-0.5 * ((w - 550) / 30) ** 2))]
    # The Ohta ColorChecker spectra start at 380 nm; 360-375 nm repeat the first
    # sample (colour-science's constant extrapolation), and the filled values are stored.
    for name, sd in colour.SDS_COLOURCHECKERS["ColorChecker N Ohta"].items():
        values = [sd[max(x, sd.shape.start)] for x in w]
        out.append((f"ColorChecker {name}", np.asarray(values, dtype=float)))
    return out


def build_reference():
    cmf, d65 = tables()
    spectra = [{"label": label, "reflectance": r.tolist(), **colour_of(r)} for label, r in test_spectra()]
    pairs = []
    for i, (L1, a1, b1, L2, a2, b2, printed) in enumerate(SHARMA_2005, start=1):
        de = float(colour.delta_E(np.array([L1, a1, b1]), np.array([L2, a2, b2]), method="CIE 2000"))
        pairs.append({"label": f"Sharma 2005 pair {i}", "lab1": [L1, a1, b1], "lab2": [L2, a2, b2],
                      "delta_e_2000": de, "printed": printed})
    return {"schema": "colorimetry/1",
            "description": "CIE 1931 2-degree colour-matching functions and D65 (360-780 nm, 5 nm), and "
                           "colour-science's colorimetry of test spectra and CIEDE2000 of the Sharma et al. "
                           "(2005) pairs.",
            "generator": "python-checks/colorimetry.py", "regenerate": REGENERATE,
            "colour_science_version": colour.__version__,
            "conventions": "XYZ with Y = 1 for a perfect reflector under D65 (Integration method); sRGB per "
                           "IEC 61966-2-1; Lab relative to the D65 white of chromaticity (0.3127, 0.3290)",
            "wavelengths_nm": {"start": START_NM, "step": STEP_NM, "count": len(WAVELENGTHS)},
            "cmf_xyz": cmf.tolist(), "d65": d65.tolist(), "d65_white_xy": list(map(float, D65_XY)),
            "spectra": spectra, "delta_e_2000": pairs}


def rust_tables():
    cmf, d65 = tables()
    rows = "\n".join(f"    [{x!r}, {y!r}, {z!r}]," for x, y, z in cmf.tolist())
    d65_rows = "\n".join(f"    {v!r}," for v in d65.tolist())
    n = len(WAVELENGTHS)
    return f"""//! The CIE 1931 2° standard observer and illuminant D65, {START_NM}–{END_NM} nm every {STEP_NM} nm.
//!
//! Generated by `python-checks/colorimetry.py` from colour-science {colour.__version__}
//! (`MSDS_CMFS["CIE 1931 2 Degree Standard Observer"]`, `SDS_ILLUMINANTS["D65"]`,
//! read at their tabulated wavelengths); regenerate with
//! `{REGENERATE}`. Do not edit.

/// The first wavelength, in nanometres.
pub const START_NM: f64 = {START_NM:.1f};
/// The spacing of the samples, in nanometres.
pub const STEP_NM: f64 = {STEP_NM:.1f};
/// The number of samples.
pub const SAMPLES: usize = {n};

/// The colour-matching functions `[x̄, ȳ, z̄]` at each wavelength.
pub const CMF_XYZ: [[f64; 3]; SAMPLES] = [
{rows}
];

/// The relative spectral power of D65 at each wavelength (100 at 560 nm).
pub const D65: [f64; SAMPLES] = [
{d65_rows}
];
"""


def main(json_path=DEFAULT_JSON, rust_path=DEFAULT_RUST):
    write_json(json_path, build_reference())
    write_text(rust_path, rust_tables())


if __name__ == "__main__":
    main(*sys.argv[1:3])
