"""Scene.lines gives the paths `plumbago lines -o x.json` writes, on both backends."""
import json
import re

import numpy as np

import plumbago as pg
from conftest import cli


def test_paths_are_the_json(backend, tmp_path):
    out = cli("lines", "builtin:cad", "--size", "160x120", "--backend", backend, "-o", tmp_path / "l.json").stdout
    saved = json.loads((tmp_path / "l.json").read_text())["paths"]
    s = pg.Scene("builtin:cad")
    s.size = (160, 120)
    paths = s.lines(backend)
    assert len(paths) == len(saved) > 0
    for p, q in zip(paths, saved):
        assert (p["kind"], p["object"], p["closed"]) == (q["kind"], q["object"], q["closed"])
        assert np.array_equal(p["points"], np.array(q["points"]).reshape(-1, 3))
        assert np.array_equal(p["screen"], np.array(q["screen"]).reshape(-1, 2))
        assert p["visible"].dtype == bool and list(p["visible"]) == q["visible"]
    shown, runs = map(int, re.search(r"(\d+) shown, (\d+) visible runs", out).groups())
    assert sum(1 for p in paths if p["runs"]) == shown and sum(len(p["runs"]) for p in paths) == runs
