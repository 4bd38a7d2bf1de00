"""Checks of the mpmath Fresnel reference generator (python3 -m pytest -q python-checks)."""
import json
import os
import sys

from mpmath import mp, mpf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fresnel_mpmath as fm  # noqa: E402


def close(a, b, digits=40):
    return abs(a - b) <= mpf(10) ** -digits * max(abs(a), abs(b))


def test_glass_normal_incidence_is_four_percent():
    with mp.workdps(fm.DPS):
        for cos_i in (1.0, -1.0):  # from outside and from inside
            assert close(fm.dielectric(cos_i, 1.5)["r"], mpf("0.04"))


def test_r_plus_t_is_exactly_one():
    with mp.workdps(fm.DPS):
        for cos_i, eta in [(0.5, 1.5), (-0.7453, 1.5), (1e-8, 1.333), (0.3, 1 + 1e-12), (-0.9, 1e-3)]:
            d = fm.dielectric(cos_i, eta)
            assert mp.fadd(d["r"], d["t"], exact=True) == 1


def test_conductor_without_absorption_matches_dielectric():
    with mp.workdps(fm.DPS):
        for n in (1.5, 0.5, 2.42):
            for cos_i in (1.0, 0.9, 0.7, 0.3, 0.1, 1e-3):
                assert close(fm.conductor(cos_i, n, 0.0)[2], fm.dielectric(cos_i, n)["r"])


def test_total_internal_reflection():
    with mp.workdps(fm.DPS):
        d = fm.dielectric(-0.5, 1.5)
        assert d["tir"] and d["r"] == 1 and d["t"] == 0


def test_committed_reference_is_up_to_date(tmp_path):
    committed = fm.DEFAULT_PATH
    fresh = tmp_path / "fresnel_mpmath.json"
    fm.main(str(fresh))
    with open(committed, encoding="utf-8") as fh:
        assert json.load(fh) == json.loads(json.dumps(fm.build_reference()))
    with open(committed, "rb") as a, open(fresh, "rb") as b:
        assert a.read() == b.read()
