"""Mitsuba 3's Fresnel and specular-direction laws on a grid, beside the exact values.

Regenerate (from the repository root; the output is byte-for-byte stable):

    .venv/bin/python python-checks/mitsuba_laws.py

writes ``validation/reference/mitsuba_laws.json`` (schema ``mitsuba-laws/1``,
described in ``validation/README.md``).

What Mitsuba is asked, in its ``scalar_rgb`` variant (float32 arithmetic):

- ``mi.fresnel(cos_theta_i, eta)`` -> ``(F, cos_theta_t, eta_it, eta_ti)``;
- ``mi.fresnel_polarized(cos_theta_i, eta)`` -> ``(a_s, a_p, cos_theta_t, eta_it,
  eta_ti)``, complex amplitudes (``a_p`` in Fresnel's 1823 sign convention, the
  negative of the modern one; only ``|a|^2`` is compared, which does not depend
  on it), for real ``eta`` and for a conductor's complex ``n + i kappa``;
- ``mi.fresnel_conductor(cos_theta_i, n + i kappa)`` -> ``F``;
- ``mi.reflect(wi, m)`` and ``mi.refract(wi, m, cos_theta_t, eta_ti)`` with the
  last two from ``mi.fresnel(dot(wi, m), eta)``.

Mitsuba's conventions (``include/mitsuba/render/fresnel.h``) are the suite's:
``eta`` is the interior index over the exterior one, ``cos_theta_i >= 0`` means
light from the outside, ``wi`` points away from the surface, and the refracted
direction points away on the other side. Mitsuba's ``cos_theta_t`` is signed
(opposite to ``cos_theta_i``) and 0 under total internal reflection.

Every input is a float32 value stored as the exact double, so both sides
evaluate at the same point. Beside each Mitsuba result the file holds the
exact value at that input: Fresnel terms from ``fresnel_mpmath``'s textbook
formulas, directions from the vector form of the law of reflection and of
Snell's law, both in mpmath at 50 digits, rounded once to double. Schlick's
approximation ``F0 + (1 - F0)(1 - cos)^5`` is tabulated the same way (Mitsuba
has no Python binding for it): it is the definition an implementation of the
approximation must reproduce. For the report's figures, Mitsuba's
reflectance of nine materials is also tabulated every degree (``curves``).
"""
import os
import struct
import sys

import mpmath
from mpmath import mp, mpf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fresnel_mpmath as fm  # noqa: E402

import drjit as dr  # noqa: E402
import mitsuba as mi  # noqa: E402
from atomic_write import write_json

VARIANT = "scalar_rgb"
mi.set_variant(VARIANT)
mp.dps = 50

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_PATH = os.path.join(ROOT, "validation", "reference", "mitsuba_laws.json")
REGENERATE = ".venv/bin/python python-checks/mitsuba_laws.py"


def f32(x):
    """The nearest float32 to x, as the exact Python float."""
    return struct.unpack("<f", struct.pack("<f", float(x)))[0]


def f32_step(x, k):
    """The float32 k steps from float32 x away from zero (k < 0: towards zero)."""
    return struct.unpack("<f", struct.pack("<I", struct.unpack("<I", struct.pack("<f", x))[0] + k))[0]


# Grids ----------------------------------------------------------------------
COS = [1.0, 0.99, 0.9, 0.7, 0.5, 0.3, 0.1, 1e-2, 1e-3, 1e-6]
DIELECTRICS = [("glass", 1.5), ("water", 1.333), ("diamond", 2.42), ("eta<1 (0.5)", 0.5),
               ("eta=1.0001", 1.0001), ("index-matched", 1.0)]
CONDUCTORS = [("gold R (course)", 0.17, 3.1), ("gold G (course)", 0.35, 2.7), ("gold B (course)", 1.5, 1.9),
              ("silver", 0.15, 3.6), ("copper", 0.27, 3.4), ("aluminium", 1.2, 7.0),
              ("weak absorber", 1.5, 0.01)]
SCHLICK_F0 = [0.02, 0.04, 0.1, 0.5, 0.9]
# Curves for the report's figures: Mitsuba's reflectance every degree, per material.
CURVE_DEGREES = list(range(0, 91))
CURVES = [("glass, from outside", 1.5, 0.0, 1), ("glass, from inside", 1.5, 0.0, -1),
          ("water, from outside", 1.333, 0.0, 1), ("gold R (course)", 0.17, 3.1, 1),
          ("gold G (course)", 0.35, 2.7, 1), ("gold B (course)", 1.5, 1.9, 1),
          ("silver", 0.15, 3.6, 1), ("copper", 0.27, 3.4, 1), ("aluminium", 1.2, 7.0, 1)]
