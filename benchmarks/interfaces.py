#!/usr/bin/python3
"""Thin layers against zero-thickness interface elements, case by case.

For Cases 1 (adhesive, alpha = 45), 2 and 3 (the footings, the row under
the footing only: the paper's "better mesh") and 4 (rough wall), runs the
thin-layer scene over the layer's aspect ratio (10 to 10000) and the
zero-thickness scene over the interface stiffness k_n = k_s (10 to 1e8 times
E / L, with E the soil's modulus and L the case's length: column width,
footing half-width or radius, wall height), all by the default method, and
tables per run: the outcome, the collapse load (none unless the run ended in
a collapse or a plateau), its error against the analytic value, iterations,
wall time, and the oscillation of the raw normal traction (at the
integration points, Output/Gauss-point profiles) along the interface at the
last accepted step (the median second difference between neighbouring
samples over the median traction: 0 for a linear profile). Writes
output/benchmarks/interfaces/interfaces.csv, .md (also printed) and
interfaces.png.

Case 4 is measured by the reaction on the wall for both models (not the
paper's average stress in the column, which the zero-thickness wall does
not have), against CP2's 2.6 (the slip-line value is 2.571).
"""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from benchmarks.outcomes import run  # noqa: E402 (a run by the default method)
from benchmarks.run import write_results  # noqa: E402
from benchmarks import page  # noqa: E402
from thinlayer_tools import TOP, cases, results  # noqa: E402

OUT = os.path.join(TOP, "output", "benchmarks", "interfaces")

E_OVER_L = 1e5  # every case: E = 1e5 of the soil or blocks, L = 1

# case: title, thin-layer file, its geometry with {ar}, layer material id;
# zero-thickness file, its geometry, its interface curves, the curve
# profiled; entries for both models.
CASES = {
    "case1": ("Case 1, adhesive, alpha 45",
              cases.PARAMETER_FILES["case1"], cases.geometry("case1", 1, alpha=45), 2,
              "prm/case1-inclined-adhesive-zero-thickness.prm",
              "alpha=45, elements_along=8, elements_block=8, zero_thickness=1", [3], 3, []),
    "case2": ("Case 2, strip footing",
              "prm/case2-strip-footing-better-mesh.prm",
              "half_width=1, width=5, depth=3, aspect_ratio={ar}, n_footing=8, "
              "n_side=12, n_depth=10, interface_beyond_footing=0", 2,
              "prm/case2-strip-footing-zero-thickness.prm",
              "half_width=1, width=5, depth=3, n_footing=8, n_side=12, n_depth=10, "
              "zero_thickness=1", [5], 5, []),
    "case3": ("Case 3, circular footing",
              "prm/case3-circular-footing-better-mesh.prm",
              "half_width=1, width=5, depth=3, aspect_ratio={ar}, n_footing=8, "
              "n_side=12, n_depth=10, interface_beyond_footing=0", 2,
              "prm/case3-circular-footing-zero-thickness.prm",
              "half_width=1, width=5, depth=3, n_footing=8, n_side=12, n_depth=10, "
              "zero_thickness=1", [5], 5, []),
    "case4": ("Case 4, rough wall",
              cases.PARAMETER_FILES["case4"], cases.geometry("case4", 1), 2,
              "prm/case4-rough-wall-zero-thickness.prm",
              "wall_height=1, width=3, depth=2, aspect_ratio=10, n_wall=10, n_below=5, "
              "n_x=12, zero_thickness=1", [6, 7], 6,
              ["Monitors/Load measure=reaction", "Monitors/Load boundary id=1",
               "Monitors/Load component=x", "Monitors/Load scale=1"]),
}
ASPECT_RATIOS = [10, 100, 1000, 10000]
STIFFNESS_FACTORS = [10, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8]
# The oscillation is the raw tractions' (the profiles' recovered ones are
# smooth by construction).
RAW = "Output/Gauss-point profiles=true"


