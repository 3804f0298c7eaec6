#!/usr/bin/python3
"""Error against the analytic value, and cost, over a thinlayer sweep.

    /usr/bin/python3 -m thinlayer_tools.plots.study OUTPUT_DIR X_NAME

Reads OUTPUT_DIR/sweep.csv (X_NAME is one of the swept names, e.g.
aspect_ratio; every combination of the other swept names is a series) and
writes study.png (relative error of the collapse load, and wall time,
against X_NAME; open markers where no step failed, i.e. collapse was not
detected within the load programme) and study.md (the same as a table, with
iterations and DoFs).
"""
import argparse
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from thinlayer_tools import results  # noqa: E402


def value(text):
    """A number; for a list value (stations, harmonics) its length."""
    try:
        return float(text)
    except ValueError:
        items = [t for t in text.replace("{", "").replace("}", "").split(",") if t.strip()]
        return float(len(items)) if len(items) > 1 else math.nan


def main(directory, x_name):
    with open(os.path.join(directory, "sweep.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    swept = results.swept_names(rows)
    others = [n for n in swept if n != x_name]

    def key(r):
        return tuple(r[n] for n in others)

    series = sorted({key(r) for r in rows}, key=lambda k: [value(v) for v in k])
    fig, (ax_err, ax_time) = plt.subplots(1, 2, figsize=(11, 4))
    lines = ["| " + " | ".join(others + [x_name]) + " | outcome | "
             "collapse load (last converged) | error | iterations | DoFs | wall s |",
             "|" + "---|" * (len(others) + 7)]
    for s in series:
        pts = sorted((r for r in rows if key(r) == s), key=lambda r: value(r[x_name]))
        xs = [value(r[x_name]) for r in pts]
        # The error of a collapse load; a run without a collapse has none
        # (a gap in the line), and is listed with its outcome.
        detected = [results.collapse_detected(r) for r in pts]
        err = [100 * results.collapse_error(r) if d and results.collapse_error(r) is not None
               else math.nan for r, d in zip(pts, detected)]
        label = ", ".join("%s = %s" % (n, v) for n, v in zip(others, s)) or None
        line, = ax_err.plot(xs, err, "-", label=label)
        ax_err.plot([a for a, d in zip(xs, detected) if d], [e for e, d in zip(err, detected) if d],
                    "o", color=line.get_color())
        ax_err.plot([a for a, d in zip(xs, detected) if not d],
                    [0 for d in detected if not d], "x", color=line.get_color())
        ax_time.plot(xs, [value(r["wall_seconds"]) for r in pts], "o-", label=label)
        for r, d in zip(pts, detected):
            lines.append("| " + " | ".join(r[n] for n in others + [x_name]) +
                         " | %s | %s | %s | %s | %s | %.2f |" % (
                             r["outcome"],
                             r["collapse_load"] if d else "(%s)" % r["last_converged_load"],
                             "%+.1f%%" % (100 * results.collapse_error(r))
                             if d and results.collapse_error(r) is not None else "-",
                             r["total_iterations"], r["dofs"], value(r["wall_seconds"])))
    xs_all = [value(r[x_name]) for r in rows]
    listed = any("," in r[x_name] for r in rows)
    for ax in (ax_err, ax_time):
        ax.set_xlabel(("number of " if listed else "") + x_name)
        ax.grid(alpha=0.3)
        if min(xs_all) > 0 and max(xs_all) / min(xs_all) > 20:
            ax.set_xscale("log")
    ax_err.axhline(0, color="k", lw=0.8)
    ax_err.set_ylabel("collapse load error against analytic (%); x: no collapse")
    ax_err.set_title("open: no step failed (collapse not detected)", fontsize=10)
    ax_time.set_ylabel("wall time (s)")
    ax_time.set_yscale("log")
    if others:
        ax_err.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "study.png"), dpi=120)
    results.record(os.path.join(directory, "study.png"))
    with open(os.path.join(directory, "study.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    results.record(os.path.join(directory, "study.md"))
    print("\n".join(lines))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("directory", help="the results directory of a sweep")
    parser.add_argument("x_name", help="the swept name on the horizontal axis")
    arguments = parser.parse_args()
    main(arguments.directory, arguments.x_name)
