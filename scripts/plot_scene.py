#!/usr/bin/python3
"""Curves and displacement vectors of one thinlayer run.

    /usr/bin/python3 scripts/plot_scene.py OUTPUT_DIR [REFERENCE_LABEL]

Reads OUTPUT_DIR/history.csv, summary.json and displacements.csv and writes
load_displacement.png (load against displacement, failed steps open, with the
analytic reference if the run declared one, and iterations per step) and
displacement_vectors.png (the displacements at the last step and that
step's increment, which at a failed step is the mechanism, drawn as arrows
at the vertices).
"""
import argparse
import csv
import json
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import results  # noqa: E402


def main(directory, reference_label="analytic"):
    rows = results.history(directory)
    with open(os.path.join(directory, "summary.json")) as f:
        summary = json.load(f)

    # Converged, accepted states on the curve; the steps that ended the run
    # marked apart (a failed step's state is no equilibrium, and a step that
    # converged on the mechanism was never accepted).
    steps = results.states(rows) + results.failures(rows)
    u = [results.number(s["displacement"]) for s in steps]
    p = [results.number(s["load"]) for s in steps]
    failed = [s["converged"] == "0" or s.get("accepted") == "0" for s in steps]
    fig, (ax, ax_it) = plt.subplots(2, 1, figsize=(6, 6.5), sharex=True,
                                    gridspec_kw={"height_ratios": [2, 1]})
    ax.plot([0] + [x for x, f in zip(u, failed) if not f],
            [0] + [y for y, f in zip(p, failed) if not f], "o-", ms=4, label="computed")
    ax.plot([x for x, f in zip(u, failed) if f], [y for y, f in zip(p, failed) if f],
            "o", mfc="white", color="C3", label="step failed or on the mechanism")
    if summary.get("reference_load") is not None:
        ax.axhline(summary["reference_load"], color="k", ls="--", label=reference_label)
    ax.set_ylabel("load")
    ax.grid(alpha=0.3)
    ax.legend()
    ax.set_title(os.path.basename(os.path.normpath(directory)))
    ax_it.plot(u, [int(s["iterations"]) for s in steps], ".-")
    ax_it.set_yscale("log")
    ax_it.set_xlabel("displacement")
    ax_it.set_ylabel("iterations")
    ax_it.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "load_displacement.png"), dpi=120)

    with open(os.path.join(directory, "displacements.csv"), newline="") as f:
        nodes = [[float(r[k]) for k in ("x", "y", "u_x", "u_y", "du_x", "du_y")]
                 for r in csv.DictReader(f)]
    x, y, ux, uy, dux, duy = zip(*nodes)
    size = max(max(x) - min(x), max(y) - min(y))
    aspect = (max(y) - min(y)) / (max(x) - min(x))
    fig, axes = plt.subplots(2, 1, figsize=(8, 2 * 8 * aspect + 1.5))
    for ax, (vx, vy), what in zip(axes, ((ux, uy), (dux, duy)),
                                  ("displacements", "displacement increment of the step")):
        largest = max(math.hypot(a, b) for a, b in zip(vx, vy)) or 1
        ax.quiver(x, y, vx, vy, angles="xy", scale_units="xy",
                  scale=largest / (0.06 * size), width=0.002)
        ax.set_aspect("equal")
        ax.set_title("%s at the last step (largest %.3g; step %s, %s)"
                     % (what, largest, steps[-1]["step"],
                        "failed" if failed[-1] else "converged"), fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "displacement_vectors.png"), dpi=120)
    print("wrote load_displacement.png and displacement_vectors.png in", directory)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("directory", help="a run's results directory")
    parser.add_argument("reference_label", nargs="?", default="analytic",
                        help="the name of the analytic reference in the legend")
    arguments = parser.parse_args()
    main(arguments.directory, arguments.reference_label)