def oscillation(directory, pattern):
    """Median |second difference| over median |value| of the normal
    traction along the first run at angle 0, at the last accepted step."""
    states = results.states(results.history(directory))
    if not states:
        return float("nan")
    path = os.path.join(directory, pattern % int(states[-1]["step"]))
    if not os.path.exists(path):
        return float("nan")
    rows = [r for r in results.read_csv(path)
            if r["run"] == "0" and abs(results.number(r["angle"])) < 1e-9]
    values = [results.number(r["normal_traction"]) for r in rows]
    if len(values) < 3:
        return float("nan")
    second = sorted(abs(values[k - 1] - 2 * values[k] + values[k + 1])
                    for k in range(1, len(values) - 1))
    size = sorted(abs(v) for v in values)
    return second[len(second) // 2] / size[len(size) // 2] if size[len(size) // 2] else float("nan")


def measure(case, model, parameter, summary, directory, pattern):
    error = results.collapse_error(summary)
    load = results.collapse_load(summary)
    return {"case": case, "model": model, "parameter": parameter,
            "outcome": summary.get("outcome", "error"),
            "collapse_load": load if load is not None else float("nan"),
            "analytic": results.number(summary.get("reference_load")),
            "error": error if error is not None else float("nan"),
            "iterations": int(summary.get("total_iterations", 0)),
            "wall_seconds": results.number(summary.get("wall_seconds")),
            "oscillation": oscillation(directory, pattern)
            if summary.get("outcome") != "error" else float("nan")}


HEADER = ("| case | model | aspect ratio or k / (E/L) | outcome | collapse load | analytic "
          "| error | iterations | time (s) | traction oscillation |")


def format_row(r):
    def number(value, form):
        return form % value if math.isfinite(value) else "-"
    return "| %s | %s | %g | %s | %s | %s | %s | %d | %s | %s |" % (
        r["case"], r["model"], r["parameter"], r["outcome"],
        number(r["collapse_load"], "%.4f"), number(r["analytic"], "%.4g"),
        number(100 * r["error"], "%+.2f%%"), r["iterations"],
        number(r["wall_seconds"], "%.2f"), number(r["oscillation"], "%.3f"))


def chart(rows, path):
    metrics = [("error", "collapse load error\nagainst the analytic value (%)", 100),
               ("iterations", "iterations (all steps)", 1),
               ("wall_seconds", "wall time (s)", 1),
               ("oscillation", "normal traction oscillation\n(median 2nd difference / median)", 1)]
    figure, axes = plt.subplots(len(metrics), 2, figsize=(11, 13), sharex="col")
    markers = {"case1": "o", "case2": "s", "case3": "^", "case4": "D"}
    for column, (model, xlabel) in enumerate(
            [("thin layer", "thin layer: aspect ratio L / t"),
             ("zero thickness", "zero-thickness elements: k_n = k_s, in units of E / L")]):
        for row, (key, label, scale) in enumerate(metrics):
            axis = axes[row][column]
            for case, (title, *_rest) in CASES.items():
                # A refused run (outcome error) has no figures at all.
                points = [r for r in rows if r["case"] == case and r["model"] == model
                          and r["outcome"] != "error"]
                good = [r for r in points if math.isfinite(r[key])]
                axis.plot([r["parameter"] for r in good], [scale * r[key] for r in good],
                          marker=markers[case], label=title)
                if key == "error":
                    # Runs without a collapse load: marked at zero, never on the curve.
                    failed = [r for r in rows if r["case"] == case and r["model"] == model
                              and not math.isfinite(r["error"])]
                    if failed:
                        axis.plot([r["parameter"] for r in failed], [0] * len(failed), "x",
                                  color=axis.lines[-1].get_color(), markersize=10)
            axis.set_xscale("log")
            if key in ("wall_seconds", "iterations"):
                axis.set_yscale("log")
            if key == "error":
                axis.axhline(0, color="black", linewidth=0.8)
            axis.set_ylabel(label)
            axis.grid(alpha=0.3, which="both")
        axes[-1][column].set_xlabel(xlabel)
    axes[0][0].legend(fontsize=8)
    axes[0][1].plot([], [], "x", color="grey", markersize=10,
                    label="no collapse load: not converged, or refused\n"
                          "(k above 1e6 E/h of the cells beside it)")
    axes[0][1].legend(fontsize=8)
    axes[0][0].set_title("thin layers (one element thick)")
    axes[0][1].set_title("zero-thickness (Goodman-type) elements")
    figure.suptitle("Thin layers against zero-thickness interface elements, default method")
    figure.tight_layout()
    figure.savefig(path, dpi=100)
    plt.close(figure)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true",
                        help="aspect ratios 10 and 1000, stiffnesses 10, 1e4 and 1e8 E/L")
    parser.add_argument("--replot", action="store_true",
                        help="redraw the chart from the last interfaces.csv, running nothing")
    parser.add_argument("--cases", default=",".join(CASES),
                        help="comma-separated subset of " + ", ".join(CASES))
    page.add_argument(parser)
    arguments = parser.parse_args()
    page.configure(arguments)
    if arguments.replot:
        rows = results.read_csv(os.path.join(OUT, "interfaces.csv"))
        for r in rows:
            for key in ("parameter", "collapse_load", "analytic", "error",
                        "iterations", "wall_seconds", "oscillation"):
                r[key] = results.number(r[key])
        chart(rows, os.path.join(OUT, "interfaces.png"))
        print("wrote", os.path.join(OUT, "interfaces.png"))
        return
    ratios = [10, 1000] if arguments.quick else ASPECT_RATIOS
    factors = [10, 1e4, 1e8] if arguments.quick else STIFFNESS_FACTORS
    os.makedirs(OUT, exist_ok=True)
    rows = []
    for case in arguments.cases.split(","):
        if case not in CASES:
            sys.exit("unknown case %r; expected one of %s" % (case, ", ".join(CASES)))
        (title, thin, geometry, material, zero, zero_geometry, curves, profiled,
         common) = CASES[case]
        for ratio in ratios:
            directory = os.path.join(OUT, "%s-thin-%d" % (case, ratio))
            summary = run(thin, geometry.format(ar=ratio), "default", directory,
                          ["Layers/Material ids=%d" % material, RAW] + common)
            rows.append(measure(case, "thin layer", ratio, summary, directory,
                                "layer-%d-gauss-%%04d.csv" % material))
            print(format_row(rows[-1]), flush=True)
        for factor in factors:
            directory = os.path.join(OUT, "%s-zero-%g" % (case, factor))
            entries = []
            for curve in curves:
                entries += ["Interface %d/Normal stiffness=%g" % (curve, factor * E_OVER_L),
                            "Interface %d/Shear stiffness=%g" % (curve, factor * E_OVER_L)]
            summary = run(zero, zero_geometry, "default", directory, entries + [RAW] + common)
            rows.append(measure(case, "zero thickness", factor, summary, directory,
                                "interface-%d-gauss-%%04d.csv" % profiled))
            print(format_row(rows[-1]), flush=True)
    write_results(rows, "interfaces", HEADER, format_row, OUT)
    chart(rows, os.path.join(OUT, "interfaces.png"))
    print("wrote", os.path.join(OUT, "interfaces.png"))


if __name__ == "__main__":
    main()
