"""Measured spectral n, kappa of four metals (from Mitsuba 3) and their colours (colour-science).

Regenerate (from the repository root; the output is stable up to the last bits
of BLAS rounding, see ``reproduce.py``):

    .venv/bin/python python-checks/metals.py

writes ``validation/reference/metals.json`` (schema ``metals/1``):

- for gold, silver, copper and aluminium, the complex index ``n + i kappa`` as
  Mitsuba ships it in ``data/ior/<symbol>.eta.spd`` and ``<symbol>.k.spd``
  (luxpop.com tabulation; wavelengths in nm), read from the installed mitsuba
  package, unchanged;
- for each metal and angle of incidence, the exact unpolarised reflectance
  spectrum on the CIE grid (360-780 nm, 5 nm; n and kappa interpolated linearly
  between tabulated wavelengths, the conductor Fresnel law from
  ``fresnel_mpmath``), and colour-science's XYZ, linear sRGB and Lab of it
  under D65 (the conventions of ``colorimetry.py``).

The Rust side recomputes these colours with its own colorimetry and its own
Fresnel law, and measures the colour error of the shortcuts against them.
"""
import os
import sys

import numpy as np
from mpmath import mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import colorimetry
from atomic_write import write_json  # noqa: E402
import fresnel_mpmath as fm  # noqa: E402

import mitsuba  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_PATH = os.path.join(ROOT, "validation", "reference", "metals.json")
REGENERATE = ".venv/bin/python python-checks/metals.py"
IOR_DIR = os.path.join(os.path.dirname(mitsuba.__file__), "data", "ior")
METALS = [("gold", "Au"), ("silver", "Ag"), ("copper", "Cu"), ("aluminium", "Al")]
ANGLES_DEG = [0, 45, 60, 75, 85]


def read_spd(path):
    """[(wavelength_nm, value)] from a Mitsuba .spd file ('#' comments, two columns)."""
    rows = []
    with open(path, encoding="utf-8") as fh:
        for line in fh:
            line = line.split("#", 1)[0].strip()
            if line:
                w, v = line.split()
                rows.append((float(w), float(v)))
    return rows


def read_metal(symbol):
    eta, k = read_spd(os.path.join(IOR_DIR, f"{symbol}.eta.spd")), read_spd(os.path.join(IOR_DIR, f"{symbol}.k.spd"))
    assert [w for w, _ in eta] == [w for w, _ in k], f"{symbol}: n and kappa tabulated at different wavelengths"
    return [w for w, _ in eta], [v for _, v in eta], [v for _, v in k]


def reflectance_spectrum(wavelengths, n, k, cos_i):
    """Exact unpolarised conductor reflectance on the CIE grid."""
    grid = colorimetry.WAVELENGTHS
    n_grid, k_grid = np.interp(grid, wavelengths, n), np.interp(grid, wavelengths, k)
    with mp.workdps(fm.DPS):
        return [float(fm.conductor(cos_i, a, b)[2]) for a, b in zip(n_grid, k_grid)]


def build_reference():
    metals = []
    for name, symbol in METALS:
        wavelengths, n, k = read_metal(symbol)
        assert wavelengths[0] <= colorimetry.START_NM and wavelengths[-1] >= colorimetry.END_NM
        angles = []
        for deg in ANGLES_DEG:
            cos_i = float(mp.cos(mp.radians(deg)))
            r = reflectance_spectrum(wavelengths, n, k, cos_i)
            angles.append({"angle_deg": deg, "cos_i": cos_i, "reflectance": r, **colorimetry.colour_of(np.array(r))})
        metals.append({"name": name, "mitsuba_file": f"data/ior/{symbol}.eta.spd, {symbol}.k.spd",
                       "wavelengths_nm": wavelengths, "n": n, "kappa": k, "angles": angles})
    return {"schema": "metals/1",
            "description": "Measured complex indices of gold, silver, copper and aluminium as shipped with "
                           "Mitsuba 3, and colour-science's colour of their exact reflectance spectra.",
            "generator": "python-checks/metals.py", "regenerate": REGENERATE,
            "mitsuba_version": mitsuba.__version__, "colour_science_version": colorimetry.colour.__version__,
            "interpolation": "linear in wavelength between tabulated samples",
            "metals": metals}


def main(path=DEFAULT_PATH):
    write_json(path, build_reference())


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else DEFAULT_PATH)
