"""The report's section on earth pressure with weight: a smooth vertical
wall moved away from (active) or into (passive) a cohesionless backfill
that starts from its at-rest stresses (prm/earth-pressure-rankine.prm),
against Rankine's coefficients, which are exact for a smooth wall."""
import math

import matplotlib.pyplot as plt

from thinlayer_tools import results
from thinlayer_tools.report import figures
from thinlayer_tools.report.page import Section
from thinlayer_tools.report.runs import PAPER

SCENE = "earth-pressure-rankine"
ANGLES = (20, 30, 40)
# --quick: the middle angle only.
QUICK_ANGLES = (30,)
SIDES = ("active", "passive")
# Asked of the default method: the plateau within the collapse
# resolution of K, the resultant within as much of H / 3.
WITHIN = 0.005


def rankine(phi, side):
    s = math.sin(math.radians(phi))
    return (1 - s) / (1 + s) if side == "active" else (1 + s) / (1 - s)


def run_name(phi, side, what=""):
    return "rankine-%s-%d%s" % (side, phi, what)


def overrides(phi, side, moment=False):
    return ("Material 1/Friction angle=%d" % phi,
            "Boundary 4/Displacement=%s; 0" % ("-1e-6" if side == "active" else "1e-6"),
            "Monitors/Displacement scale=%s" % ("-1e6" if side == "active" else "1e6"),
            "Reference/Analytic load=%.10g" % rankine(phi, side),
            "Output/Write VTU=false") + \
        (("Monitors/Load component=moment", "Monitors/Load scale=-2") if moment else ())


def angles(quick):
    return QUICK_ANGLES if quick else ANGLES


def run_list(quick):
    runs = []
    for phi in angles(quick):
        for side in SIDES:
            runs.append((run_name(phi, side), SCENE, overrides(phi, side)))
            runs.append((run_name(phi, side, "-moment"), SCENE, overrides(phi, side, True)))
    for side in SIDES:
        runs.append((run_name(30, side, "-paper"), SCENE, PAPER + overrides(30, side)))
    runs.append((run_name(30, "active", "-gravity"), SCENE,
                 ("Initial state/Procedure=gravity loading",) + overrides(30, "active")))
    return runs


def rankine_section(runs, quick):
    table = [["phi", "side", "method", "initial state", "K (plateau)", "Rankine", "error",
              "resultant / H", "iterations", "wall s"]]
    good = True
    names = []

    def row(name, phi, side, method, moment_name=None):
        names.append(name)
        s = runs.summary(name)
        k = results.collapse_load(s)
        truth = rankine(phi, side)
        error = k / truth - 1 if k else None
        height = None
        if moment_name:
            names.append(moment_name)
            m = results.collapse_load(runs.summary(moment_name))
            height = m / k if m and k else None
        table.append(["%d" % phi, side, method, s.get("initial_state", "none"),
                      "%.4f" % k if k else s["outcome"], "%.4f" % truth,
                      "%+.3f%%" % (100 * error) if error is not None else "-",
                      "%.4f" % height if height else "-",
                      "%d" % s["total_iterations"], "%.2f" % s["wall_seconds"]])
        return error, height

    for phi in angles(quick):
        for side in SIDES:
            error, height = row(run_name(phi, side), phi, side, "default",
                                run_name(phi, side, "-moment"))
            good = good and error is not None and abs(error) <= WITHIN and \
                height is not None and abs(3 * height - 1) <= WITHIN
    paper = [row(run_name(30, side, "-paper"), 30, side, "paper's") for side in SIDES]
    gravity, _ = row(run_name(30, "active", "-gravity"), 30, "active", "default")
    good = good and gravity is not None and abs(gravity) <= WITHIN

    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, side in zip(axes, SIDES):
        for phi in angles(quick):
            figures.curve(ax, runs.path(run_name(phi, side)), "phi = %d" % phi, marker=".")
            ax.axhline(rankine(phi, side), color="k", ls="--", lw=0.8)
        ax.set_xscale("symlog", linthresh=1)
        ax.set_xlim(left=0)
        ax.set_xlabel("wall movement %s the soil, 1e6 u / H" % (
            "away from" if side == "active" else "into"))
        ax.set_ylabel("wall force / (gamma H^2 / 2)")
        ax.set_title("%s (dashed: Rankine's K)" % side)
        ax.grid(alpha=0.3)
        figures.failure_legend(ax, fontsize=7, loc="center right")
    fig.tight_layout()

    paper_text = ", ".join("%s %s" % (side, "%.4f (%+.1f%%)" % (
        rankine(30, side) * (1 + e), 100 * e) if e is not None else "no plateau")
        for side, (e, _) in zip(SIDES, paper))
    why = ("A smooth wall of height H retaining a cohesionless Mohr-Coulomb backfill "
           "(no dilation, E = 1e5 gamma H) on a smooth base, 2H wide, which starts from the K0 "
           "procedure's at-rest stresses (K0 = 1 - sin(phi): Initial state/Procedure, "
           "Material <id>/K0) and is then moved by prescribed displacements (the default "
           "method, prm/%s.prm). Rankine's coefficients are exact for a smooth wall, and the "
           "pressure is linear in depth: asked, the wall's force levels off within %.1f%% of "
           "K gamma H^2 / 2 and the resultant, from the moment of the wall's reaction about "
           "the base, acts within %.1f%% of H / 3, for every angle both ways (phi = 20, 30 "
           "and 40; 30 only in --quick), and the same "
           "plateau is reached from gravity loading (elastic, so the at-rest ratio is then "
           "nu / (1 - nu)). %s The paper's method (viscoplastic, body-load criterion) on the "
           "same scene, phi = 30: %s. Near the ground surface the at-rest stresses are small, "
           "and its viscoplastic strain increments overshoot the cohesionless apex: its "
           "iterations stop with every point inside the yield surface, in states that are "
           "not the elastic-plastic response (the active force rises as the wall moves "
           "away); thinlayer flags the later ones as drift, the earlier ones not, and claims "
           "no plateau for a run with drift." % (
               SCENE, 100 * WITHIN, 100 * WITHIN,
               "It does." if good else "It does NOT.", paper_text))
    return Section(
        "earth-pressure-rankine", "Earth pressure with weight: Rankine",
        "(not in the paper) K_a = (1 - sin phi) / (1 + sin phi), K_p = 1 / K_a on a smooth "
        "wall (Rankine 1857), the resultant at H / 3.",
        "agrees" if good else "disagrees", why, rows=table,
        figures=[(figures.data_uri(fig), "Converged states of the loading, from the at-rest "
                  "state; dashed: Rankine's K.")],
        cost="%.1f s for the %d runs" % (runs.seconds(*names), len(names)),
        paper_value="K_a, K_p for phi = 20, 30, 40",
        our_value=", ".join("%.4f" % results.collapse_load(runs.summary(run_name(phi, side)))
                            for phi in angles(quick) for side in SIDES))


def sections(runs, quick):
    return [rankine_section(runs, quick)]
