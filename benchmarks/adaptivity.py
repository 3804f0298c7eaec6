#!/usr/bin/python3
"""Adaptive refinement against uniform refinement and the hand-graded
meshes: collapse load against DoFs and time, per scene.

Scenes (each its file's coarse mesh, method and programme):
- Prandtl's flexible strip footing (prm/prandtl-strip-footing-adaptive.prm,
  a uniform mesh of 72 cells; the collapse bracketed to 0.1%), (2 + pi) c;
- the rough rigid circular footing by harmonic 0, pushed down (prm/circular-
  footing-rigid-settlement-adaptive.prm, 68 cells), 6.05 c (Eason and
  Shield);
- the smooth pile section on interface elements (prm/circular-inclusion-
  zero-thickness-adaptive.prm, 6 cells per quarter circle), 9.181 c D;
- Case 2 on a thin layer of aspect ratio 100 (prm/case2-strip-footing-
  adaptive.prm, the paper's coarse mesh) and on interface elements
  (prm/case2-strip-footing-zero-thickness-adaptive.prm, 19 cells), L C_w;
- with --3d, the rough rigid circular footing in 3D (prm/circular-footing-
  rigid-3d-adaptive.prm, a quarter body of 216 cells) against the
  hand-tuned mesh of prm/circular-footing-rigid-3d.prm, 6.05 c.

Per scene three series: the adaptive cycles (the scene's marking of the
plastic work), the uniform refinement of the same coarse mesh, and the
hand-graded meshes: the scene file's own and finer ones of its grading.
Each row is one cycle's (or one mesh's) run: cells, DoFs, equations,
collapse load, its error, the run's wall time and, for the adaptive series,
the time of all cycles up to it (each cycle re-solves the path, so reaching
that mesh costs them all). One run each: the times are single runs on a
machine that did nothing else.

    /usr/bin/python3 -m benchmarks.adaptivity [--quick] [--3d] [--output DIR] [--page]

--quick: Prandtl only, 3 adaptive cycles and 2 uniform ones, no hand-graded
meshes (CI). The targets (the issue's): Prandtl within 0.5% with at most a
quarter of the equations of the first uniform mesh within it and in less
time; the rough footing within 1% with at most a quarter of those of the
first hand-graded mesh within it; the pile section and Case 2 within 1%
with fewer than the first hand-graded (for the layer: uniform) mesh
within it; the 3D footing within 1% with fewer DoFs, in less time, than
the hand-tuned mesh.
Writes DIR/adaptivity.csv and .md (DIR: output/benchmarks), the chart
DIR/adaptivity.png (collapse load over the reference against DoFs, the
series per scene, the reference drawn), and prints the table with the
targets' verdicts; the runs go into DIR/runs/adaptivity-*.
Results are measurements, not tests: quote them with the machine.
"""
import argparse
import csv
import json
import math
import os
import subprocess

from thinlayer_tools import THINLAYER, TOP, cases, overrides

from benchmarks import page

OUT = os.path.join(TOP, "output", "benchmarks")

GRADED = "hand-graded"
# The Adaptivity section at its defaults, as if the file had none: a single
# run on the mesh as given (an entry the file sets means nothing without
# cycles, and the program refuses it).
SINGLE_RUN = ("Adaptivity/Cycles=0", "Adaptivity/Indicator=plastic work",
              "Adaptivity/Marking=bulk", "Adaptivity/Marking fraction=0.5",
              "Adaptivity/Stop tolerance=0.005", "Adaptivity/Maximum DoFs=2000000")

