"""Checks of the Mitsuba laws reference generator (python3 -m pytest -q python-checks)."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mitsuba_laws as ml  # noqa: E402


def test_mitsuba_glass_normal_incidence_is_four_percent():
    # Mitsuba's own answer for the textbook value, both sides (float32: a few ulps of 0.04).
    for cos_i in (1.0, -1.0):
        assert abs(ml.mitsuba_dielectric(cos_i, 1.5)["f"] - 0.04) < 1e-7


def test_mitsuba_eta_is_interior_over_exterior():
    # From outside eta_it = eta; from inside its reciprocal: the suite's convention.
    outside, inside = ml.mitsuba_dielectric(0.5, 1.5), ml.mitsuba_dielectric(-0.5, 1.5)
    assert outside["eta_it"] == 1.5 and abs(inside["eta_it"] - 1 / 1.5) < 1e-7
    assert inside["f"] == 1.0 and inside["cos_t"] == 0.0  # 60 deg inside glass: total internal reflection


def test_polarized_powers_average_to_the_unpolarized_reflectance():
    for cos_i, eta in ((0.5, 1.5), (0.9, 1.333), (-0.9, 1.5), (0.1, 2.42)):
        d = ml.mitsuba_dielectric(cos_i, eta)
        r = 0.5 * (math.hypot(*d["a_s"]) ** 2 + math.hypot(*d["a_p"]) ** 2)
        assert abs(r - d["f"]) < 1e-6  # both float32: a few ulps of values below 1


def test_exact_refraction_obeys_snell():
    wi = ml.unit([0.6, 0.0, 0.8])
    t = ml.exact_directions(wi, [0.0, 0.0, 1.0], 1.5)["refract"]
    assert abs(math.hypot(t[0], t[1]) * 1.5 - math.hypot(wi[0], wi[1])) < 1e-12 and t[2] < 0
    assert ml.exact_directions([0.8, 0.0, -0.6], [0.0, 0.0, 1.0], 1.5)["refract"] is None  # TIR


def test_grid_reaches_tir_grazing_and_metals():
    doc = ml.build_reference()
    assert any(c["exact"]["tir"] for c in doc["dielectric"])
    assert any(c["cos_i"] == 0.0 for c in doc["dielectric"])
    assert any(c["kappa"] > 3 for c in doc["conductor"])
    assert any(c["exact"]["refract"] is None for c in doc["directions"])

