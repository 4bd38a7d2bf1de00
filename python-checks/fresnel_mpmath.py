"""Exact Fresnel reflectance references computed with mpmath.

Regenerate (from the repository root; the output is byte-for-byte stable):

    python3 python-checks/fresnel_mpmath.py

writes ``validation/reference/fresnel_mpmath.json``.

The formulas are the plain textbook ones, deliberately independent of the
reformulated Rust implementation. Everything is evaluated at ``mp.dps = 90``
(more at grazing incidence, see ``working_dps``: there T = 1 - R ~ |cos_i|)
so that cancellation (near the critical angle, near eta = 1, in T) costs
nothing; values are stored to 50 significant digits.

Dielectric, ``eta = n_inside / n_outside``, signed ``cos_i`` (> 0: light from
outside, eta_eff = eta; < 0: light from inside, eta_eff = 1 / eta), c = |cos_i|:

    sin2_t = (1 - c^2) / eta_eff^2          TIR if sin2_t > 1: R_s = R_p = 1, T = 0
    cos_t  = sqrt(1 - sin2_t)
    r_s = (c - eta_eff cos_t) / (c + eta_eff cos_t)     R_s = r_s^2
    r_p = (eta_eff c - cos_t) / (eta_eff c + cos_t)     R_p = r_p^2
    R = (R_s + R_p) / 2,  T = 1 - R  (exact subtraction, so R + T == 1 exactly)

and eta == 1 exactly is index matched: R = 0, T = 1 at every angle.

Conductor, complex index eta = n + i kappa, light from outside, c = |cos_i|:
the same r_s, r_p with cos_t = sqrt(1 - (1 - c^2) / eta^2) (principal branch),
R_s = |r_s|^2, R_p = |r_p|^2 (as |numerator|^2 / |denominator|^2), R = mean;
n = 1, kappa = 0 gives 0.

Inputs are exactly representable in their tier ("f64": Python floats; "f32":
float32 values stored as the exact Python float) and the reference is computed
at the stored value. The keys r_s, r_p, r, t hold the power quantities R_s,
R_p, R, T, each as [hi, lo] (hi = nearest double, lo = nearest double of
q - hi); R and T also as 50-digit strings (r_digits, t_digits).
The relative condition number is cond = sum_x |x dq/dx / q| over the inputs
(cos_i, eta) or (cos_i, n, kappa), by central differences (mpmath.diff) with
step |x| * 2^-120, which never straddles the critical angle (checked). It is
0.0 where q == 0 or under TIR; at eta == 1 exactly R has a double zero in eta
and is identically 0 in cos_i, so cond_t = 0.0 there too (at cos_i = 0 that
limit is discontinuous; 0.0 is stored by the same convention).
"""
import math
import os
import struct
import sys

import mpmath
from mpmath import mp, mpc, mpf
from atomic_write import write_json

DPS = 90
DIGITS = 50
STEP = mpf(2) ** -120
mp.dps = DPS

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_PATH = os.path.join(ROOT, "validation", "reference", "fresnel_mpmath.json")


def dielectric(cos_i, eta):
    """Textbook dielectric Fresnel terms at the current precision (a dict)."""
    cos_i, eta = mpf(cos_i), mpf(eta)
    if eta == 1:
        return {"r_s": mpf(0), "r_p": mpf(0), "r": mpf(0), "t": mpf(1), "tir": False}
    eta_eff = eta if cos_i >= 0 else 1 / eta
    c = abs(cos_i)
    sin2_t = (1 - c * c) / (eta_eff * eta_eff)
    if sin2_t > 1:
        return {"r_s": mpf(1), "r_p": mpf(1), "r": mpf(1), "t": mpf(0), "tir": True}
    cos_t = mp.sqrt(1 - sin2_t)
    r_s = (c - eta_eff * cos_t) / (c + eta_eff * cos_t)
    r_p = (eta_eff * c - cos_t) / (eta_eff * c + cos_t)
    R_s, R_p = r_s * r_s, r_p * r_p
    R = (R_s + R_p) / 2
    return {"r_s": R_s, "r_p": R_p, "r": R, "t": mp.fsub(1, R, exact=True), "tir": False}


