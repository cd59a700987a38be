#!/usr/bin/python3
"""Study 5: the pencil interior (Lee et al. 2006 §5): 1-way (one texture per
pixel, from the corner of largest weight: interior.blend=nearest_corner, Lee Fig. 6a),
3-way blending, 3-way blending + cross hatching, with Gouraud (per-vertex, Lee) or Phong
(per-pixel) intensity, against frame time. The contours-only frame is the time baseline (what the interior adds).

Reference: the most accurate and complete setting, 3-way + cross hatching with per-pixel
(Phong) intensity, rendered in the same run. Reported per setting: the difference of the
final image and of the interior's buffers (intensity, darkness) from it, by
`plumbago bench --against`. The scenes' paper effect is left out so the interior is all
that changes.

Settings (experiments/config/*.yaml, interior): scenes, size, frames, tolerance. Run
through experiments/Snakefile (lib/study_cli.py).
"""
import pathlib
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "lib"))
import plumbago_cli as pc  # noqa: E402
import study_cli  # noqa: E402

BUFFERS = ["compose.color", "interior_intensity.intensity", "pencil_interior.interior_darkness"]
VARIANTS = [("contours only", ["contours"], []),
            ("1-way", ["contours", "interior"], ["interior.blend=nearest_corner"]),
            ("3-way", ["contours", "interior"], []),
            ("3-way + hatching", ["contours", "interior", "crosshatch"], [])]


FIGURES = ["difference_vs_time.png"]


def points(s):
    """One point a scene: every variant's ratio compares it with that scene's contours-only frame."""
    return [pc.stem(f) for f in s["scenes"]]


def scenes(s):
    return s["scenes"]


def measure(s, point):
    base = next(f for f in s["scenes"] if pc.stem(f) == point)
    size, frames, tolerance = s["size"], s["frames"], s["tolerance"]
    shadings = pc.module().params("interior")["interior.shading"]["choices"]  # gouraud, phong
    rows = []
    with tempfile.TemporaryDirectory(prefix="plumbago-interior-") as work:
        files = {name: pc.derive_scene(base, work, "%s-%d" % (point, i), effects=effects)
                 for i, (name, effects, _) in enumerate(VARIANTS)}
        saved = pathlib.Path(work) / (point + "-reference")
        ref = pc.bench(files["3-way + hatching"], ["interior.shading=phong"], size=size, frames=frames, save=saved,
                       buffers=BUFFERS)
        baseline = None
        for name, _, sets in VARIANTS:
            for shading in shadings:
                j = pc.bench(files[name], sets + ["interior.shading=" + shading], size=size, frames=frames,
                             against=saved / "gpu", buffers=BUFFERS, tolerance=tolerance)
                g = pc.result(j, "gpu")
                baseline = baseline or g["frame_ms"]  # contours only, first shading
                row = dict(scene=point, variant=name, shading=shading, width=g["size"][0], height=g["size"][1],
                           frame_ms=g["frame_ms"], ratio_to_contours_only=g["frame_ms"] / baseline,
                           interior_gpu_ms=sum(v for k, v in g["stages"].items() if "interior" in k),
                           reference="3-way + hatching, phong")
                for b in BUFFERS:
                    e = g["errors"].get(b)
                    short = b.split(".")[1]
                    row[short + "_mean_abs"] = e["mean_abs"] if e else float("nan")
                    row[short + "_over_tolerance"] = e["over_tolerance"] if e else float("nan")
                rows.append(row)
                pc.log("%-16s %-17s %-8s %7.1f ms (%.2fx contours only)  image mean |diff| %.4f  intensity %.4f" %
                       (point, name, shading, row["frame_ms"], row["ratio_to_contours_only"], row["color_mean_abs"],
                        row["intensity_mean_abs"]))
    return rows, pc.machine(ref["renderer"])


def plot(rows, out):
    plt = pc.pyplot()
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    fig, axes = plt.subplots(1, len(scenes), figsize=(6.5 * len(scenes), 4.8), squeeze=False)
    markers = {"gouraud": "o", "phong": "s"}
    colors = {name: "C%d" % i for i, (name, _, _) in enumerate(VARIANTS)}
    floor = 1e-3  # %: log axis, exact agreement (the reference itself) is drawn here
    for ax, scene in zip(axes[0], scenes):
        for r in (r for r in rows if r["scene"] == scene):
            y = max(100 * r["color_mean_abs"], floor)
            ax.plot(r["frame_ms"], y, markers[r["shading"]], color=colors[r["variant"]], ms=8,
                    label="%s, %s" % (r["variant"], r["shading"]))
            ax.annotate("%.2fx" % r["ratio_to_contours_only"], (r["frame_ms"], y), fontsize=8,
                        xytext=(5, 3), textcoords="offset points")
        ax.set_title("%s at %dx%d" % (scene, rows[0]["width"], rows[0]["height"]), fontsize=10)
        ax.set_xlabel("frame ms (median; label: time / contours only)")
        ax.set_ylabel("mean |image - reference| (%% of full scale; 0 drawn at %g)" % floor)
        ax.set_yscale("log")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle("interior: difference from 3-way + cross hatching with Phong intensity,\nagainst frame time", fontsize=11)
    pc.save_figure(fig, out, "difference_vs_time.png")


if __name__ == "__main__":
    study_cli.main(__doc__, sys.modules[__name__])
