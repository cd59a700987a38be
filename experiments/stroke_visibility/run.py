#!/usr/bin/python3
"""Stroke visibility: how right is the ID-image test (Kalnins et al. 2002, §4.6), and what does it cost?

Kalnins et al. 2002 decide which parts of a feature line are visible from an ID reference
image (Kalnins et al. 2002, §4.6): a sample is visible when its own key is found within a pixel of it. That
is an approximation. Here every path of every object is also tested by Embree occlusion
rays from the eye every 0.5 px of window arc length (`plumbago lines --truth`), and the
visible runs the strokes draw are compared with them:
  - false visible: the share of ray-hidden arc that a run covers;
  - false hidden: the share of ray-visible arc that no run covers;
over every path, and apart for silhouettes and for creases with borders (their tests differ),
against the sampling step (strokes.vis_step_px), the width of the ID image's line quads
(strokes.id_silhouette_px and id_crease_px together) and the depth biases of the silhouettes'
quads (strokes.id_depth_bias) and of the creases' and borders' (strokes.id_crease_depth_bias),
strokes.crease_under_silhouettes (a crease sample also tested at its own pixel of the ID
image before the silhouettes' quads) and strokes.id_silhouette_lift (silhouette quads nearer
by that many times their segment's world length), one at a time around the defaults, with the time of the ID
image and visibility passes (CPU reference, wall time, the fastest of 3 runs; the flags
are the same on the GPU, whose parity is exact).

A silhouette's rays pass over hits within two of the point's face's longest edges: a
silhouette point lies on the smooth (interpolated-normal) silhouette, which the mesh's own
facets graze, so an occluder closer than that to it is not seen by the rays either. A
crease's or border's pass over the triangles the point lies on, and nothing else.

Settings (experiments/config/*.yaml, stroke_visibility): scenes, size, repeats, sweeps
(parameter: values). Run through experiments/Snakefile (lib/study_cli.py).
"""
import json
import pathlib
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "lib"))
import plumbago_cli as pc  # noqa: E402
import study_cli  # noqa: E402

# the program's defaults
DEFAULTS = {"vis_step_px": 2, "id_width_px": 3, "id_depth_bias": 0.005, "id_crease_depth_bias": 1e-4,
            "crease_under_silhouettes": 0, "id_silhouette_lift": 0}
FIGURES = ["visibility_error.png"]


def points(s):
    """One point per scene and swept parameter (the sweeps' values: settings' sweeps)."""
    return ["%s-%s" % (pc.stem(f), name) for f in s["scenes"] for name in s["sweeps"]]


def scenes(s):
    return s["scenes"]


def settings(name, value):
    if name == "id_width_px":
        return ["strokes.id_silhouette_px=%g" % value, "strokes.id_crease_px=%g" % max(value - 1, 1)]
    return ["strokes.%s=%g" % (name, value)]


def covered(runs, s, length, closed):
    for s0, s1 in runs:
        if s0 <= s <= s1 or (closed and s0 <= s + length <= s1):
            return True
    return False


KINDS = {"silhouette": ("silhouette",), "crease": ("crease", "border")}  # the rates reported apart


