"""curvature() gives the numbers `plumbago curvature` writes as CSV, exactly."""
import numpy as np
import pytest

import plumbago as pg
from conftest import cli

COLUMNS = {"positions": [1, 2, 3], "normal": [4, 5, 6], "k_min": 7, "k_max": 8, "d_min": [9, 10, 11],
           "d_max": [12, 13, 14], "firmness": 15}


def write_torus(path, n=24, m=12, major=1.0, minor=0.4):
    """A torus as an OBJ file: n x m quads, each two triangles."""
    u, v = np.meshgrid(np.arange(n) * 2 * np.pi / n, np.arange(m) * 2 * np.pi / m, indexing="ij")
    points = np.stack([(major + minor * np.cos(v)) * np.cos(u), (major + minor * np.cos(v)) * np.sin(u),
                       minor * np.sin(v)], -1).reshape(-1, 3)
    faces = []
    for i in range(n):
        for j in range(m):
            a, b, c, d = i * m + j, ((i + 1) % n) * m + j, ((i + 1) % n) * m + (j + 1) % m, i * m + (j + 1) % m
            faces += [(a, b, c), (a, c, d)]
    with open(path, "w") as f:
        f.writelines("v %.9g %.9g %.9g\n" % tuple(p) for p in points)
        f.writelines("f %d %d %d\n" % (a + 1, b + 1, c + 1) for a, b, c in faces)
    return len(points), len(faces)


@pytest.mark.parametrize("settings", [{}, {"method": "jet", "direction_smoothing": 0}])
def test_arrays_are_the_csv(tmp_path, settings):
    mesh = tmp_path / "torus.obj"
    vertices, faces = write_torus(mesh)
    args = sum((["--set", "curvature.%s=%s" % kv] for kv in settings.items()), [])
    cli("curvature", mesh, "-o", tmp_path / "k.csv", "--no-cache", "--quiet", *args)
    table = np.loadtxt(tmp_path / "k.csv", delimiter=",", skiprows=1, dtype=np.float32)
    k = pg.curvature(mesh, cache=False, **settings)
    assert k["positions"].shape == (vertices, 3) and k["triangles"].shape == (faces, 3)
    for name, columns in COLUMNS.items():
        assert k[name].dtype == np.float32
        assert np.array_equal(k[name], table[:, columns]), name
    assert k["method"] == settings.get("method", "tensor") and k["ms"] > 0


def test_refusals(tmp_path):
    with pytest.raises(pg.MeshError, match="nothing.obj"):
        pg.curvature(tmp_path / "nothing.obj")
    mesh = tmp_path / "torus.obj"
    write_torus(mesh)
    with pytest.raises(ValueError, match="curvature.no_such"):
        pg.curvature(mesh, no_such=1)
