"""The report's section on a pile's shaft resistance: a rigid pile pushed
down through cohesionless Mohr-Coulomb soil with weight, by Fourier
harmonic 0, sliding on zero-thickness Coulomb interface elements
(prm/pile-shaft-axial-zero-thickness.prm) or on a thin frictional layer of
elements (prm/pile-shaft-axial.prm). The truths are Coulomb's law on every
point of the shaft and the statics of the pile (its load is the
interface's or the layer's shear); the classical beta-method estimate is
compared, its difference measured."""
import glob
import math
import os

import matplotlib.pyplot as plt

from thinlayer_tools import results
from thinlayer_tools.report import figures
from thinlayer_tools.report.page import Section
from thinlayer_tools.report.runs import PAPER

SCENE = "pile-shaft-axial-zero-thickness"
# The scene's pile and soil (its parameter file).
R, T, L, K0, GAMMA, DELTA = 0.5, 0.05, 10.0, 0.6, 1.0, 20.0
BETA = math.pi * (R + T) * L ** 2 * K0 * GAMMA * math.tan(math.radians(DELTA))
LAYER_SCENE = "pile-shaft-axial"
# The layer's scene: K = K0 = 1, tan(delta) = sin(phi_s) (Davis 1968).
PHI_S, K_LAYER = 20.0, 1.0
BETA_LAYER = math.pi * R * L ** 2 * K_LAYER * GAMMA * math.sin(math.radians(PHI_S))
# Asked: the load is the interface's shear within the soft toe column's
# base (0.5%), and every shaft point slides to 1e-6 of the largest traction.
STATICS, SLIDING = 0.005, 1e-6


# The truths are of the points' own states (Coulomb's law at each): the
# runs also write the raw profiles, at the Gauss points, which they read.
RAW = ("Output/Write VTU=false", "Output/Gauss-point profiles=true")


def run_list(quick):
    return [("pile-shaft", SCENE, RAW),
            ("pile-shaft-paper", SCENE, PAPER + ("Output/Write VTU=false",)),
            ("pile-shaft-layer", LAYER_SCENE, RAW),
            ("pile-shaft-layer-paper", LAYER_SCENE, PAPER + ("Output/Write VTU=false",))]


def layer_integrals(directory):
    """The last step's layer profile (two Gauss points per cell side, on
    the layer's midline): its shear divided by the estimate, the points
    that do not yield, the largest excess over Coulomb's line of the layer
    (tau - sigma_n tan(phi_s), relative to the largest traction), and the
    range of tau / sigma_n."""
    last = sorted(glob.glob(os.path.join(directory, "layer-2-gauss-*.csv")))[-1]
    rows = sorted(results.read_csv(last), key=lambda r: float(r["y"]))
    shear, elastic, beyond, largest, ratios = 0.0, 0, 0.0, 0.0, []
    for k in range(0, len(rows) - 1, 2):
        h = (float(rows[k + 1]["y"]) - float(rows[k]["y"])) * math.sqrt(3)
        for row in rows[k:k + 2]:
            tau, sigma = abs(float(row["shear_traction"])), -float(row["normal_traction"])
            shear += 2 * math.pi * float(row["x"]) * h / 2 * tau
            elastic += int(float(row["plastic"])) == 0
            beyond = max(beyond, tau - sigma * math.tan(math.radians(PHI_S)))
            largest = max(largest, sigma)
            ratios.append(tau / sigma)
    return shear / BETA_LAYER, elastic, beyond / largest, min(ratios), max(ratios)


def integrals(directory):
    """The last step's interface profile integrated with its Gauss points
    (three per cell side): the shaft's shear, the shear below the toe, the
    normal traction on the shaft, the worst departure from Coulomb's law,
    each force divided by the beta method's estimate; and the samples."""
    last = sorted(glob.glob(os.path.join(directory, "interface-6-gauss-*.csv")))[-1]
    rows = sorted(results.read_csv(last), key=lambda r: float(r["y"]))
    tan_delta = math.tan(math.radians(DELTA))
    shaft = below = normal = worst = largest = 0.0
    for k in range(0, len(rows) - 2, 3):
        h = (float(rows[k + 2]["y"]) - float(rows[k]["y"])) / math.sqrt(3 / 5)
        for row, weight in zip(rows[k:k + 3], (5 / 18, 8 / 18, 5 / 18)):
            w = 2 * math.pi * float(row["x"]) * h * weight
            tau, sigma = float(row["shear_traction"]), -float(row["normal_traction"])
            if -float(row["y"]) > L:
                below += w * tau
                continue
            shaft += w * tau
            normal += w * sigma
            worst = max(worst, abs(abs(tau) - sigma * tan_delta))
            largest = max(largest, sigma)
    return (abs(shaft) / BETA, abs(below) / BETA, normal * tan_delta / BETA,
            worst / largest, rows)


