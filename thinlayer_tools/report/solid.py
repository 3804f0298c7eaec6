"""The report's sections on 3D bodies (Kinematics/Type = 3d): Case 1
extruded (plane strain held, then free), zero-thickness interface elements
in 3D (Cases 1 and 3), a rigid disc's stiffnesses from
the 3D body and from Fourier harmonics, and Case 3 computed both ways,
error against cost."""
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from thinlayer_tools import results  # noqa: E402
from thinlayer_tools.report.figures import data_uri  # noqa: E402
from thinlayer_tools.report.page import Section  # noqa: E402

# Case 1 at 45 degrees, plane strain and its column extruded (u_z held on
# both faces), and the column free along z on its front face.
CASE1_RUNS = [("case1-plane", "case1-inclined-adhesive", ("Output/Write VTU=false",)),
              ("case1-3d", "case1-3d", ("Output/Write VTU=false",)),
              ("case1-3d-free", "case1-3d", ("Output/Write VTU=false",
                                             "Boundary 6/Constrained components="))]
# Plane strain to this (relative, of the largest load and displacement).
PLANE_STRAIN_AGREEMENT = 1e-8

# The rigid disc: (motion, overrides of prm/rigid-disc-3d.prm, of
# prm/rigid-disc-fourier.prm, Bycroft's half-space stiffness of G, R, nu).
DISC_MOTIONS = [
    ("vertical", ("Boundary 1/Displacement=0; -1; 0", "Boundary 5/Constrained components=z",
                  "Monitors/Load component=y"),
     ("Kinematics/Harmonics=0", "Kinematics/Stations=0", "Boundary 1/Displacement=0; 0; -1",
      "Monitors/Load component=y"), lambda G, R, nu: 4 * G * R / (1 - nu)),
    ("horizontal", ("Boundary 1/Displacement=1; 0; 0", "Boundary 5/Constrained components=z",
                    "Monitors/Load component=x"),
     ("Kinematics/Harmonics=1", "Kinematics/Stations=0, 60, 120, 180",
      "Boundary 1/Displacement=1; 0; 0", "Monitors/Load component=x"),
     lambda G, R, nu: 8 * G * R / (2 - nu)),
    ("rocking", ("Boundary 1/Displacement=0; x; 0", "Boundary 5/Constrained components=z",
                 "Monitors/Load component=moment"),
     ("Kinematics/Harmonics=1", "Kinematics/Stations=0, 60, 120, 180",
      "Boundary 1/Displacement=0; 0; r*cos(theta)", "Monitors/Load component=moment"),
     lambda G, R, nu: 8 * G * R ** 3 / (3 * (1 - nu))),
    ("torsion", ("Boundary 1/Displacement=z; 0; -x", "Boundary 5/Constrained components=x, y",
                 "Monitors/Load component=torque"),
     ("Kinematics/Harmonics=0", "Kinematics/Stations=0", "Kinematics/Series=antisymmetric",
      "Boundary 1/Displacement=-r*sin(theta); r*cos(theta); 0",
      "Monitors/Load component=torque"), lambda G, R, nu: 16 * G * R ** 3 / 3),
]
DISC_AGREEMENT = 0.01
# The same disc on a domain of radius and depth 20 R, the mesh graded
# further (3D, Fourier overrides): the stiffnesses approach Bycroft's half
# space. Vertical and horizontal only.
WIDE = ("Mesh/Geometry parameters=sector=180, footing=0, half_width=1, width=20, depth=20, "
        "n_around=4, n_footing=4, n_side=12, n_depth=12, growth=1.3",)
WIDE_FOURIER = ("Mesh/Geometry parameters=half_width=1, width=20, depth=20, n_footing=8, "
                "n_side=12, n_depth=12, growth=1.3",)
WIDE_MOTIONS = ("vertical", "horizontal")
E, NU = 1e5, 0.3
# The collapse resolution of prm/case3-circular-footing-3d.prm's runs (the
# default, a share of the load).
COLLAPSE_RESOLUTION = 0.005


