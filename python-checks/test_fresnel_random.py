"""Checks of the random-case reference generator (python3 -m pytest -q python-checks)."""
import base64
import math
import os
import struct
import sys

import pytest
from mpmath import mp, mpf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fresnel_mpmath as fm  # noqa: E402
import fresnel_random as fr  # noqa: E402


def test_splitmix64_gives_its_published_sequence():
    # Vigna's reference implementation (prng.di.unimi.it/splitmix64.c), seed 0.
    rng = fr.SplitMix64(0)
    assert [rng.next_u64() for _ in range(3)] == [
        0xE220A8397B1DCDAF, 0x6E789E6AA1B965F4, 0x06C45D188009454F]


def test_nearest_rounds_once_to_nearest_even_subnormals_included():
    with mp.workdps(fm.DPS):
        tiny = mpf(2) ** -1074
        assert fr.nearest(tiny * mpf("0.5"), "f64") == 0.0  # a tie: to even, 0
        assert fr.nearest(tiny * mpf("1.5"), "f64") == 2 * 5e-324  # a tie: to even, 2
        assert fr.nearest(tiny * mpf("2.5"), "f64") == 2 * 5e-324
        assert fr.nearest(mpf(1) + mpf(2) ** -53, "f64") == 1.0  # a tie at 1: to even
        assert fr.nearest(mpf(1) + mpf(2) ** -53 + mpf(2) ** -200, "f64") == 1.0 + 2.0 ** -52
        assert fr.nearest(mpf(1) + mpf(2) ** -24, "f32") == 1.0
        assert fr.nearest(mpf(2) ** -149 * mpf("0.75"), "f32") == 2.0 ** -149
        assert fr.nearest(mpf(1) / 3, "f32") == fm.f32(1 / 3)
        assert fr.nearest(None, "f64") != fr.nearest(None, "f64")  # NaN
        rng = fr.SplitMix64(3)
        for _ in range(200):  # normal doubles: mpmath's own rounding to nearest agrees
            x = mpf(rng.unit()) * mpf(2) ** (rng.below(2000) - 1000) * (1 + mpf(10) ** -60)
            assert fr.nearest(x, "f64") == float(x)


def test_the_floats_sampling_is_uniform_over_bit_patterns():
    rng = fr.SplitMix64(5)
    draws = [fr.draw(rng, 0.0, 1.0, "f64", "floats") for _ in range(2000)]
    # [0, 1] spans 1023 binades of doubles and the subnormals; [1e-3, 1] fewer than 10.
    assert sum(x < 1e-3 for x in draws) > 0.98 * len(draws)
    exponents = [math.frexp(x)[1] for x in draws if x > 0]  # each binade alike: -1074 .. 1
    assert abs(sum(exponents) / len(exponents) + 511) < 30
    signed = [fr.draw(rng, -1.0, 1.0, "f32", "floats") for _ in range(2000)]
    assert all(fm.f32(x) == x for x in signed)
    assert 0.45 < sum(x < 0 for x in signed) / len(signed) < 0.55


def test_the_reals_sampling_is_uniform_over_the_range():
    rng = fr.SplitMix64(5)
    draws = [fr.draw(rng, 0.25, 4.0, "f32", "reals") for _ in range(4000)]
    assert all(fm.f32(x) == x and 0.25 <= x <= 4.0 for x in draws)
    assert abs(sum(draws) / len(draws) - 2.125) < 0.1


def _column(case_set, name):
    fmt = "<d" if case_set["tier"] == "f64" else "<f"
    raw = base64.b64decode(case_set["columns"][name])
    return [v for (v,) in struct.iter_unpack(fmt, raw)]


@pytest.fixture(scope="module")
def committed():
    import json
    with open(fr.DEFAULT_PATH, encoding="utf-8") as fh:
        return json.load(fh)


def test_committed_values_are_mpmaths_correctly_rounded(committed):
    """A spot check of the committed file against the laws, independent of
    how it was written: every 250th case of each set."""
    for case_set in committed["sets"]:
        law, tier = case_set["law"], case_set["tier"]
        names = list(fr.LAWS[law])
        inputs = [_column(case_set, n) for n in names]
        values = {k: _column(case_set, k) for k in case_set["columns"] if k not in names}
        for i in range(0, case_set["count"], 250):
            args = [col[i] for col in inputs]
            with mp.workdps(fm.working_dps(args[0] if law in ("dielectric", "conductor", "schlick") else 1.0)):
                expected, _ = fr.EVALUATE[law](tier, *args)
            for key, v in expected.items():
                got = values[key][i]
                assert (math.isnan(v) and math.isnan(got)) or v == got, (law, tier, i, key)

