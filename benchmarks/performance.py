#!/usr/bin/python3
"""Time to answer: Prandtl's strip footing bracketed to collapse, per mesh size.

    /usr/bin/python3 -m benchmarks.performance [--cells 2048,8192,32768] [--repeat 3]
    (also: /usr/bin/python3 -m benchmarks.run --performance)

For every mesh size (cells of thinlayer_tools.cases.PRANDTL_SIZES) three ways
to the collapse load (2 + pi)c:
- the paper's method on seven fixed load steps to 1.04 (0.5, 0.3, 0.1, 0.05,
  0.05, 0.02, 0.02) at TOL 1e-3, the first failed step ending the run (a 2%
  bracket at best);
- the paper's method with automatic stepping at TOL 1e-3, bracketed to 0.5%;
- the default method (no Solver/Method) with automatic stepping at TOL 1e-4,
  bracketed to 0.5%, on the file's programme (0.5, 3*0.1, 20*0.01, 10*0.02)
  and on the paper's seven steps;
- the default method on the file's programme with Newton's corrections
  solved by GMRES on a kept factor (Solver/Newton corrections = krylov)
  rather than by a factor of every tangent;
- the default method with adaptive step lengths (Loading/Step length =
  adaptive): the file's first step and end only, the steps between grown
  from the iterations of the last one;
- the default method under work control (Loading/Control = work): after
  the file's first step each step prescribes the work of the load, the
  load factor found with the displacements, the collapse reached as the
  plateau of the load.
Each row gives the outcome and bracket, the error of the collapse load, the
work (iterations, factorisations, substitutions, sweeps over the Gauss
points), the median wall time of --repeat runs and its ratio to the paper's
fixed programme, ms per iteration against the floors (one substitution,
one factorisation) and the peak memory; then the exponent of a least-squares
fit of time against equations per way, over the sizes run. Into
output/benchmarks/ (or --output): performance.csv, performance.md (printed
too) and performance.png (time against equations, log-log, the ways as
series, one substitution and one factorisation drawn as the floors).
Then, with --scenes, the benchmark scenes with thin layers at their study
meshes' finest level (2): Case 2 at aspect ratios 1000 and 10000, Case 3 at
10, each by the paper's method on the file's programme, by the default
method, and by the default method under work control, with the knee
beside the collapse and the most iterations an accepted step took away
from collapse (below 90% of the collapse load, or
of the last converged load where there is none): performance-scenes.csv
and .md.
Then, with --scenes-3d K,K, the 3D scenes on their files' meshes (the rigid
rough circular footing, Case 3 with interface elements and with its thin
layer) by the ways numbered K (the default method; the same with Newton's
corrections by GMRES on a kept factor; accelerated initial stress alone;
the default method with adaptive step lengths; under work control, on the
scenes under load; Newton's method alone), with the Krylov iterations,
the peak memory per DoF and each target's verdict (the rigid footing in
60 s with at most one factorisation per five Newton iterations, Case 3 in
120 s): performance-3d.csv and .md, and performance-3d.png (the time of
every way on every scene, the targets drawn, the ways that missed the
scene's answer hatched).
With --large-3d, the rigid footing on about 259,000 DoFs by the default
method on 2 ranks, once, stopped at the target's 900 s (a run still going
then has missed it), its memory the largest rank's peak times the ranks.
Under each table the targets' verdicts (thinlayer_tools.speed_targets).
Results are measurements, not tests: quote them with the machine.
"""
import argparse
import json
import math
import os
import subprocess
import time

from thinlayer_tools import THINLAYER, TOP, cases, mpirun, overrides, results, speed_targets
from thinlayer_tools.report.runs import DEFAULT as DEFAULT_METHOD, PAPER
from thinlayer_tools.report.speed import fit_exponent

from benchmarks import page
from benchmarks import run as common

