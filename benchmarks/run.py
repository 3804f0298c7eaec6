#!/usr/bin/python3
"""Speed and accuracy benchmarks of thinlayer: the results are not tests.

    /usr/bin/python3 -m benchmarks.run [--quick] [--repeat N] [--jobs N]
    /usr/bin/python3 -m benchmarks.run --ladder [--repeat N]
    /usr/bin/python3 -m benchmarks.run --stability
    /usr/bin/python3 -m benchmarks.run --performance [--repeat N]

Default: case x solution method x tolerance x mesh level, each run N times
(default 3), into output/benchmarks/ (or --output): benchmarks.csv (the
outcome, the error of the collapse load against the analytic value and
against the mesh's discrete limit, iterations, median wall time, peak
memory), benchmarks.md (the same table, also printed), benchmarks.png
(both errors against median wall time per case, methods as series) and
near_collapse.png (iterations per load step over the last steps before
collapse, per case and method). Every method converges on the same
measure, the displacement test (the last correction of the step's
displacement increment against its size), so that a TOL means the same for
all (the residual is not defined for the viscoplastic method, whose stresses
are in equilibrium at every iteration). The discrete limit of a case
and mesh is Newton's collapse load at TOL 1e-8 bracketed to 0.1%: the
error against it is what the solver adds to the mesh's own error.
--quick runs mesh level 1 only, at TOL 1e-3 only.
--ladder climbs the cost ladder ("no more model than the scene needs"):
element Q8 or Q9 x 2x2 or 3x3 Gauss points x mesh level 1 and 2, for every
case with its recommended method, and for Case 3 the harmonics {1}, {1,3},
{1,3,5}, into ladder.csv/.md/.png. --stability runs the Case 1 stability
maps (adhesive and frictional, aspect ratio x TOL) with every method, into
output/benchmarks/stability/ (a map per material and method, and
stability.md summing them up). --performance is benchmarks/performance.py
on 2048, 8192 and 32768 cells: the time to bracket Prandtl's collapse load
by the paper's method (fixed programme and automatic stepping) and the
default method, with their work and the fitted growth of time with size.
Peak memory is the maximum resident set size reported by /usr/bin/time
(about 170 MB of it are the libraries deal.II loads). THINLAYER in the
environment names another binary (so that a build can go on meanwhile).
"""
import argparse
import concurrent.futures
import csv
import json
import os
import statistics
import subprocess
import time

from thinlayer_tools import THINLAYER, TOP, cases, overrides, results, run_module

from benchmarks import page
OUT = os.path.join(TOP, "output", "benchmarks")

# case: (parameter file, {mesh level: geometry parameters}), the levels of
# thinlayer_tools.cases at the aspect ratio (and Case 1's inclination) each
# case is benchmarked at.
CASES = {
    "prandtl": (cases.PARAMETER_FILES["prandtl"],
                {level: cases.geometry("prandtl", level) for level in (1, 2, 3)}),
    "case1-adhesive": (cases.PARAMETER_FILES["case1"],
                       {level: cases.geometry("case1", level, 100) for level in (1, 2, 3)}),
    "case2": (cases.PARAMETER_FILES["case2"],
              {level: cases.geometry("case2", level, 10) for level in (1, 2)}),
    "case3": (cases.PARAMETER_FILES["case3"],
              {level: cases.geometry("case3", level, 10) for level in (1, 2)}),
    "case4-rough": (cases.PARAMETER_FILES["case4"],
                    {level: cases.geometry("case4", level, 10) for level in (1, 2)}),
    # Scenes with weight (each file's own mesh): the active thrust on a
    # smooth wall from the K0 state (Rankine's K_a), a slab's safety factor
    # on a thin seam by strength reduction (tan(phi) / tan(beta)), N_q
    # under a smooth footing with a surcharge (Prandtl-Reissner), a
    # homogeneous slope's safety factor (Bishop's simplified method),
    # N_gamma under a rough footing (Martin's exact value) and the active
    # and the passive thrust on a rough wall through interface elements
    # (Coulomb's and Lancellotta's bounds; no exact value is known). The
    # pile's shaft is left out: its load keeps rising slowly (the toe), so
    # it has no limit to measure a method against.
    "rankine-active": ("prm/earth-pressure-rankine.prm", {1: ""}),
    "seam-safety": ("prm/inclined-seam-strength-reduction.prm", {1: ""}),
    "bearing-nq": ("prm/strip-footing-bearing-capacity.prm", {1: ""}),
    "slope-safety": ("prm/slope-strength-reduction.prm", {1: ""}),
    "n-gamma": ("prm/strip-footing-n-gamma.prm", {1: ""}),
    "active-wall": ("prm/earth-pressure-wall-friction-zero-thickness.prm", {1: ""}),
    "passive-wall": ("prm/earth-pressure-passive-wall-friction-zero-thickness.prm", {1: ""}),
}
# The levels the default mode runs per case: two where a run takes about a
# second, one where the slower methods take several (Case 3, Case 4), and
# Prandtl at level 1 only, since its level 2 took a third of the whole
# benchmark's time (the --performance mode times Prandtl on finer meshes).
BENCHMARK_LEVELS = {"prandtl": (1,), "case1-adhesive": (1, 2), "case2": (1, 2),
                    "case3": (1,), "case4-rough": (1,), "rankine-active": (1,),
                    "seam-safety": (1,), "bearing-nq": (1,), "slope-safety": (1,),
                    "n-gamma": (1,), "active-wall": (1,), "passive-wall": (1,)}
