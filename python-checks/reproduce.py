"""Whether a freshly generated reference reproduces the committed one: the one
rule, used by the generators' tests and by ``optics validate``.

Most references are byte-for-byte stable: mpmath and Mitsuba do their own
arithmetic, and the CIE tables are published data. The two written through
colour-science (``TOLERANT``) are not, across machines: colour-science
multiplies its 3x3 colour matrices with numpy, numpy hands them to OpenBLAS,
and OpenBLAS picks its kernel per CPU (or by ``OPENBLAS_CORETYPE``); kernels
order the sums differently, so the last bits of linear sRGB, sRGB and CIELAB
move. Those files reproduce when they are the same JSON document (keys and
their order, strings, integers, the structure, the number of elements) with
every number within ``BLAS_TOLERANCE * max(1, |value|)``.

The spread, measured between the Haswell and SkylakeX kernels on one machine
(run from the repository root)::

    OPENBLAS_CORETYPE=Haswell .venv/bin/python python-checks/colorimetry.py /tmp/h.json /tmp/h.rs
    OPENBLAS_CORETYPE=SkylakeX .venv/bin/python python-checks/colorimetry.py /tmp/s.json /tmp/s.rs
    .venv/bin/python python-checks/reproduce.py /tmp/s.json /tmp/h.json --as colorimetry.json

prints "139 numbers differ, by at most 3.8e-14 of max(1, |value|)" (in CIELAB,
which multiplies the differences of XYZ by up to 500); ``metals.py`` run the
same way gives 93 numbers, at most 5.6e-14. The tolerance, 1e-12, is eighteen
times the larger.

Mitsuba's path renders (``F32_TOLERANT``) move too, across CPUs: Mitsuba
traces through Embree, which picks its kernels by the instruction set it
finds, and a last bit moved in one bounce changes a sample. The arrays of
its path statistics (base64, ``mean_f16le_zlib`` and ``std_bf16le_zlib``:
zlib-compressed float16 and bfloat16) then reproduce within a tolerance of
their own, element by element, ``|a - b| <= tolerance * max(1, |a|, |b|)``;
the offset sensitivity (``offset_sensitivity_f16le_zlib``, from the Python
Whitted integrator) must decode to the same values (tolerance 0), whatever
bytes the local zlib compresses them to; every other byte of the file must be
identical (the Whitted images, the edge masks, the scene texts). The spread,
measured between the committed file as written on an earlier machine and
the same script at the same commit on an AVX-512 machine (for the earlier
64 x 48 float32 format, whose tolerances these keep)::

    .venv/bin/python python-checks/mitsuba_render.py /tmp/m.json
    .venv/bin/python python-checks/reproduce.py validation/reference/mitsuba_renders.json /tmp/m.json

was 278 means of ``webgl_seven_spheres`` at most 5.8e-5 of max(1, |value|)
and 590 variances at most 4.7e-4; the tolerances, 1e-3 (mean) and 1e-2
(standard deviation), are about twenty times those. They bound the
reproduction of the reference only: the harness compares the tracer with
the committed file.

A sample that moves is another matter: on two AMD EPYC machines the 64 x 48
tolerances held, but at 320 x 240 one path of ``webgl_seven_spheres`` in a
pixel took another branch, and that pixel's mean moved by 7e-3 of itself
(8 means and 5 standard deviations of its 230 400 moved beyond the
tolerances, the means by at most 0.0095 of their standard error, the
deviations by at most 0.16 of theirs). Such moves are invisible to the
harness, which tests each pixel against its standard error, so a path's
statistics (a ``path`` object with ``samples`` N and both arrays) also
reproduce when at most ``MOVED_FRACTION`` of an array's elements lie beyond
its tolerance, each within ``MOVED_STANDARD_ERRORS`` of its standard error:
sigma / sqrt(N) for a mean, sigma / sqrt(2 (N - 1)) for a standard deviation,
sigma the larger of the two files' deviations of that pixel. A systematic
shift moves more elements than that and is still refused.

Usage: ``reproduce.py COMMITTED FRESH [--as NAME]`` prints where FRESH departs
from COMMITTED, and the spread of their numbers. It exits 0 if FRESH
reproduces COMMITTED, 1 if it does not, and 2 if it cannot tell (a file that
cannot be read, bad arguments). The rule is chosen by NAME (default:
COMMITTED's file name).
"""
import argparse
import base64
import json
import math
import os
import struct
import sys
import zlib

