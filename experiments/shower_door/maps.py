#!/usr/bin/env python3
"""Assembles the per-pixel residuals that plumbago_shower_door --maps wrote for the first
frame pair into one figure (README.md): where the perturbation fails to follow the surface."""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PANELS = [("object_sketch1", "object: sketch, frame 1"),
          ("object_A", "object: A per pixel"),
          ("object_enlarge0_A", "object_enlarge0: A per pixel"),
          ("object_B", "object: B per pixel"),
          ("default_A", "default: A per pixel")]


def main(folder, out):
    fig, axes = plt.subplots(1, len(PANELS), figsize=(4 * len(PANELS), 4.4))
    for ax, (name, title) in zip(axes, PANELS):
        img = plt.imread(f"{folder}/{name}.png")
        h, w = img.shape[:2]
        ax.imshow(img[h // 10: h - h // 10, w // 10: w - w // 10], cmap="gray", vmin=0, vmax=1)
        ax.set_title(title, fontsize=10)
        ax.axis("off")
    fig.suptitle("Frame pair (0, 1): |(u, v) residual| per moving pixel, white = 0.1 or more; black also = pixel left out")
    fig.tight_layout()
    fig.savefig(out, dpi=90)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
