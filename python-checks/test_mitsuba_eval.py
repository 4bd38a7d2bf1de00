"""Checks of the evaluator of exported cases (python3 -m pytest -q python-checks)."""
import json
import os
import sys

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mitsuba_eval as me  # noqa: E402


def run(tmp_path, cases, schema="law-cases/1"):
    path, out = tmp_path / "cases.json", tmp_path / "results.json"
    path.write_text(json.dumps({"schema": schema, "seed": 1, "cases": cases}))
    me.main(str(path), str(out))
    return json.loads(out.read_text())


def test_one_result_per_case_in_order(tmp_path):
    doc = run(tmp_path, [{"law": "fresnel", "cos_i": 1.0, "eta": 1.5},
                         {"law": "fresnel_conductor", "cos_i": 1.0, "n": 1.5, "kappa": 0.0},
                         {"law": "directions", "wi": [0.0, 0.0, 1.0], "n": [0.0, 0.0, 1.0], "eta": 1.5}])
    assert doc["schema"] == "law-results/1" and len(doc["results"]) == 3
    assert abs(doc["results"][0]["f"] - 0.04) < 1e-7 and abs(doc["results"][1]["f"] - 0.04) < 1e-6
    assert doc["results"][2]["refract"] == [0.0, 0.0, -1.0]  # straight through, away on the inside


def test_unknown_law_and_schema_are_refused(tmp_path):
    with pytest.raises(SystemExit):
        run(tmp_path, [{"law": "snell", "x": 1}])
    with pytest.raises(SystemExit):
        run(tmp_path, [], schema="law-cases/2")