# Zero-thickness interface elements: Case 1 (plane strain, and extruded
# with u_z held) and Case 3 (Fourier harmonics 1, 3, and the half body),
# each sliding at its analytic load.
INTERFACE_RUNS = [
    ("case1-zt-plane", "case1-inclined-adhesive-zero-thickness", ("Output/Write VTU=false",)),
    ("case1-zt-3d", "case1-3d-zero-thickness", ("Output/Write VTU=false",)),
    ("case3-zt-fourier", "case3-circular-footing-zero-thickness", ("Output/Write VTU=false",)),
    ("case3-zt-3d", "case3-circular-footing-3d-zero-thickness", ("Output/Write VTU=false",)),
]
# In --quick the half body has 4 elements around the half circle (not 16),
# and is loaded from 0.9 in steps of 0.01.
INTERFACE_QUICK = ("Mesh/Geometry parameters=sector=180, footing=1, zero_thickness=1, "
                   "half_width=1, width=5, depth=3, footing_height=0.5, n_around=1, "
                   "n_footing=4, n_side=12, n_depth=10, growth=1.2",
                   "Loading/Load increments=0.9, 12*0.01")


# The rough rigid circular footing: the 3D quarter body (not in --quick: it
# takes some 15 minutes) and harmonic 0 on the like r-z mesh.
FOOTING_3D = ("footing-rigid-3d", "circular-footing-rigid-3d", ("Output/Write VTU=false",))
FOOTING_FOURIER = ("footing-rigid-fourier", "circular-footing-rigid",
                   ("Output/Write VTU=false",
                    "Mesh/Geometry parameters=half_width=1, width=5, depth=3, n_footing=8, "
                    "n_side=16, n_depth=16, growth=1.3",
                    "Discretisation/Element=Q8", "Boundary 1/Constrained components=r, z",
                    "Reference/Analytic load=6.05"))
FOOTING_TARGET = 0.02


def run_list(quick):
    """The runs of these sections: (name, scene, overrides)."""
    runs = list(CASE1_RUNS) + [FOOTING_FOURIER] + ([] if quick else [FOOTING_3D])
    for name, scene, overrides in INTERFACE_RUNS:
        quick_3d = quick and name == "case3-zt-3d"
        runs.append((name, scene, overrides + (INTERFACE_QUICK if quick_3d else ())))
    # The disc's runs (a minute of 3D bodies) are left to the full report:
    # in CI, tests/verification/disc_stiffness checks the same stiffnesses.
    for motion, solid, fourier, _ in ([] if quick else DISC_MOTIONS):
        runs.append(("disc-%s-3d" % motion, "rigid-disc-3d", solid))
        runs.append(("disc-%s-fourier" % motion, "rigid-disc-fourier", fourier))
        if motion in WIDE_MOTIONS:
            runs.append(("disc-%s-3d-wide" % motion, "rigid-disc-3d", WIDE + solid))
            runs.append(("disc-%s-fourier-wide" % motion, "rigid-disc-fourier",
                         WIDE_FOURIER + fourier))
    return runs


def benchmark_arguments(quick):
    """benchmarks/fourier_vs_3d.py's arguments: the Fourier series only in
    --quick (its 3D body, even with 8 elements around the half circle,
    takes a minute of CI's half hour), 16 and 32 elements around the half
    circle otherwise."""
    return ["--levels", "" if quick else "4,8"]


