"""The scenes the tracer ships, from their one list.

``crates/tracer/src/scene/shipped.json`` lists them: ``course``, the
course's scenes in the order the course meets them, which the harness
cross-checks against Mitsuba, and ``technique``, the scenes that show a
technique. The tracer reads the same file (``tracer::scene::course_scenes``);
each scene is ``crates/tracer/scenes/<name>.json``.
"""
import json
import os

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE_LIST = "crates/tracer/src/scene/shipped.json"


def course_scenes(root=ROOT):
    """The course scenes' names, in the list's order; ValueError naming the
    file if it is not an object whose ``course`` is a list of names."""
    path = os.path.join(root, SCENE_LIST)
    with open(path, encoding="utf-8") as fh:
        lists = json.load(fh)
    names = lists.get("course") if isinstance(lists, dict) else None
    if not isinstance(names, list) or not all(isinstance(n, str) and n for n in names):
        raise ValueError(f"{SCENE_LIST}: expected {{\"course\": [names], ...}}")
    return names
