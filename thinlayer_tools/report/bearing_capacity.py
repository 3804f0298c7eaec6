"""The report's section on bearing capacity factors: a smooth rigid strip
footing on weightless Mohr-Coulomb soil, N_q under a surcharge (from the K0
procedure) and N_c with cohesion, against Prandtl and Reissner's exact
factors (prm/strip-footing-bearing-capacity.prm)."""
import math

from thinlayer_tools import results
from thinlayer_tools.report.page import Section
from thinlayer_tools.report.runs import PAPER

SCENE = "strip-footing-bearing-capacity"
ANGLES = (20, 30)
# Asked: above the exact factor (a displacement method) and within 3%.
WITHIN = 0.03
COHESION = ("Initial state/Procedure=none", "Initial state/Surcharge=0",
            "Material 1/Cohesion=1")


def factors(phi):
    t = math.tan(math.radians(phi))
    nq = math.exp(math.pi * t) * math.tan(math.radians(45 + phi / 2)) ** 2
    return {"N_q": nq, "N_c": (nq - 1) / t}


def run_name(phi, factor, what=""):
    return "bearing-%s-%d%s" % (factor.replace("_", "").lower(), phi, what)


def overrides(phi, factor):
    return ("Material 1/Friction angle=%d" % phi, "Material 1/Dilation angle=%d" % phi,
            "Reference/Analytic load=%.6g" % factors(phi)[factor],
            "Output/Write VTU=false") + (COHESION if factor == "N_c" else ())


def angles(quick):
    """The friction angles run: 30 degrees only in --quick."""
    return (30,) if quick else ANGLES


def run_list(quick):
    runs = [(run_name(phi, f), SCENE, overrides(phi, f)) for phi in angles(quick)
            for f in ("N_q", "N_c")]
    runs.append((run_name(30, "N_q", "-paper"), SCENE, PAPER + overrides(30, "N_q")))
    return runs


def bearing_capacity(runs, quick):
    table = [["phi", "factor", "method", "outcome", "found", "exact", "error", "iterations",
              "wall s"]]
    good = True
    for phi in angles(quick):
        for f in ("N_q", "N_c"):
            for what, method in (("", "default"), ("-paper", "paper's")):
                name = run_name(phi, f, what)
                if not runs.has(name):
                    continue
                s = runs.summary(name)
                found, exact = results.collapse_load(s), factors(phi)[f]
                table.append(["%d" % phi, f, method, s["outcome"],
                              "%.3f" % found if found else "-", "%.3f" % exact,
                              "%+.2f%%" % (100 * (found / exact - 1)) if found else "-",
                              "%d" % s["total_iterations"], "%.2f" % s["wall_seconds"]])
                if method == "default":
                    good = good and found is not None and 0 < found / exact - 1 < WITHIN
    names = [n for n, _, _ in run_list(quick)]
    why = ("A smooth rigid strip footing pushed into weightless Mohr-Coulomb soil with "
           "associated flow (prm/%s.prm, half the footing on 16 elements, E = 1e4 q): N_q "
           "with a surcharge q beside the footing, the soil starting from the K0 procedure's "
           "stresses sigma_v = -q (Initial state/Surcharge; K0 = 1), and N_c with c = 1 from "
           "a stress-free start. Prandtl's and Reissner's factors are exact for weightless "
           "soil; a displacement method collapses above them: asked, every plateau lies above "
           "its factor and within %.0f%%. %s N_gamma (soil with weight) is not checked: "
           "its published exact values (Martin 2005) are not at hand to cite." % (
               SCENE, 100 * WITHIN, "It does." if good else "It does NOT."))
    return Section(
        "bearing-capacity", "Bearing capacity factors N_q and N_c",
        "(not in the paper) N_q = exp(pi tan phi) tan^2(45 + phi/2), N_c = (N_q - 1) cot phi "
        "(Prandtl 1920, Reissner 1924).",
        "agrees" if good else "disagrees", why, rows=table,
        cost="%.1f s for the %d runs" % (runs.seconds(*names), len(names)),
        paper_value="N_q, N_c for phi = 20, 30",
        our_value=", ".join(table[k][4] for k in range(1, len(table)) if table[k][2] == "default"))


def sections(runs, quick):
    return [bearing_capacity(runs, quick)]
