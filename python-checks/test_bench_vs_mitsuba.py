"""The benchmark's statistics against cases with a known answer (the
variance of a known noise, Student's t's tabulated quantiles, an image
shifted by many standard errors), and one ``--quick`` run end to end."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench_statistics as stats  # noqa: E402
import bench_vs_mitsuba as bench  # noqa: E402
import mitsuba_render as mr  # noqa: E402

import mitsuba as mi  # noqa: E402


def noisy(mean, sigma, seed, shape=(24, 32, 3)):
    return mean + sigma * np.random.default_rng(seed).standard_normal(shape)


def test_pair_variance_is_the_variance_of_one_render():
    # Two renders of N(0.5, 0.1^2) noise: 2304 values, so the estimate of
    # sigma^2 = 0.01 has a relative standard error sqrt(2 / 2304) = 3 %; 15 % is 5 of them.
    v = stats.pair_variance(noisy(0.5, 0.1, 1), noisy(0.5, 0.1, 2))
    assert abs(v - 0.01) < 0.15 * 0.01, v


def test_critical_t_is_students():
    # Two-sided 5 % quantiles of Student's t (any table): 12.706 at 1 dof,
    # 2.571 at 5, 1.960 as the dof grow; 4 digits as tabulated.
    for dof, expected in [(1, 12.706), (5, 2.571), (10**6, 1.960)]:
        assert abs(stats.two_sided_critical_t(0.05, dof) - expected) < 1e-3, dof


def test_guarded_variance_takes_the_neighbourhoods_mean_where_larger():
    variance = np.zeros((3, 3, 3))
    variance[1, 1] = 9.0
    guarded = stats.guarded_variance(variance)
    # The centre keeps its own 9; a corner sees it among 4 pixels: 9 / 4.
    assert guarded[1, 1, 0] == 9.0 and guarded[0, 0, 0] == 9.0 / 4 and guarded[0, 1, 0] == 9.0 / 6


def renders(mean, count, first_seed, sigma=0.05):
    return [noisy(mean, sigma, first_seed + k) for k in range(count)]


def test_renders_of_one_image_agree():
    result = stats.agreement(renders(0.5, 6, 0), renders(0.5, 6, 100), 0.01)
    assert result["agrees"], result


def test_a_shifted_image_disagrees():
    # A 4 % shift of the mean. A render's image mean has a standard
    # deviation of 0.05 / sqrt(768) = 1.8e-3, the difference of six against
    # six 1.8e-3 sqrt(2 / 6) = 1.04e-3, so 0.02 is t = 19, past the critical
    # t at 0.005 / 3 with 5 dof (6.0) and the tolerance (5.1e-4); a pixel's
    # own t is 0.02 / (0.05 sqrt(2 / 6)) = 0.7, far below its threshold.
    result = stats.agreement(renders(0.52, 6, 0), renders(0.5, 6, 100), 0.01)
    assert not result["agrees"] and all(c["fails"] for c in result["image_mean"]), result
    assert result["pixels"]["failed"] == 0


def test_one_wrong_pixel_disagrees():
    # One pixel-channel 50 standard errors (1.44) off, past the critical t
    # at 0.005 / 2304 with 5 dof (about 30): the image mean of its channel
    # moves by 1.44 / 768 = 1.9e-3, t = 1.8, so only the per-pixel test sees it.
    ours = renders(0.5, 6, 0)
    for image in ours:
        image[3, 4, 1] += 50 * 0.05 * (2 / 6) ** 0.5
    result = stats.agreement(ours, renders(0.5, 6, 100), 0.01)
    assert not result["agrees"] and result["pixels"]["failed"] == 1, result


def test_the_scenes_are_the_path_checks():
    names = bench.bench_scenes()
    assert "kaleidoscope" not in names and "normals" not in names  # PATH_SKIPPED, NOT_A_RADIANCE
    assert "kaleidoscope_lit" in names and "gold_spheres" in names


def test_lambert_replaces_course_rough_with_its_diffuse_colour():
    scene = json.loads(mr.scene_text("gold_spheres")[1])
    measured = bench.measured_scene(scene, "lambert")
    assert measured["materials"]["green"] == {"type": "lambert", "albedo": [0.1, 0.8, 0.3]}
    assert measured["materials"]["gold"] == scene["materials"]["gold"]
    assert bench.measured_scene(scene, "course") == scene


def optics_binary():
    """The optics binary the tests of the workspace built (CI runs ``cargo
    test`` first), else a debug build made here."""
    target = os.environ.get("CARGO_TARGET_DIR", os.path.join(mr.ROOT, "target"))
    for profile in ("release", "debug"):
        path = os.path.join(target, profile, "optics")
        if os.access(path, os.X_OK):
            return path
    subprocess.run(["cargo", "build", "--quiet", "-p", "optics"], cwd=mr.ROOT, check=True)
    return os.path.join(target, "debug", "optics")


def test_quick_run_writes_the_versioned_record(tmp_path):
    # In its own process, as a user runs it: the run sets Mitsuba's variant
    # and thread count for the whole process, which the other tests in this
    # one should not inherit.
    out = tmp_path / "bench.json"
    run = subprocess.run(
        [sys.executable, os.path.join(os.path.dirname(__file__), "bench_vs_mitsuba.py"),
         "--quick", "--scenes", "first_red_sphere,diffuse", "--variants", "scalar_rgb",
         "--optics", optics_binary(), "--out", str(out)],
        capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    document = json.loads(out.read_text())
    assert document["schema"] == "bench-vs-mitsuba/1"
    assert document["machine"]["cores"] == os.cpu_count() and document["date"]
    assert [e["name"] for e in document["scenes"]] == ["first_red_sphere", "diffuse"]
    for entry in document["scenes"]:
        assert len(entry["pairs"]) == 1 and entry["agreement"]["agrees"], entry["agreement"]
        # The verdict is the agreement's, recorded once.
        assert entry["agreement"]["images"] == "agree" and "images" not in entry, entry
        assert entry["spp"] >= 1 and entry["time_ratio"]["median"] > 0
        pair = entry["pairs"][0]
        expected = (pair["mitsuba"]["variance"] * sum(pair["mitsuba"]["seconds"])) / (
            pair["tracer"]["variance"] * sum(pair["tracer"]["seconds"]))
        assert entry["efficiency_ratio"]["median"] == pytest.approx(expected, rel=1e-12)
    assert "| `first_red_sphere` | scalar_rgb |" in run.stdout


def test_too_few_pairs_and_unknown_scenes_are_refused(tmp_path):
    with pytest.raises(SystemExit):
        bench.parse(["--pairs", "2"])
    assert bench.main(["--scenes", "kaleidoscope", "--optics", sys.executable, "--out", str(tmp_path / "x")]) == 1


def test_the_documents_get_the_table_and_summary_between_their_markers(tmp_path):
    def entry(name, variant, efficiency, time, comparable=True):
        ratio = {"median": efficiency, "min": efficiency * 0.9, "max": efficiency * 1.1}
        return {"name": name, "variant": variant, "spp": 64, "comparable": comparable, "mitsuba_bsdf": "native",
                "seconds": {"tracer": {"median": 1.0}, "mitsuba": {"median": time}},
                "time_ratio": {"median": time, "min": time, "max": time},
                "efficiency_ratio": ratio if comparable else None, "load_average": {"median": 1.0}}
    scenes = [entry("a", "scalar_rgb", 2.0, 3.0), entry("b", "scalar_rgb", 8.0, 3.0),
              entry("c", "scalar_rgb", 1.0, 1.0, comparable=False)]
    scenes[1]["agreement"] = {"images": "agree under Mitsuba's offsets"}
    document = {"command": "python-checks/bench_vs_mitsuba.py --docs", "date": "2026-12-03T10:00:00Z",
                "machine": {"cpu": "Test CPU", "platform": "x", "cores": 2, "load_average_at_end": [1.5, 1, 1]},
                "scenes": scenes, "not_run": {"llvm_ad_rgb": "no libLLVM"},
                "summary": [bench.summary(scenes, "scalar_rgb")]}
    results_md, readme = tmp_path / "results.md", tmp_path / "README.md"
    results_md.write_text("# Results\n\n<!-- results: bench-vs-mitsuba -->\nold\n<!-- /results: bench-vs-mitsuba -->\nafter\n")
    readme.write_text("# Readme\n")
    bench.write_docs(document, str(results_md), str(readme))
    text = results_md.read_text()
    assert "old" not in text and text.endswith("<!-- /results: bench-vs-mitsuba -->\nafter\n")
    assert ("Measured by `python-checks/bench_vs_mitsuba.py --docs` on Test CPU, 2 threads (load average 1.50), "
            "2026-12-03") in text
    assert "| `a` | scalar_rgb |" in text and "| geometric mean (2 scenes) | scalar_rgb |" in text
    assert "| agree | 1.0 |" in text and "| agree under Mitsuba's offsets | 1.0 |" in text
    summary = readme.read_text()
    assert summary.startswith("# Readme\n\n<!-- results: bench-vs-mitsuba-summary -->\n")
    # The geometric mean of 2 and 8 is 4; the worst scene is a, the best b.
    assert "4.00× Mitsuba's, geometric mean over 2 scenes; from 2.00× (`a`) to 8.00× (`b`)" in summary
    assert "`c` (scalar_rgb)" in summary and "`llvm_ad_rgb` not run: no libLLVM" in summary
    # Written again, the section is replaced, not appended twice.
    bench.write_docs(document, str(results_md), str(readme))
    assert readme.read_text() == summary and results_md.read_text() == text


def test_docs_are_written_only_by_a_full_run(tmp_path):
    assert bench.main(["--docs", "--quick", "--optics", sys.executable, "--out", str(tmp_path / "x")]) == 1
    assert bench.main(["--docs", "--scenes", "diffuse", "--optics", sys.executable, "--out", str(tmp_path / "x")]) == 1


def test_a_table_that_is_not_a_record_is_refused_by_name(tmp_path, capsys):
    for text in ("not json", "[1, 2]", '{"schema": "other/1"}'):
        path = tmp_path / "record.json"
        path.write_text(text)
        assert bench.main(["--table", str(path), "--docs"]) == 1, text
        assert f"--table {path}" in capsys.readouterr().err
    assert bench.main(["--table", str(tmp_path / "missing.json")]) == 1


def test_a_difference_the_tracer_makes_too_under_mitsubas_offset_rule_is_not_a_disagreement():
    # The 4 % shift of test_a_shifted_image_disagrees: the tracer's own
    # renders disagree; where its renders under Mitsuba's offset rule agree,
    # the light moved is Mitsuba's offsets' (agree under them); where those
    # disagree too, the images disagree; renders that agree never ask.
    shifted, theirs = renders(0.52, 6, 0), renders(0.5, 6, 100)
    verdict = bench.judged(shifted, theirs, 0.01, lambda: renders(0.5, 6, 200))
    assert verdict["images"] == "agree under Mitsuba's offsets", verdict
    assert not verdict["agrees"] and verdict["under_mitsuba_offsets"]["agrees"]
    verdict = bench.judged(shifted, theirs, 0.01, lambda: renders(0.52, 6, 200))
    assert verdict["images"] == "disagree", verdict

    def never():
        raise AssertionError("asked for renders under Mitsuba's offsets where the images agree")

    assert bench.judged(renders(0.5, 6, 0), theirs, 0.01, never)["images"] == "agree"


def test_mitsubas_path_escapes_one_scattering_after_the_suites_depth(tmp_path):
    # A copper mirror filling the view under a white sky shows the sky only
    # through one scattering. The suite's max_depth 0 allows none: black.
    # Mitsuba's path at the translation of 0 (its max_depth 2, direct light
    # at the first vertex) samples the mirror's lobe and counts the sky it
    # escapes to, as the suite's max_depth 1 does: so the tracer's renders
    # held against Mitsuba under its offset rule, where each escape counts
    # (inside_water), run at ESCAPE_MAX_DEPTH, one past the translated
    # depth. Within the harness's float32 tolerance, 1e-3 relative: the
    # copper's reflectance varies by 2e-3 over the view (cos 0.97 to 1),
    # and both sides jitter 16 samples over each of 192 pixels.
    s = {"version": 1, "image": {"width": 16, "height": 12},
         "camera": {"type": "look_at", "eye": [0, 0, 1], "target": [0, 0, 0], "up": [0, 1, 0],
                    "fov_y_deg": 30, "near": 1e-3, "far": 100},
         "background": [1, 1, 1],
         "materials": {"copper": {"type": "conductor", "n": [0.2, 0.924, 1.102], "kappa": [3.912, 2.452, 2.142]}},
         "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "material": "copper"}]}
    translated = 0
    d = mr.mitsuba_scene(s, 16, 12, translated)
    d["sensor"]["film"]["rfilter"] = {"type": "box"}
    mitsuba = np.array(mi.render(mi.load_dict(d, optimize=False), seed=0, spp=16), dtype=np.float64)

    def tracer(max_depth):
        path = os.path.join(tmp_path, "mirror.json")
        with open(path, "w", encoding="utf-8") as f:
            json.dump(s, f)
        png = os.path.join(tmp_path, "mirror.png")
        subprocess.run([optics_binary(), "render", path, "-o", png, "--integrator", "path",
                        "--max-depth", str(max_depth), "--pixel-filter", "box", "--spp", "16"],
                       check=True, capture_output=True)
        return bench.read_pfm(png[:-4] + ".pfm")

    escape = translated + bench.ESCAPE_MAX_DEPTH - mr.PATH_MAX_DEPTH
    assert np.all(tracer(translated) == 0.0)
    ours, theirs = tracer(escape).mean(axis=(0, 1)), mitsuba.mean(axis=(0, 1))
    assert np.all(theirs > 0.4), theirs  # copper reflects half the light or more
    assert np.all(np.abs(ours - theirs) <= 1e-3 * theirs), (ours, theirs)
