#!/usr/bin/python3
"""Study 6: the CPU reference against the GPU backend, per scene: time per frame on each
(measured in the same `plumbago bench --backend both` process) and the end-to-end error
of the GPU's final image against the reference's (`bench --against`).

  /usr/bin/python3 experiments/reference_vs_gpu/run.py [--quick] [--out DIR] [--replot]
"""
import pathlib
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "lib"))
import plumbago_cli as pc  # noqa: E402

TOLERANCE = 0.05  # a pixel "differs" where a channel differs by more than this


def scenes(quick):
    if quick:
        return ["scenes/fandisk_contours.json", "scenes/fandisk_pencil.json", "scenes/torus.json",
                "scenes/sphere_interior.json", "scenes/ogre_sketchy.json"]
    return sorted(str(p.relative_to(pc.ROOT)) for p in (pc.ROOT / "scenes").glob("*.json") if p.name != "scene.schema.json")


def sweep(a):
    size, frames, reference_frames = ("320x320", 5, 1) if a.quick else (None, 10, 3)
    rows, info = [], None
    with tempfile.TemporaryDirectory(prefix="plumbago-rvg-") as work:
        for scene in scenes(a.quick):
            saved = pathlib.Path(work) / pathlib.Path(scene).stem
            try:
                both = pc.bench(scene, size=size, frames=frames, backend="both", reference_frames=reference_frames, save=saved, buffers=["compose.color"])
            except RuntimeError as e:
                pc.log("skipped %s: %s" % (scene, str(e).splitlines()[-1]))
                continue
            info = info or pc.machine(both["renderer"])
            g, r = pc.result(both, "gpu"), pc.result(both, "reference")
            # The GPU frame saved above against the reference frame saved above: compared by
            # the CLI, through a one-frame run whose time is not used.
            err = pc.bench(scene, size=size, frames=1, backend="gpu", against=saved / "reference",
                           buffers=["compose.color"], tolerance=TOLERANCE)
            e = pc.result(err, "gpu")["errors"]["compose.color"]
            row = dict(scene=pathlib.Path(scene).stem, faces=g["faces"], width=g["size"][0], height=g["size"][1],
                       gpu_ms=g["frame_ms"], reference_ms=r["frame_ms"], gpu_over_reference=g["frame_ms"] / r["frame_ms"],
                       mean_abs=e["mean_abs"], rmse=e["rmse"], max_abs=e["max_abs"], share_over_tolerance=e["over_tolerance"],
                       tolerance=TOLERANCE)
            rows.append(row)
            pc.log("%-22s gpu %8.1f ms  reference %8.1f ms  ratio %5.2f  mean |diff| %.4f  over %.2f: %.2f%%" %
                   (row["scene"], row["gpu_ms"], row["reference_ms"], row["gpu_over_reference"], row["mean_abs"],
                    TOLERANCE, 100 * row["share_over_tolerance"]))
    return rows, info


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
    pc.study_main(__doc__, HERE, sweep, plot)