def case1_section(runs):
    plane = results.states(results.history(runs.path("case1-plane")))
    held = results.states(results.history(runs.path("case1-3d")))
    free = runs.summary("case1-3d-free")
    scale_load = max(abs(results.number(r["load"])) for r in plane)
    scale_u = max(abs(results.number(r["displacement"])) for r in plane)
    same = len(plane) == len(held)
    difference = max((max(abs(results.number(a["load"]) - results.number(b["load"])) / scale_load,
                          abs(results.number(a["displacement"])
                              - results.number(b["displacement"])) / scale_u)
                      for a, b in zip(plane, held)), default=math.inf)
    agree = same and difference <= PLANE_STRAIN_AGREEMENT
    rows = [["run", "kinematics", "cells", "DoFs", "outcome", "collapse load P/C_w",
             "final displacement", "wall s"]]
    for name in ("case1-plane", "case1-3d", "case1-3d-free"):
        s = runs.summary(name)
        collapse = results.collapse_load(s)
        rows.append([name, s["kinematics"], "%d" % s["cells"], "%d" % s["dofs"], s["outcome"],
                     "%.4f" % collapse if collapse is not None else "-",
                     "%.5e" % results.number(s["final_displacement"]),
                     "%.2f" % s["wall_seconds"]])
    why = ("prm/case1-3d.prm extrudes the column of prm/case1-inclined-adhesive.prm (alpha = 45, "
           "R/t = 10) along z, one 20-node hexahedron deep, and holds u_z on both faces: a "
           "20-node hexahedron integrated over its depth is the 8-node quadrilateral, so the "
           "plane-strain field is the 3D solution, plastic points and all. %s converged states "
           "of the two; their loads and displacements differ by at most %.1e of the largest "
           "(asked: %.0e). Freed on its front face the column may bulge along z: it collapses "
           "at %s, softer on the way (final displacement %.4e against %.4e held)." % (
               "The same number of" if same else "A DIFFERENT number of", difference,
               PLANE_STRAIN_AGREEMENT,
               "%.4f" % results.collapse_load(free) if results.collapse_load(free) else "no load",
               results.number(free["final_displacement"]),
               results.number(runs.summary("case1-3d")["final_displacement"])))
    return Section("case1-3d", "Case 1 in 3D: plane strain held, then free",
                   "(not in the paper) plane strain.", "beyond" if agree else "differs", why,
                   rows=rows, cost="%.1f s for the three runs" % runs.seconds(
                       "case1-plane", "case1-3d", "case1-3d-free"),
                   paper_value="(not in the paper)",
                   our_value=("3D held = plane strain, bit for bit" if difference == 0 else
                              "3D held = plane strain to %.0e" % difference)
                   if agree else "differs")


def _bracket(summary):
    """(last converged, first failed) load factor of a collapse, else None."""
    if not results.collapse_detected(summary):
        return None
    return (results.number(summary["last_converged_load"]),
            results.number(summary["first_failed_load"]))


def interface_section(runs):
    plane = results.states(results.history(runs.path("case1-zt-plane")))
    held = results.states(results.history(runs.path("case1-zt-3d")))
    scale_load = max(abs(results.number(r["load"])) for r in plane)
    scale_u = max(abs(results.number(r["displacement"])) for r in plane)
    difference = max((max(abs(results.number(a["load"]) - results.number(b["load"])) / scale_load,
                          abs(results.number(a["displacement"])
                              - results.number(b["displacement"])) / scale_u)
                      for a, b in zip(plane, held)), default=math.inf)
    same = len(plane) == len(held) and difference <= PLANE_STRAIN_AGREEMENT
    rows = [["run", "kinematics", "cells", "DoFs", "outcome", "collapse bracket",
             "analytic", "contains it", "wall s"]]
    contained = True
    names = [name for name, _, _ in INTERFACE_RUNS]
    for name in names:
        s = runs.summary(name)
        bracket = _bracket(s)
        # Case 1's load is P / C_w (its analytic 1 / (sin cos)), Case 3's
        # P / (pi R^2 C_w) (1).
        reference = results.number(s.get("reference_load"))
        inside = (bracket is not None and math.isfinite(reference)
                  and bracket[0] <= reference * (1 + 1e-12)
                  and reference * (1 - 1e-12) <= bracket[1])
        contained = contained and inside
        rows.append([name, s["kinematics"], "%d" % s["cells"], "%d" % s["dofs"], s["outcome"],
                     "%.4f - %.4f" % bracket if bracket else "-", "%.4g" % reference,
                     "yes" if inside else "NO", "%.1f" % s["wall_seconds"]])
    why = ("Zero-thickness interface elements (Tresca, adhesion C_w = 1) in 3D: 16-node "
           "elements pairing the 8-node faces on either side of a physical surface. Case 1's "
           "column extruded along z with u_z held (prm/case1-3d-zero-thickness.prm) against "
           "its plane-strain column (prm/case1-inclined-adhesive-zero-thickness.prm): %s "
           "converged states, loads and displacements within %.1e of the largest (asked: "
           "%.0e). Case 3's footing as a half body standing on the soil "
           "(prm/case3-circular-footing-3d-zero-thickness.prm) against Fourier harmonics 1, 3 "
           "(prm/case3-circular-footing-zero-thickness.prm): pure sliding needs "
           "P = pi R^2 C_w. Case 1's load is P / C_w, Case 3's P / (pi R^2 C_w). %s" % (
               "the same" if len(plane) == len(held) else "A DIFFERENT number of",
               difference, PLANE_STRAIN_AGREEMENT,
               "Every run's collapse bracket contains the analytic load factor."
               if contained else "NOT every run's collapse bracket contains the analytic load "
               "factor."))
    return Section("interface-elements-3d", "Zero-thickness interface elements in 3D",
                   "(not in the paper) Goodman-type elements along a line, in plane strain "
                   "and for the footing's Fourier harmonics.",
                   "beyond" if same and contained else "differs", why, rows=rows,
                   cost="%.1f s for the %d runs" % (runs.seconds(*names), len(names)),
                   paper_value="(not in the paper)",
                   our_value=("3D = plane strain to %.0e; slides at the analytic load" % difference)
                   if same and contained else "differs")


