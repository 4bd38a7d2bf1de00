"""Figures of a validation report, drawn with matplotlib from ``report.json``.

    .venv/bin/python python-checks/plot_report.py validation/out/report.json validation/out/figures

``optics validate`` runs this after writing ``report.json`` (schema
``validation-report/2``, see ``validation/README.md``); it reads only that file
and writes PNGs into the figure directory, printing each file name on its own
line. The numbers are the report's; nothing is recomputed here.
"""
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SCHEMA = "validation-report/2"


def _save(fig, path):
    """Saves under a temporary name and renames, so no partial PNG is left behind."""
    tmp = path + ".tmp"
    fig.savefig(tmp, dpi=90, format="png")
    plt.close(fig)
    os.replace(tmp, path)
    return path


def _curve_panels(n):
    """A figure of `n` curve panels, three to a row, 4 × 3 inches each."""
    rows, cols = math.ceil(n / 3), 3
    return plt.subplots(rows, cols, figsize=(4 * cols, 3 * rows), squeeze=False)


def _finish_panels(fig, axes, used, path, **legend):
    """Hides the panels past the first `used`, puts the legend on the first
    and saves the figure to `path`."""
    for ax in list(axes.flat)[used:]:
        ax.axis("off")
    axes.flat[0].legend(**legend)
    fig.tight_layout()
    return _save(fig, path)


def fresnel_curves(report, out):
    curves = report["fresnel_curves"]
    fig, axes = _curve_panels(len(curves))
    for ax, c in zip(axes.flat, curves):
        ax.plot(c["angle_deg"], c["exact"], "k-", label="exact")
        ax.plot(c["angle_deg"], c["schlick-incident"], "b--", label="Schlick, incident cos θi (schlick-incident)")
        ax.plot(c["angle_deg"], c["schlick-rarer"], "g-.", label="Schlick, rarer medium's cos (schlick-rarer)")
        ax.plot(c["angle_deg"], c["mitsuba"], "r:", lw=2, label="Mitsuba 3")
        ax.set_title(c["label"], fontsize=10)
        ax.set_xlim(0, 90)
        ax.set_ylim(0, 1.02)
        ax.set_xlabel("angle of incidence (deg)")
        ax.set_ylabel("reflectance")
    return _finish_panels(fig, axes, len(curves), os.path.join(out, "fresnel_curves.png"), fontsize=8)


def fresnel_errors(report, out):
    curves = report["fresnel_curves"]
    fig, axes = _curve_panels(len(curves))
    floor = 1e-10  # below any float32 rounding; zeros are drawn here
    for ax, c in zip(axes.flat, curves):
        incident = [max(abs(s - e), floor) for s, e in zip(c["schlick-incident"], c["exact"])]
        rarer = [max(abs(s - e), floor) for s, e in zip(c["schlick-rarer"], c["exact"])]
        mitsuba = [max(abs(m - e), floor) for m, e in zip(c["mitsuba"], c["exact"])]
        ax.semilogy(c["angle_deg"], incident, "b-", label="|schlick-incident − exact|")
        ax.semilogy(c["angle_deg"], rarer, "g-.", label="|schlick-rarer − exact|")
        ax.semilogy(c["angle_deg"], mitsuba, "r-", label="|Mitsuba (float32) − exact|")
        ax.set_title(c["label"], fontsize=10)
        ax.set_xlim(0, 90)
        ax.set_ylim(floor, 2)
        ax.set_xlabel("angle of incidence (deg)")
    return _finish_panels(fig, axes, len(curves), os.path.join(out, "fresnel_errors.png"), fontsize=8)


def metal_swatches(report, out):
    colours = report["metal_colours"]
    metals = list(dict.fromkeys(c["metal"] for c in colours))
    angles = sorted(set(c["angle_deg"] for c in colours))
    fig, axes = plt.subplots(len(metals), 1, figsize=(1.6 * len(angles) + 5, 2.0 * len(metals)), squeeze=False)
    for ax, metal in zip(axes.flat, metals):
        methods = list(dict.fromkeys(c["method"] for c in colours if c["metal"] == metal))
        for row, method in enumerate(methods):
            for col, angle in enumerate(angles):
                cell = next(c for c in colours if c["metal"] == metal and c["method"] == method and c["angle_deg"] == angle)
                rgb = [min(max(x, 0.0), 1.0) for x in cell["srgb"]]
                ax.add_patch(plt.Rectangle((col, -row - 1), 0.95, 0.9, color=rgb))
                if method != "spectral (exact)":
                    de = cell["delta_e_2000"]
                    ax.text(col + 0.47, -row - 0.55, f"{de:.2f}", ha="center", va="center", fontsize=7,
                            color="black" if sum(rgb) > 1.2 else "white")
        ax.set_xlim(0, len(angles))
        ax.set_ylim(-len(methods), 0)
        ax.set_xticks([i + 0.47 for i in range(len(angles))], [f"{a:g}°" for a in angles])
        ax.set_yticks([-i - 0.55 for i in range(len(methods))], methods, fontsize=7)
        ax.set_title(f"{metal}: colour by method and angle (ΔE00 from spectral)", fontsize=9)
        ax.tick_params(length=0)
        for side in ax.spines.values():
            side.set_visible(False)
    fig.subplots_adjust(left=0.3, right=0.98, top=0.95, bottom=0.04, hspace=0.45)
    path = os.path.join(out, "metal_swatches.png")
    return _save(fig, path)


