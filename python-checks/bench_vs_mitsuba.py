"""The tracer's ``path`` integrator against Mitsuba 3's ``path``, side by
side on the physically based course scenes: wall time, image variance,
efficiency, and whether the two images agree at all.

Run (from the repository root, after ``cargo build --release -p optics``):

    DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM-19.so \\
        .venv/bin/python python-checks/bench_vs_mitsuba.py

writes ``validation/out/bench-vs-mitsuba.json`` (schema ``bench-vs-mitsuba/1``)
and prints the table; with ``--docs`` (a full run only) it also writes the
table into ``docs/results.md`` and its summary into the README, each
stamped with the command, the machine and the date (``--table JSON
--docs`` writes them from a record). ``--quick`` is a smoke run (32 x 24, one pair, a
tenth of a second a run); ``--help`` lists the rest. Without a libLLVM of
version 17 or later Mitsuba's ``llvm_ad_rgb`` cannot start and is reported
as not run; ``scalar_rgb`` always runs.

The scenes are the ones the harness's path check renders with ``mi.render``
(``mitsuba_render.course_scenes`` less ``NOT_A_RADIANCE`` and
``PATH_SKIPPED``), translated by ``mitsuba_render.path_scene``: box filter,
independent sampler, ``max_depth`` the suite's 16 bounces (Mitsuba's 18).
The course's rough material (Blinn-Phong) has no native Mitsuba BSDF; the
harness registers a Python one, which in ``scalar_rgb`` is called once per
sample under Python's lock and would time Python, not Mitsuba. So by
default (``--rough lambert``) every ``course_rough`` becomes a ``lambert``
of albedo ``diffuse`` on both sides, as ``mitsuba_full_light.py`` measures
it: Mitsuba's native ``diffuse``, the tracer's ``lambert``, from the same
rewritten scene file. ``--rough course`` keeps the harness's translation,
Python BSDF and all (``scalar_rgb`` only). ``--sampler stratified`` gives
Mitsuba jittered strata in every dimension (the tracer stratifies its
pixel samples, Mitsuba's ``independent`` does not); ``--ray-offset
mitsuba`` starts the tracer's secondary rays by Mitsuba's rule.

Per scene and variant:

1. One untimed render on each side at 1 sample per pixel (Mitsuba's JIT
   compiles its kernels there), then the spp: the smallest at which each
   side's run lasts ``--seconds`` (extrapolated from a calibration run of
   each), the same for both sides, and one more untimed render at it.
2. ``--pairs`` pairs, each A B A B: tracer seed 2k, Mitsuba seed 2k, tracer
   seed 2k + 1, Mitsuba seed 2k + 1, so that the machine's drift falls on
   both sides alike. A tracer run is the whole ``optics render`` process
   (``--threads``, ``--pixel-filter box``, the PNG and PFM written); a
   Mitsuba run is ``mi.render`` and reading its film into numpy, on
   ``--threads`` Dr.Jit threads.
3. Per pair and side: the time of a run (the two runs' mean) and the
   variance of a pixel-channel of one render, ``mean((I1 - I2)^2) / 2``
   over all pixels and channels of the pair's two renders (linear
   radiance); efficiency ``1 / (variance x time)``. The ratios
   tracer / Mitsuba per pair, reported as the median and the min-max over
   pairs, and their geometric means over the comparable scenes.
4. Agreement (``bench_statistics.agreement``): the mean of the tracer's
   ``2 x pairs`` renders against Mitsuba's, per pixel-channel (Welch's t
   with each side's variance over its renders, guarded by its 3 x 3
   neighbourhood's mean as the harness's
   ``compare::welch::guarded_variance``, the conservative ``n - 1`` degrees
   of freedom; Bonferroni over the pixel-channels at ``--alpha`` / 2) and
   per channel of the image mean (Welch's t over the renders' image means;
   Bonferroni over the channels at ``--alpha`` / 2); a test fails where
   ``p`` is below its threshold and the means differ by more than the
   harness's float32 tolerance ``1e-5 + 1e-3 |Mitsuba|``.
5. Where they do not agree, the harness's second question
   (``validation/src/renders/image_mean.rs``): does the tracer make the
   same image when it starts its secondary rays by Mitsuba's rule? Its
   ``2 x pairs`` renders under that rule (untimed, the same spp and seeds)
   are held to the same test against Mitsuba's (with ``--ray-offset
   mitsuba`` too), at ``max_depth`` D + 1
   (``ESCAPE_MAX_DEPTH``): Mitsuba's ``path`` at D + 2 counts the light
   that leaves the last vertex by a sampled direction and escapes, the
   suite's D stops a scattering sooner (``mitsuba_render``'s module doc).
   Agreeing there, the images agree but for Mitsuba's offsets (``agree
   under Mitsuba's offsets``: inside a dielectric sphere they free chords
   that total internal reflection traps, see ``docs/results.md``) and the
   ratios, of the tracer's own renders, are compared; otherwise the scene
   is reported as disagreeing and its ratios as not comparable.
"""
import argparse
import datetime
import json
import math
import os
import platform
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mitsuba_render as mr  # noqa: E402  (sets scalar_rgb; the variant is set again below)
from atomic_write import write_json, write_text  # noqa: E402
from bench_statistics import agreement, geometric_mean, pair_variance, spread  # noqa: E402

