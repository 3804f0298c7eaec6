#!/usr/bin/python3
"""Tables and figures of Griffiths' Case 1 from thinlayer sweeps.

Run with Debian's python3 (it has python3-matplotlib):

    /usr/bin/python3 -m thinlayer_tools.plots.case1 table1     output/case1-table1
    /usr/bin/python3 -m thinlayer_tools.plots.case1 figure3    output/case1-figure3
    /usr/bin/python3 -m thinlayer_tools.plots.case1 frictional output/case1-figure4
    /usr/bin/python3 -m thinlayer_tools.plots.case1 frictional output/case1-figure5

Each reads DIR/sweep.csv and the runs' history.csv files and writes PNG
(and for table1 a Markdown and a CSV table) into DIR.
"""
import argparse
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from thinlayer_tools import closed_form  # noqa: E402
from thinlayer_tools import results  # noqa: E402
from thinlayer_tools.report import figures  # noqa: E402
from thinlayer_tools.report.case1 import slip_panel  # noqa: E402


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def number(text):
    return float(text) if text not in ("", None) else math.nan


def table1(directory):
    """Computed collapse loads against P_ult/C_w = 1/(sin a cos a)."""
    rows = read_csv(os.path.join(directory, "sweep.csv"))
    alphas = sorted({float(r["alpha"]) for r in rows})
    ratios = sorted({r["aspect_ratio"] for r in rows}, key=float)
    tolerances = sorted({r["Solver/Tolerance"] for r in rows}, key=float, reverse=True)

    def find(alpha, ratio, tol):
        return next(r for r in rows if float(r["alpha"]) == alpha
                    and r["aspect_ratio"] == ratio and r["Solver/Tolerance"] == tol)

    lines = ["# Table 1: P_ult / C_w, computed against 1/(sin a cos a)", "",
             "'layer <=' is the upper bound of the layer the mesh models (a slip plane",
             "inside it, thinlayer_tools/closed_form.py): its exact collapse load is at most that.", ""]
    flat = [["alpha", "analytic", "aspect_ratio", "tolerance", "computed",
             "relative_error", "collapse_detected", "total_iterations"]]
    for tol in tolerances:
        lines += ["TOL = %s (computed value, error; '>' where no step failed, so"
                  " collapse was not detected within the load programme)" % tol, ""]
        lines += ["| alpha | analytic | " + " | ".join("AR %s" % a for a in ratios) + " |",
                  "|---|---|" + "---|" * len(ratios)]
        for alpha in alphas:
            cells = []
            for ratio in ratios:
                r = find(alpha, ratio, tol)
                detected = results.collapse_detected(r)
                # A collapse load and its error only for a collapse; the
                # others say what happened instead.
                bound = closed_form.inclined_layer_upper_bound(alpha, float(ratio))
                if detected:
                    cells.append("%.2f (%+.1f%%; layer <= %.2f)" % (
                        results.collapse_load(r), 100 * results.collapse_error(r), bound))
                else:
                    cells.append("%s at %.2f (layer <= %.2f)" % (
                        r["outcome"], number(r["last_converged_load"]), bound))
                flat.append([alpha, r["reference_load"], ratio, tol, r["collapse_load"],
                             r["relative_error"] if detected else "", int(detected),
                             r["total_iterations"]])
            lines.append("| %g | %.2f | %s |" % (alpha, number(find(alpha, ratios[0], tol)["reference_load"]),
                                                 " | ".join(cells)))
        lines.append("")
    with open(os.path.join(directory, "table1.md"), "w") as f:
        f.write("\n".join(lines))
    results.record(os.path.join(directory, "table1.md"))
    with open(os.path.join(directory, "table1.csv"), "w", newline="") as f:
        csv.writer(f).writerows(flat)
    results.record(os.path.join(directory, "table1.csv"))
    print("\n".join(lines))

    fig, axes = plt.subplots(1, len(tolerances), figsize=(5 * len(tolerances), 4), sharey=True)
    axes = axes if len(tolerances) > 1 else [axes]
    fine = [10 + 0.5 * i for i in range(141)]
    for ax, tol in zip(axes, tolerances):
        ax.plot(fine, [closed_form.inclined_interface_load(a) for a in fine],
                "k-", label="analytic (zero-thickness interface)")
        for ratio, marker in zip(ratios, "os^"):
            pts = [find(a, ratio, tol) for a in alphas]
            # The layer's own upper bound: its exact collapse load lies on
            # or below this line, whatever the solver.
            line, = ax.plot(fine, [closed_form.inclined_layer_upper_bound(a, float(ratio))
                                   for a in fine], ":", lw=1)
            detected = [results.collapse_detected(r) for r in pts]
            ax.plot([a for a, d in zip(alphas, detected) if d],
                    [results.collapse_load(r) for r, d in zip(pts, detected) if d],
                    marker, color=line.get_color(),
                    label="aspect ratio %s (dotted: the layer's upper bound)" % ratio)
            ax.plot([a for a, d in zip(alphas, detected) if not d],
                    [number(r["last_converged_load"]) for r, d in zip(pts, detected) if not d],
                    marker, mfc="none", color=ax.lines[-1].get_color())
        ax.set_title("TOL = %s (open: no collapse; last converged load)" % tol)
        ax.set_xlabel("interface inclination alpha (degrees)")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("P_ult / C_w")
    axes[0].legend()
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "table1.png"), dpi=120)
    results.record(os.path.join(directory, "table1.png"))


