#!/usr/bin/python3
"""Runs on several MPI ranks against one: the same Prandtl scene (flexible
strip footing on Tresca soil, (2 + pi) c) at growing meshes, by the paper's
method on its seven fixed steps (TOL 1e-3) and by the default method with
automatic stepping to a 0.5% bracket, on 1, 2 (and with --ranks, more)
ranks. Per run: the outcome and collapse load (they must agree with one
rank's: the outcome identical, the converged loads within 1e-6 relative),
iterations, the median wall time of REPEAT runs, milliseconds per
iteration, the largest peak memory of any rank (summary.json's
peak_memory_mb_per_rank, VmHWM) and of it the loaded program's
(program_memory_mb_per_rank).

    /usr/bin/python3 -m benchmarks.ranks [--repeat 3] [--cells 2048,8192,32768] (or 512, 131072) [--ranks 1,2]
                                         [--methods paper,default]

Writes output/benchmarks/ranks.csv and ranks.md and prints the table.
"""
import argparse
import os
import statistics

from thinlayer_tools import THINLAYER, TOP, mpirun, run_for_summary
from thinlayer_tools.cases import PAPER_FIXED_STEPS, PRANDTL_SIZES
from thinlayer_tools.report.runs import DEFAULT, PAPER

from benchmarks import page

OUT = os.path.join(TOP, "output", "benchmarks")
MESHES = PRANDTL_SIZES
METHODS = [
    ("paper's method, 7 fixed steps", PAPER + PAPER_FIXED_STEPS),
    ("default, automatic stepping", DEFAULT + ("Solver/Tolerance=1e-4",
                                               "Loading/Collapse resolution=0.005")),
]


def run_once(ranks, geometry, entries, directory):
    command = mpirun(ranks) + [THINLAYER, os.path.join(TOP, "prm", "prandtl-strip-footing.prm"),
                               "-s", "Mesh/Geometry parameters=" + geometry,
                               "-s", "Mesh/Maximum cells=200000",
                               "-s", "Output/Directory=" + directory,
                               "-s", "Output/Write VTU=false",
                               "-s", "Output/Print timing=false"]
    for entry in entries:
        command += ["-s", entry]
    return run_for_summary(command, directory)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--cells", default="2048,8192,32768")
    parser.add_argument("--ranks", default="1,2")
    parser.add_argument("--methods", default="paper,default",
                        help="which of the two: paper, default")
    page.add_argument(parser)
    args = parser.parse_args()
    page.configure(args)
    os.makedirs(OUT, exist_ok=True)
    rows = []
    for cells in (int(c) for c in args.cells.split(",")):
        for k, (label, entries) in enumerate(METHODS):
            if ("paper" if k == 0 else "default") not in args.methods.split(","):
                continue
            one = None
            for ranks in (int(r) for r in args.ranks.split(",")):
                directory = os.path.join(OUT, "runs", "ranks-%d-%d-%d" % (cells, ranks, k))
                runs = [run_once(ranks, MESHES[cells], entries, directory)
                        for _ in range(args.repeat)]
                s = runs[-1]
                if one is None:
                    one = s
                load = s["collapse_load"] if s["collapse_load"] is not None else s["last_converged_load"]
                load_one = (one["collapse_load"] if one["collapse_load"] is not None
                            else one["last_converged_load"])
                wall = statistics.median(r["wall_seconds"] for r in runs)
                row = {"cells": s["cells"], "equations": s["equations"], "method": label,
                       "ranks": s["ranks"], "outcome": s["outcome"],
                       "same_outcome": s["outcome"] == one["outcome"],
                       "load": load, "load_difference": abs(load - load_one) / abs(load_one),
                       "last_converged_difference":
                           abs(s["last_converged_load"] - one["last_converged_load"])
                           / abs(one["last_converged_load"]),
                       "iterations": s["total_iterations"], "wall_median_s": wall,
                       "ms_per_iteration": 1e3 * statistics.median(
                           r["seconds_per_iteration"] for r in runs),
                       "peak_mb_per_rank": max(r["peak_memory_mb_per_rank"] for r in runs),
                       "program_mb_per_rank": max(r["program_memory_mb_per_rank"] for r in runs)}
                rows.append(row)
                print(row, flush=True)
    header = ("| cells | equations | method | ranks | outcome | same outcome | load / (2+pi)c "
              "| last converged load vs 1 rank | iterations | wall s (median) | ms per iteration "
              "| peak MB per rank | of which the program |")
    lines = [header, "|" + "---|" * (header.count("|") - 1)]
    for r in rows:
        lines.append("| %d | %d | %s | %d | %s | %s | %.5f | %.1e | %d | %.2f | %.2f | %.0f | %.0f |" % (
            r["cells"], r["equations"], r["method"], r["ranks"], r["outcome"],
            "yes" if r["same_outcome"] else "NO", r["load"] / (2 + 3.141592653589793),
            r["last_converged_difference"], r["iterations"], r["wall_median_s"],
            r["ms_per_iteration"], r["peak_mb_per_rank"], r["program_mb_per_rank"]))
    with open(os.path.join(OUT, "ranks.csv"), "w") as f:
        f.write(",".join(rows[0].keys()) + "\n")
        for r in rows:
            f.write(",".join(str(v) for v in r.values()) + "\n")
    page.write(OUT, "ranks", "Prandtl's footing on several ranks", lines)


if __name__ == "__main__":
    main()
