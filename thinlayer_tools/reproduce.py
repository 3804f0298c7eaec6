#!/usr/bin/python3
"""Reproduce Griffiths' paper into one report: run every scene the paper's
tables and figures need, by the paper's method and by the default one,
the validations against closed forms, the stability maps and the
speed-against-accuracy benchmark, then write DIR/report.html.

    /usr/bin/python3 -m thinlayer_tools.reproduce [--quick] [--output DIR] [--report-only]

Call it through scripts/reproduce.sh, which builds thinlayer first. The runs
go into DIR/runs/NAME (each a thinlayer results directory), the benchmark
into DIR/benchmarks; everything is written into DIR.partial and replaces
DIR (default output/reproduce) only when the page is written, so DIR
always holds one whole reproduction. --quick runs smaller sweeps and a one-pass
benchmark (for CI); --report-only rewrites the page from the runs already
in DIR.
"""
import argparse
import concurrent.futures
import os
import shutil
import subprocess
import sys
import time

from thinlayer_tools import THINLAYER, TOP, mpirun, run_module
from thinlayer_tools import overrides as command_line_overrides
from thinlayer_tools.report import (adaptivity, bearing_capacity, case1, case4, continuation,
                                    curved, earth_pressure, footings, limits, methods, page,
                                    parallel, phases, pile, pile_lateral, scaling, solid, speed,
                                    strength_reduction, tractions, wall_friction, weight)
from thinlayer_tools.report.runs import DEFAULT, PAPER, Runs

ALL_ALPHAS = "alpha = 10, 20, 30, 40, 45, 50, 60, 70, 80"
QUICK_ALPHAS = "alpha = 20, 45, 70"
METHOD_NAMES = {"viscoplastic": PAPER, "default": DEFAULT,
                "newton": ("Solver/Method=newton", "Solver/Convergence criterion=residual")}


