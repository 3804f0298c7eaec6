#!/usr/bin/python3
"""Profiles along the interfaces of one thinlayer run: its layers and its
interface elements.

Reads OUTPUT_DIR/layer-<id>-NNNN.csv (a thin layer the scene names in
Layers/Material ids) or interface-<id>-NNNN.csv (zero-thickness
interface elements, an Interface <id> section), and history.csv, and writes one
chart per interface, layer-<id>.png or interface-<id>.png: slip, opening,
shear and normal traction and the mobilised strength tau_mob / tau_max
against arc length along the layer, at a few load steps. Converged,
accepted steps are solid lines, plastic points filled. A step that ended
the run without an accepted state (a failure) is drawn apart: its tractions
dashed, and for its slip the shape of its last increment (the mechanism),
scaled to the largest converged slip, since its displacements run away. Units are the
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

from thinlayer_tools import results  # noqa: E402


SERIES = re.compile(r"((?:layer|interface)-\d+)-(\d+)\.csv$")


def profile_files(directory, series):
    """{step: path} of the files SERIES-NNNN.csv."""
    files = {}
    for path in glob.glob(os.path.join(directory, series + "-*.csv")):
        match = SERIES.search(path)
        if match and match.group(1) == series:
            files[int(match.group(2))] = path
    return files


def all_series(directory):
    """The interfaces written: layer-<id> and interface-<id>."""
    names = set()
    for path in glob.glob(os.path.join(directory, "*.csv")):
        match = SERIES.search(path)
        if match:
            names.add(match.group(1))
    return sorted(names)


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


def plot(directory, series, steps, angle, count):
    rows = results.history(directory)
    files = profile_files(directory, series)
    if not files:
        raise SystemExit("no %s-NNNN.csv in %s: does the scene name the layer "
                         "in Interfaces/Material ids, or have an Interface "
                         "section?" % (series, directory))
    if steps:
        missing = [s for s in steps if s not in files]
        if missing:
            raise SystemExit("no profile for step(s) %s in %s" % (missing, directory))
        failed_steps = {int(r["step"]) for r in results.failures(rows)}
        accepted = [s for s in steps if s not in failed_steps]
        failed = [s for s in steps if s in failed_steps]
    else:
        accepted, failed = chosen_steps(rows, files, count)

    figure, axes = plt.subplots(3, 2, figsize=(11, 10), sharex=True)
    panels = [("slip", "slip (relative tangential displacement)\n(scene units)"),
              ("opening", "opening (relative normal displacement)\n(scene units)"),
              ("shear_traction", "shear traction\n(scene units)"),
              ("normal_traction", "normal traction (tension +)\n(scene units)"),
              ("mobilised_strength", "mobilised strength\ntau_mob / tau_max (-)")]
    colours = plt.get_cmap("viridis")
    drawn = [(s, False) for s in accepted] + [(s, True) for s in failed]
    profiles = {}
    for step, _ in drawn:
        profiles[step] = [r for r in results.read_csv(files[step])
                          if abs(results.number(r["angle"]) - angle) < 1e-6]
        if not profiles[step]:
            raise SystemExit("no station at %g degrees in %s" % (angle, files[step]))
    # A failed state's displacements run away along the mechanism: its slip
    # is drawn as the shape of its last increment, scaled to the largest
    # converged slip, and its opening not at all.
    largest_slip = max([abs(results.number(r["slip"])) for step in accepted
                        for r in profiles[step]] + [0]) or 1
    for index, (step, is_failure) in enumerate(drawn):
        profile = profiles[step]
        colour = "tab:red" if is_failure else colours(index / max(len(accepted), 1))
        label = "step %d, load factor %.4g%s" % (
            step, load_factor(rows, step), " (failed: no equilibrium)" if is_failure else "")
        for run in sorted({r["run"] for r in profile}):
            points = [r for r in profile if r["run"] == run]
            s = [results.number(r["arc_length"]) for r in points]
            first = run == sorted({r["run"] for r in profile})[0]
            for axis, (column, _) in zip(axes.flat, panels):
                values = [results.number(r[column]) for r in points]
                if is_failure and column == "slip":
                    increment = [results.number(r["slip_increment"]) for r in points]
                    scale = largest_slip / (max(abs(v) for v in increment) or 1)
                    axis.plot(s, [scale * v for v in increment], ":", color=colour,
                              label=label + ":\nshape of its last slip increment "
                              "(the mechanism), scaled" if first else None)
                    continue
                if is_failure and column == "opening":
                    continue
                axis.plot(s, values, "--" if is_failure else "-", color=colour,
                          label=label if first and column == "slip" else None)
                plastic = [(x, y) for x, y, r in zip(s, values, points) if r["plastic"] == "1"]
                elastic = [(x, y) for x, y, r in zip(s, values, points) if r["plastic"] != "1"]
                if plastic:
                    axis.plot(*zip(*plastic), "o", color=colour, markersize=4)
                if elastic:
                    axis.plot(*zip(*elastic), "o", color=colour, markersize=4,
                              markerfacecolor="white")
    for axis, (_, title) in zip(axes.flat, panels):
        axis.set_ylabel(title)
        axis.axhline(0, color="grey", linewidth=0.5)
        axis.grid(alpha=0.3)
    # The mobilised strength lies in [0, 1]: 1 where the interface yields.
    axes.flat[4].axhline(1, color="k", linewidth=0.8)
    axes.flat[4].set_ylim(-0.05, 1.1)
    axes.flat[5].set_visible(False)
    axes.flat[3].xaxis.set_tick_params(labelbottom=True)
    for axis in (axes.flat[3], axes.flat[4]):
        axis.set_xlabel("arc length along the interface (mesh length units)")
    axes.flat[0].legend(fontsize=8)
    where = " at %g degrees" % angle if angle else ""
    kind = ("zero-thickness elements, Interface %s" % series.split("-")[-1]
            if series.startswith("interface") else
            "thin layer, material id %s" % series.split("-")[-1])
    figure.suptitle("Interface (%s)%s: %s\nfilled markers: plastic; open: elastic"
                    % (kind, where, os.path.basename(os.path.normpath(directory))))
    figure.tight_layout()
    output = os.path.join(directory, series + ".png")
    figure.savefig(output, dpi=110)
    results.record(output)
    plt.close(figure)
    print("wrote", output)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("directory", help="a run's results directory")
    parser.add_argument("--series", action="append",
                        help="layer-<id> (a thin layer) or interface-<id> "
                             "(zero-thickness elements); default: every one written")
    parser.add_argument("--steps", type=int, nargs="+",
                        help="load steps to draw (default: a few accepted steps "
                             "and the failure that ended the run)")
    parser.add_argument("--count", type=int, default=4,
                        help="accepted steps drawn by default (default 4)")
    parser.add_argument("--angle", type=float, default=0,
                        help="Fourier scenes: the station, in degrees (default 0)")
    arguments = parser.parse_args()
    if not os.path.isdir(arguments.directory):
        raise SystemExit("%s is not a results directory" % arguments.directory)
    names = arguments.series or all_series(arguments.directory)
    if not names:
        raise SystemExit("no layer-*-NNNN.csv or interface-*-NNNN.csv in %s: name a "
                         "thin layer in Layers/Material ids, or add an Interface "
                         "section" % arguments.directory)
    for series in names:
        plot(arguments.directory, series, arguments.steps, arguments.angle,
             arguments.count)


if __name__ == "__main__":
    main()
