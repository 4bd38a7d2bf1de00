"""The path tracer's noise per sample and its time, two builds of ``optics``
side by side: what a change of sampler (or anything else) buys in
efficiency, ``1 / (variance x time)``, the quantity ``bench_vs_mitsuba.py``
races.

Run (from the repository root, with the two builds at hand):

    .venv/bin/python python-checks/sampler_variance.py \\
        --before OPTICS_BEFORE --after target/release/optics [--docs]

Per scene (the bench's scenes, its Lambert translation of ``course_rough``)
and ``--pairs`` pairs, each A B A B: before seed 2k, after seed 2k, before
seed 2k + 1, after seed 2k + 1, every run the whole ``optics render``
process (``--integrator path --pixel-filter box``, ``--spp``, ``--size``,
``--threads``), so that the machine's drift falls on both builds alike.
Per pair and build: the variance of a pixel-channel of one render,
``mean((I1 - I2)^2) / 2`` over the two seeds' renders (real error
variance: stratification counts), and the time of a run (the two runs'
mean). The ratios after / before per pair, reported as the median and the
min-max over pairs. Writes ``validation/out/sampler-variance.json``; with
``--docs`` the table into ``docs/tracer.md``'s ``sampler`` section, stamped
with the command, the machine and the date.
"""
import argparse
import datetime
import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench_vs_mitsuba as bench  # noqa: E402
import mitsuba_render as mr  # noqa: E402
from atomic_write import write_json, write_text  # noqa: E402
from bench_statistics import pair_variance, spread  # noqa: E402

SCHEMA = "sampler-variance/1"
DEFAULT_OUT = os.path.join(mr.ROOT, "validation", "out", "sampler-variance.json")
TRACER_MD = os.path.join(mr.ROOT, "docs", "tracer.md")
SECTION = "sampler"
SCENES = ("shadow", "glass_spheres", "kaleidoscope_lit", "gold_spheres")


def measure_scene(name, args, workdir):
    scene = bench.measured_scene(json.loads(mr.scene_text(name)[1]), "lambert")
    path = os.path.join(workdir, f"{name}.json")
    with open(path, "w", encoding="utf-8") as f:
        json.dump(scene, f)
    sides = {side: bench.Tracer(optics, path, args.size, args.threads, os.path.join(workdir, side))
             for side, optics in (("before", args.before), ("after", args.after))}
    for side in sides:
        os.makedirs(os.path.join(workdir, side), exist_ok=True)
        sides[side].run(1, 0)  # untimed: the binary and the scene into the page cache
    pairs = []
    for k in range(args.pairs):
        runs = {"before": [], "after": []}
        for seed in (2 * k, 2 * k + 1):
            for side in ("before", "after"):
                runs[side].append(sides[side].run(args.spp, seed))
        pair = {}
        for side, ((t1, i1), (t2, i2)) in runs.items():
            pair[side] = {"seconds": (t1 + t2) / 2, "variance": pair_variance(i1, i2)}
        pairs.append(pair)
        print(f"{name} pair {k}: " + ", ".join(
            f"{s} {p['seconds']:.3f} s variance {p['variance']:.4g}" for s, p in pair.items()),
            file=sys.stderr, flush=True)
    return {"name": name, "spp": args.spp, "pairs": pairs, "ratio_after_over_before": ratios(pairs)}


def ratios(pairs):
    """Per pair after / before: the variance, the time, and the efficiency
    ``1 / (variance x time)`` (so the efficiency ratio is before's
    ``variance x time`` over after's); each as the median and min-max."""
    return {
        "variance": spread([p["after"]["variance"] / p["before"]["variance"] for p in pairs]),
        "time": spread([p["after"]["seconds"] / p["before"]["seconds"] for p in pairs]),
        "efficiency": spread([(p["before"]["variance"] * p["before"]["seconds"])
                              / (p["after"]["variance"] * p["after"]["seconds"]) for p in pairs]),
    }


def table(document):
    lines = ["| scene | spp | variance before | variance after | variance ratio | "
             "time ratio | efficiency ratio |",
             "|---|---|---|---|---|---|---|"]
    for e in document["scenes"]:
        r = e["ratio_after_over_before"]
        median = lambda side: sorted(p[side]["variance"] for p in e["pairs"])[len(e["pairs"]) // 2]  # noqa: E731
        cell = lambda s: f"{s['median']:.3f} ({s['min']:.3f}–{s['max']:.3f})"  # noqa: E731
        lines.append(f"| `{e['name']}` | {e['spp']} | {median('before'):.4g} | {median('after'):.4g} | "
                     f"{cell(r['variance'])} | {cell(r['time'])} | {cell(r['efficiency'])} |")
    return "\n".join(lines)


def stamp(document):
    m = document["machine"]
    return (f"`{document['command']}`, {document['size'][0]} × {document['size'][1]}, "
            f"{document['threads']} threads, {document['pairs']} A B A B pairs; "
            f"{m['cpu']}, {m['cores']} cores, load {m['load_average_at_start'][0]:.1f} at the start; "
            f"{document['date']}. Ratios after / before: median (min–max over pairs); "
            f"efficiency ratio above 1 is better.")


def parse(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--before", required=True, help="the optics binary measured first in each pair")
    p.add_argument("--after", required=True, help="the optics binary measured second")
    p.add_argument("--scenes", default=",".join(SCENES), help="comma-separated scene names")
    p.add_argument("--spp", type=int, default=64)
    p.add_argument("--size", type=int, nargs=2, default=(160, 120), metavar=("W", "H"))
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--pairs", type=int, default=3)
    p.add_argument("--out", default=DEFAULT_OUT)
    p.add_argument("--docs", action="store_true", help="write the table into docs/tracer.md")
    return p.parse_args(argv)


def main(argv):
    args = parse(argv)
    for flag, optics in (("--before", args.before), ("--after", args.after)):
        if not os.access(optics, os.X_OK):
            print(f"sampler_variance.py: {flag} {optics}: no such executable", file=sys.stderr)
            return 1
    if args.pairs < 1 or args.spp < 1:
        print("sampler_variance.py: --pairs and --spp must be at least 1", file=sys.stderr)
        return 1
    started = datetime.datetime.now(datetime.timezone.utc)
    load = bench.machine()
    entries = []
    with tempfile.TemporaryDirectory(prefix="sampler-variance-") as workdir:
        for name in args.scenes.split(","):
            try:
                entries.append(measure_scene(name, args, workdir))
            except (bench.BenchError, KeyError, OSError) as error:
                print(f"sampler_variance.py: {name}: {error}", file=sys.stderr)
                return 1
    load["load_average_at_end"] = list(os.getloadavg())
    document = {
        "schema": SCHEMA,
        "generator": "python-checks/sampler_variance.py",
        "command": "python-checks/sampler_variance.py " + " ".join(
            a if os.path.sep not in a else os.path.basename(a) for a in argv),
        "date": started.strftime("%Y-%m-%d %H:%M UTC"),
        "machine": load,
        "size": list(args.size), "threads": args.threads, "pairs": args.pairs,
        "scenes": entries,
    }
    write_json(args.out, document)
    print(table(document))
    if args.docs:
        with open(TRACER_MD, encoding="utf-8") as f:
            text = f.read()
        write_text(TRACER_MD, bench.replace_section(text, SECTION, f"{stamp(document)}\n\n{table(document)}"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
