"""The Fresnel and angle laws at random inputs, against mpmath's 50-digit values.

Regenerate (from the repository root; the output is byte-for-byte stable):

    python3 python-checks/fresnel_random.py

writes ``validation/reference/fresnel_random.json``.

After them, one targeted set (``NEAR``): the f64 dielectric drawn as ``reals`` over the small
region where its roundings add up most.

``fresnel_mpmath.py`` holds the hand-built grid (critical angles, eta near 1,
the extremes); this file draws inputs nobody chose, from a fixed seed, in two
ways for each tier (binary64 "f64", binary32 "f32"):

- ``reals``: uniform over the real numbers of each argument's range, then
  rounded to the tier (most cosines are of order one);
- ``floats``: uniform over the tier's floating-point numbers in the range,
  that is over their bit patterns, as Herbie samples (Panchekha et al.,
  PLDI 2015): each binade is as likely as any other, so most cosines and
  angles are far below 1e-3 (about one in 1000 of the doubles of [0, 1] and
  one in 127 of its float32s subnormal), while a common critical angle or
  an index within 1e-3 of 1 is rarely hit.

The laws are ``fresnel_mpmath``'s (the textbook formulas, one place): the
dielectric R_s, R_p, R, T and total internal reflection, the conductor R_s,
R_p, R, Snell's law for angles with its condition number over theta_i, the
critical and Brewster angles, and Schlick's F0 + (1 - F0)(1 - cos)^5.
Each is evaluated at ``fm.DPS`` digits or more (``fm.working_dps``) and
rounded once, to nearest with ties to even, subnormals included, to the
tier: the stored value is the correctly rounded answer a perfect law would
return, from which a law's error is counted in floating-point numbers.

Encoding: each column is the base64 of its values as little-endian IEEE 754
numbers of the tier (``f64le`` or ``f32le``); "no value" (total internal
reflection in Snell's law, no critical angle) is a quiet NaN; ``tir`` is one
byte per case (1: total internal reflection). The generator is SplitMix64
(Steele, Lea & Flood, OOPSLA 2014), written out below so that no library's
generator can change the draws.
"""
import base64
import math
import os
import struct
import sys

import mpmath
from mpmath import mp, mpf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fresnel_mpmath as fm  # noqa: E402
from atomic_write import write_json  # noqa: E402

SEED = 11
COUNT = 5000  # per law, tier and sampling: 10^4 per law and tier
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_PATH = os.path.join(ROOT, "validation", "reference", "fresnel_random.json")

TIERS = {"f64": {"prec": 53, "emin": -1074, "bits": "<Q", "float": "<d"},
         "f32": {"prec": 24, "emin": -149, "bits": "<I", "float": "<f"}}
# Each argument's range, per law; in the order the law takes them.
ETA = (0.25, 4.0)  # a quarter to four: air and glass, water, diamond, germanium, either way
LAWS = {
    "dielectric": {"cos_i": (-1.0, 1.0), "eta": ETA},
    "conductor": {"cos_i": (0.0, 1.0), "n": (0.05, 4.0), "kappa": (0.0, 10.0)},
    "transmitted_angle": {"theta_i": (0.0, math.pi / 2), "eta_path": ETA},
    "critical_angle": {"eta_path": ETA},
    "brewster_angle": {"eta_path": ETA},
    "schlick": {"cos_i": (0.0, 1.0), "f0": (0.0, 1.0)},
}

# A targeted sweep, drawn after all the sets above (whose draws it leaves as they were): the
# reals sampling confined to where the f64 dielectric's roundings add up most, R_p the square
# of a ratio of about six of them. 6 of these cases are past 8 numbers from the correctly
# rounded value, the worst 10 (the grid's worst found, 10.9 ulps at cos_i = 0.76528...,
# eta = 1.70205..., is in fresnel_mpmath.py), too rare for the uniform samplings' 5000 cases
# over the whole range to show.
NEAR = {"dielectric": {"tier": "f64", "count": 20000, "ranges": {"cos_i": (0.755, 0.775), "eta": (1.69, 1.715)}}}


class SplitMix64:
    def __init__(self, seed):
        self.state = seed

    def next_u64(self):
        self.state = (self.state + 0x9E3779B97F4A7C15) & 0xFFFFFFFFFFFFFFFF
        z = self.state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & 0xFFFFFFFFFFFFFFFF
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & 0xFFFFFFFFFFFFFFFF
        return z ^ (z >> 31)

    def unit(self):
        """Uniform in [0, 1), 53 bits."""
        return (self.next_u64() >> 11) / 2.0 ** 53

    def below(self, n):
        """Uniform integer in [0, n), by rejection (no modulo bias)."""
        mask = (1 << max(1, (n - 1).bit_length())) - 1
        while True:
            k = self.next_u64() & mask
            if k < n:
                return k


# The tiers' numbers ---------------------------------------------------------
def nearest(x, tier):
    """The mpf x rounded to nearest, ties to even, in the tier (subnormals
    included), as the exact Python float; NaN for None."""
    if x is None:
        return math.nan
    if x == 0:
        return 0.0
    prec, emin = TIERS[tier]["prec"], TIERS[tier]["emin"]
    _, e = mp.frexp(x)  # x = m 2^e, 1/2 <= |m| < 1
    q = max(int(e) - prec, emin)  # the exponent of the last place
    scaled = mpf(x) * mpf(2) ** -q  # exact: a power of two
    k = int(mp.floor(scaled))
    d = scaled - k
    if d > 0.5 or (d == 0.5 and k % 2):
        k += 1
    return math.ldexp(k, q)


def ordinal(x, tier):
    """The tier's number x as an integer, monotonic in x (+0 and -0 both 0)."""
    t = TIERS[tier]
    bits = struct.unpack(t["bits"], struct.pack(t["float"], abs(x)))[0]
    return -bits if x < 0 else bits


