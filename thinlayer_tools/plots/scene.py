#!/usr/bin/python3
"""Curves and displacement vectors of one thinlayer run.

    /usr/bin/python3 -m thinlayer_tools.plots.scene OUTPUT_DIR [REFERENCE_LABEL]

Reads OUTPUT_DIR/history.csv, summary.json and displacements.csv and writes
load_displacement.png (load against displacement: converged states
joined, the attempts that ended the run marked x, the analytic reference
if the run declared one, and iterations per step; --load-label and
--displacement-label name the axes with their normalisation) and
displacement_vectors.png (the displacements at the last step and that
step's increment, which at a failed step is the mechanism, drawn as arrows
at the vertices, with the body's outline and axes).
"""
import argparse
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from thinlayer_tools import results  # noqa: E402
from thinlayer_tools.report import figures  # noqa: E402


def main(directory, reference_label="analytic", load_label=None, displacement_label=None,
         length_unit="L"):
    # Axes the caller does not name are named from the run's Monitors.
    default_load, default_displacement = results.axis_labels(directory)
    load_label = load_label or default_load
    displacement_label = displacement_label or default_displacement
    rows = results.history(directory)
    with open(os.path.join(directory, "summary.json")) as f:
        summary = json.load(f)

    # Converged, accepted states joined; the attempts that ended the run
    # marked apart (a failed step's state is no equilibrium, and a step that
    # converged on the mechanism was never accepted).
    fig, (ax, ax_it) = plt.subplots(2, 1, figsize=(6.5, 7), sharex=True,
                                    gridspec_kw={"height_ratios": [2, 1]})
    figures.curve(ax, directory, "computed (converged states)", marker="o", ms=3)
    if summary.get("reference_load") is not None:
        ax.axhline(summary["reference_load"], color="k", ls="--", label=reference_label)
    ax.set_ylabel(load_label)
    ax.grid(alpha=0.3)
    figures.failure_legend(ax, fontsize=7)
    ax.set_title("%s: %s" % (os.path.basename(os.path.normpath(directory)), summary["outcome"]),
                 fontsize=9)
    steps = results.states(rows)
    ax_it.plot([results.number(s["displacement"]) for s in steps],
               [int(s["iterations"]) for s in steps], ".-")
    ax_it.set_yscale("log")
    ax_it.set_xlabel(displacement_label)
    ax_it.set_ylabel("iterations per step")
    ax_it.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "load_displacement.png"), dpi=120)
    results.record(os.path.join(directory, "load_displacement.png"))
    plt.close(fig)

    fig, axes = plt.subplots(2, 1, figsize=(8, 9))
    for ax, increment, what in zip(axes, (False, True),
                                   ("displacements", "increment of the last step (at a "
                                    "failed step: the mechanism)")):
        largest = figures.vectors(ax, directory, increment, length_unit)
        ax.set_title("%s, largest %.3g %s" % (what, largest, length_unit), fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "displacement_vectors.png"), dpi=120)
    results.record(os.path.join(directory, "displacement_vectors.png"))
    print("wrote load_displacement.png and displacement_vectors.png in", directory)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("directory", help="a run's results directory")
    parser.add_argument("reference_label", nargs="?", default="analytic",
                        help="the name of the analytic reference in the legend")
    parser.add_argument("--load-label",
                        help="the load axis, with its normalisation (default: what the "
                             "run's Monitors section measures)")
    parser.add_argument("--displacement-label",
                        help="the displacement axis, with its normalisation (default: what "
                             "the run's Monitors section measures)")
    parser.add_argument("--length-unit", default="L", help="the unit of the vector plots' axes")
    arguments = parser.parse_args()
    main(arguments.directory, arguments.reference_label, arguments.load_label,
         arguments.displacement_label, arguments.length_unit)
