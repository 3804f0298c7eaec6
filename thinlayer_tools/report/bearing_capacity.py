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


N_GAMMA = "strip-footing-n-gamma"
# Martin (2005), the method of characteristics: a rough strip footing, phi = 30.
N_GAMMA_MESH = ("Mesh/Geometry parameters=half_width=1, width=8, depth=5, n_footing=%d, "
                "n_side=%d, n_depth=%d, growth=%g")
N_GAMMA_RUNS = (  # name, overrides, mesh, method, also in --quick
    ("n-gamma-coarse", (N_GAMMA_MESH % (8, 12, 10, 1.14),), "2 h (8 under the half footing)",
     "default", True),
    ("n-gamma", (), "file's, h (16)", "default", True),
    ("n-gamma-fine", (N_GAMMA_MESH % (32, 48, 40, 1.035),), "h / 2 (32)", "default", False),
    ("n-gamma-paper", PAPER, "file's, h (16)", "paper's", True))


def n_gamma_runs(quick):
    return [run for run in N_GAMMA_RUNS if run[4] or not quick]


def run_list(quick):
    runs = [(run_name(phi, f), SCENE, overrides(phi, f)) for phi in angles(quick)
            for f in ("N_q", "N_c")]
    runs.append((run_name(30, "N_q", "-paper"), SCENE, PAPER + overrides(30, "N_q")))
    runs += [(name, N_GAMMA, extra + ("Output/Write VTU=false",))
             for name, extra, _, _, _ in n_gamma_runs(quick)]
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
    names = [n for n, _, _ in run_list(quick) if not n.startswith("n-gamma")]
    why = ("A smooth rigid strip footing pushed into weightless Mohr-Coulomb soil with "
           "associated flow (prm/%s.prm, half the footing on 16 elements, E = 1e4 q): N_q "
           "with a surcharge q beside the footing, the soil starting from the K0 procedure's "
           "stresses sigma_v = -q (Initial state/Surcharge; K0 = 1), and N_c with c = 1 from "
           "a stress-free start. Prandtl's and Reissner's factors are exact for weightless "
           "soil; a displacement method collapses above them: asked, every plateau lies above "
           "its factor and within %.0f%%. %s N_gamma (soil with weight) has a section of its "
           "own." % (
               SCENE, 100 * WITHIN, "It does." if good else "It does NOT."))
    return Section(
        "bearing-capacity", "Bearing capacity factors N_q and N_c",
        "(not in the paper) N_q = exp(pi tan phi) tan^2(45 + phi/2), N_c = (N_q - 1) cot phi "
        "(Prandtl 1920, Reissner 1924).",
        "agrees" if good else "disagrees", why, rows=table,
        cost="%.1f s for the %d runs" % (runs.seconds(*names), len(names)),
        paper_value="N_q, N_c for phi = 20, 30",
        our_value=", ".join(table[k][4] for k in range(1, len(table)) if table[k][2] == "default"))


def n_gamma(runs, quick):
    """N_gamma of a rough strip footing against Martin's exact value, and the
    first-order extrapolation of two meshes."""
    table = [["mesh", "method", "outcome", "N_gamma", "exact", "error", "iterations",
              "wall s"]]
    found = {}
    # Martin's exact value, as prm/strip-footing-n-gamma.prm states it.
    exact = runs.summary(n_gamma_runs(quick)[0][0])["reference_load"]
    for name, _, mesh, method, _ in n_gamma_runs(quick):
        s = runs.summary(name)
        found[name] = results.collapse_load(s)
        last = results.number(s.get("last_converged_load"))
        shown = ("%.3f" % found[name] if found[name]
                 else "%.3f (last converged)" % last if last else "-")
        table.append([mesh, method, s["outcome"], shown, "%.2f" % exact,
                      "%+.2f%%" % (100 * (found[name] / exact - 1)) if found[name]
                      else "-", "%d" % s["total_iterations"], "%.2f" % s["wall_seconds"]])
    # The two finest meshes run (--quick leaves h / 2 out).
    coarse, fine = ((found["n-gamma-coarse"], found["n-gamma"]) if quick
                    else (found["n-gamma"], found["n-gamma-fine"]))
    extrapolated = 2 * fine - coarse if coarse and fine else None
    if extrapolated:
        table.append(["extrapolated from the two finest, 2 N(h/2) - N(h)", "default", "-",
                      "%.3f" % extrapolated, "%.2f" % exact,
                      "%+.2f%%" % (100 * (extrapolated / exact - 1)), "-", "-"])
    good = extrapolated is not None and coarse > fine > exact and \
        abs(extrapolated / exact - 1) < 0.02
    why = ("A rough rigid strip footing (fixed horizontally) pushed into cohesionless "
           "Mohr-Coulomb soil with weight and no surcharge, phi = 30 degrees, associated "
           "flow, from the K0 procedure's stresses (prm/%s.prm): with B = 2 and gamma = 1 its "
           "pressure at collapse is N_gamma. The method of characteristics gives it exactly "
           "(Martin 2005, with his program ABC): %.2f. A displacement method collapses "
           "above it; asked, the plateau falls towards it from above when the elements' "
           "size is halved, and the first-order extrapolation 2 N(h/2) - N(h) of the two "
           "finest meshes run lies within 2%%. %s" % (N_GAMMA, exact, "It does." if good else "It does NOT."))
    names = [name for name, _, _, _, _ in n_gamma_runs(quick)]
    return Section(
        "bearing-capacity-n-gamma", "Bearing capacity factor N_gamma",
        "(not in the paper) N_gamma = %.2f for a rough footing, phi = 30 (Martin 2005, exact)."
        % exact,
        "agrees" if good else "disagrees", why, rows=table,
        cost="%.1f s for the %d runs" % (runs.seconds(*names), len(names)),
        paper_value="%.2f" % exact,
        our_value="%.3f, %.3f (two finest); extrapolated %s" % (
            coarse or float("nan"), fine or float("nan"),
            "%.3f" % extrapolated if extrapolated else "-"))


def sections(runs, quick):
    return [bearing_capacity(runs, quick), n_gamma(runs, quick)]
