#!/usr/bin/python3
"""Study 2: G-buffer precision (gbuffer.normal_format: the GPU normal targets stored as
RGBA8, RGBA16F or RGBA32F) and the normals edge detection compares (edge.normals: face or
interpolated), against frame time.

Error of the edge map (edge_detect.contour_darkness) against two stated references, both
rendered in the same run: the most accurate setting of the same stage (RGBA32F, same
normal mode), and the CPU reference backend (Embree G-buffer in float, same normal mode).
Time: the frame and the G-buffer pass, in ms and as a ratio to RGBA32F in the same job.

Settings (experiments/config/*.yaml, gbuffer_precision): scenes, normals, size, frames,
tolerance. Run through experiments/Snakefile (lib/study_cli.py).
"""
import pathlib
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "lib"))
import plumbago_cli as pc  # noqa: E402
import study_cli  # noqa: E402

EDGE = "edge_detect.contour_darkness"


FIGURES = ["edge_error_vs_time.png"]


def points(s):
    """One point per scene and normal mode: its ratios compare the formats with RGBA32F."""
    return ["%s-%s" % (pc.stem(f), mode) for f in s["scenes"] for mode in s["normals"]]


def scenes(s):
    return s["scenes"]


def measure(s, point):
    stem, mode = point.rsplit("-", 1)
    scene = next(f for f in s["scenes"] if pc.stem(f) == stem)
    size, frames, tolerance = s["size"], s["frames"], s["tolerance"]
    formats = pc.module().params("gbuffer")["gbuffer.normal_format"]["choices"]  # most precise first
    most = "rgba32f"
    assert most in formats
    rows = []
    with tempfile.TemporaryDirectory(prefix="plumbago-gbuf-") as work:
        saved = pathlib.Path(work) / stem / mode
        base = ["edge.normals=" + mode]
        both = pc.bench(scene, base + ["gbuffer.normal_format=" + most], size=size, frames=1, backend="both",
                        save=saved, buffers=[EDGE])
        ref32 = None
        for fmt in formats:
            sets = base + ["gbuffer.normal_format=" + fmt]
            g = pc.result(pc.bench(scene, sets, size=size, frames=frames, against=saved / "gpu", buffers=[EDGE],
                                   tolerance=tolerance), "gpu")
            c = pc.result(pc.bench(scene, sets, size=size, frames=1, against=saved / "reference", buffers=[EDGE],
                                   tolerance=tolerance), "gpu")
            if fmt == most:
                ref32 = g
            e, ec = g["errors"][EDGE], c["errors"][EDGE]
            rows.append(dict(scene=stem, normals=mode, normal_format=fmt, width=g["size"][0], height=g["size"][1],
                             frame_ms=g["frame_ms"], gbuffer_gpu_ms=g["stages"].get("gbuffer", float("nan")),
                             edge_mean_abs_vs_rgba32f=e["mean_abs"], edge_max_abs_vs_rgba32f=e["max_abs"],
                             edge_over_tolerance_vs_rgba32f=e["over_tolerance"],
                             edge_mean_abs_vs_cpu=ec["mean_abs"], edge_max_abs_vs_cpu=ec["max_abs"],
                             edge_over_tolerance_vs_cpu=ec["over_tolerance"], tolerance=tolerance))
    for r in rows:
        r["frame_ratio_to_rgba32f"] = r["frame_ms"] / ref32["frame_ms"]
        r["gbuffer_ratio_to_rgba32f"] = r["gbuffer_gpu_ms"] / ref32["stages"]["gbuffer"]
        pc.log("%-15s %-12s %-7s %7.1f ms (%.2fx rgba32f)  edge mean |diff| vs rgba32f %.2e  vs CPU %.2e"
               "  pixels over %.2f vs CPU %.3f%%" %
               (stem, mode, r["normal_format"], r["frame_ms"], r["frame_ratio_to_rgba32f"],
                r["edge_mean_abs_vs_rgba32f"], r["edge_mean_abs_vs_cpu"], tolerance,
                100 * r["edge_over_tolerance_vs_cpu"]))
    return rows, pc.machine(both["renderer"])


def plot(rows, out):
    plt = pc.pyplot()
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    fig, grid = plt.subplots(len(scenes), 2, figsize=(11, 4.4 * len(scenes)), squeeze=False)
    axes = [[ax for row in grid for ax in row]]
    markers = {"rgba32f": "o", "rgba16f": "s", "rgba8": "^"}
    colors = {"interpolated": "C0", "face": "C1"}
    floor = 1e-7  # log axis: exact agreement (0) is drawn here
    for i, scene in enumerate(scenes):
        for ax, key, title in [(axes[0][2 * i], "edge_mean_abs_vs_cpu", "against the CPU reference"),
                               (axes[0][2 * i + 1], "edge_mean_abs_vs_rgba32f", "against RGBA32F (same normals)")]:
            for r in (r for r in rows if r["scene"] == scene):
                y = max(r[key], floor)
                ax.plot(r["frame_ms"], y, markers[r["normal_format"]], color=colors[r["normals"]], ms=8,
                        label="%s normals, %s" % (r["normals"], r["normal_format"]))
                ax.annotate("%.2fx" % r["frame_ratio_to_rgba32f"], (r["frame_ms"], y), fontsize=7, xytext=(5, 2),
                            textcoords="offset points")
            ax.set_yscale("log")
            ax.set_title("%s: edge map %s" % (scene, title), fontsize=9)
            ax.set_xlabel("frame ms (median; label: time / RGBA32F)")
            ax.grid(alpha=0.3, which="both")
        axes[0][2 * i].set_ylabel("mean |edge map - reference| (0 drawn at %g)" % floor)
    axes[0][0].legend(fontsize=7)
    fig.suptitle("G-buffer normal storage and normal mode: edge-map error against frame time (%dx%d)" %
                 (rows[0]["width"], rows[0]["height"]), fontsize=11)
    pc.save_figure(fig, out, "edge_error_vs_time.png")


if __name__ == "__main__":
    study_cli.main(__doc__, sys.modules[__name__])