# The paper's way: seven coarse fixed steps to 1.04 (2 + pi)c at TOL 1e-3
# (thinlayer_tools.cases.PAPER_FIXED_STEPS), the first failed step ending
# the run; the file's own programme of 0.01 steps at TOL 1e-4 stalls at
# 0.94 on 2048 cells (250 iterations a step), no answer.
PAPER_FIXED = PAPER + cases.PAPER_FIXED_STEPS
PAPER_AUTOMATIC = PAPER + ("Solver/Tolerance=1e-3", "Loading/Collapse resolution=0.005")
# The scene names the paper's method: the default one by name.
DEFAULT = DEFAULT_METHOD + ("Loading/Collapse resolution=0.005",)
# The default method on the paper's seven steps, cut back where they fail:
# how much of its time is the file's programme of 0.01 steps near collapse.
DEFAULT_SEVEN = DEFAULT + (cases.PAPER_FIXED_STEPS[1],)
# label, entries.
WAYS = [
    (speed_targets.PAPER_FIXED, PAPER_FIXED),
    ("paper's method, automatic stepping", PAPER_AUTOMATIC),
    (speed_targets.DEFAULT, DEFAULT),
    ("default method, 7 steps cut back", DEFAULT_SEVEN),
    ("default method, Newton's corrections by GMRES on a kept factor",
     DEFAULT + ("Solver/Newton corrections=krylov",)),
    ("default method, adaptive step length", DEFAULT + ("Loading/Step length=adaptive",)),
    ("default method, work control", DEFAULT + ("Loading/Control=work",)),
]
# The default method's tolerance (the paper's ways set theirs).
TOLERANCE = "1e-4"
PRM = "prm/prandtl-strip-footing.prm"


def measure(sizes, repeat, skip):
    """Every way on every size but the ways numbered in @p skip (cells:
    [way index]) there."""
    rows = []
    for cells in sizes:
        geometry = cases.PRANDTL_SIZES[cells]
        paper_time = None
        for k, (label, entries) in enumerate(WAYS):
            if k in skip.get(cells, ()):
                continue
            directory = os.path.join(common.OUT, "runs", "performance-%d-%d" % (cells, k))
            summary, median, peak = common.median_run(PRM, geometry, "cholmod", TOLERANCE,
                                                      directory, repeat, entries)
            if paper_time is None:
                paper_time = median
            # The bracket as the run states it (load factors); the load of
            # a failed state is no equilibrium and bounds nothing.
            bracket = summary.get("collapse_load_factor_bracket") or {}
            reference = summary["reference_load"]
            rows.append({
                "cells": summary["cells"], "equations": summary["equations"], "way": label,
                "method": summary["method"], "outcome": summary["outcome"],
                "last_converged": summary["last_converged_load"] / reference,
                "bracket_low": bracket.get("low"), "bracket_high": bracket.get("high"),
                "relative_error": results.collapse_error(summary),
                "total_iterations": summary["total_iterations"],
                "factorisations": summary["factorisations"],
                "substitutions": summary["substitutions"], "sweeps": summary["sweeps"],
                "wall_median_s": median, "runs": repeat,
                "against_paper_fixed": median / paper_time,
                "ms_per_iteration": 1e3 * summary["seconds_per_iteration"],
                "ms_per_substitution": 1e3 * summary["seconds_per_substitution"],
                "ms_per_factorisation": 1e3 * (summary["seconds_per_factorisation"] or math.nan),
                "peak_memory_mb": peak})
            print(rows[-1], flush=True)
    return rows