SCHLICK_COS = COS + [0.0]


def dielectric_inputs():
    """[(label, cos_i, eta)]: both sides, normal to grazing, TIR, the critical and Brewster angles."""
    out = []
    for name, eta in DIELECTRICS:
        eta = f32(eta)
        for c in COS:
            out.append((f"{name} outside cos={c:g}", f32(c), eta))
            out.append((f"{name} inside cos=-{c:g}", -f32(c), eta))
        out.append((f"{name} grazing cos=0", 0.0, eta))
    glass = f32(1.5)
    crit = f32(float(-mp.sqrt(1 - 1 / mpf(glass) ** 2)))  # cos of the critical angle, inside glass
    out += [(f"glass inside critical {k:+d}ulp", f32_step(crit, k), glass) for k in (-64, -4, -1, 0, 1, 4, 64)]
    brewster = f32(float(1 / mp.sqrt(1 + mpf(glass) ** 2)))
    out += [(f"glass outside brewster {k:+d}ulp", f32_step(brewster, k), glass) for k in (-1, 0, 1)]
    return out


def conductor_inputs():
    return [(f"{name} cos={c:g}", f32(c), f32(n), f32(k))
            for name, n, k in CONDUCTORS for c in COS + [0.0]]


def unit(v):
    norm = mp.sqrt(sum(mpf(x) ** 2 for x in v))
    return [f32(float(mpf(x) / norm)) for x in v]


def direction_inputs():
    """[(label, wi, m, eta)]: axis-aligned and tilted normals, both sides, TIR."""
    normals = [("n=+z", [0.0, 0.0, 1.0]), ("n tilted", unit([0.3, -0.2, 0.9]))]
    angles_deg = [0, 10, 30, 41, 45, 60, 80, 89.9]
    out = []
    for nname, m in normals:
        # A tangent perpendicular to m, to tilt wi in a plane of incidence.
        t = unit([m[2], 0.0, -m[0]]) if abs(m[0]) + abs(m[2]) > 0 else [1.0, 0.0, 0.0]
        for deg in angles_deg:
            th = mp.radians(deg)
            for side, sname in ((1, "outside"), (-1, "inside")):
                wi = unit([side * mp.cos(th) * mpf(m[i]) + mp.sin(th) * mpf(t[i]) for i in range(3)])
                for eta in (1.5, 1.333):
                    out.append((f"{nname} {sname} {deg}deg eta={eta}", wi, m, f32(eta)))
    return out


# Mitsuba --------------------------------------------------------------------
def mitsuba_dielectric(cos_i, eta):
    F, cos_t, eta_it, eta_ti = mi.fresnel(cos_i, eta)
    a_s, a_p, cos_t_p, _, _ = mi.fresnel_polarized(cos_i, eta)
    return {"f": float(F), "cos_t": float(cos_t), "eta_it": float(eta_it), "eta_ti": float(eta_ti),
            "a_s": [float(dr.real(a_s)), float(dr.imag(a_s))],
            "a_p": [float(dr.real(a_p)), float(dr.imag(a_p))]}


def mitsuba_conductor(cos_i, n, kappa):
    eta = mi.ScalarComplex2f(n, kappa)
    a_s, a_p, _, _, _ = mi.fresnel_polarized(cos_i, eta)
    return {"f": float(mi.fresnel_conductor(cos_i, eta)),
            "a_s": [float(dr.real(a_s)), float(dr.imag(a_s))],
            "a_p": [float(dr.real(a_p)), float(dr.imag(a_p))]}


def mitsuba_directions(wi, m, eta):
    wi_v, m_n = mi.ScalarVector3f(*wi), mi.ScalarNormal3f(*m)
    _, cos_t, _, eta_ti = mi.fresnel(dr.dot(wi_v, m_n), eta)
    reflected = mi.reflect(wi_v, m_n)
    refracted = mi.refract(wi_v, m_n, cos_t, eta_ti)
    return {"reflect": [float(x) for x in reflected], "refract": [float(x) for x in refracted],
            "cos_t": float(cos_t)}


