"""The studies' tables for pages.py, read from RESULTS/<study>/ (results.csv, run_info.json,
the figures): `{{study NAME}}`, `{{headline}}`, `{{figure NAME FILE}}`, `{{paper_claims}}`;
`{{study NAME RECORDED}}` and `{{paper_claims RECORDED}}` read a run recorded on another
machine from bench/results/RECORDED/ instead."""
import collections
import json
import math
import os
import pathlib
import sys

Context = collections.namedtuple("Context", "root results reports")
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "lib"))
import plumbago_cli as pc  # noqa: E402


def ms(x):
    return "%.1f" % x


def ratio(x):
    return "%.2fx" % x


def pct(x):
    return "-" if math.isnan(x) else "%.2f%%" % (100 * x)


def sci(x):
    return "%.1e" % x


def val(x):
    return "%g" % x if isinstance(x, float) else str(x)


def size(r):
    return "%dx%d" % (r["width"], r["height"])


def col(header, key, fmt=val):
    return header, (lambda r: fmt(r[key]))


# Per study: its table's columns, the headline's question, and the columns whose range the
# headline gives for time and for error.
STUDIES = {
    "reference_vs_gpu": dict(
        question="GPU backend against the CPU reference, per scene",
        columns=[col("scene", "scene"), col("faces", "faces"), ("size", size), col("GPU ms", "gpu_ms", ms),
                 col("reference ms", "reference_ms", ms), col("GPU / reference", "gpu_over_reference", ratio),
                 col("mean abs diff", "mean_abs", pct), col("pixels over tolerance", "share_over_tolerance", pct)],
        time=("gpu_over_reference", ratio, "GPU / reference frame"), error=("mean_abs", pct, "image, mean abs")),
    "contours": dict(
        question="contour copies, distortion grid, shake",
        columns=[col("sweep", "sweep"), col("copies", "copies"), col("grid cell px", "grid_cell"),
                 col("shake px", "shake_amplitude"), col("frame ms", "frame_ms", ms),
                 col("/ default (same job)", "ratio_to_default", ratio), col("grid ms", "distortion_ms", ms),
                 col("mean abs diff", "mean_abs", pct), col("pixels over tolerance", "share_over_tolerance", pct)],
        time=("ratio_to_default", ratio, "frame / default"), error=("mean_abs", pct, "image, mean abs")),
    "interior": dict(
        question="interior: 1-way, 3-way, cross hatching; Gouraud or Phong",
        columns=[col("scene", "scene"), col("variant", "variant"), col("shading", "shading"),
                 col("frame ms", "frame_ms", ms), col("/ contours only", "ratio_to_contours_only", ratio),
                 col("image mean abs", "color_mean_abs", pct), col("intensity mean abs", "intensity_mean_abs", pct),
                 col("darkness mean abs", "interior_darkness_mean_abs", pct)],
        time=("ratio_to_contours_only", ratio, "frame / contours only"), error=("color_mean_abs", pct, "image")),
    "gbuffer_precision": dict(
        question="G-buffer normal storage and edge normals",
        columns=[col("scene", "scene"), col("normals", "normals"), col("format", "normal_format"),
                 col("frame ms", "frame_ms", ms), col("/ RGBA32F", "frame_ratio_to_rgba32f", ratio),
                 col("G-buffer / RGBA32F", "gbuffer_ratio_to_rgba32f", ratio),
                 col("edge mean abs vs CPU", "edge_mean_abs_vs_cpu", sci),
                 col("edge mean abs vs RGBA32F", "edge_mean_abs_vs_rgba32f", sci)],
        time=("frame_ratio_to_rgba32f", ratio, "frame / RGBA32F"),
        error=("edge_mean_abs_vs_cpu", sci, "edge map vs CPU")),
    "pencil_textures": dict(
        question="pencil stack: layers and tile size",
        columns=[col("layers", "layers"), col("tile", "tile"), col("frame ms", "frame_ms", ms),
                 col("/ default", "ratio_to_default", ratio), col("generation ms", "generation_ms", ms),
                 col("stack MiB", "stack_mib", val), col("image mean abs", "color_mean_abs", pct),
                 col("darkness mean abs", "darkness_mean_abs", pct)],
        time=("ratio_to_default", ratio, "frame / default"), error=("darkness_mean_abs", pct, "darkness")),
    "scaling": dict(
        question="mesh size (faces) and image size (pixels)",
        columns=[col("sweep", "sweep"), col("backend", "backend"), col("faces", "faces"), ("size", size),
                 col("frame ms", "frame_ms", ms), col("/ smallest", "ratio_to_smallest", ratio)],
        time=("ratio_to_smallest", ratio, "frame / smallest of its sweep"), error=None),
    "stroke_scaling": dict(
        question="strokes against faces (Kalnins et al. 2002)",
        columns=[col("sweep", "sweep"), col("backend", "backend"), col("faces", "faces"), col("decals", "drawn"),
                 col("strokes that show", "shown"), col("visible runs", "visible_runs"),
                 col("frame ms", "frame_ms", ms), col("/ smallest", "ratio_to_smallest", ratio),
                 col("stroke pass ms", "stage:stroke", ms), col("others' CPU share", "others_cpu", pct)],
        time=("ratio_to_smallest", ratio, "frame / smallest of its sweep"), error=None),
    "curvature_accuracy": dict(
        question="curvature: tensor radius, jet degree, on analytic surfaces",
        columns=[col("surface", "surface"), col("meshing", "meshing"), col("vertices", "vertices"),
                 col("method", "method"), col("setting", "setting"), col("ms", "ms", ms),
                 col("direction deg", "direction_deg", lambda x: "%.2f" % x), col("k_min", "k_min_rel", pct),
                 col("k_max", "k_max_rel", pct)],
        time=("ms", ms, "ms"), error=("k_max_rel", pct, "k_max, median relative")),
    "stroke_visibility": dict(
        question="stroke visibility by the ID image, against Embree rays",
        columns=[col("scene", "scene"), col("swept", "swept"), col("value", "value"),
                 col("false visible", "false_visible", pct), col("false hidden", "false_hidden", pct),
                 col("silhouettes: false visible", "silhouette_false_visible", pct),
                 col("silhouettes: false hidden", "silhouette_false_hidden", pct),
                 col("creases: false visible", "crease_false_visible", pct),
                 col("creases: false hidden", "crease_false_hidden", pct),
                 col("ID image ms", "id_image_ms", ms), col("visibility ms", "visibility_ms", ms)],
        time=("visibility_ms", ms, "visibility ms"), error=("false_hidden", pct, "false hidden")),
    "shower_door": dict(
        question="shower door: coherence of each sketchy style over an orbit (not timed)",
        columns=None, time=None, error=("field_coherence", "%.3f".__mod__, "field coherence, per pair")),
    "temporal_coherence": dict(
        question="stroke rendering over an orbit: sliding, births, deaths (not timed)",
        columns=None, time=None, error=("image_coherence", "%.3f".__mod__, "stroke layer coherence, per pair")),
}


