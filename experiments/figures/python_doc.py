#!/usr/bin/python3
"""docs/images/python_depth_scale.png: runs the code blocks of docs/python.md marked
`python ablation`, in order, in one namespace, as a notebook would, with the module built
with the program (plumbago_cli.module), and saves the figure the last block leaves in `fig`.

  python_doc.py DOC.md OUT.png
"""
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "lib"))
import plumbago_cli as pc  # noqa: E402

BLOCK = re.compile(r"^```python ablation\n(.*?)^```$", re.S | re.M)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    doc, out = pathlib.Path(sys.argv[1]), sys.argv[2]
    blocks = BLOCK.findall(doc.read_text())
    if not blocks:
        sys.exit("%s: no ```python ablation block" % doc)
    pc.module()
    pc.pyplot()  # Agg: no display
    namespace = {}
    for i, code in enumerate(blocks):
        exec(compile(code, "%s, block %d" % (doc, i + 1), "exec"), namespace)
    namespace["fig"].savefig(out, dpi=110)


if __name__ == "__main__":
    main()