def run_list(quick):
    """Every run of the report: (name, parameter file, overrides). The
    sections name these runs; their parameter files are the scenes of
    prm/, changed only by the overrides listed here."""
    alphas = QUICK_ALPHAS if quick else ALL_ALPHAS
    runs = [
        ("table1-paper", "case1-table1", ("Sweep/Values=%s; aspect_ratio = 10, 100, 1000; "
                                          "Solver/Tolerance = 1e-2, 1e-5" % alphas,)),
        ("table1-default", "case1-table1", DEFAULT + (
            "Solver/Tolerance=1e-5", "Sweep/Values=%s; aspect_ratio = 10, 100, 1000" % alphas)),
        ("figure3-paper", "case1-figure3", ()),
        ("figure3-paper-loose", "case1-figure3", ("Solver/Tolerance=1e-2",)),
        ("figure3-default", "case1-figure3", DEFAULT),
        ("figure4-paper", "case1-figure4", ()),
        ("figure4-default", "case1-figure4", DEFAULT + (
            "Sweep/Values=alpha = 10, 15, 20, 22, 24, 25, 26, 27, 28, 30, 32",)),
        ("figure5-paper", "case1-figure5", ()),
        ("figure5-default", "case1-figure5", DEFAULT),
        ("case1-zero-adhesive", "case1-inclined-adhesive-zero-thickness", ()),
        ("case1-zero-frictional", "case1-inclined-frictional-zero-thickness", ()),
        ("prandtl-paper", "prandtl-strip-footing", ()),
        ("prandtl-default", "prandtl-strip-footing", DEFAULT),
    ]
    for case, scene in (("case2", "case2-strip-footing"), ("case3", "case3-circular-footing")):
        runs += [
            (case + "-paper", scene, ("Output/Write VTU=false",)),
            (case + "-default", scene, DEFAULT + ("Output/Write VTU=false",)),
            (case + "-better-paper", scene + "-better-mesh", ("Output/Write VTU=false",)),
            (case + "-better-default", scene + "-better-mesh", DEFAULT + ("Output/Write VTU=false",)),
            (case + "-zero", scene + "-zero-thickness", ("Output/Write VTU=false",)),
        ]
    runs += [
        ("case3-displacement", "case3-circular-footing-displacement", ("Output/Write VTU=false",)),
        ("case4-smooth-paper", "case4-smooth-wall", ("Output/Write VTU=false",)),
        ("case4-figure12-paper", "case4-figure12", ()),
        ("case4-smooth-default", "case4-smooth-wall", DEFAULT + ("Output/Write VTU=false",)),
        ("case4-figure12-default", "case4-figure12", DEFAULT),
        ("case4-rough-accelerated", "case4-rough-wall-accelerated", ("Output/Write VTU=false",)),
        ("case4-zero", "case4-rough-wall-zero-thickness", ("Output/Write VTU=false",)),
    ]
    runs.append(("circular-footing-rigid", "circular-footing-rigid", ("Output/Write VTU=false",)))
    # The limit, not the knee: rigid footings by load and by settlement.
    runs += limits.run_list(quick)
    # The body's own weight: a vertical cut by gravity loading.
    runs += weight.run_list(quick)
    # Earth pressure from the at-rest state: Rankine on a smooth wall.
    runs += earth_pressure.run_list(quick)
    # Active earth pressure on a rough wall, against Coulomb and Rankine.
    runs += wall_friction.run_list(quick)
    # Safety factors by strength reduction.
    runs += strength_reduction.run_list(quick)
    # Bearing capacity factors (a surcharge from the K0 procedure).
    runs += bearing_capacity.run_list(quick)
    # Loading phases: a block pressed, then pushed until it slides.
    runs += phases.run_list(quick)
    # A pile's shaft resistance on interface elements (harmonic 0).
    runs += pile.run_list(quick)
    # A pile loaded laterally (harmonics 0-3).
    runs += pile_lateral.run_list(quick)
    # Curved interfaces: a pile section sliding on a circle.
    runs += curved.run_list(quick)
    # Interface tractions recovered at the nodes, beside the raw ones.
    runs += tractions.run_list(quick)
    # The same scenes on several MPI ranks (the fourth field), for the
    # section on ranks: every kinematics and element kind, each method kind.
    runs += parallel.ONE_RANK_RUNS
    runs += [(name + "-%dranks" % ranks, scene, overrides + ("Output/Write VTU=false",), ranks)
             for name, scene, overrides, ranks in parallel.RUNS]
    runs += [(parallel.amg_run_name(name, ranks), scene, overrides + ("Output/Write VTU=false",),
              ranks) for name, scene, overrides, ranks in parallel.AMG_RUNS]
    # How the stepping reaches a collapse: the programme, adaptive steps,
    # work control.
    runs += continuation.run_list(quick)
    # Time and memory against size and ranks.
    runs += scaling.run_list(quick)
    # 3D bodies: Case 1 extruded, the rigid disc both ways.
    runs += solid.run_list(quick)
    for material, scene in (("adhesive", "case1-stability-map"),
                            ("frictional", "case1-frictional-stability-map")):
        for method in (("viscoplastic", "default") if quick else METHOD_NAMES):
            runs.append(("map-%s-%s" % (material, method), scene, METHOD_NAMES[method]))
    # Why thinner layers needed tighter tolerances: the paper's method on the
    # stability maps (the adhesive one only in --quick), one change at a time.
    scenes = {"adhesive": "case1-stability-map", "frictional": "case1-frictional-stability-map"}
    runs += [("hypothesis-%s-%s" % (material, name), scenes[material], PAPER + overrides)
             for material in methods.hypothesis_materials(quick)
             for name, _, overrides in methods.HYPOTHESES]
    return runs


def run_one(directory, name, scene, overrides, ranks=1):
    """One run into DIR/runs/NAME, its output into DIR/logs/NAME.log: its
    exit status and wall time."""
    command = mpirun(ranks) + [THINLAYER, os.path.join(TOP, "prm", scene + ".prm")] + \
        command_line_overrides(["Output/Directory=" + os.path.join(directory, "runs", name),
                                "Output/Print timing=false"] + list(overrides))
    begun = time.time()
    done = subprocess.run(command, capture_output=True, text=True)
    with open(os.path.join(directory, "logs", name + ".log"), "w") as f:
        f.write(done.stdout + done.stderr)
    return done.returncode, time.time() - begun