def rows(c, name):
    return pc.read_csv(c.results / name / "results.csv")


def run_of(c, name):
    """Which run, machine and date: from run_info.json."""
    return run_in(c, c.results / name)


def run_in(c, folder):
    """Which run, machine and date: from the folder's run_info.json."""
    path = folder / "run_info.json"
    where = os.path.relpath(folder, c.root)
    if not path.exists():
        return "`%s/results.csv`; its run wrote no run_info.json, so run, machine and date are not recorded" % where
    i = json.loads(path.read_text())
    when = i["date"] + (" to %s" % i["finished"] if i.get("finished", i["date"]) != i["date"] else "")
    machine = "; ".join(i["machines"]) if "machines" in i else "%s (%d threads), %s" % (i["cpu"], i["threads"],
                                                                                        i["renderer"])
    return "`%s/`, run of %s on %s, load average %s at the start" % (where, when, machine, i["load_average"])


def markdown(header, body):
    return ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)] + \
        ["| " + " | ".join(cells) + " |" for cells in body]


def mean_by(rs, key, value):
    groups = collections.defaultdict(list)
    for r in rs:
        if isinstance(r[value], float) and not math.isnan(r[value]):
            groups[r[key]].append(r[value])
    return {k: sum(v) / len(v) for k, v in groups.items()}


def shower_door_table(rs):
    field, image = mean_by(rs, "mode", "field_coherence"), mean_by(rs, "mode", "image_coherence")
    return markdown(["mode", "frame pairs", "field coherence (mean)", "sketch image coherence (mean)"],
                    [[m, str(sum(r["mode"] == m for r in rs)), "%.3f" % field[m], "%.3f" % image[m]]
                     for m in dict.fromkeys(r["mode"] for r in rs) if m in field])