# The cases the ladder climbs and the method each climbs with: the
# recommended one (the manual's page on running a scene: solution methods).
LADDER_METHOD = {"prandtl": ("viscoplastic", "body loads"),
                 "case1-adhesive": ("accelerated initial stress", "residual"),
                 "case2": ("accelerated initial stress", "residual"),
                 "case3": ("accelerated initial stress", "residual"),
                 "case4-rough": ("accelerated initial stress", "residual")}
# Case 3's harmonics rung, with stations every 15 degrees so that only the
# harmonics change.
LADDER_HARMONICS = ["1", "1, 3", "1, 3, 5"]
LADDER_STATIONS = ", ".join(str(15 * k) for k in range(13))
# Each method with its convergence criterion: one measure for all, the
# displacement test (the viscoplastic method's own body-load test compares
# a different quantity, so its TOL would mean something else, and the
# residual is not defined for it).
METHODS = [("viscoplastic", "displacements"), ("initial stress", "displacements"),
           ("accelerated initial stress", "displacements"), ("newton", "displacements"),
           ("accelerated with newton fallback", "displacements")]
# The discrete limit of a case and mesh: Newton, tight, bracketed to 0.1%.
LIMIT_ENTRIES = ("Solver/Method=newton", "Solver/Convergence criterion=residual",
                 "Loading/Collapse resolution=0.001")
LIMIT_TOLERANCE = "1e-8"
TOLERANCES = ["1e-3", "1e-5"]


def percent(error):
    """An error in percent; '-' where the run has no collapse load."""
    return "%+.1f%%" % (100 * error) if error is not None else "-"


def points(pts):
    """(wall time, |error| in percent) of the runs that have a collapse load."""
    shown = [r for r in pts if r["relative_error"] is not None]
    return ([r["wall_median_s"] for r in shown],
            [abs(100 * r["relative_error"]) for r in shown])


def run_once(prm, geometry, solver, tol, directory, extra=()):
    entries = ["Solver/Linear solver=" + solver, "Solver/Tolerance=" + tol,
               "Output/Directory=" + directory, "Output/Write VTU=false",
               "Output/Print timing=false"]
    if geometry:
        entries.append("Mesh/Geometry parameters=" + geometry)
    command = ["/usr/bin/time", "-f", "%M", THINLAYER, os.path.join(TOP, prm)] + \
        overrides(list(entries) + list(extra))
    done = subprocess.run(command, capture_output=True, text=True, check=True)
    peak_kb = int(done.stderr.strip().splitlines()[-1])
    with open(os.path.join(directory, "summary.json")) as f:
        return json.load(f), peak_kb


