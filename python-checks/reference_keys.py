"""Which committed reference is current: each one keyed by what made it.

A reference is regenerated only when what made it changes. Its key is the
SHA-256 of

- its generator's source, with the sources of the ``python-checks`` modules
  it imports, transitively (``atomic_write``, ``colorimetry``, ...);
- the repository files it reads (the globs in ``GENERATORS`` below: the
  tracer's scene files and their list, ``scene_list.SCENE_LIST``, for the
  renders);
- the pinned tools (``python-checks/requirements.txt``) and Python's
  major.minor version.

``validation/reference/keys.json`` records, for every generator in
``GENERATORS`` (the one list of them: ``optics validate`` reads its order
from the file), that key and the SHA-256 of each file it wrote, as they were
when the references were last regenerated. A reference whose recorded key
is not the key computed now is *stale* (a generator, an input or a tool
changed since); one whose bytes do not hash to the recorded value was
changed by hand or corrupted. Neither is trusted: both are regenerated.

``fresh`` gives a generator's output for the current key through a cache
(``--cache DIR``, ``optics validate`` uses ``validation/out/cache``): an
entry is used only if its own recorded key is the current key and every file
in it hashes to what the entry recorded; otherwise the generator runs again
and the entry is rewritten whole.

Usage (from the repository root, in the pinned environment)::

    .venv/bin/python python-checks/reference_keys.py            # each reference's state; exit 1 if any is stale
    .venv/bin/python python-checks/reference_keys.py --json     # the same as one JSON object, exit 0
    .venv/bin/python python-checks/reference_keys.py --regenerate  # regenerate the stale ones, then record the keys
    .venv/bin/python python-checks/reference_keys.py --regenerate --all  # every reference, from scratch
    .venv/bin/python python-checks/reference_keys.py --fresh GENERATOR DIR --cache CACHE  # one generator's output in DIR
"""
import argparse
import glob
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys

from atomic_write import write_json, write_text
from scene_list import SCENE_LIST

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
KEYS_PATH = os.path.join(ROOT, "validation", "reference", "keys.json")
REQUIREMENTS = os.path.join(HERE, "requirements.txt")
REGENERATE = ".venv/bin/python python-checks/reference_keys.py --regenerate"

# (generator, files it writes, repository files it reads, kind). The kind
# groups references that one tool computes the same way: CI regenerates at
# least one reference of each kind from scratch on every run.
GENERATORS = [
    ("fresnel_mpmath.py", ["fresnel_mpmath.json"], [], "mpmath"),
    ("fresnel_random.py", ["fresnel_random.json"], [], "mpmath"),
    ("mitsuba_laws.py", ["mitsuba_laws.json"], [], "mitsuba-laws"),
    ("colorimetry.py", ["colorimetry.json", "cie_tables.rs"], [], "colour-science"),
    ("metals.py", ["metals.json"], [], "colour-science"),
    ("mitsuba_render.py", ["mitsuba_renders.json"],
     [SCENE_LIST, "crates/tracer/scenes/*.json"], "mitsuba-render"),
    ("mitsuba_full_light.py", ["mitsuba_full_light.json"],
     [SCENE_LIST, "crates/tracer/scenes/*.json"], "mitsuba-render"),
    ("flip_reference.py", ["flip.json"], [], "flip"),
]

# The reference of each kind that every CI run regenerates from scratch and
# requires to reproduce the committed file (python-checks/reproduce.py's
# rule): the quickest of its kind, and of Mitsuba's renders one scene's entry
# (the generator's ``--only``; each scene renders alone, in its own process).
# The others are trusted by their key and their recorded SHA-256, and
# ``--regenerate --all`` remakes every one. Each generator's time from
# scratch on two cores (``pytest --durations`` before the references were
# keyed): fresnel_mpmath 1.7 s, fresnel_random 16.5 s, mitsuba_laws 0.07 s,
# colorimetry 0.15 s, metals 0.22 s, mitsuba_render 108 s (``shadow`` alone:
# 6.6 s), mitsuba_full_light 215 s, flip_reference 0.01 s.
FROM_SCRATCH = {
    "mpmath": ("fresnel_mpmath.py", None),
    "mitsuba-laws": ("mitsuba_laws.py", None),
    "colour-science": ("colorimetry.py", None),
    "mitsuba-render": ("mitsuba_render.py", "shadow"),
    "flip": ("flip_reference.py", None),
}

