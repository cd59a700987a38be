#!/usr/bin/python3
"""Study 7: scaling. Frame time per stage, on both backends, as the mesh grows from about
10K to 1M faces (the procedural torus tessellated finer: 9216 x resolution^2 faces) at a
fixed image size, and as the image grows from 512^2 to 4K UHD (3840x2160) with a fixed
mesh. Effects: contours and interior. Every point is one `plumbago bench --backend both`
run; ratios are to the smallest point of the same sweep, measured in the same job. The
log-log slope of each stage's time against faces and against pixels says which grows
with which (slopes.csv).

Settings (experiments/config/*.yaml, scaling): faces, sizes, fixed_faces, fixed_size,
frames, reference_frames. Run through experiments/Snakefile (lib/study_cli.py).
"""
import math
import pathlib
import sys
import tempfile

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "lib"))
import plumbago_cli as pc  # noqa: E402
import study_cli  # noqa: E402

EFFECTS = ["contours", "interior"]


def scene(folder, resolution):
    path = pathlib.Path(folder) / ("torus-%g.json" % resolution)
    path.write_text('{"mesh": {"procedural": "torus", "resolution": %.6g}, "effects": %s}' %
                    (resolution, str(EFFECTS).replace("'", '"')))
    return str(path)


FIGURES = ["stage_ms_vs_faces_and_pixels.png"]
EXTRA = ["slopes.csv"]


def points(s):
    """One point a sweep: its ratios and log-log slopes compare every size of the sweep."""
    return ["faces", "pixels"]


def scenes(s):
    return []


def size(text):
    w, h = text.split("x")
    return int(w), int(h)


def measure(s, point):
    if point == "faces":
        todo = [(f, size(s["fixed_size"])) for f in s["faces"]]
    else:
        todo = [(s["fixed_faces"], size(x)) for x in s["sizes"]]
    rows, info = [], None
    with tempfile.TemporaryDirectory(prefix="plumbago-scaling-") as work:
        for f, (w, h) in todo:
            resolution = pc.torus_resolution(f)
            j = pc.bench(scene(work, resolution), size="%dx%d" % (w, h), frames=s["frames"], backend="both",
                         reference_frames=s["reference_frames"])
            info = info or pc.machine(j["renderer"])
            for r in j["results"]:
                row = dict(sweep=point, backend=r["backend"], faces=r["faces"], width=w, height=h, pixels=w * h,
                           frame_ms=r["frame_ms"])
                for k, v in r["stages"].items():
                    row["stage:" + k] = v
                for k, v in r["preprocessing"].items():
                    row["preprocessing:" + k] = v
                rows.append(row)
                pc.log("%-6s %-9s %8d faces %4dx%-4d  %9.1f ms  %s" % (point, r["backend"], r["faces"], w, h,
                       r["frame_ms"], "  ".join("%s %.1f" % (k, v) for k, v in sorted(r["stages"].items()))))
    for backend in ("gpu", "reference"):
        sel = [r for r in rows if r["backend"] == backend]
        for r in sel:
            r["ratio_to_smallest"] = r["frame_ms"] / sel[0]["frame_ms"]
    return rows, info


def slopes(rows):
    """Log-log slope of each stage's ms against faces (faces sweep) and pixels (pixel sweep)."""
    out = []
    for backend in ("gpu", "reference"):
        keys = sorted({k for r in rows if r["backend"] == backend for k in r if k.startswith("stage:")}) + ["frame_ms"]
        for k in keys:
            row = dict(backend=backend, stage=k.replace("stage:", ""))
            for sweep_name, x in (("faces", "faces"), ("pixels", "pixels")):
                sel = [r for r in rows if r["sweep"] == sweep_name and r["backend"] == backend
                       and isinstance(r.get(k), float) and r[k] > 0 and not math.isnan(r[k])]
                if len(sel) >= 2:
                    row["slope_vs_" + x] = float(np.polyfit(np.log([r[x] for r in sel]), np.log([r[k] for r in sel]), 1)[0])
                    row["ratio_%s_last_over_first" % x] = sel[-1][k] / sel[0][k]
            out.append(row)
    return out


def plot(rows, out):
    plt = pc.pyplot()
    fig, axes = plt.subplots(2, 2, figsize=(12, 9))
    for i, backend in enumerate(("gpu", "reference")):
        for jx, (sweep_name, x, label) in enumerate((("faces", "faces", "faces"), ("pixels", "pixels", "pixels"))):
            ax = axes[i][jx]
            sel = [r for r in rows if r["sweep"] == sweep_name and r["backend"] == backend]
            keys = sorted({k for r in sel for k in r if k.startswith("stage:")})
            for k in keys + ["frame_ms"]:
                pts = [(r[x], r[k]) for r in sel if isinstance(r.get(k), float) and r[k] > 0]
                if pts:
                    ax.plot(*zip(*pts), "o-" if k != "frame_ms" else "k*--", lw=1.5 if k != "frame_ms" else 2,
                            label=k.replace("stage:", "") if k != "frame_ms" else "whole frame (wall clock)")
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.grid(alpha=0.3, which="both")
            fixed = ("%dx%d" % (sel[0]["width"], sel[0]["height"])) if sweep_name == "faces" else ("%d faces" % sel[0]["faces"])
            ax.set_title("%s: ms against %s (%s)" % ("GPU (llvmpipe, per-pass timer queries)" if backend == "gpu"
                                                       else "CPU reference (per-pass wall clock)", label, fixed), fontsize=9)
            ax.set_xlabel(label)
            ax.set_ylabel("ms")
            ax.legend(fontsize=7)
    pc.save_figure(fig, out, "stage_ms_vs_faces_and_pixels.png")


def finish(rows, out):
    """slopes.csv: the log-log slope of each stage over each sweep."""
    s = slopes(rows)
    pc.write_csv(pathlib.Path(out) / "slopes.csv", s)
    for r in s:
        pc.log("%-9s %-36s slope vs faces %5.2f  vs pixels %5.2f" % (r["backend"], r["stage"],
               r.get("slope_vs_faces", float("nan")), r.get("slope_vs_pixels", float("nan"))))


if __name__ == "__main__":
    study_cli.main(__doc__, sys.modules[__name__])
