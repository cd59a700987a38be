#!/usr/bin/python3
"""Curvature accuracy against time: a radius sweep of the tensor (exact and approximate
ball), a degree sweep of the jet and the default (method = auto) on analytic surfaces,
regular, irregular and strongly irregular meshes (see README.md).

Calls the Python module's curvature() (no cache) on meshes written by surfaces.py and
compares its arrays with the exact curvature; the time is the computation's own.

Settings (experiments/config/*.yaml, curvature_accuracy): surfaces, meshings (regular,
irregular, strong), radii, ball_clips (exact, approximate: the approximate ball at each
radius > 0), degrees. One point per surface and meshing. Run through experiments/Snakefile (lib/study_cli.py).
"""
import pathlib
import sys
import tempfile

import numpy as np

import surfaces

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "lib"))
import plumbago_cli as pc  # noqa: E402
import study_cli  # noqa: E402

FIGURES = ["k_error_vs_time.png", "direction_error_vs_time.png"]
DEFAULT_RADIUS = 0.01        # only to size the meshes; the sweep sets the radius explicitly
EDGES_PER_DEFAULT_RADIUS = 2.0
UMBILIC_RATIO = 0.1          # directions are compared where the exact ones are defined


def boundary_distance(positions, triangles):
    """Distance from every vertex to the nearest vertex on an open boundary (inf if none)."""
    edges = np.sort(np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]]), axis=1)
    unique, count = np.unique(edges, axis=0, return_counts=True)
    border = np.unique(unique[count == 1])
    if border.size == 0:
        return np.full(len(positions), np.inf)
    out = np.empty(len(positions))
    for start in range(0, len(positions), 4096):
        chunk = positions[start:start + 4096]
        d = np.linalg.norm(chunk[:, None, :] - positions[border][None, :, :], axis=2)
        out[start:start + 4096] = d.min(axis=1)
    return out


def errors(k, truth, keep):
    """Median direction error (degrees), median relative errors of k_min and k_max, as in
    tests/curvature/curvature_test.cpp, and the share of vertices with either more than 50% off;
    `k` is plumbago.curvature's."""
    _, k_min, k_max, d_min = truth(k["positions"][keep].astype(np.float64))
    scale = 0.1 * np.maximum(np.abs(k_min), np.abs(k_max))
    e_min = np.abs(k["k_min"][keep] - k_min) / np.maximum(np.abs(k_min), scale)
    e_max = np.abs(k["k_max"][keep] - k_max) / np.maximum(np.abs(k_max), scale)
    defined = np.abs(k_max - k_min) >= UMBILIC_RATIO * (np.abs(k_max) + np.abs(k_min))
    cosine = np.abs(np.einsum("ij,ij->i", k["d_min"][keep].astype(np.float64), d_min))[defined]
    direction = np.degrees(np.arccos(np.minimum(cosine, 1.0)))
    far_off = np.mean((e_min > 0.5) | (e_max > 0.5))
    return (np.median(direction) if direction.size else np.nan), np.median(e_min), np.median(e_max), far_off


def points(s):
    return ["%s-%s" % (name, meshing) for name in s["surfaces"] for meshing in s["meshings"]]


def scenes(s):
    return []


