"""The command line every study shares; experiments/Snakefile drives it.

  run.py points SETTINGS                  the sweep's points, one a line
  run.py measure SETTINGS POINT OUT.json  one point: its CSV rows and the machine it ran on
  run.py collect SETTINGS DIR POINT.json...  DIR/results.csv, DIR/run_info.json, the plots
  run.py replot DIR                       the plots again from DIR/results.csv

SETTINGS is the study's block of the workflow's config as JSON (experiments/config/).
A study module gives points(settings), measure(settings, point) -> (rows, info or None),
plot(rows, out) and, optionally, finish(rows, out) for what the whole sweep derives.
Everything a ratio compares is measured inside one point, so one job.
"""
import argparse
import json
import pathlib

import plumbago_cli as pc


def _collect(study, settings, out, point_files):
    rows, infos = [], []
    for f in point_files:
        j = json.loads(pathlib.Path(f).read_text())
        rows += j["rows"]
        if j["info"]:
            infos.append(j["info"])
    if not rows:
        raise SystemExit("no point of the sweep gave a result (see the points' logs)")
    if hasattr(study, "finish"):
        rows = study.finish(rows, out) or rows
    pc.write_csv(out / "results.csv", rows)
    info = dict(infos[0], points=len(point_files), finished=max(i["date"] for i in infos))
    machines = sorted({"%s, %s" % (i["cpu"], i["renderer"]) for i in infos})
    if len(machines) > 1:
        info["machines"] = machines
    pc.write_run_info(out, dict(info, settings=settings))
    study.plot(rows, out)
    pc.log("wrote", out)


def main(doc, study):
    p = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter,
                                epilog=__doc__)
    sub = p.add_subparsers(dest="command", required=True)
    sub.add_parser("points").add_argument("settings")
    m = sub.add_parser("measure")
    for a in ("settings", "point", "output"):
        m.add_argument(a)
    c = sub.add_parser("collect")
    c.add_argument("settings")
    c.add_argument("out")
    c.add_argument("point_files", nargs="+")
    sub.add_parser("replot").add_argument("out")
    a = p.parse_args()
    if a.command == "replot":
        study.plot(pc.read_csv(pathlib.Path(a.out) / "results.csv"), pathlib.Path(a.out))
        return
    settings = json.loads(a.settings)
    if a.command == "points":
        print("\n".join(study.points(settings)))
    elif a.command == "measure":
        if a.point not in study.points(settings):
            raise SystemExit("no point %s in this sweep (run.py points)" % a.point)
        rows, info = study.measure(settings, a.point)
        pathlib.Path(a.output).write_text(json.dumps(dict(point=a.point, rows=rows, info=info), indent=1) + "\n")
    else:
        out = pathlib.Path(a.out)
        out.mkdir(parents=True, exist_ok=True)
        _collect(study, settings, out, a.point_files)