def table(rows):
    header = ("| cells | equations | way | outcome | last converged load / (2+pi)c "
              "| collapse load factor bracket "
              "| iterations | factorisations | substitutions | sweeps | wall s (median) "
              "| time / paper's fixed | ms per iteration | ms per substitution "
              "| ms per factorisation | peak MB |")

    def bracket(r):
        if r["bracket_low"] is None or r["bracket_high"] is None:
            return "-"
        return "%.4f - %.4f" % (r["bracket_low"], r["bracket_high"])

    common.write_results(
        rows, "performance", header,
        lambda r: "| %d | %d | %s | %s | %.4f | %s | %d | %d | %d | %d | %.2f | %.2f | %.1f "
                  "| %.2f | %s | %.0f |" % (
                      r["cells"], r["equations"], r["way"], r["outcome"], r["last_converged"],
                      bracket(r),
                      r["total_iterations"], r["factorisations"], r["substitutions"],
                      r["sweeps"], r["wall_median_s"], r["against_paper_fixed"],
                      r["ms_per_iteration"], r["ms_per_substitution"],
                      "-" if math.isnan(r["ms_per_factorisation"])
                      else "%.1f" % r["ms_per_factorisation"],
                      r["peak_memory_mb"]))
    lines = ["", "| way | exponent of time against equations | sizes |", "|---|---|---|"]
    for label, _ in WAYS:
        points = [(r["equations"], r["wall_median_s"]) for r in rows if r["way"] == label]
        exponent = fit_exponent(points)
        lines.append("| %s | %s | %d |" % (label, "%.2f" % exponent if exponent else "-",
                                           len(points)))
    lines += targets(speed_targets.prandtl(rows, fit_exponent))
    page.write(common.OUT, "performance", common.TITLES["performance"], lines, mode="a")


def targets(verdicts):
    """The targets' verdicts as markdown lines (page.write() prints them)."""
    return ["", "Targets:", ""] + speed_targets.table(verdicts)


def chart(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    for (label, _), style in zip(WAYS, ("o-", "s--", "^-", "v-", "d:", "x-.", "P-")):
        shown = [r for r in rows if r["way"] == label]
        ax.plot([r["equations"] for r in shown], [r["wall_median_s"] for r in shown], style,
                label=label)
    # The floors: one substitution (the paper's runs) and one factorisation
    # (the default method's tangents), per size.
    substitution = [r for r in rows if r["way"] == WAYS[0][0]]
    factorisation = [r for r in rows if r["way"] == WAYS[2][0]
                     and not math.isnan(r["ms_per_factorisation"])]
    ax.plot([r["equations"] for r in substitution],
            [1e-3 * r["ms_per_substitution"] for r in substitution], "x:", color="grey",
            label="one substitution")
    ax.plot([r["equations"] for r in factorisation],
            [1e-3 * r["ms_per_factorisation"] for r in factorisation], "+-.", color="grey",
            label="one factorisation")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("equations")
    ax.set_ylabel("wall time to the collapse bracket [s] (median)")
    ax.set_title("Prandtl's strip footing: time to answer", fontsize=9)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(common.OUT, "performance.png"), dpi=100)


# The thin-layer scenes: (case, aspect ratio) at mesh level 2, and the ways.
SCENES = [("case2", 1000), ("case2", 10000), ("case3", 10)]
SCENE_WAYS = [("paper", "paper's method, the scene's programme", ()),
              ("default", speed_targets.SCENE_DEFAULT, DEFAULT_METHOD),
              ("work", "default method, work control",
               DEFAULT_METHOD + ("Loading/Control=work",))]
# A step "away from collapse": below this share of the collapse load.
AWAY = 0.9


def most_iterations_away(directory, summary):
    """The most iterations of an accepted step whose load is below AWAY of
    the collapse load (of the last converged load where there is none)."""
    top = results.collapse_load(summary) or summary["last_converged_load"]
    steps = [r for r in results.states(results.history(directory))
             if abs(results.number(r["load"])) < AWAY * abs(top)]
    return max((int(r["iterations"]) for r in steps), default=0)


