"""The report's section on scaling: Prandtl's scene by the paper's method on
its seven fixed steps at growing meshes, on one rank and on two; the time
per iteration and the peak memory per rank measured, a model fitted to the
measurements and shown beside them, and the model's forecast for 10^6 to
10^8 unknowns on 1 to 1024 ranks.

The model (N unknowns, P ranks, plane strain):
  memory per rank  M = M_program + a N + b N log2(N) / P
      the loaded program (libraries, MPI; measured before the mesh is
      read), what every rank holds whole (the mesh as read, kept beside
      the rank's part of the split mesh) and what is split (the split
      mesh, DoF maps and constraints, the point states, the vectors, the
      matrix rows and the factor, whose fill grows as N log N for a 2D
      nested-dissection ordering);
  time per iteration  T = c N / P + d N + e N log2(N) / P + h [P > 1]
      the point rules and vector operations split over the ranks, the work
      every rank does on whole data (none is left in an iteration: the
      monitors and outputs read each rank's own cells), the substitution
      with a factor split
      over the ranks, and the latency of the exchanges (ghost values,
      reductions) a run on several ranks makes each iteration.
The coefficients are non-negative least-squares fits to the runs of this
section; the forecast extrapolates them, with the limits stated beside it.
"""
import itertools
import math

import numpy

from thinlayer_tools.cases import PAPER_FIXED_STEPS, PRANDTL_SIZES
from thinlayer_tools.report.page import Section
from thinlayer_tools.report.parallel import LOAD_AGREEMENT, compare_with_one_rank
from thinlayer_tools.report.runs import PAPER

CELLS = (512, 2048, 8192, 32768)
# --quick keeps three sizes for the fits, the largest a quarter of the
# full report's second.
QUICK_CELLS = (128, 512, 2048)
RANKS = (1, 2)
FORECAST_UNKNOWNS = (1e6, 1e7, 1e8)
FORECAST_RANKS = (1, 16, 128, 1024)
# Memory per core of a typical cluster node (MB), the budget of a rank.
RANK_BUDGET_MB = 4096


def name(cells, ranks):
    return "scaling-%d-%dranks" % (cells, ranks)


def run_list(quick):
    """The section's runs, in the reproduction's form (name, scene,
    overrides, ranks)."""
    return [(name(cells, ranks), "prandtl-strip-footing",
             PAPER + PAPER_FIXED_STEPS + ("Mesh/Geometry parameters=" + PRANDTL_SIZES[cells],
                                          "Mesh/Maximum cells=200000",
                                          "Output/Write VTU=false"), ranks)
            for cells in (QUICK_CELLS if quick else CELLS) for ranks in RANKS]


def memory_terms(n, p):
    return [n, n * math.log2(n) / p]


def rest_terms(n, p):
    """An iteration beside its substitution."""
    return [n / p, n]


def substitution_terms(n, p):
    """One rank's CHOLMOD, several ranks' MUMPS and their latency."""
    return ([n * math.log2(n), 0.0, 0.0] if p == 1
            else [0.0, n * math.log2(n) / p, 1.0])


def fit(rows, terms, values):
    """Least squares with no coefficient negative (no cost is): every
    subset of the few terms is fitted, and the best fit whose coefficients
    are all non-negative is kept. Absolute errors, so that the largest
    runs, whose factors no longer fit the processor's caches as the
    forecast's will not, weigh most."""
    matrix = numpy.array([terms(*r) for r in rows], dtype=float)
    values = numpy.array(values, dtype=float)
    best, best_residual = numpy.zeros(matrix.shape[1]), math.inf
    for subset in itertools.chain.from_iterable(
            itertools.combinations(range(matrix.shape[1]), k)
            for k in range(1, matrix.shape[1] + 1)):
        columns = list(subset)
        coefficients = numpy.zeros(matrix.shape[1])
        coefficients[columns], *_ = numpy.linalg.lstsq(matrix[:, columns], values, rcond=None)
        residual = float(numpy.sum((matrix @ coefficients - values) ** 2))
        if min(coefficients) >= 0 and residual < best_residual:
            best, best_residual = coefficients, residual
    return best


def evaluate(coefficients, terms, n, p):
    return float(numpy.dot(coefficients, terms(n, p)))


def measure(runs, cells_list):
    """Each run's figures, and whether every run on two ranks agrees with
    its one-rank run."""
    measured, agree = [], True
    for cells in cells_list:
        one = runs.summary(name(cells, 1))
        for ranks in RANKS:
            s = runs.summary(name(cells, ranks))
            difference, same = compare_with_one_rank(s, one)
            agree = agree and same
            measured.append({
                "cells": cells, "n": s["equations"], "p": s["ranks"],
                "iteration": s["seconds_per_iteration"],
                "substitution": s["seconds_per_substitution"],
                "peak": s["peak_memory_mb_per_rank"],
                "program": s["program_memory_mb_per_rank"],
                "wall": s["wall_seconds"], "difference": difference})
    return measured, agree


class Model:
    """The model of the module's docstring fitted to the MEASURED runs."""

    def __init__(self, measured):
        self.program = max(m["program"] for m in measured)
        size = [(m["n"], m["p"]) for m in measured]
        self.memory_fit = fit(size, memory_terms,
                              [m["peak"] - self.program for m in measured])
        self.rest_fit = fit(size, rest_terms,
                            [m["iteration"] - m["substitution"] for m in measured])
        self.substitution_fit = fit(size, substitution_terms,
                                    [m["substitution"] for m in measured])

    def memory(self, n, p):
        return self.program + evaluate(self.memory_fit, memory_terms, n, p)

    def substitution(self, n, p):
        return evaluate(self.substitution_fit, substitution_terms, n, p)

    def iteration(self, n, p):
        return evaluate(self.rest_fit, rest_terms, n, p) + self.substitution(n, p)


