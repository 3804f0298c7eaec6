"""The report's section on curved interfaces: a rigid circular pile
section moving laterally through weightless Tresca soil, its contact a
thin Tresca layer (prm/circular-inclusion.prm) or zero-thickness Tresca
interface elements (prm/circular-inclusion-zero-thickness.prm) of strength
alpha c, with the cells along the circles curved (Mesh/Curved cells =
true) or straight (the polygon), against Randolph and Houlsby's (1984)
exact limiting pressure."""
import math

from thinlayer_tools import results
from thinlayer_tools.report.page import Section

KINDS = {"layer": "circular-inclusion", "interface": "circular-inclusion-zero-thickness"}
# Asked: every curved run on the finest mesh within this of the exact
# pressure, and closer than on the coarsest.
WITHIN = 0.02


def plan(quick):
    """(alphas, cells per quarter circle)."""
    return ((0.01, 1.0), (6, 12)) if quick else ((0.01, 0.5, 1.0), (6, 12, 24))


def randolph_houlsby(alpha):
    """P / (c D) = pi + 2 Delta + 2 cos Delta + 4 (cos Delta/2 + sin Delta/2),
    sin Delta = alpha (Randolph and Houlsby 1984; exact: Martin and Randolph
    2006)."""
    d = math.asin(alpha)
    return math.pi + 2 * d + 2 * math.cos(d) + 4 * (math.cos(d / 2) + math.sin(d / 2))


def run_name(kind, alpha, n, curved):
    return "inclusion-%s-%g-%d-%s" % (kind, alpha, n, "curved" if curved else "straight")


def overrides(kind, alpha, n, curved):
    n_radial = 5 * n // 3
    geometry = "radius=1, thickness=0.02, outer=20, n_around=%d, n_radial=%d, growth=%.10g%s" % (
        n, n_radial, 1.2 ** (20 / n_radial), ", zero_thickness=1" if kind == "interface" else "")
    strength = ("Interface 4/Adhesion=%g" if kind == "interface"
                else "Material 2/Cohesion=%g") % alpha
    return ("Mesh/Geometry parameters=" + geometry, strength,
            "Mesh/Curved cells=%s" % ("true" if curved else "false"),
            "Reference/Analytic load=%.6f" % randolph_houlsby(alpha), "Output/Write VTU=false")


def run_list(quick):
    alphas, meshes = plan(quick)
    return [(run_name(kind, alpha, n, curved), scene, overrides(kind, alpha, n, curved))
            for kind, scene in KINDS.items() for alpha in alphas for n in meshes
            for curved in (True, False)]


def curved_interfaces(runs, quick):
    alphas, meshes = plan(quick)
    table = [["contact", "alpha", "exact P / (c D)"] +
             ["%s, %d per quarter" % (c, n) for c in ("curved", "straight") for n in meshes]]
    good = True
    worst_straight, worst_curved = 0.0, 0.0
    for kind in KINDS:
        for alpha in alphas:
            exact = randolph_houlsby(alpha)
            row = [{"layer": "thin layer t = R/50", "interface": "interface elements"}[kind],
                   "%g" % alpha, "%.3f" % exact]
            errors = {}
            for curved in (True, False):
                for n in meshes:
                    s = runs.summary(run_name(kind, alpha, n, curved))
                    load = results.collapse_load(s)
                    error = load / exact - 1 if load else None
                    errors[curved, n] = error
                    row.append("%.3f (%+.1f%%)" % (load, 100 * error) if load else s["outcome"])
            table.append(row)
            fine, coarse = errors[True, meshes[-1]], errors[True, meshes[0]]
            good = good and fine is not None and coarse is not None and \
                abs(fine) <= WITHIN and abs(fine) < abs(coarse)
            worst_curved = max(worst_curved, abs(fine) if fine is not None else math.inf)
            straight = errors[False, meshes[-1]]
            worst_straight = max(worst_straight, abs(straight) if straight is not None else 0)
    names = [name for name, _, _ in run_list(quick)]
    smooth = runs.summary(run_name("layer", alphas[0], meshes[-1], True))
    smooth_load = results.collapse_load(smooth)
    below = (" The thin layer's own width shows on the finest mesh: the smooth layer of width "
             "R / 50 ends below the exact value of a zero-thickness contact (%.3f)." % smooth_load
             if smooth_load and smooth_load < randolph_houlsby(alphas[0]) else "")
    why = ("A rigid circular pile section (R = 1) moving laterally through weightless Tresca "
           "soil (c = 1, E = 1e5 c, nu = 0.49) in plane strain, the half y >= 0 of the plane out "
           "to 20 R (meshes/circular-inclusion.geo, its circles drawn as gmsh arcs): the "
           "contact a thin Tresca layer t = R / 50 of strength alpha c (prm/%s.prm) or "
           "zero-thickness Tresca interface elements of adhesion alpha c on a stiff skin "
           "(prm/%s.prm, D = 2 (R + t)). Randolph and Houlsby's (1984) lower bound, which "
           "Martin and Randolph (2006) matched with an upper bound, is exact. Asked: with the "
           "cells following the circles, every contact and alpha ends within %.0f%% of it on "
           "%d cells per quarter circle (%d outwards), closer than on %d. %s With straight cells "
           "the contact slides on the polygon of its nodes and each vertex anchors it: the "
           "error on the finest mesh reaches %+.0f%% (a smooth pile), against %.1f%% at worst "
           "curved, and refining cures it only slowly (the table).%s" % (
               KINDS["layer"], KINDS["interface"], 100 * WITHIN, meshes[-1], 5 * meshes[-1] // 3,
               meshes[0], "It does." if good else "It does NOT.", 100 * worst_straight,
               100 * worst_curved, below))
    return Section(
        "curved-interfaces", "Curved interfaces: a pile section sliding on a circle",
        "(not in the paper) P / (c D) = pi + 2 Delta + 2 cos Delta + 4 (cos Delta/2 + "
        "sin Delta/2), sin Delta = alpha: 9.142 smooth to 11.940 rough (Randolph and Houlsby "
        "1984)", "agrees" if good else "disagrees", why, rows=table,
        cost="%.1f s for the %d runs" % (runs.seconds(*names), len(names)),
        paper_value="9.142 (smooth) to 11.940 (rough)",
        our_value="curved cells within %.1f%%; straight up to %+.0f%%" % (
            100 * worst_curved, 100 * worst_straight))


def sections(runs, quick):
    return [curved_interfaces(runs, quick)]
