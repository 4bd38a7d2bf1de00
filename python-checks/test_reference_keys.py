"""The references are regenerated only when what made them changes, and a
changed generator, input, tool pin, or a corrupted file is always caught."""
import json
import os
import shutil

import pytest

import reference_keys as rk
import reproduce


def test_every_committed_reference_is_current_by_its_key():
    recorded = rk.read_keys()
    assert [g[0] for g in rk.GENERATORS] == list(recorded), "keys.json lists the generators in order"
    stale = {script: why for script in recorded
             if (why := rk.state(script, recorded, rk.key(script)))}
    assert not stale, f"{stale}; regenerate with: {rk.REGENERATE}"


def test_each_kind_of_reference_has_one_regenerated_from_scratch():
    kinds = {kind for _, _, _, kind in rk.GENERATORS}
    assert set(rk.FROM_SCRATCH) == kinds
    for kind, (script, _) in rk.FROM_SCRATCH.items():
        assert rk.generator(script)[3] == kind, script


def committed_part(script, name, only):
    """The committed file ``name`` of ``script``, or of it the part ``only``
    as the generator's ``--only`` writes it."""
    with open(rk.committed_path(name), "rb") as fh:
        data = fh.read()
    if only is None:
        return data
    assert script == "mitsuba_render.py", f"{script} has no parts"
    import mitsuba_render as mr
    return mr.to_text(mr.select(json.loads(data), only)).encode()


@pytest.mark.parametrize("kind", sorted(rk.FROM_SCRATCH))
def test_a_reference_of_each_kind_reproduces_from_scratch(kind, tmp_path):
    """The generator runs in its own process, as ``optics validate`` runs it,
    and each file it writes must reproduce the committed one by
    ``reproduce.py``'s rule for that file (byte for byte unless the rule
    allows a stated tolerance)."""
    script, only = rk.FROM_SCRATCH[kind]
    rk.run_generator(script, str(tmp_path), only=only)
    for name in rk.generator(script)[1]:
        tolerance, f32 = reproduce.rule_for(name)
        with open(tmp_path / name, "rb") as fresh:
            found = reproduce.differences(committed_part(script, name, only), fresh.read(),
                                          tolerance, f32_tolerances=f32)
        assert not found, f"{name}: {found}; regenerate with: {rk.REGENERATE}"


def test_one_scenes_part_of_the_renders_is_the_whole_documents_part():
    # The partial document the proof regenerates is the committed one with
    # the other scenes left out, and nothing else changed.
    import mitsuba_render as mr
    with open(mr.DEFAULT_PATH, encoding="utf-8") as fh:
        whole = json.load(fh)
    part = mr.select(whole, "shadow")
    assert [entry["name"] for entry in part["scenes"]] == ["shadow"]
    assert {k: v for k, v in part.items() if k not in ("scenes", "excluded")} == \
        {k: v for k, v in whole.items() if k not in ("scenes", "excluded")}
    assert "shadow" in [e["name"] for e in whole["scenes"]]


def test_the_scene_list_input_is_the_one_the_render_generators_read():
    # The render generators read their scenes through scene_list.py; their
    # keys must hash the file it reads, or a new scene would leave them
    # unchanged.
    import scene_list
    assert rk.SCENE_LIST == scene_list.SCENE_LIST
    for script in ("mitsuba_render.py", "mitsuba_full_light.py"):
        assert "scene_list.py" in rk.local_modules(script), script
        assert rk.SCENE_LIST in rk.generator(script)[2], script


@pytest.fixture
def tree(tmp_path):
    """A copy of the files a render reference's key reads."""
    shutil.copytree(rk.HERE, tmp_path / "python-checks",
                    ignore=shutil.ignore_patterns("__pycache__"))
    for pattern in (rk.SCENE_LIST, "crates/tracer/scenes/*.json"):
        for name, _ in rk.inputs([pattern]):
            os.makedirs(tmp_path / os.path.dirname(name), exist_ok=True)
            shutil.copyfile(os.path.join(rk.ROOT, name), tmp_path / name)
    return tmp_path


def key_of(tree, script="mitsuba_render.py", python="3.11"):
    return rk.key(script, root=str(tree), folder=str(tree / "python-checks"),
                  requirements=str(tree / "python-checks" / "requirements.txt"), python=python)