# Per scene: its name, parameter file, coarse geometry and entries every
# run of it takes; the hand-graded meshes (the file's own first, then finer
# ones of the same grading); the target: the first adaptive mesh within
# `error` of the closed form has at most `ratio` times the equations of the
# first mesh of the `against` series within it (and takes less time); the
# marking and its fraction, and the adaptive and uniform cycles. Bulk
# marking where the plastic work spreads over the mechanism; fixed-number
# marking where it concentrates in a few cells (Case 2's layer at the
# footing's edge), where bulk marking refines a handful a cycle and stalls.
SCENES = [
    {"name": "Prandtl's footing", "prm": "prm/prandtl-strip-footing-adaptive.prm",
     "coarse": "half_width=1, width=5, depth=3, n_footing=4, n_side=8, n_depth=6, growth=1",
     "graded": [cases.geometry("prandtl", level) for level in (1, 2, 3)],
     "entries": ("Loading/Collapse resolution=0.001",),
     "error": 0.005, "ratio": 0.25, "against": "uniform",
     "marking": "bulk", "fraction": 0.6, "cycles": 6, "uniform": 3},
    {"name": "rough rigid circular footing (harmonic 0)",
     "prm": "prm/circular-footing-rigid-settlement-adaptive.prm",
     "coarse": "half_width=1, width=5, depth=3, aspect_ratio=10, n_footing=4, n_side=6, "
               "n_depth=5, interface_beyond_footing=1, refinement=1",
     "graded": ["half_width=1, width=5, depth=3, aspect_ratio=10, n_footing=8, n_side=12, "
                "n_depth=10, interface_beyond_footing=1, refinement=%d" % r for r in (1, 2, 3)],
     "entries": (), "error": 0.01, "ratio": 0.25, "against": GRADED,
     "marking": "bulk", "fraction": 0.6, "cycles": 7, "uniform": 3},
    {"name": "smooth pile section, interface elements",
     "prm": "prm/circular-inclusion-zero-thickness-adaptive.prm",
     "coarse": "radius=1, thickness=0.02, outer=20, n_around=6, n_radial=10, growth=1.3, "
               "zero_thickness=1",
     "graded": ["radius=1, thickness=0.02, outer=20, n_around=%d, n_radial=%d, growth=1.2, "
                "zero_thickness=1" % (n, r) for n, r in ((12, 20), (24, 40))],
     "entries": (), "error": 0.01, "ratio": 1.0, "against": GRADED,
     "marking": "bulk", "fraction": 0.6, "cycles": 6, "uniform": 2},
    {"name": "Case 2, thin layer (aspect ratio 100)", "prm": "prm/case2-strip-footing-adaptive.prm",
     "coarse": "half_width=1, width=5, depth=3, aspect_ratio=100, n_footing=8, n_side=12, "
               "n_depth=10, interface_beyond_footing=1",
     "graded": [], "entries": (), "error": 0.01, "ratio": 1.0, "against": "uniform",
     "marking": "fixed number", "fraction": 0.25, "cycles": 4, "uniform": 2},
    {"name": "Case 2, interface elements",
     "prm": "prm/case2-strip-footing-zero-thickness-adaptive.prm",
     "coarse": "half_width=1, width=5, depth=3, n_footing=2, n_side=3, n_depth=3, "
               "zero_thickness=1",
     "graded": ["half_width=1, width=5, depth=3, n_footing=8, n_side=12, n_depth=10, "
                "zero_thickness=1"],
     "entries": (), "error": 0.01, "ratio": 1.0, "against": GRADED,
     "marking": "fixed number", "fraction": 0.25, "cycles": 3, "uniform": 1},
]
# The 3D footing (--3d): the hand-tuned mesh alone takes minutes.
SCENE_3D = {
    "name": "rough rigid circular footing, 3D", "prm": "prm/circular-footing-rigid-3d-adaptive.prm",
    "coarse": "sector=90, footing=0, half_width=1, width=5, depth=3, n_around=2, n_footing=2, "
              "n_side=6, n_depth=6, growth=1.3",
    "graded": ["sector=90, footing=0, half_width=1, width=5, depth=3, n_around=4, n_footing=4, "
               "n_side=16, n_depth=16, growth=1.3"],
    "entries": (), "error": 0.01, "ratio": 1.0,
    "against": GRADED, "marking": "bulk", "fraction": 0.3, "cycles": 7, "uniform": 1}
FIELDS = ["scene", "series", "cycle", "cells", "dofs", "equations", "outcome",
          "collapse_load", "reference_load", "relative_error", "wall_seconds",
          "cumulative_seconds"]


