#!/usr/bin/env python3
"""Plots results.csv of the shower-door experiment (README.md): the coherence of each
mode per frame pair, for the (u, v) perturbation field and for the rendered sketch."""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# default, repeat and rough all score exactly 0 on the field: markers keep each visible.
STYLE = {"default": ("tab:blue", "-o"), "repeat": ("tab:cyan", "-s"), "rough": ("tab:red", "-x"),
         "object": ("tab:green", "-"), "object_enlarge0": ("tab:olive", "--"),
         "unperturbed": ("black", ":")}
STYLE_ORDER = {"default": 0, "repeat": 1, "rough": 2}


def main(path, out):
    rows = list(csv.DictReader(open(path)))
    series = defaultdict(lambda: defaultdict(list))
    for r in rows:
        for key in ("field_coherence", "image_coherence"):
            if r[key] != "":
                series[key][r["mode"]].append((int(r["pair"]), float(r[key])))
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5), sharey=True)
    titles = {"field_coherence": "(u, v) perturbation field (Nienhaus & Döllner 2004, §3.2)",
              "image_coherence": "rendered sketch (RGB)"}
    for ax, key in zip(axes, ("field_coherence", "image_coherence")):
        for mode, points in series[key].items():
            color, line = STYLE.get(mode, ("gray", "-"))
            xs, ys = zip(*sorted(points))
            mean = sum(ys) / len(ys)
            ax.plot(xs, ys, line, color=color, label=f"{mode} (mean {mean:.3f})", markevery=(STYLE_ORDER.get(mode, 0), 4),
                    markersize=5, fillstyle="none")
        ax.set_title(titles[key])
        ax.set_xlabel("frame pair (t, t+1)")
        ax.set_ylim(-0.03, 1.03)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="center right")
    axes[0].set_ylabel("coherence B / (A + B)\n1 = moves with the surface, 0 = fixed to the screen")
    r = rows[0]
    fig.suptitle(f"Shower-door effect: {r['mesh']}, {r['size']}x{r['size']}, orbit {r['step_deg']}° per frame")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
