"""params() and effects() hold what `plumbago params` and `plumbago effects` print."""
import plumbago as pg
from conftest import cli


def test_params_are_the_commands():
    rows = [line.split(None, 4) for line in cli("params").stdout.splitlines()]
    params = pg.params()
    assert list(params) == [r[0] for r in rows]
    for key, type_, default, _, _ in rows:
        p = params[key]
        assert p["type"] == type_ and p["doc"] and p["range"]
        assert str(p["default"]).lower() == default or float(p["default"]) == float(default), key


def test_one_stages_params():
    edge = pg.params("edge")
    assert edge and all(k.startswith("edge.") for k in edge)
    assert edge["edge.normals"]["choices"] and "min" in edge["edge.depth_scale"]


def test_effects_are_the_commands():
    lines = cli("effects").stdout.splitlines()
    names = [line.split()[0] for line in lines[0::2]]
    runs = [line.split("runs:")[1].split() for line in lines[1::2]]
    effects = pg.effects()
    assert [e["name"] for e in effects] == names
    assert [e["stages"] for e in effects] == runs
    assert all(e["doc"] for e in effects)
