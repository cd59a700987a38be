"""Scene.render and Scene.stages give what `plumbago render` writes: the PNG's bytes, the
EXR's floats, every buffer of --dump-stages, on both backends."""
import json

import numpy as np
from PIL import Image

import plumbago as pg
from conftest import cli

SCENE, SIZE, SETS = "builtin:torus", (96, 64), {"edge.depth_scale": 12, "contour.copies": 2}


def scene():
    s = pg.Scene(SCENE)
    s.size = SIZE
    for key, value in SETS.items():
        s.set(key, value)
    return s


def render_args(backend):
    args = [SCENE, "--backend", backend, "--size", "%dx%d" % SIZE]
    for key, value in SETS.items():
        args += ["--set", "%s=%s" % (key, value)]
    return args


def test_image_is_the_png_byte_for_byte(backend, tmp_path):
    cli("render", *render_args(backend), "-o", tmp_path / "x.png")
    img = scene().render(backend)
    png = np.asarray(Image.open(tmp_path / "x.png"))
    assert img.dtype == np.uint8 and img.shape == (SIZE[1], SIZE[0], png.shape[2])
    assert np.array_equal(img, png)


def test_linear_image_is_the_exr_exactly(backend, tmp_path):
    cli("render", *render_args(backend), "-o", tmp_path / "x.exr")
    img = scene().render(backend, linear=True)
    assert img.dtype == np.float32
    assert np.array_equal(img, pg.read_image(tmp_path / "x.exr"))


def test_stages_are_the_dumped_buffers_exactly(backend, tmp_path):
    cli("render", *render_args(backend), "-o", tmp_path / "x.png", "--dump-stages", tmp_path / "dump")
    stages = scene().stages(backend)
    files = {f.name[len(backend) + 1:-len(".exr")]: f for f in (tmp_path / "dump").glob(backend + ".*.exr")}
    assert sorted(stages) == sorted(files)
    assert "gbuffer.normal" in stages and stages["gbuffer.normal"].shape == (SIZE[1], SIZE[0], 3)
    for name, array in stages.items():
        saved = pg.read_image(files[name])  # a 2-channel buffer's file has a third channel of zeros
        channels = array.shape[2]
        assert saved.shape[:2] == array.shape[:2] and not saved[..., channels:].any(), name
        assert np.array_equal(array, saved[..., :channels]), name


def test_the_backends_differ_and_the_parameter_matters():
    s = scene()
    gpu, reference = s.render("gpu", linear=True), s.render("reference", linear=True)
    assert gpu.shape == reference.shape and not np.array_equal(gpu, reference)
    s.set("edge.depth_scale", 0)
    assert not np.array_equal(s.render("gpu", linear=True), gpu)


def test_a_dict_scene_renders_as_its_file(tmp_path):
    doc = {"objects": [{"mesh": {"procedural": "torus"}}], "resolution": [48, 40]}
    (tmp_path / "t.json").write_text(json.dumps(doc))
    cli("render", tmp_path / "t.json", "--backend", "reference", "-o", tmp_path / "t.png")
    assert np.array_equal(pg.Scene(doc).render("reference"), np.asarray(Image.open(tmp_path / "t.png")))


def test_frames_of_a_camera_path(tmp_path):
    doc = {"objects": [{"mesh": {"procedural": "sphere"}}], "resolution": [32, 32],
           "animation": {"orbit_deg": 90, "frames": 3, "fps": 30}}
    s = pg.Scene(doc)
    assert s.frames == 3
    (tmp_path / "p.json").write_text(json.dumps(doc))
    cli("render", tmp_path / "p.json", "--frame", 2, "-o", tmp_path / "f2.png")
    assert np.array_equal(s.render(frame=2), np.asarray(Image.open(tmp_path / "f2.png")))
