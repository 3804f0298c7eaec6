#!/usr/bin/python3
"""Outcomes of every case with every solution method: the results are not tests.

    /usr/bin/python3 -m benchmarks.outcomes [--quick] [--repeat N] [--methods M,...]
                                            [--cases C,...] [--levels L,...]

Runs every paper case and Prandtl over mesh levels and, where the case has
an interface, its aspect ratio, with each solution method and automatic load
stepping (collapse bracketed to 0.5%), and tables per run: the outcome
(completed, collapse, not converged), the collapse load (or, where there is
none, the last converged load, in brackets), its difference from Newton's
collapse load on the same mesh, bracketed to 0.1% (the reference: Newton's
consistent tangent follows the mesh's curve to its knee), its error against
the analytic value, load steps attempted, iterations, the most iterations
of an accepted step below 90% of the last accepted load factor (away from
collapse) and the median wall time of N runs (default 1).
A run whose outcome is not a collapse is never given an error: the table
says what happened instead. Writes output/benchmarks/outcomes/outcomes.csv
and outcomes.md (also printed). --quick: level 1 and aspect ratios 10 and
1000 only. --kpc instead tables Case 4's passive coefficient K_pc by the
default method against the wall column's aspect ratio and the mesh level
for C_w / c_u = 0 (smooth wall), 0.5 and 1, beside the slip-line value
1 + asin(a) + sqrt(1 - a^2) (kpc.csv, kpc.md). --table1 instead runs
Table 1 (Case 1, alpha 10-80 x aspect ratio 10, 100, 1000) by the default
method, on the scene's mesh and on one twice as fine, each collapse load
against 1/(sin alpha cos alpha), the zero-thickness interface's value, and
beside the upper bound of the layer the mesh models (a slip plane inside
the layer, thinlayer_tools/closed_form.py), which the body's exact collapse load
cannot exceed (table1.csv, table1.md). THINLAYER in the environment names another binary.
"""
import argparse
import json
import math
import os
import statistics
import subprocess

from benchmarks.run import write_results
from benchmarks import page
from thinlayer_tools import THINLAYER, TOP, cases, closed_form, results

OUT = os.path.join(TOP, "output", "benchmarks", "outcomes")

# case: (parameter file, {level: geometry parameters with {ar} for the
# interface's aspect ratio}, aspect ratios), the levels of
# thinlayer_tools.cases.
LAYER_ASPECT_RATIOS = [10, 100, 1000, 10000]
CASES = {
    "prandtl": (cases.PARAMETER_FILES["prandtl"],
                {level: cases.geometry("prandtl", level) for level in (1, 2, 3)}, [None]),
    "case1": (cases.PARAMETER_FILES["case1"],
              {level: cases.geometry("case1", level) for level in (1, 2, 3)},
              LAYER_ASPECT_RATIOS),
    "case2": (cases.PARAMETER_FILES["case2"],
              {level: cases.geometry("case2", level) for level in (1, 2, 3)},
              LAYER_ASPECT_RATIOS),
    "case3": (cases.PARAMETER_FILES["case3"],
              {level: cases.geometry("case3", level) for level in (1, 2)},
              LAYER_ASPECT_RATIOS),
    "case4-rough": (cases.PARAMETER_FILES["case4"],
                    {level: cases.geometry("case4", level) for level in (1, 2, 3)},
                    LAYER_ASPECT_RATIOS),
}
# Each method with its convergence criterion and tolerance.
METHODS = {
    "viscoplastic": ("viscoplastic", "body loads", "1e-5"),
    "accelerated": ("accelerated initial stress", "residual", "1e-5"),
    "newton": ("newton", "residual", "1e-8"),
    # The default: no solver entry at all (accelerated with Newton
    # fallback, the residual criterion, TOL 1e-4).
    "default": None,
}


# Collapse resolution of the runs, and of the Newton reference (finer, so
# that "agrees within the resolution" compares against a sharper bracket).
RESOLUTION = "0.005"
REFERENCE_RESOLUTION = "0.001"


def run(prm, geometry, method, directory, extra=(), resolution=RESOLUTION):
    command = [THINLAYER, os.path.join(TOP, prm)]
    if METHODS[method] is None:
        # The scene's own solver entries give way to the defaults.
        command += ["-s", "Solver/Method=accelerated with newton fallback",
                    "-s", "Solver/Convergence criterion=default",
                    "-s", "Solver/Tolerance=1e-4",
                    "-s", "Solver/Maximum iterations=250"]
    else:
        name, criterion, tol = METHODS[method]
        command += ["-s", "Solver/Method=" + name,
                    "-s", "Solver/Convergence criterion=" + criterion,
                    "-s", "Solver/Tolerance=" + tol]
    command += ["-s", "Loading/Collapse resolution=" + resolution,
               "-s", "Output/Directory=" + directory,
               "-s", "Output/Write VTU=false",
               "-s", "Output/Print timing=false",
               "-s", "Mesh/Geometry parameters=" + geometry]
    for entry in extra:
        command += ["-s", entry]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        return {"outcome": "error", "reason": done.stderr.strip()[-200:]}
    with open(os.path.join(directory, "summary.json")) as f:
        return json.load(f)


