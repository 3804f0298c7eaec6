#!/usr/bin/python3
"""Error against the analytic value, and cost, over a thinlayer sweep.

    /usr/bin/python3 scripts/plot_study.py OUTPUT_DIR X_NAME [SERIES_NAME]

Reads OUTPUT_DIR/sweep.csv (X_NAME and SERIES_NAME are swept names, e.g.
aspect_ratio and refinement) and writes study.png (relative error of the
collapse load, and wall time, against X_NAME, a line per SERIES_NAME value;
open markers where no step failed, i.e. collapse was not detected) and
study.md (the same as a table, with iterations and DoFs).
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def value(text):
    try:
        return float(text)
    except ValueError:
        return math.nan


def main(directory, x_name, series_name=None):
    with open(os.path.join(directory, "sweep.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    series = sorted({r[series_name] for r in rows}, key=value) if series_name else [None]
    fig, (ax_err, ax_time) = plt.subplots(1, 2, figsize=(11, 4))
    lines = ["| %s | %s | collapse detected | last converged load | relative error | "
             "iterations | DoFs | wall s |" % (x_name, series_name or ""),
             "|---|---|---|---|---|---|---|---|"]
    for s in series:
        pts = sorted((r for r in rows if series_name is None or r[series_name] == s),
                     key=lambda r: value(r[x_name]))
        xs = [value(r[x_name]) for r in pts]
        err = [100 * value(r["relative_error"]) for r in pts]
        detected = [r["converged"] == "0" for r in pts]
        label = "%s = %s" % (series_name, s) if series_name else None
        line, = ax_err.plot(xs, err, "-", label=label)
        ax_err.plot([a for a, d in zip(xs, detected) if d], [e for e, d in zip(err, detected) if d],
                    "o", color=line.get_color())
        ax_err.plot([a for a, d in zip(xs, detected) if not d],
                    [e for e, d in zip(err, detected) if not d], "o", mfc="white",
                    color=line.get_color())
        ax_time.plot(xs, [value(r["wall_seconds"]) for r in pts], "o-", label=label)
        for r, d in zip(pts, detected):
            lines.append("| %s | %s | %s | %s | %+.1f%% | %s | %s | %.2f |" % (
                r[x_name], s if s is not None else "", "yes" if d else "no",
                r["last_converged_load"], 100 * value(r["relative_error"]),
                r["total_iterations"], r["dofs"], value(r["wall_seconds"])))
    for ax in (ax_err, ax_time):
        ax.set_xlabel(x_name)
        ax.grid(alpha=0.3)
        if all(value(r[x_name]) > 0 for r in rows) and \
                max(value(r[x_name]) for r in rows) / min(value(r[x_name]) for r in rows) > 20:
            ax.set_xscale("log")
    ax_err.axhline(0, color="k", lw=0.8)
    ax_err.set_ylabel("collapse load error against analytic (%)")
    ax_err.set_title("open: no step failed (collapse not detected)")
    ax_time.set_ylabel("wall time (s)")
    ax_time.set_yscale("log")
    if series_name:
        ax_err.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "study.png"), dpi=120)
    with open(os.path.join(directory, "study.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    main(*sys.argv[1:])