import drjit as dr  # noqa: E402
import mitsuba as mi  # noqa: E402
import numpy as np  # noqa: E402

SCHEMA = "bench-vs-mitsuba/1"
DEFAULT_OUT = os.path.join(mr.ROOT, "validation", "out", "bench-vs-mitsuba.json")
VARIANTS = ("scalar_rgb", "llvm_ad_rgb")
# Mitsuba's ``math::RayEpsilon`` for float32, 1500 * 2^-24 (the harness's
# ``MITSUBA_RAY_EPSILON``, validation/src/renders/mod.rs).
MITSUBA_RAY_EPSILON = 1500.0 / 16_777_216.0
# The tracer's max_depth under Mitsuba's offset rule: Mitsuba's ``path`` at
# ``PATH_MAX_DEPTH + 2`` lets light escape after ``PATH_MAX_DEPTH + 1``
# scatterings, where each new one frees another slice of the chords its
# offsets move (``mitsuba_render``'s module doc, "escapes").
ESCAPE_MAX_DEPTH = mr.PATH_MAX_DEPTH + 1


class BenchError(RuntimeError):
    """A run that could not be made, naming what failed."""


# -- scenes ------------------------------------------------------------------

def bench_scenes():
    """The scenes the harness's path check renders, in the tracer's order."""
    names = []
    for name in mr.course_scenes():
        scene = json.loads(mr.scene_text(name)[1])
        if mr.why_excluded(scene) is None and name not in mr.PATH_SKIPPED:
            names.append(name)
    return names


def measured_scene(scene, rough, ray_offset="robust"):
    """The scene both sides render: under ``rough == "lambert"`` each
    ``course_rough`` a ``lambert`` of albedo ``diffuse``; under
    ``ray_offset == "mitsuba"`` the tracer's secondary rays started by
    Mitsuba's rule, ``RayEpsilon (1 + max |p_i|)`` (Mitsuba has no such
    setting and ignores it)."""
    out = json.loads(json.dumps(scene))
    if ray_offset == "mitsuba":
        out.setdefault("render", {})["ray_offset"] = {"scaled": MITSUBA_RAY_EPSILON}
    if rough == "lambert":
        for name, material in out["materials"].items():
            if material["type"] == "course_rough":
                out["materials"][name] = {"type": "lambert", "albedo": material["diffuse"]}
    return out


def has_course_rough(scene):
    return any(m["type"] == "course_rough" for m in scene["materials"].values())


# -- the two sides -----------------------------------------------------------

