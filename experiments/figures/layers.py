#!/usr/bin/python3
"""docs/images/pencil_layers.png: the first eight layers of the pencil texture stack
(Lee et al. 2006 Eq. 3-4; compare their Fig. 4) in a 4 x 2 grid, from `plumbago textures`.

  layers.py TEXTURES_DIR OUT.png
"""
import pathlib
import sys

from PIL import Image

COLUMNS, ROWS = 4, 2


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    textures, out = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    layers = [Image.open(textures / ("pencil_layer_%02d.png" % i)).convert("L") for i in range(COLUMNS * ROWS)]
    w, h = layers[0].size
    sheet = Image.new("L", (COLUMNS * w, ROWS * h))
    for i, layer in enumerate(layers):
        sheet.paste(layer, ((i % COLUMNS) * w, (i // COLUMNS) * h))
    sheet.save(out)


if __name__ == "__main__":
    main()