# Exact ----------------------------------------------------------------------
def exact_directions(wi, m, eta):
    """Mirror and refracted directions at the stored (float32) inputs, in mpmath."""
    wi, m, eta = [mpf(x) for x in wi], [mpf(x) for x in m], mpf(eta)
    c = sum(a * b for a, b in zip(wi, m))
    reflected = [2 * c * m[i] - wi[i] for i in range(3)]
    eta_eff, facing, c_abs = (eta, m, c) if c >= 0 else (1 / eta, [-x for x in m], -c)
    sin2_t = (1 - c_abs * c_abs) / (eta_eff * eta_eff)
    if sin2_t > 1:
        refracted = None
    else:
        cos_t = mp.sqrt(1 - sin2_t)
        refracted = [float(-wi[i] / eta_eff + (c_abs / eta_eff - cos_t) * facing[i]) for i in range(3)]
    return {"reflect": [float(x) for x in reflected], "refract": refracted}


def mitsuba_curve(n, kappa, side):
    """Mitsuba's unpolarised reflectance at every CURVE_DEGREES angle (cos_i stored as float32)."""
    cosines = [side * f32(float(mp.cos(mp.radians(d)))) for d in CURVE_DEGREES]
    if kappa == 0.0:
        values = [float(mi.fresnel(c, f32(n))[0]) for c in cosines]
    else:
        values = [float(mi.fresnel_conductor(c, mi.ScalarComplex2f(f32(n), f32(kappa)))) for c in cosines]
    return cosines, values


def exact_schlick(cos_i, f0):
    return float(fm.schlick(cos_i, f0))


# Document -------------------------------------------------------------------
def build_reference():
    dielectric = []
    for label, cos_i, eta in dielectric_inputs():
        with mp.workdps(fm.working_dps(cos_i) if cos_i != 0 else fm.DPS):
            d = fm.dielectric(cos_i, eta)
            exact = {"r_s": float(d["r_s"]), "r_p": float(d["r_p"]), "r": float(d["r"]), "tir": d["tir"]}
        dielectric.append({"label": label, "cos_i": cos_i, "eta": eta,
                           "mitsuba": mitsuba_dielectric(cos_i, eta), "exact": exact})
    conductor = []
    for label, cos_i, n, kappa in conductor_inputs():
        with mp.workdps(fm.DPS):
            r_s, r_p, r = fm.conductor(cos_i, n, kappa)
        conductor.append({"label": label, "cos_i": cos_i, "n": n, "kappa": kappa,
                          "mitsuba": mitsuba_conductor(cos_i, n, kappa),
                          "exact": {"r_s": float(r_s), "r_p": float(r_p), "r": float(r)}})
    directions = [{"label": label, "wi": wi, "n": m, "eta": eta,
                   "mitsuba": mitsuba_directions(wi, m, eta), "exact": exact_directions(wi, m, eta)}
                  for label, wi, m, eta in direction_inputs()]
    schlick = [{"label": f"F0={f0:g} cos={c:g}", "cos_i": f32(c), "f0": f32(f0),
                "exact": exact_schlick(f32(c), f32(f0))}
               for f0 in SCHLICK_F0 for c in SCHLICK_COS]
    curves = []
    for label, n, kappa, side in CURVES:
        cosines, values = mitsuba_curve(n, kappa, side)
        curves.append({"label": label, "n": f32(n), "kappa": f32(kappa), "cos_i": cosines, "mitsuba_f": values})
    doc = {"schema": "mitsuba-laws/1",
           "description": "Mitsuba 3's fresnel, fresnel_polarized, fresnel_conductor, reflect and refract "
                          "(float32) at float32 inputs, beside the exact values at the same inputs (mpmath); "
                          "Schlick's approximation tabulated exactly.",
           "generator": "python-checks/mitsuba_laws.py",
           "regenerate": REGENERATE,
           "mitsuba_version": mi.__version__, "mitsuba_variant": VARIANT,
           "drjit_version": dr.__version__, "mpmath_version": mpmath.__version__,
           "conventions": "eta = n_inside / n_outside; cos_i > 0: light from outside; directions point away "
                          "from the surface; a_p in Fresnel's 1823 sign convention (only |a|^2 is meaningful here)",
           "dielectric": dielectric, "conductor": conductor, "directions": directions, "schlick": schlick,
           "curves": curves}
    for kind in ("dielectric", "conductor", "directions", "schlick"):
        labels = [c["label"] for c in doc[kind]]
        assert len(set(labels)) == len(labels), f"duplicate labels in {kind}"
    return doc


def main(path=DEFAULT_PATH):
    write_json(path, build_reference())


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else DEFAULT_PATH)