def from_ordinal(k, tier):
    t = TIERS[tier]
    x = struct.unpack(t["float"], struct.pack(t["bits"], abs(k)))[0]
    return -x if k < 0 else x


def draw(rng, lo, hi, tier, sampling):
    """One number of the tier in [lo, hi] (lo, hi numbers of the tier)."""
    if sampling == "reals":
        return min(hi, max(lo, nearest(mpf(lo + (hi - lo) * rng.unit()), tier)))
    a, b = ordinal(lo, tier), ordinal(hi, tier)
    return from_ordinal(a + rng.below(b - a + 1), tier)


def top(x, tier):
    """The largest number of the tier at most x."""
    y = nearest(mpf(x), tier)
    return y if y <= x else from_ordinal(ordinal(y, tier) - 1, tier)


# The laws, each rounded to the tier ------------------------------------------
def dielectric(tier, cos_i, eta):
    d = fm.dielectric(cos_i, eta)
    return {k: nearest(d[k], tier) for k in ("r_s", "r_p", "r", "t")}, d["tir"]


def conductor(tier, cos_i, n, kappa):
    return dict(zip(("r_s", "r_p", "r"), (nearest(q, tier) for q in fm.conductor(cos_i, n, kappa)))), None


def transmitted_angle(tier, theta_i, eta_path):
    """theta_t, and its relative condition number over theta_i, in closed form:
    theta_i (d theta_t / d theta_i) / theta_t = theta_i cos theta_i / (eta cos theta_t theta_t)."""
    theta_t = fm.transmitted(theta_i, eta_path)
    if theta_t is None or theta_t == 0:
        cond = mpf(0)
    else:
        t = mpf(theta_i)
        cond = t * mp.cos(t) / (mpf(eta_path) * mp.cos(theta_t) * theta_t)
    return {"theta_t": nearest(theta_t, tier), "cond_theta": nearest(cond, tier)}, None


def critical_angle(tier, eta_path):
    return {"theta_c": nearest(mp.asin(mpf(eta_path)) if eta_path < 1 else None, tier)}, None


def brewster_angle(tier, eta_path):
    return {"theta_b": nearest(mp.atan(mpf(eta_path)), tier)}, None


def schlick(tier, cos_i, f0):
    return {"f": nearest(fm.schlick(cos_i, f0), tier)}, None


EVALUATE = {"dielectric": dielectric, "conductor": conductor, "transmitted_angle": transmitted_angle,
            "critical_angle": critical_angle, "brewster_angle": brewster_angle, "schlick": schlick}


def encode(values, tier):
    fmt = TIERS[tier]["float"]
    return base64.b64encode(b"".join(struct.pack(fmt, v) for v in values)).decode("ascii")


def case_set(law, tier, sampling, rng, ranges=None, count=COUNT):
    """``count`` cases of one law in one tier and sampling over ``ranges`` (the law's own by
    default; "near" draws as "reals"), as a JSON-ready dict."""
    ranges = {arg: (nearest(mpf(lo), tier), top(hi, tier)) for arg, (lo, hi) in (ranges or LAWS[law]).items()}
    columns, tir = {arg: [] for arg in ranges}, []
    for _ in range(count):
        args = [draw(rng, lo, hi, tier, "reals" if sampling == "near" else sampling) for lo, hi in ranges.values()]
        cos = args[0] if law in ("dielectric", "conductor", "schlick") else 1.0
        with mp.workdps(fm.working_dps(cos)):
            values, is_tir = EVALUATE[law](tier, *args)
        for arg, x in zip(ranges, args):
            columns[arg].append(x)
        for key, v in values.items():
            columns.setdefault(key, []).append(v)
        if is_tir is not None:
            tir.append(1 if is_tir else 0)
    out = {"law": law, "tier": tier, "sampling": sampling, "count": count,
           "ranges": {arg: list(r) for arg, r in ranges.items()},
           "encoding": f"{tier}le", "columns": {k: encode(v, tier) for k, v in columns.items()}}
    if tir:
        out["tir_u8"] = base64.b64encode(bytes(tir)).decode("ascii")
    return out


def build_reference():
    """The whole reference document as a JSON-ready dict (deterministic)."""
    rng = SplitMix64(SEED)
    sets = [case_set(law, tier, sampling, rng)
            for law in LAWS for tier in TIERS for sampling in ("reals", "floats")]
    sets += [case_set(law, near["tier"], "near", rng, near["ranges"], near["count"]) for law, near in NEAR.items()]
    return {"schema": "fresnel-random/1",
            "description": "The Fresnel and angle laws at seeded random inputs, uniform over the reals "
                           "and uniform over the floating-point numbers of each argument's range, "
                           "with mpmath's values correctly rounded to the tier.",
            "regenerate": "python3 python-checks/fresnel_random.py",
            "generator": "python-checks/fresnel_random.py",
            "mpmath_version": mpmath.__version__,
            "significant_digits": fm.DIGITS,
            "seed": SEED,
            "conventions": "eta = n_inside / n_outside; cos_i > 0: light from outside; conductor index "
                           "n + i kappa, light from outside; angles in radians, their index "
                           "eta_path = n_t / n_i; NaN: the law has no value (total internal "
                           "reflection, no critical angle)",
            "samplings": {"reals": "uniform over the real numbers of the range, rounded to the tier",
                          "floats": "uniform over the tier's floating-point numbers in the range "
                                    "(their bit patterns)",
                          "near": "uniform over the real numbers of a targeted region, rounded to the tier"},
            "sets": sets}


def main(path=DEFAULT_PATH):
    with mp.workdps(fm.DPS):
        write_json(path, build_reference())


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else DEFAULT_PATH)