def read_pfm(path):
    """A PFM (``PF``, little-endian) as float64 rows top to bottom, (h, w, 3)."""
    with open(path, "rb") as f:
        data = f.read()
    header, rest = data.split(b"\n", 1)
    size, rest = rest.split(b"\n", 1)
    scale, raster = rest.split(b"\n", 1)
    if header != b"PF" or float(scale) >= 0.0:
        raise BenchError(f"{path}: not a little-endian colour PFM")
    width, height = (int(v) for v in size.split())
    image = np.frombuffer(raster, dtype="<f4", count=width * height * 3).reshape(height, width, 3)
    return image[::-1].astype(np.float64)


class Tracer:
    """``optics render`` of one scene file, a fresh process each run."""

    def __init__(self, optics, scene_path, size, threads, workdir, max_depth=mr.PATH_MAX_DEPTH):
        self.optics, self.scene_path, self.size, self.threads = optics, scene_path, size, threads
        self.max_depth = max_depth
        self.png = os.path.join(workdir, "tracer.png")

    def command(self, spp, seed):
        return [self.optics, "render", self.scene_path, "-o", self.png, "--integrator", "path",
                "--max-depth", str(self.max_depth), "--pixel-filter", "box", "--spp", str(spp),
                "--seed", str(seed), "--width", str(self.size[0]), "--height", str(self.size[1]),
                "--threads", str(self.threads)]

    def run(self, spp, seed):
        """(seconds, image) of one whole ``optics render`` process."""
        command = self.command(spp, seed)
        start = time.perf_counter()
        done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        seconds = time.perf_counter() - start
        if done.returncode != 0:
            raise BenchError(f"{' '.join(command)}: exit {done.returncode}: {done.stderr.decode()[-400:]}")
        return seconds, read_pfm(self.png[:-4] + ".pfm")


class Mitsuba:
    """``mi.render`` of the harness's Mitsuba translation of one scene."""

    def __init__(self, scene, size, sampler):
        # The harness's scene; ``stratified``: jittered strata in every
        # dimension (the tracer stratifies the pixel's two only).
        self.scene = mr.path_scene(scene, size[0], size[1], sampler)

    def run(self, spp, seed):
        """(seconds, image) of one ``mi.render`` and the film read out."""
        start = time.perf_counter()
        image = np.array(mi.render(self.scene, seed=seed, spp=spp), dtype=np.float64)
        return time.perf_counter() - start, image


# -- one scene ---------------------------------------------------------------

def choose_spp(run, seconds, start_spp=1):
    """The spp at which ``run(spp)`` (seconds) lasts ``seconds``:
    calibrated where a run takes a third of it or more, so that a fixed
    start-up cost does not dominate the extrapolation, and 10 % over it,
    since that cost makes a linear extrapolation fall short."""
    spp = start_spp
    took = run(spp)
    while took < seconds / 3 and spp < 1 << 16:
        spp *= 4
        took = run(spp)
    return max(1, math.ceil(1.1 * spp * seconds / took))


