#!/usr/bin/python3
"""The papers' claimed frame rates next to ours: `plumbago bench --paper` (text and JSON),
at each scene's own resolution (--quick: 320x320, fewer frames).

  /usr/bin/python3 experiments/paper_claims/run.py [--quick] [--out DIR]
"""
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "lib"))
import plumbago_cli as pc  # noqa: E402


def main():
    a = pc.arguments(__doc__, HERE)
    args = ["bench", "--paper", "--frames", "3" if a.quick else "20"] + (["--size", "320x320"] if a.quick else [])
    if not a.quick:
        args += ["--reference-frames", "3"]
    text = pc.run(args + ["--json"])
    (pathlib.Path(a.out) / "paper_claims.json").write_text(text)
    import json  # the table below is made from the same run's JSON, not timed again
    j = json.loads(text)
    lines = ["machine:     %s" % j["machine"], "GL renderer: %s" % j["renderer"], "",
             "| paper | their scene | faces | resolution | their fps | their hardware | our scene | faces | size | "
             "our GPU fps | our CPU reference fps |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    for c in j["claims"]:
        fps = "%g" % c["fps_low"] if c["fps_low"] == c["fps_high"] else "%g-%g" % (c["fps_low"], c["fps_high"])
        g, r = c["ours_gpu"], c["ours_reference"]
        ours = g or r
        lines.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            c["paper"], c["scene"], c["faces"] or "?", c["resolution"], fps, c["hardware"],
            ("`%s` (%s)" % (c["ours_scene"], c["note"])) if c["ours_scene"] else "none (%s)" % c["note"],
            ours["faces"] if ours else "", "%dx%d" % tuple(ours["size"]) if ours else "",
            "%.1f" % g["fps"] if g else "-", "%.1f" % r["fps"] if r else "-"))
    (pathlib.Path(a.out) / "paper_claims.md").write_text("\n".join(lines) + "\n")
    pc.write_run_info(a.out, pc.machine(j["renderer"]))
    pc.log("\n".join(lines))
    pc.log("wrote", a.out)


if __name__ == "__main__":
    main()
