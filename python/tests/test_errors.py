"""Bad input raises exceptions that carry the command line's messages (the file and line, or
the key), and leaves the scene as it was."""
import json

import pytest

import plumbago as pg
from conftest import cli


def cli_error(*args):
    """The message `plumbago` prints for a refused input (exit code 2)."""
    result = cli(*args, check=False)
    assert result.returncode == 2, result.stderr
    return result.stderr.strip().removeprefix("plumbago: error: ")


def test_a_broken_scene_file_names_its_line(tmp_path):
    path = tmp_path / "broken.json"
    path.write_text('{\n  "mesh": {"procedural": "torus"},\n  "resolution": [64, 64,\n}\n')
    with pytest.raises(pg.SceneError) as e:
        pg.Scene(str(path))
    assert str(path) in str(e.value) and "line 4" in str(e.value)
    assert str(e.value) == cli_error("render", path, "-o", tmp_path / "x.png")
    assert not (tmp_path / "x.png").exists()


def test_a_bad_key_of_a_dict_scene_is_named():
    with pytest.raises(pg.SceneError, match="/objects/0/colour"):
        pg.Scene({"objects": [{"mesh": {"procedural": "torus"}, "colour": [1, 0, 0]}]})


def test_a_missing_mesh_names_the_file(tmp_path):
    path = tmp_path / "m.json"
    path.write_text(json.dumps({"mesh": "no_such.obj"}))
    with pytest.raises(ValueError, match="no_such.obj") as e:
        pg.Scene(path)
    assert str(e.value) == cli_error("render", path, "-o", tmp_path / "x.png")


def test_a_bad_parameter_is_a_value_error_naming_it():
    s = pg.Scene("builtin:torus")
    with pytest.raises(ValueError, match="edge.no_such"):
        s.set("edge.no_such", 1)
    with pytest.raises(ValueError, match=r"edge.depth_scale.*1e\+39") as e:
        s.set("edge.depth_scale", 1e39)
    assert "--set: " + str(e.value) == cli_error("render", "builtin:torus", "--set", "edge.depth_scale=1e39")
    with pytest.raises(ValueError, match="edge.normals.*'sideways'"):
        s.set("edge.normals", "sideways")
    with pytest.raises(ValueError, match="edge.depth_scale"):
        s.set("edge.depth_scale", [1])
    assert s.get("edge.depth_scale") == pg.params("edge")["edge.depth_scale"]["default"]


def test_values_of_every_type():
    s = pg.Scene("builtin:torus")
    s.set("edge.depth_scale", 12)
    s.set("edge.normals", "face")
    s.set("curvature.direction_smoothing", 3)
    s.set("curvature.ring_fallback", False)
    assert (s.get("edge.depth_scale"), s.get("edge.normals")) == (12.0, "face")
    assert (s.get("curvature.direction_smoothing"), s.get("curvature.ring_fallback")) == (3, False)


def test_a_bad_size_keeps_the_old_one():
    s = pg.Scene("builtin:torus")
    before = s.size
    with pytest.raises(ValueError, match="size: 0x10 is out of range"):
        s.size = (0, 10)
    assert s.size == before


def test_bad_backend_frame_and_stage():
    s = pg.Scene("builtin:torus")
    s.size = (16, 16)
    with pytest.raises(ValueError, match="'vulkan'"):
        s.render("vulkan")
    with pytest.raises(ValueError, match="frame 1: the scene has 1 frame"):
        s.render(frame=1)
    with pytest.raises(ValueError, match="no_such_stage"):
        s.compare(["no_such_stage"])
    with pytest.raises(ValueError, match="unknown stage 'nope'"):
        pg.params("nope")


def test_memory_budget_refuses_before_rendering():
    s = pg.Scene("builtin:torus")
    s.size = (16384, 16384)
    with pytest.raises(ValueError, match="memory budget"):
        s.render("reference")