def figure3(directory):
    """Load against displacement for each inclination and aspect ratio."""
    rows = read_csv(os.path.join(directory, "sweep.csv"))
    alphas = sorted({r["alpha"] for r in rows}, key=float)
    fig, axes = plt.subplots(2, len(alphas), figsize=(4.5 * len(alphas), 7),
                             gridspec_kw={"height_ratios": [2, 1]})
    for column, alpha in enumerate(alphas):
        ax, ax_it = axes[0][column], axes[1][column]
        for r in (r for r in rows if r["alpha"] == alpha):
            rows_of_run = figures.curve(ax, os.path.join(directory, "run-%03d" % int(r["run"])),
                                        "aspect ratio %s" % r["aspect_ratio"])
            h = results.states(rows_of_run)
            ax_it.plot([number(s["load"]) / number(r["reference_load"]) for s in h],
                       [int(s["iterations"]) for s in h], ".-", color=ax.lines[-3].get_color())
        ax.axhline(closed_form.inclined_interface_load(float(alpha)), color="k", ls="--",
                   label="analytic")
        ax.set_title("alpha = %s degrees" % alpha)
        ax.set_xlabel("axial displacement of the top, E u / (C_w b)")
        ax.grid(alpha=0.3)
        ax_it.set_xlabel("P / P_ult")
        ax_it.set_yscale("log")
        ax_it.grid(alpha=0.3)
    axes[0][0].set_ylabel("axial stress P / C_w")
    axes[1][0].set_ylabel("iterations per step")
    figures.failure_legend(axes[0][0], fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "figure3.png"), dpi=120)
    results.record(os.path.join(directory, "figure3.png"))
    print("wrote", os.path.join(directory, "figure3.png"))


def frictional(directory):
    """Per value of the other swept entry (TOL or the layer's modulus), a
    panel: the top's displacement at full load where the layer held, 'x'
    where it slid (a failed step: no state to plot)."""
    rows = read_csv(os.path.join(directory, "sweep.csv"))
    swept = results.swept_names(rows)
    series_key = next(k for k in swept if k != "alpha")
    values = sorted({r[series_key] for r in rows}, key=float, reverse=True)
    fig, axes = plt.subplots(1, len(values), figsize=(3.4 * len(values), 3.6), sharey=True,
                             squeeze=False)
    for ax, value in zip(axes[0], values):
        slip_panel(ax, [r for r in rows if r[series_key] == value],
                   "%s = %s" % (series_key.split("/")[-1], value))
    axes[0][0].set_ylabel("|u_x of the top| E / P")
    axes[0][0].legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    name = os.path.basename(os.path.normpath(directory)) + ".png"
    fig.savefig(os.path.join(directory, name), dpi=120)
    results.record(os.path.join(directory, name))
    print("wrote", os.path.join(directory, name))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("figure", choices=("table1", "figure3", "frictional"))
    parser.add_argument("directory", help="the results directory of the study")
    arguments = parser.parse_args()
    {"table1": table1, "figure3": figure3, "frictional": frictional}[arguments.figure](
        arguments.directory)