def run(prm, entries, directory):
    """thinlayer PRM with ENTRIES into DIRECTORY, without fields; its
    summary.json."""
    command = [THINLAYER, os.path.join(TOP, prm)] + overrides(
        list(entries) + ["Output/Directory=" + directory, "Output/Write VTU=false",
                         "Output/Print timing=false"])
    if subprocess.run(command, cwd=TOP, stdout=subprocess.DEVNULL).returncode not in (0, 4):
        raise SystemExit("adaptivity: %s failed (its error above)" % prm)
    with open(os.path.join(directory, "summary.json")) as f:
        return json.load(f)


def rows_of(scene, series, summary):
    """The rows of one series: its cycles (an adaptive run's summary) or
    its single run."""
    reference = summary.get("reference_load")
    cycles = (summary.get("adaptivity") or {}).get("cycles") or [
        {"cycle": 0, "cells": summary["cells"], "dofs": summary["dofs"],
         "equations": summary["equations"], "outcome": summary["outcome"],
         "collapse_load": summary["collapse_load"],
         "relative_error": summary["relative_error"],
         "wall_seconds": summary["wall_seconds"]}]
    rows, cumulative = [], 0.0
    for c in cycles:
        cumulative += c["wall_seconds"] or 0.0
        rows.append({"scene": scene, "series": series, "cycle": c["cycle"],
                     "cells": c["cells"], "dofs": c["dofs"], "equations": c["equations"],
                     "outcome": c["outcome"], "collapse_load": c["collapse_load"],
                     "reference_load": reference, "relative_error": c["relative_error"],
                     "wall_seconds": c["wall_seconds"],
                     "cumulative_seconds": cumulative if series == "adaptive"
                     else c["wall_seconds"]})
    return rows


def measure(scenes, quick, output):
    rows = []
    for scene in scenes:
        name, prm, entries = scene["name"], scene["prm"], list(scene["entries"])
        tag = prm.split("/")[-1].replace(".prm", "")
        base = entries + ["Adaptivity/Stop tolerance=0"]
        adaptive_cycles, uniform_cycles = (3, 2) if quick else (scene["cycles"],
                                                                scene["uniform"])
        summary = run(prm, base + ["Mesh/Geometry parameters=" + scene["coarse"],
                                   "Adaptivity/Cycles=%d" % adaptive_cycles,
                                   "Adaptivity/Marking=" + scene["marking"],
                                   "Adaptivity/Marking fraction=%g" % scene["fraction"]],
                      os.path.join(output, "runs", "adaptivity-%s-adaptive" % tag))
        rows += rows_of(name, "adaptive", summary)
        summary = run(prm, base + ["Mesh/Geometry parameters=" + scene["coarse"],
                                   "Adaptivity/Cycles=%d" % uniform_cycles,
                                   "Adaptivity/Marking=uniform",
                                   # No fraction for uniform marking: the
                                   # default, as if left out.
                                   "Adaptivity/Marking fraction=0.5"],
                      os.path.join(output, "runs", "adaptivity-%s-uniform" % tag))
        rows += rows_of(name, "uniform", summary)
        if quick:
            continue
        for k, geometry in enumerate(scene["graded"]):
            summary = run(prm, entries + list(SINGLE_RUN)
                          + ["Mesh/Geometry parameters=" + geometry],
                          os.path.join(output, "runs", "adaptivity-%s-graded-%d" % (tag, k)))
            for row in rows_of(name, GRADED, summary):
                row["cycle"] = k
                rows.append(row)
    return rows


def error(row):
    value = row["relative_error"]
    return value if value is not None and math.isfinite(value) else math.nan