def measure(s, point):
    name, meshing = point.rsplit("-", 1)
    make = surfaces.SURFACES[name]
    rows = []
    with tempfile.TemporaryDirectory(prefix="plumbago-curvature-") as folder:
        work = pathlib.Path(folder)
        rng = np.random.default_rng(1)
        coarse, _, _ = make(0.2, False, rng)
        diagonal = np.linalg.norm(coarse.max(0) - coarse.min(0))
        edge = DEFAULT_RADIUS * diagonal / EDGES_PER_DEFAULT_RADIUS
        positions, triangles, truth = make(edge, surfaces.JITTER[meshing], rng)
        mesh = work / f"{name}-{meshing}.obj"
        surfaces.write_obj(mesh, positions, triangles)
        keep = boundary_distance(positions, triangles) >= 0.1 * diagonal
        runs = [("default", 0, {})]
        runs += [("tensor", r, dict(method="tensor", radius=r)) for r in s["radii"]]
        runs += [("approximate", r, dict(method="tensor", radius=r, ball_clip="approximate"))
                 for r in s["radii"] if r > 0 and "approximate" in s["ball_clips"]]
        runs += [("jet", d, dict(method="jet", jet_degree=d)) for d in s["degrees"]]
        for method, setting, params in runs:
            k = pc.module().curvature(mesh, cache=False, **params)
            ms, used = k["ms"], k["method"]
            direction, e_min, e_max, far_off = errors(k, truth, keep)
            rows.append(dict(surface=name, meshing=meshing, vertices=len(positions), method=method,
                             setting=setting, ms=ms, direction_deg=direction, k_min_rel=e_min, k_max_rel=e_max,
                             far_off=far_off, used=used,
                             edges_per_radius=setting * diagonal / edge if method != "jet" else np.nan))
            print("%-9s %-9s %-11s %5g  %8.1f ms  direction %6.2f deg  k_min %6.2f%%  k_max %6.2f%%  > 50%% off "
                  "%6.2f%% (%s)" % (name, meshing, method, setting, ms, direction, 100 * e_min, 100 * e_max,
                                   100 * far_off, used), flush=True)
    return [{k: (float(v) if isinstance(v, np.floating) else v) for k, v in r.items()} for r in rows], \
        pc.machine("CPU (oneTBB), no GL")


ERROR_FLOOR = {"k_rel": 1e-4, "direction_deg": 1e-3}  # log axes: smaller errors are drawn at the floor


def plot(rows, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    names = [n for n in surfaces.SURFACES if any(r["surface"] == n for r in rows)]
    for metric, label, filename in [("k_rel", "median relative error of k (mean of k_min, k_max)",
                                     "k_error_vs_time.png"),
                                    ("direction_deg", "median direction error (degrees)",
                                     "direction_error_vs_time.png")]:
        fig, axes = plt.subplots(1, len(names), figsize=(4 * len(names), 4), sharey=False, squeeze=False)
        axes = axes[0]
        for ax, name in zip(axes, names):
            for method, marker in (("tensor", "o"), ("approximate", "^"), ("jet", "s")):
                for meshing, style in (("regular", "-"), ("irregular", "--"), ("strong", ":")):
                    sel = [r for r in rows if r["surface"] == name and r["method"] == method and r["meshing"] == meshing]
                    if not sel:
                        continue
                    x = [r["ms"] for r in sel]
                    y = [0.5 * (r["k_min_rel"] + r["k_max_rel"]) if metric == "k_rel" else r[metric] for r in sel]
                    y = [max(v, ERROR_FLOOR[metric]) for v in y]  # NaN (no defined directions) stays NaN
                    ax.plot(x, y, style, marker=marker, label=f"{method} {meshing}")
                    for r, xi, yi in zip(sel, x, y):
                        text = ("1-ring" if r["setting"] == 0 else "r=%g" % r["setting"]) if method != "jet" \
                            else "d=%d" % r["setting"]
                        ax.annotate(text, (xi, yi), fontsize=6, xytext=(2, 2), textcoords="offset points")
            count = sorted({int(r["vertices"]) for r in rows if r["surface"] == name})
            ax.set_title(f"{name} ({'/'.join(map(str, count))} vertices)")
            ax.set_xscale("log")
            if all(np.isnan(line.get_ydata()).all() for line in ax.get_lines()):
                ax.text(0.5, 0.5, "umbilic everywhere:\nno directions to compare", ha="center",
                        transform=ax.transAxes)
                continue
            ax.set_yscale("log")
            ax.set_xlabel("time (ms, 2 cores)")
            ax.grid(True, which="both", alpha=0.3)
        axes[0].set_ylabel(label)
        axes[0].legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(out / filename, dpi=120)
        plt.close(fig)


if __name__ == "__main__":
    study_cli.main(__doc__, sys.modules[__name__])