def footing_section(runs):
    rows = [["model", "cells", "DoFs", "collapse pressure / c", "vs 6.05", "wall s", "peak MB"]]
    names = [FOOTING_FOURIER[0]] + ([FOOTING_3D[0]] if runs.has(FOOTING_3D[0]) else [])
    errors = {}
    for name in names:
        s = runs.summary(name)
        load, error = results.collapse_load(s), results.collapse_error(s)
        errors[name] = error
        rows.append([name, "%d" % s["cells"], "%d" % s["dofs"],
                     "%.4f" % load if load is not None else "-",
                     "%+.2f%%" % (100 * error) if error is not None else "-",
                     "%.0f" % s["wall_seconds"], "%.0f" % s["peak_memory_mb_per_rank"]])
    solid = errors.get(FOOTING_3D[0])
    if solid is None and not runs.has(FOOTING_3D[0]):
        verdict, value = "not run", "not run in --quick"
    else:
        within = solid is not None and abs(solid) <= FOOTING_TARGET
        verdict = "agrees" if within else "disagrees"
        value = "%+.2f%% (3D)" % (100 * solid) if solid is not None else "no plateau"
    why = ("A rough rigid circular footing (radius R = 1) pushed into weightless Tresca soil "
           "(c = 1) to its plateau: the Eason-Shield limit 6.05 c. 3D: a quarter of the body "
           "(prm/circular-footing-rigid-3d.prm), 20-node hexahedra graded towards the "
           "footing's edge outwards and downwards (growth 1.3 over 16 elements each way); "
           "Fourier: harmonic 0 on the like r-z mesh (8-node cells, 8 across the footing). "
           "Asked of the 3D body: within %.0f%%. The 3D disc is a polygon of 32 sides, its "
           "area 0.64%% short of pi R^2, by which its pressure per pi R^2 comes low." % (
               100 * FOOTING_TARGET))
    return Section("footing-rigid-3d", "The rough rigid circular footing in 3D",
                   "(not in the paper) 6.05 c (Eason and Shield 1960).", verdict, why,
                   rows=rows, cost="%.0f s for the %d runs" % (runs.seconds(*names), len(names)),
                   paper_value="6.05 c (closed form)", our_value=value)


