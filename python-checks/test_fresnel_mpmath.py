"""Checks of the mpmath Fresnel reference generator (python3 -m pytest -q python-checks)."""
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


# The extremes the grid must hold -------------------------------------------
import re  # noqa: E402

import pytest  # noqa: E402


@pytest.fixture(scope="module")
def doc():
    return fm.build_reference()


def labels(doc, kind, tier):
    return {c["label"] for c in doc[kind][tier]}


# Paths with a critical angle: light from inside with eta > 1, from outside with eta < 1.
CRITICAL_DIELECTRIC = {
    "f64": ["glass inside", "water inside", "diamond inside", "eta=1.0001 inside", "eta=1e3 inside",
            "eta=1+1e-12 inside", "eta=1/1.5 outside", "eta=1/1.333 outside", "eta=1e-3 outside",
            "eta=1-1e-12 outside"],
    "f32": ["glass inside", "water inside", "diamond inside", "eta=1.0001 inside", "eta=1e3 inside",
            "eta=1+2^-23 inside", "eta=1/1.5 outside", "eta=1/1.333 outside", "eta=1e-3 outside",
            "eta=1-2^-24 outside"]}
CRITICAL_CONDUCTOR = {  # kappa = 0, n < 1
    "f64": ["dielectric below 1 via conductor n=0.5", "n=1e-3 kappa=0", "n=1-1e-12 kappa=0"],
    "f32": ["dielectric below 1 via conductor n=0.5", "n=1e-3 kappa=0", "n=1-2^-24 kappa=0"]}
F64_CRITICAL = ["critical-1e-12rad", "critical+1e-12rad", "critical nearest double",
                "critical |cos|+1ulp", "critical |cos|-1ulp"]
F32_CRITICAL = ["critical f32 nearest"] + [f"critical f32 |cos|{k:+d}ulp" for k in (-4, -1, 1, 4)]
CONDUCTOR_EXTREMES = {
    "f64": ["kappa=1e3 n=1", "n=1e3 kappa=0", "n=1e3 kappa=1", "n=1+1e-12 kappa=0", "n=1+1e-12 kappa=1e-12",
            "n=1-1e-12 kappa=0", "n=1-1e-12 kappa=1e-12"],
    "f32": ["kappa=1e3 n=1", "n=1e3 kappa=0", "n=1e3 kappa=1", "n=1+2^-23 kappa=0", "n=1+2^-23 kappa=1e-12",
            "n=1-2^-24 kappa=0", "n=1-2^-24 kappa=1e-12"]}
TINIEST = {"f64": "1e-300", "f32": "1e-38"}
# Cases written before the near-critical offsets were rounded towards the critical angle.
ROUNDED_TO_NEAREST = {"glass inside", "water inside"}


@pytest.mark.parametrize("tier", ["f64", "f32"])
def test_every_critical_path_has_near_critical_cases(doc, tier):
    names = F64_CRITICAL if tier == "f64" else F32_CRITICAL
    have_d, have_c = labels(doc, "dielectric", tier), labels(doc, "conductor", tier)
    missing = [f"{p} {n}" for p in CRITICAL_DIELECTRIC[tier] for n in names if f"{p} {n}" not in have_d]
    missing += [f"{p} {n}" for p in CRITICAL_CONDUCTOR[tier] for n in names if f"{p} {n}" not in have_c]
    if tier == "f64":  # near grazing (eta = 1 +- 1e-12) also the wider offsets
        missing += [f"{p} critical{d}rad" for p in ("eta=1+1e-12 inside", "eta=1-1e-12 outside")
                    for d in fm.CRIT_RAD_NEAR_ONE if f"{p} critical{d}rad" not in have_d]
    assert not missing


@pytest.mark.parametrize("tier", ["f64", "f32"])
def test_conductor_extremes_present(doc, tier):
    have = labels(doc, "conductor", tier)
    missing = [f"{m} cos={c}" for m in CONDUCTOR_EXTREMES[tier] for c in ("1", "0", TINIEST[tier])
               if f"{m} cos={c}" not in have]
    assert not missing
    cases = {c["label"]: c for c in doc["conductor"][tier]}
    assert cases[CONDUCTOR_EXTREMES[tier][-2] + " cos=0"]["kappa"] == 0.0
    assert cases[CONDUCTOR_EXTREMES[tier][-1] + " cos=1"]["kappa"] == (fm.f32(1e-12) if tier == "f32" else 1e-12)
    assert cases["n=1e3 kappa=1 cos=0"]["n"] == 1e3 and cases["kappa=1e3 n=1 cos=1"]["kappa"] == 1e3


def _exact_critical_cos(case):
    """(|cos| of the critical angle, side) for a dielectric or kappa = 0 conductor case."""
    if "n" in case:
        return mp.sqrt(1 - mpf(case["n"]) ** 2)
    eta = mpf(case["eta"])
    return mp.sqrt(1 - 1 / eta ** 2) if case["cos_i"] < 0 else mp.sqrt(1 - eta ** 2)


