"""The report's section on runs on several MPI ranks: scenes of every
kinematics and element kind run on one rank and on two or three, their
outcomes and loads compared."""
import math

from thinlayer_tools import results
from thinlayer_tools.report.page import Section
from thinlayer_tools.report.runs import DEFAULT

# The default method's runs are compared at a tolerance of 1e-6: at its
# scenes' 1e-4 the load (a reaction) of a converged state is itself 2e-7
# off the applied load on Prandtl's footing, and runs on one rank and on
# two, or with AMG-CG, differed by 2e-7 to 1.4e-6 from one machine to
# another, the tolerance's share and not rounding; at 1e-6 they agree to
# 1e-15, in the same time.
TIGHT = ("Solver/Tolerance=1e-6",)
# (one-rank run, its scene, its overrides, ranks): the reproduction runs
# each scene on one rank as NAME (ONE_RANK_RUNS) and again on RANKS ranks as
# NAME-<RANKS>ranks. The paper's method's runs are the report's own.
CASE1_AR1000 = ("Mesh/Geometry parameters=alpha=30, aspect_ratio=1000, elements_along=8, "
                "elements_block=8",)
RUNS = [
    ("case1-ar1000-tight", "case1-inclined-adhesive", DEFAULT + CASE1_AR1000 + TIGHT, 2),
    ("case1-ar1000-tight", "case1-inclined-adhesive", DEFAULT + CASE1_AR1000 + TIGHT, 3),
    ("prandtl-tight", "prandtl-strip-footing", DEFAULT + TIGHT, 2),
    ("prandtl-tight", "prandtl-strip-footing", DEFAULT + TIGHT, 3),
    ("case2-zero", "case2-strip-footing-zero-thickness", (), 2),
    ("case2-zero", "case2-strip-footing-zero-thickness", (), 3),
    # Two harmonics: on 2 ranks one per rank (spread), on 3 split.
    ("case3-tight", "case3-circular-footing", DEFAULT + TIGHT, 2),
    ("case3-tight", "case3-circular-footing", DEFAULT + TIGHT, 3),
    ("case3-zero", "case3-circular-footing-zero-thickness", (), 2),
]
ONE_RANK_RUNS = list(dict.fromkeys(run[:3] for run in RUNS if run[0].endswith("-tight")))
# The iterative solver (Solver/Linear solver = amg cg) on one rank and two,
# each compared with the one-rank run of the direct solver: (that run, its
# scene, its overrides, ranks); run as NAME-amg-<RANKS>ranks.
AMG = ("Solver/Linear solver=amg cg",)
AMG_RUNS = [
    ("prandtl-tight", "prandtl-strip-footing", DEFAULT + TIGHT + AMG, 1),
    ("prandtl-tight", "prandtl-strip-footing", DEFAULT + TIGHT + AMG, 2),
    ("case3-tight", "case3-circular-footing", DEFAULT + TIGHT + AMG, 2),
]


def amg_run_name(name, ranks):
    """The name of the AMG-CG run of NAME's scene on RANKS ranks."""
    return "%s-amg-%dranks" % (name, ranks)
# Converged loads of several ranks must agree with one rank's this closely
# (the forces are summed in another order: rounding, not a model change).
LOAD_AGREEMENT = 1e-6


def compare_with_one_rank(summary, one):
    """The relative difference of SUMMARY's last converged load from ONE's
    (the same scene on one rank), and whether the two agree: the same
    outcome and that difference within LOAD_AGREEMENT."""
    difference = abs(results.number(summary["last_converged_load"])
                     - results.number(one["last_converged_load"])) \
        / abs(results.number(one["last_converged_load"]))
    return difference, summary["outcome"] == one["outcome"] and difference <= LOAD_AGREEMENT


def load(summary):
    """The collapse load, else the last converged one."""
    value = results.number(summary["collapse_load"])
    return value if math.isfinite(value) else results.number(summary["last_converged_load"])


def sections(runs, quick):
    table = [["scene (run)", "kinematics", "ranks", "linear solver (summary.json)", "outcome",
              "collapse load", "last converged load vs 1 rank", "wall s", "peak MB per rank"]]
    agree, seconds = True, 0.0
    # (row label, run, the one-rank direct run it is compared with)
    compared = []
    for name, _, _, ranks in RUNS:
        compared += [(name, name, name),
                     ("%s-%dranks" % (name, ranks),) * 2 + (name,)]
    compared += [(amg_run_name(name, ranks) + " (AMG-CG)", amg_run_name(name, ranks), name)
                 for name, _, _, ranks in AMG_RUNS]
    for label, run, one_rank_run in compared:
        s, one = runs.summary(run), runs.summary(one_rank_run)
        difference, same = compare_with_one_rank(s, one)
        agree = agree and same
        if run != one_rank_run:
            seconds += s["wall_seconds"]
        table.append([label, s["kinematics"], "%d" % s.get("ranks", 1),
                      s.get("linear_solver", "-"), s["outcome"] + ("" if same else " (DIFFERS)"),
                      "%.6g" % load(s) if results.collapse_detected(s) else "-",
                      "%.1e" % difference, "%.2f" % s["wall_seconds"],
                      "%.0f" % s["peak_memory_mb_per_rank"]])
    why = ("Each scene run on one rank and again under mpirun: the mesh split by cells "
           "(METIS, the two cells of a zero-thickness element together), each rank holding its "
           "own cells and a layer of ghost cells (a fully distributed triangulation), its own "
           "cells' point states, the constraint lines of the DoFs it holds and its own DoFs' "
           "entries of the vectors (with ghosts for its cells' other DoFs), the forces added "
           "into their owners, the elastic stiffness distributed by rows and factorised once "
           "by MUMPS (for a 3D mesh with its block low-rank compression to 1e-8 of the "
           "matrix's norm, as Solver/Linear solver = automatic chooses; the table names each "
           "run's solver; "
           "a Fourier scene with at least as many harmonics as ranks: each harmonic "
           "gathered and factorised whole on one rank, the ranks substituting at once), "
           "Newton's tangent distributed by rows and refactorised by MUMPS the same way; "
           "the outputs read each rank's own cells and rank 0 writes what one file holds. The runs "
           "marked AMG-CG solve the elastic stiffness by conjugate gradients with algebraic "
           "multigrid (Solver/Linear solver = amg cg, to a residual of 1e-10) instead of "
           "factors, on one rank and on two, and are compared with the one-rank direct run. "
           "The runs by the default method (named -tight) iterate to a tolerance of 1e-6 "
           "instead of their scenes' 1e-4, so that what remains of the difference is rounding "
           "(the forces summed and the factors computed in another order) and the CG "
           "tolerance: at 1e-4 the converged states themselves differ by up to the "
           "tolerance's share, 1e-6 of the load. %s The section asks for "
           "at most %.0e relative, and the same outcome. Time and memory against ranks and mesh "
           "size are in benchmarks/ranks.py, the solvers against each other in "
           "benchmarks/linear_solvers.py (the manual's benchmark page)." % (
               "Every run agrees with its one-rank run." if agree else
               "Some runs DIFFER from their one-rank run (marked).", LOAD_AGREEMENT))
    return [Section(
        "ranks", "Runs on several processes (MPI)",
        "(not in the paper) one process.",
        "beyond" if agree else "differs", why, rows=table,
        cost="%.0f s for the %d runs on several ranks or with AMG-CG" % (
            seconds, len(RUNS) + len(AMG_RUNS)),
        paper_value="(not in the paper)",
        our_value="outcomes identical, loads within %.0e" % LOAD_AGREEMENT if agree
        else "some runs differ")]