def number(value):
    return value if isinstance(value, (int, float)) and math.isfinite(value) else float("nan")


def write_table(name, rows, header, format_row):
    """NAME.csv and NAME.md (also printed) in OUT, as benchmarks/run.py writes its tables."""
    write_results(rows, name, header, format_row, OUT)


def table1():
    """Table 1 by the default method: thinlayer's own sweep over alpha and
    the aspect ratio, on the scene's mesh (8 elements along the interface)
    and on one twice as fine (a layer of the same aspect ratio is then half
    as thick), each collapse load against 1 / (sin alpha cos alpha) and
    beside the layer's own upper bound."""
    rows = []
    for level, elements in ((1, 8), (2, 16)):
        directory = os.path.join(OUT, "table1-level%d" % level)
        command = [THINLAYER, os.path.join(TOP, "prm", "case1-table1.prm"),
                   "-s", "Solver/Method=accelerated with newton fallback",
                   "-s", "Solver/Convergence criterion=default",
                   "-s", "Solver/Tolerance=1e-4",
                   "-s", "Loading/Collapse resolution=" + RESOLUTION,
                   "-s", "Mesh/Geometry parameters=alpha=45, aspect_ratio=10, "
                   "elements_along=%d, elements_block=%d" % (elements, elements),
                   "-s", "Sweep/Values=alpha = 10, 20, 30, 40, 45, 50, 60, 70, 80; "
                   "aspect_ratio = 10, 100, 1000",
                   "-s", "Output/Directory=" + directory]
        subprocess.run(command, capture_output=True, text=True, check=True)
        for r in results.read_csv(os.path.join(directory, "sweep.csv")):
            error = results.collapse_error(r)
            alpha, ratio = int(r["alpha"]), int(r["aspect_ratio"])
            rows.append({"level": level, "elements_along": elements,
                         "alpha": alpha, "aspect_ratio": ratio,
                         "exact": results.number(r["reference_load"]),
                         "layer_bound": closed_form.inclined_layer_upper_bound(alpha, ratio),
                         "outcome": r["outcome"],
                         "collapse_load": results.number(r["collapse_load"]),
                         "error": error if error is not None else float("nan"),
                         "iterations": int(r["total_iterations"]),
                         "wall_seconds": results.number(r["wall_seconds"])})
            print(format_table1(rows[-1]), flush=True)
    write_table("table1", rows, TABLE1_HEADER, format_table1)


TABLE1_HEADER = ("| elements along | alpha | AR | 1/(sin a cos a) | layer's upper bound "
                 "| outcome | collapse load | error | iterations | wall s |")


def format_table1(r):
    load = "%.4f" % r["collapse_load"] if math.isfinite(r["collapse_load"]) else "-"
    error = "%+.2f%%" % (100 * r["error"]) if math.isfinite(r["error"]) else "-"
    bound = "%.4f (%+.2f%%)" % (r["layer_bound"], 100 * (r["layer_bound"] / r["exact"] - 1))
    return "| %d | %d | %d | %.4f | %s | %s | %s | %s | %d | %.2f |" % (
        r["elements_along"], r["alpha"], r["aspect_ratio"], r["exact"], bound, r["outcome"], load,
        error, r["iterations"], r["wall_seconds"])


def kpc_table(quick):
    """K_pc by the default method against aspect ratio, level and C_w / c_u."""
    rows = []
    _, levels, ratios = CASES["case4-rough"]
    for adhesion in (0.0, 0.5, 1.0):
        slip_line = closed_form.passive_rough_wall(adhesion)
        prm = "prm/case4-smooth-wall.prm" if adhesion == 0 else "prm/case4-rough-wall.prm"
        for level, template in sorted(levels.items()):
            for ar in ratios:
                if quick and (level > 1 or ar not in (10, 1000)):
                    continue
                directory = os.path.join(OUT, "runs", "kpc-%g-%d-%s" % (adhesion, level, ar))
                extra = [] if adhesion == 0 else ["Material 2/Cohesion=%g" % adhesion]
                s = run(prm, template.format(ar=ar), "default", directory, extra)
                kpc = number(s.get("collapse_load"))
                last = number(s.get("last_converged_load"))
                row = {"adhesion": adhesion, "level": level, "aspect_ratio": ar,
                       "slip_line": slip_line, "outcome": s.get("outcome"), "kpc": kpc,
                       "last_converged": last,
                       "against_slip_line": (kpc - slip_line) / slip_line
                       if math.isfinite(kpc) else float("nan"),
                       "wall_seconds": number(s.get("wall_seconds"))}
                rows.append(row)
                print(format_kpc(row), flush=True)
    write_table("kpc", rows, KPC_HEADER, format_kpc)


