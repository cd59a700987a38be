#!/usr/bin/python3
"""The temporal-coherence study's tables and figure (README.md), from its CSV files in DIR:
summary.csv -> summary.md (the tables README.md and docs/accuracy-vs-time.md show), with
coherent_summary.csv the silhouettes under both parameterizations side by side,
results.csv -> temporal_coherence.png (every measure per frame pair).

  report.py DIR
"""
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "lib"))
import plumbago_cli as pc  # noqa: E402


def fmt(x, digits=2):
    return "-" if not isinstance(x, float) or math.isnan(x) else "%.*f" % (digits, x)


def layer(r):
    if r["kind"] != "all":
        return ""
    return "%s (%s-%s)" % tuple(fmt(r[k], 3) for k in ("image_coherence_mean", "image_coherence_min",
                                                        "image_coherence_max"))


def share(part, whole):
    return "%.1f%%" % (100 * part / whole) if whole else "-"


KEY = [("scene", lambda r: r["scene"]), ("kind", lambda r: r["kind"])]
# Per kind: the strokes, their births and deaths, and the stroke layer's score.
STROKES = KEY + [
    ("strokes / frame", lambda r: fmt(r["strokes_per_frame"], 1)),
    ("px / frame", lambda r: "%.0f" % r["length_per_frame_px"]),
    ("born / pair", lambda r: fmt(r["born_per_pair"])), ("died / pair", lambda r: fmt(r["died_per_pair"])),
    ("born + died, share of px", lambda r: share(r["born_px_per_pair"] + r["died_px_per_pair"],
                                                 2 * r["length_per_frame_px"])),
    ("samples matched", lambda r: share(r["matched"], r["samples"])),
    ("stroke layer coherence: mean (min-max)", layer)]
# Per kind: what changed at the samples that matched.
CHANGES = KEY + [
    ("slide px: mean", lambda r: fmt(r["slide_mean_px"])), ("median", lambda r: fmt(r["slide_median_px"])),
    ("p95", lambda r: fmt(r["slide_p95_px"], 1)), ("max", lambda r: fmt(r["slide_max_px"], 0)),
    ("alpha change: p95", lambda r: fmt(r["alpha_change_p95"])), ("max", lambda r: fmt(r["alpha_change_max"])),
    ("width change px: p95", lambda r: fmt(r["width_change_p95_px"])),
    ("max", lambda r: fmt(r["width_change_max_px"])),
    ("offset change px: mean", lambda r: fmt(r["offset_change_mean_px"])),
    ("p95", lambda r: fmt(r["offset_change_p95_px"]))]


def table(rows, columns):
    """Markdown lines: one row per scene and line kind, then all kinds."""
    return ["| " + " | ".join(h for h, _ in columns) + " |", "|" + "---|" * len(columns)] + \
        ["| " + " | ".join(f(r) for _, f in columns) + " |" for r in rows]


def tables(rows):
    """Both tables of the summary, as README.md and docs/accuracy-vs-time.md show them."""
    return ["Strokes, per pair of consecutive frames (pooled over the pairs):", ""] + table(rows, STROKES) + \
        ["", "Changes at the samples that matched, per pair (pooled over the pairs):", ""] + table(rows, CHANGES)


def ratio(a, b):
    return "%.1fx" % (a / b) if isinstance(a, float) and isinstance(b, float) and b > 0 else "-"


def lower(base, coherent, key, digits):
    """The coherent value and, in parentheses, how many times lower it is."""
    return "%s (%s)" % (fmt(coherent[key], digits), ratio(base[key], coherent[key]))


