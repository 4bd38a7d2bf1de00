"""Whether a freshly generated reference reproduces the committed one.

Most references are byte-for-byte stable: mpmath and Mitsuba do their own
arithmetic. The two written through colour-science (``colorimetry.json``,
``metals.json``) are not, across machines: colour-science multiplies its 3x3
colour matrices with numpy, numpy hands them to OpenBLAS, and OpenBLAS picks
its kernel per CPU (or by ``OPENBLAS_CORETYPE``); kernels order the sums
differently, so the last bits of linear sRGB, sRGB and CIELAB move. Measured
between the Haswell and SkylakeX kernels on one machine: 232 numbers differ,
by at most 5.7e-14 (CIELAB a*, which multiplies the differences of XYZ by
500), 1000 ulps of the smallest value. Those files reproduce when every
number agrees within ``BLAS_TOLERANCE * max(1, |value|)``, twenty times the
measured spread, and everything else (keys, strings, integers, the
structure, the number of elements, the order of keys) is identical. The
harness (``validation::reference::departures``) applies the same rule, but
for the order of keys, which its JSON reader does not keep.
"""
import json

BLAS_TOLERANCE = 1e-12


def differences(committed, fresh, float_tolerance=0.0, limit=5):
    """Up to ``limit`` descriptions of where ``fresh`` (bytes) departs from
    ``committed`` (bytes); empty when it reproduces. With no tolerance the
    bytes must be identical; with one, the JSON documents must agree as
    described in the module docstring."""
    if committed == fresh:
        return []
    if float_tolerance == 0.0:
        return ["the bytes differ"]
    found = []
    _walk(json.loads(committed), json.loads(fresh), "", float_tolerance, found)
    return found[:limit]


def _walk(a, b, path, tolerance, found):
    if isinstance(a, float) or isinstance(b, float):
        numbers = all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in (a, b))
        if not numbers or abs(a - b) > tolerance * max(1.0, abs(a), abs(b)):
            found.append(f"{path or '.'}: committed {a!r}, regenerated {b!r}")
    elif isinstance(a, dict) and isinstance(b, dict):
        if list(a) != list(b):
            found.append(f"{path or '.'}: keys {list(a)} against {list(b)}")
            return
        for key in a:
            _walk(a[key], b[key], f"{path}.{key}", tolerance, found)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            found.append(f"{path or '.'}: {len(a)} elements against {len(b)}")
            return
        for i, (x, y) in enumerate(zip(a, b)):
            _walk(x, y, f"{path}[{i}]", tolerance, found)
    elif type(a) is not type(b) or a != b:
        found.append(f"{path or '.'}: committed {a!r}, regenerated {b!r}")
