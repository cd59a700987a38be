#!/usr/bin/env python3
"""Draws the strokes of the stand-ins for Kalnins et al. 2002's Table 1 scenes over their
renderings, as SVG, and makes them stroke files with `plumbago strokefile` (Kalnins et al. 2002, §3, §6):

  draw_stand_ins.py snowman     scenes/drawn/snowman.svg -> snowman.strokes.json: the face
                                and buttons as decals, structured hatching on the shadow
                                side of each ball, two layers of mobile hatching on each
                                tree (Fig. 8)
  draw_stand_ins.py cup         scenes/drawn/cup.svg -> cup.strokes.json: flowers, leaves and
                                a band as decals on spot's flank (Table 1's cup)
  draw_stand_ins.py breakfast   scenes/drawn/breakfast.level<k>.svg -> .strokes.json: free
                                hatching on each object's shadow side, level 0 from the
                                scene's camera, level 1 denser from halfway to the table (Fig. 7)

An artist would draw these over `plumbago render SCENE`'s PNG; here the scene's own camera
places them (the spheres' and cones' outlines projected, the models' bounding boxes), so
that they can be drawn again when a scene changes. Run from the repository root; PLUMBAGO
names the program (default build/plumbago).
"""
import json
import math
import os
import random
import subprocess
import sys
import tempfile

import numpy as np

from hatch_svg import hatches, svg

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


class Camera:
    """docs/conventions.md's camera: look-at, vertical field of view, window origin bottom-left."""

    def __init__(self, c, width, height):
        self.eye, self.target, self.up = (np.array(c[k], float) for k in ("eye", "target", "up"))
        self.fov_deg, self.width, self.height = c["fov_deg"], width, height
        f = self.target - self.eye
        self.forward = f / np.linalg.norm(f)
        self.right = np.cross(self.forward, self.up)
        self.right /= np.linalg.norm(self.right)
        self.true_up = np.cross(self.right, self.forward)
        self.focal = height / 2 / math.tan(math.radians(self.fov_deg) / 2)  # px per unit at depth 1

    def project(self, p):
        d = np.asarray(p, float) - self.eye
        z = d @ self.forward
        return (self.width / 2 + self.focal * (d @ self.right) / z, self.height / 2 + self.focal * (d @ self.true_up) / z)

    def disc(self, center, radius):
        """A sphere's outline, nearly: its center's projection and radius x focal / depth."""
        depth = (np.asarray(center, float) - self.eye) @ self.forward
        return self.project(center), radius * self.focal / depth

    def away_from(self, center, light):
        """The window direction from a point away from the light (the shadow side)."""
        a, b = self.project(center), self.project(np.asarray(center, float) + 0.1 * np.asarray(light, float))
        v = np.array(a) - np.array(b)
        return v / np.linalg.norm(v)

    def closer(self, fraction):
        """This camera moved `fraction` of the way to its target (the same planes)."""
        c = {"eye": list(self.eye + fraction * (self.target - self.eye)), "target": list(self.target),
             "up": list(self.up), "fov_deg": self.fov_deg}
        return Camera(c, self.width, self.height)

    def document(self):
        return {"eye": list(self.eye), "target": list(self.target), "up": list(self.up), "fov_deg": self.fov_deg}


class SceneCamera:
    """A scene's own camera as its file gives it (a fitted one too: view_direction), for
    drawing over the scene's render without projecting anything."""

    def __init__(self, scene):
        self.camera, (self.width, self.height) = scene["camera"], scene["resolution"]

    def document(self):
        return self.camera


def transform_of(obj):
    return np.array(obj.get("transform", np.eye(4).flatten().tolist()), float).reshape(4, 4).T  # column-major


def ring(camera, center, axis_a, axis_b, radius, n, start=0.0, end=2 * math.pi):
    """A circle (or an arc) on a surface, projected: window points with pressure 1."""
    out = []
    for k in range(n + 1):
        t = start + (end - start) * k / n
        p = np.asarray(center) + radius * (math.cos(t) * np.asarray(axis_a) + math.sin(t) * np.asarray(axis_b))
        out.append((*camera.project(p), 1.0))
    return out


def on_sphere(center, radius, direction):
    d = np.asarray(direction, float)
    return np.asarray(center, float) + radius * d / np.linalg.norm(d)


def shadow_hatches(camera, center_px, reach, light_side, offset, angle, spacing, rng, inside=None):
    """Hatches over the disc around center_px, on the side away from the light."""
    cx, cy = center_px

    def keep(x, y):
        in_disc = (x - cx) ** 2 + (y - cy) ** 2 <= reach * reach if inside is None else inside(x, y)
        return in_disc and light_side[0] * (x - cx) + light_side[1] * (y - cy) >= offset

    return hatches(keep, (cx, cy), reach, angle, spacing, rng)


def triangle_inside(a, b, c):
    def inside(x, y):
        def side(p, q):
            return (q[0] - p[0]) * (y - p[1]) - (q[1] - p[1]) * (x - p[0])
        s = [side(a, b), side(b, c), side(c, a)]
        return all(v >= 0 for v in s) or all(v <= 0 for v in s)
    return inside


