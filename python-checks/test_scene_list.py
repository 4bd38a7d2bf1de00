"""The scene list Python reads is the tracer's file, read whole or refused."""
import json
import os

import pytest

import scene_list


def test_the_course_list_names_the_tracers_scene_files():
    names = scene_list.course_scenes()
    assert names and len(set(names)) == len(names)
    for name in names:
        assert os.path.isfile(os.path.join(scene_list.ROOT, "crates", "tracer", "scenes", f"{name}.json")), name


def write_list(root, document):
    path = root / scene_list.SCENE_LIST
    path.parent.mkdir(parents=True)
    path.write_text(json.dumps(document), encoding="utf-8")


def test_the_course_list_is_read_in_its_order(tmp_path):
    write_list(tmp_path, {"course": ["b", "a"], "technique": []})
    assert scene_list.course_scenes(root=str(tmp_path)) == ["b", "a"]


@pytest.mark.parametrize("document", [
    [], {"technique": ["a"]}, {"course": "a"}, {"course": ["a", 1]}, {"course": [""]},
])
def test_a_list_without_course_names_is_refused_naming_the_file(tmp_path, document):
    write_list(tmp_path, document)
    with pytest.raises(ValueError, match="shipped.json"):
        scene_list.course_scenes(root=str(tmp_path))
