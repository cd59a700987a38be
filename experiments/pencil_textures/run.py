#!/usr/bin/python3
"""Study 4: the pencil texture stack (Lee et al. 2006 §3, SPEC 1.2): how many tone layers
(pencil_textures.layers) and how large a tile (pencil_textures.size), against frame time, generation time and
memory.

Reference: the most accurate setting of the sweep, the most layers at the largest tile
(64 at 1024; --quick: 64 at 512), rendered in the same run. Each setting's final image
and pencil-interior darkness are compared with it by `plumbago bench --against`. The
contour texture's layer (contour.texture_layer) is scaled with the layer count so it keeps
its tone. Memory is the stack as the GPU allocates it (one R32F texture array,
layers x size^2 x 4 bytes), computed from the parameters, not measured.

  /usr/bin/python3 experiments/pencil_textures/run.py [--quick] [--out DIR] [--replot]
"""
import pathlib
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "lib"))
import plumbago_cli as pc  # noqa: E402

SCENE = "scenes/fandisk_pencil.json"
TOLERANCE = 0.05
BUFFERS = ["compose.color", "pencil_interior.interior_darkness"]
BYTES_PER_TEXEL = 4  # GL_R32F (gpu/pipeline.cpp uploads the stack as R32F)


def sets(layers, size, default_layers, default_layer):
    return ["pencil_textures.layers=%d" % layers, "pencil_textures.size=%d" % size,
            "contour.texture_layer=%d" % min(layers - 1, round(default_layer * layers / default_layers))]


def sweep(a):
    size, frames = ("400x400", 3) if a.quick else (None, 8)
    layers = [8, 32, 64] if a.quick else [8, 16, 32, 64]
    tiles = [128, 512] if a.quick else [128, 256, 512, 1024]
    default_layers, default_tile = pc.param_default("pencil_textures.layers"), pc.param_default("pencil_textures.size")
    default_layer = pc.param_default("contour.texture_layer")
    rows = []
    with tempfile.TemporaryDirectory(prefix="plumbago-pencil-") as work:
        ref = pc.bench(SCENE, sets(max(layers), max(tiles), default_layers, default_layer), size=size, frames=1,
                       save=work, buffers=BUFFERS)
        info = pc.machine(ref["renderer"])
        configs = [(default_layers, default_tile)] + [(n, t) for n in layers for t in tiles if (n, t) != (default_layers, default_tile)]
        base = None
        for n, t in configs:
            g = pc.result(pc.bench(SCENE, sets(n, t, default_layers, default_layer), size=size, frames=frames,
                                   against=pathlib.Path(work) / "gpu", buffers=BUFFERS, tolerance=TOLERANCE), "gpu")
            base = base or g
            e, d = g["errors"]["compose.color"], g["errors"]["pencil_interior.interior_darkness"]
            row = dict(layers=n, tile=t, width=g["size"][0], height=g["size"][1], frame_ms=g["frame_ms"],
                       ratio_to_default=g["frame_ms"] / base["frame_ms"],
                       generation_ms=g["preprocessing"].get("pencil_textures", float("nan")),
                       generation_ratio_to_default=g["preprocessing"].get("pencil_textures", float("nan")) /
                       base["preprocessing"]["pencil_textures"],
                       stack_mib=n * t * t * BYTES_PER_TEXEL / 2 ** 20, color_mean_abs=e["mean_abs"],
                       color_over_tolerance=e["over_tolerance"], darkness_mean_abs=d["mean_abs"],
                       reference="%d layers at %d" % (max(layers), max(tiles)), tolerance=TOLERANCE)
            rows.append(row)
            pc.log("%2d layers x %4d: %7.1f ms (%.2fx default)  generation %8.0f ms  %6.1f MiB  image mean |diff| %.4f"
                   "  darkness %.4f" % (n, t, row["frame_ms"], row["ratio_to_default"], row["generation_ms"],
                                        row["stack_mib"], row["color_mean_abs"], row["darkness_mean_abs"]))
    rows.sort(key=lambda r: (r["layers"], r["tile"]))
    return rows, info


def plot(rows, out):
    plt = pc.pyplot()
    fig, axes = plt.subplots(1, 3, figsize=(16, 4.8))
    layers = sorted({int(r["layers"]) for r in rows})
    for i, n in enumerate(layers):
        sel = sorted((r for r in rows if r["layers"] == n), key=lambda r: r["tile"])
        style = dict(color="C%d" % i, label="%d layers" % n)
        axes[0].plot([r["stack_mib"] for r in sel], [r["frame_ms"] for r in sel], "o:", lw=0.8, **style)
        for ax, x in ((axes[1], "generation_ms"), (axes[2], "stack_mib")):
            ax.plot([r[x] for r in sel], [100 * r["darkness_mean_abs"] for r in sel], "o-", **style)
            for r in sel:
                if n == layers[-1] or r["tile"] == max(r2["tile"] for r2 in rows):  # label once per tile size
                    ax.annotate("%d" % r["tile"], (r[x], 100 * r["darkness_mean_abs"]), fontsize=7, xytext=(3, 3),
                                textcoords="offset points")
    axes[0].set_ylim(0, 1.15 * max(r["frame_ms"] for r in rows))
    axes[0].set_ylabel("frame ms (median)")
    axes[0].set_title("frame time against stack memory", fontsize=10)
    axes[1].set_title("difference against generation time", fontsize=10)
    axes[2].set_title("difference against stack memory (labels: tile size)", fontsize=10)
    for ax, t in zip(axes, ("stack memory MiB (R32F, computed)", "stack generation ms (CPU, once per scene)",
                            "stack memory MiB (R32F, computed)")):
        ax.set_xlabel(t)
        ax.set_xscale("log")
        ax.grid(alpha=0.3, which="both")
    axes[1].set_ylabel("mean |interior darkness - reference| (%)")
    axes[0].legend(fontsize=8)
    fig.suptitle("pencil textures: difference from %s, against time and memory (%s at %dx%d)" %
                 (rows[0]["reference"], pathlib.Path(SCENE).stem, rows[0]["width"], rows[0]["height"]), fontsize=11)
    pc.save_figure(fig, out, "difference_vs_time_and_memory.png")


if __name__ == "__main__":
    pc.study_main(__doc__, HERE, sweep, plot)