IMPORT = re.compile(r"^\s*(?:import|from)\s+([A-Za-z_][A-Za-z0-9_]*)", re.M)


def committed_path(name):
    """Where a generated file is committed: the CIE tables in the radiometry
    crate, every other file in ``validation/reference/``."""
    if name.endswith(".rs"):
        return os.path.join(ROOT, "crates", "radiometry", "src", name)
    return os.path.join(ROOT, "validation", "reference", name)


def generator(script):
    """The ``GENERATORS`` entry of ``script``; KeyError naming it if none."""
    for entry in GENERATORS:
        if entry[0] == script:
            return entry
    raise KeyError(f"{script} is not a reference generator (one of {', '.join(g[0] for g in GENERATORS)})")


def local_modules(script, folder=HERE):
    """``script`` and the python-checks modules it imports, transitively, sorted."""
    seen, todo = set(), [script]
    while todo:
        name = todo.pop()
        if name in seen:
            continue
        seen.add(name)
        with open(os.path.join(folder, name), encoding="utf-8") as fh:
            for module in IMPORT.findall(fh.read()):
                if os.path.isfile(os.path.join(folder, module + ".py")):
                    todo.append(module + ".py")
    return sorted(seen)


def inputs(patterns, root=ROOT):
    """[(name, bytes)] of the repository files the globs ``patterns`` name,
    sorted. A pattern that names nothing is an error, never an empty input."""
    found = {}
    for pattern in patterns:
        files = sorted(glob.glob(os.path.join(root, pattern)))
        if not files:
            raise FileNotFoundError(f"input {pattern} of a reference names no file")
        for file in files:
            name = os.path.relpath(file, root).replace(os.sep, "/")
            with open(file, "rb") as fh:
                found[name] = fh.read()
    return sorted(found.items())


def key(script, root=ROOT, folder=HERE, requirements=REQUIREMENTS, python=None):
    """The SHA-256 (hex) of everything ``script``'s output depends on."""
    _, _, patterns, _ = generator(script)
    digest = hashlib.sha256()

    def part(label, data):
        # Each part is labelled and length-prefixed, so no two inputs can
        # run together into the same bytes.
        digest.update(f"{label}\0{len(data)}\0".encode())
        digest.update(data)

    for module in local_modules(script, folder):
        with open(os.path.join(folder, module), "rb") as fh:
            part(f"python-checks/{module}", fh.read())
    for name, data in inputs(patterns, root):
        part(name, data)
    with open(requirements, "rb") as fh:
        part("requirements.txt", fh.read())
    version = python or "{}.{}".format(*sys.version_info[:2])
    part("python", version.encode())
    return digest.hexdigest()


def file_hash(path):
    with open(path, "rb") as fh:
        return hashlib.sha256(fh.read()).hexdigest()


def read_keys(path=KEYS_PATH):
    """The recorded keys: {generator: {"key", "kind", "outputs": {name: sha256}}}."""
    with open(path, encoding="utf-8") as fh:
        document = json.load(fh)
    return {entry["generator"]: entry for entry in document["generators"]}


def state(script, recorded, current_key):
    """Why ``script``'s committed output cannot be trusted, or None."""
    entry = recorded.get(script)
    if entry is None:
        return "no key recorded"
    if entry["key"] != current_key:
        return "stale: its generator, an input or a tool changed since it was written"
    for name, expected in entry["outputs"].items():
        path = committed_path(name)
        if not os.path.isfile(path):
            return f"{name} is missing"
        if file_hash(path) != expected:
            return f"{name} does not hash to its recorded SHA-256 (edited by hand or corrupted)"
    return None


def keys_document(entries):
    return {
        "schema": "reference-keys/1",
        "generator": "python-checks/reference_keys.py",
        "regenerate": REGENERATE + " --all",
        "generators": entries,
    }


def record_keys(path=KEYS_PATH):
    """Writes the current key and output hashes of every generator."""
    entries = []
    for script, outputs, _, kind in GENERATORS:
        entries.append({
            "generator": script,
            "kind": kind,
            "key": key(script),
            "outputs": {name: file_hash(committed_path(name)) for name in outputs},
        })
    write_json(path, keys_document(entries))