def _is_tir(kind, case):
    if kind == "dielectric":
        return case["tir"]
    tir = case["r"] == [1.0, 0.0] and case["r_digits"] == "1.0"
    assert tir == fm.conductor_tir(case["cos_i"], case["n"], case["kappa"])
    return tir


PAIR = re.compile(r"^(?P<path>.*) critical(?: f32)?(?: \|cos\|(?P<ulp>[+-]\d+)ulp|(?P<rad>[+-][0-9e.-]+)rad)$")


@pytest.mark.parametrize("kind", ["dielectric", "conductor"])
@pytest.mark.parametrize("tier", ["f64", "f32"])
def test_near_critical_pairs_straddle_total_internal_reflection(doc, kind, tier):
    """Beyond the critical angle (a larger angle, a smaller |cos|) TIR; before it, not. Every
    offset has its mirror image, so each pair has one side under TIR and one not."""
    with mp.workdps(fm.DPS):
        cases = {c["label"]: c for c in doc[kind][tier]}
        seen = 0
        for label, case in cases.items():
            m = PAIR.match(label)
            if not m:
                continue
            seen += 1
            g = "ulp" if m["ulp"] else "rad"
            offset = m[g]
            mirror = ("-" if offset.startswith("+") else "+") + offset[1:]
            assert label[:m.start(g)] + mirror + label[m.end(g):] in cases, label
            beyond = offset.startswith("-") if m["ulp"] else offset.startswith("+")
            assert _is_tir(kind, case) == beyond, label
            c, exact = abs(mpf(case["cos_i"])), _exact_critical_cos(case)
            assert (c < exact) == beyond, label
            if m["rad"]:  # the stored angle is within the stated offset of the critical angle
                ratio = (mp.acos(c) - mp.acos(exact)) / mpf(m["rad"])
                if m["path"] in ROUNDED_TO_NEAREST:
                    assert abs(ratio - 1) < mpf("1e-4"), label
                else:
                    assert 0.5 < ratio <= 1, label
            if kind == "conductor" and not beyond:  # kappa = 0: the dielectric law, refracting
                assert close(fm.conductor(case["cos_i"], case["n"], 0.0)[2],
                             fm.dielectric(case["cos_i"], case["n"])["r"], 30)
        assert seen == {("dielectric", "f64"): 52, ("dielectric", "f32"): 80,
                        ("conductor", "f64"): 16, ("conductor", "f32"): 24}[kind, tier], seen


def test_nearest_double_and_float32_are_nearest(doc):
    with mp.workdps(fm.DPS):
        for kind in ("dielectric", "conductor"):
            for tier, ulp in (("f64", 2.0 ** -52), ("f32", 2.0 ** -23)):
                for case in doc[kind][tier]:
                    if not case["label"].endswith(("critical nearest double", "critical f32 nearest")):
                        continue
                    c, exact = abs(mpf(case["cos_i"])), _exact_critical_cos(case)
                    half = mpf(2) ** (mp.floor(mp.log(exact, 2))) * ulp / 2
                    assert abs(c - exact) <= half, case["label"]


def test_conductor_tir_is_exactly_one():
    with mp.workdps(fm.DPS):
        for cos_i, n in [(0.5, 0.5), (1e-8, 1 - 1e-12), (0.0, 0.5), (0.9, 1e-3)]:
            assert fm.conductor_tir(cos_i, n, 0.0)
            assert fm.conductor(cos_i, n, 0.0) == (1, 1, 1)
        assert not fm.conductor_tir(0.5, 0.5, 1e-12)


@pytest.mark.parametrize("tier", ["f64", "f32"])
def test_angle_laws_cover_every_index_and_straddle_the_critical_angle(doc, tier):
    cases = doc["angles"][tier]
    for name, eta in fm.ANGLE_INDICES[tier]:
        mine = {c["label"]: c for c in cases if c["label"].startswith(name + " ")}
        assert f"{name} critical" in mine and f"{name} brewster" in mine, name
        assert (mine[f"{name} critical"]["value"] is None) == (fm.f32(eta) >= 1 if tier == "f32" else eta >= 1)
        if mine[f"{name} critical"]["value"] is not None:
            for d in fm.CRIT_ANGLE_RAD[tier]:
                case = mine[f"{name} transmitted theta_i=critical{d}rad"]
                assert (case["value"] is None) == d.startswith("+"), case["label"]


def test_angles_agree_with_snell_and_the_textbook():
    with mp.workdps(fm.DPS):
        t = fm.transmitted(0.5, 1.5)
        assert close(mp.sin(t) * mpf(1.5), mp.sin(mpf(0.5)))
        assert fm.transmitted(1.0, 1 / 1.5) is None  # 57° out of glass: beyond 41.8°
        assert close(mp.asin(mpf(1) / 2), mp.pi / 6)
