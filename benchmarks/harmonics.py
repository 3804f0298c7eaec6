#!/usr/bin/python3
"""Fourier harmonics on several ranks: each harmonic's stiffness split over
all ranks (MUMPS on every rank for every harmonic; Solver/Spread harmonics
over ranks = false) against the harmonics spread over the ranks, each
factorised whole on one rank and substituted at the same time as the
others' (CHOLMOD; the default).

Case 3 (the circular footing, harmonics 1 and 3, the paper's method) on a
mesh refined 4 times the paper's, on one rank (CHOLMOD, both harmonics,
the node's cores as threads) and on two, split and spread. Per row: the
substitution time of an iteration (every harmonic), the time per
iteration and the peak memory per rank, medians of REPEAT runs of one
load step (half the paper's collapse load, at most 250 iterations), and
the step's displacement against one rank's.

    /usr/bin/python3 -m benchmarks.harmonics [--repeat 3]

Writes output/benchmarks/harmonics.md and prints it.
"""
import argparse
import os
import statistics

from thinlayer_tools import THINLAYER, TOP, mpirun, run_for_summary

from benchmarks import page

OUT = os.path.join(TOP, "output", "benchmarks")
GEOMETRY = ("half_width=1, width=5, depth=3, aspect_ratio=10, n_footing=32, "
            "n_side=48, n_depth=40, interface_beyond_footing=1")
STATIONS = "0, 45, 90, 135, 180"


def run(ranks, spread, directory):
    command = mpirun(ranks) + [
        THINLAYER, os.path.join(TOP, "prm", "case3-circular-footing.prm"),
        "-s", "Mesh/Geometry parameters=" + GEOMETRY,
        "-s", "Kinematics/Stations=" + STATIONS,
        "-s", "Solver/Spread harmonics over ranks=" + ("true" if spread else "false"),
        # One load step of at most 250 iterations: what is timed is an
        # iteration, not the run to collapse.
        "-s", "Loading/Load increments=0.5",
        "-s", "Loading/Collapse resolution=0",
        "-s", "Output/Directory=" + directory,
        "-s", "Output/Write VTU=false",
        "-s", "Output/Print timing=false"]
    return run_for_summary(command, directory)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    page.add_argument(parser)
    args = parser.parse_args()
    page.configure(args)
    layouts = [("one rank, both harmonics", 1, True),
               ("two ranks, each harmonic split (MUMPS)", 2, False),
               ("two ranks, one harmonic each (spread)", 2, True)]
    runs = {label: [] for label, _, _ in layouts}
    for k in range(args.repeat):
        for label, ranks, spread in layouts:
            directory = os.path.join(OUT, "runs", "harmonics-%d-%s-%d" % (
                ranks, "spread" if spread else "split", k))
            runs[label].append(run(ranks, spread, directory))
    one = runs[layouts[0][0]][0]["final_displacement"]
    header = ("| layout | equations | substitution ms per iteration | ms per iteration "
              "| peak MB per rank | displacement vs 1 rank |")
    lines = [header, "|---|---|---|---|---|---|"]
    for label, rows in runs.items():
        lines.append("| %s | %d | %.1f | %.1f | %.0f | %.1e |" % (
            label, rows[0]["equations"],
            1e3 * statistics.median(r["seconds_per_substitution"] for r in rows),
            1e3 * statistics.median(r["seconds_per_iteration"] for r in rows),
            statistics.median(r["peak_memory_mb_per_rank"] for r in rows),
            abs(rows[0]["final_displacement"] - one) / abs(one)))
    page.write(OUT, "harmonics", "Fourier harmonics over the ranks", lines)


if __name__ == "__main__":
    main()
