"""The Pareto plot script: it draws a sweep and refuses what is not one."""
import json

import pytest

import plot_tradeoff


def sweep():
    def point(label, seconds, rmse, pareto):
        errors = {"rel_rmse": rmse, "delta_e_mean": rmse * 10, "delta_e_p99": rmse * 30,
                  "flip_mean": rmse / 2}
        return {"label": label, "seconds_median": seconds, "errors": errors, "pareto": pareto}

    return {
        "schema": "optics.tradeoff",
        "version": 1,
        "scene": "s.json",
        "width": 4,
        "height": 3,
        "command": "optics tradeoff s.json",
        "machine": "test",
        "date": "2026-12-04",
        "points": [
            point("fast", 0.1, 0.5, ["rel_rmse", "delta_e_mean", "delta_e_p99", "flip_mean"]),
            point("slow and worse", 1.0, 0.6, []),
            point("exact", 2.0, 0.0, ["rel_rmse", "delta_e_mean", "delta_e_p99", "flip_mean"]),
        ],
    }


def test_a_sweep_draws_a_png(tmp_path):
    path = tmp_path / "s.json"
    path.write_text(json.dumps(sweep()))
    out = tmp_path / "s.png"
    plot_tradeoff.main(["plot_tradeoff.py", str(path), str(out)])
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert not (tmp_path / "s.png.tmp").exists()


def test_a_sweep_from_before_flip_still_draws(tmp_path):
    old = sweep()
    for p in old["points"]:
        del p["errors"]["flip_mean"]
    path = tmp_path / "old.json"
    path.write_text(json.dumps(old))
    out = tmp_path / "old.png"
    plot_tradeoff.main(["plot_tradeoff.py", str(path), str(out)])
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_the_front_is_the_marked_points_by_time():
    names = [p["label"] for p in plot_tradeoff.front(sweep()["points"], "rel_rmse")]
    assert names == ["fast", "exact"]


def test_another_schema_is_refused(tmp_path):
    bad = sweep()
    bad["version"] = 3
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(bad))
    with pytest.raises(SystemExit, match="not an optics.tradeoff version 1 or 2"):
        plot_tradeoff.load(str(path))


def test_coinciding_points_share_one_label():
    points = sweep()["points"] + [
        {"label": "twin", "seconds_median": 0.105, "errors": {"rel_rmse": 0.5}, "pareto": []}
    ]
    assert plot_tradeoff.labels(points, "rel_rmse") == ["fast, twin", "slow and worse", "exact", None]
