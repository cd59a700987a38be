#!/usr/bin/python3
"""docs/images/direction_field_<name>.png: the d_min field of a scene's mesh, Lee's
propagation alone (curvature.direction_smoothing = 0) beside the default smoothing.

A short line along d_min at one vertex per screen cell (the one nearest the eye among
those facing it), over the mesh shaded grey, seen orthographically from the scene's
camera direction; coloured by firmness: orange where the directions were propagated
(0), black where the tensor's own are held fixed (1).

  figure.py SCENE OUT.png
"""
import json
import pathlib
import sys

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "lib"))
import field  # noqa: E402
import plumbago_cli as pc  # noqa: E402

CELLS = 60                   # screen cells across the mesh's larger extent: one line each at most
HALF_LENGTH = 0.42           # of a cell, in world units along d_min
DEFAULT_VIEW = [1, 0.7, 1.6]  # docs/scene-format.md: camera.view_direction


def camera_axes(scene):
    """Unit screen right, screen up and towards-the-eye vectors of the scene's camera direction."""
    camera = scene.get("camera", {})
    toward = np.array(camera.get("view_direction", DEFAULT_VIEW), float)
    toward /= np.linalg.norm(toward)
    right = np.cross(-toward, camera.get("up", [0, 1, 0]))
    right /= np.linalg.norm(right)
    return right, np.cross(right, -toward), toward


def sample(screen, depth, facing, cell):
    """One vertex per screen cell: the front-facing one nearest the eye."""
    candidates = np.flatnonzero(facing)
    keys = np.floor(screen[candidates] / cell).astype(np.int64)
    order = np.lexsort((-depth[candidates], keys[:, 1], keys[:, 0]))
    keys = keys[order]
    first = np.ones(len(order), bool)
    first[1:] = (keys[1:] != keys[:-1]).any(axis=1)
    return candidates[order[first]]


def shade(ax, p, triangles, view, toward, light):
    """The faces turned towards the eye, far to near, grey by their lighting."""
    from matplotlib.collections import PolyCollection
    corners = p[triangles]
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-30)
    front = np.flatnonzero(normals @ toward > 0)
    front = front[np.argsort(corners[front].mean(axis=1) @ toward)]
    grey = np.repeat((0.78 + 0.2 * np.clip(normals[front] @ light, 0, 1))[:, None], 3, axis=1)
    ax.add_collection(PolyCollection(corners[front] @ view, facecolors=grey, edgecolors=grey, linewidths=0.3))


def hedgehog(ax, k, view, toward):
    """A short line along d_min at the sampled vertices, orange (firmness 0) to black (1)."""
    from matplotlib.collections import LineCollection
    p = k["positions"].astype(np.float64)
    screen = p @ view
    cell = np.ptp(screen, axis=0).max() / CELLS
    chosen = sample(screen, p @ toward, k["normal"] @ toward > 0, cell)
    tip = HALF_LENGTH * cell * k["d_min"][chosen]
    segments = np.stack([(p[chosen] - tip) @ view, (p[chosen] + tip) @ view], 1)
    colour = np.array([0.9, 0.45, 0.0])[None] * (1 - k["firmness"][chosen, None])
    ax.add_collection(LineCollection(segments, colors=colour, linewidths=1.4))


def draw(ax, k, axes, light, title):
    right, up, toward = axes
    view = np.stack([right, up], 1)
    shade(ax, k["positions"].astype(np.float64), k["triangles"], view, toward, light)
    hedgehog(ax, k, view, toward)
    ax.autoscale_view()
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title(title, fontsize=12)


def stats_lines(k):
    """What run.py measures, per region: the edges' mean turn and the share turning more than 20 degrees."""
    edges = field.edges(k["triangles"])
    angles, masks = field.turn_deg(k, edges), field.regions(k, edges)
    mean, turning = zip(*(field.summary(angles[masks[region]])[1:] for region in ("propagated", "mixed", "all")))
    return ("propagated edges: mean %.1f°, %.1f%% turn > 20°\nmixed: %.1f°, %.1f%%; all: %.1f°, %.1f%%"
            % (mean[0], 100 * turning[0], mean[1], 100 * turning[1], mean[2], 100 * turning[2]))


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    scene_path, out = pathlib.Path(sys.argv[1]), sys.argv[2]
    scene = json.loads(scene_path.read_text())
    mesh = pathlib.Path(pc.scene_models(str(scene_path))[0])
    axes = camera_axes(scene)
    light = np.array(scene["lights"][0]["direction"] if scene.get("lights") else axes[2], float)
    light /= np.linalg.norm(light)
    titles = {"literal": "literal: Lee's propagation alone (direction_smoothing = 0)",
              "smoothed": "smoothed: the default (direction_smoothing = %d)"
              % pc.param_default("curvature.direction_smoothing")}
    plt = pc.pyplot()
    fig, panels = plt.subplots(1, 2, figsize=(16, 8.4))
    fig.subplots_adjust(left=0.01, right=0.99, bottom=0.05, top=0.88, wspace=0.02)
    for ax, setting in zip(panels, field.SETTINGS):
        k = pc.module().curvature(mesh, cache=False, **field.SETTINGS[setting])
        draw(ax, k, axes, light, titles[setting] + "\n" + stats_lines(k))
    fig.supxlabel("d_min on %s: orange where propagated (firmness 0), black where reliable (1), between where weakly "
                 "anisotropic" % mesh.name, fontsize=13)
    fig.savefig(out, dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    main()