def run_generator(script, destination, python=sys.executable, only=None):
    """Runs ``script`` writing its outputs into ``destination``; with
    ``only``, just that part of them (``--only``)."""
    _, outputs, _, _ = generator(script)
    os.makedirs(destination, exist_ok=True)
    command = [python, "-W", "ignore", os.path.join(HERE, script)]
    command += [os.path.join(destination, name) for name in outputs]
    if only is not None:
        command += ["--only", only]
    subprocess.run(command, check=True, cwd=ROOT)


def cached_entry(script, cache, current_key):
    """The cache folder holding ``script``'s output for ``current_key`` if it
    is whole and unaltered, else None."""
    folder = os.path.join(cache, os.path.splitext(script)[0])
    manifest = os.path.join(folder, "entry.json")
    try:
        with open(manifest, encoding="utf-8") as fh:
            entry = json.load(fh)
        if entry["key"] != current_key:
            return None
        _, outputs, _, _ = generator(script)
        if sorted(entry["outputs"]) != sorted(outputs):
            return None
        for name, expected in entry["outputs"].items():
            if file_hash(os.path.join(folder, name)) != expected:
                return None
    except (OSError, ValueError, KeyError, TypeError):
        return None
    return folder


def fresh(script, destination, cache, run=run_generator):
    """Puts ``script``'s output for the current key into ``destination``:
    from the cache where its entry is whole and of this key, else by running
    the generator (and rewriting the entry). Returns whether it ran."""
    current_key = key(script)
    folder = cached_entry(script, cache, current_key)
    ran = folder is None
    if ran:
        folder = os.path.join(cache, os.path.splitext(script)[0])
        shutil.rmtree(folder, ignore_errors=True)
        run(script, folder)
        _, outputs, _, _ = generator(script)
        hashes = {name: file_hash(os.path.join(folder, name)) for name in outputs}
        write_text(os.path.join(folder, "entry.json"),
                   json.dumps({"generator": script, "key": current_key, "outputs": hashes}, indent=1) + "\n")
    os.makedirs(destination, exist_ok=True)
    for name in generator(script)[1]:
        shutil.copyfile(os.path.join(folder, name), os.path.join(destination, name))
    return ran


def regenerate(everything):
    """Regenerates the stale references (or all) in place, then records the keys."""
    recorded = read_keys() if os.path.isfile(KEYS_PATH) else {}
    for script, outputs, _, _ in GENERATORS:
        why = state(script, recorded, key(script))
        if everything or why:
            print(f"{script}: regenerating ({why or 'asked for all'})", flush=True)
            run_generator(script, os.path.join(ROOT, ".reference-regeneration"))
            for name in outputs:
                os.replace(os.path.join(ROOT, ".reference-regeneration", name), committed_path(name))
    shutil.rmtree(os.path.join(ROOT, ".reference-regeneration"), ignore_errors=True)
    record_keys()


def report():
    """Prints each reference's state; 0 if all are current, 1 if not."""
    recorded = read_keys()
    stale = 0
    for script, _, _, kind in GENERATORS:
        why = state(script, recorded, key(script))
        stale += why is not None
        print(f"{script} ({kind}): {why or 'current'}")
    if stale:
        print(f"{stale} stale; regenerate with: {REGENERATE}")
    return 1 if stale else 0


def states_json():
    """Each generator, its outputs and its state (None: current), as JSON:
    what ``optics validate`` reads to decide what to regenerate."""
    recorded = read_keys()
    return json.dumps({"generators": [
        {"generator": script, "kind": kind, "outputs": outputs,
         "state": state(script, recorded, key(script))}
        for script, outputs, _, kind in GENERATORS
    ]})


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--regenerate", action="store_true")
    parser.add_argument("--all", action="store_true")
    parser.add_argument("--fresh", nargs=2, metavar=("GENERATOR", "DIR"))
    parser.add_argument("--cache", default=os.path.join(ROOT, "validation", "out", "cache"))
    parser.add_argument("--key", metavar="GENERATOR")
    parser.add_argument("--json", action="store_true", help="each reference's state as one JSON object")
    args = parser.parse_args(argv)
    try:
        if args.json:
            print(states_json())
            return 0
        if args.key:
            print(key(args.key))
            return 0
        if args.fresh:
            ran = fresh(args.fresh[0], args.fresh[1], args.cache)
            print("regenerated" if ran else "cached")
            return 0
        if args.regenerate:
            regenerate(args.all)
            return 0
        return report()
    except (KeyError, FileNotFoundError, subprocess.CalledProcessError) as error:
        print(f"reference_keys.py: {error}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