def disc_section(runs, quick):
    if quick:
        return Section("disc-3d", "A rigid disc: 3D body against Fourier harmonics",
                       "(not in the paper) Fourier harmonics stand for the body of revolution.",
                       "not run", "Its 3D bodies are left to the full report; "
                       "tests/verification/disc_stiffness checks the same stiffnesses.",
                       paper_value="(not in the paper)", our_value="not run in --quick")
    G = E / (2 * (1 + NU))
    rows = [["motion", "domain (radius x depth) / R", "3D half body", "Fourier",
             "3D vs Fourier", "Bycroft's half space", "3D / half space"]]
    agree, names = True, []
    for motion, _, _, half_space in DISC_MOTIONS:
        for suffix, domain in (("", "5 x 3"), ("-wide", "20 x 20")):
            if suffix and motion not in WIDE_MOTIONS:
                continue
            names += ["disc-%s-3d%s" % (motion, suffix), "disc-%s-fourier%s" % (motion, suffix)]
            solid, fourier = (abs(results.number(runs.summary(name)["last_converged_load"]))
                              for name in names[-2:])
            agree = agree and abs(solid / fourier - 1) < DISC_AGREEMENT
            bycroft = half_space(G, 1.0, NU)
            rows.append([motion, domain, "%.5g" % solid, "%.5g" % fourier,
                         "%+.2f%%" % (100 * (solid / fourier - 1)), "%.5g" % bycroft,
                         "%.3f" % (solid / bycroft)])
    why = ("A rigid disc of radius R = 1 on a cylinder of elastic soil (E = 1e5, nu = 0.3, "
           "base fixed, side held horizontally), pushed down, sideways, rocked about a "
           "horizontal axis and twisted about its own: force or moment per unit displacement "
           "or rotation (prm/rigid-disc-3d.prm, prm/rigid-disc-fourier.prm). 3D: the half body "
           "of 20-node hexahedra, the plane z = 0 held as each motion's symmetry asks; "
           "Fourier: its r-z plane (8-node cells, the same radial and vertical spacing), "
           "harmonic 0 (vertical), 1 (horizontal, rocking), antisymmetric 0 (torsion). They "
           "agree within %.0f%% %s: each discretises the body its own way (3D with a core of "
           "hexahedra around the axis), so their difference is the discretisation's. A "
           "finite layer on a fixed base is stiffer than Bycroft's half space; on a domain "
           "four times as wide and nearly seven times as deep the 3D stiffnesses come %s "
           "towards the half space's (last column)." % (
               100 * DISC_AGREEMENT, "for every motion and domain" if agree
               else "NOT for every motion and domain",
               "down" if all(float(rows[k + 1][-1]) < float(rows[k][-1])
                             for k in (1, 3)) else "NOT down"))
    return Section("disc-3d", "A rigid disc: 3D body against Fourier harmonics",
                   "(not in the paper) Fourier harmonics stand for the body of revolution.",
                   "beyond" if agree else "differs", why, rows=rows,
                   cost="%.1f s for the %d runs" % (runs.seconds(*names), len(names)),
                   paper_value="(not in the paper)",
                   our_value="within %.0f%%" % (100 * DISC_AGREEMENT) if agree else "differs")


def _difference(row, reference, key):
    return results.number(row[key]) / results.number(reference[key]) - 1


def _error_cost_figure(fourier, solid, reference):
    """Each model's difference from REFERENCE against its wall time: the
    displacement at half collapse and the mean slip, Fourier and 3D as
    series."""
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, key, title in ((axes[0], "displacement_half",
                            "footing displacement at half the collapse load"),
                           (axes[1], "mean_slip",
                            "mean slip under the footing at the last converged state")):
        for series, rows, marker in (("Fourier", fourier[:-1], "o-"), ("3D", solid, "s-")):
            if not rows:
                continue
            x = [results.number(r["wall_seconds"]) for r in rows]
            y = [max(abs(_difference(r, reference, key)), 1e-6) for r in rows]
            ax.loglog(x, y, marker, label=series)
            for r, xi, yi in zip(rows, x, y):
                label = r["model"].replace("Fourier ", "") if series == "Fourier" \
                    else "%s around" % r["around"]
                ax.annotate(label, (xi, yi), textcoords="offset points", xytext=(4, 4),
                            fontsize=8)
        ax.axhline(0.01, color="0.6", ls=":", lw=1)
        left, right = ax.get_xlim()
        ax.set_xlim(left, right * 4)  # room for the last point's label
        ax.set_xlabel("wall time of the run to collapse / s")
        ax.set_ylabel("|value / value of Fourier {1, 3, 5, 7} - 1|")
        ax.set_title(title, fontsize=9)
        ax.legend()
    fig.tight_layout()
    figure = data_uri(fig)
    plt.close(fig)
    return figure