def alone(run):
    """Whether a run must have the machine to itself: one on several ranks,
    or one whose time per iteration the scaling section models."""
    name, _, _, *ranks = run
    return (ranks and ranks[0] > 1) or name.startswith("scaling-")


def run_all(runs, directory, jobs=1):
    """Each run with a progress line as it ends; a run that ends in an error
    stops the reproduction (non-convergence is a result, not an error). With
    @p jobs > 1 the runs that need not run alone (alone()) run that many at
    a time, then the others one by one."""
    start = time.time()
    shared = [r for r in runs if jobs > 1 and not alone(r)]
    ordered = shared + [r for r in runs if r not in shared]

    def report(k, run, status, seconds):
        name, scene = run[0], run[1]
        print("[%2d/%d] %-28s %s  %6.1f s  (%.0f s in all)" % (
            k, len(ordered), name, "prm/%s.prm" % scene, seconds, time.time() - start),
            flush=True)
        if status != 0:
            print("reproduce: %s failed (exit %d); its output is in %s" % (
                name, status, os.path.join(directory, "logs", name + ".log")), file=sys.stderr)
            sys.exit(1)

    k = 0
    if shared:
        with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
            futures = {pool.submit(run_one, directory, *run): run for run in shared}
            for future in concurrent.futures.as_completed(futures):
                k += 1
                report(k, futures[future], *future.result())
    for run in ordered[len(shared):]:
        k += 1
        report(k, run, *run_one(directory, *run))


def run_benchmark(directory, quick, jobs=1):
    """benchmarks/run.py's speed-against-accuracy matrix; in --quick, @p
    jobs cases at a time (the full report times each case alone)."""
    run_into(directory, "run", ["--quick", "--repeat", "1", "--jobs", str(jobs)] if quick
             else ["--repeat", "3"], "speed-against-accuracy")


def run_into(directory, module, arguments, what):
    """python3 -m benchmarks.MODULE with @p arguments into DIR/benchmarks;
    the reproduction stops, naming @p what, if it fails."""
    arguments = ["--output", os.path.join(directory, "benchmarks")] + arguments
    print("benchmark: python3 -m benchmarks.%s %s" % (module, " ".join(arguments)), flush=True)
    if run_module("benchmarks." + module, arguments).returncode != 0:
        sys.exit("reproduce: the %s benchmark failed" % what)


def run_performance(directory, quick):
    """benchmarks/performance.py's time to answer."""
    run_into(directory, "performance", speed.benchmark_arguments(quick), "time-to-answer")


def run_linear_solvers(directory, quick):
    """benchmarks/linear_solvers.py's solvers against each other."""
    run_into(directory, "linear_solvers", speed.linear_solvers_arguments(quick), "linear-solver")


def run_adaptivity(directory, quick):
    """benchmarks/adaptivity.py's cycles against uniform refinement."""
    run_into(directory, "adaptivity", adaptivity.benchmark_arguments(quick),
             "adaptive-refinement")


def run_fourier_vs_3d(directory, quick):
    """benchmarks/fourier_vs_3d.py's Case 3 by harmonics and in 3D."""
    run_into(directory, "fourier_vs_3d", solid.benchmark_arguments(quick), "Fourier-or-3D")


