"""Shared helpers of the experiments: run `plumbago bench` through the command line and
read its JSON, derive scene files, name the machine, write CSV.

The program is $PLUMBAGO, or build/plumbago under the repository root.
"""
import argparse
import csv
import json
import os
import pathlib
import platform
import subprocess
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
QUICK_OUT = pathlib.Path(tempfile.gettempdir()) / "plumbago-experiments-quick"


def plumbago():
    return os.environ.get("PLUMBAGO", str(ROOT / "build" / "plumbago"))


def run(args, **kw):
    """Runs plumbago with `args`; raises with its stderr when it fails."""
    cmd = [plumbago()] + [str(a) for a in args]
    result = subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT, **kw)
    if result.returncode != 0:
        raise RuntimeError("%s failed (%d):\n%s" % (" ".join(cmd), result.returncode, result.stderr))
    return result.stdout


def bench(scene, sets=(), size=None, frames=5, backend="gpu", reference_frames=None, save=None, against=None, buffers=None, tolerance=None):
    """One `plumbago bench --json` call; returns the parsed JSON."""
    args = ["bench", scene, "--json", "--frames", frames, "--backend", backend]
    for s in sets:
        args += ["--set", s]
    if size:
        args += ["--size", size]
    if reference_frames:
        args += ["--reference-frames", reference_frames]
    if save:
        args += ["--save", save]
    if against:
        args += ["--against", against]
    if buffers:
        args += ["--buffers", ",".join(buffers)]
    if tolerance is not None:
        args += ["--tolerance", tolerance]
    return json.loads(run(args))


def result(j, backend):
    return next(r for r in j["results"] if r["backend"] == backend)


def params():
    """Every parameter as {key: {type, default, range, doc}} from `plumbago params`."""
    out = {}
    for line in run(["params"]).splitlines():
        key, type_, default, rest = line.split(None, 3)
        if rest.startswith("["):  # "[lo, hi]"
            range_, doc = rest[:rest.index("]") + 1], rest[rest.index("]") + 1:].strip()
        else:
            range_, doc = rest.split(None, 1)
        out[key] = dict(type=type_, default=default, range=range_, doc=doc)
    return out


def param_default(key):
    p = params()[key]
    return {"int": int, "real": float}.get(p["type"], str)(p["default"])


def param_range(key):
    lo, hi = params()[key]["range"].strip("[]").split(",")
    return float(lo), float(hi)


def derive_scene(base, folder, name, **changes):
    """Writes a copy of scene file `base` into `folder` with top-level keys changed and
    mesh paths made absolute; returns its path."""
    base = pathlib.Path(base)
    if not base.is_absolute():
        base = ROOT / base
    scene = json.loads(base.read_text())

    def absolute(mesh):
        return str((base.parent / mesh).resolve()) if isinstance(mesh, str) else mesh

    if "mesh" in scene:
        scene["mesh"] = absolute(scene["mesh"])
    for o in scene.get("objects", []):
        o["mesh"] = absolute(o["mesh"])
    scene.update(changes)
    path = pathlib.Path(folder) / (name + ".json")
    path.write_text(json.dumps(scene, indent=1))
    return str(path)


def machine(renderer):
    model = "unknown CPU"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return dict(cpu=model, threads=os.cpu_count(), renderer=renderer, system=platform.platform(),
                load_average=" ".join("%.2f" % x for x in os.getloadavg()), date=time.strftime("%Y-%m-%d %H:%M"),
                plumbago=plumbago())


def write_run_info(out, info):
    (pathlib.Path(out) / "run_info.json").write_text(json.dumps(info, indent=1) + "\n")


def write_csv(path, rows):
    keys = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k, v in r.items():
            try:
                r[k] = float(v)
            except (TypeError, ValueError):
                pass
    return rows


def arguments(doc, here):
    """--quick, --out, --replot; the output folder defaults to the study's own folder
    (full runs) or a temporary folder (quick runs, so they never overwrite the recorded ones)."""
    p = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--quick", action="store_true", help="fewer settings, smaller images, fewer frames")
    p.add_argument("--out", help="folder for results.csv and the plots (default: this folder; --quick: %s/NAME)" % QUICK_OUT)
    p.add_argument("--replot", action="store_true", help="only redraw the plots from --out/results.csv")
    a = p.parse_args()
    if a.out is None:
        a.out = str(QUICK_OUT / here.name) if a.quick else str(here)
    pathlib.Path(a.out).mkdir(parents=True, exist_ok=True)
    return a


def pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def log(*a):
    print(*a, flush=True)


def study_main(doc, here, sweep, plot):
    """The command line every study shares: sweep (or --replot the recorded CSV), write
    results.csv and run_info.json into --out, draw the plots."""
    a = arguments(doc, here)
    if a.replot:
        plot(read_csv(pathlib.Path(a.out) / "results.csv"), a.out)
        return
    rows, info = sweep(a)
    write_csv(pathlib.Path(a.out) / "results.csv", rows)
    write_run_info(a.out, info)
    plot(rows, a.out)
    log("wrote", a.out)


def save_figure(fig, out, name):
    """Lays out `fig`, writes it as out/name at the studies' resolution and closes it."""
    fig.tight_layout()
    fig.savefig(pathlib.Path(out) / name, dpi=110)
    pyplot().close(fig)