def metal_spectra(report, out):
    spectra = report["metal_spectra"]
    metals = list(dict.fromkeys(s["metal"] for s in spectra))
    rows, cols = math.ceil(len(metals) / 2), 2
    fig, axes = plt.subplots(rows, cols, figsize=(11, 3.4 * rows), squeeze=False)
    for ax, metal in zip(axes.flat, metals):
        for i, s in enumerate(x for x in spectra if x["metal"] == metal):
            colour = plt.cm.viridis(i / 5)
            ax.plot(s["wavelength_nm"], s["exact"], "-", color=colour, label=f"{s['angle_deg']:g}° exact")
            ax.plot(s["wavelength_nm"], s["schlick"], "--", color=colour, label=f"{s['angle_deg']:g}° Schlick")
        ax.set_title(f"{metal}: reflectance spectrum", fontsize=10)
        ax.set_xlabel("wavelength (nm)")
        ax.set_ylabel("reflectance")
        ax.set_xlim(360, 780)
    return _finish_panels(fig, axes, len(metals), os.path.join(out, "metal_spectra.png"), fontsize=6, ncol=2)


def delta_e_table(report, out):
    rows = report["metal_delta_e"]
    metals = list(dict.fromkeys(r["metal"] for r in rows))
    methods = list(dict.fromkeys(r["method"] for r in rows))
    fig, ax = plt.subplots(figsize=(10, 4))
    width = 0.8 / len(methods)
    for i, method in enumerate(methods):
        xs, ys = [], []
        for j, metal in enumerate(metals):
            r = next((r for r in rows if r["metal"] == metal and r["method"] == method), None)
            if r is not None:
                xs.append(j + i * width)
                ys.append(r["delta_e_2000"])
        ax.bar(xs, ys, width, label=method)
    ax.axhline(1.0, color="grey", lw=0.8, ls="--")
    ax.set_xticks([j + 0.4 - width / 2 for j in range(len(metals))], metals)
    ax.set_ylabel("worst CIEDE2000 over angles")
    ax.set_title("Colour error of the shortcuts against the spectral colour (dashed: just noticeable)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    path = os.path.join(out, "metal_delta_e.png")
    return _save(fig, path)


def techniques(report, out):
    """The slides' cheap refraction's angle from Snell's law, the fitted
    empirical Fresnel form beside the exact law and Schlick, and the
    environment-mapped mirror's error as its surroundings move away."""
    curves = report["technique_curves"]
    fits = curves["fresnel_fits"]
    sweeps = curves.get("envmap_distance", [])
    panels = 1 + len(fits) + (1 if sweeps else 0)
    fig, axes = plt.subplots(1, panels, figsize=(4 * panels, 3.2), squeeze=False)
    ax = axes.flat[0]
    for c in curves["refraction"]:
        ax.plot(c["angle_deg"], c["error_deg"], label=c["label"])
    ax.set_title("cheap refraction against Snell's law", fontsize=10)
    ax.set_xlim(0, 90)
    ax.set_xlabel("angle of incidence (deg)")
    ax.set_ylabel("angle between the rays (deg)")
    ax.legend(fontsize=7)
    for ax, c in zip(list(axes.flat)[1:], fits):
        bias, scale, power = c["form"]
        ax.plot(c["angle_deg"], c["exact"], "k-", label="exact")
        ax.plot(c["angle_deg"], c["fitted"], "g--",
                label=f"fitted: {bias:.3f} + {scale:.3f} (1 + I·N)^{power:.2f}")
        ax.plot(c["angle_deg"], c["schlick"], "b:", lw=2, label="Schlick")
        ax.set_title(f"empirical Fresnel, {c['label']}", fontsize=10)
        ax.set_xlim(0, 90)
        ax.set_ylim(0, 1.02)
        ax.set_xlabel("angle of incidence (deg)")
        ax.legend(fontsize=7)
    if sweeps:
        ax = axes.flat[-1]
        for c in sweeps:
            ax.loglog(c["distance"], c["rel_rmse"], "o-",
                      label=f"{c['label']}: RMSE ∝ d^{c['fitted_exponent']:.2f}")
        ticks = sorted({d for c in sweeps for d in c["distance"]})
        ax.set_xticks(ticks, [f"{d:g}" for d in ticks], minor=False)
        ax.set_xticks([], minor=True)
        ax.set_title("environment map against the traced mirror", fontsize=10)
        ax.set_xlabel("distance of the surroundings (mirror radii)")
        ax.set_ylabel("relative RMSE over the mirror")
        ax.legend(fontsize=7)
    fig.tight_layout()
    return _save(fig, os.path.join(out, "techniques.png"))


def main(report_path, out):
    with open(report_path, encoding="utf-8") as fh:
        report = json.load(fh)
    if report.get("schema") != SCHEMA:
        sys.exit(f"{report_path}: schema {report.get('schema')!r}, expected {SCHEMA!r}")
    os.makedirs(out, exist_ok=True)
    drawn = []
    if report["fresnel_curves"]:
        drawn += [fresnel_curves(report, out), fresnel_errors(report, out)]
    if report.get("metal_spectra"):
        drawn.append(metal_spectra(report, out))
    if report["metal_colours"]:
        drawn += [metal_swatches(report, out), delta_e_table(report, out)]
    if report.get("technique_curves", {}).get("refraction"):
        drawn.append(techniques(report, out))
    for path in drawn:
        print(os.path.basename(path))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_report.py REPORT_JSON FIGURE_DIR")
    main(sys.argv[1], sys.argv[2])
