"""docs/curvature.md's summaries: `{{curvature_summary STUDY BENCH_FILE}}`, each estimator's
accuracy on the analytic surfaces (the study's results.csv) next to its time on the shared
models (a Google Benchmark run of bench/curvature_bench.cpp under bench/results/), and
`{{direction_summary STUDY}}`, how the direction field turns, literal against smoothed
(experiments/direction_field)."""
import math
import re

import bench_tables
from study_tables import markdown, rows, run_of

# (label, the study's method and setting, the benchmark's variant)
METHODS = [("default (`auto`)", "default", 0.0, "auto_default"),
           ("1-ring (`--radius 0`)", "tensor", 0.0, "tensor_1ring"),
           ("ball, exact (the tensor's default)", "tensor", 0.01, "tensor_default"),
           ("ball, approximate (`ball_clip=approximate`)", "approximate", 0.01, "tensor_approximate_ball"),
           ("jet, degree 2 (`--method jet`)", "jet", 2.0, "jet_default")]
MODELS = ["fandisk", "stanford-bunny", "ogre"]


def span(values, fmt):
    values = [v for v in values if not math.isnan(v)]
    if not values:
        return "-"
    lo, hi = fmt(min(values)), fmt(max(values))
    return lo if lo == hi else "%s-%s" % (lo, hi)


def percent(x):
    return "%.2g%%" % (100 * x) if x >= 0.001 else "<0.1%"


def accuracy(rs, method, setting):
    """Per meshing: the median k error (mean of k_min and k_max) and the share far off, each a
    range over the surfaces; the median direction error on the irregular meshes."""
    def sel(meshing):
        return [r for r in rs if r["method"] == method and r["setting"] == setting and r["meshing"] == meshing]
    k = {m: span([0.5 * (r["k_min_rel"] + r["k_max_rel"]) for r in sel(m)], percent) for m in ("regular", "irregular")}
    return [k["regular"], k["irregular"], span([r["far_off"] for r in sel("strong")], percent),
            span([r["direction_deg"] for r in sel("irregular")], lambda x: "%.2f°" % x)]


def timings(c, file):
    """benchmark name -> (time in ms, counters)."""
    out = {}
    for m in map(bench_tables.GBENCH.match, bench_tables.lines(c, file)):
        if m:
            scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[m.group(3)]
            out[m.group(1).replace("/manual_time", "")] = (float(m.group(2)) * scale, m.group(7))
    return out


def cost(times, variant):
    small = " / ".join("%.0f" % times[k][0] if (k := "BM_Curvature/%s/%s" % (model, variant)) in times else "-"
                       for model in MODELS)
    big = next((v for k, v in times.items() if k.startswith("BM_Curvature/bunny-1M/%s" % variant)), None)
    per_million = re.search(r"s_per_1M_vertices=([\d.]+)s", big[1]) if big else None
    return [small, "%.1f s" % float(per_million.group(1)) if per_million else "-"]


def curvature_summary(c, study, file):
    rs, times = rows(c, study), timings(c, file)
    body = [[label] + accuracy(rs, method, setting) + cost(times, variant)
            for label, method, setting, variant in METHODS]
    header = ["method", "k error, regular", "k error, irregular", "> 50% off, strongly irregular",
              "direction, irregular", "ms: " + " / ".join(MODELS), "bunny-1M, per 1M vertices"]
    return ["Accuracy from " + run_of(c, study) + "; time from `bench/results/%s` (%s)." %
            (file, bench_tables.header(c, file) or "Google Benchmark"), ""] + markdown(header, body)


REGIONS = ["propagated", "border", "reliable", "all"]


def turning(rs, mesh, meshing, region):
    """`literal -> smoothed` share of the region's edges turning by more than 20 degrees."""
    by = {r["setting"]: r for r in rs if (r["mesh"], r["meshing"], r["region"]) == (mesh, meshing, region)}
    if not by or not by["literal"]["edges"]:
        return "-"
    return "%.1f%% -> %.1f%%" % (100 * by["literal"]["over_20"], 100 * by["smoothed"]["over_20"])


def direction_summary(c, study):
    rs = rows(c, study)
    meshes = list(dict.fromkeys((r["mesh"], r["meshing"]) for r in rs))
    body = [["%s%s" % (mesh, "" if meshing == "model" else ", " + meshing)] +
            [turning(rs, mesh, meshing, region) for region in REGIONS] for mesh, meshing in meshes]
    return ["From " + run_of(c, study) + "; edges turning by more than 20 degrees, literal -> smoothed.", ""] + \
        markdown(["mesh"] + ["%s edges" % region for region in REGIONS], body)


KINDS = {"curvature_summary": curvature_summary, "direction_summary": direction_summary}