def compared(base, coherent):
    """Markdown lines: per scene, the silhouettes' slide, offset change and births under the
    2002 paper's arc length and coherent (Kalnins et al. 2003), the texture's stretch that
    coherence costs (none under arc length), and the coherent stages' time a frame."""
    by_scene = {(r["scene"], r["kind"]): r for r in coherent}
    layers = {r["scene"]: r for r in base if r["kind"] == "all"}
    head = ["scene", "slide median px: arc length", "coherent", "p95: arc length", "coherent", "max: arc length",
            "coherent", "offset change p95 px: arc length", "coherent", "stretch median: coherent", "p95",
            "born + died / pair: arc length", "coherent",
            "stroke layer coherence: arc length",
            "coherent", "coherent stages, ms / frame (reference)"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for b in base:
        c, total = by_scene.get((b["scene"], b["kind"])), by_scene.get((b["scene"], "all"))
        if b["kind"] != "silhouette" or not c:
            continue
        lines.append("| " + " | ".join([
            b["scene"], fmt(b["slide_median_px"]), lower(b, c, "slide_median_px", 2),
            fmt(b["slide_p95_px"], 1), lower(b, c, "slide_p95_px", 1),
            fmt(b["slide_max_px"], 0), fmt(c["slide_max_px"], 0),
            fmt(b["offset_change_p95_px"], 3), lower(b, c, "offset_change_p95_px", 3),
            fmt(c["stretch_median"], 3), fmt(c["stretch_p95"], 3),
            fmt(b["born_per_pair"] + b["died_per_pair"]), fmt(c["born_per_pair"] + c["died_per_pair"]),
            fmt(layers[b["scene"]]["image_coherence_mean"], 3), fmt(total["image_coherence_mean"], 3) if total else "-",
            fmt(total["coherence_ms"]) if total else "-"]) + " |")
    return ["Silhouettes, arc length (Kalnins et al. 2002) and coherent (Kalnins et al. 2003), per pair (pooled "
            "over the pairs; in parentheses, how many times lower):", ""] + lines


# Per panel: the column, its title, the y scale, and a second column drawn dashed.
MEASURES = [("image_coherence", "stroke layer coherence B / (A + B)", "linear", None),
            ("slide_mean_px", "texture slide, mean px", "log", None),
            ("slide_p95_px", "texture slide, p95 px", "log", None),
            ("born", "strokes born (solid) and died (dashed)", "symlog", "died"),
            ("alpha_change_p95", "alpha change: p95 (solid), max (dashed)", "linear", "alpha_change_max"),
            ("width_change_p95_px", "width change px: p95 (solid), max (dashed)", "linear", "width_change_max_px"),
            ("offset_change_mean_px", "offset change px: mean (solid), p95 (dashed)", "linear", "offset_change_p95_px"),
            ("matched_share", "samples that land on the next frame's strokes", "linear", None)]
KIND_LINES = {"all": "-", "crease": "--", "border": ":", "silhouette": "-.", "decal": (0, (1, 3))}


def series(rows, scene, kind, key):
    points = [(int(r["pair"]), r[key]) for r in rows if r["scene"] == scene and r["kind"] == kind]
    return zip(*[(p, v) for p, v in points if isinstance(v, float) and not math.isnan(v)])


def plot(rows, out):
    plt = pc.pyplot()
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    kinds = list(dict.fromkeys(r["kind"] for r in rows))
    colors = dict(zip(scenes, plt.rcParams["axes.prop_cycle"].by_key()["color"]))
    for r in rows:
        r["matched_share"] = r["matched"] / r["samples"] if r["samples"] else math.nan
    fig, axes = plt.subplots(2, 4, figsize=(21, 8.5))
    for ax, (key, title, scale, dashed) in zip(axes.flat, MEASURES):
        by_kind = key.startswith("slide")  # the other measures: all kinds together
        for scene in scenes:
            for kind in kinds if by_kind else ["all"]:
                xs_ys = list(series(rows, scene, kind, key))
                if xs_ys:
                    ax.plot(*xs_ys, linestyle=KIND_LINES.get(kind, "-"), color=colors[scene],
                            label="%s %s" % (scene, kind) if by_kind else scene)
                if dashed:
                    ax.plot(*series(rows, scene, kind, dashed), linestyle="--", color=colors[scene])
        ax.set_title(title + ("" if by_kind else " (all kinds)"))
        ax.set_yscale(scale)
        ax.set_xlabel("frame pair (t, t+1)")
        ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=8)
    axes[0][1].legend(fontsize=7, ncol=2)
    r = rows[0]
    fig.suptitle("Temporal coherence of stroke rendering (Kalnins et al. 2002): orbit %g° per frame, CPU reference"
                 % r["step"])
    pc.save_figure(fig, out, "temporal_coherence.png")


def summary_lines(folder):
    """The tables of a run in `folder`: both of summary.csv, and the silhouettes in both modes
    where it has coherent_summary.csv."""
    base = pc.read_csv(folder / "summary.csv")
    lines = tables(base)
    if (folder / "coherent_summary.csv").exists():
        lines += [""] + compared(base, pc.read_csv(folder / "coherent_summary.csv"))
    return lines


def main(folder):
    folder = pathlib.Path(folder)
    (folder / "summary.md").write_text("\n".join(summary_lines(folder)) + "\n")
    plot(pc.read_csv(folder / "results.csv"), folder)


if __name__ == "__main__":
    main(sys.argv[1])