# The title of each table's page.
TITLES = {
    "benchmarks": "Speed and accuracy of the methods",
    "ladder": "The cost ladder",
    "stability": "Stability maps of Case 1",
    "outcomes": "Outcomes of every method",
    "kpc": "Case 4: K_pc against the wall column",
    "table1": "Table 1 by the default method",
    "performance": "Time to answer on Prandtl's footing",
    "performance-scenes": "Time to answer on the thin-layer scenes",
    "performance-3d": "Time to answer on the 3D scenes",
}


def write_results(rows, name, header, format_row, out=None):
    """NAME.csv (every field) and NAME.md (a table headed by what measured
    it, also printed) in @p out (default: the output directory)."""
    out = out or OUT
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, name + ".csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    lines = [header, "|" + "---|" * (header.count("|") - 1)] + [format_row(r) for r in rows]
    page.write(out, name, TITLES.get(name, name), lines)


def median_run(prm, geometry, solver, tol, directory, repeat, extra=()):
    """The summary of the last of @p repeat runs, their median time, peak memory."""
    times, summary, peak = [], None, 0
    for _ in range(repeat):
        summary, peak_kb = run_once(prm, geometry, solver, tol, directory, extra)
        times.append(summary["wall_seconds"])
        peak = max(peak, peak_kb)
    return summary, statistics.median(times), round(peak / 1024, 1)


def ladder(repeat):
    """Error against cost as the model grows: element, quadrature, mesh,
    and for Case 3 the harmonics."""
    rows = []

    def rung(case, level, element, gauss, harmonics=None):
        prm, levels = CASES[case]
        method, criterion = LADDER_METHOD[case]
        entries = ("Discretisation/Element=" + element,
                   "Discretisation/Gauss points per direction=" + gauss) + \
            method_entries(method, criterion)
        label = "%s-%d-%s-%s" % (case, level, element, gauss)
        if harmonics:
            entries += ("Kinematics/Harmonics=" + harmonics,
                        "Kinematics/Stations=" + LADDER_STATIONS)
            label += "-h" + harmonics.replace(", ", "_")
        directory = os.path.join(OUT, "runs", "ladder-" + label)
        summary, median, peak = median_run(prm, levels[level], "cholmod", "1e-3",
                                           directory, repeat, entries)
        row = {"case": case, "mesh_level": level, "element": element,
               "gauss_points": gauss + "x" + gauss, "harmonics": harmonics or "",
               "method": method, "equations": summary["equations"],
               "collapse_detected": int(results.collapse_detected(summary)),
               "relative_error": results.collapse_error(summary),
               "total_iterations": summary["total_iterations"],
               "wall_median_s": median, "peak_memory_mb": peak}
        rows.append(row)
        print("%-15s level %d %s %s %-8s error %7s %6d iterations %8.3f s" % (
            case, level, element, row["gauss_points"], harmonics or "",
            percent(row["relative_error"]), row["total_iterations"], median), flush=True)

    for case in LADDER_METHOD:
        for level in (1, 2):
            for element in ("Q8", "Q9"):
                for gauss in ("2", "3"):
                    rung(case, level, element, gauss)
    for level in (1, 2):
        for harmonics in LADDER_HARMONICS:
            rung("case3", level, "Q8", "2", harmonics)

    write_results(rows, "ladder",
                  "| case | method | level | element | Gauss | harmonics | equations "
                  "| collapse detected | error | iterations | wall s (median) |",
                  lambda r: "| %s | %s | %d | %s | %s | %s | %d | %s | %s | %d | %.3f |" % (
                      r["case"], r["method"], r["mesh_level"], r["element"],
                      r["gauss_points"], r["harmonics"] or "(file's)", r["equations"],
                      "yes" if r["collapse_detected"] else "no",
                      percent(r["relative_error"]), r["total_iterations"],
                      r["wall_median_s"]))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    cases = list(LADDER_METHOD)
    fig, axes = plt.subplots(2, 3, figsize=(15, 8), squeeze=False)
    axes[1][2].axis("off")
    for ax, case in zip([a for line in axes for a in line], cases):
        for element, marker in (("Q8", "o"), ("Q9", "s")):
            for gauss, style in (("2x2", "-"), ("3x3", "--")):
                pts = [r for r in rows if r["case"] == case and r["element"] == element
                       and r["gauss_points"] == gauss and not r["harmonics"]]
                ax.plot(*points(pts), marker + style, label="%s, %s" % (element, gauss))
        for harmonics, colour in zip(LADDER_HARMONICS, ("C4", "C5", "C6")):
            pts = [r for r in rows if r["case"] == case and r["harmonics"] == harmonics]
            if pts:
                ax.plot(*points(pts), "^:", color=colour,
                        label="Q8, 2x2, harmonics " + harmonics)
        ax.set_xscale("log")
        ax.set_xlabel("wall time, median (s)")
        ax.set_ylabel("|error| of the collapse load (%)")
        ax.set_title("%s, %s (points: mesh levels 1, 2)" % (case, LADDER_METHOD[case][0]),
                     fontsize=8)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "ladder.png"), dpi=120)