def bench_scene(name, variant, args, workdir, log):
    scene = measured_scene(json.loads(mr.scene_text(name)[1]), args.rough, args.ray_offset)
    path = os.path.join(workdir, f"{name}.json")
    with open(path, "w", encoding="utf-8") as f:
        json.dump(scene, f)
    tracer = Tracer(args.optics, path, args.size, args.threads, workdir)
    mitsuba = Mitsuba(scene, args.size, args.sampler)
    tracer.run(1, 0)  # untimed: the page cache, Mitsuba's JIT
    mitsuba.run(1, 0)
    # Each side calibrated: at 1 spp the tracer's process start can make it
    # look the slower where it is the faster.
    spp = args.spp or max(choose_spp(lambda n: side.run(n, 0)[0], args.seconds) for side in (tracer, mitsuba))
    if args.sampler == "stratified":
        spp = math.ceil(math.sqrt(spp)) ** 2  # its n x n strata, on both sides
    tracer.run(spp, 0)  # untimed, at the measured spp
    mitsuba.run(spp, 0)
    pairs, renders = [], {"tracer": [], "mitsuba": []}
    for k in range(args.pairs):
        runs = {"tracer": [], "mitsuba": []}
        for seed in (2 * k, 2 * k + 1):
            for side, renderer in (("tracer", tracer), ("mitsuba", mitsuba)):
                runs[side].append(renderer.run(spp, seed))
        pair = {}
        for side in runs:
            (s1, i1), (s2, i2) = runs[side]
            renders[side] += [i1, i2]
            pair[side] = {"seconds": [s1, s2], "variance": pair_variance(i1, i2)}
        t_t, t_m = (sum(pair[s]["seconds"]) / 2 for s in ("tracer", "mitsuba"))
        v_t, v_m = pair["tracer"]["variance"], pair["mitsuba"]["variance"]
        pair["load_average"] = os.getloadavg()[0]  # the machine is shared: how busy it was
        pair["time_ratio"] = t_t / t_m
        pair["efficiency_ratio"] = (v_m * t_m) / (v_t * t_t) if v_t > 0 and t_t > 0 else None
        pairs.append(pair)
        log(f"  {name} {variant} pair {k + 1}: tracer {t_t:.3f} s, Mitsuba {t_m:.3f} s, "
            f"variance {v_t:.3e} / {v_m:.3e}, load {pair['load_average']:.2f}")
    def under_mitsuba_offsets():
        moved_path = os.path.join(workdir, f"{name}-mitsuba-offsets.json")
        with open(moved_path, "w", encoding="utf-8") as f:
            json.dump(measured_scene(json.loads(mr.scene_text(name)[1]), args.rough, "mitsuba"), f)
        moved = Tracer(args.optics, moved_path, args.size, args.threads, workdir, ESCAPE_MAX_DEPTH)
        return [moved.run(spp, seed)[1] for seed in range(2 * args.pairs)]

    agree = judged(renders["tracer"], renders["mitsuba"], args.alpha, under_mitsuba_offsets)
    if "under_mitsuba_offsets" in agree:
        log(f"  {name} {variant}: images {agree['images']} (under Mitsuba's offset rule, max_depth "
            f"{ESCAPE_MAX_DEPTH})")
    efficiency = [p["efficiency_ratio"] for p in pairs]
    entry = {
        "name": name,
        "variant": variant,
        "spp": spp,
        "course_rough_as": args.rough if has_course_rough(json.loads(mr.scene_text(name)[1])) else None,
        "mitsuba_bsdf": "python" if args.rough == "course" and has_course_rough(scene) else "native",
        "tracer_command": " ".join(tracer.command(spp, "SEED")),
        "pairs": pairs,
        "agreement": agree,
        "comparable": agree["images"] != "disagree" and None not in efficiency,
        "time_ratio": spread([p["time_ratio"] for p in pairs]),
        "efficiency_ratio": spread(efficiency) if None not in efficiency else None,
        "seconds": {s: spread([sum(p[s]["seconds"]) / 2 for p in pairs]) for s in ("tracer", "mitsuba")},
        "variance": {s: spread([p[s]["variance"] for p in pairs]) for s in ("tracer", "mitsuba")},
        "load_average": spread([p["load_average"] for p in pairs]),
    }
    return entry


def judged(ours, theirs, alpha, under_mitsuba_offsets=None):
    """``agreement`` of the renders ``ours`` and ``theirs``, with the
    verdict ``images``: ``agree``; else, where ``under_mitsuba_offsets``
    (called only then) gives the tracer's renders under Mitsuba's offset
    rule and those agree with ``theirs`` (recorded beside, as
    ``under_mitsuba_offsets``), ``agree under Mitsuba's offsets``: the
    difference is light that Mitsuba's offsets move; else ``disagree``."""
    agree = agreement(ours, theirs, alpha)
    agree["images"] = "agree" if agree["agrees"] else "disagree"
    if not agree["agrees"] and under_mitsuba_offsets is not None:
        moved = agreement(under_mitsuba_offsets(), theirs, alpha)
        agree["under_mitsuba_offsets"] = moved
        if moved["agrees"]:
            agree["images"] = "agree under Mitsuba's offsets"
    return agree


