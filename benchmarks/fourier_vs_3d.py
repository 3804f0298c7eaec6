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
converged states), the displacement at the last converged state, the row's
mean slip along x under the footing at that state (mean_slip(), below), DoFs,
wall time, peak memory, and the time of a constant-stiffness iteration
against that of its substitutions (every harmonic's). Differences are against the richest Fourier
model, {1, 3, 5, 7}: the harmonics' series converged on this r-z mesh.
One run each (the 3D ones are long; their times are quoted as measured,
on a machine that did nothing else).

    /usr/bin/python3 -m benchmarks.fourier_vs_3d [--levels 4,8] [--output DIR] [--tables-only]

Writes DIR/fourier-vs-3d.csv and .md (DIR: output/benchmarks) and prints
the table; the runs go into DIR/runs (--tables-only: the tables from the
runs already there).
"""
import argparse
import csv
import json
import math
import os
import subprocess

from thinlayer_tools import THINLAYER, TOP
from thinlayer_tools.results import collapse_load, history, number, states

from benchmarks import page

OUT = os.path.join(TOP, "output", "benchmarks")
SERIES = [("1", "0, 45, 90, 135, 180"),
          ("1, 3", "0, 45, 90, 135, 180"),
          ("1, 3, 5", "0, 30, 60, 90, 120, 150, 180"),
          ("1, 3, 5, 7", "0, 22.5, 45, 67.5, 90, 112.5, 135, 157.5, 180")]
SOLID_GEOMETRY = ("sector=180, footing=1, half_width=1, width=5, depth=3, "
                  "footing_height=0.5, aspect_ratio=10, n_around=%d, "
                  "n_footing=4, n_side=12, n_depth=10, growth=1.2")
FIELDS = ["model", "around", "dofs", "equations", "collapse_load", "displacement_half",
          "displacement_last", "mean_slip", "wall_seconds", "peak_memory_mb", "iterations",
          "seconds_per_iteration", "seconds_per_substitution"]


def displacement_at(rows, load_factor):
    """The displacement at LOAD_FACTOR, interpolated in the converged
    states ROWS (load factor increasing)."""
    points = [(number(r["load_factor"]), number(r["displacement"])) for r in rows]
    points = [(0.0, 0.0)] + points
    for (l0, u0), (l1, u1) in zip(points, points[1:]):
        if l0 <= load_factor <= l1:
            return u0 + (u1 - u0) * (load_factor - l0) / (l1 - l0)
    return float("nan")


def mean_slip(directory, step):
    """The row's slip along x averaged over the footing's disc (r < R = 1)
    at load step STEP, from the run's layer-2-NNNN.csv. Fourier: the
    slip at each station's samples (x = cos(theta) slip_r - sin(theta)
    slip_theta), weighted by r dr (2-point Gauss pairs: the cell's width is
    sqrt(3) times their distance) and the trapezoidal rule in theta over the
    circle. 3D: each cell's 2x2 samples weighted by a quarter of the cell's
    area (three times that of the quadrilateral through them)."""
    path = os.path.join(directory, "layer-2-%04d.csv" % step)
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    total = area = 0.0
    if "angle" in rows[0]:
        angles = sorted({float(r["angle"]) for r in rows})
        for angle in angles:
            at = [r for r in rows if float(r["angle"]) == angle]
            theta = math.radians(angle)
            w_theta = 2 * math.pi / (len(angles) - 1) * (
                0.5 if angle in (angles[0], angles[-1]) else 1.0)
            for k in range(0, len(at), 2):
                h = math.sqrt(3) * (float(at[k + 1]["x"]) - float(at[k]["x"]))
                for r in at[k:k + 2]:
                    x = float(r["x"])
                    if x < 1.0:
                        w = w_theta * x * h / 2
                        total += w * (float(r["slip"]) * math.cos(theta)
                                      - float(r["slip_out_of_plane"]) * math.sin(theta))
                        area += w
    else:
        for k in range(0, len(rows), 4):
            cell = rows[k:k + 4]
            p = [(float(r["x"]), float(r["z"])) for r in cell]
            quad = [p[0], p[2], p[3], p[1]]
            a = 0.5 * abs(sum(quad[i][0] * quad[(i + 1) % 4][1] - quad[(i + 1) % 4][0]
                              * quad[i][1] for i in range(4)))
            for r in cell:
                if math.hypot(float(r["x"]), float(r["z"])) < 1.0:
                    total += 0.75 * a * float(r["slip_1"])
                    area += 0.75 * a
    return total / area


def measure(model, around, command, directory, run=True):
    if run:
        subprocess.run(command, capture_output=True, text=True, check=True)
    with open(os.path.join(directory, "summary.json")) as f:
        summary = json.load(f)
    converged = states(history(directory))
    collapse = collapse_load(summary)
    return {
        "model": model, "around": around, "dofs": summary["dofs"],
        "equations": summary["equations"],
        "collapse_load": collapse if collapse is not None else float("nan"),
        "displacement_half": (displacement_at(converged, collapse / 2)
                              if collapse is not None else float("nan")),
        "displacement_last": number(converged[-1]["displacement"]),
        "mean_slip": mean_slip(directory, int(converged[-1]["step"])),
        "wall_seconds": summary["wall_seconds"],
        "peak_memory_mb": summary["peak_memory_mb_per_rank"],
        "iterations": summary["total_iterations"],
        "seconds_per_iteration": summary["seconds_per_iteration"],
        "seconds_per_substitution": summary["seconds_per_substitution"]}


def common(directory):
    return ["-s", "Output/Directory=" + directory, "-s", "Output/Write VTU=false",
            "-s", "Output/Print timing=false"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--levels", default="4,8",
                        help="3D: elements per 45 degrees, comma-separated (empty: "
                             "the Fourier series only)")
    parser.add_argument("--output", default=OUT, help="the directory of the tables and runs")
    parser.add_argument("--tables-only", action="store_true",
                        help="measure the runs already in DIR/runs, run nothing")
    page.add_argument(parser)
    args = parser.parse_args()
    page.configure(args)
    out = os.path.abspath(args.output)
    rows = []
    for harmonics, stations in SERIES:
        directory = os.path.join(out, "runs", "fourier-" + harmonics.replace(", ", "-"))
        command = [THINLAYER, os.path.join(TOP, "prm", "case3-circular-footing.prm"),
                   "-s", "Kinematics/Harmonics=" + harmonics,
                   "-s", "Kinematics/Stations=" + stations] + common(directory)
        rows.append(measure("Fourier {%s}" % harmonics, "", command, directory,
                            not args.tables_only))
        print(rows[-1], flush=True)
    for level in [int(n) for n in args.levels.split(",") if n.strip()]:
        directory = os.path.join(out, "runs", "solid-%d" % level)
        command = [THINLAYER, os.path.join(TOP, "prm", "case3-circular-footing-3d.prm"),
                   "-s", "Mesh/Geometry parameters=" + SOLID_GEOMETRY % level
                   ] + common(directory)
        rows.append(measure("3D", 4 * level, command, directory, not args.tables_only))
        print(rows[-1], flush=True)

    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "fourier-vs-3d.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=FIELDS)
        writer.writeheader()
        writer.writerows(rows)
    reference = rows[len(SERIES) - 1]
    lines = ["| model | elements around the half circle | equations | collapse load "
             "(vs {1,3,5,7}) | displacement at half collapse (vs {1,3,5,7}) "
             "| mean slip at the last converged state x 1e5 (vs {1,3,5,7}) "
             "| wall s | peak MB | ms per iteration | ms per substitution |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %s | %s | %d | %.4f (%+.2f%%) | %.4f (%+.3f%%) | %.4f (%+.2f%%) "
                     "| %.1f | %.0f | %.2f | %.2f |" % (
            r["model"], r["around"], r["equations"], r["collapse_load"],
            100 * (r["collapse_load"] / reference["collapse_load"] - 1),
            r["displacement_half"],
            100 * (r["displacement_half"] / reference["displacement_half"] - 1),
            1e5 * r["mean_slip"], 100 * (r["mean_slip"] / reference["mean_slip"] - 1),
            r["wall_seconds"], r["peak_memory_mb"], 1e3 * r["seconds_per_iteration"],
            1e3 * r["seconds_per_substitution"]))
    page.write(out, "fourier-vs-3d", "Fourier harmonics against a 3D body", lines)


if __name__ == "__main__":
    main()