def fourier_or_3d_section(directory):
    rows_csv = results.read_csv(os.path.join(directory, "benchmarks", "fourier-vs-3d.csv"))
    fourier = [r for r in rows_csv if r["model"].startswith("Fourier")]
    solid = [r for r in rows_csv if r["model"] == "3D"]
    reference = fourier[-1]
    table = [["model", "elements around the half circle", "equations", "collapse load",
              "displacement at half collapse (x 1e-5)", "vs the richest Fourier",
              "mean slip under the footing at the last converged state (x 1e-5)", "vs the richest Fourier",
              "wall s", "peak MB", "ms per iteration", "ms per substitution"]]
    for r in rows_csv:
        table.append([r["model"], r["around"] or "-", r["equations"],
                      "%.4f" % results.number(r["collapse_load"]),
                      "%.4f" % results.number(r["displacement_half"]),
                      "%+.3f%%" % (100 * _difference(r, reference, "displacement_half")),
                      "%.4f" % (1e5 * results.number(r["mean_slip"])),
                      "%+.2f%%" % (100 * _difference(r, reference, "mean_slip")),
                      "%.1f" % results.number(r["wall_seconds"]),
                      "%.0f" % results.number(r["peak_memory_mb"]),
                      "%.2f" % (1e3 * results.number(r["seconds_per_iteration"])),
                      "%.2f" % (1e3 * results.number(r["seconds_per_substitution"]))])

    figure = _error_cost_figure(fourier, solid, reference)

    def first_within(key, tolerance):
        return next((r["model"].replace("Fourier ", "") for r in fourier[:-1]
                     if abs(_difference(r, reference, key)) < tolerance), "{1, 3, 5, 7}")

    # The runs bracket the collapse to the scene's resolution, 0.5% of the
    # load: loads one bracket apart are the same collapse.
    loads = [results.number(r["collapse_load"]) for r in rows_csv]
    same_collapse = max(loads) - min(loads) <= COLLAPSE_RESOLUTION * min(loads) + 1e-9
    cheapest = fourier[-1]
    last = solid[-1] if solid else None
    cost = (results.number(last["wall_seconds"]) / results.number(cheapest["wall_seconds"])
            if last else math.nan)
    why = ("Case 3 (the paper's footing, R/t = 10, the paper's method) on one r-z resolution: "
           "Fourier harmonics on the r-z plane (8-node cells) and the half body of 20-node "
           "hexahedra (the same spacing along radii and in depth) with more and more elements "
           "around. The reference is the richest Fourier series, {1, 3, 5, 7}. %s The "
           "footing's displacement needs %s for 0.1%%; the row's mean slip under the footing "
           "at the last converged state, near collapse, needs %s for 1%%: harmonic 1 with a "
           "little of 3 and 5. %s Fourier harmonics suffice for this body of revolution; 3D "
           "is for bodies that are not." % (
               ("Every model finds the same collapse load factor, %.4f" % loads[0]
                if max(loads) == min(loads) else
                "Every model finds the collapse load factor between %.4f and %.4f, within the "
                "runs' resolution of %.1f%%" % (min(loads), max(loads),
                                                100 * COLLAPSE_RESOLUTION))
               + " (the row of R/t = 10 is some 15.5% strong, the paper's own finding)."
               if same_collapse else "The collapse loads DIFFER between the models.",
               first_within("displacement_half", 1e-3), first_within("mean_slip", 1e-2),
               ("The 3D body with %s elements around the half circle lies %+.3f%% and %+.2f%% "
                "from it, at %.0f times the wall time of Fourier {1, 3, 5, 7} (%.0f s against "
                "%.1f s) and %.0f times its memory; a 3D iteration is its substitution (%.0f%% "
                "of the time), the factors of a 3D mesh filling in far more than a 2D one's." % (
                    last["around"], 100 * _difference(last, reference, "displacement_half"),
                    100 * _difference(last, reference, "mean_slip"), cost,
                    results.number(last["wall_seconds"]),
                    results.number(cheapest["wall_seconds"]),
                    results.number(last["peak_memory_mb"])
                    / results.number(cheapest["peak_memory_mb"]),
                    100 * results.number(last["seconds_per_substitution"])
                    / results.number(last["seconds_per_iteration"]))) if last else
               "The 3D body runs in the full report only (--quick: the Fourier series)."))
    return Section("fourier-or-3d", "Fourier or 3D",
                   "Griffiths: Fourier harmonics 1 and 3 (five stations) model the laterally "
                   "loaded circular footing.", "beyond" if same_collapse else "differs", why,
                   rows=table,
                   figures=[(figure, "Each model's difference from Fourier {1, 3, 5, 7} against "
                             "its wall time, the dotted line 1%; the 3D points differ from it "
                             "also by their own r-z discretisation (a core of hexahedra at the "
                             "axis).")],
                   cost="%.0f s for the %d runs" % (
                       sum(results.number(r["wall_seconds"]) for r in rows_csv), len(rows_csv)),
                   paper_value="harmonics 1, 3",
                   our_value="%s for 1%% slip; %s" % (
                       first_within("mean_slip", 1e-2),
                       "3D alike at %.0fx the time" % cost if last else
                       "3D in the full report"))


def sections(runs, quick):
    return [case1_section(runs), interface_section(runs), footing_section(runs),
            disc_section(runs, quick), fourier_or_3d_section(runs.directory)]
