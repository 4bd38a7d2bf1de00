"""Evaluates cases exported by the Rust harness with Mitsuba 3 (float32).

    .venv/bin/python python-checks/mitsuba_eval.py CASES_JSON RESULTS_JSON

``optics validate`` writes ``cases.json`` (schema ``law-cases/1``, see
``validation/README.md``): a list of inputs, each tagged by ``law``
(``fresnel``, ``fresnel_conductor``, ``directions``). This writes
``results.json`` (schema ``law-results/1``): one result per case, in order,
holding Mitsuba's outputs under the names the Rust side reads (``f``,
``cos_t``, ``reflect``, ``refract``). The Mitsuba calls and conventions are
those of ``mitsuba_laws.py``.
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mitsuba_laws as ml  # noqa: E402
from atomic_write import write_text

CASES_SCHEMA, RESULTS_SCHEMA = "law-cases/1", "law-results/1"


def evaluate(case):
    law = case["law"]
    if law == "fresnel":
        d = ml.mitsuba_dielectric(case["cos_i"], case["eta"])
        return {"f": d["f"], "cos_t": d["cos_t"]}
    if law == "fresnel_conductor":
        return {"f": ml.mitsuba_conductor(case["cos_i"], case["n"], case["kappa"])["f"]}
    if law == "directions":
        return ml.mitsuba_directions(case["wi"], case["n"], case["eta"])
    raise ValueError(f"unknown law {law!r}")


def main(cases_path, results_path):
    with open(cases_path, encoding="utf-8") as fh:
        doc = json.load(fh)
    if doc.get("schema") != CASES_SCHEMA:
        sys.exit(f"{cases_path}: schema {doc.get('schema')!r}, expected {CASES_SCHEMA!r}")
    results = []
    for i, case in enumerate(doc["cases"]):
        try:
            results.append(evaluate(case))
        except (KeyError, TypeError, ValueError) as error:
            sys.exit(f"{cases_path}: cases[{i}]: {error!r}")
    out = {"schema": RESULTS_SCHEMA,
           "evaluator": f"Mitsuba {ml.mi.__version__} ({ml.VARIANT}, float32)",
           "results": results}
    write_text(results_path, json.dumps(out, allow_nan=False))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: mitsuba_eval.py CASES_JSON RESULTS_JSON")
    main(sys.argv[1], sys.argv[2])
