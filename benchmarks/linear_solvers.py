#!/usr/bin/python3
"""The linear solvers against each other on the elastic stiffness: the
direct factorisation (CHOLMOD on one rank, MUMPS on several), MUMPS with
block low-rank compression (several ranks), and conjugate gradients
preconditioned by algebraic multigrid (Solver/Linear solver = amg cg,
PETSc's GAMG with the rigid-body motions). Scenes: Prandtl's footing at
growing meshes (cells graded at the same proportions), the footing on 3840
cells graded 1.15 per cell (cells of aspect ratio up to ~100 near the
footing's edge), Case 1's column at mesh level 3 with a thin layer as
stiff as the blocks at aspect ratios 1 to 1000, and ten times stiffer at
10, and the 3D rigid circular footing at about 40,000 and 120,000 DoFs
(without amg cg, whose set-up there takes longer than the rest of the
benchmark).

Under the table, per scene and rank count with more than one solver, the
verdict on Solver/Linear solver = automatic
(thinlayer_tools.speed_targets.automatic_solver): whether the solver it
picks (CHOLMOD on one rank; on several, block low-rank for a 3D mesh and
MUMPS uncompressed for a plane one) is the fastest per solve, times within
5% counting as equal.

Each run is one elastic load step; per run: the set-up time (assembly,
factorisation or multigrid set-up, and the ten solves that time one),
the time of one solve (median of ten,
summary.json's seconds_per_substitution), CG iterations per solve, and the
largest peak memory of any rank. Medians of REPEAT runs. A run whose CG
does not converge in Solver/Linear solver iterations (here 20000) is
listed as failed.

    /usr/bin/python3 -m benchmarks.linear_solvers [--repeat 3] [--ranks 1,2] [--large] [--only TEXT]
        [--output DIR]

--large adds Prandtl at 131072 cells and the 3D footing at about 259,000
DoFs; --only runs the scenes whose label contains TEXT ("131072"; "A|B"
for either). Writes output/benchmarks/ (or --output)
linear_solvers.csv and linear_solvers.md and prints the table.
"""
import argparse
import csv
import json
import os
import statistics
import subprocess

from thinlayer_tools import THINLAYER, TOP, mpirun, speed_targets
from thinlayer_tools.cases import PARAMETER_FILES, PRANDTL_SIZES, geometry

from benchmarks import page

OUT = os.path.join(TOP, "output", "benchmarks")
SOLVERS = (("direct", "cholmod"), ("direct, block low-rank", "block low-rank"),
           ("AMG-CG", "amg cg"))
FOOTING_3D = "prm/circular-footing-rigid-3d.prm"
FOOTING_3D_MESHES = (
    (None, "about 40,000 DoFs"),
    ("sector=90, footing=0, half_width=1, width=5, depth=3, n_around=5, n_footing=6, "
     "n_side=24, n_depth=28, growth=1.2", "about 120,000 DoFs"))
FOOTING_3D_LARGE = ("sector=90, footing=0, half_width=1, width=5, depth=3, n_around=6, "
                    "n_footing=8, n_side=32, n_depth=38, growth=1.14", "about 259,000 DoFs")


def scenes(large):
    """(label, parameter file, entries, whether amg cg runs) of every
    scene."""
    sizes = [2048, 8192, 32768] + ([131072] if large else [])
    for cells in sizes:
        yield ("Prandtl, %d cells" % cells, PARAMETER_FILES["prandtl"],
               ("Mesh/Geometry parameters=" + PRANDTL_SIZES[cells],
                "Loading/Load increments=0.1"), True)
    yield ("Prandtl, 3840 cells graded 1.15", PARAMETER_FILES["prandtl"],
           ("Mesh/Geometry parameters=half_width=1, width=5, depth=3, n_footing=32, "
            "n_side=48, n_depth=48, growth=1.15", "Loading/Load increments=0.1"), True)
    for ar, stiffness in ((1, 1), (10, 1), (100, 1), (1000, 1), (10, 10)):
        label = "Case 1, layer AR %d%s" % (ar, ", 10x stiffer" if stiffness > 1 else "")
        yield (label, PARAMETER_FILES["case1"],
               ("Mesh/Geometry parameters=" + geometry("case1", 3, ar),
                "Material 2/Young's modulus=%g" % (1e5 * stiffness),
                "Loading/Load increments=0.1", "Loading/Collapse resolution=0"), True)
    for mesh, size in FOOTING_3D_MESHES + ((FOOTING_3D_LARGE,) if large else ()):
        yield ("3D rigid footing, " + size, FOOTING_3D,
               (("Mesh/Geometry parameters=" + mesh,) if mesh else ()) +
               ("Loading/Load increments=0.01", "Loading/Collapse resolution=0"), False)