def append(path, text):
    with open(path, "a", encoding="utf-8") as fh:
        fh.write(text)


@pytest.mark.parametrize("change", [
    "the generator", "a module it imports", "a scene file", "the scene list",
    "a tool pin", "the python version",
])
def test_a_changed_input_changes_the_key(tree, change):
    before = key_of(tree)
    python = "3.11"
    if change == "the generator":
        append(tree / "python-checks" / "mitsuba_render.py", "\n# changed\n")
    elif change == "a module it imports":
        append(tree / "python-checks" / "atomic_write.py", "\n# changed\n")
    elif change == "a scene file":
        append(tree / "crates" / "tracer" / "scenes" / "shadow.json", " ")
    elif change == "the scene list":
        path = tree / rk.SCENE_LIST
        text = path.read_text(encoding="utf-8").replace('"shadow",', '"shadow",\n    "new_scene",', 1)
        assert "new_scene" in text
        path.write_text(text, encoding="utf-8")
    elif change == "a tool pin":
        path = tree / "python-checks" / "requirements.txt"
        path.write_text(path.read_text().replace("mitsuba==", "mitsuba==9"), encoding="utf-8")
    else:
        python = "3.12"
    assert key_of(tree, python=python) != before, change


def test_a_change_outside_what_a_generator_reads_keeps_its_key(tree):
    before = key_of(tree, "flip_reference.py")
    append(tree / "python-checks" / "mitsuba_render.py", "\n# changed\n")
    append(tree / "crates" / "tracer" / "scenes" / "shadow.json", " ")
    assert key_of(tree, "flip_reference.py") == before


def test_a_scene_list_that_cannot_be_found_is_an_error_not_an_empty_input(tree):
    (tree / rk.SCENE_LIST).unlink()
    with pytest.raises(FileNotFoundError):
        key_of(tree)


def test_a_corrupted_or_stale_committed_reference_is_not_current(tmp_path, monkeypatch):
    recorded = rk.read_keys()
    script = "flip_reference.py"
    entry = recorded[script]
    assert rk.state(script, recorded, entry["key"]) is None
    assert "stale" in rk.state(script, recorded, "0" * 64)
    corrupted = dict(entry, outputs={name: "0" * 64 for name in entry["outputs"]})
    assert "SHA-256" in rk.state(script, {script: corrupted}, entry["key"])
    assert rk.state(script, {}, entry["key"]) == "no key recorded"


def fake_generator(calls):
    def run(script, folder):
        calls.append(script)
        os.makedirs(folder, exist_ok=True)
        for name in rk.generator(script)[1]:
            with open(os.path.join(folder, name), "w", encoding="utf-8") as fh:
                fh.write(f"{name} as written\n")
    return run


def test_a_whole_cache_entry_of_this_key_is_used_and_anything_else_regenerated(tmp_path, monkeypatch):
    calls, cache, out = [], tmp_path / "cache", tmp_path / "out"
    run = fake_generator(calls)
    script = "colorimetry.py"
    assert rk.fresh(script, out, cache, run) is True
    assert rk.fresh(script, out, cache, run) is False, "an unchanged key is served from the cache"
    assert calls == [script]
    assert (out / "cie_tables.rs").read_text() == "cie_tables.rs as written\n"

    entry = cache / "colorimetry"
    (entry / "colorimetry.json").write_text("corrupted\n")
    assert rk.fresh(script, out, cache, run) is True, "a corrupted entry is regenerated"
    assert (out / "colorimetry.json").read_text() == "colorimetry.json as written\n"

    (entry / "cie_tables.rs").unlink()
    assert rk.fresh(script, out, cache, run) is True, "an incomplete entry is regenerated"

    manifest = json.loads((entry / "entry.json").read_text())
    (entry / "entry.json").write_text(json.dumps(dict(manifest, key="0" * 64)))
    assert rk.fresh(script, out, cache, run) is True, "an entry of another key is regenerated"

    (entry / "entry.json").write_text("{ not json")
    assert rk.fresh(script, out, cache, run) is True, "an unreadable entry is regenerated"

    monkeypatch.setattr(rk, "key", lambda script: "f" * 64)
    assert rk.fresh(script, out, cache, run) is True, "a changed key is regenerated"
    assert len(calls) == 6