def measure_scenes(repeat):
    rows = []
    for case, aspect_ratio in SCENES:
        geometry = cases.geometry(case, 2, aspect_ratio)
        for short, label, entries in SCENE_WAYS:
            name = "performance-%s-%d-%s" % (case, aspect_ratio, short)
            directory = os.path.join(common.OUT, "runs", name)
            summary, median, peak = common.median_run(cases.PARAMETER_FILES[case], geometry,
                                                      "cholmod", "1e-4", directory, repeat,
                                                      entries)
            rows.append({
                "scene": "%s, aspect ratio %d" % (case, aspect_ratio),
                "equations": summary["equations"], "way": label, "outcome": summary["outcome"],
                "collapse_load": results.collapse_load(summary),
                "knee_load": results.number(summary.get("knee_load")),
                "total_iterations": summary["total_iterations"],
                "factorisations": summary["factorisations"],
                "substitutions": summary["substitutions"],
                "most_iterations_away": most_iterations_away(directory, summary),
                "wall_median_s": median, "runs": repeat, "peak_memory_mb": peak})
            print(rows[-1], flush=True)
    common.write_results(
        rows, "performance-scenes",
        "| scene | equations | way | outcome | collapse load | knee | iterations "
        "| factorisations | substitutions | most iterations a step below %.0f%% of the collapse "
        "| wall s (median) | peak MB |" % (100 * AWAY),
        lambda r: "| %s | %d | %s | %s | %s | %s | %d | %d | %d | %d | %.2f | %.0f |" % (
            r["scene"], r["equations"], r["way"], r["outcome"],
            "%.4f" % r["collapse_load"] if r["collapse_load"] is not None else "-",
            "%.4f" % r["knee_load"] if r["knee_load"] == r["knee_load"] else "-",
            r["total_iterations"], r["factorisations"], r["substitutions"],
            r["most_iterations_away"], r["wall_median_s"], r["peak_memory_mb"]))
    page.write(common.OUT, "performance-scenes", common.TITLES["performance-scenes"],
               targets(speed_targets.scenes(rows)),
               mode="a")
    return rows


# The 3D scenes on their files' meshes, each with its targets (seconds to
# the answer, None: none set; factorisations per Newton iteration) and
# whether it is loaded (not driven by prescribed displacements, so that
# work control applies), and the ways: the default method (Newton's
# tangent factorised at every iteration, whatever the file says), the same
# with Newton's corrections by GMRES on kept factors, the accelerated
# method alone, the default method with adaptive step lengths, under work
# control, and Newton's method alone (a factorisation per iteration).
SCENES_3D = [("prm/circular-footing-rigid-3d.prm", 60.0, 0.2, False),
             ("prm/case3-circular-footing-3d-zero-thickness.prm", 120.0, None, True),
             ("prm/case3-circular-footing-3d.prm", None, None, True)]
WAYS_3D = [(speed_targets.SCENE_DEFAULT,
            DEFAULT_METHOD + ("Solver/Newton corrections=factorised",)),
           ("default method, Newton's corrections by GMRES on a kept factor",
            DEFAULT_METHOD + ("Solver/Newton corrections=krylov",)),
           ("accelerated initial stress alone",
            ("Solver/Method=accelerated initial stress",
             "Solver/Convergence criterion=default")),
           ("default method, adaptive step length",
            DEFAULT_METHOD + ("Solver/Newton corrections=factorised",
                              "Loading/Step length=adaptive")),
           ("default method, work control",
            DEFAULT_METHOD + ("Solver/Newton corrections=factorised",
                              "Loading/Control=work")),
           ("Newton's method alone",
            ("Solver/Method=newton", "Solver/Convergence criterion=default"))]
# The ways that need a scene under load.
UNDER_LOAD_ONLY = {4}


def row_3d(scene, way, summary, seconds, runs, peak, verdict):
    """A row of performance-3d.csv: @p way on @p scene, from the run's
    @p summary, its (median) wall @p seconds over @p runs, @p peak MB."""
    return {
        "scene": scene, "equations": summary["equations"], "dofs": summary["dofs"],
        "way": way, "outcome": summary["outcome"],
        "collapse_load": results.collapse_load(summary),
        "relative_error": results.collapse_error(summary),
        "total_iterations": summary["total_iterations"],
        "factorisations": summary["factorisations"],
        "krylov_iterations": summary.get("krylov_iterations", 0),
        "substitutions": summary["substitutions"], "sweeps": summary["sweeps"],
        "ms_per_factorisation": 1e3 * (summary["seconds_per_factorisation"] or math.nan),
        "ms_per_substitution": 1e3 * summary["seconds_per_substitution"],
        "wall_median_s": seconds, "runs": runs, "peak_memory_mb": peak,
        "peak_kb_per_dof": 1024 * peak / summary["dofs"], "verdict": verdict}