def verdicts(scenes, rows):
    """Per scene: the first adaptive mesh within the scene's error of the
    closed form against the first mesh of its comparison series within it:
    equations (at most the scene's ratio of them) and time (less)."""
    lines = []
    for scene in scenes:
        name, target, against = scene["name"], scene["error"], scene["against"]
        here = [r for r in rows if r["scene"] == name]
        what = "within %.1f%%: at most %s the equations of the first %s mesh within it, " \
               "in less time" % (100 * target, "%g times" % scene["ratio"], against)

        def first(series):
            within = [r for r in here if r["series"] == series and abs(error(r)) <= target]
            return within[0] if within else None

        if not any(r["series"] == against for r in here):
            lines.append("| %s | %s | the %s meshes not run (--quick) | not run |"
                         % (name, what, against))
            continue
        a, other = first("adaptive"), first(against)
        if a is None:
            lines.append("| %s | %s | no adaptive cycle came within it | missed |" % (name, what))
            continue
        measured = "adaptive cycle %d: %d equations (%+.2f%%), %.1f s with the cycles before it" \
            % (a["cycle"], a["equations"], 100 * error(a), a["cumulative_seconds"])
        if other is None:
            lines.append("| %s | %s | %s; no %s mesh within it | met |"
                         % (name, what, measured, against))
            continue
        ratio = a["equations"] / other["equations"]
        met = ratio <= scene["ratio"] and a["cumulative_seconds"] < other["wall_seconds"]
        lines.append("| %s | %s | %s; %s: %d equations (%+.2f%%), %.1f s; ratio %.2f | %s |"
                     % (name, what, measured, against, other["equations"], 100 * error(other),
                        other["wall_seconds"], ratio, "met" if met else "missed"))
    return lines


def table(rows):
    lines = ["| scene | series | cycle | cells | DoFs | equations | outcome | collapse load | "
             "error | wall s | s to this mesh |", "|" + "---|" * 11]
    for r in rows:
        load = r["collapse_load"]
        lines.append("| %s | %s | %d | %d | %d | %d | %s | %s | %s | %.2f | %.2f |" % (
            r["scene"], r["series"], r["cycle"], r["cells"], r["dofs"], r["equations"],
            r["outcome"], "%.4f" % load if load is not None else "-",
            "%+.3f%%" % (100 * error(r)) if math.isfinite(error(r)) else "-",
            r["wall_seconds"], r["cumulative_seconds"]))
    return lines


def chart(scenes, rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    names = [s["name"] for s in scenes if any(r["scene"] == s["name"] for r in rows)]
    fig, axes = plt.subplots(1, len(names), figsize=(4.2 * len(names), 3.6), squeeze=False)
    styles = {"adaptive": ("o-", "C0"), "uniform": ("s--", "C1"), GRADED: ("^:", "C2")}
    for ax, name in zip(axes[0], names):
        here = [r for r in rows if r["scene"] == name]
        for series, (style, color) in styles.items():
            points = [(r["dofs"], r["collapse_load"] / r["reference_load"]) for r in here
                      if r["series"] == series and r["collapse_load"] is not None]
            if points:
                ax.plot(*zip(*points), style, color=color, label=series, markersize=4)
        ax.axhline(1.0, color="k", linewidth=0.8, label="closed form")
        ax.set_xscale("log")
        ax.set_xlabel("DoFs")
        ax.set_ylabel("collapse load / closed form")
        ax.set_title(name, fontsize=9)
        ax.grid(True, which="both", linewidth=0.3)
    axes[0][0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true",
                        help="Prandtl's footing only, 3 adaptive and 2 uniform cycles")
    parser.add_argument("--output", default=OUT,
                        help="the results directory (default %(default)s)")
    parser.add_argument("--3d", dest="three_d", action="store_true",
                        help="also the 3D footing (its hand-tuned mesh alone takes minutes)")
    page.add_argument(parser)
    arguments = parser.parse_args()
    page.configure(arguments)
    scenes = SCENES[:1] if arguments.quick else SCENES + ([SCENE_3D] if arguments.three_d else [])
    rows = measure(scenes, arguments.quick, arguments.output)
    os.makedirs(arguments.output, exist_ok=True)
    with open(os.path.join(arguments.output, "adaptivity.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=FIELDS)
        writer.writeheader()
        writer.writerows(rows)
    chart(scenes, rows, os.path.join(arguments.output, "adaptivity.png"))
    lines = table(rows) + ["", "Targets:", "", "| scene | target | measured | verdict |",
                           "|---|---|---|---|"] + verdicts(scenes, rows)
    page.write(arguments.output, "adaptivity", "Adaptive refinement", lines)


if __name__ == "__main__":
    main()