def conductor(cos_i, n, kappa):
    """Textbook conductor Fresnel reflectances (R_s, R_p, R), light from outside."""
    c, n, kappa = abs(mpf(cos_i)), mpf(n), mpf(kappa)
    if n == 1 and kappa == 0:
        return mpf(0), mpf(0), mpf(0)
    eta = mpc(n, kappa)
    cos_t = mp.sqrt(1 - (1 - c * c) / (eta * eta))
    abs2 = lambda z: z.real ** 2 + z.imag ** 2  # |z|^2 without a square root
    # |r|^2 = |num|^2 / |den|^2: exactly 1 under TIR (kappa = 0, n < 1), where num = conj(den)
    R_s = abs2(c - eta * cos_t) / abs2(c + eta * cos_t)
    R_p = abs2(eta * c - cos_t) / abs2(eta * c + cos_t)
    return R_s, R_p, (R_s + R_p) / 2


def schlick(cos_i, f0):
    """Schlick's approximation as defined, F0 + (1 - F0)(1 - cos_i)^5, exactly."""
    cos_i, f0 = mpf(cos_i), mpf(f0)
    return f0 + (1 - f0) * (1 - cos_i) ** 5


def conductor_tir(cos_i, n, kappa):
    """Total internal reflection in the conductor law: kappa = 0, n < 1, beyond the
    critical angle (1 - c^2 > n^2). There R_s = R_p = R = 1 exactly."""
    c, n = abs(mpf(cos_i)), mpf(n)
    return kappa == 0 and 1 - c * c > n * n


def _log_sensitivities(f, args, regime=None):
    """|x_i * df/dx_i| for each input (0 where x_i == 0), by central differences.

    ``regime(*args)`` (optional) must not change across x_i +- h: this guards
    against a difference quotient straddling the critical angle."""
    out = []
    for i, x in enumerate(map(mpf, args)):
        if x == 0:
            out.append(mpf(0))
            continue
        h = abs(x) * STEP

        def at(t, i=i):
            return [mpf(a) for a in args[:i]] + [t] + [mpf(a) for a in args[i + 1:]]

        if regime is not None and len({regime(*at(x + k * h)) for k in (-1, 0, 1)}) != 1:
            raise ArithmeticError(f"difference straddles a regime change at {args!r}")
        out.append(abs(x * mp.diff(lambda t: f(*at(t)), x, h=h)))
    return out


def working_dps(cos_i):
    """DPS, plus ~log10(1/|cos_i|) digits: at grazing incidence T = 1 - R ~ |cos_i|
    cancels, and so does the difference quotient of R in cos_i."""
    return DPS + max(0, -math.frexp(cos_i)[1]) // 3  # 2^3 < 10: at least log10(1/c)


def _cond(sens, q):
    return 0.0 if q == 0 else float(mp.fsum(sens) / abs(q))


def _pair(x):
    hi = float(x)
    return [hi, float(x - hi)]


def dielectric_case(label, cos_i, eta):
    with mp.workdps(working_dps(cos_i)):
        d = dielectric(cos_i, eta)
        sens = [] if eta == 1 else _log_sensitivities(  # eta == 1: both conds 0 (docstring)
            lambda c, e: dielectric(c, e)["r"], (cos_i, eta), regime=lambda c, e: dielectric(c, e)["tir"])
        return {"label": label, "cos_i": cos_i, "eta": eta, "tir": d["tir"],
                "r_s": _pair(d["r_s"]), "r_p": _pair(d["r_p"]), "r": _pair(d["r"]), "t": _pair(d["t"]),
                "r_digits": mp.nstr(d["r"], DIGITS), "t_digits": mp.nstr(d["t"], DIGITS),
                "cond_r": _cond(sens, d["r"]), "cond_t": _cond(sens, d["t"])}


def conductor_case(label, cos_i, n, kappa):
    with mp.workdps(working_dps(cos_i)):
        R_s, R_p, R = conductor(cos_i, n, kappa)
        sens = _log_sensitivities(  # R == 0 (index matched): cond 0, the guard is moot there
            lambda c, a, b: conductor(c, a, b)[2], (cos_i, n, kappa), regime=None if R == 0 else conductor_tir)
        return {"label": label, "cos_i": cos_i, "n": n, "kappa": kappa,
                "r_s": _pair(R_s), "r_p": _pair(R_p), "r": _pair(R),
                "r_digits": mp.nstr(R, DIGITS), "cond_r": _cond(sens, R)}


