#!/usr/bin/python3
"""Figure 12 and Table 2 of Griffiths (Case 4, passive earth pressure).

    /usr/bin/python3 -m thinlayer_tools.plots.case4 SMOOTH_DIR ROUGH_SWEEP_DIR

SMOOTH_DIR is the output of prm/case4-smooth-wall.prm, ROUGH_SWEEP_DIR of
prm/case4-figure12.prm (a sweep over the wall column's adhesion). Writes
figure12.png (passive force against wall movement for each C_w / c_u) and
table2.md (computed K_pc against CP2's 2.0, 2.4, 2.6) into ROUGH_SWEEP_DIR.
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from thinlayer_tools import results  # noqa: E402

CP2 = {0.0: 2.0, 0.5: 2.4, 1.0: 2.6}
C_U = 1.0


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main(smooth, rough):
    curves = [(0.0, read(os.path.join(smooth, "history.csv")))]
    for r in read(os.path.join(rough, "sweep.csv")):
        curves.append((float(r["Material 2/Cohesion"]) / C_U,
                       read(os.path.join(rough, "run-%03d" % int(r["run"]), "history.csv"))))
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    lines = ["| C_w / c_u | CP2 K_pc | computed K_pc (last step) | error | peak | "
             "iterations |", "|---|---|---|---|---|---|"]
    # Converged, accepted states only.
    curves = [(ratio, results.states(steps)) for ratio, steps in curves]
    smooth_final = float(curves[0][1][-1]["load"])
    for ratio, steps in sorted(curves):
        u = [0] + [float(s["displacement"]) for s in steps]
        p = [0] + [float(s["load"]) for s in steps]
        line, = ax.plot(u, p, "-", label="C_w / c_u = %g" % ratio)
        ax.axhline(CP2[ratio], color=line.get_color(), ls=":", lw=1)
        final = p[-1]
        lines.append("| %g | %.1f | %.3f | %+.1f%% | %.3f | %d |" % (
            ratio, CP2[ratio], final, 100 * (final / CP2[ratio] - 1), max(p),
            sum(int(s["iterations"]) for s in steps)))
    lines.append("")
    lines.append("Rough (C_w = c_u) over smooth: %+.0f%% (CP2: +30%%)."
                 % (100 * (float(sorted(curves)[-1][1][-1]["load"]) / smooth_final - 1)))
    ax.set_xlabel("wall movement E delta / (c_u H)")
    ax.set_ylabel("K_pc = P_p / (c_u H)")
    ax.set_title("passive resistance (dotted: CP2, Table 2)")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(rough, "figure12.png"), dpi=120)
    results.record(os.path.join(rough, "figure12.png"))
    with open(os.path.join(rough, "table2.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    results.record(os.path.join(rough, "table2.md"))
    print("\n".join(lines))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("smooth", help="results of prm/case4-smooth-wall.prm")
    parser.add_argument("rough", help="results of prm/case4-figure12.prm (a sweep)")
    arguments = parser.parse_args()
    main(arguments.smooth, arguments.rough)
