#!/usr/bin/python3
"""Study 4: the pencil texture stack (Lee et al. 2006 §3): how many tone layers
(pencil_textures.layers) and how large a tile (pencil_textures.size), against frame time, generation time and
memory.

Reference: the most accurate setting of the sweep, the most layers at the largest tile
(full config: 64 at 1024), rendered in the same job. Each setting's final image
and pencil-interior darkness are compared with it by `plumbago bench --against`. The
contour texture's layer (contour.texture_layer) is scaled with the layer count so it keeps
its tone. Memory is the stack as the GPU allocates it (one R32F texture array,
layers x size^2 x 4 bytes), computed from the parameters, not measured.

Settings (experiments/config/*.yaml, pencil_textures): scene, layers, tiles, size,
frames, tolerance. Run through experiments/Snakefile (lib/study_cli.py).
"""
import pathlib
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "lib"))
import plumbago_cli as pc  # noqa: E402
import study_cli  # noqa: E402

BUFFERS = ["compose.color", "pencil_interior.interior_darkness"]
BYTES_PER_TEXEL = 4  # GL_R32F (gpu/core/pipeline.cpp uploads the stack as R32F)


def sets(layers, size, default_layers, default_layer):
    return ["pencil_textures.layers=%d" % layers, "pencil_textures.size=%d" % size,
            "contour.texture_layer=%d" % min(layers - 1, round(default_layer * layers / default_layers))]


FIGURES = ["difference_vs_time_and_memory.png"]


def points(s):
    """The default setting, then one point per layers x tile; each measures the default too,
    so its ratios compare two runs of one job."""
    return ["default"] + ["%dx%d" % (n, t) for n in s["layers"] for t in s["tiles"]]


def scenes(s):
    return [s["scene"]]


def measure(s, point):
    default_layers, default_tile = pc.param_default("pencil_textures.layers"), pc.param_default("pencil_textures.size")
    default_layer = pc.param_default("contour.texture_layer")
    n, t = (default_layers, default_tile) if point == "default" else map(int, point.split("x"))
    if point != "default" and (n, t) == (default_layers, default_tile):
        pc.log("%s is the default setting: its row is the default point's" % point)
        return [], None
    size, tolerance = s["size"], s["tolerance"]
    most, largest = max(s["layers"]), max(s["tiles"])
    with tempfile.TemporaryDirectory(prefix="plumbago-pencil-") as work:
        ref = pc.bench(s["scene"], sets(most, largest, default_layers, default_layer), size=size, frames=1,
                       save=work, buffers=BUFFERS)

        def run(layers, tile):
            return pc.result(pc.bench(s["scene"], sets(layers, tile, default_layers, default_layer), size=size,
                                      frames=s["frames"], against=pathlib.Path(work) / "gpu", buffers=BUFFERS,
                                      tolerance=tolerance), "gpu")
        base = run(default_layers, default_tile)
        g = base if point == "default" else run(n, t)
    e, d = g["errors"]["compose.color"], g["errors"]["pencil_interior.interior_darkness"]
    row = dict(layers=n, tile=t, width=g["size"][0], height=g["size"][1], frame_ms=g["frame_ms"],
               ratio_to_default=g["frame_ms"] / base["frame_ms"],
               generation_ms=g["preprocessing"].get("pencil_textures", float("nan")),
               generation_ratio_to_default=g["preprocessing"].get("pencil_textures", float("nan")) /
               base["preprocessing"]["pencil_textures"],
               stack_mib=n * t * t * BYTES_PER_TEXEL / 2 ** 20, color_mean_abs=e["mean_abs"],
               color_over_tolerance=e["over_tolerance"], darkness_mean_abs=d["mean_abs"],
               reference="%d layers at %d" % (most, largest), tolerance=tolerance, scene=pc.stem(s["scene"]))
    pc.log("%2d layers x %4d: %7.1f ms (%.2fx default)  generation %8.0f ms  %6.1f MiB  image mean |diff| %.4f"
           "  darkness %.4f" % (n, t, row["frame_ms"], row["ratio_to_default"], row["generation_ms"],
                                row["stack_mib"], row["color_mean_abs"], row["darkness_mean_abs"]))
    return [row], pc.machine(ref["renderer"])


def finish(rows, out):
    return sorted(rows, key=lambda r: (r["layers"], r["tile"]))


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
                 (rows[0]["reference"], rows[0].get("scene", "the scene"), rows[0]["width"], rows[0]["height"]), fontsize=11)
    pc.save_figure(fig, out, "difference_vs_time_and_memory.png")


if __name__ == "__main__":
    study_cli.main(__doc__, sys.modules[__name__])