BLAS_TOLERANCE = 1e-12
TOLERANT = ("colorimetry.json", "metals.json")
F32_TOLERANT = {
    "mitsuba_renders.json": {
        "mean_f16le_zlib": 1e-3, "std_bf16le_zlib": 1e-2, "offset_sensitivity_f16le_zlib": 0.0},
    "mitsuba_full_light.json": {"mean_f32le": 1e-3},
}
# Files of Mitsuba renders whose plain numbers (a region's mean per pass)
# may move as their float32 images do, across CPUs: ``mitsuba_renders.json``'s
# mean tolerance, not yet measured on a second CPU for this file.
FLOAT_TOLERANT = {"mitsuba_full_light.json": 1e-3}
# A path's statistics: the elements that may move as one sample does (see
# the module docstring), as a fraction of the array, and by how much.
MOVED_FRACTION = 1e-4
MOVED_STANDARD_ERRORS = 0.5
PATH_MEAN, PATH_STD = "mean_f16le_zlib", "std_bf16le_zlib"


def tolerance_for(name):
    """The float tolerance of the reference file ``name``: 0 (byte for byte)
    unless it is one of ``TOLERANT`` or ``FLOAT_TOLERANT``."""
    base = os.path.basename(name)
    if base in FLOAT_TOLERANT:
        return FLOAT_TOLERANT[base]
    return BLAS_TOLERANCE if base in TOLERANT else 0.0


def f32_tolerances_for(name):
    """The tolerances of the base64 float32 arrays of the reference file
    ``name``, by key: none (byte for byte) unless it is in ``F32_TOLERANT``."""
    return F32_TOLERANT.get(os.path.basename(name), {})


def rule_for(name):
    """``(float_tolerance, f32_tolerances)``: the whole rule of ``name``."""
    return tolerance_for(name), f32_tolerances_for(name)


def differences(committed, fresh, float_tolerance=0.0, limit=5, f32_tolerances=None):
    """Up to ``limit`` descriptions of where ``fresh`` (bytes) departs from
    ``committed`` (bytes); empty when it reproduces. With no tolerance the
    bytes must be identical; with one, the JSON documents must agree as
    described in the module docstring."""
    if committed == fresh:
        return []
    if float_tolerance == 0.0 and not f32_tolerances:
        return ["the bytes differ"]
    try:
        a, b = json.loads(committed), json.loads(fresh)
    except ValueError as e:
        return [f"not JSON: {e}"]
    found = []
    _walk(a, b, "", float_tolerance, found, f32=f32_tolerances or {})
    return found[:limit]


def _f32_array(text, key=""):
    """The floats of a base64 array, by the format its key ends with:
    ``_f16le_zlib`` (IEEE float16), ``_bf16le_zlib`` (bfloat16), both zlib
    compressed, else float32."""
    raw = base64.b64decode(text, validate=True)
    if key.endswith("_zlib"):
        try:
            raw = zlib.decompress(raw)
        except zlib.error as e:
            raise ValueError(f"not zlib: {e}") from e
        if len(raw) % 2:
            raise ValueError("not a whole number of 16-bit values")
        if key.endswith("_bf16le_zlib"):
            halves = struct.unpack(f"<{len(raw) // 2}H", raw)
            return struct.unpack(f"<{len(halves)}f", struct.pack(f"<{len(halves)}I", *(h << 16 for h in halves)))
        return struct.unpack(f"<{len(raw) // 2}e", raw)
    if len(raw) % 4:
        raise ValueError("not a whole number of float32 values")
    return struct.unpack(f"<{len(raw) // 4}f", raw)


def _f32_pair(a, b, here, found):
    """The two decoded arrays at ``here``, or None (and why, in ``found``)."""
    key = here.rsplit(".", 1)[-1]
    try:
        x, y = _f32_array(a, key), _f32_array(b, key)
    except ValueError as e:
        found.append(f"{here}: not a base64 float array ({e})")
        return None
    if len(x) != len(y):
        found.append(f"{here}: {len(x)} values against {len(y)}")
        return None
    return x, y


def _f32_walk(a, b, here, tolerance, found, diffs, standard_errors=None):
    """Two base64 float arrays, element by element. With ``standard_errors``
    (one per element) up to ``MOVED_FRACTION`` of the elements may lie beyond
    ``tolerance`` if each is within ``MOVED_STANDARD_ERRORS`` of its own."""
    pair = _f32_pair(a, b, here, found)
    if pair is None:
        return
    beyond = []
    for i, (p, q) in enumerate(zip(*pair)):
        scaled = abs(p - q) / max(1.0, abs(p), abs(q))
        if diffs is not None and p != q:
            diffs.append(scaled if not math.isnan(scaled) else math.inf)
        if not scaled <= tolerance:  # a NaN is never within it
            beyond.append(i)
    moved = [] if standard_errors is None else [
        i for i in beyond if abs(pair[0][i] - pair[1][i]) <= MOVED_STANDARD_ERRORS * standard_errors[i]]
    if len(moved) > MOVED_FRACTION * len(pair[0]):
        found.append(f"{here}: {len(moved)} of {len(pair[0])} values moved within "
                     f"{MOVED_STANDARD_ERRORS} standard errors, more than {MOVED_FRACTION:g} of them")
        moved = []
    moved = set(moved)
    for i in beyond:
        if i not in moved:
            found.append(f"{here}[{i}]: committed {pair[0][i]!r}, regenerated {pair[1][i]!r}")


