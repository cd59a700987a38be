#!/usr/bin/python3
"""Side-by-side animation of one scene's stroke layers under the 2002 paper's arc length (left)
and coherent silhouettes (Kalnins et al. 2003, right), from the folders of frame_NNN.png that
plumbago_temporal_coherence --layers writes, as an animated GIF: the window `crop` of each
(x, y, width, height in px from the top left; default the whole layer) at `scale`.

  animate.py ARC_LENGTH_DIR COHERENT_DIR OUT.gif [--fps 10] [--scale 1] [--crop X Y W H]
"""
import argparse
import pathlib

from PIL import Image, ImageDraw


def frames(folder):
    paths = sorted(pathlib.Path(folder).glob("frame_*.png"))
    if not paths:
        raise SystemExit("%s: no frame_*.png" % folder)
    return paths


def labelled(path, label, scale, crop):
    image = Image.open(path).convert("RGB")
    if crop:
        x, y, w, h = crop
        image = image.crop((x, y, x + w, y + h))
    image = image.resize((round(image.width * scale), round(image.height * scale)), Image.LANCZOS)
    ImageDraw.Draw(image).text((8, 8), label, fill=(200, 0, 0))
    return image


def side_by_side(left, right):
    out = Image.new("RGB", (left.width + right.width + 4, max(left.height, right.height)), (128, 128, 128))
    out.paste(left, (0, 0))
    out.paste(right, (left.width + 4, 0))
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("arc_length")
    p.add_argument("coherent")
    p.add_argument("out")
    p.add_argument("--fps", type=float, default=10)
    p.add_argument("--scale", type=float, default=1)
    p.add_argument("--crop", type=int, nargs=4, metavar=("X", "Y", "W", "H"))
    a = p.parse_args()
    left, right = frames(a.arc_length), frames(a.coherent)
    if len(left) != len(right):
        raise SystemExit("%d frames against %d" % (len(left), len(right)))
    images = [side_by_side(labelled(l, "arc length (2002)", a.scale, a.crop),
                           labelled(r, "coherent (2003)", a.scale, a.crop))
              for l, r in zip(left, right)]
    out = pathlib.Path(a.out)
    tmp = out.with_name(out.name + ".tmp")
    images[0].save(tmp, format="GIF", save_all=True, append_images=images[1:], duration=round(1000 / a.fps), loop=0,
                   optimize=True)
    tmp.replace(out)  # no partial file


if __name__ == "__main__":
    main()
