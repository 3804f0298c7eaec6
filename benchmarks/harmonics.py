#!/usr/bin/python3
"""Fourier harmonics on several ranks: each harmonic's stiffness split over
all ranks (what thinlayer does: MUMPS on every rank for every harmonic)
against the harmonics spread over the ranks, each factorised whole on one
rank (CHOLMOD on one core), which the harmonics' independence would allow.

Case 3 (the circular footing, harmonics 1 and 3, the paper's method) on a
mesh refined 4 times the paper's. Rows: one rank (CHOLMOD, both harmonics,
the node's cores as threads); two ranks (each harmonic split by MUMPS);
and the spread emulated: two one-rank runs at once, each of one harmonic
on one core (DEAL_II_NUM_THREADS = OPENBLAS_NUM_THREADS = 1), whose
substitutions are what a rank of the spread would do each iteration (the
solution's broadcast, ~0.5 MB, not counted). Per row: the substitution
time of an iteration (every harmonic the row's process solves; the
emulation's is the larger of its two), the time per iteration and the
peak memory per rank, medians of REPEAT runs.

    /usr/bin/python3 -m benchmarks.harmonics [--repeat 3]

Writes output/benchmarks/harmonics.md and prints it.
"""
import argparse
import json
import os
import statistics
import subprocess

from thinlayer_tools import THINLAYER, TOP, mpirun

OUT = os.path.join(TOP, "output", "benchmarks")
GEOMETRY = ("half_width=1, width=5, depth=3, aspect_ratio=10, n_footing=32, "
            "n_side=48, n_depth=40, interface_beyond_footing=1")
STATIONS = "0, 45, 90, 135, 180"


def start(ranks, harmonics, directory, one_core=False):
    command = mpirun(ranks) + [
        THINLAYER, os.path.join(TOP, "prm", "case3-circular-footing.prm"),
        "-s", "Mesh/Geometry parameters=" + GEOMETRY,
        "-s", "Kinematics/Harmonics=" + harmonics,
        "-s", "Kinematics/Stations=" + STATIONS,
        "-s", "Loading/Load increments=0.5, 0.1",
        "-s", "Output/Directory=" + directory,
        "-s", "Output/Write VTU=false",
        "-s", "Output/Print timing=false"]
    env = dict(os.environ)
    if one_core:
        env.update(DEAL_II_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    return subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            text=True, env=env)


def summary(process, directory):
    _, err = process.communicate()
    if process.returncode != 0:
        raise SystemExit("run in %s failed: %s" % (directory, err))
    with open(os.path.join(directory, "summary.json")) as f:
        return json.load(f)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    runs = {"one rank, both harmonics": [], "two ranks, each harmonic split": [],
            "spread: one harmonic per rank (emulated)": []}
    for k in range(args.repeat):
        for label, ranks in (("one rank, both harmonics", 1),
                             ("two ranks, each harmonic split", 2)):
            directory = os.path.join(OUT, "runs", "harmonics-%d-%d" % (ranks, k))
            s = summary(start(ranks, "1, 3", directory), directory)
            runs[label].append((s["seconds_per_substitution"], s["seconds_per_iteration"],
                                s["peak_memory_mb_per_rank"], s["equations"]))
        directories = [os.path.join(OUT, "runs", "harmonics-spread-%s-%d" % (h, k))
                       for h in ("1", "3")]
        processes = [start(1, h, d, one_core=True) for h, d in zip(("1", "3"), directories)]
        spread = [summary(p, d) for p, d in zip(processes, directories)]
        # Harmonic 3 alone carries no load here: its run's iteration time is
        # no iteration's; harmonic 1's run iterates as a rank would.
        runs["spread: one harmonic per rank (emulated)"].append(
            (max(s["seconds_per_substitution"] for s in spread),
             spread[0]["seconds_per_iteration"],
             max(s["peak_memory_mb_per_rank"] for s in spread),
             sum(s["equations"] for s in spread)))
    header = ("| layout | equations | substitution ms per iteration | ms per iteration "
              "| peak MB per rank |")
    lines = [header, "|---|---|---|---|---|"]
    for label, rows in runs.items():
        lines.append("| %s | %d | %.1f | %.1f | %.0f |" % (
            label, rows[0][3], 1e3 * statistics.median(r[0] for r in rows),
            1e3 * statistics.median(r[1] for r in rows),
            statistics.median(r[2] for r in rows)))
    os.makedirs(OUT, exist_ok=True)
    with open(os.path.join(OUT, "harmonics.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
