"""Checks of the colorimetry and metals reference generators (python3 -m pytest -q python-checks)."""
import json
import os
import sys
import warnings

import numpy as np

warnings.filterwarnings("ignore", message=".*SciPy.*")
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import colorimetry  # noqa: E402
import metals  # noqa: E402
import reproduce  # noqa: E402
from reproduce import PATH_MEAN, PATH_STD  # noqa: E402


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


def test_only_the_colour_science_files_are_compared_with_a_tolerance():
    assert reproduce.tolerance_for(colorimetry.DEFAULT_JSON) == reproduce.BLAS_TOLERANCE
    assert reproduce.tolerance_for(metals.DEFAULT_PATH) == reproduce.BLAS_TOLERANCE
    for exact in (colorimetry.DEFAULT_RUST, "validation/reference/fresnel_mpmath.json",
                  "mitsuba_laws.json", "mitsuba_renders.json"):
        assert reproduce.tolerance_for(exact) == 0.0, exact


def test_only_mitsubas_path_statistics_are_float_arrays_with_a_tolerance():
    assert reproduce.f32_tolerances_for("validation/reference/mitsuba_renders.json") == {
        "mean_f16le_zlib": 1e-3, "std_bf16le_zlib": 1e-2, "offset_sensitivity_f16le_zlib": 0.0}
    for exact in (colorimetry.DEFAULT_JSON, metals.DEFAULT_PATH, "fresnel_mpmath.json",
                  "mitsuba_laws.json"):
        assert reproduce.f32_tolerances_for(exact) == {}, exact


def test_float_arrays_reproduce_within_their_tolerance_and_nothing_else_moves():
    import base64
    import struct
    import zlib
    f32 = lambda *v: base64.b64encode(struct.pack(f"<{len(v)}f", *v)).decode()  # noqa: E731
    f16 = lambda *v, level=9: base64.b64encode(zlib.compress(struct.pack(f"<{len(v)}e", *v), level)).decode()  # noqa: E731

    def bf16(*v, level=9):
        bits = struct.unpack(f"<{len(v)}I", struct.pack(f"<{len(v)}f", *v))
        raw = struct.pack(f"<{len(v)}H", *(b >> 16 for b in bits))
        return base64.b64encode(zlib.compress(raw, level)).decode()

    doc = {"path": {"mean_f16le_zlib": f16(0.5, 873.5), "std_bf16le_zlib": bf16(0.0, 7.7e7),
                    "offset_sensitivity_f16le_zlib": f16(0.0, 0.25)},
           "whitted": {"radiance_f32le": f32(0.25)}}
    committed = json.dumps(doc).encode()
    rule = reproduce.f32_tolerances_for("mitsuba_renders.json")
    # One float16 ulp of the mean (5.7e-4 relative), one bfloat16 ulp of
    # the standard deviation at 7.7e7 (below 7.8e-3), the sensitivity
    # compressed to other bytes (another zlib level).
    moved = {"path": {"mean_f16le_zlib": f16(0.5, 874.0), "std_bf16le_zlib": bf16(0.0, 7.7e7 * (1 + 7e-3)),
                      "offset_sensitivity_f16le_zlib": f16(0.0, 0.25, level=1)},
             "whitted": doc["whitted"]}
    assert reproduce.differences(committed, json.dumps(moved).encode(), f32_tolerances=rule) == []
    assert reproduce.differences(committed, json.dumps(moved).encode()) == ["the bytes differ"]
    path = doc["path"]
    for changed in ({"path": dict(path, mean_f16le_zlib=f16(0.5 + 2e-3, 873.5))},  # a mean beyond 1e-3
                    {"path": dict(path, std_bf16le_zlib=bf16(0.02, 7.7e7))},  # a deviation beyond 1e-2
                    {"path": dict(path, offset_sensitivity_f16le_zlib=f16(0.0, 0.2502))},  # any move
                    {"path": dict(path, mean_f16le_zlib=f16(float("nan"), 873.5))},  # NaN
                    {"path": dict(path, mean_f16le_zlib=f16(0.5))},  # a value lost
                    {"path": dict(path, mean_f16le_zlib="not base64!")},  # not an array
                    {"path": dict(path, mean_f16le_zlib=f32(0.5))},  # not zlib
                    {"path": path, "whitted": {"radiance_f32le": f32(0.25 + 1e-7)}}):
        changed.setdefault("whitted", doc["whitted"])
        found = reproduce.differences(committed, json.dumps(changed).encode(), f32_tolerances=rule)
        assert found, changed