def sections(runs, quick):
    return (case1.sections(runs, quick) + footings.sections(runs, quick)
            + case4.sections(runs, quick) + methods.sections(runs, quick)
            + limits.sections(runs, quick) + weight.sections(runs, quick)
            + earth_pressure.sections(runs, quick)
            + wall_friction.sections(runs, quick)
            + strength_reduction.sections(runs, quick)
            + bearing_capacity.sections(runs, quick)
            + phases.sections(runs, quick) + pile.sections(runs, quick)
            + pile_lateral.sections(runs, quick)
            + curved.sections(runs, quick) + tractions.sections(runs, quick)
            + continuation.sections(runs, quick) + speed.sections(runs, quick)
            + parallel.sections(runs, quick) + scaling.sections(runs, quick)
            + solid.sections(runs, quick) + adaptivity.sections(runs, quick))


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true", help="smaller sweeps, one-pass benchmark")
    parser.add_argument("--output", default=os.path.join(TOP, "output", "reproduce"),
                        help="the report's directory (replaced when the new report is written)")
    parser.add_argument("--jobs", type=int, default=1,
                        help="runs at a time (those on one rank that no section times; "
                             "the others always alone)")
    parser.add_argument("--report-only", action="store_true",
                        help="rewrite report.html from the runs in the directory")
    arguments = parser.parse_args()
    directory = os.path.abspath(arguments.output)
    start = time.time()
    # A reproduction is written beside DIR and put in its place when the
    # page is written: an error or an interruption leaves the previous one.
    work = directory if arguments.report_only else directory + ".partial"
    if not arguments.report_only:
        if not os.access(THINLAYER, os.X_OK):
            sys.exit("reproduce: no thinlayer binary at %s: run scripts/reproduce.sh" % THINLAYER)
        if os.path.isdir(work):
            shutil.rmtree(work)
        os.makedirs(os.path.join(work, "logs"))
        jobs = max(1, arguments.jobs)
        run_all(run_list(arguments.quick), work, jobs)
        with open(os.path.join(work, "jobs.txt"), "w") as f:
            f.write("%d\n" % jobs)
        run_benchmark(work, arguments.quick, jobs)
        run_performance(work, arguments.quick)
        run_linear_solvers(work, arguments.quick)
        run_fourier_vs_3d(work, arguments.quick)
        run_adaptivity(work, arguments.quick)
    runs = Runs(work)
    print("report: drawing the figures", flush=True)
    items = sections(runs, arguments.quick)
    page.write(os.path.join(work, "report.html"),
               "thinlayer reproduces Griffiths' thin-layer interfaces",
               introduction(arguments.quick, jobs_of(work)), items,
               footer(directory, runs, time.time() - start))
    if work != directory:
        if os.path.isdir(directory):
            shutil.rmtree(directory)
        os.rename(work, directory)
    print("report: %s (%d items, %.0f s)" % (os.path.join(directory, "report.html"), len(items),
                                             time.time() - start))


def jobs_of(directory):
    """How many runs at a time the runs in DIR were made (jobs.txt)."""
    try:
        with open(os.path.join(directory, "jobs.txt")) as f:
            return int(f.read())
    except (OSError, ValueError):
        return 1


def introduction(quick, jobs=1):
    return [
        "D.V. Griffiths, Numerical modelling of interfaces using conventional finite "
        "elements: each table and figure of the paper beside what thinlayer computes, by "
        "the paper's method (viscoplastic constant-stiffness iterations with its body-load "
        "criterion) and by thinlayer's default method (accelerated initial stress with a "
        "Newton fallback), each on the scene file's load programme, a failed step cut back "
        "until the collapse is bracketed to 0.5% of the load; then the validations against closed forms, the "
        "stability maps and the speed against accuracy of every method.",
        "The paper's values are read from its text and tables; its figures' curves are "
        "not in the text we have, so a figure's verdict compares what the text says of it. "
        "Curves join converged states only; an x marks the attempt that ended a run.",
    ] + (["This is the --quick report: smaller sweeps and a benchmark run once, for CI."]
         if quick else []) + (["Its scenes on one rank ran %d at a time: their wall times are "
                               "those of a shared machine (%s, the scaling and the runs on "
                               "several ranks ran alone)." % (
                                   jobs, "the benchmarks but the methods' matrix, which ran "
                                   "%d cases at a time" % jobs if quick else "the benchmarks")]
                              if jobs > 1 else [])


def footer(directory, runs, seconds):
    return ("Written by thinlayer_tools/reproduce.py from the runs in %s/runs (every run's "
            "history.csv, summary.json, mesh.msh and parameters.prm are there) in %.0f s on %s; "
            "thinlayer %s." % (directory, seconds, runs.machine(), runs.version()))


if __name__ == "__main__":
    main()
