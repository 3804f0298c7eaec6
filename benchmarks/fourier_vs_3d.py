#!/usr/bin/python3
"""Fourier harmonics or a 3D body: Case 3 (the laterally loaded circular
footing on an interface row, the paper's method) computed both ways on the
same r-z resolution (8 elements across the footing's radius, 12 beyond,
10 in depth, the row one element thick at R/t = 10).

- Fourier: the r-z plane (prm/case3-circular-footing.prm) with harmonics
  {1}, {1, 3}, {1, 3, 5} and {1, 3, 5, 7} (5, 5, 7 and 9 stations);
- 3D: the half body (prm/case3-circular-footing-3d.prm, 20-node
  hexahedra) with 16, 32 (and, with --levels 4,8,16, 64) elements around
  the half circle.

Per model: the collapse load factor (P / (pi R^2 C_w), 1 in closed form),
the footing's displacement at half the collapse load (interpolated in the
converged states), the displacement at the last converged state, DoFs,
wall time and peak memory. Differences are against the richest Fourier
model, {1, 3, 5, 7}: the harmonics' series converged on this r-z mesh.
One run each (the 3D ones are long; their times are quoted as measured,
on a machine that did nothing else).

    /usr/bin/python3 -m benchmarks.fourier_vs_3d [--levels 4,8] [--output DIR]

Writes DIR/fourier-vs-3d.csv and .md (DIR: output/benchmarks) and prints
the table; the runs go into DIR/runs.
"""
import argparse
import csv
import os

from thinlayer_tools import THINLAYER, TOP, run_for_summary
from thinlayer_tools.results import collapse_load, history, number, states

OUT = os.path.join(TOP, "output", "benchmarks")
SERIES = [("1", "0, 45, 90, 135, 180"),
          ("1, 3", "0, 45, 90, 135, 180"),
          ("1, 3, 5", "0, 30, 60, 90, 120, 150, 180"),
          ("1, 3, 5, 7", "0, 22.5, 45, 67.5, 90, 112.5, 135, 157.5, 180")]
SOLID_GEOMETRY = ("sector=180, footing=1, half_width=1, width=5, depth=3, "
                  "footing_height=0.5, aspect_ratio=10, n_around=%d, "
                  "n_footing=4, n_side=12, n_depth=10, growth=1.2")
FIELDS = ["model", "around", "dofs", "equations", "collapse_load", "displacement_half",
          "displacement_last", "wall_seconds", "peak_memory_mb", "iterations",
          "seconds_per_iteration"]


def displacement_at(rows, load_factor):
    """The displacement at LOAD_FACTOR, interpolated in the converged
    states ROWS (load factor increasing)."""
    points = [(number(r["load_factor"]), number(r["displacement"])) for r in rows]
    points = [(0.0, 0.0)] + points
    for (l0, u0), (l1, u1) in zip(points, points[1:]):
        if l0 <= load_factor <= l1:
            return u0 + (u1 - u0) * (load_factor - l0) / (l1 - l0)
    return float("nan")


def measure(model, around, command, directory):
    summary = run_for_summary(command, directory)
    converged = states(history(directory))
    collapse = collapse_load(summary)
    return {
        "model": model, "around": around, "dofs": summary["dofs"],
        "equations": summary["equations"],
        "collapse_load": collapse if collapse is not None else float("nan"),
        "displacement_half": (displacement_at(converged, collapse / 2)
                              if collapse is not None else float("nan")),
        "displacement_last": number(converged[-1]["displacement"]),
        "wall_seconds": summary["wall_seconds"],
        "peak_memory_mb": summary["peak_memory_mb_per_rank"],
        "iterations": summary["total_iterations"],
        "seconds_per_iteration": summary["seconds_per_iteration"]}


def common(directory):
    return ["-s", "Output/Directory=" + directory, "-s", "Output/Write VTU=false",
            "-s", "Output/Print timing=false"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--levels", default="4,8",
                        help="3D: elements per 45 degrees, comma-separated")
    parser.add_argument("--output", default=OUT, help="the directory of the tables and runs")
    args = parser.parse_args()
    out = os.path.abspath(args.output)
    rows = []
    for harmonics, stations in SERIES:
        directory = os.path.join(out, "runs", "fourier-" + harmonics.replace(", ", "-"))
        command = [THINLAYER, os.path.join(TOP, "prm", "case3-circular-footing.prm"),
                   "-s", "Kinematics/Harmonics=" + harmonics,
                   "-s", "Kinematics/Stations=" + stations] + common(directory)
        rows.append(measure("Fourier {%s}" % harmonics, "", command, directory))
        print(rows[-1], flush=True)
    for level in [int(n) for n in args.levels.split(",")]:
        directory = os.path.join(out, "runs", "solid-%d" % level)
        command = [THINLAYER, os.path.join(TOP, "prm", "case3-circular-footing-3d.prm"),
                   "-s", "Mesh/Geometry parameters=" + SOLID_GEOMETRY % level
                   ] + common(directory)
        rows.append(measure("3D", 4 * level, command, directory))
        print(rows[-1], flush=True)

    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "fourier-vs-3d.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=FIELDS)
        writer.writeheader()
        writer.writerows(rows)
    reference = rows[len(SERIES) - 1]
    lines = ["| model | elements around the half circle | equations | collapse load "
             "(vs {1,3,5,7}) | displacement at half collapse (vs {1,3,5,7}) "
             "| wall s | peak MB |",
             "|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %s | %s | %d | %.4f (%+.2f%%) | %.4f (%+.2f%%) | %.1f | %.0f |" % (
            r["model"], r["around"], r["equations"], r["collapse_load"],
            100 * (r["collapse_load"] / reference["collapse_load"] - 1),
            r["displacement_half"],
            100 * (r["displacement_half"] / reference["displacement_half"] - 1),
            r["wall_seconds"], r["peak_memory_mb"]))
    with open(os.path.join(out, "fourier-vs-3d.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