def _path_walk(a, b, path, tolerance, found, diffs, f32):
    """A path's statistics: its arrays by ``_f32_walk`` with the standard
    errors of each element, everything else by ``_walk``."""
    n = a["samples"]
    deviations = _f32_pair(a[PATH_STD], b[PATH_STD], f"{path}.{PATH_STD}", found)
    if deviations is None:
        return
    sigma = [max(abs(p), abs(q)) for p, q in zip(*deviations)]
    errors = {PATH_MEAN: [s / math.sqrt(n) for s in sigma],
              PATH_STD: [s / math.sqrt(2 * (n - 1)) for s in sigma]}
    for key in a:
        here = f"{path}.{key}"
        if key in errors and isinstance(a[key], str) and isinstance(b[key], str):
            _f32_walk(a[key], b[key], here, f32[key], found, diffs, errors[key])
        else:
            _walk(a[key], b[key], here, tolerance, found, diffs, f32)


def _is_path(a, b, f32):
    """Whether ``a`` and ``b`` are a path's statistics compared with tolerances."""
    return (isinstance(a, dict) and isinstance(b, dict) and list(a) == list(b)
            and PATH_MEAN in f32 and PATH_STD in f32 and PATH_MEAN in a and PATH_STD in a
            and type(a.get("samples")) is int and a["samples"] == b.get("samples") and a["samples"] > 1)


def spread(committed, fresh, f32_keys=()):
    """(how many numbers differ, the largest |a - b| / max(1, |a|, |b|)) over
    two JSON documents of the same structure; the strings at ``f32_keys``
    count as the float32 arrays they encode."""
    diffs = []
    f32 = {key: math.inf for key in f32_keys}
    _walk(json.loads(committed), json.loads(fresh), "", 0.0, [], diffs, f32)
    return len(diffs), max(diffs, default=0.0)


def _walk(a, b, path, tolerance, found, diffs=None, f32=None):
    here = path or "."
    key = path.rsplit(".", 1)[-1]
    if f32 and key in f32 and isinstance(a, str) and isinstance(b, str):
        _f32_walk(a, b, here, f32[key], found, diffs)
    elif type(a) is not type(b):  # 1 against 1.0 too: the writers never change a number's type
        found.append(f"{here}: committed {a!r}, regenerated {b!r}")
    elif isinstance(a, float):
        scaled = abs(a - b) / max(1.0, abs(a), abs(b))
        if diffs is not None and a != b:
            diffs.append(scaled if not math.isnan(scaled) else math.inf)
        if not scaled <= tolerance:  # a NaN is never within it
            found.append(f"{here}: committed {a!r}, regenerated {b!r}")
    elif f32 and _is_path(a, b, f32):
        _path_walk(a, b, path, tolerance, found, diffs, f32)
    elif isinstance(a, dict):
        if list(a) != list(b):
            found.append(f"{here}: keys {list(a)} against {list(b)}")
            return
        for key in a:
            _walk(a[key], b[key], f"{path}.{key}", tolerance, found, diffs, f32)
    elif isinstance(a, list):
        if len(a) != len(b):
            found.append(f"{here}: {len(a)} elements against {len(b)}")
            return
        for i, (x, y) in enumerate(zip(a, b)):
            _walk(x, y, f"{path}[{i}]", tolerance, found, diffs, f32)
    elif a != b:
        found.append(f"{here}: committed {a!r}, regenerated {b!r}")


def main(argv):
    parser = argparse.ArgumentParser(description="Whether FRESH reproduces the committed reference.")
    parser.add_argument("committed")
    parser.add_argument("fresh")
    parser.add_argument("--as", dest="name", help="the reference's file name, which chooses the rule")
    try:
        args = parser.parse_args(argv)
    except SystemExit as e:  # argparse's own exit: bad arguments
        return 2 if e.code else 0
    try:
        with open(args.committed, "rb") as f:
            committed = f.read()
        with open(args.fresh, "rb") as f:
            fresh = f.read()
        tolerance, f32 = rule_for(args.name or args.committed)
        found = differences(committed, fresh, tolerance, f32_tolerances=f32)
        if (tolerance or f32) and committed != fresh and not found:
            count, worst = spread(committed, fresh, f32)
            allowed = f"{tolerance:g}" if tolerance else ", ".join(f"{k} {v:g}" for k, v in f32.items())
            moved = " (beyond it only as a moved sample moves them)" if worst > max([tolerance, *f32.values()]) else ""
            print(f"{count} numbers differ, by at most {worst:.2g} of max(1, |value|)"
                  f" (tolerance {allowed}){moved}")
    except Exception as e:  # noqa: BLE001 - any failure here means "cannot tell", not "differs"
        print(f"reproduce.py: {type(e).__name__}: {e}", file=sys.stderr)
        return 2
    for line in found:
        print(line)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
