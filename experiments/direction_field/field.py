"""The d_min field of a mesh (plumbago.curvature: per-vertex arrays and the welded mesh's
triangles) and how much it turns across the mesh's edges; run.py and figure.py share it.
"""
import numpy as np

SETTINGS = {"literal": {"direction_smoothing": 0},  # Lee et al. 2006 §5.3's propagation alone
            "smoothed": {}}                          # the default smoothing sweeps
TURN_DEG = 20.0  # an edge "turns" when its ends' d_min lines differ by more


def edges(triangles):
    pairs = np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    return np.unique(np.sort(pairs, axis=1), axis=0)


def turn_deg(k, edges):
    """Per edge (a, b): the angle, modulo pi, between d_min at a and d_min at b projected
    into a's tangent plane (degrees); `k` is plumbago.curvature's."""
    a, b = edges.T
    normal, d_min = k["normal"].astype(np.float64), k["d_min"].astype(np.float64)
    moved = d_min[b] - np.einsum("ij,ij->i", d_min[b], normal[a])[:, None] * normal[a]
    length = np.maximum(np.linalg.norm(moved, axis=1), 1e-12)
    cosine = np.abs(np.einsum("ij,ij->i", d_min[a], moved)) / length
    return np.degrees(np.arccos(np.minimum(cosine, 1.0)))


def regions(k, edges):
    """Edge masks: both ends reliable (firmness 1), both propagated (0), the rest (mixed), which is
    the border (one end reliable, the other propagated) and the weak (an end in between), and all."""
    firm = k["firmness"][edges]
    reliable, propagated = (firm == 1).all(axis=1), (firm == 0).all(axis=1)
    weak = ((firm > 0) & (firm < 1)).any(axis=1)
    mixed = ~(reliable | propagated)
    return {"reliable": reliable, "propagated": propagated, "mixed": mixed, "border": mixed & ~weak, "weak": weak,
            "all": np.ones(len(edges), bool)}


def vertex_counts(k):
    """Vertices reliable (firmness 1), propagated (0) and weak (in between)."""
    firm = k["firmness"]
    return {"reliable_vertices": int(np.sum(firm == 1)), "propagated_vertices": int(np.sum(firm == 0)),
            "weak_vertices": int(np.sum((firm > 0) & (firm < 1)))}


def summary(angles):
    """Edges, mean angle (degrees) and the share turning more than TURN_DEG."""
    if angles.size == 0:
        return 0, np.nan, np.nan
    return angles.size, float(np.mean(angles)), float(np.mean(angles > TURN_DEG))
