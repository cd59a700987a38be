"""Shared helpers of the experiments: run `plumbago bench` through the command line and
read its JSON (a process of its own, as the papers time it), load the Python module built
with the program, derive scene files, name the machine, write CSV; the scenes and models a
study reads (experiments/Snakefile names them as inputs). The command line every study
shares is study_cli.py.

The program is $PLUMBAGO, or build/plumbago under the repository root; the module
(docs/python.md) is the one built with it, in the python/ folder beside it.
"""
import csv
import glob
import json
import math
import os
import pathlib
import platform
import resource
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]


def plumbago():
    return os.environ.get("PLUMBAGO", str(ROOT / "build" / "plumbago"))


def module():
    """The Python module `plumbago` built with the program (its folder's python/), imported."""
    folder = str(pathlib.Path(plumbago()).resolve().parent / "python")
    if folder not in sys.path:
        sys.path.insert(0, folder)
    import plumbago as pg
    return pg


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


def lines_counts(scene, backend="gpu"):
    """The lines of `scene` (a file under the repository root, or builtin:NAME) at its camera
    (Scene.lines): its paths (feature lines and decals), how many show (a visible run or
    more), and the visible runs the strokes draw."""
    paths = module().Scene(scene if scene.startswith("builtin:") else str(ROOT / scene)).lines(backend)
    return dict(paths=len(paths), shown=sum(1 for p in paths if p["runs"]),
                visible_runs=sum(len(p["runs"]) for p in paths))


TORUS_FACES_AT_1 = 9216  # faces of the procedural torus at resolution 1 (bench's count says what was drawn)


def torus_resolution(faces):
    """The procedural torus' resolution for about `faces` faces (TORUS_FACES_AT_1 x resolution^2)."""
    return math.sqrt(faces / TORUS_FACES_AT_1)


def result(j, backend):
    return next(r for r in j["results"] if r["backend"] == backend)


def param_default(key):
    return module().params()[key]["default"]


def param_range(key):
    p = module().params()[key]
    return float(p["min"]), float(p["max"])


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


def cpu_clock():
    """What others_cpu compares: the machine's busy CPU seconds (/proc/stat), this process's
    and its finished children's, and the wall clock."""
    with open("/proc/stat") as f:
        ticks = [int(x) for x in f.readline().split()[1:9]]
    busy = (sum(ticks) - ticks[3] - ticks[4]) / os.sysconf("SC_CLK_TCK")  # less idle and iowait
    own = sum(getattr(resource.getrusage(who), t) for who in (resource.RUSAGE_SELF, resource.RUSAGE_CHILDREN)
              for t in ("ru_utime", "ru_stime"))
    return busy, own, time.time()


def others_cpu(since):
    """The share of the machine's CPU time (0 to 1, all cores) that other processes used since
    cpu_clock() gave `since`: how much they can have disturbed a timing."""
    busy, own, wall = cpu_clock()
    return max(0.0, (busy - since[0] - (own - since[1])) / ((wall - since[2]) * os.cpu_count()))


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


def pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def log(*a):
    print(*a, flush=True)


def save_figure(fig, out, name):
    """Lays out `fig`, writes it as out/name at the studies' resolution and closes it."""
    fig.tight_layout()
    fig.savefig(pathlib.Path(out) / name, dpi=110)
    pyplot().close(fig)


def scene_files(patterns):
    """Scene files named by `patterns` (paths or globs under the repository root; builtin:NAME
    kept as is), each once, in order; the schema is not a scene."""
    out = []
    for p in patterns:
        found = [p] if p.startswith("builtin:") else sorted(
            str(pathlib.Path(f).relative_to(ROOT)) if pathlib.Path(f).is_relative_to(ROOT) else f
            for f in glob.glob(str(ROOT / p)))
        if not found:
            raise SystemExit("no scene file matches %s" % p)
        out += [f for f in found if not f.endswith("scene.schema.json") and f not in out]
    return out


def stem(scene):
    return pathlib.Path(scene.replace("builtin:", "builtin_")).stem


def scene_models(scene):
    """The mesh files `scene` reads (absolute; procedural meshes and builtins read none)."""
    if scene.startswith("builtin:"):
        return []
    path = ROOT / scene
    j = json.loads(path.read_text())
    meshes = [j.get("mesh")] + [o.get("mesh") for o in j.get("objects", [])]
    return [str((path.parent / m).resolve()) for m in meshes if isinstance(m, str)]


def missing_models(scene):
    return [m for m in scene_models(scene) if not pathlib.Path(m).is_file()]


def scene_inputs(scenes):
    """What a study reads for `scenes`: the scene files and the models that are there (a scene
    whose models are missing is skipped by the study, as the log says)."""
    out = []
    for s in scenes:
        if not s.startswith("builtin:"):
            out += [str(ROOT / s)] + [m for m in scene_models(s) if pathlib.Path(m).is_file()]
    return out


if __name__ == "__main__":  # run-info OUT RENDERER: run_info.json for a study that is not in Python
    import sys
    if len(sys.argv) != 4 or sys.argv[1] != "run-info":
        sys.exit("usage: plumbago_cli.py run-info OUT RENDERER")
    write_run_info(sys.argv[2], machine(sys.argv[3]))