# -- the run -----------------------------------------------------------------

def set_variant(variant, threads):
    """Mitsuba in ``variant`` on ``threads`` threads, or the reason it cannot run."""
    if variant not in mi.variants():
        return f"{variant} is not in this Mitsuba build"
    try:
        mi.set_variant(variant)
        dr.set_thread_count(threads)
        if variant.startswith("llvm"):
            dr.eval(mi.Float(1.0) + 1.0)  # loads libLLVM: fails here, not mid-render
    except Exception as error:  # noqa: BLE001  (Dr.Jit raises RuntimeError, ImportError, ...)
        return f"{variant}: {error}".splitlines()[0]
    return None


def machine():
    model = None
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    load = os.getloadavg() if hasattr(os, "getloadavg") else None
    return {"platform": platform.platform(), "cpu": model, "cores": os.cpu_count(),
            "load_average_at_start": list(load) if load else None}


def summary(entries, variant):
    mine = [e for e in entries if e["variant"] == variant and e["comparable"]]
    return {
        "variant": variant,
        "comparable_scenes": len(mine),
        "geometric_mean_efficiency_ratio": geometric_mean(e["efficiency_ratio"]["median"] for e in mine),
        "geometric_mean_time_ratio": geometric_mean(e["time_ratio"]["median"] for e in mine),
    }


def table(document):
    lines = ["| scene | variant | spp | tracer s | Mitsuba s | time ratio (tracer / Mitsuba) | "
             "efficiency ratio (tracer / Mitsuba) | images | load |",
             "|---|---|---|---|---|---|---|---|---|"]
    for e in document["scenes"]:
        t, m = e["seconds"]["tracer"]["median"], e["seconds"]["mitsuba"]["median"]
        r = e["time_ratio"]
        time_ratio = f"{r['median']:.2f} ({r['min']:.2f}–{r['max']:.2f})"
        if e["comparable"]:
            q = e["efficiency_ratio"]
            efficiency = f"{q['median']:.2f} ({q['min']:.2f}–{q['max']:.2f})"
            images = e.get("agreement", {}).get("images", "agree")
        else:
            efficiency, images = "not comparable", "disagree"
        bsdf = " (Python BSDF)" if e["mitsuba_bsdf"] == "python" else ""
        lines.append(f"| `{e['name']}` | {e['variant']}{bsdf} | {e['spp']} | {t:.2f} | {m:.2f} | "
                     f"{time_ratio} | {efficiency} | {images} | {e['load_average']['median']:.1f} |")
    for s in document["summary"]:
        if s["comparable_scenes"]:
            lines.append(f"| geometric mean ({s['comparable_scenes']} scenes) | {s['variant']} | | | | "
                         f"{s['geometric_mean_time_ratio']:.2f} | {s['geometric_mean_efficiency_ratio']:.2f} | | |")
    for variant, why in document["not_run"].items():
        lines.append(f"| (not run) | {variant} | | | | {why} | | | |")
    return "\n".join(lines)


# -- the documents ------------------------------------------------------------

RESULTS_MD = os.path.join(mr.ROOT, "docs", "results.md")
README_MD = os.path.join(mr.ROOT, "README.md")
SECTION, SUMMARY_SECTION = "bench-vs-mitsuba", "bench-vs-mitsuba-summary"


def stamp(document):
    """The lead line of a measured section, as ``results::Section::measured``
    writes it: the command, the machine, its load, the date."""
    m = document["machine"]
    load = m.get("load_average_at_end") or m.get("load_average_at_start")
    load = f" (load average {load[0]:.2f})" if load else ""
    return (f"Measured by `{document['command']}` on {m['cpu'] or m['platform']}, {m['cores']} threads{load}, "
            f"{document['date'][:10]}; a timing of that machine, not compared.")


