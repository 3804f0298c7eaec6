#!/usr/bin/python3
"""Profiles along a thin-layer interface of one thinlayer run.

Reads OUTPUT_DIR/interface-<id>-NNNN.csv (written when the scene names the
layer in Interfaces/Material ids) and history.csv, and writes
OUTPUT_DIR/interface-<id>.png: slip, opening, shear and normal traction
against arc length along the layer, at a few load steps. Converged,
accepted steps are solid lines, plastic points filled. A step that ended
the run without an accepted state (a failure) is drawn apart, dashed, with
its last increment of slip, which shows the mechanism. Units are the
scene's own (lengths of the mesh, displacements and stresses of its
parameters).
"""
import argparse
import glob
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import results  # noqa: E402


def profile_files(directory, material_id):
    """{step: path} of the interface-<id>-NNNN.csv files."""
    files = {}
    for path in glob.glob(os.path.join(directory, "interface-%d-*.csv" % material_id)):
        match = re.search(r"-(\d+)\.csv$", path)
        files[int(match.group(1))] = path
    return files


def layer_ids(directory):
    ids = set()
    for path in glob.glob(os.path.join(directory, "interface-*-*.csv")):
        match = re.search(r"interface-(\d+)-\d+\.csv$", path)
        if match:
            ids.add(int(match.group(1)))
    return sorted(ids)


def chosen_steps(rows, available, count):
    """A few accepted steps spread over the run, and the failure that ended it."""
    accepted = sorted({int(r["step"]) for r in results.states(rows)} & set(available))
    failed = sorted({int(r["step"]) for r in results.failures(rows)} & set(available))
    steps = []
    if accepted:
        for k in range(count):
            index = round(k * (len(accepted) - 1) / max(count - 1, 1))
            if accepted[index] not in steps:
                steps.append(accepted[index])
    return steps, failed[-1:] if failed else []


def load_factor(rows, step):
    matching = [r for r in rows if int(r["step"]) == step]
    return results.number(matching[-1]["load_factor"]) if matching else float("nan")


def plot(directory, material_id, steps, angle, count):
    rows = results.history(directory)
    files = profile_files(directory, material_id)
    if not files:
        raise SystemExit("no interface-%d-NNNN.csv in %s: does the scene name "
                         "the layer in Interfaces/Material ids?" % (material_id, directory))
    if steps:
        missing = [s for s in steps if s not in files]
        if missing:
            raise SystemExit("no profile for step(s) %s in %s" % (missing, directory))
        failed_steps = {int(r["step"]) for r in results.failures(rows)}
        accepted = [s for s in steps if s not in failed_steps]
        failed = [s for s in steps if s in failed_steps]
    else:
        accepted, failed = chosen_steps(rows, files, count)

    figure, axes = plt.subplots(2, 2, figsize=(11, 7.5), sharex=True)
    panels = [("slip", "slip (relative tangential displacement)"),
              ("opening", "opening (relative normal displacement)"),
              ("shear_traction", "shear traction"),
              ("normal_traction", "normal traction (tension +)")]
    colours = plt.get_cmap("viridis")
    series = [(s, False) for s in accepted] + [(s, True) for s in failed]
    for index, (step, is_failure) in enumerate(series):
        profile = [r for r in results.read_csv(files[step])
                   if abs(results.number(r["angle"]) - angle) < 1e-6]
        if not profile:
            raise SystemExit("no station at %g degrees in %s" % (angle, files[step]))
        colour = "tab:red" if is_failure else colours(index / max(len(accepted), 1))
        label = "step %d, load factor %.4g%s" % (
            step, load_factor(rows, step), " (failed: no equilibrium)" if is_failure else "")
        for run in sorted({r["run"] for r in profile}):
            points = [r for r in profile if r["run"] == run]
            s = [results.number(r["arc_length"]) for r in points]
            for axis, (column, _) in zip(axes.flat, panels):
                values = [results.number(r[column]) for r in points]
                axis.plot(s, values, "--" if is_failure else "-", color=colour,
                          label=label if run == points[0]["run"] and column == "slip" else None)
                plastic = [(x, y) for x, y, r in zip(s, values, points) if r["plastic"] == "1"]
                elastic = [(x, y) for x, y, r in zip(s, values, points) if r["plastic"] != "1"]
                if plastic:
                    axis.plot(*zip(*plastic), "o", color=colour, markersize=4)
                if elastic:
                    axis.plot(*zip(*elastic), "o", color=colour, markersize=4,
                              markerfacecolor="white")
            if is_failure:
                increment = [results.number(r["slip_increment"]) for r in points]
                axes.flat[0].plot(s, increment, ":", color="black",
                                  label="its last increment of slip (the mechanism)"
                                  if run == points[0]["run"] else None)
    for axis, (_, title) in zip(axes.flat, panels):
        axis.set_ylabel(title + "\n(scene units)")
        axis.axhline(0, color="grey", linewidth=0.5)
        axis.grid(alpha=0.3)
    for axis in axes[1]:
        axis.set_xlabel("arc length along the interface (mesh length units)")
    axes.flat[0].legend(fontsize=8)
    where = " at %g degrees" % angle if angle else ""
    figure.suptitle("Interface (material id %d)%s: %s\nfilled markers: plastic; "
                    "open: elastic" % (material_id, where, os.path.basename(os.path.normpath(directory))))
    figure.tight_layout()
    output = os.path.join(directory, "interface-%d.png" % material_id)
    figure.savefig(output, dpi=110)
    plt.close(figure)
    print("wrote", output)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("directory", help="a run's results directory")
    parser.add_argument("--id", type=int, action="append",
                        help="material id of the layer (default: every layer written)")
    parser.add_argument("--steps", type=int, nargs="+",
                        help="load steps to draw (default: a few accepted steps "
                             "and the failure that ended the run)")
    parser.add_argument("--count", type=int, default=4,
                        help="accepted steps drawn by default (default 4)")
    parser.add_argument("--angle", type=float, default=0,
                        help="Fourier scenes: the station, in degrees (default 0)")
    arguments = parser.parse_args()
    ids = arguments.id or layer_ids(arguments.directory)
    if not ids:
        raise SystemExit("no interface-<id>-NNNN.csv in %s: name the layer in "
                         "Interfaces/Material ids" % arguments.directory)
    for material_id in ids:
        plot(arguments.directory, material_id, arguments.steps, arguments.angle,
             arguments.count)


if __name__ == "__main__":
    main()
