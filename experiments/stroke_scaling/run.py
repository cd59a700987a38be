#!/usr/bin/python3
"""Strokes against faces: Kalnins et al. 2002 say the strokes, not the faces, set the frame
time of stroke-based rendering. Frame time on both backends:
  - strokes: N decal strokes (short arcs, about 20 px) on the procedural torus at a fixed
    face count;
  - faces: the torus tessellated from about 1K to 1M faces with a fixed set of decals.
Scenes and stroke files are written per point (torus_decals.py); the strokes that show and
the visible runs drawn are counted by the Python module (Scene.lines). Each point runs `plumbago bench
--backend both` `repeats` times and keeps each backend's fastest run, the least disturbed
(GPU: median of `frames` after a warm-up; reference: median of `reference_frames`).
others_cpu: the share of the machine's CPU time other processes took meanwhile; load_1min:
the load average at the point's start (this study's own runs included).

Linear fits (fits.csv): ms per 1K strokes that show (the strokes sweep and any point at its
face count) and ms per 100K faces (the points with the fixed strokes), per pass and for the
frame; table1.csv puts them together for the scene sizes of Kalnins et al.'s Table 1
(bench/paper_claims.hpp) and says which part is larger.

Settings (experiments/config/*.yaml, stroke_scaling): size, frames, reference_frames,
repeats, strokes, fixed_faces, faces, fixed_strokes. Run through experiments/Snakefile
(lib/study_cli.py).
"""
import os
import pathlib
import re
import sys
import tempfile

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "lib"))
import plumbago_cli as pc  # noqa: E402
import study_cli  # noqa: E402
import torus_decals  # noqa: E402

FIGURES = ["ms_vs_strokes_and_faces.png"]
EXTRA = ["fits.csv", "table1.csv"]
BACKENDS = ("gpu", "reference")
PER = {"strokes": 1e3, "faces": 1e5}  # the fits' units: ms per 1K strokes, per 100K faces
CLAIMS = HERE.parent.parent / "bench" / "paper_claims.hpp"
READS = ["experiments/stroke_scaling/torus_decals.py", "bench/paper_claims.hpp"]


def points(s):
    return ["strokes-%d" % n for n in s["strokes"]] + ["faces-%d" % f for f in s["faces"]]


def scenes(s):
    return []


def measure(s, point):
    sweep, value = point.split("-")
    faces, n = (s["fixed_faces"], int(value)) if sweep == "strokes" else (float(value), s["fixed_strokes"])
    load, clock = os.getloadavg()[0], pc.cpu_clock()
    with tempfile.TemporaryDirectory(prefix="plumbago-stroke-scaling-") as work:
        scene = torus_decals.write(work, faces, n, s["size"])
        counts = pc.lines_counts(scene)
        runs = [pc.bench(scene, frames=s["frames"], backend="both", reference_frames=s["reference_frames"])
                for _ in range(s["repeats"])]
    others = pc.others_cpu(clock)
    rows = []
    for backend in BACKENDS:  # the fastest run of each: the least disturbed
        r = min((pc.result(j, backend) for j in runs), key=lambda x: x["frame_ms"])
        row = dict(sweep=sweep, backend=backend, faces=r["faces"], drawn=n, shown=counts["shown"],
                   visible_runs=counts["visible_runs"], size=s["size"], frame_ms=r["frame_ms"],
                   unattributed_ms=r["frame_ms"] - sum(r["stages"].values()), load_1min=load, others_cpu=others)
        row.update({"stage:" + k: v for k, v in r["stages"].items()})
        row.update({"preprocessing:" + k: v for k, v in r["preprocessing"].items()})
        rows.append(row)
        pc.log("%-14s %-9s %8d faces %5d shown %9.1f ms  %s" % (point, backend, r["faces"], counts["shown"],
               r["frame_ms"], "  ".join("%s %.1f" % kv for kv in sorted(r["stages"].items()))))
    return rows, pc.machine(runs[0]["renderer"])


def quantities(rows):
    return ["frame_ms"] + sorted({k for r in rows for k in r if k.startswith("stage:")}) + ["unattributed_ms"]


def fit_rows(rows, backend, x):
    """The rows a fit against x uses: those at the other sweep's fixed value."""
    sel = [r for r in rows if r["backend"] == backend]
    fixed = {"strokes": "faces", "faces": "drawn"}[x]
    at = next(r[fixed] for r in sel if r["sweep"] == x)
    return [r for r in sel if r[fixed] == at]


def fit(rows, backend, x, key):
    """Least-squares line of key against x ("strokes": the strokes that show; "faces"): ms per
    PER[x], intercept, points."""
    sel = [r for r in fit_rows(rows, backend, x) if isinstance(r.get(key), float)]
    xs = np.array([r["shown" if x == "strokes" else "faces"] for r in sel], float)
    if len(set(xs)) < 2:
        return float("nan"), float("nan"), len(sel)
    slope, intercept = np.polyfit(xs, [r[key] for r in sel], 1)
    return slope * PER[x], intercept, len(sel)


