#!/usr/bin/python3
"""Speed and accuracy benchmarks of thinlayer: the results are not tests.

    /usr/bin/python3 benchmarks/run.py [--quick] [--repeat N]
    /usr/bin/python3 benchmarks/run.py --ladder [--repeat N]

Runs each configuration below N times (default 3), and writes into
output/benchmarks/: benchmarks.csv (one row per configuration: error of the
collapse load against the analytic value, iterations, median and spread of
the wall time, peak memory), benchmarks.md (the same as a table, also
printed) and benchmarks.png (error against median wall time per case, one
series per linear solver and tolerance). --quick runs the smallest meshes
only. --ladder instead climbs the cost ladder ("no more model than the
scene needs"): element Q8 or Q9 x 2x2 or 3x3 Gauss points x mesh level, for
Prandtl and Case 1 with CHOLMOD and TOL 1e-3, into ladder.csv, ladder.md and
ladder.png. Peak memory is the maximum resident set size reported by
/usr/bin/time (about 170 MB of it are the libraries deal.II loads). The
full run takes about 10 minutes on the 2-core machine.
"""
import csv
import json
import os
import statistics
import subprocess
import sys

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
THINLAYER = os.path.join(TOP, "build", "thinlayer")
OUT = os.path.join(TOP, "output", "benchmarks")

# case: (parameter file, {mesh level: geometry parameters})
CASES = {
    "prandtl": ("prm/prandtl-strip-footing.prm", {
        1: "half_width=1, width=5, depth=3, n_footing=8, n_side=12, n_depth=12, growth=1.15",
        2: "half_width=1, width=5, depth=3, n_footing=16, n_side=24, n_depth=24, growth=1.07",
        3: "half_width=1, width=5, depth=3, n_footing=32, n_side=48, n_depth=48, growth=1.035",
    }),
    "case1-adhesive": ("prm/case1-inclined-adhesive.prm", {
        1: "alpha=30, aspect_ratio=100, elements_along=8, elements_block=8",
        2: "alpha=30, aspect_ratio=100, elements_along=16, elements_block=16",
        3: "alpha=30, aspect_ratio=100, elements_along=32, elements_block=32",
    }),
    "case2": ("prm/case2-strip-footing.prm", {
        1: "half_width=1, width=5, depth=3, aspect_ratio=10, n_footing=8, n_side=12, n_depth=10, interface_beyond_footing=1, refinement=1",
        2: "half_width=1, width=5, depth=3, aspect_ratio=10, n_footing=8, n_side=12, n_depth=10, interface_beyond_footing=1, refinement=2",
    }),
    "case3": ("prm/case3-circular-footing.prm", {
        1: "half_width=1, width=5, depth=3, aspect_ratio=10, n_footing=8, n_side=12, n_depth=10, interface_beyond_footing=1, refinement=1",
    }),
}
SOLVERS = ["cholmod", "umfpack"]
# UMFPACK is the comparison; on the finest meshes it alone would take most
# of the run (about 2 minutes a run for Prandtl at level 3).
MAX_LEVEL = {"cholmod": 3, "umfpack": 2}
TOLERANCES = ["1e-3", "1e-4", "1e-5"]


def run_once(prm, geometry, solver, tol, directory, extra=()):
    command = ["/usr/bin/time", "-f", "%M", THINLAYER, os.path.join(TOP, prm),
               "-s", "Mesh/Geometry parameters=" + geometry,
               "-s", "Solver/Linear solver=" + solver,
               "-s", "Solver/Tolerance=" + tol,
               "-s", "Output/Directory=" + directory,
               "-s", "Output/Write VTU=false",
               "-s", "Output/Print timing=false"]
    for entry in extra:
        command += ["-s", entry]
    done = subprocess.run(command, capture_output=True, text=True, check=True)
    peak_kb = int(done.stderr.strip().splitlines()[-1])
    with open(os.path.join(directory, "summary.json")) as f:
        return json.load(f), peak_kb