KPC_HEADER = ("| C_w / c_u | level | AR | slip line | outcome | K_pc (plateau) "
              "| vs slip line | wall s |")


def format_kpc(r):
    kpc = ("%.4f" % r["kpc"] if math.isfinite(r["kpc"])
           else "(%.4f)" % r["last_converged"])
    error = "%+.2f%%" % (100 * r["against_slip_line"]) if math.isfinite(r["against_slip_line"]) else "-"
    return "| %g | %d | %s | %.3f | %s | %s | %s | %.2f |" % (
        r["adhesion"], r["level"], r["aspect_ratio"], r["slip_line"], r["outcome"], kpc,
        error, r["wall_seconds"])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="level 1, aspect ratios 10 and 1000")
    parser.add_argument("--repeat", type=int, default=1, help="runs per scene (median time)")
    parser.add_argument("--methods", default=",".join(METHODS), help="comma-separated: " + ", ".join(METHODS))
    parser.add_argument("--cases", default=",".join(CASES), help="comma-separated: " + ", ".join(CASES))
    parser.add_argument("--levels", default="1,2,3", help="comma-separated mesh levels (1-3)")
    parser.add_argument("--kpc", action="store_true",
                        help="Case 4's K_pc table instead (default method)")
    parser.add_argument("--table1", action="store_true",
                        help="Table 1 (Case 1, alpha x aspect ratio) by the default method instead")
    page.add_argument(parser)
    args = parser.parse_args()
    page.configure(args)
    os.makedirs(OUT, exist_ok=True)
    if args.kpc:
        kpc_table(args.quick)
        return
    if args.table1:
        table1()
        return
    methods = args.methods.split(",")
    if "newton" not in methods:
        methods = ["newton"] + methods  # the reference of every row
    os.makedirs(OUT, exist_ok=True)

    rows = []
    for case in args.cases.split(","):
        prm, levels, ratios = CASES[case]
        for level, geometry_template in sorted(levels.items()):
            if (args.quick and level > 1) or str(level) not in args.levels.split(","):
                continue
            for ar in ratios:
                if args.quick and ar not in (None, 10, 1000):
                    continue
                geometry = geometry_template.format(ar=ar)
                reference = None
                for method in sorted(methods, key=lambda m: m != "newton"):
                    directory = os.path.join(OUT, "runs", "%s-%d-%s-%s" % (case, level, ar, method))
                    times = []
                    resolution = REFERENCE_RESOLUTION if method == "newton" else RESOLUTION
                    for _ in range(args.repeat):
                        s = run(prm, geometry, method, directory, resolution=resolution)
                        times.append(number(s.get("wall_seconds")))
                    collapse = number(s.get("collapse_load"))
                    if method == "newton":
                        reference = collapse
                    analytic = number(s.get("reference_load"))
                    row = {
                        "case": case, "level": level, "aspect_ratio": ar or "",
                        "method": method, "outcome": s.get("outcome"),
                        "collapse_load": collapse,
                        "last_converged_load": number(s.get("last_converged_load")),
                        "against_newton": (collapse - reference) / reference
                        if math.isfinite(collapse) and reference and math.isfinite(reference) else float("nan"),
                        "against_analytic": (collapse - analytic) / analytic
                        if math.isfinite(collapse) and math.isfinite(analytic) else float("nan"),
                        "attempts": s.get("attempts"), "iterations": s.get("total_iterations"),
                        "wall_seconds": statistics.median(times),
                        "iterations_away": iterations_away_from_collapse(directory),
                        "reason": s.get("reason", ""),
                    }
                    rows.append(row)
                    print(format_row(row), flush=True)

    write_table("outcomes", rows, HEADER, format_row)


def iterations_away_from_collapse(directory):
    """The most iterations of an accepted step below 90% of the last
    accepted load factor (away from collapse)."""
    states = results.states(results.history(directory))
    if not states:
        return None
    top = max(abs(float(r["load_factor"])) for r in states)
    away = [int(r["iterations"]) for r in states if abs(float(r["load_factor"])) <= 0.9 * top]
    return max(away) if away else None


HEADER = ("| case | level | AR | method | outcome | collapse load | vs Newton | vs analytic "
          "| attempts | iterations | it/step < 90% | wall s |")


def format_row(r):
    def percent(x):
        return "%+.2f%%" % (100 * x) if math.isfinite(x) else "-"
    load = ("%.4g" % r["collapse_load"] if math.isfinite(r["collapse_load"])
            else "(%.4g)" % r["last_converged_load"])
    away = r["iterations_away"] if r["iterations_away"] is not None else "-"
    return "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %.2f |" % (
        r["case"], r["level"], r["aspect_ratio"], r["method"], r["outcome"], load,
        percent(r["against_newton"]), percent(r["against_analytic"]),
        r["attempts"], r["iterations"], away, r["wall_seconds"])


if __name__ == "__main__":
    main()