def measure_scenes_3d(repeat, which, large=False):
    """Every way of WAYS_3D (numbered in @p which) on every 3D scene; with
    @p large, the large scene too (measure_large_3d())."""
    rows = []
    targets_s = {}
    for prm, seconds_target, factorisation_target, loaded in SCENES_3D:
        name = os.path.splitext(os.path.basename(prm))[0]
        for k, (label, entries) in enumerate(WAYS_3D):
            if k not in which or (k in UNDER_LOAD_ONLY and not loaded):
                continue
            directory = os.path.join(common.OUT, "runs", "performance-3d-%s-%d" % (name, k))
            summary, median, peak = common.median_run(prm, None, "cholmod", "1e-4",
                                                      directory, repeat, entries)
            newton = summary["total_iterations"]
            per_iteration = summary["factorisations"] / newton if newton else math.nan
            verdicts = ["at most %.0f s: %s" % (
                seconds_target, "met" if median <= seconds_target else "missed")] \
                if seconds_target is not None else []
            if factorisation_target is not None and \
                    "Solver/Method=accelerated initial stress" not in entries:
                verdicts.append("at most %.1f factorisations per iteration: %s (%.2f)" % (
                    factorisation_target,
                    "met" if per_iteration <= factorisation_target else "missed",
                    per_iteration))
            targets_s[name] = seconds_target
            rows.append(row_3d(name, label, summary, median, repeat, peak,
                               "; ".join(verdicts) or "no target set"))
            print(rows[-1], flush=True)
    if large:
        rows.append(measure_large_3d())
        targets_s[rows[-1]["scene"]] = speed_targets.LARGE_SECONDS

    def number(value, form):
        return form % value if value is not None and value == value else "-"

    common.write_results(
        rows, "performance-3d",
        "| scene | DoFs | way | outcome | collapse load | error | iterations "
        "| factorisations | Krylov iterations | substitutions | sweeps | ms per factorisation "
        "| ms per substitution | wall s (median) | peak MB | peak kB per DoF | targets |",
        lambda r: "| %s | %d | %s | %s | %s | %s | %d | %d | %d | %d | %d | %s | %.1f | %.1f "
                  "| %.0f | %.1f | %s |" % (
                      r["scene"], r["dofs"], r["way"], r["outcome"],
                      number(r["collapse_load"], "%.4f"),
                      number(r["relative_error"] and 100 * r["relative_error"], "%+.2f%%"),
                      r["total_iterations"], r["factorisations"], r["krylov_iterations"],
                      r["substitutions"], r["sweeps"], number(r["ms_per_factorisation"], "%.0f"),
                      r["ms_per_substitution"], r["wall_median_s"], r["peak_memory_mb"],
                      r["peak_kb_per_dof"], r["verdict"]))
    chart_3d(rows, targets_s)
    page.write(common.OUT, "performance-3d", common.TITLES["performance-3d"],
               targets(speed_targets.scenes(rows, iterations=False) +
                       speed_targets.large_3d(rows)), mode="a")
    return rows


# The large 3D scene: the rigid footing's file on a mesh of about 259,000
# DoFs (the counts around, along and down about doubled, the grading eased
# so that the largest cell is about as many times the smallest as on the
# file's mesh: 1.14^32 against 1.3^16; at 1.3 the smallest cells make the
# stiffness singular to the Gauss-point check), on LARGE_RANKS ranks,
# stopped at the target's time: a run still going then has missed it.
LARGE_PRM = "prm/circular-footing-rigid-3d.prm"
LARGE_GEOMETRY = ("sector=90, footing=0, half_width=1, width=5, depth=3, n_around=6, "
                  "n_footing=8, n_side=32, n_depth=38, growth=1.14")
LARGE_RANKS = 2