def write_results(rows, name, header, format_row):
    """NAME.csv (every field) and NAME.md (a table, also printed) in OUT."""
    with open(os.path.join(OUT, name + ".csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    lines = [header, "|" + "---|" * (header.count("|") - 1)] + [format_row(r) for r in rows]
    with open(os.path.join(OUT, name + ".md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


def median_run(prm, geometry, solver, tol, directory, repeat, extra=()):
    """The summary of the last of @p repeat runs, their median time, peak memory."""
    times, summary, peak = [], None, 0
    for _ in range(repeat):
        summary, peak_kb = run_once(prm, geometry, solver, tol, directory, extra)
        times.append(summary["wall_seconds"])
        peak = max(peak, peak_kb)
    return summary, statistics.median(times), round(peak / 1024, 1)


def ladder(repeat):
    """Error against cost as the model grows: element, quadrature, mesh."""
    rows = []
    for case in ("prandtl", "case1-adhesive"):
        prm, levels = CASES[case]
        for level in (1, 2):
            for element in ("Q8", "Q9"):
                for gauss in ("2", "3"):
                    directory = os.path.join(OUT, "runs", "ladder-%s-%d-%s-%s"
                                             % (case, level, element, gauss))
                    summary, median, peak = median_run(
                        prm, levels[level], "cholmod", "1e-3", directory, repeat,
                        ("Discretisation/Element=" + element,
                         "Discretisation/Gauss points per direction=" + gauss))
                    row = {"case": case, "mesh_level": level, "element": element,
                           "gauss_points": gauss + "x" + gauss,
                           "equations": summary["equations"],
                           "collapse_detected": int(not summary["converged"]),
                           "relative_error": summary["relative_error"],
                           "total_iterations": summary["total_iterations"],
                           "wall_median_s": median, "peak_memory_mb": peak}
                    rows.append(row)
                    print("%-15s level %d %s %s error %+6.1f%% %6d iterations %8.3f s" % (
                        case, level, element, row["gauss_points"],
                        100 * (row["relative_error"] or 0), row["total_iterations"], median),
                        flush=True)
    write_results(rows, "ladder",
                  "| case | level | element | Gauss | equations | collapse detected | error "
                  "| iterations | wall s (median) |",
                  lambda r: "| %s | %d | %s | %s | %d | %s | %+.1f%% | %d | %.3f |" % (
                      r["case"], r["mesh_level"], r["element"], r["gauss_points"],
                      r["equations"], "yes" if r["collapse_detected"] else "no",
                      100 * (r["relative_error"] or 0), r["total_iterations"],
                      r["wall_median_s"]))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, case in zip(axes, ("prandtl", "case1-adhesive")):
        for element, marker in (("Q8", "o"), ("Q9", "s")):
            for gauss, style in (("2x2", "-"), ("3x3", "--")):
                pts = [r for r in rows if r["case"] == case and r["element"] == element
                       and r["gauss_points"] == gauss]
                ax.plot([r["wall_median_s"] for r in pts],
                        [abs(100 * (r["relative_error"] or 0)) for r in pts],
                        marker + style, label="%s, %s" % (element, gauss))
        ax.set_xscale("log")
        ax.set_xlabel("wall time, median (s)")
        ax.set_ylabel("|error| of the collapse load (%)")
        ax.set_title(case + " (points: mesh levels 1, 2)", fontsize=9)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "ladder.png"), dpi=120)


def main():
    if "--ladder" in sys.argv:
        os.makedirs(OUT, exist_ok=True)
        ladder(int(sys.argv[sys.argv.index("--repeat") + 1]) if "--repeat" in sys.argv else 3)
        return
    quick = "--quick" in sys.argv
    repeat = int(sys.argv[sys.argv.index("--repeat") + 1]) if "--repeat" in sys.argv else 3
    os.makedirs(OUT, exist_ok=True)
    rows = []
    for case, (prm, levels) in CASES.items():
        for level, geometry in sorted(levels.items()):
            if quick and level > 1:
                continue
            for solver in SOLVERS:
                if level > MAX_LEVEL[solver]:
                    continue
                for tol in TOLERANCES:
                    directory = os.path.join(OUT, "runs", "%s-%d-%s-%s" % (case, level, solver, tol))
                    summary, median, peak = median_run(prm, geometry, solver, tol, directory,
                                                       repeat)
                    row = {
                        "case": case, "mesh_level": level, "cells": summary["cells"],
                        "equations": summary["equations"], "linear_solver": solver,
                        "tolerance": tol,
                        "collapse_detected": int(not summary["converged"]),
                        "last_converged_load": summary["last_converged_load"],
                        "relative_error": summary["relative_error"],
                        "total_iterations": summary["total_iterations"],
                        "wall_median_s": median,
                        "peak_memory_mb": peak,
                    }
                    rows.append(row)
                    print("%-15s level %d %-8s TOL %-5s error %+6.1f%% %6d iterations %8.3f s "
                          "(median of %d) %7.1f MB" % (
                              case, level, solver, tol, 100 * (row["relative_error"] or 0),
                              row["total_iterations"], row["wall_median_s"], repeat,
                              row["peak_memory_mb"]), flush=True)
    write_results(rows, "benchmarks",
                  "| case | level | cells | equations | solver | TOL | collapse detected "
                  "| error | iterations | wall s (median) | peak MB |",
                  lambda r: "| %s | %d | %d | %d | %s | %s | %s | %+.1f%% | %d | %.3f | %.1f |" % (
                      r["case"], r["mesh_level"], r["cells"], r["equations"],
                      r["linear_solver"], r["tolerance"],
                      "yes" if r["collapse_detected"] else "no",
                      100 * (r["relative_error"] or 0), r["total_iterations"],
                      r["wall_median_s"], r["peak_memory_mb"]))
    chart(rows)


def chart(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    cases = list(dict.fromkeys(r["case"] for r in rows))
    fig, axes = plt.subplots(1, len(cases), figsize=(4.5 * len(cases), 4), squeeze=False)
    for ax, case in zip(axes[0], cases):
        for solver, marker in zip(SOLVERS, "os"):
            for tol, colour in zip(TOLERANCES, ("C0", "C1", "C2")):
                pts = sorted((r for r in rows if r["case"] == case and r["linear_solver"] == solver
                              and r["tolerance"] == tol), key=lambda r: r["mesh_level"])
                ax.plot([r["wall_median_s"] for r in pts],
                        [abs(100 * (r["relative_error"] or 0)) for r in pts],
                        marker + ("-" if solver == "cholmod" else "--"), color=colour,
                        label="%s, TOL %s" % (solver, tol))
        ax.set_xscale("log")
        ax.set_xlabel("wall time, median (s)")
        ax.set_ylabel("|error| of the collapse load (%)")
        ax.set_title(case + " (points: mesh levels)", fontsize=9)
        ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "benchmarks.png"), dpi=120)


if __name__ == "__main__":
    main()
