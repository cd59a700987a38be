"""The recorded benchmarks' tables for pages.py, parsed from files under bench/results/:
`{{spells FILE}}`, `{{ab FILE}}`, `{{gbench FILE [REGEX]}}`, `{{bench_text FILE}}`,
`{{limits FILE}}`, `{{ring FILE}}`. Each table starts with the file it comes from and the date and machine
the file records."""
import re
import statistics

from study_tables import markdown


def lines(c, file):
    return (c.root / "bench" / "results" / file).read_text().splitlines()


def source(file, text):
    return ["From `bench/results/%s`: %s" % (file, text), ""]


def header(c, file):
    """The file's own description: its leading '# ' comment lines."""
    out = []
    for line in lines(c, file):
        if not line.startswith("#"):
            break
        out.append(line.lstrip("# ").strip())
    return " ".join(x for x in out if x)


def spells(c, file):
    """`HH:MM:SS  33.14 ms = 30.2 fps`, one run a line: the spread of the runs."""
    ms = [float(m.group(1)) for m in map(re.compile(r"^\d\d:\d\d:\d\d\s+([\d.]+) ms").match, lines(c, file)) if m]
    q1, med, q3 = statistics.quantiles(ms, n=4, method="inclusive")
    body = [["median", "%.1f" % med, "%.1f" % (1000 / med)],
            ["quartiles", "%.1f / %.1f" % (q1, q3), "%.1f / %.1f" % (1000 / q1, 1000 / q3)],
            ["fastest / slowest run", "%.1f / %.1f" % (min(ms), max(ms)), "%.1f / %.1f" % (1000 / min(ms), 1000 / max(ms))],
            ["runs at 30 fps or more", "%d of %d" % (sum(x <= 1000 / 30 for x in ms), len(ms)), ""]]
    return source(file, header(c, file)) + markdown(["%d runs" % len(ms), "ms a frame", "fps"], body)


AB = re.compile(r"^(\S+)\s+old median\s+([\d.]+) ms \(min\s+([\d.]+)\)\s+new median\s+([\d.]+) ms \(min\s+([\d.]+)\)")


def ab(c, file):
    """The file's last same-sitting A/B section: old against new per scene."""
    sections = []
    for line in lines(c, file):
        if line.startswith("## "):
            sections.append((line[3:], []))
        m = AB.match(line)
        if m and sections:
            sections[-1][1].append(m.groups())
    section, rows = [s for s in sections if "A/B" in s[0]][-1]
    body = [[scene, "%s (%s)" % (o, omin), "%s (%s)" % (n, nmin), "%.1f" % (1000 / float(n)),
             "%.2fx" % (float(o) / float(n))] for scene, o, omin, n, nmin in rows]
    return source(file, header(c, file) + " Section: " + section + ".") + \
        markdown(["scene", "before: median (min) ms", "after: median (min) ms", "after: fps", "speed-up"], body)


GBENCH = re.compile(r"^(BM_\S+)\s+([\d.]+) (\w+)\s+([\d.]+) (\w+)\s+(\d+)\s*(.*)$")


def gbench(c, file, pattern="."):
    """A Google Benchmark console output (its first run, where the file holds several):
    each benchmark matching `pattern`."""
    text = lines(c, file)
    first = next(i for i, x in enumerate(text) if GBENCH.match(x))
    text = text[:next((i for i in range(first, len(text)) if text[i].startswith("## ")), len(text))]
    date = next((x for x in text if re.match(r"^\d{4}-\d\d-\d\dT", x)), "no date in the file")
    run_on = next((x for x in text if x.startswith("Run on")), "machine not recorded")
    load = next((x for x in text if x.startswith("Load Average")), "")
    body = [[m.group(1), "%s %s" % (m.group(2), m.group(3)), "%s %s" % (m.group(4), m.group(5)), m.group(6),
             m.group(7).strip()] for m in map(GBENCH.match, text) if m and re.search(pattern, m.group(1))]
    return source(file, "%s, %s%s." % (date, run_on, ", " + load if load else "")) + \
        markdown(["benchmark", "time", "CPU", "iterations", "counters / label"], body)


BENCH_TEXT = re.compile(r"^(\S+) \[(\w+)\]: ([\d.]+) ms/frame = ([\d.]+) fps")
STAGE = re.compile(r"^  (\S+)\s+([\d.]+) ms$")


def bench_text(c, file):
    """`plumbago bench` text output: each scene and backend's frame and passes."""
    text, body = lines(c, file), []
    renderer = next((x.split(":", 1)[1].strip() for x in text if x.startswith("renderer:")), "not recorded")
    for line in text:
        m = BENCH_TEXT.match(line)
        if m:
            body.append([m.group(1), m.group(2), m.group(3), m.group(4), ""])
        elif body and STAGE.match(line):
            body[-1][4] += ("%s%s %s" % ((", " if body[-1][4] else "",) + STAGE.match(line).groups()))
    return source(file, "`plumbago bench` text output, GL renderer %s; the date is in the file's name." % renderer) + \
        markdown(["scene", "backend", "ms a frame", "fps", "passes (ms, GL timer)"], body)


RING = re.compile(r"^old (BM_\S+) min ([\d.]+)\s+new ([\d.]+)|^old (BM_\S+) ([\d.]+)\s+new ([\d.]+)")


def ring(c, file):
    """`old BENCHMARK min X  new Y` lines: old against new, one line a round."""
    runs = {}
    for m in map(RING.match, lines(c, file)):
        if m:
            name, old, new = (m.group(1), m.group(2), m.group(3)) if m.group(1) else m.group(4, 5, 6)
            runs.setdefault(name, []).append((float(old), float(new)))
    body = [[name, str(len(r)), "%g -> %g" % (min(o for o, _ in r), min(n for _, n in r)),
             "%g -> %g" % (statistics.median(o for o, _ in r), statistics.median(n for _, n in r))]
            for name, r in runs.items()]
    return source(file, header(c, file)) + markdown(["benchmark", "rounds", "best ms", "median ms"], body)


LIMIT_PASS = re.compile(r"^  (\S+)\s+([\d.]+) ms =\s+([\d.]+) x (\w+)$")
PROBE = re.compile(r"^  probe (\w+)\s+([\d.]+) ms$")
PROBES = ["fullscreen", "fetch3x3", "compute", "compute3x3", "raster", "readback"]


def limits(c, file):
    """`plumbago bench --limits` text output: the probes of each scene, then each GPU pass as
    a multiple of its probe."""
    text, probes, passes, scene = lines(c, file), [], [], None
    renderer = next((x.split(":", 1)[1].strip() for x in text if x.startswith("renderer:")), "not recorded")
    for line in text:
        if BENCH_TEXT.match(line):
            scene = BENCH_TEXT.match(line).group(1)
            probes.append([scene] + [""] * len(PROBES))
        elif PROBE.match(line) and PROBE.match(line).group(1) in PROBES:
            probes[-1][1 + PROBES.index(PROBE.match(line).group(1))] = PROBE.match(line).group(2)
        elif LIMIT_PASS.match(line):
            m = LIMIT_PASS.match(line)
            passes.append([scene, m.group(1), m.group(2), m.group(4), m.group(3)])
    return source(file, "`plumbago bench --limits` text output, GL renderer %s; the date is in the file's name."
                  % renderer) + markdown(["scene"] + ["%s (ms)" % p for p in PROBES], probes) + [""] + \
        markdown(["scene", "pass", "ms", "probe", "multiple of the probe"], passes)


KINDS = {"spells": spells, "ab": ab, "gbench": gbench, "bench_text": bench_text, "limits": limits, "ring": ring}
