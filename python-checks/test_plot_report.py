"""Checks of the report figure script (python3 -m pytest -q python-checks)."""
import json
import os
import sys

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_report  # noqa: E402


def tiny_report():
    angles = [0.0, 45.0, 89.0]
    return {"schema": "validation-report/2",
            "fresnel_curves": [{"label": "glass, from outside", "angle_deg": angles, "exact": [0.04, 0.05, 0.9],
                                "schlick-incident": [0.04, 0.045, 0.95], "schlick-rarer": [0.04, 0.045, 0.95],
                                "mitsuba": [0.04, 0.05, 0.9]}],
            "metal_spectra": [{"metal": "gold", "angle_deg": 0.0, "wavelength_nm": [400.0, 500.0, 600.0],
                               "exact": [0.4, 0.5, 0.9], "schlick": [0.4, 0.5, 0.9]}],
            "metal_colours": [{"metal": "gold", "angle_deg": a, "method": m, "srgb": [1.0, 0.9, 0.6],
                               "lab": [90.0, 1.0, 38.0], "delta_e_2000": 0.0 if m.startswith("spectral") else 5.0}
                              for a in angles for m in ("spectral (exact)", "course RGB")],
            "metal_delta_e": [{"metal": "gold", "method": "course RGB", "delta_e_2000": 5.0, "at_angle_deg": 0.0}],
            "technique_curves": {
                "refraction": [{"label": "into water, c = 1", "angle_deg": angles, "error_deg": [0.0, 9.0, 7.8]}],
                "fresnel_fits": [{"label": "glass", "angle_deg": angles, "exact": [0.04, 0.05, 0.9],
                                  "fitted": [0.046, 0.05, 0.85], "schlick": [0.04, 0.045, 0.95],
                                  "form": [0.046, 0.912, 4.96]}],
                "envmap_distance": [{"label": "sky", "distance": [6.0, 12.0, 24.0], "rel_rmse": [0.08, 0.04, 0.02],
                                     "delta_e_mean": [3.0, 1.5, 0.8], "fitted_exponent": -1.0}]}}


def test_every_figure_is_drawn(tmp_path, capsys):
    report = tmp_path / "report.json"
    report.write_text(json.dumps(tiny_report()))
    plot_report.main(str(report), str(tmp_path / "figures"))
    listed = capsys.readouterr().out.split()
    assert listed == ["fresnel_curves.png", "fresnel_errors.png", "metal_spectra.png", "metal_swatches.png",
                      "metal_delta_e.png", "techniques.png"]
    for name in listed:
        assert (tmp_path / "figures" / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_another_schema_is_refused(tmp_path):
    report = tmp_path / "report.json"
    report.write_text(json.dumps({**tiny_report(), "schema": "validation-report/999"}))
    with pytest.raises(SystemExit):
        plot_report.main(str(report), str(tmp_path / "figures"))
