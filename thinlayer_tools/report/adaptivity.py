"""The report's section on adaptive refinement: benchmarks/adaptivity.py's
cycles against uniform refinement and the hand-graded meshes, with the
verdicts the benchmark computes (its Targets table)."""
import math
import os

from thinlayer_tools import results
from thinlayer_tools.report import figures
from thinlayer_tools.report.page import Section


def benchmark_arguments(quick):
    """benchmarks/adaptivity.py's arguments: Prandtl's footing only, 3
    adaptive and 2 uniform cycles, for --quick; every scene otherwise."""
    return ["--quick"] if quick else []


def targets(directory):
    """The Targets rows of adaptivity.md: (scene, target, measured, verdict)."""
    rows = []
    with open(os.path.join(directory, "adaptivity.md")) as f:
        after = False
        for line in f:
            if line.startswith("Targets:"):
                after = True
            elif after and line.startswith("| ") and not line.startswith("| scene"):
                rows.append([cell.strip() for cell in line.strip().strip("|").split("|")])
    return rows


def sections(runs, quick):
    directory = os.path.join(runs.directory, "benchmarks")
    rows = results.read_csv(os.path.join(directory, "adaptivity.csv"))
    table = [["scene", "series", "cycle", "cells", "DoFs", "equations", "outcome",
              "collapse load", "error", "wall s", "s to this mesh"]]
    for r in rows:
        error = results.number(r["relative_error"])
        load = results.number(r["collapse_load"])
        table.append([r["scene"], r["series"], r["cycle"], r["cells"], r["dofs"],
                      r["equations"], r["outcome"],
                      "%.4f" % load if math.isfinite(load) else "-",
                      "%+.3f%%" % (100 * error) if math.isfinite(error) else "-",
                      "%.2f" % results.number(r["wall_seconds"]),
                      "%.2f" % results.number(r["cumulative_seconds"])])
    verdicts = targets(directory)
    missed = [v for v in verdicts if v[-1] != "met"]
    chart = os.path.join(directory, "adaptivity.png")
    shown = [(figures.embed(chart), "Collapse load over the closed form against DoFs: the "
              "adaptive cycles, uniform refinement of the same coarse mesh and the scene "
              "file's hand-graded mesh; the line at 1 is the closed form.")] \
        if os.path.isfile(chart) else []
    why = ("Each scene runs its load path from a coarse mesh, and again on the mesh refined "
           "where the last run's plastic work was (the scene file's marking: Doerfler's bulk "
           "marking, or a fixed share of the cells where the work concentrates), "
           "cycle after cycle (Adaptivity section); beside it, the same coarse mesh refined "
           "uniformly, and the scene file's mesh graded by hand. Asked: the first adaptive "
           "mesh within the scene's error of the closed form has fewer equations than the "
           "first uniform or hand-graded one within it. %s%s" % (
               "Met." if verdicts and not missed else
               "Missed: " + "; ".join("%s (%s): %s" % (v[0], v[1], v[2]) for v in missed) + "."
               if verdicts else "No target could be judged.",
               " Prandtl's footing only, 3 adaptive and 2 uniform cycles (--quick); the full "
               "report runs the rigid circular footing, the pile section and Case 2 too, and "
               "the hand-graded meshes." if quick else ""))
    return [Section("adaptive-refinement", "Adaptive refinement",
                    "(not in the paper) meshes graded by hand.",
                    "beyond" if verdicts and not missed else "differs", why, rows=table,
                    figures=shown,
                    cost="%.0f s of runs" % sum(results.number(r["wall_seconds"])
                                                for r in rows),
                    paper_value="(not in the paper)",
                    our_value="%d of %d targets met" % (len(verdicts) - len(missed),
                                                        len(verdicts)))]
