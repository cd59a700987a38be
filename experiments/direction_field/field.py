"""The d_min field of `plumbago curvature` and how much it turns across the mesh's edges;
run.py and figure.py share it.

A mesh's faces come from its OBJ file, welded and cleaned as plumbago's loader does
(identical positions merged in order of first use, faces that lose a corner dropped), and
are used only when the CSV has as many vertices at the same positions.
"""
import pathlib
import re
import subprocess
import tempfile

import numpy as np

SETTINGS = {"literal": ["--set", "curvature.direction_smoothing=0"],  # Lee et al. 2006 §5.3's propagation alone
            "smoothed": []}                                          # the default smoothing sweeps
TURN_DEG = 20.0  # an edge "turns" when its ends' d_min lines differ by more


def run_curvature(plumbago, mesh, args):
    """`plumbago curvature MESH --no-cache ARGS`: (its reported ms, the CSV as an array, the method used)."""
    with tempfile.TemporaryDirectory(prefix="plumbago-direction-field-") as folder:
        out = pathlib.Path(folder) / "k.csv"
        result = subprocess.run([plumbago, "curvature", str(mesh), "-o", str(out), "--no-cache"] + args,
                                capture_output=True, text=True, check=True)
        table = np.loadtxt(out, delimiter=",", skiprows=1, ndmin=2)
    summary = re.search(r"vertices, (\w+), ([0-9.]+) ms", result.stderr)
    return float(summary.group(2)), table, summary.group(1)


def read_obj(path):
    """Positions (float32) and triangles (polygons fanned) of an OBJ file, as written."""
    positions, triangles = [], []
    for line in open(path):
        words = line.split()
        if words[:1] == ["v"]:
            positions.append([float(w) for w in words[1:4]])
        elif words[:1] == ["f"]:
            corners = [int(w.split("/")[0]) for w in words[1:]]
            corners = [c - 1 if c > 0 else len(positions) + c for c in corners]
            triangles += [(corners[0], corners[i], corners[i + 1]) for i in range(1, len(corners) - 1)]
    return np.array(positions, np.float32), np.array(triangles, np.int64)


def welded_faces(path, table):
    """The triangles of OBJ file `path` indexing the rows of `table` (plumbago's CSV)."""
    positions, triangles = read_obj(path)
    _, first, inverse = np.unique(positions + np.float32(0.0), axis=0, return_index=True, return_inverse=True)
    rank = np.argsort(np.argsort(first))  # welded vertices numbered in order of first appearance
    kept, triangles = positions[np.sort(first)], rank[inverse.ravel()][triangles]
    triangles = triangles[(triangles[:, 0] != triangles[:, 1]) & (triangles[:, 1] != triangles[:, 2])
                          & (triangles[:, 2] != triangles[:, 0])]
    scale = np.abs(kept).max() if len(kept) else 1.0
    if len(kept) != len(table) or np.abs(kept - table[:, 1:4]).max() > 1e-6 * scale:
        raise SystemExit("%s: %d welded vertices do not match the CSV's %d rows" % (path, len(kept), len(table)))
    return triangles


def edges(triangles):
    pairs = np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    return np.unique(np.sort(pairs, axis=1), axis=0)


def turn_deg(table, edges):
    """Per edge (a, b): the angle, modulo pi, between d_min at a and d_min at b projected
    into a's tangent plane (degrees)."""
    a, b = edges.T
    normal, d_min = table[:, 4:7], table[:, 9:12]
    moved = d_min[b] - np.einsum("ij,ij->i", d_min[b], normal[a])[:, None] * normal[a]
    length = np.maximum(np.linalg.norm(moved, axis=1), 1e-12)
    cosine = np.abs(np.einsum("ij,ij->i", d_min[a], moved)) / length
    return np.degrees(np.arccos(np.minimum(cosine, 1.0)))


def regions(table, edges):
    """Edge masks: both ends reliable (firmness 1), both propagated (0), the rest (mixed), which is
    the border (one end reliable, the other propagated) and the weak (an end in between), and all."""
    firm = table[edges, 15]
    reliable, propagated = (firm == 1).all(axis=1), (firm == 0).all(axis=1)
    weak = ((firm > 0) & (firm < 1)).any(axis=1)
    mixed = ~(reliable | propagated)
    return {"reliable": reliable, "propagated": propagated, "mixed": mixed, "border": mixed & ~weak, "weak": weak,
            "all": np.ones(len(edges), bool)}


def vertex_counts(table):
    """Vertices reliable (firmness 1), propagated (0) and weak (in between)."""
    firm = table[:, 15]
    return {"reliable_vertices": int(np.sum(firm == 1)), "propagated_vertices": int(np.sum(firm == 0)),
            "weak_vertices": int(np.sum((firm > 0) & (firm < 1)))}


def summary(angles):
    """Edges, mean angle (degrees) and the share turning more than TURN_DEG."""
    if angles.size == 0:
        return 0, np.nan, np.nan
    return angles.size, float(np.mean(angles)), float(np.mean(angles > TURN_DEG))
