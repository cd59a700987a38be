"""The study's scenes: the procedural torus (common/mesh/procedural.cpp: radii 1 and 0.4 about the
z axis) at a given face count, seen from above, with a stroke file (common/strokes/stroke_file.hpp)
of N decal strokes drawn on its upper half.

Stroke i is a short arc on the surface (STROKE_LENGTH, about 20 px at the study's camera)
at a seeded random place and direction, projected to the window with the scene's camera,
so the first N strokes of every sweep point are the same strokes, whatever the mesh. They
lie where the tube faces the camera; the `lines` count of each point says how many show.
"""
import json
import math
import pathlib

import numpy as np

import plumbago_cli as pc

R, TUBE = 1.0, 0.4  # the procedural torus' radii
CAMERA = dict(eye=[0.0, -1.3, 4.4], target=[0.0, 0.0, 0.0], up=[0.0, 1.0, 0.0], fov_deg=40.0, near=1.0, far=9.0)
STROKE_LENGTH = 0.1  # surface units
STROKE_POINTS = 6
SEED = 2002


def surface(theta, phi):
    return np.array([(R + TUBE * math.cos(phi)) * math.cos(theta), (R + TUBE * math.cos(phi)) * math.sin(theta),
                     TUBE * math.sin(phi)])


def window(points, width, height):
    """Window pixels (origin bottom-left, docs/conventions.md) of world points through CAMERA."""
    eye, target, up = (np.array(CAMERA[k]) for k in ("eye", "target", "up"))
    f = (target - eye) / np.linalg.norm(target - eye)
    s = np.cross(f, up) / np.linalg.norm(np.cross(f, up))
    u = np.cross(s, f)
    t = math.tan(math.radians(CAMERA["fov_deg"]) / 2)
    out = []
    for p in points:
        d = p - eye
        z = d @ f
        out.append([(d @ s / (z * t * width / height) * 0.5 + 0.5) * width, (d @ u / (z * t) * 0.5 + 0.5) * height,
                    1.0])
    return out


def strokes(n, width, height):
    """The first n strokes of the seeded sequence, as stroke-file entries."""
    rng = np.random.default_rng(SEED)
    out = []
    for _ in range(n):
        theta, phi, heading = rng.uniform(0, 2 * math.pi), rng.uniform(0.15 * math.pi, 0.85 * math.pi), \
            rng.uniform(0, 2 * math.pi)
        step = np.linspace(-0.5, 0.5, STROKE_POINTS) * STROKE_LENGTH
        arc = [surface(theta + k * math.cos(heading) / (R + TUBE * math.cos(phi)), phi + k * math.sin(heading) / TUBE)
               for k in step]
        out.append({"role": "decal", "points": window(arc, width, height)})
    return out


def write(folder, faces, n, size):
    """Writes the scene (and, for n > 0, its stroke file) into `folder`; returns the scene's path."""
    width, height = map(int, size.split("x"))
    folder = pathlib.Path(folder)
    scene = {"objects": [{"mesh": {"procedural": "torus", "resolution": pc.torus_resolution(faces)},
                          "style": "strokes"}],
             "camera": CAMERA, "resolution": [width, height]}
    if n:
        drawn = {"camera": CAMERA, "resolution": [width, height], "strokes": strokes(n, width, height)}
        (folder / "decals.json").write_text(json.dumps(drawn))
        scene["stroke_files"] = ["decals.json"]
    path = folder / "scene.json"
    path.write_text(json.dumps(scene, indent=1))
    return str(path)
