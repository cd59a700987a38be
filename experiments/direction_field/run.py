#!/usr/bin/python3
"""How smooth the d_min field is where the curvature is reliable and where it was
propagated (issue 19 §4), with Lee's propagation alone (`literal`:
curvature.direction_smoothing = 0) and with the default smoothing (`smoothed`).

Calls the Python module's curvature() (no cache) on the shared models and on meshes written
by ../curvature_accuracy/surfaces.py; over the mesh's edges, the angle modulo pi between the
two ends' d_min (field.py), summarised per region: both ends reliable (firmness 1), both
propagated (firmness 0), the rest (mixed: the border between the two, and edges with a
weakly anisotropic end), and all edges. Time: the computation's own (curvature()'s ms).

Settings (experiments/config/*.yaml, direction_field): models (names in ../shared/models,
skipped when absent), surfaces, meshings, edges_per_diagonal (the analytic meshes' edge
length), repeats (the fastest run's time is kept). One point per mesh.
Run through experiments/Snakefile (lib/study_cli.py).
"""
import pathlib
import sys
import tempfile

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "lib"))
sys.path.insert(0, str(HERE.parent / "curvature_accuracy"))
import field  # noqa: E402
import plumbago_cli as pc  # noqa: E402
import study_cli  # noqa: E402
import surfaces  # noqa: E402

MODELS = pc.ROOT.parent / "shared" / "models"
MODEL_NAMES = ["fandisk", "stanford-bunny", "ogre"]  # the full config's models, inputs of the jobs (READS)
READS = ["experiments/direction_field/field.py", "experiments/curvature_accuracy/surfaces.py"] + \
    [str(MODELS / (m + ".obj")) for m in MODEL_NAMES if (MODELS / (m + ".obj")).is_file()]
FIGURES = ["turning_edges.png"]
# The pictures of the field in docs/images/direction_field_<name>.png (figure.py), from these scenes' cameras.
IMAGES = {"fandisk": "scenes/fandisk_pencil.json", "ogre": "scenes/ogre_sketchy.json"}


def points(s):
    models = [m for m in s["models"] if (MODELS / (m + ".obj")).is_file()]
    return models + ["%s-%s" % (name, meshing) for name in s["surfaces"] for meshing in s["meshings"]]


def scenes(s):
    return []


def analytic_mesh(s, point, folder):
    """Writes the surface and meshing `point` names as an OBJ file in `folder`; its path."""
    name, meshing = point.rsplit("-", 1)
    make, rng = surfaces.SURFACES[name], np.random.default_rng(1)
    coarse, _, _ = make(0.2, 0.0, rng)
    edge = np.linalg.norm(coarse.max(0) - coarse.min(0)) / s["edges_per_diagonal"]
    positions, triangles, _ = make(edge, surfaces.JITTER[meshing], rng)
    path = pathlib.Path(folder) / (point + ".obj")
    surfaces.write_obj(path, positions, triangles)
    return path


def measure_setting(mesh, setting, repeats):
    """The rows of one setting: one per region, each with the fastest of `repeats` runs' time."""
    runs = [pc.module().curvature(mesh, cache=False, **field.SETTINGS[setting]) for _ in range(repeats)]
    k = runs[0]
    edges = field.edges(k["triangles"])
    angles, counts = field.turn_deg(k, edges), field.vertex_counts(k)
    rows = []
    for region, mask in field.regions(k, edges).items():
        count, mean, turning = field.summary(angles[mask])
        rows.append(dict(setting=setting, region=region, edges=count, mean_deg=mean, over_20=turning,
                         vertices=len(k["k_min"]), **counts, method=k["method"], ms=min(r["ms"] for r in runs)))
        pc.log("%-22s %-8s %-10s %7d edges  mean %6.2f deg  > 20 deg %6.2f%%  %8.1f ms (%s)"
               % (mesh.stem, setting, region, count, mean, 100 * turning, rows[-1]["ms"], k["method"]))
    return rows


def measure(s, point):
    model = point in s["models"]
    with tempfile.TemporaryDirectory(prefix="plumbago-direction-field-") as folder:
        mesh = MODELS / (point + ".obj") if model else analytic_mesh(s, point, folder)
        name, meshing = (point, "model") if model else point.rsplit("-", 1)
        rows = [dict(mesh=name, meshing=meshing, **r) for setting in field.SETTINGS
                for r in measure_setting(mesh, setting, s["repeats"])]
    return rows, pc.machine("CPU (oneTBB), no GL")


PANELS = {"propagated": "both ends propagated (firmness 0)", "border": "one end reliable, the other propagated",
          "weak": "an end weakly anisotropic (0 < firmness < 1)"}


def plot(rows, out):
    plt = pc.pyplot()
    meshes = list(dict.fromkeys((r["mesh"], r["meshing"]) for r in rows))
    y = np.arange(len(meshes))[::-1]
    fig, axes = plt.subplots(1, 3, figsize=(13, 0.35 * len(meshes) + 1.5), sharey=True)
    for ax, region in zip(axes, ("propagated", "border", "weak")):  # reliable directions are held fixed: the same
        for offset, setting in ((0.2, "literal"), (-0.2, "smoothed")):
            share = [next(100 * r["over_20"] for r in rows if (r["mesh"], r["meshing"]) == m
                          and r["setting"] == setting and r["region"] == region) for m in meshes]
            ax.barh(y + offset, share, 0.4, label=setting)
        ax.set_title(PANELS[region], fontsize=10)
        ax.set_xlabel("edges whose d_min turns > 20 degrees (%)")
        ax.grid(True, axis="x", alpha=0.3)
    axes[0].set_yticks(y, ["%s, %s" % m if m[1] != "model" else m[0] for m in meshes])
    axes[-1].legend(loc="lower right")
    pc.save_figure(fig, out, FIGURES[0])


if __name__ == "__main__":
    study_cli.main(__doc__, sys.modules[__name__])
