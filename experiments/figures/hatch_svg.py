#!/usr/bin/env python3
"""Draws a hatching group as an SVG over a rendering, the way an artist would over the PNG:
roughly parallel, evenly spaced strokes, clipped to a disc (or a box) and to the side of a
line through it (the shadow side), each a little wobbly, pressure rising and falling along
it. `plumbago strokefile SCENE out.svg --role hatching` makes it a stroke file (SPEC 4.9-4.10).

  hatch_svg.py --size 800 600 --disc 400 300 187 --side 0.6 -0.7 40 --angle 30 --spacing 12 \\
      --group 0 > hatches.svg

Window coordinates (origin bottom-left, SPEC 0) on the command line; the SVG's y runs down.
"""
import argparse
import math
import random


def clip(points, inside):
    """The longest run of consecutive points that are inside."""
    best, run = [], []
    for p in points:
        run = run + [p] if inside(p) else []
        best = run if len(run) > len(best) else best
    return best


def hatch_lines(a):
    """The strokes, window coordinates, as lists of (x, y, pressure)."""
    rng = random.Random(a.seed)
    cx, cy, r = a.disc if a.disc else ((a.box[0] + a.box[2]) / 2, (a.box[1] + a.box[3]) / 2,
                                       math.hypot(a.box[2] - a.box[0], a.box[3] - a.box[1]) / 2)
    d = (math.cos(math.radians(a.angle)), math.sin(math.radians(a.angle)))
    n = (-d[1], d[0])

    def inside(p):
        x, y = p[0] - cx, p[1] - cy
        in_shape = (x * x + y * y <= r * r) if a.disc else (a.box[0] <= p[0] <= a.box[2] and a.box[1] <= p[1] <= a.box[3])
        return in_shape and (not a.side or a.side[0] * x + a.side[1] * y >= a.side[2])

    strokes = []
    offset = -r + a.spacing / 2
    while offset < r:
        o = offset + rng.uniform(-0.15, 0.15) * a.spacing
        points = []
        for k in range(int(2 * r / 3) + 1):
            t = -r + 3 * k
            wobble = a.wobble * math.sin(t / 37.0 + offset) + rng.uniform(-0.3, 0.3) * a.wobble
            points.append((cx + d[0] * t + n[0] * (o + wobble), cy + d[1] * t + n[1] * (o + wobble)))
        run = clip(points, inside)
        if len(run) >= max(2, int(a.min_length / 3)):
            m = len(run) - 1
            strokes.append([(x, y, 0.55 + 0.45 * math.sin(math.pi * i / m)) for i, (x, y) in enumerate(run)])
        offset += a.spacing
    return strokes


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--size", type=int, nargs=2, required=True, metavar=("W", "H"))
    shape = p.add_mutually_exclusive_group(required=True)
    shape.add_argument("--disc", type=float, nargs=3, metavar=("CX", "CY", "R"))
    shape.add_argument("--box", type=float, nargs=4, metavar=("X0", "Y0", "X1", "Y1"))
    p.add_argument("--side", type=float, nargs=3, metavar=("NX", "NY", "D"),
                   help="keep points with NX (x - cx) + NY (y - cy) >= D")
    p.add_argument("--angle", type=float, default=30, help="direction of the strokes, degrees from +x")
    p.add_argument("--spacing", type=float, default=12, help="px between neighbouring strokes")
    p.add_argument("--wobble", type=float, default=0.8, help="px of hand tremor")
    p.add_argument("--min-length", type=float, default=20, help="shorter strokes are left out, px")
    p.add_argument("--group", type=int, default=0)
    p.add_argument("--free", action="store_true", help="a free group (its own level of detail)")
    p.add_argument("--seed", type=int, default=1)
    a = p.parse_args()
    w, h = a.size
    print('<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %d %d">' % (w, h, w, h))
    free = ' data-free="true"' if a.free else ""
    for s in hatch_lines(a):
        pts = " ".join("%.2f,%.2f" % (x, h - y) for x, y, _ in s)
        pressure = " ".join("%.2f" % q for _, _, q in s)
        print('  <polyline data-role="hatching" data-group="%d"%s data-pressure="%s" points="%s" fill="none" '
              'stroke="black"/>' % (a.group, free, pressure, pts))
    print("</svg>")


if __name__ == "__main__":
    main()