def run_once(ranks, parameter_file, entries, solver, directory):
    command = mpirun(ranks) + [THINLAYER, os.path.join(TOP, parameter_file),
                               "-s", "Mesh/Maximum cells=200000",
                               "-s", "Solver/Method=viscoplastic",
                               "-s", "Solver/Linear solver=" + solver,
                               "-s", "Output/Directory=" + directory,
                               "-s", "Output/Write VTU=false",
                               "-s", "Output/Print timing=false"]
    if solver == "amg cg":
        command += ["-s", "Solver/Linear solver iterations=20000"]
    for entry in entries:
        command += ["-s", entry]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        return {"failed": done.stderr.strip().splitlines()[-1][:120]}
    with open(os.path.join(directory, "summary.json")) as f:
        return json.load(f)


def main():
    global OUT
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--ranks", default="1")
    parser.add_argument("--large", action="store_true")
    parser.add_argument("--only", default="",
                        help="run the scenes whose label contains this (or one of A|B)")
    parser.add_argument("--output", default=OUT, help="the results directory (default %(default)s)")
    page.add_argument(parser)
    args = parser.parse_args()
    page.configure(args)
    OUT = os.path.abspath(args.output)
    os.makedirs(OUT, exist_ok=True)
    rows = []
    for label, parameter_file, entries, amg in scenes(args.large):
        if not any(part in label for part in args.only.split("|")):
            continue
        for ranks in (int(r) for r in args.ranks.split(",")):
            for name, solver in SOLVERS:
                if (solver == "block low-rank" and ranks == 1) or (solver == "amg cg" and not amg):
                    continue
                directory = os.path.join(OUT, "runs", "linear-solver")
                runs = [run_once(ranks, parameter_file, entries, solver, directory)
                        for _ in range(args.repeat)]
                row = {"scene": label, "ranks": ranks,
                       "solver": name if ranks == 1 or name != "direct" else "direct (MUMPS)"}
                if any("failed" in r for r in runs):
                    row.update({"equations": "", "setup_s": "", "solve_s": "",
                                "cg_iterations": "", "peak_mb_per_rank": "", "wall_s": "",
                                "kinematics": "",
                                "note": next(r["failed"] for r in runs if "failed" in r)})
                else:
                    s = runs[-1]
                    row.update({
                        "equations": s["equations"],
                        "setup_s": statistics.median(
                            r["timing"]["setup and factorisation"] for r in runs),
                        "solve_s": statistics.median(r["seconds_per_substitution"] for r in runs),
                        "cg_iterations": s["linear_iterations_per_solve"],
                        "peak_mb_per_rank": statistics.median(
                            r["peak_memory_mb_per_rank"] for r in runs),
                        "wall_s": sum(r["wall_seconds"] for r in runs),
                        "kinematics": s["kinematics"],
                        "note": ""})
                print(row, flush=True)
                rows.append(row)

    with open(os.path.join(OUT, "linear_solvers.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)

    def number(value, pattern):
        return pattern % value if isinstance(value, (int, float)) and value == value else "-"

    lines = ["| scene | equations | ranks | solver | set-up s (with 10 solves) | s per solve | CG iterations "
             "per solve | peak MB per rank | note |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %s | %s | %d | %s | %s | %s | %s | %s | %s |" % (
            r["scene"], r["equations"], r["ranks"], r["solver"],
            number(r["setup_s"], "%.2f"), number(r["solve_s"], "%.4f"),
            number(r["cg_iterations"], "%.0f"), number(r["peak_mb_per_rank"], "%.0f"),
            r["note"]))
    lines += ["", "Targets:", ""] + speed_targets.table(speed_targets.automatic_solver(rows))
    page.write(OUT, "linear_solvers", "Linear solvers", lines)


if __name__ == "__main__":
    main()
