#!/usr/bin/python3
"""Study 6: the CPU reference against the GPU backend, per scene: time per frame on each
(measured in the same `plumbago bench --backend both` process) and the end-to-end error
of the GPU's final image against the reference's (`bench --against`).

Settings (experiments/config/*.yaml, reference_vs_gpu): scenes, size, frames,
reference_frames, tolerance. Run through experiments/Snakefile (lib/study_cli.py).
"""
import pathlib
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "lib"))
import plumbago_cli as pc  # noqa: E402
import study_cli  # noqa: E402

FIGURES = ["time_and_error_per_scene.png"]


def points(s):
    """One point a scene: the ratio it reports compares the two backends of one bench run."""
    return [pc.stem(f) for f in pc.scene_files(s["scenes"])]


def scenes(s):
    return pc.scene_files(s["scenes"])


def measure(s, point):
    scene = next(f for f in pc.scene_files(s["scenes"]) if pc.stem(f) == point)
    tolerance = s["tolerance"]  # a pixel "differs" where a channel differs by more than this
    with tempfile.TemporaryDirectory(prefix="plumbago-rvg-") as work:
        saved = pathlib.Path(work) / point
        try:
            both = pc.bench(scene, size=s["size"], frames=s["frames"], backend="both",
                            reference_frames=s["reference_frames"], save=saved, buffers=["compose.color"])
        except RuntimeError as e:
            pc.log("skipped %s: %s" % (scene, str(e).splitlines()[-1]))
            return [], None
        g, r = pc.result(both, "gpu"), pc.result(both, "reference")
        # The GPU frame saved above against the reference frame saved above: compared by
        # the CLI, through a one-frame run whose time is not used.
        err = pc.bench(scene, size=s["size"], frames=1, backend="gpu", against=saved / "reference",
                       buffers=["compose.color"], tolerance=tolerance)
    e = pc.result(err, "gpu")["errors"]["compose.color"]
    row = dict(scene=point, faces=g["faces"], width=g["size"][0], height=g["size"][1],
               gpu_ms=g["frame_ms"], reference_ms=r["frame_ms"], gpu_over_reference=g["frame_ms"] / r["frame_ms"],
               mean_abs=e["mean_abs"], rmse=e["rmse"], max_abs=e["max_abs"], share_over_tolerance=e["over_tolerance"],
               tolerance=tolerance)
    pc.log("%-22s gpu %8.1f ms  reference %8.1f ms  ratio %5.2f  mean |diff| %.4f  over %.2f: %.2f%%" %
           (row["scene"], row["gpu_ms"], row["reference_ms"], row["gpu_over_reference"], row["mean_abs"],
            tolerance, 100 * row["share_over_tolerance"]))
    return [row], pc.machine(both["renderer"])


def plot(rows, out):
    plt = pc.pyplot()
    names = [r["scene"] for r in rows]
    x = range(len(rows))
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(13, 4.8))
    w = 0.4
    ax1.bar([i - w / 2 for i in x], [r["gpu_ms"] for r in rows], w, label="GPU (llvmpipe)")
    ax1.bar([i + w / 2 for i in x], [r["reference_ms"] for r in rows], w, label="CPU reference")
    for i, r in zip(x, rows):
        ax1.annotate("%.2fx" % r["gpu_over_reference"], (i, max(r["gpu_ms"], r["reference_ms"])), ha="center",
                     xytext=(0, 3), textcoords="offset points", fontsize=7)
    ax1.set_xticks(list(x))
    ax1.set_xticklabels(names, rotation=35, ha="right", fontsize=8)
    ax1.set_ylabel("ms per frame (median)")
    ax1.set_title("time per frame (label: GPU / reference)")
    ax1.legend(fontsize=8)
    ax2.bar([i - w / 2 for i in x], [100 * r["mean_abs"] for r in rows], w, label="mean |GPU - reference| (% of full scale)")
    ax2.bar([i + w / 2 for i in x], [100 * r["share_over_tolerance"] for r in rows], w,
            label="pixels differing by > %g (%%)" % rows[0]["tolerance"])
    ax2.set_xticks(list(x))
    ax2.set_xticklabels(names, rotation=35, ha="right", fontsize=8)
    ax2.set_ylabel("%")
    ax2.set_title("end-to-end error of the GPU image against the reference")
    ax2.legend(fontsize=8)
    pc.save_figure(fig, out, "time_and_error_per_scene.png")


if __name__ == "__main__":
    study_cli.main(__doc__, sys.modules[__name__])