def run_until(prm, geometry, ranks, directory, entries, seconds):
    """Run @p prm on @p ranks ranks; at @p seconds ask it to stop (SIGTERM
    to the ranks: the run writes what it has, `outcome: interrupted`).
    Returns the summary and the wall seconds the run took."""
    command = mpirun(ranks) + [THINLAYER, os.path.join(TOP, prm)] + overrides(
        ["Mesh/Geometry parameters=" + geometry, "Output/Directory=" + directory,
         "Output/Write VTU=false", "Output/Print timing=false"] + list(entries))
    start, started = time.monotonic(), time.time()
    child = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                             text=True)
    try:
        child.wait(timeout=seconds)
    except subprocess.TimeoutExpired:
        # The ranks themselves: mpirun would end them without their results.
        subprocess.run(["pkill", "-TERM", "-P", str(child.pid)], check=False)
        if ranks == 1:
            child.terminate()
        child.wait()
    elapsed = time.monotonic() - start
    path = os.path.join(directory, "summary.json")
    # A summary older than the run is an earlier run's.
    if not os.path.isfile(path) or os.path.getmtime(path) < started:
        raise RuntimeError("%s ended with %d and wrote no summary: %s"
                           % (prm, child.returncode, child.stderr.read()))
    with open(path) as f:
        return json.load(f), elapsed


def measure_large_3d():
    """The default method on the large 3D scene, once (it runs up to its
    target's time): a row as measure_scenes_3d() writes, its memory that of
    all ranks (the largest rank's peak times the ranks)."""
    directory = os.path.join(common.OUT, "runs", "performance-3d-large")
    summary, seconds = run_until(LARGE_PRM, LARGE_GEOMETRY, LARGE_RANKS, directory,
                                 WAYS_3D[0][1], speed_targets.LARGE_SECONDS)
    peak = LARGE_RANKS * summary["peak_memory_mb_per_rank"]
    row = row_3d("circular-footing-rigid-3d, %d DoFs, %d ranks" % (summary["dofs"], LARGE_RANKS),
                 WAYS_3D[0][0], summary, seconds, 1, peak,
                 "stopped at %.0f s" % speed_targets.LARGE_SECONDS
                 if summary["outcome"] == "interrupted" else "-")
    print(row, flush=True)
    return row