def snowman(scene):
    cam = Camera(scene["camera"], *scene["resolution"])
    light = scene["lights"][0]["direction"]
    rng = random.Random(8)
    balls = [transform_of(o) for o in scene["objects"][:3]]
    elements = []
    for g, (m, spacing) in enumerate(zip(balls, (3.8, 3.6, 3.4))):
        center, radius = m[:3, 3], m[0, 0]
        (cx, cy), r = cam.disc(center, radius)
        side = cam.away_from(center, light)
        strokes = shadow_hatches(cam, (cx, cy), r * 0.98, side, r * 0.05, 60 + 25 * g, spacing, rng)
        elements.append((strokes, {"data-role": "hatching", "data-group": str(g)}))
    for t, m in enumerate(transform_of(o) for o in scene["objects"][4:6]):
        base, apex = m @ [0, 0, -1, 1], m @ [0, 0, 1, 1]
        radius = np.linalg.norm(m[:3, 0]) * 0.5
        a, b = cam.project(base[:3] - [radius, 0, 0]), cam.project(base[:3] + [radius, 0, 0])
        tip = cam.project(apex[:3])
        inside = triangle_inside(a, b, tip)
        center = ((a[0] + b[0] + tip[0]) / 3, (a[1] + b[1] + tip[1]) / 3)
        reach = max(math.dist(center, p) for p in (a, b, tip))
        side = cam.away_from((base[:3] + apex[:3]) / 2, light)
        for layer, (angle, spacing) in enumerate(((70, 4), (-20, 5.5))):
            strokes = shadow_hatches(cam, center, reach, side, -reach * 0.05, angle, spacing, rng, inside)
            elements.append((strokes, {"data-role": "hatching", "data-group": str(3 + 2 * t + layer),
                                       "data-mobile": "true"}))  # they move with the view (§6.3)
    head = balls[2]
    hc, hr = head[:3, 3], head[0, 0]
    face = []
    for x in (-0.35, 0.35):  # the eyes
        p = on_sphere(hc, hr, [x, 0.3, 1])
        face.append(ring(cam, p, [1, 0, 0], [0, 1, 0], 0.035, 10))
    for k in range(5):  # the mouth: a smile of coal dots
        t = math.radians(-140 + 25 * k)
        p = on_sphere(hc, hr, [0.45 * math.cos(t), -0.25 + 0.25 * math.sin(t), 1])
        face.append(ring(cam, p, [1, 0, 0], [0, 1, 0], 0.03, 8))
    body = balls[1]
    for y in (0.35, 0.0, -0.35):  # the buttons
        p = on_sphere(body[:3, 3], body[0, 0], [0, y, 1])
        face.append(ring(cam, p, [1, 0, 0], [0, 1, 0], 0.05, 12))
    elements.append((face, {"data-role": "decal", "data-style": "ink"}))
    return [(cam, elements)]


def flower(center, radius, petals=5):
    """One stroke: a flower of `petals` loops around `center`, window coordinates."""
    out = []
    for k in range(petals * 12 + 1):
        t = 2 * math.pi * k / (petals * 12)
        r = radius * abs(math.sin(petals * t / 2))
        out.append((center[0] + r * math.cos(t), center[1] + r * math.sin(t), 0.6 + 0.4 * r / radius))
    return out


def cup(scene, folder):
    """Decals over spot's flank, as drawn on a cup: three flowers with their stems, two
    leaves and a band under them; only where spot shows (its mask), so that each lands on it."""
    cam = SceneCamera(scene)
    inside = object_mask(scene, cam, 0, folder)
    pixels = [(x, y) for x in range(0, cam.width, 4) for y in range(0, cam.height, 4) if inside(x, y)]
    xs, ys = sorted(p[0] for p in pixels), sorted(p[1] for p in pixels)
    x0, x1, y0, y1 = xs[len(xs) // 5], xs[4 * len(xs) // 5], ys[len(ys) // 5], ys[4 * len(ys) // 5]
    strokes = []
    for k in range(3):
        c = (x0 + (x1 - x0) * (0.2 + 0.3 * k), y0 + (y1 - y0) * 0.62)
        strokes.append(flower(c, 20))
        stem = [(c[0] + 2 * math.sin(j / 3), c[1] - 20 - 3 * j, 1.0) for j in range(12)]
        strokes.append(stem)
    for k in range(2):
        c = (x0 + (x1 - x0) * (0.35 + 0.3 * k), y0 + (y1 - y0) * 0.45)
        strokes.append([(c[0] + 10 * math.cos(t / 6 * math.pi), c[1] + 4 * math.sin(t / 6 * math.pi), 0.8)
                        for t in range(13)])
    strokes.append([(x0 + (x1 - x0) * j / 30, y0 + (y1 - y0) * 0.3 + 2 * math.sin(j / 2), 0.9) for j in range(31)])
    strokes = [[p for p in s if inside(p[0], p[1])] for s in strokes]
    return [(cam, [([s for s in strokes if len(s) >= 2], {"data-role": "decal"})])]


def mesh_bounds(path):
    lo, hi = np.full(3, np.inf), np.full(3, -np.inf)
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                p = np.array(line.split()[1:4], float)
                lo, hi = np.minimum(lo, p), np.maximum(hi, p)
    return lo, hi


def object_box(scene, obj, folder):
    """The window box of an object: its bounding box's corners projected, and its center."""
    m = transform_of(obj)
    mesh = obj["mesh"]
    if isinstance(mesh, dict):
        lo, hi = np.array([-1.0, -1.0, -1.0]), np.array([1.0, 1.0, 1.0])
    else:
        lo, hi = mesh_bounds(os.path.join(folder, mesh))
    corners = [m @ [x, y, z, 1] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])]
    return [c[:3] for c in corners], (m @ [*(lo + hi) / 2, 1])[:3]


