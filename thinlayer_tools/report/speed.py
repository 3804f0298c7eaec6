"""The report's section on time to answer: benchmarks/performance.py's
Prandtl runs, the default method against the paper's per mesh size, with
the targets the project set itself checked on the run."""
import csv
import math
import os

from thinlayer_tools import results, speed_targets
from thinlayer_tools.report import figures
from thinlayer_tools.report.page import Section

# The targets and their verdicts: thinlayer_tools.speed_targets, shared
# with the benchmark that prints them.
DEFAULT = speed_targets.DEFAULT


def benchmark_arguments(quick):
    """benchmarks/performance.py's arguments: 512 cells once for --quick
    (it exercises the script in CI's half hour), else 2048 to 32768 cells,
    the thin-layer scenes and the 3D scenes, medians of three, and the
    large 3D scene once."""
    return ["--cells", "512", "--repeat", "1"] if quick else \
        ["--cells", "2048,8192,32768", "--repeat", "3", "--scenes", "--scenes-3d", "0,1,2,3,4,5",
         "--large-3d"]


def read(directory):
    with open(os.path.join(directory, "performance.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for key in ("cells", "equations", "total_iterations", "factorisations",
                    "substitutions", "sweeps", "runs"):
            r[key] = int(r[key])
        for key in ("wall_median_s", "against_paper_fixed", "ms_per_iteration",
                    "ms_per_substitution", "ms_per_factorisation", "last_converged",
                    "bracket_low", "bracket_high"):
            r[key] = results.number(r[key])
    return rows


def fit_exponent(points):
    """The slope of log(time) against log(equations) of (equations, time)
    @p points, least squares; None with fewer than two sizes."""
    if len(points) < 2:
        return None
    xs = [math.log(e) for e, _ in points]
    ys = [math.log(t) for _, t in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx


def exponent(rows, way):
    """The least-squares exponent of time against equations (None: one size)."""
    return fit_exponent([(r["equations"], r["wall_median_s"]) for r in rows
                         if r["way"] == way])


def time_to_answer(runs, quick):
    directory = os.path.join(runs.directory, "benchmarks")
    rows = read(directory)
    by = {(r["cells"], r["way"]): r for r in rows}
    sizes = sorted({r["cells"] for r in rows})
    table = [["cells (equations)", "way", "outcome", "last converged load / (2+pi)c",
              "collapse load factor bracket (the run's)",
              "iterations",
              "factorisations", "substitutions", "wall s", "/ paper's fixed",
              "ms per iteration", "ms per substitution", "ms per factorisation"]]
    for r in rows:
        table.append(["%d (%d)" % (r["cells"], r["equations"]), r["way"], r["outcome"],
                      "%.4f" % r["last_converged"],
                      "%.4f - %.4f" % (r["bracket_low"], r["bracket_high"])
                      if math.isfinite(r["bracket_low"]) and math.isfinite(r["bracket_high"])
                      else "-",
                      "%d" % r["total_iterations"], "%d" % r["factorisations"],
                      "%d" % r["substitutions"], "%.2f" % r["wall_median_s"],
                      "%.2f" % r["against_paper_fixed"], "%.1f" % r["ms_per_iteration"],
                      "%.2f" % r["ms_per_substitution"],
                      "%.1f" % r["ms_per_factorisation"]
                      if r["ms_per_factorisation"] == r["ms_per_factorisation"] else "-"])
    verdicts = speed_targets.prandtl(rows, fit_exponent)
    missed = speed_targets.missed(verdicts)
    exponents = "; ".join("%s: %s" % (way, "%.2f" % e if e is not None else "one size")
                          for way, e in ((w, exponent(rows, w))
                                         for w in dict.fromkeys(r["way"] for r in rows)))
    why = ("Prandtl's strip footing. The paper's method: seven fixed steps to 1.04 (2 + pi)c "
           "at TOL 1e-3, its first failed step ending the run (a 2%% bracket at best), and "
           "the same TOL with automatic stepping to a 0.5%% bracket; the default method at "
           "TOL 1e-4 to a 0.5%% bracket, on the scene's programme (0.01 steps near "
           "collapse), on the paper's seven steps, with Newton's corrections solved by "
           "GMRES on a kept factor instead of a factor of every tangent, and with adaptive "
           "step lengths (Loading/Step length = adaptive: the programme's first step and "
           "end only, each step grown from the iterations of the last), and under work "
           "control (Loading/Control = work: each step prescribes the work of the load, "
           "the collapse found as the plateau of the load rather than bracketed). "
           "Fitted exponents of time against equations: %s. Targets (the same "
           "verdicts as the benchmark's): %s.%s" % (
               exponents, verdict_text(verdicts),
               " One run of 512 cells (--quick); the full report runs 2048 to 32768 "
               "cells, medians of three." if quick else " Medians of three runs."))
    return Section(
        "time-to-answer", "Time to answer: bracketing Prandtl's collapse load",
        "(not in the paper) the paper's viscoplastic method needs one factorisation for the "
        "analysis and many cheap iterations.",
        "beyond" if not missed else "differs", why, rows=table,
        figures=[(figures.embed(os.path.join(directory, "performance.png")),
                  "Median wall time to the collapse bracket (0.5% wide by automatic stepping; the paper's "
                  "fixed steps end at their first failure) against the equations, "
                  "log-log, per way; grey: the time of one substitution and of one "
                  "factorisation of the tangent (the floors of an iteration).")],
        cost="%.0f s of runs" % sum(r["wall_median_s"] * r["runs"] for r in rows),
        paper_value="(not in the paper)",
        our_value="default / paper's fixed: " + ", ".join(
            "%.2f at %d cells" % (by[(c, DEFAULT)]["against_paper_fixed"], c) for c in sizes))


def verdict_text(verdicts):
    """The verdicts of thinlayer_tools.speed_targets as one sentence's
    clauses: target (where): measured, met or missed."""
    return "; ".join("%s (%s): %s, %s" % (v["target"], v["where"], v["measured"], v["verdict"])
                     for v in verdicts)


def figure(text):
    """A load of a CSV field, to four places; '-' where there is none."""
    value = results.number(text)
    return "%.4f" % value if math.isfinite(value) else "-"


def scenes(runs, quick):
    """The thin-layer scenes' table (benchmarks/performance.py --scenes),
    with the iterations a step away from collapse checked."""
    path = os.path.join(runs.directory, "benchmarks", "performance-scenes.csv")
    if not os.path.isfile(path):
        return Section("time-to-answer-scenes", "Time to answer: the thin-layer scenes",
                       "(not in the paper)", "not run",
                       "Case 2 and Case 3 at their study meshes' level 2 run in the full "
                       "report only (benchmarks/performance.py --scenes).")
    rows = results.read_csv(path)
    table = [["scene", "equations", "way", "outcome", "collapse load", "knee", "iterations",
              "factorisations", "most iterations a step below 90% of the collapse",
              "wall s (median)"]]
    for r in rows:
        table.append([r["scene"], r["equations"], r["way"], r["outcome"],
                      figure(r["collapse_load"]), figure(r["knee_load"]), r["total_iterations"],
                      r["factorisations"], r["most_iterations_away"],
                      "%.2f" % float(r["wall_median_s"])])
    verdicts = speed_targets.scenes(rows)
    missed = speed_targets.missed(verdicts)
    why = ("Each scene at its study meshes' finest level (2), by the paper's method on the "
           "file's programme, by the default method, and by the default method under work "
           "control (Newton throughout, the collapse as the plateau of the load). The default method's iterations "
           "count the accelerated initial-stress attempt (up to 100 iterations in "
           "these plane-strain scenes, where a Newton step costs less than the "
           "accelerated method's whole limit; one substitution each) before Newton "
           "takes a step over. A step is away from collapse below 90%% of the collapse "
           "load. Targets (the same verdicts as the benchmark's): %s." % verdict_text(verdicts))
    return Section("time-to-answer-scenes", "Time to answer: the thin-layer scenes",
                   "(not in the paper)", "beyond" if not missed else "differs", why,
                   rows=table, cost="%.0f s of runs" % sum(
                       float(r["wall_median_s"]) * int(r["runs"]) for r in rows),
                   paper_value="(not in the paper)",
                   our_value="most iterations a step away from collapse: " + ", ".join(
                       r["most_iterations_away"] for r in rows
                       if r["way"] == speed_targets.SCENE_DEFAULT))


def scenes_3d(runs, quick):
    """The 3D scenes' table (benchmarks/performance.py --scenes-3d), with
    each target's verdict as the benchmark computed it."""
    path = os.path.join(runs.directory, "benchmarks", "performance-3d.csv")
    title = "Time to answer: the 3D scenes"
    if not os.path.isfile(path):
        return Section("time-to-answer-3d", title, "(not in the paper)", "not run",
                       "The rigid circular footing and Case 3 (interface elements, thin "
                       "layer) in 3D run in the full report only (benchmarks/performance.py "
                       "--scenes-3d), some minutes each.")
    rows = results.read_csv(path)
    table = [["scene", "DoFs", "way", "outcome", "collapse load", "error", "iterations",
              "factorisations", "Krylov iterations", "substitutions", "wall s (median)",
              "peak kB per DoF", "targets"]]
    for r in rows:
        error = results.number(r["relative_error"])
        table.append([r["scene"], r["dofs"], r["way"], r["outcome"], figure(r["collapse_load"]),
                      "%+.2f%%" % (100 * error) if math.isfinite(error) else "-",
                      r["total_iterations"], r["factorisations"], r["krylov_iterations"],
                      r["substitutions"], "%.1f" % float(r["wall_median_s"]),
                      "%.1f" % float(r["peak_kb_per_dof"]), r["verdict"]])
    missed = [r["scene"] + " (" + r["way"] + "): " + r["verdict"] for r in rows
              if r["way"] == speed_targets.SCENE_DEFAULT and "missed" in r["verdict"]]
    verdicts = speed_targets.scenes(rows, iterations=False) + speed_targets.large_3d(rows)
    missed += ["%s (%s): %s" % (v["target"], v["where"], v["measured"])
               for v in speed_targets.missed(verdicts)]
    why = ("Each 3D scene on its file's mesh (the rigid footing, Case 3 with interface "
           "elements, Case 3 with its thin layer), by the default method (Newton's tangent "
           "factorised at every iteration), by the same with Newton's corrections by GMRES "
           "on a kept factor, by accelerated initial stress alone, by the default method "
           "with adaptive step lengths, on the scenes under load under work control, and by "
           "Newton's method alone. "
           "Asked of the default method: the rigid footing in at most 60 s with at most one "
           "factorisation per five Newton iterations, Case 3 with interface elements in at "
           "most 120 s; the answer most ways agree on, as fast as any other method's; a scene of at least %d DoFs on 2 ranks in at most %.0f s "
           "and %.0f kB per DoF. %s" % (
               speed_targets.LARGE_DOFS, speed_targets.LARGE_SECONDS,
               speed_targets.LARGE_KB_PER_DOF,
               "Met." if not missed else "Missed: " + "; ".join(missed) + "."))
    chart = os.path.join(runs.directory, "benchmarks", "performance-3d.png")
    shown = [(figures.embed(chart), "Median wall time of every way on every 3D scene "
              "(log scale); dashed: the scene's time target; hatched: a way that did not "
              "reach the scene's answer.")] if os.path.isfile(chart) else []
    return Section("time-to-answer-3d", title, "(not in the paper)",
                   "beyond" if not missed else "differs", why, rows=table, figures=shown,
                   cost="%.0f s of runs" % sum(
                       float(r["wall_median_s"]) * int(r["runs"]) for r in rows),
                   paper_value="(not in the paper)",
                   our_value="; ".join("%s by the %s: %.0f s" % (
                       r["scene"], r["way"], float(r["wall_median_s"])) for r in rows))


def linear_solvers_arguments(quick):
    """benchmarks/linear_solvers.py's arguments: Prandtl on 2048 cells once
    for --quick, else Prandtl on 8192 cells and the 3D rigid footing at
    about 40,000 and 120,000 DoFs, medians of three; one rank and two."""
    return ["--only", "Prandtl, 2048 cells", "--ranks", "1,2", "--repeat", "1"] if quick \
        else ["--only", "Prandtl, 8192 cells|3D rigid footing", "--ranks", "1,2",
              "--repeat", "3"]


def linear_solvers(runs, quick):
    """The solvers of the elastic stiffness against each other
    (benchmarks/linear_solvers.py), and whether Solver/Linear solver =
    automatic picks the fastest."""
    path = os.path.join(runs.directory, "benchmarks", "linear_solvers.csv")
    rows = results.read_csv(path)
    table = [["scene", "equations", "ranks", "solver", "set-up s (with 10 solves)",
              "s per solve", "CG iterations per solve", "peak MB per rank", "note"]]
    def number(text, form):
        value = results.number(text)
        return form % value if math.isfinite(value) else "-"

    for r in rows:
        table.append([r["scene"], r["equations"] or "-", r["ranks"], r["solver"],
                      number(r["setup_s"], "%.2f"), number(r["solve_s"], "%.4f"),
                      number(r["cg_iterations"], "%.0f"), number(r["peak_mb_per_rank"], "%.0f"),
                      r["note"]])
    verdicts = speed_targets.automatic_solver(rows)
    missed = speed_targets.missed(verdicts)
    why = ("One elastic load step per run, the elastic stiffness factorised (CHOLMOD on one "
           "rank, MUMPS on several, without and with its block low-rank compression to 1e-8 "
           "of the matrix's norm) or solved by conjugate gradients with PETSc's GAMG (not on "
           "the 3D footing, whose multigrid set-up outlasts the rest of this benchmark). "
           "Solver/Linear solver = automatic picks CHOLMOD on one rank and, on several, the "
           "compressed MUMPS factor for a 3D mesh and the uncompressed one for a plane mesh "
           "(whose fronts are too small to compress); the verdict asks whether that pick is the fastest per "
           "solve, times within %.0f%% counting as equal: %s.%s" % (
               100 * speed_targets.TIME_NOISE, verdict_text(verdicts),
               " Prandtl on 2048 cells once (--quick); the full report runs Prandtl on 8192 "
               "cells and the 3D footing at about 40,000 and 120,000 DoFs, medians of three."
               if quick else " Medians of three runs."))
    return Section(
        "linear-solvers", "The linear algebra, chosen automatically",
        "(not in the paper) one factorisation of the stiffness.",
        "beyond" if verdicts and not missed else "differs", why, rows=table,
        cost="%.0f s of runs" % sum(results.number(r["wall_s"]) for r in rows if r["wall_s"]),
        paper_value="(not in the paper)",
        our_value="automatic picks the fastest in %d of %d scenes and rank counts" % (
            len(verdicts) - len(missed), len(verdicts)))


def sections(runs, quick):
    return [time_to_answer(runs, quick), scenes(runs, quick), scenes_3d(runs, quick),
            linear_solvers(runs, quick)]