def method_entries(method, criterion):
    return ("Solver/Method=" + method, "Solver/Convergence criterion=" + criterion)


def main():
    global OUT
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true", help="mesh level 1 only")
    parser.add_argument("--repeat", type=int, default=3,
                        help="runs of each configuration; times are their median (default 3)")
    which = parser.add_mutually_exclusive_group()
    which.add_argument("--ladder", action="store_true", help="the cost ladder")
    which.add_argument("--stability", action="store_true", help="the Case 1 stability maps")
    which.add_argument("--performance", action="store_true",
                       help="time to answer on Prandtl, 2048 to 32768 elements "
                       "(benchmarks/performance.py)")
    parser.add_argument("--jobs", type=int, default=1,
                        help="cases at a time in the default benchmark (default 1: times of "
                             "a machine that runs nothing else)")
    parser.add_argument("--output", default=OUT, help="the results directory (default %(default)s)")
    page.add_argument(parser)
    arguments = parser.parse_args()
    page.configure(arguments)
    OUT = os.path.abspath(arguments.output)
    repeat = arguments.repeat
    if repeat < 1:
        parser.error("--repeat: expected at least 1")
    os.makedirs(OUT, exist_ok=True)
    if arguments.ladder:
        ladder(repeat)
        return
    if arguments.stability:
        stability()
        return
    if arguments.performance:
        from benchmarks import performance
        performance.performance((2048, 8192, 32768), repeat, scenes=True)
        return
    benchmark(arguments.quick, repeat, max(1, arguments.jobs))


def discrete_limit(case, level, prm, geometry):
    """Newton's collapse load on this mesh at TOL 1e-8, bracketed to 0.1%."""
    directory = os.path.join(OUT, "runs", "%s-%d-limit" % (case, level))
    summary, _ = run_once(prm, geometry, "cholmod", LIMIT_TOLERANCE, directory, LIMIT_ENTRIES)
    load = results.collapse_load(summary)
    print("%-15s level %d discrete limit %s (%s)" % (
        case, level, "%.5g" % load if load is not None else "-", summary["outcome"]), flush=True)
    return load


def case_rows(case, level, prm, geometry, tolerances, repeat):
    """The rows of one case and mesh level: every method at every TOL."""
    rows = []
    limit = discrete_limit(case, level, prm, geometry)
    for method, criterion in METHODS:
        for tol in tolerances:
            directory = os.path.join(OUT, "runs", "%s-%d-%s-%s" % (
                case, level, method.replace(" ", "_"), tol))
            summary, median, peak = median_run(
                prm, geometry, "cholmod", tol, directory, repeat,
                method_entries(method, criterion))
            load = results.collapse_load(summary)
            row = {
                "case": case, "mesh_level": level, "cells": summary["cells"],
                "equations": summary["equations"], "method": method,
                "tolerance": tol, "outcome": summary["outcome"],
                "collapse_detected": int(results.collapse_detected(summary)),
                "last_converged_load": summary["last_converged_load"],
                "relative_error": results.collapse_error(summary),
                "discrete_limit": limit,
                "discrete_error": (load - limit) / limit
                if load is not None and limit else None,
                "total_iterations": summary["total_iterations"],
                "wall_median_s": median,
                "peak_memory_mb": peak,
                "directory": directory,
            }
            rows.append(row)
            print("%-15s level %d %-32s TOL %-5s error %7s (limit %7s) %6d iterations "
                  "%8.3f s (median of %d) %7.1f MB" % (
                      case, level, method, tol, percent(row["relative_error"]),
                      percent(row["discrete_error"]), row["total_iterations"],
                      row["wall_median_s"], repeat, row["peak_memory_mb"]), flush=True)
    return rows