def pile(runs, quick):
    s = runs.summary("pile-shaft")
    shaft, below, normal, slip, rows = integrals(runs.path("pile-shaft"))
    load = results.number(s.get("last_converged_load"))
    plateau = results.collapse_load(s)
    paper = runs.summary("pile-shaft-paper")
    table = [["quantity", "divided by the beta method's estimate", "note"],
             ["load at its plateau (collapse_load)", "%.4f" % plateau if plateau else "-",
              s["outcome"]],
             ["load at the end of the programme", "%.4f" % load, "rises slowly: the toe"],
             ["shaft resistance, int 2 pi r tau", "%.4f" % shaft,
              "%+.1f%% against the estimate" % (100 * (shaft - 1))],
             ["below the toe: the column's drag on the soil", "%.4f" % below, "-"],
             ["tan(delta) int 2 pi r sigma_n over the shaft", "%.4f" % normal,
              "equals the shaft resistance when every point slides"],
             ["paper's method: load", "%.4f (last converged)" %
              results.number(paper.get("last_converged_load")), paper["outcome"]]]
    statics = abs(load / (shaft + below) - 1)
    good = slip < SLIDING and statics < STATICS

    layer = runs.summary("pile-shaft-layer")
    layer_shear, elastic, beyond, low, high = layer_integrals(runs.path("pile-shaft-layer"))
    layer_plateau = results.collapse_load(layer)
    layer_load = results.number(layer.get("last_converged_load"))
    layer_statics = abs(layer_load / layer_shear - 1)
    good = good and elastic == 0 and beyond <= 1e-9 and layer_statics < STATICS
    table += [["thin layer (K = 1; estimate pi R L^2 K gamma sin(phi_s)): load at its "
               "plateau", "%.4f" % layer_plateau if layer_plateau else "-",
               "%s; %+.1f%% against the estimate" % (
                   layer["outcome"], 100 * (layer_plateau - 1)) if layer_plateau else
               layer["outcome"]],
              ["thin layer: load at the end; the layer's int 2 pi r tau",
               "%.4f; %.4f" % (layer_load, layer_shear),
               "statics %.2f%% apart" % (100 * layer_statics)],
              ["thin layer: tau / sigma_n along it", "%.3f to %.3f" % (low, high),
               "Davis's sin(phi_s) = %.3f; points not yielding: %d" % (
                   math.sin(math.radians(PHI_S)), elastic)]]
    layer_paper = runs.summary("pile-shaft-layer-paper")
    paper_plateau = results.collapse_load(layer_paper)
    table.append(["thin layer, paper's method: load", "%.4f" % paper_plateau if paper_plateau
                  else "%.4f (last converged)" % results.number(
                      layer_paper.get("last_converged_load")), layer_paper["outcome"]])

    fig, ax = plt.subplots(figsize=(5.5, 4))
    shaft_rows = [r for r in rows if -float(r["y"]) <= L]
    depth = [-float(r["y"]) for r in shaft_rows]
    ax.plot([-float(r["normal_traction"]) for r in shaft_rows], depth, ".-",
            label="normal traction on the shaft at the end")
    ax.plot([K0 * GAMMA * d for d in depth], depth, "k--", lw=1, label="K0 gamma z")
    ax.invert_yaxis()
    ax.set_xlabel("sigma_n / (gamma L) x L (gamma = 1, L = 10)")
    ax.set_ylabel("depth z")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    why = ("A rigid pile (R = 0.5, L = 10) pushed down through cohesionless Mohr-Coulomb "
           "soil (phi = 30, K0 = 0.6, gamma = 1) by Fourier harmonic 0, sliding on "
           "zero-thickness Coulomb interface elements (delta = 20), from the K0 procedure's "
           "stresses (prm/%s.prm). Asked, from the interface's profile at the end: every "
           "point of the shaft slides at tau = sigma_n tan(delta) (largest departure %.1e of "
           "the largest traction; asked below %.0e), and the pile's load is the interface's "
           "shear (statics: %.2f%% apart, asked below %.1f%%, the soft column's base under "
           "the toe carrying the rest). %s The beta method's estimate pi (R + t) L^2 K0 "
           "gamma tan(delta), which takes the normal traction as K0 gamma z, is not a truth "
           "here: as the shaft is loaded the normal traction rises above K0 gamma z near the "
           "ground and falls below it near the toe (the figure), and the shaft resistance "
           "ends %+.1f%% from it. The column under the toe drags the soil along its own side "
           "of the interface, so the load keeps rising slowly after its plateau. The same pile "
           "on a thin frictional layer of elements (prm/%s.prm: phi_s = 20, no dilation, "
           "t = R / 10, K0 = 1 so that the layer starts with sigma_z = sigma_r): asked, every "
           "point of the layer yields, none lies beyond tau = sigma_n tan(phi_s), and the "
           "pile's load is the layer's shear on its midline within %.1f%%. Its plateau lies "
           "%+.1f%% from the beta method with Davis's (1968) tan(delta) = sin(phi_s). With "
           "K0 = 0.6 the layer's normal stress near the ground grows without bound as the "
           "pile moves, and the default method stops converging with the load still rising "
           "(1.14 of its estimate)." % (
               SCENE, slip, SLIDING, 100 * statics, 100 * STATICS,
               "It does." if good else "It does NOT.", 100 * (shaft - 1), LAYER_SCENE,
               100 * STATICS, 100 * (layer_plateau - 1) if layer_plateau else math.nan))
    return Section(
        "pile-shaft", "A pile's shaft resistance (Fourier harmonic 0)",
        "(not in the paper) Q_s = int 2 pi r sigma_n tan(delta) dz; the beta method takes "
        "sigma_n = K0 gamma z.",
        "agrees" if good else "disagrees", why, rows=table,
        figures=[(figures.data_uri(fig), "The normal traction the soil keeps on the shaft "
                  "at the end of the loading, against the at-rest K0 gamma z.")],
        cost="%.1f s for the 4 runs" % runs.seconds("pile-shaft", "pile-shaft-paper",
                                                    "pile-shaft-layer", "pile-shaft-layer-paper"),
        paper_value="beta method: 1 (normalised)",
        our_value="interface elements: shaft %.4f, load %.4f; thin layer: load %s" % (
            shaft, load, "%.4f" % layer_plateau if layer_plateau else layer["outcome"]))


def sections(runs, quick):
    return [pile(runs, quick)]