def temporal_coherence_tables(c):
    sys.path.insert(0, str(c.root / "experiments" / "temporal_coherence"))
    import report
    return report.summary_lines(c.results / "temporal_coherence")


def results_folder(c, name, recorded=None):
    """A study's results: its last run, or a run recorded under bench/results/RECORDED/ (another machine)."""
    return c.root / "bench" / "results" / recorded if recorded else c.results / name


def study(c, name, recorded=None):
    folder = results_folder(c, name, recorded)
    spec, rs = STUDIES[name], pc.read_csv(folder / "results.csv")
    out = ["From " + run_in(c, folder) + ".", ""]
    if name == "shower_door":
        return out + shower_door_table(rs)
    if name == "temporal_coherence":
        return out + temporal_coherence_tables(c)
    out += markdown([h for h, _ in spec["columns"]], [[f(r) for _, f in spec["columns"]] for r in rs])
    if name == "stroke_scaling":
        out += stroke_scaling_fits(folder)
    if name == "scaling":
        slopes = pc.read_csv(folder / "slopes.csv")
        out += ["", "Log-log slope of each stage's ms against faces and against pixels (`slopes.csv`):", ""]
        out += markdown(["backend", "stage", "slope vs faces", "slope vs pixels"],
                        [[s["backend"], s["stage"], "%.2f" % s.get("slope_vs_faces", math.nan),
                          "%.2f" % s.get("slope_vs_pixels", math.nan)] for s in slopes])
    return out


def stroke_scaling_fits(folder):
    fits = pc.read_csv(folder / "fits.csv")
    table1 = pc.read_csv(folder / "table1.csv")
    return ["", "Linear fits, per pass and for the frame (`fits.csv`):", ""] + markdown(
        ["backend", "pass", "ms per 1K strokes", "ms per 100K faces"],
        [[f["backend"], f["quantity"], "%.2f" % f["ms_per_1k_strokes"], "%.2f" % f["ms_per_100k_faces"]]
         for f in fits]) + ["", "The frame fits at the sizes of Kalnins et al.'s Table 1 (`table1.csv`):", ""] + \
        markdown(["backend", "their scene", "faces", "strokes", "strokes ms", "faces ms", "larger"],
                 [[t["backend"], t["scene"], val(t["faces"]), val(t["strokes"]), ms(t["strokes_ms"]),
                   ms(t["faces_ms"]), t["larger"]] for t in table1])


def span(rs, key, fmt):
    values = [r[key] for r in rs if isinstance(r.get(key), float) and not math.isnan(r[key])]
    return "%s to %s" % (fmt(min(values)), fmt(max(values))) if values else "-"


def headline(c):
    body = []
    for name, spec in STUDIES.items():
        if not (c.results / name / "results.csv").exists():
            continue
        rs = rows(c, name)
        cells = [spec["question"], "[%s](#%s)" % (name, name.replace("_", "-"))]
        for part in (spec["time"], spec["error"]):
            cells.append("%s: %s" % (part[2], span(rs, part[0], part[1])) if part else "-")
        body.append(cells)
    return markdown(["question", "study", "time (range over the sweep)", "error (range over the sweep)"], body)


def figure(c, name, file):
    return ["![%s](%s)" % (name, os.path.relpath(c.results / name / file, c.reports))]


def paper_claims(c, recorded=None):
    sys.path.insert(0, str(c.root / "experiments" / "paper_claims"))
    import run as claims
    folder = results_folder(c, "paper_claims", recorded)
    j = json.loads((folder / "paper_claims.json").read_text())
    return ["From " + run_in(c, folder) + ".", "", "machine: %s; GL renderer: %s" % (j["machine"], j["renderer"]),
            ""] + claims.table(j)


KINDS = {"study": study, "headline": lambda c: headline(c),
         "figure": figure, "paper_claims": paper_claims}


def study_rows(c, name, *conditions):
    """The rows of a study whose columns have the given values (`key=value`)."""
    spec, wanted = STUDIES[name], [x.split("=", 1) for x in conditions]
    rs = [r for r in rows(c, name) if all(val(r[k]) == v for k, v in wanted)]
    return ["From " + run_of(c, name) + ", rows with %s." % ", ".join(conditions), ""] + \
        markdown([h for h, _ in spec["columns"]], [[f(r) for _, f in spec["columns"]] for r in rs])


KINDS["study_rows"] = study_rows
