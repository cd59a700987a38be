"""Scene.compare and Scene.bench give what `plumbago compare --json` and `bench --json` print."""
import json

import plumbago as pg
from conftest import cli

STAGES = ["edge_detect", "contour_light"]


def test_compare_is_the_commands():
    s = pg.Scene("builtin:torus")
    s.size = (64, 64)
    r = s.compare(STAGES)
    printed = json.loads(cli("compare", "builtin:torus", "--size", "64x64", "--json", "--stages", ",".join(STAGES),
                             check=False).stdout)
    assert r["pass"] == printed["pass"] and r["renderer"] == printed["renderer"] == pg.renderer()
    assert [x["name"] for x in r["stages"]] == [x["name"] for x in printed["stages"]]
    for mine, theirs in zip(r["stages"], printed["stages"]):
        assert {k: mine[k] for k in ("pass", "max_abs", "rmse", "over_tolerance", "tolerance")} == \
            {k: theirs[k] for k in ("pass", "max_abs", "rmse", "over_tolerance", "tolerance")}


def test_bench_times_every_pass(backend):
    s = pg.Scene("builtin:torus")
    s.size = (64, 64)
    t = s.bench(frames=2, backend=backend)
    assert t["backend"] == backend and t["size"] == [64, 64] and t["frame_ms"] > 0
    assert "edge_detect" in "".join(t["stages"]) and all(ms >= 0 for ms in t["stages"].values())