def summary_text(document):
    """The README's lines: per variant the geometric means, and the scene
    where the tracer does worst, from the record."""
    lines = [stamp(document), ""]
    for s in document["summary"]:
        mine = [e for e in document["scenes"] if e["variant"] == s["variant"] and e["comparable"]]
        if not mine:
            continue
        worst = min(mine, key=lambda e: e["efficiency_ratio"]["median"])
        best = max(mine, key=lambda e: e["efficiency_ratio"]["median"])
        lines.append(f"- against `{s['variant']}`: efficiency (1 / (variance × time)) "
                     f"{s['geometric_mean_efficiency_ratio']:.2f}× Mitsuba's, geometric mean over "
                     f"{s['comparable_scenes']} scenes; from {worst['efficiency_ratio']['median']:.2f}× "
                     f"(`{worst['name']}`) to {best['efficiency_ratio']['median']:.2f}× (`{best['name']}`); "
                     f"time at equal samples {s['geometric_mean_time_ratio']:.2f}× Mitsuba's")
    disagree = [f"`{e['name']}` ({e['variant']})" for e in document["scenes"] if not e["comparable"]]
    if disagree:
        lines.append(f"- images that did not agree, so not compared: {', '.join(disagree)}")
    for variant, why in document["not_run"].items():
        lines.append(f"- `{variant}` not run: {why}")
    return "\n".join(lines)


def replace_section(text, name, body):
    """``text`` with ``body`` between the markers of section ``name`` (the
    markers ``results`` writes); a section not there yet is appended."""
    begin, end = f"<!-- results: {name} -->\n", f"<!-- /results: {name} -->\n"
    body = body.rstrip("\n") + "\n"
    start = text.find(begin)
    stop = text.find(end, start + len(begin)) if start >= 0 else -1
    if start < 0 or stop < 0:
        return f"{text.rstrip(chr(10))}\n\n{begin}{body}{end}"
    return text[:start + len(begin)] + body + text[stop:]


def write_docs(document, results_md=RESULTS_MD, readme_md=README_MD):
    """The full table into ``docs/results.md``, the summary into the README."""
    for path, name, body in ((results_md, SECTION, f"{stamp(document)}\n\n{table(document)}"),
                             (readme_md, SUMMARY_SECTION, summary_text(document))):
        with open(path, encoding="utf-8") as f:
            text = f.read()
        write_text(path, replace_section(text, name, body))


