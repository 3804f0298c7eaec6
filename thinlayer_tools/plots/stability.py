#!/usr/bin/python3
"""Stability map of a sweep over aspect ratio and tolerance.

    /usr/bin/python3 -m thinlayer_tools.plots.stability OUTPUT_DIR

Reads OUTPUT_DIR/sweep.csv (swept over aspect_ratio and Solver/Tolerance)
and each run's history.csv, and writes stability.png: for every aspect ratio
and tolerance, the error of the last converged load against the analytic
value ('x' where no step failed, i.e. collapse was not detected) and the
drift into illegal stress space, the largest max_yield_ratio over the
converged steps. stability.md has the same as a table.
"""
import argparse
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from thinlayer_tools import results  # noqa: E402


def main(directory):
    with open(os.path.join(directory, "sweep.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    ratios = sorted({r["aspect_ratio"] for r in rows}, key=float)
    tols = sorted({r["Solver/Tolerance"] for r in rows}, key=float, reverse=True)
    error = [[math.nan] * len(tols) for _ in ratios]
    drift = [[math.nan] * len(tols) for _ in ratios]
    detected = [[False] * len(tols) for _ in ratios]
    lines = ["| aspect ratio | TOL | outcome | error | drift (max yield ratio) "
             "| iterations |", "|---|---|---|---|---|---|"]
    for r in rows:
        i, j = ratios.index(r["aspect_ratio"]), tols.index(r["Solver/Tolerance"])
        with open(os.path.join(directory, "run-%03d" % int(r["run"]), "history.csv"),
                  newline="") as f:
            steps = results.states(list(csv.DictReader(f)))
        ratios_of_steps = [results.number(s["max_yield_ratio"]) for s in steps
                           if math.isfinite(results.number(s["max_yield_ratio"]))]
        detected[i][j] = results.collapse_detected(r)
        # An error only where there is a collapse load.
        error[i][j] = (100 * results.collapse_error(r)
                       if detected[i][j] and results.collapse_error(r) is not None else math.nan)
        drift[i][j] = max(ratios_of_steps) if ratios_of_steps else math.nan
        lines.append("| %s | %s | %s | %s | %.2e | %s |" % (
            r["aspect_ratio"], r["Solver/Tolerance"], r["outcome"],
            "%+.1f%%" % error[i][j] if detected[i][j] else "-", drift[i][j],
            r["total_iterations"]))

    fig, axes = plt.subplots(1, 2, figsize=(12, 4))
    panels = [(error, "error of the collapse load (%)", "RdBu_r", False),
              (drift, "drift: log10 max yield ratio", "viridis", True)]
    for ax, (data, title, cmap, log) in zip(axes, panels):
        shown = [[math.log10(v) if log and v > 0 else (v if not log else math.nan)
                  for v in row] for row in data]
        limit = max([abs(v) for row in shown for v in row if not math.isnan(v)], default=1) or 1
        image = ax.imshow(shown, cmap=cmap, aspect="auto",
                          vmin=-limit if not log else None, vmax=limit if not log else None)
        fig.colorbar(image, ax=ax)
        for i in range(len(ratios)):
            for j in range(len(tols)):
                text = ("x" if not detected[i][j] and not log else
                        "%+.0f" % data[i][j] if not log else "%.0e" % data[i][j])
                ax.text(j, i, text, ha="center", va="center", fontsize=7)
        ax.set_xticks(range(len(tols)))
        ax.set_xticklabels(tols)
        ax.set_yticks(range(len(ratios)))
        ax.set_yticklabels(ratios)
        ax.set_xlabel("tolerance TOL")
        ax.set_ylabel("interface aspect ratio")
        ax.set_title(title + ("\n(x: collapse not detected)" if not log else ""), fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "stability.png"), dpi=120)
    results.record(os.path.join(directory, "stability.png"))
    with open(os.path.join(directory, "stability.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    results.record(os.path.join(directory, "stability.md"))
    print("\n".join(lines))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("directory", help="the results directory of a stability-map sweep")
    main(parser.parse_args().directory)