def benchmark(quick, repeat, jobs=1):
    """Case x level x method x TOL: both errors, iterations, time, memory.
    With @p jobs > 1, that many cases (each its discrete limit, then its
    methods) run at a time: their times are a shared machine's."""
    tasks = [(case, level, prm, geometry) for case, (prm, levels) in CASES.items()
             for level, geometry in sorted(levels.items())
             if level in BENCHMARK_LEVELS[case] and not (quick and level > 1)]
    # --quick runs the looser TOL only.
    tolerances = TOLERANCES[:1] if quick else TOLERANCES
    if jobs > 1:
        with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
            per_task = list(pool.map(lambda task: case_rows(*task, tolerances, repeat), tasks))
    else:
        per_task = [case_rows(*task, tolerances, repeat) for task in tasks]
    rows = [row for task_rows in per_task for row in task_rows]
    write_results(rows, "benchmarks",
                  "| case | level | cells | equations | method | TOL | outcome "
                  "| error (analytic) | error (discrete limit) | iterations | wall s (median) "
                  "| peak MB |",
                  lambda r: "| %s | %d | %d | %d | %s | %s | %s | %s | %s | %d | %.3f | %.1f |" % (
                      r["case"], r["mesh_level"], r["cells"], r["equations"],
                      r["method"], r["tolerance"], r["outcome"],
                      percent(r["relative_error"]), percent(r["discrete_error"]),
                      r["total_iterations"], r["wall_median_s"], r["peak_memory_mb"]))
    benchmark_chart(rows)
    near_collapse_chart(rows)


