#!/usr/bin/python3
"""What the first run shows: its collapse load beside the closed form, a
picture of the scene (overview.png: the mesh with its layer, the mechanism
and the load-displacement curve), and where its results are.

    /usr/bin/python3 -m thinlayer_tools.first_run OUTPUT_DIR [--load-label ...]
        [--displacement-label ...] [--reference-label ...] [--length-unit ...]

Exits non-zero unless the run ended in a collapse.
"""
import argparse
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from thinlayer_tools import results  # noqa: E402
from thinlayer_tools.report import figures  # noqa: E402


def overview(directory, summary, labels):
    """The mesh (the layer in red), the last step's increment (at the
    collapse: the mechanism) and the curve, side by side."""
    fig, (mesh, mechanism, load) = plt.subplots(1, 3, figsize=(11, 4.6),
                                                gridspec_kw={"width_ratios": [1, 1, 1.6]})
    unit = labels.length_unit
    figures.draw_mesh(mesh, directory, "x / " + unit, "y / " + unit)
    mesh.set_title("mesh: %d cells, the layer in red" % summary["cells"], fontsize=9)
    mesh.get_legend().remove()
    figures.vectors(mechanism, directory, increment=True, length_unit=unit)
    mechanism.set_title("the mechanism (the last increment)", fontsize=9)
    figures.curve(load, directory, "computed (converged states)", marker="o", ms=3)
    if summary.get("reference_load") is not None:
        load.axhline(summary["reference_load"], color="k", ls="--",
                     label=labels.reference_label)
    default_load, default_displacement = results.axis_labels(directory)
    load.set_xlabel(labels.displacement_label or default_displacement)
    load.set_ylabel(labels.load_label or default_load)
    load.set_ylim(bottom=0)
    load.grid(alpha=0.3)
    figures.failure_legend(load, fontsize=7, loc="lower right")
    load.set_title("load against displacement", fontsize=9)
    fig.tight_layout()
    path = os.path.join(directory, "overview.png")
    fig.savefig(path, dpi=110)
    results.record(path)
    plt.close(fig)
    return path


def main(directory, labels):
    with open(os.path.join(directory, "summary.json")) as f:
        summary = json.load(f)
    print()
    print("thinlayer: %s, %d cells, %s" % (summary["parameter_file"], summary["cells"],
                                           summary["method"]))
    print("  outcome: %s" % summary["outcome"])
    if summary["outcome"] == "collapse" and summary["reference_load"] is not None:
        print("  collapse load %.4g (the last converged state), closed form %.4g: error %+.2f%%"
              % (summary["collapse_load"], summary["reference_load"],
                 100 * results.collapse_error(summary)))
    bracket = summary.get("collapse_load_factor_bracket") or {}
    if "low" in bracket and "high" in bracket:
        print("  the collapse lies between load factors %.6g and %.6g (bracketed by halving)"
              % (bracket["low"], bracket["high"]))
    print("  %d load steps, %d iterations, %.1f s" % (summary["load_steps"],
                                                       summary["total_iterations"],
                                                       summary["wall_seconds"]))
    absolute = os.path.abspath(directory)
    print("  the scene at a glance:       %s" % os.path.abspath(overview(directory, summary, labels)))
    print("  the load-displacement curve: %s" % os.path.join(absolute, "load_displacement.png"))
    print("  the mechanism:               %s" % os.path.join(absolute,
                                                              "displacement_vectors.png"))
    print("  the fields, for ParaView:    %s" % os.path.join(absolute, "fields.pvd"))
    print("  history.csv and summary.json are beside them.")
    return 0 if summary["outcome"] == "collapse" else 1


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("directory", help="a run's results directory")
    parser.add_argument("--load-label", help="default: what the run's Monitors measure")
    parser.add_argument("--displacement-label",
                        help="default: what the run's Monitors measure")
    parser.add_argument("--reference-label", default="closed form")
    parser.add_argument("--length-unit", default="L",
                        help="the length the coordinates are given in")
    arguments = parser.parse_args()
    sys.exit(main(arguments.directory, arguments))
