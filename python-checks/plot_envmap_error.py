"""The error of environment mapping against ray tracing as the surroundings
move away, drawn with matplotlib from the record the example writes.

    cargo run --release -p optics --example envmap_vs_traced -- docs/images
    .venv/bin/python python-checks/plot_envmap_error.py \
        docs/images/envmap_vs_traced.json docs/images/envmap_error_vs_distance.png

Two panels, log-log: the relative RMSE of radiance and the mean ΔE2000 of
the displayed image over the mirror's pixels, against the surroundings'
distance in mirror radii, for each surroundings, with the power law fitted
by the example (its exponent in the legend) and dashed guides of slope −1
and −1/2. It reads only that file; nothing is recomputed here but the
fitted lines' intercepts. Prints the PNG's path.
"""
import json
import math
import os
import sys

import matplotlib
import matplotlib.ticker

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SCHEMA = "optics.envmap_vs_traced"
VERSION = 1
MEASURES = [
    ("rel_rmse", "relative RMSE of radiance, mirror pixels"),
    ("delta_e_mean", "mean ΔE2000 of the displayed image, mirror pixels"),
]
NAMES = {"sky": "smooth sky (sphere of radius d)", "objects": "nine objects of radius 0.3 d"}


def load(path):
    """The record at `path`, refused unless it is the schema this draws."""
    with open(path, encoding="utf-8") as f:
        record = json.load(f)
    if record.get("schema") != SCHEMA or record.get("version") != VERSION:
        raise SystemExit(f"{path}: not an {SCHEMA} version {VERSION} record")
    return record


def draw(record, png):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, (measure, title) in zip(axes, MEASURES):
        for k, (kind, name) in enumerate(NAMES.items()):
            rows = [r for r in record["sweep"] if r["surroundings"] == kind]
            xs = [r["distance"] for r in rows]
            ys = [r["errors"][measure] for r in rows]
            slope = record["fitted_exponents"][kind][measure]
            # The fitted line through the points' geometric mean.
            mx = sum(math.log(x) for x in xs) / len(xs)
            my = sum(math.log(y) for y in ys) / len(ys)
            fit = [math.exp(my + slope * (math.log(x) - mx)) for x in xs]
            ax.plot(xs, ys, "o", color=f"C{k}", label=f"{name}: exponent {slope:.2f}")
            ax.plot(xs, fit, "-", color=f"C{k}", linewidth=1)
        distances = [r["distance"] for r in record["sweep"]]
        lo, hi = min(distances), max(distances)
        top = max(r["errors"][measure] for r in record["sweep"])
        for power, style in [(-1.0, "--"), (-0.5, ":")]:
            y0 = top * 1.5
            ax.plot([lo, hi], [y0, y0 * (hi / lo) ** power], style, color="grey", linewidth=0.8,
                    label=f"slope {power:g}")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ticks = [2, 4, 8, 16, 32, 64]
        ax.set_xticks(ticks, [str(t) for t in ticks])
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_xlabel("distance of the surroundings d, mirror radii")
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="both", linewidth=0.3)
        ax.legend(fontsize=7)
    res = record["resolution"]
    fig.suptitle(
        f"environment-mapped mirror sphere against traced, {res['image']}² pixels, "
        f"cube map {res['cube']}² per face: {record['command']}",
        fontsize=8,
    )
    fig.tight_layout()
    tmp = png + ".tmp"
    fig.savefig(tmp, dpi=80, format="png")
    plt.close(fig)
    os.replace(tmp, png)
    return png


def main(argv):
    if len(argv) != 3:
        raise SystemExit("usage: plot_envmap_error.py RECORD.json OUT.png")
    print(draw(load(argv[1]), argv[2]))


if __name__ == "__main__":
    main(sys.argv)