def rates(lines, kinds=None):
    """False-visible and false-hidden shares over the truth samples of the paths of `kinds` (None: every path)."""
    fv = hidden = fh = visible = 0
    for p in lines["paths"]:
        if kinds is not None and p["kind"] not in kinds:
            continue
        length = p["arc_px"][-1] if p["arc_px"] else 0
        if p["closed"] and len(p["screen"]) > 1:
            a, b = p["screen"][-1], p["screen"][0]
            length += ((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2) ** 0.5
        step = p["truth"]["step_px"]
        for k, seen in enumerate(p["truth"]["visible"]):
            drawn = covered(p["runs"], k * step, length, p["closed"])
            if seen:
                visible += 1
                fh += not drawn
            else:
                hidden += 1
                fv += drawn
    return fv / max(hidden, 1), fh / max(visible, 1), visible, hidden


def kind_rates(lines):
    """Per KINDS group: its false visible and false hidden, as row columns (nan: no such arc)."""
    out = {}
    for group, kinds in KINDS.items():
        fv, fh, visible, hidden = rates(lines, kinds)
        out[group + "_false_visible"] = fv if hidden else float("nan")
        out[group + "_false_hidden"] = fh if visible else float("nan")
    return out


def measure(s, point):
    stem, name = point.rsplit("-", 1)
    scene = next(f for f in s["scenes"] if pc.stem(f) == stem)
    if pc.missing_models(scene):
        pc.log("skipped %s: no %s" % (scene, ", ".join(pc.missing_models(scene))))
        return [], None
    rows = []
    with tempfile.TemporaryDirectory(prefix="plumbago-vis-") as work:
        out = pathlib.Path(work) / "lines.json"
        for value in s["sweeps"][name]:
            sets = sum((settings(n, value if n == name else DEFAULTS[n]) for n in DEFAULTS), [])
            args = ["lines", scene, "--truth", "--backend", "reference", "--size", s["size"], "-o", out]
            for x in sets:
                args += ["--set", x]
            ms = {}
            for _ in range(s["repeats"]):  # the fastest of the runs: the least disturbed
                pc.run(args)
                lines = json.loads(out.read_text())
                for t in lines["ran"]:
                    ms[t["name"]] = min(ms.get(t["name"], float("inf")), t["ms"])
            fv, fh, visible, hidden = rates(lines)
            row = dict(scene=stem.replace("builtin_", ""), swept=name, value=value,
                       size=s["size"], paths=len(lines["paths"]), truth_visible=visible, truth_hidden=hidden,
                       false_visible=fv, false_hidden=fh, **kind_rates(lines), id_image_ms=ms.get("id_image"),
                       visibility_ms=ms.get("visibility"))
            rows.append(row)
            pc.log("%-14s %-13s %-6g false visible %6.2f%%  false hidden %6.2f%%  id %6.1f ms  vis %6.1f ms" %
                   (row["scene"], name, value, 100 * fv, 100 * fh, row["id_image_ms"], row["visibility_ms"]))
    return rows, pc.machine("CPU reference (Embree)")


def plot(rows, out):
    plt = pc.pyplot()
    swept = list(dict.fromkeys(r["swept"] for r in rows))
    fig, axes = plt.subplots(1, len(swept), figsize=(5 * len(swept), 4.2), squeeze=False)
    axes = axes[0]
    for ax, name in zip(axes, swept):
        for i, scene in enumerate(dict.fromkeys(r["scene"] for r in rows)):
            pts = [r for r in rows if r["scene"] == scene and r["swept"] == name]
            xs = [r["value"] for r in pts]
            ax.plot(xs, [100 * r["false_visible"] for r in pts], "o-", color="C%d" % i, label=scene + " false visible")
            ax.plot(xs, [100 * r["false_hidden"] for r in pts], "s--", color="C%d" % i, label=scene + " false hidden")
            for r in pts:
                ax.annotate("%.0f ms" % (r["id_image_ms"] + r["visibility_ms"]), (r["value"], 100 * r["false_hidden"]),
                            fontsize=6, xytext=(3, 3), textcoords="offset points")
        if name.endswith("bias"):  # 0 and values a decade apart
            ax.set_xscale("symlog", linthresh=1e-4)
        ax.set_xlabel("strokes." + name + " (default %g)" % DEFAULTS[name])
        ax.set_ylabel("% of the arc (rays decide)")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=6)
    fig.suptitle("ID-image visibility against Embree rays (labels: ID image + visibility ms, CPU reference)", fontsize=10)
    pc.save_figure(fig, out, "visibility_error.png")


if __name__ == "__main__":
    study_cli.main(__doc__, sys.modules[__name__])