def test_a_paths_statistics_reproduce_when_a_few_pixels_move_as_a_sample_does():
    import base64
    import struct
    import zlib

    def f16(v):
        return base64.b64encode(zlib.compress(struct.pack(f"<{len(v)}e", *v))).decode()

    def bf16(v):
        bits = struct.unpack(f"<{len(v)}I", struct.pack(f"<{len(v)}f", *v))
        return base64.b64encode(zlib.compress(struct.pack(f"<{len(v)}H", *(b >> 16 for b in bits)))).decode()

    # 30 000 pixels of mean 1 and deviation 8: a mean's standard error is
    # 8 / sqrt(64) = 1, a deviation's 8 / sqrt(126) = 0.71; at most three
    # elements (1e-4 of them) may move beyond the tolerances, each by at
    # most half of that.
    n = 30000
    mean, std = [1.0] * n, [8.0] * n
    doc = {"path": {"samples": 64, PATH_MEAN: f16(mean), PATH_STD: bf16(std)}}
    committed = json.dumps(doc).encode()
    rule = reproduce.f32_tolerances_for("mitsuba_renders.json")

    def moved(means=(), deviations=(), samples=64):
        m, s = list(mean), list(std)
        for i, v in means:
            m[i] = v
        for i, v in deviations:
            s[i] = v
        return json.dumps({"path": {"samples": samples, PATH_MEAN: f16(m), PATH_STD: bf16(s)}}).encode()

    assert reproduce.differences(committed, moved([(7, 1.4), (9, 0.6), (11, 1.25)], [(7, 8.25)]),
                                 f32_tolerances=rule) == []
    for changed in (moved([(7, 1.6)]),  # beyond half a standard error
                    moved([(i, 1.25) for i in range(4)]),  # four moved: more than 1e-4 of them
                    moved([(i, 1.01) for i in range(n)]),  # a shift of every pixel
                    moved([], [(7, 8.5)]),  # a deviation beyond half its standard error
                    moved([(7, 1.25)], samples=63)):  # the sample count is not a statistic
        assert reproduce.differences(committed, changed, f32_tolerances=rule), changed
    # Elsewhere nothing moves as a sample: the same arrays outside a path's
    # statistics (no sample count) hold to the tolerances alone.
    bare = {"path": {PATH_MEAN: f16(mean), PATH_STD: bf16(std)}}
    shifted = dict(bare["path"], **{PATH_MEAN: f16([1.25] + mean[1:])})
    assert reproduce.differences(json.dumps(bare).encode(), json.dumps({"path": shifted}).encode(),
                                 f32_tolerances=rule)


def test_reproduction_tolerates_blas_rounding_and_nothing_else():
    doc = {"schema": "x/1", "n": 3, "values": [0.1, -16.299011627332910, 1e-300]}
    committed = json.dumps(doc).encode()
    blas = dict(doc, values=[0.1 + 2.8e-17, -16.299011627332966, 1e-300])
    tolerance = reproduce.BLAS_TOLERANCE
    assert reproduce.differences(committed, json.dumps(blas).encode(), tolerance) == []
    assert reproduce.differences(committed, json.dumps(blas).encode()) == ["the bytes differ"]
    assert reproduce.spread(committed, json.dumps(blas).encode())[0] == 2
    for changed in (dict(doc, values=[0.1 + 1e-9, doc["values"][1], 1e-300]),  # a real change
                    dict(doc, values=[0.1, doc["values"][1], float("nan")]),  # NaN
                    dict(doc, values=[0.1, doc["values"][1]]),  # an element lost
                    dict(doc, n=4),  # an integer
                    dict(doc, schema="x/2"),  # a string
                    dict(doc, values=[0.1, doc["values"][1], "1e-300"]),  # a type
                    dict(doc, n=3.0),  # an integer turned float
                    {k: doc[k] for k in ("n", "schema", "values")}):  # key order
        found = reproduce.differences(committed, json.dumps(changed).encode(), tolerance)
        assert found, changed
    assert reproduce.differences(committed, b"{", tolerance)


def test_the_command_line_exits_0_1_or_2_as_a_process(tmp_path):
    import subprocess
    a, b = tmp_path / "metals.json", tmp_path / "fresh.json"
    a.write_text(json.dumps({"x": [1.0, 2.0]}))
    b.write_text(json.dumps({"x": [1.0, 2.0 + 1e-14]}))
    run = lambda *args: subprocess.run([sys.executable, reproduce.__file__, *map(str, args)],
                                       capture_output=True, text=True)
    assert run(a, b).returncode == 0
    b.write_text(json.dumps({"x": [1.0, 2.1]}))
    differs = run(a, b)
    assert differs.returncode == 1 and ".x[1]" in differs.stdout
    assert run(a, tmp_path / "missing.json").returncode == 2
    assert run(a, b, "--as").returncode == 2
    assert run(a).returncode == 2


def test_the_command_line_exits_1_where_a_file_does_not_reproduce(tmp_path):
    a, b = tmp_path / "metals.json", tmp_path / "fresh.json"
    a.write_text(json.dumps({"x": [1.0, 2.0]}))
    b.write_text(json.dumps({"x": [1.0, 2.0 + 1e-14]}))
    assert reproduce.main([str(a), str(b)]) == 0
    b.write_text(json.dumps({"x": [1.0, 2.1]}))
    assert reproduce.main([str(a), str(b)]) == 1
    assert reproduce.main([str(a), str(b), "--as", "fresnel_mpmath.json"]) == 1