def forecast(model):
    """The model's memory per rank and time per iteration beyond the runs."""
    rows = [["unknowns"] + ["%d ranks: MB per rank, s per iteration" % p
                            for p in FORECAST_RANKS]]
    for n in FORECAST_UNKNOWNS:
        row = ["%.0e" % n]
        for p in FORECAST_RANKS:
            mb = model.memory(n, p)
            row.append("%.0f MB%s, %.2g s" % (mb, " (over budget)" if mb > RANK_BUDGET_MB else "",
                                              model.iteration(n, p)))
        rows.append(row)
    return rows


def sections(runs, quick):
    cells_list = QUICK_CELLS if quick else CELLS
    measured, agree = measure(runs, cells_list)
    model = Model(measured)
    program = model.program
    memory, rest, substitution = model.memory_fit, model.rest_fit, model.substitution_fit

    table = [["cells", "unknowns", "ranks", "ms per iteration", "model",
              "of which substitution", "model", "peak MB per rank", "model",
              "last converged load vs 1 rank"]]
    worst, worst_run = 0.0, ""
    for m in measured:
        pairs = ((1e3 * m["iteration"], 1e3 * model.iteration(m["n"], m["p"])),
                 (1e3 * m["substitution"], 1e3 * model.substitution(m["n"], m["p"])),
                 (m["peak"], model.memory(m["n"], m["p"])))
        for a, b in pairs:
            if abs(b - a) / a > worst:
                worst, worst_run = abs(b - a) / a, "%d cells on %d" % (m["cells"], m["p"])
        table.append(["%d" % m["cells"], "%d" % m["n"], "%d" % m["p"]]
                     + ["%.1f" % v for pair in pairs[:2] for v in pair]
                     + ["%.0f" % v for v in pairs[2]] + ["%.1e" % m["difference"]])
    largest = max(cells_list)
    one = next(m for m in measured if m["cells"] == largest and m["p"] == 1)
    two = next(m for m in measured if m["cells"] == largest and m["p"] == 2)
    memory_ratio = two["peak"] / one["peak"]
    above_program = (two["peak"] - program) / (one["peak"] - program)
    time_ratio = two["iteration"] / one["iteration"]

    why = (
        "Measured on this machine (the report's footer names it), one run each. At %d cells "
        "two ranks take %.2f of one rank's time per iteration (the project's target: at most "
        "1.2) and %.2f of its peak memory per rank (target: at most 0.6); above the %.0f MB "
        "every rank spends on the loaded program itself (libraries and MPI, measured before "
        "the mesh is read) the ratio is %.2f. The model fitted to these runs (N unknowns, P "
        "ranks): memory per rank M = %.0f MB + %.2f kB N + %.3g kB N log2(N) / P; time per "
        "iteration T = %.3g us N / P + %.3g us N + S, with the substitution S = %.3g us "
        "N log2(N) on one rank (CHOLMOD) and %.3g us N log2(N) / P + %.3g ms on several "
        "(MUMPS). Its largest error is %.0f%% (%s): the small runs' factors fit the "
        "processor's caches, and the model, fitted to absolute times, follows the large "
        "ones, whose factors do not, as the forecast's will not. "
        "Its forecast below extrapolates far beyond the two ranks and the sizes measured, and "
        "is read for its limits: every rank still holds %.2f kB per unknown whole at its "
        "peak (the mesh as read, which each rank keeps beside its part of the split mesh for "
        "what spans the ranks, and the copy the split is cut from while setting up), so "
        "where that term is not zero a large enough run exceeds a rank's %d MB (a cluster "
        "core's share) whatever the ranks%s; freeing the mesh as read once the split exists "
        "is the next floor. %s" % (
            largest, time_ratio, memory_ratio, program, above_program,
            program, memory[0] * 1024, memory[1] * 1024,
            rest[0] * 1e6, rest[1] * 1e6, substitution[0] * 1e6, substitution[1] * 1e6,
            substitution[2] * 1e3,
            100 * worst, worst_run, memory[0] * 1024, RANK_BUDGET_MB,
            ", and the work on whole data (d N) bounds the time per iteration from below"
            if rest[1] > 0 else
            " (these runs fit no time on whole data, d = 0: two ranks cannot tell it from "
            "the split work, so the forecast's times on many ranks are a lower bound)",
            "Every run on two ranks has its one-rank run's outcome and converged loads within "
            "%.0e." % LOAD_AGREEMENT if agree else
            "Some runs on two ranks DIFFER from one rank's."))
    return [Section(
        "scaling", "Time and memory against ranks and size (MPI)",
        "(not in the paper) one process.",
        "beyond" if agree else "differs", why,
        rows=table + [[""] * len(table[0])] + forecast(model),
        cost="%.0f s for the %d runs" % (sum(m["wall"] for m in measured), len(measured)),
        paper_value="(not in the paper)",
        our_value="2 ranks: time x%.2f, memory x%.2f at %d cells" % (time_ratio, memory_ratio,
                                                                     largest))]