def chart_3d(rows, targets_s):
    """performance-3d.png: the median wall time of every way on every 3D
    scene, bars grouped by scene, each scene's time target (@p targets_s:
    scene -> seconds or None) drawn; a way
    that did not reach the scene's answer (speed_targets.scene_answer())
    is hatched."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.patches
    import matplotlib.pyplot as plt
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    fig, ax = plt.subplots(figsize=(9.6, 4.6))
    width = 0.8 / len(WAYS_3D)
    seen = set()
    for k, (label, _) in enumerate(WAYS_3D):
        for i, scene in enumerate(scenes):
            here = [r for r in rows if r["scene"] == scene]
            row = next((r for r in here if r["way"] == label), None)
            if row is None:
                continue
            answer = speed_targets.scene_answer(here)
            reached = answer is not None and speed_targets.same_answer(answer)(row)
            ax.bar(i + (k - (len(WAYS_3D) - 1) / 2) * width, row["wall_median_s"], width,
                   color="C%d" % k, hatch=None if reached else "//", edgecolor="black",
                   linewidth=0.5, label=label if k not in seen else None)
            seen.add(k)
    for i, scene in enumerate(scenes):
        target = targets_s.get(scene)
        if target is not None:
            ax.plot([i - 0.45, i + 0.45], [target, target], "k--", linewidth=1)
    ax.plot([], [], "k--", linewidth=1, label="target")
    ax.add_artist(matplotlib.patches.Rectangle((0, 0), 0, 0, facecolor="white", hatch="//",
                                               edgecolor="black", linewidth=0.5,
                                               label="no answer (hatched)"))
    ax.set_xticks(range(len(scenes)))
    ax.set_xticklabels(scenes, fontsize=7)
    ax.set_yscale("log")
    ax.set_ylabel("wall time to the answer [s] (median)")
    ax.set_title("3D scenes: time to answer per way", fontsize=9)
    ax.grid(alpha=0.3, which="both", axis="y")
    ax.legend(fontsize=6, loc="upper left", bbox_to_anchor=(1.01, 1))
    fig.tight_layout()
    fig.savefig(os.path.join(common.OUT, "performance-3d.png"), dpi=100)


def performance(sizes, repeat, skip=None, scenes=False, scenes_3d=None, large_3d=False):
    os.makedirs(common.OUT, exist_ok=True)
    if sizes:
        rows = measure(sizes, repeat, skip or {})
        table(rows)
        chart(rows)
    if scenes:
        measure_scenes(repeat)
    if scenes_3d or large_3d:
        measure_scenes_3d(repeat, scenes_3d or [], large_3d)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cells", default="2048,8192,32768",
                        help="the mesh sizes, from %s (default %%(default)s)"
                        % ",".join(str(c) for c in cases.PRANDTL_SIZES))
    parser.add_argument("--repeat", type=int, default=3,
                        help="runs of each; times are their median (default 3)")
    parser.add_argument("--skip", default="",
                        help="ways not to run at a size, as CELLS:K,K;CELLS:K (K counts the "
                        "ways above from 0), e.g. 32768:1 for the paper's method's slow "
                        "automatic stepping on the finest mesh")
    parser.add_argument("--scenes", action="store_true",
                        help="also the thin-layer scenes (Case 2 and Case 3, level 2)")
    parser.add_argument("--scenes-3d", default="",
                        help="also the 3D scenes (the rigid circular footing, Case 3 with "
                        "interface elements) by the ways numbered K,K from 0 (0: the default "
                        "method, 1: the same with Newton's corrections by GMRES on a kept "
                        "factor, 2: accelerated initial stress alone, 3: the default method "
                        "with adaptive step lengths, 4: under work control, on the scenes "
                        "under load, 5: Newton's method alone), e.g. 0,1; --cells '' "
                        "runs them alone")
    parser.add_argument("--large-3d", action="store_true",
                        help="also the large 3D scene (the rigid footing at about 259,000 DoFs on "
                        "2 ranks) by the default method, once, stopped at %.0f s"
                        % speed_targets.LARGE_SECONDS)
    parser.add_argument("--output", default=common.OUT,
                        help="the results directory (default %(default)s)")
    page.add_argument(parser)
    arguments = parser.parse_args()
    page.configure(arguments)
    try:
        sizes = [int(c) for c in filter(None, arguments.cells.split(","))]
    except ValueError:
        parser.error("--cells: expected whole numbers separated by commas")
    try:
        scenes_3d = [int(k) for k in filter(None, arguments.scenes_3d.split(","))]
    except ValueError:
        parser.error("--scenes-3d: expected way numbers separated by commas, e.g. 0,1")
    if any(k not in range(len(WAYS_3D)) for k in scenes_3d):
        parser.error("--scenes-3d: ways are numbered 0 to %d" % (len(WAYS_3D) - 1))
    unknown = [c for c in sizes if c not in cases.PRANDTL_SIZES]
    if unknown:
        parser.error("--cells: no Prandtl mesh of %s cells (expected some of %s)"
                     % (unknown, ", ".join(str(c) for c in cases.PRANDTL_SIZES)))
    if arguments.repeat < 1:
        parser.error("--repeat: expected at least 1")
    skip = {}
    try:
        for part in filter(None, arguments.skip.split(";")):
            cells, ways = part.split(":")
            skip[int(cells)] = [int(k) for k in ways.split(",")]
    except ValueError:
        parser.error("--skip: expected CELLS:K,K;CELLS:K, e.g. 32768:1")
    common.OUT = os.path.abspath(arguments.output)
    performance(sizes, arguments.repeat, skip, arguments.scenes, scenes_3d, arguments.large_3d)


if __name__ == "__main__":
    main()