def run_on_scene(view, folder, command):
    """`plumbago COMMAND[0] SCENE COMMAND[1:]` on a scene document written beside the scene
    (its relative paths hold), then removed."""
    with tempfile.NamedTemporaryFile("w", suffix=".json", dir=folder, delete=False) as f:
        json.dump(view, f)
    try:
        program = os.environ.get("PLUMBAGO", os.path.join(ROOT, "build", "plumbago"))
        subprocess.run([program, command[0], f.name] + command[1:], check=True, stdout=subprocess.DEVNULL)
    finally:
        os.unlink(f.name)


def object_mask(scene, cam, k, folder):
    """Where object k shows in `cam`'s window, alone: what the artist hatches over in the PNG.
    A function of window (x, y), origin bottom-left."""
    import matplotlib.image
    view = dict(scene, camera=cam.document(), objects=[scene["objects"][k]], effects=["basecoat"])
    view["params"] = {"basecoat.preset": "solid", "basecoat.light_r": 0, "basecoat.light_g": 0, "basecoat.light_b": 0,
                      "basecoat.light_a": 1}
    for key in ("stroke_files", "animation"):
        view.pop(key, None)
    with tempfile.TemporaryDirectory() as tmp:
        run_on_scene(view, folder, ["render", "-o", os.path.join(tmp, "mask.png")])
        image = matplotlib.image.imread(os.path.join(tmp, "mask.png"))
    h, w = image.shape[:2]

    def inside(x, y):
        i, j = int(h - 1 - y), int(x)
        return 0 <= i < h and 0 <= j < w and image[i, j, 0] < 0.5
    return inside


def breakfast(scene, folder):
    base = Camera(scene["camera"], *scene["resolution"])
    light = scene["lights"][0]["direction"]
    drawings = []
    for level, (cam, spacing) in enumerate(((base, 4), (base.closer(0.45), 5))):
        rng = random.Random(7 + level)
        elements = []
        for g, obj in enumerate(scene["objects"][1:]):
            corners, center = object_box(scene, obj, folder)
            px = [cam.project(c) for c in corners]
            x0, x1 = min(p[0] for p in px), max(p[0] for p in px)
            y0, y1 = min(p[1] for p in px), max(p[1] for p in px)
            cx, cy, rx, ry = (x0 + x1) / 2, (y0 + y1) / 2, (x1 - x0) / 2, (y1 - y0) / 2
            side = cam.away_from(center, light)
            inside = object_mask(scene, cam, 1 + g, folder)
            angle = 50 + 35 * level + 15 * g
            strokes = shadow_hatches(cam, (cx, cy), max(rx, ry), side, -0.1 * min(rx, ry), angle, spacing, rng,
                                     inside)
            elements.append((strokes, {"data-role": "hatching", "data-group": str(g), "data-free": "true"}))
        drawings.append((cam, elements))
    return drawings


def make_stroke_file(scene_path, scene, cam, elements, svg_path, out_path, style):
    """The SVG, and `plumbago strokefile` over a copy of the scene seen by `cam` (without its
    stroke files, which this makes)."""
    with open(svg_path, "w") as f:
        f.write(svg(cam.width, cam.height, elements))
    view = dict(scene, camera=cam.document())
    view.pop("stroke_files", None)
    view.pop("animation", None)
    run_on_scene(view, os.path.dirname(scene_path), ["strokefile", svg_path, "-o", out_path, "--style", style])


def main():
    name = sys.argv[1] if len(sys.argv) > 1 else ""
    draw = {"snowman": lambda s, folder: snowman(s), "breakfast": breakfast, "cup": cup}
    style = {"snowman": "pencil", "breakfast": "../styles/breakfast_hatching.json",  # relative to scenes/drawn
             "cup": "../styles/cup_decal.json"}
    if name not in draw:
        sys.exit("usage: draw_stand_ins.py snowman|breakfast|cup")
    scene_path = os.path.join(ROOT, "scenes", name + "_strokes.json")
    with open(scene_path) as f:
        scene = json.load(f)
    drawings = draw[name](scene, os.path.dirname(scene_path))
    for level, (cam, elements) in enumerate(drawings):
        stem = os.path.join(ROOT, "scenes", "drawn", name + (".level%d" % level if len(drawings) > 1 else ""))
        make_stroke_file(scene_path, scene, cam, elements, stem + ".svg", stem + ".strokes.json", style[name])


if __name__ == "__main__":
    main()
