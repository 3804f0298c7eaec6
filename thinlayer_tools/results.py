"""Reading thinlayer's results the way every script should.

history.csv has a row per attempt at a load step: with automatic load
stepping, attempts that failed and were cut back are rows too, and so is
the failed step that ends a run. Curves show converged, accepted states
only (states(), below); failures are marked apart (failures()). A run has
a collapse load only where its outcome is "collapse" (or, under prescribed
displacement, where it reached a plateau): collapse_load() is None
otherwise, and no error is computed from it.
"""
import csv
import json
import math
import os


MANIFEST = "manifest.txt"


def record(path):
    """Enter PATH, a file a thinlayer script wrote into a run's or sweep's
    directory (a chart, a table), in that directory's manifest.txt, as
    thinlayer does its own files: a later run replaces a directory only
    while everything in it is listed there, unchanged, and refuses one
    with anything else. Where the directory has no manifest (it is no run
    of thinlayer's), nothing is recorded."""
    directory = os.path.dirname(os.path.abspath(path))
    manifest = os.path.join(directory, MANIFEST)
    if not os.path.isfile(manifest):
        return
    digest = 14695981039346656037
    with open(path, "rb") as f:
        for byte in f.read():
            digest = ((digest ^ byte) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
    name = os.path.basename(path)
    with open(manifest) as f:
        lines = [line for line in f
                 if line.startswith("#") or line.rstrip("\n").split(" ", 2)[2:] != [name]]
    lines.append("%016x %d %s\n" % (digest, os.path.getsize(path), name))
    with open(manifest, "w") as f:
        f.writelines(lines)


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def history(directory):
    """Every row of DIRECTORY/history.csv."""
    return read_csv(os.path.join(directory, "history.csv"))


def loading_history(directory):
    """The rows of DIRECTORY/history.csv of the phase its summary's outcome
    is of (the last one run: the loading or the strength reduction, or the
    initial state where that ended the run), and the (displacement, load)
    that phase starts from: (0, 0) for the first phase."""
    rows = history(directory)
    path = os.path.join(directory, "summary.json")
    if not os.path.exists(path):
        return rows, (0.0, 0.0)
    with open(path) as f:
        s = json.load(f)
    phase = s.get("phase", "loading")
    start = (0.0, 0.0) if phase == "initial state" else \
        (number(s.get("initial_displacement", 0)), number(s.get("initial_load", 0)))
    return [r for r in rows if r.get("phase", "loading") == phase], start


def states(rows):
    """The accepted, converged states: what a load-displacement curve shows."""
    return [r for r in rows if r["converged"] == "1" and r.get("accepted", "1") == "1"]


def failures(rows):
    """The attempts that ended in no accepted state and were not retried:
    failed ones accepted as they were (Solver/Continue after failure), and
    those after the last accepted state (the step that ended the run,
    failed or converged on the mechanism, and a probe beyond it)."""
    last = max([int(r["step"]) for r in rows if r.get("accepted", "1") == "1"], default=0)
    return [r for r in rows
            if (r["converged"] == "0" and r.get("accepted") == "1")
            or (r.get("accepted") == "0" and int(r["step"]) > last)]


def number(text):
    try:
        value = float(text)
    except (TypeError, ValueError):
        return math.nan
    return value


def collapse_detected(summary_row):
    """Whether a run (a sweep.csv row or a summary.json) ended in a collapse."""
    return summary_row.get("outcome") == "collapse"


def collapse_load(summary_row):
    """The run's collapse load, or None where it has none."""
    value = number(summary_row.get("collapse_load"))
    return value if math.isfinite(value) else None


def collapse_error(summary_row):
    """The collapse load's error against the reference, or None."""
    load, reference = collapse_load(summary_row), number(summary_row.get("reference_load"))
    if load is None or not math.isfinite(reference):
        return None
    return (load - reference) / reference


def swept_names(rows):
    """The swept names of a sweep.csv: the columns between run and the figures."""
    columns = list(rows[0].keys())
    return columns[1:columns.index("parameter_file")]


def parameters(directory, section):
    """{entry: value} of one top-level @p section of the parameters.prm a
    run wrote (every entry, defaults included); {} where it has none."""
    path = os.path.join(directory, "parameters.prm")
    entries, depth, inside = {}, 0, False
    if not os.path.exists(path):
        return entries
    with open(path) as f:
        for line in f:
            text = line.split("#", 1)[0].strip()
            if text.startswith("subsection "):
                depth += 1
                inside = depth == 1 and text[len("subsection "):].strip() == section
            elif text == "end":
                depth -= 1
                inside = inside and depth >= 1
            elif inside and depth == 1 and text.startswith("set "):
                name, _, value = text[4:].partition("=")
                entries[name.strip()] = value.strip()
    return entries


def axis_labels(directory):
    """(load, displacement): what a run's load and displacement columns
    measure, from its Monitors section, for the axes of a chart; a strength
    reduction's load is its factor F."""
    path = os.path.join(directory, "summary.json")
    phase = "loading"
    if os.path.exists(path):
        with open(path) as f:
            phase = json.load(f).get("phase", "loading")
    m = parameters(directory, "Monitors")

    def scaled(text, scale):
        return text if scale in ("", "1") else "%s x %s" % (text, scale)

    def boundary(key):
        id = m.get(key, "?")
        name = parameters(directory, "Boundary " + id).get("Name", "")
        return "boundary %s%s" % (id, " (%s)" % name if name else "")

    measure = m.get("Load measure", "load factor")
    if phase == "strength reduction":
        load = "strength reduction factor F"
    elif measure == "reaction":
        load = scaled("reaction on %s, %s" % (boundary("Load boundary id"),
                                                m.get("Load component", "?")),
                      m.get("Load scale", "1"))
    elif measure == "load factor":
        load = scaled("load factor", m.get("Load scale", "1"))
    else:
        load = scaled("mean stress %s over material %s" % (m.get("Load stress component", "?"),
                                                            m.get("Load material id", "?")),
                      m.get("Load scale", "1"))
    where = ("at (%s)" % m.get("Displacement point", "?")
             if m.get("Displacement measure") == "point"
             else "on " + boundary("Displacement boundary id"))
    displacement = scaled("displacement %s %s" % (m.get("Displacement component", "?"), where),
                          m.get("Displacement scale", "1"))
    return load, displacement