# Input grids ---------------------------------------------------------------
def f32(x):
    """Round a double to the nearest float32, returned as the exact Python float."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def f32_step(x, k):
    """The float32 k steps from float32 x away from zero (k < 0: towards zero)."""
    return struct.unpack("<f", struct.pack("<I", struct.unpack("<I", struct.pack("<f", x))[0] + k))[0]


COS = [("1", 1.0), ("0.9999999", 0.9999999), ("0.99", 0.99), ("0.9", 0.9), ("0.7", 0.7),
       ("0.5", 0.5), ("0.3", 0.3), ("0.1", 0.1), ("1e-3", 1e-3), ("1e-8", 1e-8)]
TINY_COS = {"f64": [("1e-300", 1e-300)], "f32": [("1e-38", 1e-38), ("2^-149", 2.0 ** -149)]}
DIELECTRICS = [("glass", 1.5), ("water", 1.333), ("diamond", 2.42), ("index-matched", 1.0)]
NEAR_ONE = {"f64": [("eta=1+1e-12", 1 + 1e-12), ("eta=1-1e-12", 1 - 1e-12)],
            "f32": [("eta=1+2^-23", 1 + 2.0 ** -23), ("eta=1-2^-24", 1 - 2.0 ** -24)]}
OTHER = [("eta=1e-3", 1e-3), ("eta=1e3", 1e3), ("eta=1.0001", 1.0001)]
CONDUCTORS = [("gold R", 0.17, 3.1), ("gold G", 0.35, 2.7), ("gold B", 1.5, 1.9),
              ("aluminium", 1.2, 7.0), ("silver", 0.15, 3.6), ("copper", 0.27, 3.4),
              ("kappa=1e3 n=1", 1.0, 1e3), ("n=1e-3 kappa=1", 1e-3, 1.0),
              ("dielectric via conductor n=1.5", 1.5, 0.0),
              ("dielectric below 1 via conductor n=0.5", 0.5, 0.0),
              ("index matched via conductor", 1.0, 0.0)]
TINY_KAPPA = {"f64": ("tiny absorption kappa=1e-12", 1.5, 1e-12),
              "f32": ("tiny absorption kappa=1e-7", 1.5, 1e-7)}
# Where the f64 laws' roundings add up the most: no sum cancels there, but R_p is the square of a
# ratio of a product and a sum of several rounded terms, so about ten roundings of order one,
# doubled. Found by evaluating the laws at 2e4 to 1.5e5 random doubles against these formulas;
# the errors measured there are in docs/results.md (fresnel-50-digits).
WORST_F64 = {
    "dielectric": [("worst R_p found cos=0.76528 eta=1.70205", 0.7652819693198041, 1.7020537855601314)],
    "conductor": [("worst R_p found cos=0.79158 n=0.70202 kappa=6.6467",
                   0.7915797852215061, 0.7020224126588795, 6.646724002409787),
                  ("worst R_p found cos=0.85144 n=0.37104 kappa=3.9683",
                   0.8514409935018296, 0.371036603129028, 3.9682635808941678),
                  ("worst R_s found cos=0.67544 n=0.18349 kappa=4.0605",
                   0.6754425507263279, 0.18348744872677603, 4.060512106629868),
                  ("worst R found cos=0.90842 n=0.58720 kappa=7.9773",
                   0.9084236338954503, 0.5871952415847482, 7.977317883276619)]}
CONDUCTOR_EXTREMES = {  # (name, n, kappa) on the conductor cos grid (1, 1e-300 / 1e-38 and 0 included)
    "f64": [("n=1e3 kappa=0", 1e3, 0.0), ("n=1e3 kappa=1", 1e3, 1.0),
            ("n=1+1e-12 kappa=0", 1 + 1e-12, 0.0), ("n=1+1e-12 kappa=1e-12", 1 + 1e-12, 1e-12),
            ("n=1-1e-12 kappa=0", 1 - 1e-12, 0.0), ("n=1-1e-12 kappa=1e-12", 1 - 1e-12, 1e-12)],
    "f32": [("n=1e3 kappa=0", 1e3, 0.0), ("n=1e3 kappa=1", 1e3, 1.0),
            ("n=1+2^-23 kappa=0", 1 + 2.0 ** -23, 0.0), ("n=1+2^-23 kappa=1e-12", 1 + 2.0 ** -23, 1e-12),
            ("n=1-2^-24 kappa=0", 1 - 2.0 ** -24, 0.0), ("n=1-2^-24 kappa=1e-12", 1 - 2.0 ** -24, 1e-12)]}

# Critical angles, on every path that has one (beyond it: total internal reflection).
# Light from inside with eta > 1 (cos_i < 0; glass is above, in dielectric_inputs) ...
CRITICAL_INSIDE = {
    "f64": [("water", 1.333), ("diamond", 2.42), ("eta=1.0001", 1.0001), ("eta=1e3", 1e3),
            ("eta=1+1e-12", 1 + 1e-12)],
    "f32": [("water", 1.333), ("diamond", 2.42), ("eta=1.0001", 1.0001), ("eta=1e3", 1e3),
            ("eta=1+2^-23", 1 + 2.0 ** -23)]}
# ... and light from outside with eta < 1 (cos_i > 0), ...
CRITICAL_OUTSIDE = {
    "f64": [("eta=1/1.5", 1 / 1.5), ("eta=1/1.333", 1 / 1.333), ("eta=1e-3", 1e-3),
            ("eta=1-1e-12", 1 - 1e-12)],
    "f32": [("eta=1/1.5", 1 / 1.5), ("eta=1/1.333", 1 / 1.333), ("eta=1e-3", 1e-3),
            ("eta=1-2^-24", 1 - 2.0 ** -24)]}
# ... and the conductor law with kappa = 0 and n < 1 (the dielectric one, light from outside).
CRITICAL_CONDUCTOR = {
    "f64": [("dielectric below 1 via conductor n=0.5", 0.5), ("n=1e-3 kappa=0", 1e-3),
            ("n=1-1e-12 kappa=0", 1 - 1e-12)],
    "f32": [("dielectric below 1 via conductor n=0.5", 0.5), ("n=1e-3 kappa=0", 1e-3),
            ("n=1-2^-24 kappa=0", 1 - 2.0 ** -24)]}
# f64 angle offsets (radians) from the critical angle theta_c. 1e-12 rad everywhere. Where
# theta_c is ~1e-3 rad from normal (eta = 1e3 inside, eta = 1e-3 outside) 1e-12 rad is only
# ~9 doubles of cos_i (d cos = sin(theta_c) d theta), so the +-1 ulp cases below matter too.
# Where eta = 1 +- 1e-12, cos(theta_c) = sqrt(1 - 1/eta^2) or sqrt(1 - eta^2) ~ sqrt(2e-12):
# theta_c is only ~1.414e-6 rad from grazing. 1e-12 rad is then ~7e-7 of the way to grazing
# (still ~5e9 doubles of cos_i), and 1e-9 and 1e-7 rad (0.07 % and 7 % of it) are added; the
# 1e-6 rad used for glass would put the TIR side ~0.4e-6 rad from grazing, so it is not used.
CRIT_RAD = ("-1e-12", "+1e-12")
CRIT_RAD_NEAR_ONE = ("-1e-7", "-1e-9", "-1e-12", "+1e-12", "+1e-9", "+1e-7")
CRIT_F32_ULPS = range(-4, 5)  # f32: 1e-12 rad is far below f32 resolution; +-4 f32 ulps instead


def _near(name, offsets, exact_cos, side):
    """[(label, cos_i)] with cos_i = side * cos(theta + d), rounded to double, for
    angle offsets d (decimal strings, radians) about theta = acos(exact_cos)."""
    theta, where = mp.acos(exact_cos), ("outside" if side > 0 else "inside")
    return [(f"{name} {where} {lab}", float(side * mp.cos(theta + mpf(d)))) for lab, d in offsets]


def _near_within(offsets, exact_cos, side):
    """[(offset label, cos_i)] like ``_near``, but each |cos_i| is cos(theta + d) rounded
    towards the critical cosine ``exact_cos`` (not to nearest), so that the angle of the
    stored double is on d's side of theta and at most |d| from it: "within |d| rad" holds
    exactly (checked)."""
    theta = mp.acos(exact_cos)
    out = []
    for d in offsets:
        target = mp.cos(theta + mpf(d))
        x = float(target)
        if mpf(d) > 0 and x < target:  # angle beyond theta + d: one step towards theta
            x = math.nextafter(x, math.inf)
        elif mpf(d) < 0 and x > target:
            x = math.nextafter(x, -math.inf)
        assert 0 < (mp.acos(mpf(x)) - theta) / mpf(d) <= 1, (exact_cos, d)
        out.append((f"critical{d}rad", side * x))
    return out


def _f32_nearest(x):
    """The float32 nearest the real x (a normal float32 here), as the exact Python float."""
    y = float(mp.fadd(x, 0, prec=24, rounding="n"))
    assert f32(y) == y
    return y


def _critical_cases(prefix, exact_cos, side, tier, offsets):
    """[(label, cos_i)] about the critical cosine ``exact_cos`` on one side (the sign of
    cos_i). f64: the angle offsets (``_near_within``), the nearest double and the doubles
    1 ulp either side of it; f32: the nearest float32 and CRIT_F32_ULPS float32 steps."""
    if tier == "f64":
        x = float(exact_cos)
        out = _near_within(offsets, exact_cos, side) + [
            ("critical nearest double", side * x),
            ("critical |cos|+1ulp", side * math.nextafter(x, math.inf)),
            ("critical |cos|-1ulp", side * math.nextafter(x, -math.inf))]
    else:
        x = _f32_nearest(exact_cos)
        out = [(f"critical f32 |cos|{k:+d}ulp" if k else "critical f32 nearest", side * f32_step(x, k))
               for k in CRIT_F32_ULPS]
    return [(f"{prefix} {lab}", c) for lab, c in out]


def critical_dielectric_inputs(tier):
    """[(label, cos_i, eta)] near the critical angle on both paths that have one, beyond
    the glass cases of ``dielectric_inputs`` (water's +-1e-12 rad are there too)."""
    rnd = f32 if tier == "f32" else float
    out = []
    for paths, side in ((CRITICAL_INSIDE, -1), (CRITICAL_OUTSIDE, 1)):
        for name, eta in paths[tier]:
            eta = rnd(eta)
            exact = mp.sqrt(1 - 1 / mpf(eta) ** 2) if side < 0 else mp.sqrt(1 - mpf(eta) ** 2)
            offs = () if name == "water" else CRIT_RAD_NEAR_ONE if "1e-12" in name else CRIT_RAD
            prefix = f"{name} {'outside' if side > 0 else 'inside'}"
            out += [(lab, c, eta) for lab, c in _critical_cases(prefix, exact, side, tier, offs)]
    return out


def dielectric_inputs(tier):
    """[(label, cos_i, eta)] for one tier, in a fixed order."""
    rnd = f32 if tier == "f32" else float
    cos_grid = [(lab, rnd(x)) for lab, x in COS + TINY_COS[tier]] + [("0", 0.0)]
    out = []
    for name, eta in DIELECTRICS + NEAR_ONE[tier] + OTHER:
        eta = rnd(eta)
        for lab, c in cos_grid:
            out.append((f"{name} outside cos={lab}", c, eta))
            if c != 0:
                out.append((f"{name} inside cos=-{lab}", -c, eta))
    glass, water = rnd(1.5), rnd(1.333)
    crit = lambda eta: mp.sqrt(1 - 1 / mpf(eta) ** 2)  # cos of the critical angle
    brewster = 1 / mp.sqrt(1 + mpf(glass) ** 2)  # cos(atan(eta))
    if tier == "f64":
        offs = [(f"critical{s}rad", s) for s in ("-1e-6", "-1e-9", "-1e-12", "+1e-12", "+1e-9", "+1e-6")]
        near = _near("glass", offs, crit(glass), -1)
        x = float(-crit(glass))
        near += [("glass inside critical nearest double", x),
                 ("glass inside critical |cos|+1ulp", math.nextafter(x, -math.inf)),
                 ("glass inside critical |cos|-1ulp", math.nextafter(x, math.inf))]
        out += [(lab, c, glass) for lab, c in near]
        out += [(lab, c, water) for lab, c in _near("water", offs[2:4], crit(water), -1)]
        offs = [("brewster", "0")] + [(f"brewster{s}rad", s) for s in ("-1e-9", "+1e-9", "-1e-4", "+1e-4")]
        out += [(lab, c, glass) for lab, c in _near("glass", offs, brewster, 1)]
    else:
        x, b = f32(float(-crit(glass))), f32(float(brewster))
        out += [(f"glass inside critical f32 |cos|{k:+d}ulp" if k else "glass inside critical f32 nearest",
                 f32_step(x, k), glass) for k in range(-4, 5)]
        out += [(f"glass outside brewster f32 {k:+d}ulp" if k else "glass outside brewster f32 nearest",
                 f32_step(b, k), glass) for k in range(-2, 3)]
    worst = WORST_F64["dielectric"] if tier == "f64" else []
    return out + critical_dielectric_inputs(tier) + worst


def conductor_inputs(tier):
    """[(label, cos_i, n, kappa)] for one tier, in a fixed order."""
    rnd = f32 if tier == "f32" else float
    cos_grid = [(lab, rnd(x)) for lab, x in COS if lab != "0.9999999"]
    cos_grid += [(lab, rnd(x)) for lab, x in TINY_COS[tier] if lab != "2^-149"] + [("0", 0.0)]
    out = [(f"{name} cos={lab}", c, rnd(n), rnd(k))
           for name, n, k in CONDUCTORS + [TINY_KAPPA[tier]] + CONDUCTOR_EXTREMES[tier] for lab, c in cos_grid]
    for name, n in CRITICAL_CONDUCTOR[tier]:  # kappa = 0, n < 1: TIR for |cos_i| < sqrt(1 - n^2)
        n = rnd(n)
        offs = CRIT_RAD_NEAR_ONE if "1e-12" in name else CRIT_RAD
        out += [(lab, c, n, 0.0) for lab, c in _critical_cases(name, mp.sqrt(1 - mpf(n) ** 2), 1, tier, offs)]
    return out + (WORST_F64["conductor"] if tier == "f64" else [])


# The angle laws (snell.rs), on the index along the path eta_path = n_t / n_i -------

ANGLE_INDICES = {
    "f64": [("glass in", 1.5), ("glass out", 1 / 1.5), ("water out", 1 / 1.333), ("diamond out", 1 / 2.42),
            ("eta=4", 4.0), ("eta=0.25", 0.25), ("eta=1e3", 1e3), ("eta=1e-3", 1e-3),
            ("eta=1+1e-12", 1 + 1e-12), ("eta=1-1e-12", 1 - 1e-12)],
    "f32": [("glass in", 1.5), ("glass out", 1 / 1.5), ("water out", 1 / 1.333), ("diamond out", 1 / 2.42),
            ("eta=4", 4.0), ("eta=0.25", 0.25), ("eta=1e3", 1e3), ("eta=1e-3", 1e-3),
            ("eta=1+2^-23", 1 + 2.0 ** -23), ("eta=1-2^-24", 1 - 2.0 ** -24)]}
ANGLES = [("0", 0.0), ("1e-8", 1e-8), ("0.1", 0.1), ("0.5", 0.5), ("1", 1.0), ("1.2", 1.2), ("1.5", 1.5)]
# From the critical angle, where there is one: in f32 1e-9 rad is below the spacing of angles
# (6e-8 near 0.73), so its offsets are 1e-6 and 1e-5 (16 and 160 float32 steps there).
# In f64 also 1e-12 and 1e-13 rad: near a grazing critical angle (eta_path = 1 - 1e-12) one ulp of
# sin(theta) spans about 8e-11 rad, so only a law that reads cos(theta) there decides them right.
CRIT_ANGLE_RAD = {"f64": ("-1e-6", "-1e-9", "-1e-12", "-1e-13", "+1e-13", "+1e-12", "+1e-9", "+1e-6"),
                  "f32": ("-1e-5", "-1e-6", "+1e-6", "+1e-5")}


def _angle_pair(x):
    return None if x is None else _pair(x)


def transmitted(theta_i, eta_path):
    """theta_t = asin(sin theta_i / eta_path), or None under total internal reflection."""
    x = mp.sin(mpf(theta_i)) / mpf(eta_path)
    return None if x > 1 else mp.asin(x)


def _cond_theta(theta_i, eta_path, theta_t):
    """Relative condition number of theta_t over theta_i alone, |theta_i dtheta_t/dtheta_i| / theta_t
    (0 where theta_t == 0 or there is none): the law's only rounded input is sin or cos of theta_i;
    eta_path reaches it exact."""
    if theta_t is None or theta_t == 0:
        return 0.0
    sens = _log_sensitivities(lambda t: transmitted(t, eta_path), (theta_i,))
    return _cond(sens, theta_t)


def angle_cases(tier):
    """The angle laws at exactly representable inputs of one tier."""
    rnd = f32 if tier == "f32" else float
    out = []
    quarter = [("pi/4-1ulp", math.nextafter(math.pi / 4, 0)), ("pi/4+1ulp", math.nextafter(math.pi / 4, 4))]
    if tier == "f32":
        quarter = [("pi/4-1ulp", f32_step(f32(math.pi / 4), -1)), ("pi/4+1ulp", f32_step(f32(math.pi / 4), 1))]
    half_pi = f32(math.pi / 2) if tier == "f32" else math.pi / 2
    if half_pi > math.pi / 2:  # the float32 of pi/2 rounds up: the largest angle the law accepts is below it
        half_pi = f32_step(half_pi, -1)
    for name, eta in ANGLE_INDICES[tier]:
        eta = rnd(eta)
        grid = [(lab, rnd(t)) for lab, t in ANGLES] + quarter + [("pi/2", half_pi)]
        if eta < 1:
            theta_c = mp.asin(mpf(eta))
            grid += [(f"critical{d}rad", rnd(float(theta_c + mpf(d)))) for d in CRIT_ANGLE_RAD[tier]]
        for lab, theta in grid:
            if not 0 <= theta <= math.pi / 2:
                continue
            theta_t = transmitted(theta, eta)
            out.append({"label": f"{name} transmitted theta_i={lab}", "law": "transmitted_angle",
                        "theta_i": theta, "eta_path": eta, "value": _angle_pair(theta_t),
                        "cond_theta": _cond_theta(theta, eta, theta_t)})
        critical = mp.asin(mpf(eta)) if eta < 1 else None
        out.append({"label": f"{name} critical", "law": "critical_angle", "theta_i": 0.0, "eta_path": eta,
                    "value": _angle_pair(critical), "cond_theta": 0.0})
        brewster = mp.atan(mpf(eta))
        out.append({"label": f"{name} brewster", "law": "brewster_angle", "theta_i": 0.0, "eta_path": eta,
                    "value": _angle_pair(brewster), "cond_theta": 0.0})
    return out


def build_reference():
    """The whole reference document as a JSON-ready dict (deterministic)."""
    doc = {"schema": "fresnel-reference/1",
           "description": "Exact textbook Fresnel reflectances and transmittances of dielectrics and "
                          "conductors at exactly representable f64 and f32 inputs, computed with mpmath.",
           "regenerate": "python3 python-checks/fresnel_mpmath.py",
           "generator": "python-checks/fresnel_mpmath.py",
           "mpmath_version": mpmath.__version__,
           "significant_digits": DIGITS,
           "conventions": "eta = n_inside / n_outside; cos_i > 0: light from outside; "
                          "conductor index n + i kappa, light from outside; angles in radians, "
                          "their index eta_path = n_t / n_i",
           "dielectric": {}, "conductor": {}}
    with mp.workdps(DPS):
        for tier in ("f64", "f32"):
            doc["dielectric"][tier] = [dielectric_case(*a) for a in dielectric_inputs(tier)]
            doc["conductor"][tier] = [conductor_case(*a) for a in conductor_inputs(tier)]
        doc["angles"] = {tier: angle_cases(tier) for tier in ("f64", "f32")}
    for kind in ("dielectric", "conductor", "angles"):
        for tier, cases in doc[kind].items():
            labels = [c["label"] for c in cases]
            assert len(set(labels)) == len(labels), f"duplicate labels in {kind}/{tier}"
    return doc


def main(path=DEFAULT_PATH):
    write_json(path, build_reference())


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else DEFAULT_PATH)
