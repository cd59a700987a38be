#!/usr/bin/python3
"""The papers' claimed frame rates next to ours: `plumbago bench --paper` (text and JSON),
at each scene's own resolution or the settings' size.

  /usr/bin/python3 experiments/paper_claims/run.py SETTINGS OUT_DIR

SETTINGS: the paper_claims block of experiments/config/*.yaml as JSON (frames, size,
reference_frames); experiments/Snakefile passes it. Writes paper_claims.json, the table
made from it (paper_claims.md) and run_info.json.
"""
import json
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "lib"))
import plumbago_cli as pc  # noqa: E402


def table(j):
    """The Markdown table of one `bench --paper --json` run."""
    lines = ["| paper | their scene | faces | resolution | their fps | their hardware | our scene | faces | strokes | "
             "size | our GPU fps | our CPU reference fps |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for c in j["claims"]:
        fps = "%g" % c["fps_low"] if c["fps_low"] == c["fps_high"] else "%g-%g" % (c["fps_low"], c["fps_high"])
        g, r = c["ours_gpu"], c["ours_reference"]
        ours = g or r
        lines.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            c["paper"], c["scene"], c["faces"] or "?", c["resolution"], fps, c["hardware"],
            ("`%s` (%s)" % (c["ours_scene"], c["note"])) if c["ours_scene"] else "none (%s)" % c["note"],
            ours["faces"] if ours else "", "%d" % ours["strokes"] if ours and ours.get("strokes") else "",
            "%dx%d" % tuple(ours["size"]) if ours else "",
            "%.1f" % g["fps"] if g else "-", "%.1f" % r["fps"] if r else "-"))
    return lines


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    s, out = json.loads(sys.argv[1]), pathlib.Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    args = ["bench", "--paper", "--frames", s["frames"]] + (["--size", s["size"]] if s["size"] else [])
    if s["reference_frames"]:
        args += ["--reference-frames", s["reference_frames"]]
    text = pc.run(args + ["--json"])
    (out / "paper_claims.json").write_text(text)
    j = json.loads(text)  # the table below is made from the same run's JSON, not timed again
    lines = ["machine:     %s" % j["machine"], "GL renderer: %s" % j["renderer"], ""] + table(j)
    (out / "paper_claims.md").write_text("\n".join(lines) + "\n")
    pc.write_run_info(out, dict(pc.machine(j["renderer"]), settings=s))
    pc.log("\n".join(lines))
    pc.log("wrote", out)


if __name__ == "__main__":
    main()
