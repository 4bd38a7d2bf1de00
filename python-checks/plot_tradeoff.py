"""The Pareto plot of an ``optics tradeoff`` sweep, drawn with matplotlib.

    .venv/bin/python python-checks/plot_tradeoff.py SWEEP.json SWEEP-pareto.png

``optics tradeoff`` runs this after writing the sweep (schema
``optics.tradeoff`` version 2, or 1, which differs only in calling
Schlick's rarer-medium form ``schlick``; see ``docs/tradeoffs.md``). One panel per
fixed error measure: the median render time against the error, log-log,
every point labelled, the Pareto front joined. It reads only that file; the
numbers are the sweep's, nothing is recomputed here. Prints the PNG's path.
"""
import json
import os
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SCHEMA = "optics.tradeoff"
VERSIONS = (1, 2)
MEASURES = [
    ("rel_rmse", "relative RMSE of radiance"),
    ("delta_e_mean", "mean ΔE2000, displayed"),
    ("delta_e_p99", "99th percentile ΔE2000, displayed"),
    ("flip_mean", "mean ꟻLIP, displayed"),
]
# Below this an error is drawn at this value: a log axis has no zero.
FLOOR = 1e-4


def load(path):
    """The sweep at `path`, refused unless it is the schema this draws."""
    with open(path, encoding="utf-8") as f:
        sweep = json.load(f)
    if sweep.get("schema") != SCHEMA or sweep.get("version") not in VERSIONS:
        raise SystemExit(
            f"{path}: not an {SCHEMA} version 1 or 2 sweep "
            f"(schema {sweep.get('schema')!r}, version {sweep.get('version')!r})"
        )
    return sweep


def front(points, measure):
    """The points on `measure`'s front, by increasing time, as the sweep marked them."""
    on = [p for p in points if measure in p["pareto"]]
    return sorted(on, key=lambda p: (p["seconds_median"], p["errors"][measure]))


def labels(points, measure):
    """One label per cluster of points that land on the same spot (equal
    error, times within 10 %), its members' names joined, so that coinciding
    settings do not print over each other; the others unlabelled."""
    shown = [None] * len(points)
    for i, p in enumerate(points):
        for j in range(i):
            q = points[j]
            if shown[j] is not None and q["errors"][measure] == p["errors"][measure] and (
                abs(q["seconds_median"] - p["seconds_median"]) <= 0.1 * q["seconds_median"]
            ):
                shown[j] += ", " + p["label"]
                break
        else:
            shown[i] = p["label"]
    return shown


def draw(sweep, png):
    points = sweep["points"]
    # A sweep written before a measure joined the schema lacks it.
    measures = [(m, t) for m, t in MEASURES if all(m in p["errors"] for p in points)]
    rows = (len(measures) + 1) // 2
    fig, axes = plt.subplots(rows, 2, figsize=(12, 4.75 * rows), squeeze=False)
    axes = axes.ravel()
    for ax in axes[len(measures):]:
        ax.set_visible(False)
    for ax, (measure, title) in zip(axes, measures):
        xs = [max(p["seconds_median"], 1e-6) for p in points]
        ys = [max(p["errors"][measure], FLOOR) for p in points]
        colours = ["C3" if measure in p["pareto"] else "C0" for p in points]
        ax.scatter(xs, ys, c=colours, s=18, zorder=3)
        for label, x, y in zip(labels(points, measure), xs, ys):
            if label is not None:
                short = label if len(label) <= 80 else label[:77] + "..."
                ax.annotate(short, (x, y), fontsize=6, xytext=(3, 2), textcoords="offset points")
        line = front(points, measure)
        ax.step(
            [max(p["seconds_median"], 1e-6) for p in line],
            [max(p["errors"][measure], FLOOR) for p in line],
            where="post",
            color="C3",
            linewidth=1,
            label="Pareto front",
        )
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("render time, s (median)")
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="both", linewidth=0.3)
    axes[0].legend(fontsize=8)
    title = f"{sweep['scene']} at {sweep['width']}×{sweep['height']}: {sweep['command']}"
    fig.suptitle(
        textwrap.fill(title, 110) + f"\n{sweep['machine']}, {sweep['date']}",
        fontsize=9,
    )
    fig.tight_layout()
    tmp = png + ".tmp"
    fig.savefig(tmp, dpi=90, format="png")
    plt.close(fig)
    os.replace(tmp, png)
    return png


def main(argv):
    if len(argv) != 3:
        raise SystemExit("usage: plot_tradeoff.py SWEEP.json OUT.png")
    print(draw(load(argv[1]), argv[2]))


if __name__ == "__main__":
    main(sys.argv)