def parse(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--quick", action="store_true", help="32 x 24, one pair, 0.1 s a run (a smoke run)")
    p.add_argument("--scenes", help="comma-separated scene names (default: every path-compared scene)")
    p.add_argument("--variants", default=",".join(VARIANTS), help="Mitsuba variants, comma-separated")
    p.add_argument("--rough", choices=("lambert", "course"), default="lambert",
                   help="course_rough as Lambert on both sides, or the harness's Python BSDF")
    p.add_argument("--sampler", choices=("independent", "stratified"), default="independent",
                   help="Mitsuba's sampler: the harness's independent, or stratified in every dimension")
    p.add_argument("--ray-offset", choices=("robust", "mitsuba"), default="robust",
                   help="the tracer's secondary-ray offsets: its own, or Mitsuba's rule")
    p.add_argument("--pairs", type=int, default=3, help="A B A B pairs per scene (at least 3 unless --quick)")
    p.add_argument("--seconds", type=float, default=1.0, help="the least time of a run, either side")
    p.add_argument("--spp", type=int, help="samples per pixel, instead of choosing them by --seconds")
    p.add_argument("--size", type=int, nargs=2, default=(320, 240), metavar=("W", "H"))
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--alpha", type=float, default=0.01)
    p.add_argument("--optics", default=os.path.join(os.environ.get("CARGO_TARGET_DIR", os.path.join(mr.ROOT, "target")),
                                                    "release", "optics"), help="the optics binary")
    p.add_argument("--out", default=DEFAULT_OUT)
    p.add_argument("--table", metavar="JSON", help="print the table of a record this wrote, and stop")
    p.add_argument("--docs", action="store_true",
                   help="write the table into docs/results.md and its summary into README.md "
                        "(from this run, or from --table's record)")
    args = p.parse_args(argv)
    if args.quick:
        args.size, args.pairs, args.seconds = (32, 24), 1, 0.1
    elif args.pairs < 3:
        p.error("--pairs: at least 3 (or --quick)")
    return args


def main(argv):
    args = parse(argv)
    if args.table:
        try:
            with open(args.table, encoding="utf-8") as f:
                document = json.load(f)
        except (OSError, ValueError) as error:
            print(f"bench_vs_mitsuba.py: --table {args.table}: {error}", file=sys.stderr)
            return 1
        if not isinstance(document, dict) or document.get("schema") != SCHEMA:
            schema = document.get("schema") if isinstance(document, dict) else None
            print(f"bench_vs_mitsuba.py: --table {args.table}: schema {schema!r}, "
                  f"expected {SCHEMA!r}", file=sys.stderr)
            return 1
        print(table(document))
        if args.docs:
            write_docs(document)
        return 0
    if args.docs and (args.quick or args.scenes or args.variants != ",".join(VARIANTS)):
        print("bench_vs_mitsuba.py: --docs: only a full run (every scene, every variant) writes the documents",
              file=sys.stderr)
        return 1
    if not os.access(args.optics, os.X_OK):
        print(f"bench_vs_mitsuba.py: --optics {args.optics}: no such executable "
              "(cargo build --release -p optics)", file=sys.stderr)
        return 1
    names = args.scenes.split(",") if args.scenes else bench_scenes()
    unknown = sorted(set(names) - set(bench_scenes()))
    if unknown:
        print(f"bench_vs_mitsuba.py: --scenes: {', '.join(unknown)} not among {', '.join(bench_scenes())}",
              file=sys.stderr)
        return 1
    entries, not_run = [], {}
    started = datetime.datetime.now(datetime.timezone.utc)
    load = machine()
    with tempfile.TemporaryDirectory(prefix="bench-vs-mitsuba-") as workdir:
        for variant in args.variants.split(","):
            why = set_variant(variant, args.threads)
            if why is None and args.rough == "course" and variant != "scalar_rgb":
                why = "the harness's Python Blinn-Phong BSDF is written for scalar_rgb"
            if why:
                not_run[variant] = why
                print(f"{variant}: not run: {why}", file=sys.stderr)
                continue
            for name in names:
                try:
                    entries.append(bench_scene(name, variant, args, workdir,
                                               lambda s: print(s, file=sys.stderr, flush=True)))
                except BenchError as error:
                    print(f"bench_vs_mitsuba.py: {name}: {error}", file=sys.stderr)
                    return 1
    load["load_average_at_end"] = list(os.getloadavg())
    document = {
        "schema": SCHEMA,
        "generator": "python-checks/bench_vs_mitsuba.py",
        "command": " ".join([os.path.relpath(sys.executable, mr.ROOT) if sys.executable.startswith(mr.ROOT)
                             else sys.executable, "python-checks/bench_vs_mitsuba.py", *argv]),
        "date": started.strftime("%Y-%m-%dT%H:%M:%SZ"),
        "machine": load,
        "mitsuba": {"version": mi.__version__, "drjit": dr.__version__},
        "settings": {"size": list(args.size), "pairs": args.pairs, "seconds": args.seconds,
                     "threads": args.threads, "alpha": args.alpha, "rough": args.rough,
                     "mitsuba_sampler": args.sampler, "tracer_ray_offset": args.ray_offset,
                     "max_depth": mr.PATH_MAX_DEPTH, "mitsuba_max_depth": mr.PATH_MAX_DEPTH + 2,
                     "max_depth_under_mitsuba_offsets": ESCAPE_MAX_DEPTH,
                     "pixel_filter": "box"},
        "not_run": not_run,
        "scenes": entries,
    }
    document["summary"] = [summary(entries, v) for v in args.variants.split(",") if v not in not_run]
    print(table(document))
    write_json(args.out, document)
    if args.docs:
        write_docs(document)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
