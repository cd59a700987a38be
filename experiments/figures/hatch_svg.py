#!/usr/bin/env python3
"""Draws a hatching group as an SVG over a rendering, the way an artist would over the PNG:
roughly parallel, evenly spaced strokes, clipped to a disc (or a box) and to the side of a
line through it (the shadow side), each a little wobbly, pressure rising and falling along
it. `plumbago strokefile SCENE out.svg --role hatching` makes it a stroke file (Kalnins et al. 2002, §3, §6).

  hatch_svg.py --size 800 600 --disc 400 300 187 --side 0.6 -0.7 40 --angle 30 --spacing 12 \\
      --group 0 > hatches.svg

Window coordinates (origin bottom-left, docs/conventions.md) on the command line; the SVG's y runs down.
draw_stand_ins.py uses hatches() and svg() for the scenes of Kalnins et al.'s Table 1.
"""
import argparse
import math
import random


def longest_inside(points, inside):
    """The longest run of consecutive points that are inside."""
    best, run = [], []
    for p in points:
        run = run + [p] if inside(p) else []
        best = run if len(run) > len(best) else best
    return best


def hatches(inside, center, reach, angle, spacing, rng, wobble=0.8, min_length=20):
    """Strokes at `angle` degrees, `spacing` px apart, over the disc of radius `reach` around
    `center`, each the longest run of it where inside(x, y): lists of (x, y, pressure)."""
    d = (math.cos(math.radians(angle)), math.sin(math.radians(angle)))
    n = (-d[1], d[0])
    strokes = []
    offset = -reach + spacing / 2
    while offset < reach:
        o = offset + rng.uniform(-0.15, 0.15) * spacing
        line = []
        for k in range(int(2 * reach / 3) + 1):
            t = -reach + 3 * k
            w = wobble * math.sin(t / 37.0 + offset) + rng.uniform(-0.3, 0.3) * wobble
            line.append((center[0] + d[0] * t + n[0] * (o + w), center[1] + d[1] * t + n[1] * (o + w)))
        run = longest_inside(line, lambda p: inside(*p))
        if len(run) >= max(2, int(min_length / 3)):
            m = len(run) - 1
            strokes.append([(x, y, 0.55 + 0.45 * math.sin(math.pi * i / m)) for i, (x, y) in enumerate(run)])
        offset += spacing
    return strokes


def svg(width, height, elements):
    """An SVG document of polylines: elements are (strokes, attributes) pairs, strokes lists of
    (x, y, pressure) in window coordinates, attributes a dict of data-* values."""
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %d %d">'
           % (width, height, width, height)]
    for strokes, attributes in elements:
        extra = "".join(' %s="%s"' % (k, v) for k, v in attributes.items())
        for s in strokes:
            pts = " ".join("%.2f,%.2f" % (x, height - y) for x, y, _ in s)
            pressure = " ".join("%.2f" % q for _, _, q in s)
            out.append('  <polyline%s data-pressure="%s" points="%s" fill="none" stroke="black"/>'
                       % (extra, pressure, pts))
    return "\n".join(out + ["</svg>"]) + "\n"


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
    if a.disc:
        cx, cy, r = a.disc
        in_shape = lambda x, y: (x - cx) ** 2 + (y - cy) ** 2 <= r * r
    else:
        x0, y0, x1, y1 = a.box
        cx, cy, r = (x0 + x1) / 2, (y0 + y1) / 2, math.hypot(x1 - x0, y1 - y0) / 2
        in_shape = lambda x, y: x0 <= x <= x1 and y0 <= y <= y1
    on_side = lambda x, y: not a.side or a.side[0] * (x - cx) + a.side[1] * (y - cy) >= a.side[2]
    strokes = hatches(lambda x, y: in_shape(x, y) and on_side(x, y), (cx, cy), r, a.angle, a.spacing,
                      random.Random(a.seed), a.wobble, a.min_length)
    attributes = {"data-role": "hatching", "data-group": str(a.group)}
    if a.free:
        attributes["data-free"] = "true"
    print(svg(a.size[0], a.size[1], [(strokes, attributes)]), end="")


if __name__ == "__main__":
    main()