def fits(rows):
    out = []
    for backend in BACKENDS:
        for key in quantities(rows):
            row = dict(backend=backend, quantity=key.replace("stage:", ""))
            for x in PER:
                per, intercept, n = fit(rows, backend, x, key)
                unit = "ms_per_1k_strokes" if x == "strokes" else "ms_per_100k_faces"
                row.update({unit: per, "intercept_ms_" + x: intercept, "points_" + x: n})
            out.append(row)
    return out


def table1_scenes():
    """(scene, faces, strokes) of Kalnins et al. 2002's Table 1, as bench/paper_claims.hpp has it."""
    found = re.findall(r'"Kalnins et al\. 2002", "(\w+), (\d+) strokes", (\d+),', CLAIMS.read_text())
    return [(name, int(faces), int(strokes)) for name, strokes, faces in found]


def table1(fit_table):
    """Frame time = base + strokes x (ms per stroke) + faces x (ms per face), per Table 1 scene."""
    out = []
    for backend in BACKENDS:
        f = next(r for r in fit_table if r["backend"] == backend and r["quantity"] == "frame_ms")
        per_stroke, per_face = f["ms_per_1k_strokes"] / PER["strokes"], f["ms_per_100k_faces"] / PER["faces"]
        for name, faces, strokes in table1_scenes():
            s_ms, f_ms = strokes * per_stroke, faces * per_face
            out.append(dict(backend=backend, scene=name, faces=faces, strokes=strokes, strokes_ms=s_ms, faces_ms=f_ms,
                            strokes_over_faces=s_ms / f_ms, larger="strokes" if s_ms > f_ms else "faces"))
    return out


def finish(rows, out):
    """fits.csv and table1.csv; each row's ratio to the smallest point of its sweep and backend."""
    for backend in BACKENDS:
        for sweep in PER:
            sel = [r for r in rows if r["backend"] == backend and r["sweep"] == sweep]
            for r in sel:
                r["ratio_to_smallest"] = r["frame_ms"] / sel[0]["frame_ms"]
    f = fits(rows)
    pc.write_csv(pathlib.Path(out) / "fits.csv", f)
    t = table1(f)
    pc.write_csv(pathlib.Path(out) / "table1.csv", t)
    for r in t:
        pc.log("%-9s %-9s %6d faces %5d strokes: strokes %6.1f ms, faces %6.1f ms -> %s" % (
            r["backend"], r["scene"], r["faces"], r["strokes"], r["strokes_ms"], r["faces_ms"], r["larger"]))
    return rows


def panel(ax, rows, backend, x):
    """One backend's ms against x, every stage, the points its fit uses and the frame's fit."""
    key = "shown" if x == "strokes" else "faces"
    sel = sorted(fit_rows(rows, backend, x), key=lambda r: r[key])
    for k in quantities(rows):
        pts = [(r[key], r[k]) for r in sel if isinstance(r.get(k), float) and r[k] > 0]
        if pts:
            ax.plot(*zip(*pts), "k*" if k == "frame_ms" else "o-", ms=9 if k == "frame_ms" else 4, lw=1.2,
                    label={"frame_ms": "whole frame (wall clock)", "unattributed_ms": "frame - passes"}.get(
                        k, k.replace("stage:", "")))
    sizes = [scene[2 if x == "strokes" else 1] for scene in table1_scenes()]
    ax.axvspan(min(sizes), max(sizes), color="0.5", alpha=0.12, label="Kalnins et al. Table 1's scenes")
    per, intercept, _ = fit(rows, backend, x, "frame_ms")
    xs = np.geomspace(max(sel[0][key], 1), sel[-1][key], 50)
    ax.plot(xs, intercept + per / PER[x] * xs, "k--", lw=1, label="frame fit: %.3g ms per %s %s" % (
        per, "1K" if x == "strokes" else "100K", x))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.grid(alpha=0.3, which="both")
    fixed = ("%d faces" % sel[0]["faces"]) if x == "strokes" else ("%d decals" % sel[0]["drawn"])
    ax.set_title("%s: ms against %s (%s, %s)" % ("GPU (llvmpipe; passes: GL timestamps)" if backend == "gpu" else
                                                 "CPU reference (passes: wall clock)",
                                                 "strokes that show" if x == "strokes" else x, fixed, sel[0]["size"]),
                 fontsize=9)
    ax.set_xlabel("strokes that show (`plumbago lines`)" if x == "strokes" else "faces")
    ax.set_ylabel("ms")
    ax.legend(fontsize=6)


def plot(rows, out):
    plt = pc.pyplot()
    fig, axes = plt.subplots(2, 2, figsize=(12, 9))
    for i, backend in enumerate(BACKENDS):
        for j, x in enumerate(PER):
            panel(axes[i][j], rows, backend, x)
    pc.save_figure(fig, out, FIGURES[0])


if __name__ == "__main__":
    study_cli.main(__doc__, sys.modules[__name__])
