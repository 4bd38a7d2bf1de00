"""Checks of the colorimetry and metals reference generators (python3 -m pytest -q python-checks)."""
import os
import sys
import warnings

import numpy as np

warnings.filterwarnings("ignore", message=".*SciPy.*")
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import colorimetry  # noqa: E402
import metals  # noqa: E402


def test_colour_science_reproduces_sharma_2005():
    # The paper prints four decimals: agreement within half a unit of the last one.
    for pair in colorimetry.build_reference()["delta_e_2000"]:
        assert abs(pair["delta_e_2000"] - pair["printed"]) <= 5e-5, pair


def test_perfect_white_is_the_d65_white():
    c = colorimetry.colour_of(np.ones(len(colorimetry.WAVELENGTHS)))
    assert abs(c["xyz"][1] - 1) < 1e-12
    assert abs(c["lab"][0] - 100) < 1e-9 and abs(c["lab"][1]) < 0.01 and abs(c["lab"][2]) < 0.01


def test_metal_tables_cover_the_visible_range():
    for _, symbol in metals.METALS:
        w, n, k = metals.read_metal(symbol)
        assert w[0] <= 360 and w[-1] >= 780 and all(x > 0 for x in n) and all(x > 0 for x in k)


def test_gold_is_yellow_and_silver_is_neutral():
    doc = metals.build_reference()
    gold, silver = doc["metals"][0], doc["metals"][1]
    assert gold["name"] == "gold" and gold["angles"][0]["lab"][2] > 30  # strongly yellow (b*)
    assert silver["name"] == "silver" and abs(silver["angles"][0]["lab"][1]) < 2


def _same_bytes(path, write, tmp_path, name):
    fresh = tmp_path / name
    write(str(fresh))
    with open(path, "rb") as a, open(fresh, "rb") as b:
        return a.read() == b.read()


def test_committed_colorimetry_reference_and_tables_are_up_to_date(tmp_path):
    fresh_json, fresh_rust = tmp_path / "c.json", tmp_path / "c.rs"
    colorimetry.main(str(fresh_json), str(fresh_rust))
    for committed, fresh in ((colorimetry.DEFAULT_JSON, fresh_json), (colorimetry.DEFAULT_RUST, fresh_rust)):
        with open(committed, "rb") as a, open(fresh, "rb") as b:
            assert a.read() == b.read(), f"regenerate with: {colorimetry.REGENERATE}"


def test_committed_metals_reference_is_up_to_date(tmp_path):
    assert _same_bytes(metals.DEFAULT_PATH, metals.main, tmp_path, "metals.json"), \
        f"regenerate with: {metals.REGENERATE}"
