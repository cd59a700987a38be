#!/usr/bin/python3
"""Study 3: contour drawing (Lee et al. 2006 §4): how many copies, how fine a
distortion grid and how much shake, against frame time.

Reference: the most accurate setting of the stage, 5 copies on the finest grid of the
sweep (other parameters at their defaults), rendered in the same run. Each setting's
final image is compared with it by `plumbago bench --against`; its frame time is
reported in ms and as a ratio to the default setting measured in the same run.

  /usr/bin/python3 experiments/contours/run.py [--quick] [--out DIR] [--replot]
"""
import pathlib
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "lib"))
import plumbago_cli as pc  # noqa: E402
import study_cli  # noqa: E402

FIGURES = ["difference_vs_time.png"]
SWEPT = {"copies": "copies", "grid_cell": "cells", "shake": "shakes"}  # sweep -> its settings key


def points(s):
    """The default, then one point per swept value; each measures the default too, so its
    ratio compares two runs of one job."""
    return ["default"] + ["%s-%g" % (name, v) for name, key in SWEPT.items() for v in s[key]]


def scenes(s):
    return [s["scene"]]


def setting(s, point):
    """The point's setting and the reference: the most copies on the finest grid of the sweep."""
    finest, most = min(s["cells"]), max(s["copies"])
    lo, hi = pc.param_range("contour.grid_cell")
    assert lo <= finest and max(s["cells"]) <= hi, "grid cells outside the parameter's range"
    default = dict(copies=pc.param_default("contour.copies"), grid_cell=pc.param_default("contour.grid_cell"),
                   shake=pc.param_default("contour.shake_amplitude"))
    reference = dict(default, copies=most, grid_cell=finest)
    if point == "default":
        return "default", default, default, reference
    name, value = point.rsplit("-", 1)
    value = float(value)
    point_setting = {"copies": dict(default, copies=int(value), grid_cell=finest),
                     "grid_cell": dict(default, copies=most, grid_cell=int(value)),
                     "shake": dict(default, copies=most, grid_cell=finest, shake=value)}[name]
    return name, point_setting, default, reference


def sets(s):
    return ["contour.copies=%d" % s["copies"], "contour.grid_cell=%d" % s["grid_cell"],
            "contour.shake_amplitude=%g" % s["shake"]]


def contour_pass_ms(stages):
    """The GL timer of the pass that draws the contours: alone, or fused with others ("a+b")."""
    return next((ms for name, ms in stages.items() if "multi_contour" in name.split("+")), float("nan"))


def measure(s, point):
    sweep_name, setting_, default, reference = setting(s, point)
    tolerance = s["tolerance"]
    with tempfile.TemporaryDirectory(prefix="plumbago-contours-") as work:
        ref = pc.bench(s["scene"], sets(reference), size=s["size"], frames=1, save=work, buffers=["compose.color"])

        def run(x):
            return pc.result(pc.bench(s["scene"], sets(x), size=s["size"], frames=s["frames"],
                                      against=pathlib.Path(work) / "gpu", buffers=["compose.color"],
                                      tolerance=tolerance), "gpu")
        base = run(default)
        g = base if setting_ is default else run(setting_)
    e = g["errors"]["compose.color"]
    row = dict(scene=pc.stem(s["scene"]), sweep=sweep_name, copies=setting_["copies"], grid_cell=setting_["grid_cell"],
               shake_amplitude=setting_["shake"], width=g["size"][0], height=g["size"][1], frame_ms=g["frame_ms"],
               ratio_to_default=g["frame_ms"] / base["frame_ms"],
               multi_contour_gpu_ms=contour_pass_ms(g["stages"]),
               distortion_ms=g["preprocessing"].get("distortion", float("nan")),
               mean_abs=e["mean_abs"], rmse=e["rmse"], share_over_tolerance=e["over_tolerance"], tolerance=tolerance,
               reference="copies=%d grid_cell=%d shake=%g" % (reference["copies"], reference["grid_cell"],
                                                               reference["shake"]))
    pc.log("%-9s copies %d cell %3d shake %4g: %7.1f ms (%.2fx default)  mean |diff| %.4f  over %.2f: %.2f%%" %
           (sweep_name, setting_["copies"], setting_["grid_cell"], setting_["shake"], row["frame_ms"],
            row["ratio_to_default"], row["mean_abs"], tolerance, 100 * row["share_over_tolerance"]))
    return [row], pc.machine(ref["renderer"])


def plot(rows, out):
    plt = pc.pyplot()
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6), sharey=True)
    default = next(r for r in rows if r["sweep"] == "default")
    for ax, (name, key, label) in zip(axes, [("copies", "copies", "copies (grid cell %d px)"),
                                             ("grid_cell", "grid_cell", "grid cell px (%d copies)"),
                                             ("shake", "shake_amplitude", "shake amplitude px (%d copies)")]):
        sel = sorted((r for r in rows if r["sweep"] == name), key=lambda r: r[key])
        x = [r["frame_ms"] for r in sel]
        y = [100 * r["mean_abs"] for r in sel]
        ax.plot(x, y, "o:", lw=0.8)  # dotted: the sweep's order, not a curve (times are noisy)
        for r, xi, yi in zip(sel, x, y):
            ax.annotate("%g (%.2fx)" % (r[key], r["ratio_to_default"]), (xi, yi), fontsize=8, xytext=(4, 3),
                        textcoords="offset points")
        ax.axvline(default["frame_ms"], color="gray", ls=":", lw=1)
        ax.annotate("default setting", (default["frame_ms"], 0), rotation=90, fontsize=7, color="gray",
                    xytext=(2, 2), textcoords="offset points")
        fixed = sel[0]["grid_cell"] if name == "copies" else sel[0]["copies"]
        ax.set_title(label % fixed, fontsize=10)
        ax.set_xlabel("frame ms (median; label: value, time / default setting)")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("mean |image - reference| (% of full scale)")
    fig.suptitle("contours, %s at %dx%d: difference from %s, against frame time" %
                 (rows[0].get("scene", "the scene"), rows[0]["width"], rows[0]["height"], rows[0]["reference"]),
                 fontsize=11)
    pc.save_figure(fig, out, "difference_vs_time.png")


if __name__ == "__main__":
    study_cli.main(__doc__, sys.modules[__name__])