def benchmark_chart(rows):
    """Per case, |error| against median time: against the analytic value
    (top) and against the discrete limit (bottom). Runs without a collapse
    load are marked at the top edge, never drawn as an error."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker
    cases = list(dict.fromkeys(r["case"] for r in rows))
    columns = min(3, len(cases))
    lines = (len(cases) + columns - 1) // columns
    fig, axes = plt.subplots(2 * lines, columns, figsize=(5 * columns, 3.6 * 2 * lines),
                             squeeze=False)
    for k, case in enumerate(cases):
        for half, (key, what) in enumerate((("relative_error", "analytic value"),
                                            ("discrete_error", "discrete limit"))):
            ax = axes[2 * (k // columns) + half][k % columns]
            for (method, _), colour in zip(METHODS, ("C0", "C1", "C2", "C3", "C4")):
                for tol, marker in zip(TOLERANCES, "os"):
                    pts = sorted((r for r in rows if r["case"] == case and r["method"] == method
                                  and r["tolerance"] == tol), key=lambda r: r["mesh_level"])
                    shown = [r for r in pts if r[key] is not None]
                    ax.plot([r["wall_median_s"] for r in shown],
                            [max(abs(100 * r[key]), 1e-3) for r in shown],
                            marker + ("-" if tol == TOLERANCES[0] else "--"), color=colour,
                            mfc="none" if tol == TOLERANCES[0] else colour,
                            label="%s, TOL %s" % (method, tol))
                    missing = [r for r in pts if r[key] is None]
                    ax.plot([r["wall_median_s"] for r in missing], [100] * len(missing), "x",
                            color=colour, ms=9, mew=2)
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_ylim(1e-3, 200)
            ax.axhline(100, color="k", lw=0.5)
            ax.set_xlabel("wall time, median (s)", fontsize=8)
            ax.set_ylabel("|error| against the %s (%%)" % what, fontsize=8)
            ax.set_title("%s (points: mesh levels; x at 100: no collapse;\n"
                         "errors below 0.001%% drawn at 0.001%%)" % case, fontsize=8)
            ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
            ax.grid(alpha=0.3)
    for k in range(len(cases), lines * columns):
        for half in (0, 1):
            axes[2 * (k // columns) + half][k % columns].axis("off")
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower right", fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "benchmarks.png"), dpi=100)


def near_collapse_chart(rows):
    """Iterations per step over the last ten steps, level 1, tightest TOL."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    cases = list(dict.fromkeys(r["case"] for r in rows))
    columns = min(3, len(cases))
    lines = (len(cases) + columns - 1) // columns
    fig, axes = plt.subplots(lines, columns, figsize=(5 * columns, 3.8 * lines), squeeze=False)
    for k in range(len(cases), lines * columns):
        axes[k // columns][k % columns].axis("off")
    for k, case in enumerate(cases):
        ax = axes[k // columns][k % columns]
        # The tightest TOL the case ran at (--quick runs the looser alone).
        tight = min((r["tolerance"] for r in rows if r["case"] == case), key=float)
        for (method, _), colour in zip(METHODS, ("C0", "C1", "C2", "C3", "C4")):
            run = [r for r in rows if r["case"] == case and r["method"] == method
                   and r["mesh_level"] == 1 and r["tolerance"] == tight]
            if not run:
                continue
            with open(os.path.join(run[0]["directory"], "history.csv"), newline="") as f:
                rows_of_run = list(csv.DictReader(f))
            # Iterations of the accepted steps, and the failures marked.
            steps = results.states(rows_of_run)[-10:]
            ax.plot([float(s["load_factor"]) for s in steps],
                    [int(s["iterations"]) for s in steps], "o-", color=colour, label=method)
            failed = results.failures(rows_of_run)
            ax.plot([float(s["load_factor"]) for s in failed],
                    [int(s["iterations"]) for s in failed], "x", color=colour, markersize=9,
                    mew=2)
        ax.set_yscale("log")
        ax.set_xlabel("load factor")
        ax.set_ylabel("iterations in the step")
        ax.set_title("%s, level 1, TOL %s (x: failed or on the mechanism)"
                     % (case, tight), fontsize=8)
        ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "near_collapse.png"), dpi=100)


def stability():
    """Case 1 stability maps per material and method."""
    maps = [("adhesive", "prm/case1-stability-map.prm"),
            ("frictional", "prm/case1-frictional-stability-map.prm")]
    lines = ["| interface | method | cells with collapse detected | of which within "
             "2% | median iterations | wall s |", "|---|---|---|---|---|---|"]
    for material, prm in maps:
        for method, criterion in METHODS:
            directory = os.path.join(OUT, "stability", "%s-%s" % (material, method.replace(" ", "_")))
            command = [THINLAYER, os.path.join(TOP, prm)] + overrides(
                ["Output/Directory=" + directory] + list(method_entries(method, criterion)))
            start = time.time()
            subprocess.run(command, capture_output=True, text=True, check=True)
            seconds = time.time() - start
            run_module("thinlayer_tools.plots.stability", [directory],
                       capture_output=True, text=True, check=True)
            with open(os.path.join(directory, "sweep.csv"), newline="") as f:
                runs = list(csv.DictReader(f))
            detected = [r for r in runs if results.collapse_detected(r)]
            close = [r for r in detected if results.collapse_error(r) is not None
                     and abs(results.collapse_error(r)) <= 0.02 + 1e-9]
            lines.append("| %s | %s | %d of %d | %d | %d | %.1f |" % (
                material, method, len(detected), len(runs), len(close),
                statistics.median(int(r["total_iterations"]) for r in runs), seconds))
            print(lines[-1], flush=True)
    page.write(os.path.join(OUT, "stability"), "stability", TITLES["stability"], lines)


if __name__ == "__main__":
    main()
