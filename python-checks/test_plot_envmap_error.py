"""The environment-map error plot: it draws a record and refuses what is not one."""
import pytest

import plot_envmap_error


def record():
    def row(kind, d, k):
        return {"surroundings": kind, "distance": d,
                "errors": {"rel_rmse": k / d, "delta_e_mean": 10 * k / d}}

    sweep = [row("sky", d, 0.4) for d in (5, 10, 20)] + [row("objects", d, 2.0) for d in (2, 4, 8)]
    exponents = {"rel_rmse": -1.0, "delta_e_mean": -1.0}
    return {
        "schema": "optics.envmap_vs_traced",
        "version": 1,
        "command": "cargo run --release -p optics --example envmap_vs_traced",
        "resolution": {"image": 8, "cube": 8},
        "sweep": sweep,
        "fitted_exponents": {"sky": exponents, "objects": exponents},
    }


def test_draws_a_record(tmp_path):
    png = tmp_path / "plot.png"
    assert plot_envmap_error.draw(record(), str(png)) == str(png)
    assert png.read_bytes().startswith(b"\x89PNG")


def test_refuses_another_schema(tmp_path):
    path = tmp_path / "other.json"
    path.write_text('{"schema": "optics.tradeoff", "version": 1}')
    with pytest.raises(SystemExit):
        plot_envmap_error.load(str(path))
